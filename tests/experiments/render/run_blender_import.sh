#!/bin/bash
# A run round-trips into Blender: `rice point-cache` writes a short run's grains (soft and
# rigid) as grains.obj and grains.pc2, Debian's Blender imports them in background mode with
# scripts/blender_import.py, and the vertex positions it shows at three frames equal the run's
# own render meshes of those frames (frames/*.ply) to float precision. A simplified cache
# (--max-vertices) imports too.
# Usage: run_blender_import.sh RICE SCENES OUT
set -euo pipefail
rice=$1 scenes=$2 out=$3
here=$(dirname "${BASH_SOURCE[0]}")
command -v blender > /dev/null || { echo "blender is not installed (scripts/test.sh installs it)" >&2; exit 1; }
rm -rf "$out"
short=(--set grains.count=3 --set grains.variants=2 --set solver.frames=5 --set effects.render_meshes=true --no-render)
for body in soft rigid; do
  "$rice" run "$scenes/drop.toml" "${short[@]}" --set "grains.body=\"$body\"" --out "$out/$body" > /dev/null
  "$rice" point-cache --run "$out/$body" --max-vertices 0 --out "$out/${body}_cache" > /dev/null
  blender --background --python "$here/../../../scripts/blender_import.py" -- "$out/${body}_cache" \
    --dump 1 3 5 --dump-to "$out/${body}_blender.csv" --save "$out/${body}.blend" > "$out/${body}_blender.log" 2>&1 ||
    { tail -n 20 "$out/${body}_blender.log" >&2; exit 1; }
  echo "$body:"
  python3 "$here/compare_blender_dump.py" "$out/${body}_blender.csv" "$out/$body"
  [ -s "$out/$body.blend" ] || { echo "no $body.blend saved" >&2; exit 1; }
done
"$rice" point-cache --run "$out/soft" --max-vertices 300 --out "$out/simplified" > /dev/null
blender --background --python "$here/../../../scripts/blender_import.py" -- "$out/simplified" \
  --dump 1 2 3 --dump-to "$out/simplified_blender.csv" > "$out/simplified_blender.log" 2>&1
points=$(sed -n 's/^points: //p' "$out/simplified/run_info.txt")
[ "$points" -le 900 ] || { echo "3 grains simplified to 300 vertices each have $points vertices" >&2; exit 1; }
[ "$(grep -c '^1,' "$out/simplified_blender.csv")" -eq "$points" ] || { echo "Blender shows another count" >&2; exit 1; }
echo "Blender round trip: soft and rigid equal at frames 1, 3, 5; simplified to $points vertices"
