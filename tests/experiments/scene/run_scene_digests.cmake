# The safety net of the scene runner (issue 22): short variants of the shipped scenes, run on
# one thread, must write byte-identical results to those recorded in scene_digests.txt. For
# each run it digests (SHA-256) final_centres.csv, stats.csv without its wall-time columns,
# and every frame file (frames/*.csv and *.ply, in order). A change meant to alter results
# re-records them with -DUPDATE=ON (and says so in its commit); any other difference fails,
# naming the run and the file.
# Called by CTest with -DRICE=<rice binary> -DSCENES=<experiments/scenes> -DTEST_SCENES=<tests
# scenes> -DOUT=<scratch folder> -DEXPECTED=<scene_digests.txt>.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${OUT}")

# name | scene file | overrides, comma-separated (a thumbnail render: the render is not digested).
# The scenes ship with soft grains; the chawan and the press run rigid ones, so both bodies stay
# under the net.
set(thumbnail "render.width=16,render.height=16,render.samples_per_pixel=1")
set(runs
  "shari|${SCENES}/shari.toml|grains.count=40,grains.variants=2,solver.frames=150,${thumbnail}"
  "onigiri|${SCENES}/onigiri.toml|grains.count=60,grains.variants=2,solver.frames=150,${thumbnail}"
  "chawan|${SCENES}/chawan.toml|grains.count=60,grains.variants=2,solver.frames=70,grains.body=\"rigid\",${thumbnail}"
  "drop|${SCENES}/drop.toml|grains.count=40,grains.variants=2,solver.frames=40,${thumbnail}"
  "press|${SCENES}/press.toml|grains.count=40,grains.variants=2,solver.frames=100,grains.body=\"rigid\",${thumbnail}"
  "soft_drop|${TEST_SCENES}/soft_drop.toml|"
)
set(timing_columns wall_s broad_phase_s narrow_phase_s solve_s sleeping_s)

# stats.csv's text without the columns that hold wall times.
function(stats_without_timings file result)
  file(STRINGS "${file}" lines)
  list(GET lines 0 header)
  string(REPLACE "," ";" names "${header}")
  set(drop "")
  foreach(column ${timing_columns})
    list(FIND names ${column} index)
    if(index LESS 0)
      message(FATAL_ERROR "${file} has no column ${column}")
    endif()
    list(APPEND drop ${index})
  endforeach()
  set(text "")
  foreach(line ${lines})
    string(REPLACE "," ";" cells "${line}")
    list(REMOVE_AT cells ${drop})
    list(JOIN cells "," kept)
    string(APPEND text "${kept}\n")
  endforeach()
  set(${result} "${text}" PARENT_SCOPE)
endfunction()

set(measured "")
foreach(run ${runs})
  string(REPLACE "|" ";" fields "${run}")
  list(GET fields 0 name)
  list(GET fields 1 scene)
  list(LENGTH fields n)
  set(arguments --threads 1 run "${scene}" --out "${OUT}/${name}")
  if(n GREATER 2)
    list(GET fields 2 overrides)
    string(REPLACE "," ";" overrides "${overrides}")
    foreach(o ${overrides})
      list(APPEND arguments --set "${o}")
    endforeach()
  endif()
  execute_process(COMMAND "${RICE}" ${arguments} RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "rice ${arguments} exited with ${result}: ${error}")
  endif()
  file(SHA256 "${OUT}/${name}/final_centres.csv" centres)
  stats_without_timings("${OUT}/${name}/stats.csv" stats)
  string(SHA256 stats "${stats}")
  file(GLOB frame_files "${OUT}/${name}/frames/*")
  list(SORT frame_files)
  list(LENGTH frame_files frame_count)
  set(frame_digests "")
  foreach(f ${frame_files})
    file(SHA256 "${f}" digest)
    string(APPEND frame_digests "${digest}\n")
  endforeach()
  string(SHA256 frames "${frame_digests}")
  string(APPEND measured "${name} final_centres.csv ${centres}\n")
  string(APPEND measured "${name} stats.csv ${stats}\n")
  string(APPEND measured "${name} frames(${frame_count}) ${frames}\n")
endforeach()

if(UPDATE)
  file(WRITE "${EXPECTED}" "${measured}")
  message(STATUS "recorded the digests in ${EXPECTED}")
  return()
endif()
file(STRINGS "${EXPECTED}" expected_lines)
string(REPLACE "\n" ";" measured_lines "${measured}")
list(REMOVE_ITEM measured_lines "")
set(differences "")
foreach(line ${expected_lines})
  list(FIND measured_lines "${line}" found)
  if(found LESS 0)
    string(REGEX REPLACE " [0-9a-f]+$" "" what "${line}")
    string(APPEND differences "\n  ${what}")
  endif()
endforeach()
list(LENGTH expected_lines n_expected)
list(LENGTH measured_lines n_measured)
if(NOT n_expected EQUAL n_measured)
  string(APPEND differences "\n  ${n_measured} digests measured, ${n_expected} recorded")
endif()
if(differences)
  message(FATAL_ERROR "the scene runs wrote other results than ${EXPECTED} records, in:${differences}\n"
                      "The runs are in ${OUT}; -DUPDATE=ON records their digests, for a change meant to alter results.")
endif()
