#!/usr/bin/env bash
# The main job: set up, build, and run the studies the testbed currently reproduces,
# writing CSV, plots and run statistics under out/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
./scripts/setup.sh
./build/experiments/rice study xpbd-stiffness --out out/xpbd-stiffness
./build/experiments/rice study oscillator --out out/oscillator
./build/experiments/rice study convergence --out out/convergence
echo "main: results are in out/"
