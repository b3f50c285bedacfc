#!/usr/bin/env bash
# The main job: set up, build, and run every figure, table and study the testbed has
# (`rice reproduce`) into out/, with out/index.md showing each figure, its CSV files and the
# command that made it. Steps that are up to date are skipped; arguments go to `rice
# reproduce` (--full for the paper's settings, --force, --only STEP ...).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
./scripts/setup.sh
./build/experiments/rice reproduce --out out "$@"
