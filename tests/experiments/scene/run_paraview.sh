#!/bin/bash
# A short sticky pour with [effects] paraview, read back by check_paraview.py.
# Usage: run_paraview.sh RICE SCENES OUT
set -euo pipefail
rice=$1 scenes=$2 out=$3
rm -rf "$out"
"$rice" run "$scenes/heap.toml" --set grains.count=30 --set grains.variants=2 --set solver.frames=30 \
  --set emitter.seconds=0.5 --set effects.paraview=true --no-render --out "$out" > /dev/null
python3 "$(dirname "${BASH_SOURCE[0]}")/check_paraview.py" "$out" 30 30
