# Runs `rice study hard-cases --quick` into OUT: it must exit 0 (every case finite, no tet
# inverted, overlaps under 10% of the thickness), with a row per case that says so, and the
# bunny must have been pressed (its top under the lid below 95% of its settled height).
# Called by CTest with -DRICE=<rice binary> -DSCENES=<experiments/scenes> -DOUT=<folder>.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${RICE}" study hard-cases --quick --scenes "${SCENES}" --out "${OUT}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "rice study hard-cases --quick exited with ${result}: ${output}${error}")
endif()
foreach(name hard_cases.csv run_info.txt bunny_settled/run_info.txt bunny_pressed/stats.csv cooker_drop/run_info.txt)
  if(NOT EXISTS "${OUT}/${name}")
    message(FATAL_ERROR "missing ${OUT}/${name}")
  endif()
endforeach()
file(STRINGS "${OUT}/hard_cases.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 3)
  message(FATAL_ERROR "hard_cases.csv has ${count} lines, not a header and 2 cases")
endif()
list(GET rows 1 bunny)
string(REPLACE "," ";" cells "${bunny}")
list(GET cells 11 ratio)
list(GET cells 13 passed)
if(NOT passed STREQUAL "yes" OR NOT ratio LESS 0.95)
  message(FATAL_ERROR "the bunny was not pressed below 95% of its height or failed: ${bunny}")
endif()
