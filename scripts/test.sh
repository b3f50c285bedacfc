#!/usr/bin/env bash
# Set up, build, and run the whole test suite: CTest on the Release build, then the same
# suite built with clang under AddressSanitizer and UndefinedBehaviorSanitizer
# (scripts/sanitize.sh), then every fuzz target for 20 s (scripts/fuzz.sh).
# `./scripts/test.sh --quick` runs the Release suite only.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
start=$SECONDS
./scripts/setup.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
echo "test: Release suite passed ($((SECONDS - start)) s so far)"
if [ "${1:-}" = "--quick" ]; then exit 0; fi
./scripts/sanitize.sh
echo "test: sanitizer suite passed ($((SECONDS - start)) s so far)"
./scripts/fuzz.sh 20
echo "test: all passed in $((SECONDS - start)) s"
