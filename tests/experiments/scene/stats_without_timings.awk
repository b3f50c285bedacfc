# stats.csv without the columns that hold wall times, which differ from run to run: the resume
# and workflow tests compare the rest byte for byte (run_scene_digests.cmake drops the same
# columns by the same names). Usage: awk -f stats_without_timings.awk stats.csv
BEGIN { FS = OFS = "," }
NR == 1 {
  for (i = 1; i <= NF; ++i) timing[i] = $i ~ /^(wall_s|broad_phase_s|narrow_phase_s|solve_s|sleeping_s)$/
}
{
  kept = 0
  for (i = 1; i <= NF; ++i)
    if (!timing[i]) printf "%s%s", (kept++ ? OFS : ""), $i
  print ""
}
