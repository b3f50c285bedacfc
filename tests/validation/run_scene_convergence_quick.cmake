# Runs `rice study scene-convergence --quick` into OUT and checks its outputs: a CSV row per run
# (four and the reference), the reference's own error 0, at least one run on the Pareto front,
# the plot and the run info. Called by CTest (tests/CMakeLists.txt) with -DRICE=<rice binary>
# -DSCENE=<experiments/scenes/shari.toml> -DOUT=<folder>.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${RICE}" study scene-convergence --quick --scene "${SCENE}" --out "${OUT}"
                RESULT_VARIABLE result OUTPUT_QUIET)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "rice study scene-convergence --quick exited with ${result}")
endif()
foreach(name scene_convergence.csv scene_convergence.png scene_convergence_front.csv run_info.txt)
  if(NOT EXISTS "${OUT}/${name}")
    message(FATAL_ERROR "missing ${OUT}/${name}")
  endif()
endforeach()
file(STRINGS "${OUT}/scene_convergence.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 6)
  message(FATAL_ERROR "scene_convergence.csv has ${count} lines, not a header and 5 runs")
endif()
list(GET rows 5 reference)
if(NOT reference MATCHES "^xpbd_480x1,xpbd,480,1,1,[^,]+,0,")
  message(FATAL_ERROR "the last row is not the reference at error 0: ${reference}")
endif()
set(on_front 0)
foreach(row ${rows})
  if(row MATCHES ",1$")  # the last column, pareto
    math(EXPR on_front "${on_front} + 1")
  endif()
endforeach()
if(on_front EQUAL 0)
  message(FATAL_ERROR "no run on the Pareto front")
endif()
