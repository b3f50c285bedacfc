#!/usr/bin/env bash
# Set up, build, and run the whole test suite: CTest on the Release build, then the same
# suite built with clang under AddressSanitizer and UndefinedBehaviorSanitizer
# (scripts/sanitize.sh), then every fuzz target for 10 s (scripts/fuzz.sh; run it longer by
# hand after changing a reader). `./scripts/test.sh --quick` runs the Release suite only.
# The last line sums up how long each stage took.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
start=$SECONDS
stages=""
stage() {  # NAME COMMAND...: runs the command, noting its seconds
  local name=$1 begun=$SECONDS
  shift
  "$@"
  stages+="$name $((SECONDS - begun)) s, "
  echo "test: $name passed ($((SECONDS - start)) s so far)"
}
stage "setup and Release build" env RICE_TEST_PACKAGES=1 ./scripts/setup.sh
stage "Release suite" ctest --test-dir build --output-on-failure -j "$(nproc)"
if [ "${1:-}" != "--quick" ]; then
  stage "sanitizer build and suite" ./scripts/sanitize.sh
  stage "fuzzing" ./scripts/fuzz.sh 10
fi
echo "test: all passed in $((SECONDS - start)) s: ${stages%, }"
