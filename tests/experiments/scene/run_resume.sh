#!/bin/bash
# `rice run --resume` end to end: a run killed with SIGKILL at a random frame and resumed from
# its last checkpoint ends with the same frames, final pile, render and stats.csv (its wall-time
# columns aside) as a run never interrupted; a checkpoint from another scene, or cut short, is
# refused naming why.
# Usage: run_resume.sh RICE SCENE OUT [--set key=value ...] (the overrides of both runs).
set -euo pipefail
rice=$1 scene=$2 out=$3
shift 3
frames=24
settings=("$@" --set solver.frames=$frames --set solver.checkpoint_every=2)
rm -rf "$out"
mkdir -p "$out"
"$rice" --threads 2 run "$scene" "${settings[@]}" --out "$out/whole" > /dev/null

kill_at=$((3 + RANDOM % (frames - 5)))  # in [3, frames - 3]: a checkpoint exists, frames are left
echo "killing the second run after frame $kill_at"
"$rice" --threads 2 run "$scene" "${settings[@]}" --out "$out/killed" > /dev/null &
pid=$!
printf -v frame_file "%s/killed/frames/frame_%04d.csv" "$out" "$kill_at"
while [ ! -e "$frame_file" ]; do
  if ! kill -0 $pid 2> /dev/null; then
    echo "the run ended before frame $kill_at" >&2
    exit 1
  fi
  sleep 0.02
done
kill -KILL $pid
wait $pid 2> /dev/null || true
if [ -e "$out/killed/run_info.txt" ]; then
  echo "the killed run finished before the kill; no resume tested" >&2
  exit 1
fi
"$rice" --threads 2 run "$scene" "${settings[@]}" --out "$out/killed" --resume > "$out/resume.log"
grep "resumed after frame" "$out/resume.log"

# Same bytes: every frame, the final pile, the render; stats.csv without its wall times.
for file in $(cd "$out/whole" && ls frames/* final_centres.csv render/render.exr); do
  cmp -s "$out/whole/$file" "$out/killed/$file" || { echo "resumed run: $file differs" >&2; exit 1; }
done
timeless() { cut -d, -f1,2,4-11 "$1"; }  # frame, time_s, then awake .. top_m
if ! diff <(timeless "$out/whole/stats.csv") <(timeless "$out/killed/stats.csv") > /dev/null; then
  echo "resumed run: stats.csv differs" >&2
  exit 1
fi
[ ! -e "$out/killed/checkpoint.bin" ] || { echo "a finished run left its checkpoint" >&2; exit 1; }

# Refusals: another scene (another seed), a truncated checkpoint.
"$rice" --threads 2 run "$scene" "${settings[@]}" --set solver.frames=2000 --out "$out/stopped" > /dev/null 2>&1 &
pid=$!
while [ ! -e "$out/stopped/checkpoint.bin" ]; do sleep 0.02; done
kill -TERM $pid
wait $pid 2> /dev/null && { echo "a run stopped by SIGTERM exited 0" >&2; exit 1; }
refused() {  # refused WHY ARGS...: the resume fails, saying WHY
  local why=$1
  shift
  if "$rice" run "$scene" "$@" --out "$out/stopped" --resume > /dev/null 2> "$out/refusal.txt"; then
    echo "a resume that should be refused ($why) ran" >&2
    exit 1
  fi
  grep -q "$why" "$out/refusal.txt" || { echo "refusal without '$why':" >&2; cat "$out/refusal.txt" >&2; exit 1; }
}
refused "another scene" "${settings[@]}" --set solver.frames=2000 --set grains.seed=99
truncate -s -100 "$out/stopped/checkpoint.bin"
refused "truncated" "${settings[@]}" --set solver.frames=2000
echo "resume: same bytes after a kill at frame $kill_at; other scenes and cut checkpoints refused"
