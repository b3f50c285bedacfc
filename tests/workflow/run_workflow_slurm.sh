#!/bin/bash
# The main job's workflow on a real Slurm cluster: a single-node cluster started on this
# machine (local_slurm_cluster.sh) runs a small variant of the workflow (small_config.yaml: two
# short scene runs and their videos, rendered in parts) through the Slurm profile. Each step
# and video part must be a Slurm job that completed, by the cluster's job records, and every
# output must equal, byte for byte, that of the same workflow run here on one thread (the
# run_info.txt files, which hold wall times, and stats.csv's timing columns aside). If the
# cluster cannot start, the test fails saying why.
# Usage: run_workflow_slurm.sh RICE OUT
set -euo pipefail
rice=$1 out=$(realpath -m "$2")
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
command -v snakemake > /dev/null || { echo "snakemake is not installed (scripts/setup.sh installs it)" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out"
cluster=$out/cluster
trap 'tests/workflow/local_slurm_cluster.sh stop "$cluster"' EXIT
SLURM_CONF=$(tests/workflow/local_slurm_cluster.sh start "$cluster")
export SLURM_CONF USER=${USER:-$(id -un)}  # Snakemake's Slurm executor reads USER

small=(--configfile tests/workflow/small_config.yaml)
snakemake --cores 1 "${small[@]}" --config "rice=$rice" "out=$out/local" > "$out/local.log" 2>&1 ||
  { tail -n 30 "$out/local.log" >&2; exit 1; }
# A status look every second (values over 1 fall back to Snakemake's 33 s).
snakemake --profile workflow/profiles/slurm --max-status-checks-per-second 1 "${small[@]}" \
  --config "rice=$rice" "out=$out/slurm" > "$out/slurm.log" 2>&1 || { tail -n 30 "$out/slurm.log" >&2; exit 1; }

# The job records: every step and part ran as a Slurm job and completed.
expected=(heap heap_dry video_part video_part video_part video_part video_heap video_heap_dry)
jobs=$(sed -n 's/.* Name=snakejob_\([a-z_]*\)_[0-9]* JobState=\([A-Z]*\) .*/\1 JobState=\2/p' "$cluster/jobs.log")
echo "Slurm jobs:"
echo "$jobs"
for rule in $(printf "%s\n" "${expected[@]}" | sort -u); do
  want=$(printf "%s\n" "${expected[@]}" | grep -cx "$rule")
  got=$(echo "$jobs" | grep -cx "$rule JobState=COMPLETED" || true)
  [ "$got" -eq "$want" ] || { echo "$want '$rule' jobs expected completed in Slurm's records, $got found" >&2; exit 1; }
done

# The same files, with the same bytes, as the local run.
outputs() { (cd "$1" && find heap heap-dry video-heap video-heap-dry video-parts -type f ! -name '.*' | sort); }
outputs "$out/local" > "$out/local.files"
outputs "$out/slurm" | cmp -s - "$out/local.files" ||
  { echo "the Slurm run wrote other files than the local run" >&2; exit 1; }
compared=0
timeless=tests/experiments/scene/stats_without_timings.awk
while IFS= read -r file; do
  case $file in
    */run_info.txt) continue ;;
    */stats.csv) cmp -s <(awk -f "$timeless" "$out/local/$file") <(awk -f "$timeless" "$out/slurm/$file") ;;
    *) cmp -s "$out/local/$file" "$out/slurm/$file" ;;
  esac || { echo "the Slurm run's $file differs from the local run's" >&2; exit 1; }
  compared=$((compared + 1))
done < "$out/local.files"
echo "workflow on Slurm: ${#expected[@]} jobs completed; $compared files equal to the local run's"
