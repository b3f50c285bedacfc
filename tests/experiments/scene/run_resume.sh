#!/bin/bash
# `rice run --resume` end to end: a run killed with SIGKILL at frame 3 and at a random frame and resumed from
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

# kill_and_resume AT: kills a run once frame AT is written, resumes it, and compares it with
# the whole run.
kill_and_resume() {
  local kill_at=$1 killed="$out/killed_$1"
  echo "killing a run after frame $kill_at"
  "$rice" --threads 2 run "$scene" "${settings[@]}" --out "$killed" > /dev/null &
  local pid=$!
  local frame_file
  printf -v frame_file "%s/frames/frame_%04d.csv" "$killed" "$kill_at"
  while [ ! -e "$frame_file" ]; do
    if ! kill -0 $pid 2> /dev/null; then
      echo "the run ended before frame $kill_at" >&2
      exit 1
    fi
    sleep 0.02
  done
  kill -KILL $pid
  wait $pid 2> /dev/null || true
  if [ -e "$killed/run_info.txt" ]; then
    echo "the killed run finished before the kill; no resume tested" >&2
    exit 1
  fi
  # Its stats.csv holds the frames before the one written last, at least.
  local rows=$(($(wc -l < "$killed/stats.csv") - 1))
  if [ $rows -lt $((kill_at - 1)) ]; then
    echo "the killed run's stats.csv holds $rows frames, not $((kill_at - 1))" >&2
    exit 1
  fi
  "$rice" --threads 2 run "$scene" "${settings[@]}" --out "$killed" --resume > "$killed.log"
  grep "resumed after frame" "$killed.log"

  # Same bytes: every frame, the final pile, the render; stats.csv without its wall times.
  for file in $(cd "$out/whole" && ls frames/* final_centres.csv render/render.exr); do
    cmp -s "$out/whole/$file" "$killed/$file" || { echo "resumed after frame $kill_at: $file differs" >&2; exit 1; }
  done
  timeless() { awk -f "$(dirname "${BASH_SOURCE[0]}")/stats_without_timings.awk" "$1"; }
  if ! diff <(timeless "$out/whole/stats.csv") <(timeless "$killed/stats.csv") > /dev/null; then
    echo "resumed after frame $kill_at: stats.csv differs" >&2
    exit 1
  fi
  [ ! -e "$killed/checkpoint.bin" ] || { echo "a finished run left its checkpoint" >&2; exit 1; }
}
# From the first checkpoint (frame 2, grains still parked above the bowl: a resume once woke
# them), and from a random one in [5, frames - 3].
kill_and_resume 3
random_kill=$((5 + RANDOM % (frames - 7)))
kill_and_resume $random_kill

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
echo "resume: same bytes after kills at frames 3 and $random_kill; other scenes and cut checkpoints refused"
