#!/usr/bin/env bash
# The main job: set up, build, and run the workflow (workflow/Snakefile) that makes every
# figure, table, study, scene run and video the testbed has into out/, with out/index.html
# and out/index.md showing each step's figures, its CSV files, its command and wall time.
# Steps that are up to date are skipped. Arguments go to snakemake, for example
#   ./scripts/main.sh --config full=true       # the paper's settings
#   ./scripts/main.sh figure8 video_chawan      # some steps (and what they read) only
#   ./scripts/main.sh --forceall                # everything again
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
./scripts/setup.sh
snakemake --cores "$(nproc)" --rerun-incomplete "$@"  # a step killed half way runs again
