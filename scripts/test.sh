#!/usr/bin/env bash
# Set up, build, and run the whole test suite with CTest.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
./scripts/setup.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
