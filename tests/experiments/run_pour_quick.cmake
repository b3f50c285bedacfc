# `rice pour` end to end on a small scene: 30 rigid grains for 20 frames write a stats row
# per frame, a pose file per frame, the chawan OBJ and the final pile; the same seed gives
# the same poses twice; a bad setting exits non-zero and leaves no folder.
# Called by CTest with -DRICE=<rice binary> -DOUT=<scratch folder>.
file(REMOVE_RECURSE "${OUT}")
foreach(run a b)
  execute_process(COMMAND "${RICE}" pour --count 30 --variants 2 --frames 20 --pour-seconds 0.2 --out "${OUT}/${run}"
                  RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "rice pour exited with ${result}: ${error}")
  endif()
endforeach()
foreach(name chawan.obj stats.csv final_centres.csv run_info.txt frames/frame_0001.csv frames/frame_0020.csv)
  if(NOT EXISTS "${OUT}/a/${name}")
    message(FATAL_ERROR "rice pour did not write ${name}")
  endif()
endforeach()
file(STRINGS "${OUT}/a/stats.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 21)
  message(FATAL_ERROR "stats.csv has ${count} lines, expected a header and 20 frames")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/a/frames/frame_0020.csv" "${OUT}/b/frames/frame_0020.csv"
                RESULT_VARIABLE different)
if(different)
  message(FATAL_ERROR "same seed, different poses at frame 20")
endif()
execute_process(COMMAND "${RICE}" pour --count 30 --dynamic-friction 0.9 --static-friction 0.5 --out "${OUT}/bad"
                RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
if(result EQUAL 0 OR EXISTS "${OUT}/bad")
  message(FATAL_ERROR "dynamic friction above static was accepted or left a folder")
endif()
