#!/bin/bash
# The main job's workflow (workflow/Snakefile) on this machine, on two of its cheapest steps:
# it runs them and writes the index, a second run does nothing, a changed results version
# reruns them, out/index.html links only files that exist, and headless Chromium draws it.
# Usage: run_workflow.sh RICE OUT (run from anywhere; the workflow runs in the source tree).
set -euo pipefail
rice=$1 out=$2
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
command -v snakemake > /dev/null || { echo "snakemake is not installed (scripts/setup.sh installs it)" >&2; exit 1; }
rm -rf "$out"
config=(--config "rice=$rice" "out=$out" steps=figure11,figure9)
smk() { snakemake --cores 2 --directory . "$@" "${config[@]}"; }

smk -q > "$out.log" 2>&1 || { cat "$out.log" >&2; exit 1; }
for file in index.md index.html figure11/figure11.png figure9/run_info.txt logs/figure11.log benchmarks/figure9.tsv; do
  [ -s "$out/$file" ] || { echo "the workflow wrote no $file" >&2; exit 1; }
done
grep -q "Fig. 11: water absorption" "$out/index.html" || { echo "index.html lacks the figure 11 step" >&2; exit 1; }

smk -n > "$out.dry" 2>&1
grep -q "Nothing to be done" "$out.dry" || { echo "a second run would run again:" >&2; cat "$out.dry" >&2; exit 1; }
snakemake --cores 2 --directory . -n "${config[@]}" version=test-bump > "$out.dry" 2>&1
grep -q "figure11" "$out.dry" || { echo "a new results version reruns nothing" >&2; exit 1; }

python3 tests/workflow/check_index_links.py "$out/index.html"
command -v chromium > /dev/null || { echo "chromium is not installed (scripts/test.sh installs it)" >&2; exit 1; }
chromium --headless --no-sandbox --disable-gpu --window-size=1280,1600 --screenshot="$out/index.png" \
  "file://$(realpath "$out/index.html")" > "$out.chromium.log" 2>&1 || { cat "$out.chromium.log" >&2; exit 1; }
python3 tests/workflow/check_page_not_blank.py "$out/index.png"
echo "workflow: ran, second run does nothing, links resolve, the page is drawn"
