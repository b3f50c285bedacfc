#!/usr/bin/env bash
# The main job: set up, build, and run the studies and figures the testbed currently reproduces,
# writing CSV, plots and run statistics under out/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
./scripts/setup.sh
./build/experiments/rice study xpbd-stiffness --out out/xpbd-stiffness
./build/experiments/rice study oscillator --out out/oscillator
./build/experiments/rice study convergence --out out/convergence
./build/experiments/rice figure 8 --out out/figure8
./build/experiments/rice figure 9 --out out/figure9
./build/experiments/rice figure 11 --out out/figure11
./build/experiments/rice grains --cultivar japonica --count 10 --out out/grains
./build/experiments/rice pour --out out/pour
./build/experiments/rice pour --container plate --count 400 --frames 180 --pour-seconds 3.5 --spout-height 0.05 --out out/heap
./build/experiments/rice pour --container plate --count 400 --frames 180 --pour-seconds 3.5 --spout-height 0.05 --no-cohesion --out out/heap-dry
./build/experiments/rice study pour-substeps --out out/pour-substeps
./build/experiments/rice study grain-substeps --out out/grain-substeps
./build/experiments/rice study contact --out out/contact
./build/experiments/rice study cdrf --out out/cdrf
./build/experiments/rice figure 10 --out out/figure10
./build/experiments/rice run experiments/scenes/chawan.toml --out out/scenes/chawan
./build/experiments/rice run experiments/scenes/press.toml --out out/scenes/press
./build/experiments/rice run experiments/scenes/shari.toml --out out/scenes/shari
./build/experiments/rice run experiments/scenes/onigiri.toml --out out/scenes/onigiri
./build/experiments/rice figure 13 --out out/figure13
./build/experiments/rice study render --out out/render-study
./build/experiments/rice render --pour out/pour --width 1280 --height 720 --spp 64 \
  --eye 0 -0.12 0.16 --look-at 0 0 0.03 --fov 35 --out out/render-pour
echo "main: results are in out/"
