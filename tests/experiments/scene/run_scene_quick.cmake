# `rice run` end to end on a short chawan: 30 soft grains for 20 frames write a stats row
# per frame, a pose file per frame, the chawan OBJ and the final pile; the same seed gives
# the same bytes twice on one thread and twice on two (the variants' meshes, the poses of
# every frame); a bad setting exits non-zero and leaves no folder.
# Called by CTest with -DRICE=<rice binary> -DSCENE=<chawan.toml> -DOUT=<scratch folder>.
file(REMOVE_RECURSE "${OUT}")
set(short --set grains.count=30 --set grains.variants=2 --set solver.frames=20 --set emitter.seconds=0.2
          --set render.width=32 --set render.height=24 --set render.samples_per_pixel=1)
foreach(run a b c d)
  set(threads 1)
  if(run STREQUAL "c" OR run STREQUAL "d")
    set(threads 2)
  endif()
  execute_process(COMMAND "${RICE}" --threads ${threads} run "${SCENE}" ${short} --out "${OUT}/${run}"
                  RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "rice run exited with ${result}: ${error}")
  endif()
endforeach()
foreach(name scene.toml chawan.obj stats.csv final_centres.csv run_info.txt frames/frame_0001.csv frames/frame_0020.csv
             render/render.png)
  if(NOT EXISTS "${OUT}/a/${name}")
    message(FATAL_ERROR "rice run did not write ${name}")
  endif()
endforeach()
file(STRINGS "${OUT}/a/stats.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 21)
  message(FATAL_ERROR "stats.csv has ${count} lines, expected a header and 20 frames")
endif()
# Same seed, same bytes: on a failure, say what differs first (the grains' inputs or which frame).
function(compare_runs first second)
  set(differences "")
  foreach(name grains.csv variants/variant_0.mesh variants/variant_1.mesh variants/variant_0.ply
               variants/variant_1.ply)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/${first}/${name}" "${OUT}/${second}/${name}"
                    RESULT_VARIABLE different)
    if(different)
      string(APPEND differences " ${name}")
    endif()
  endforeach()
  foreach(frame RANGE 1 20)
    string(LENGTH "${frame}" digits)
    math(EXPR zeros "4 - ${digits}")
    string(REPEAT "0" ${zeros} padding)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/${first}/frames/frame_${padding}${frame}.csv"
                    "${OUT}/${second}/frames/frame_${padding}${frame}.csv" RESULT_VARIABLE different)
    if(different)
      string(APPEND differences " frames from ${frame} on")
      break()
    endif()
  endforeach()
  if(differences)
    message(FATAL_ERROR "same seed, different results (runs ${first} and ${second}):${differences}")
  endif()
endfunction()
compare_runs(a b)  # one thread
compare_runs(c d)  # two threads
execute_process(COMMAND "${RICE}" run "${SCENE}" ${short} --set effects.dynamic_friction=0.9 --set effects.static_friction=0.5
                        --out "${OUT}/bad"
                RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
if(result EQUAL 0 OR EXISTS "${OUT}/bad")
  message(FATAL_ERROR "dynamic friction above static was accepted or left a folder")
endif()
