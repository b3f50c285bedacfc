#!/usr/bin/env bash
# Runs every fuzz target (tests/fuzz) for SECONDS seconds each (default 30), as many at once
# as there are cores, on the sanitizer build (scripts/sanitize.sh builds it; this script
# builds the fuzz targets if needed). Each target starts from its seed corpus in
# tests/fuzz/corpus/<target>/ and keeps what it learns in build-sanitize/fuzz/corpus/<target>/
# for the next run. A crash, a hang (> 10 s on one input), a sanitizer report, a reader
# promise broken (fuzz_targets.hpp) or a single allocation over 256 MB is a finding: its
# input is saved under build-sanitize/fuzz/findings/ and the script fails. After the fix,
# copy the input into tests/fuzz/regressions/<target>/ so the ordinary suite replays it.
#   ./scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-30}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj off ply medit absorption scene checkpoint)

if [ ! -f build-sanitize/build.ninja ]; then
  echo "fuzz: no sanitizer build; run ./scripts/sanitize.sh first" >&2
  exit 2
fi
cmake --build build-sanitize --target fuzzers >/dev/null

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
work=build-sanitize/fuzz
mkdir -p "$work/findings" "$work/logs"

fuzz_one() {
  local target=$1
  mkdir -p "$work/corpus/$target"
  if build-sanitize/tests/fuzz/fuzz_"$target" "$work/corpus/$target" "tests/fuzz/corpus/$target" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=256 -max_len=65536 \
      -print_final_stats=1 -artifact_prefix="$work/findings/$target-" >"$work/logs/$target.log" 2>&1; then
    local runs
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/logs/$target.log" | grep -o '[0-9]*$' || echo "?")
    echo "fuzz: $target: ${seconds} s, $runs inputs, no finding ($(ls "$work/corpus/$target" | wc -l) in its corpus)"
  else
    echo "fuzz: $target: FINDING, see $work/logs/$target.log and $work/findings/" >&2
    tail -n 40 "$work/logs/$target.log" >&2
    return 1
  fi
}

jobs=$(nproc)
failed=0
pids=()
for target in "${targets[@]}"; do
  fuzz_one "$target" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || failed=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
exit $failed
