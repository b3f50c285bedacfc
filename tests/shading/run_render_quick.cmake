# `rice render`, `rice figure 13`, `rice study cdrf` and `rice study path-depth` end to end at toy
# sizes: each writes its files; the same seed renders the same EXR twice; a missing mesh exits
# non-zero and leaves no folder.
# Called by CTest with -DRICE=<rice binary> -DOUT=<scratch folder>.
file(REMOVE_RECURSE "${OUT}")
function(run)
  execute_process(COMMAND "${RICE}" ${ARGN} RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "rice ${ARGN} exited with ${result}: ${error}")
  endif()
endfunction()
function(expect_files folder)
  foreach(name ${ARGN})
    if(NOT EXISTS "${folder}/${name}")
      message(FATAL_ERROR "${folder} lacks ${name}")
    endif()
  endforeach()
endfunction()

run(grains --count 2 --out "${OUT}/grains")
foreach(copy a b)
  run(render --meshes "${OUT}/grains" --side-by-side --width 48 --height 24 --spp 4 --out "${OUT}/render_${copy}")
endforeach()
expect_files("${OUT}/render_a" render.png render.exr run_info.txt)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/render_a/render.exr" "${OUT}/render_b/render.exr"
                RESULT_VARIABLE different)
if(different)
  message(FATAL_ERROR "same seed, different renders")
endif()
run(render --meshes "${OUT}/grains" --side-by-side --integrator path --max-depth 8 --width 24 --height 12 --spp 2
    --out "${OUT}/render_path")
expect_files("${OUT}/render_path" render.png render.exr run_info.txt)
file(STRINGS "${OUT}/render_path/run_info.txt" integrator REGEX "^integrator: path$")
if(NOT integrator)
  message(FATAL_ERROR "render --integrator path: run_info.txt does not say integrator: path")
endif()
run(figure 13 --width 120 --height 40 --spp 2 --photons 2000 --out "${OUT}/figure13")
expect_files("${OUT}/figure13" figure13_render.png figure13_reference.exr figure13.csv run_info.txt)
run(study cdrf --photons 2000 --grain-photons 2000 --radii-mm 1 2 --soak-minutes 15 120 --out "${OUT}/cdrf")
expect_files("${OUT}/cdrf" cdrf_fit.csv cdrf_profiles.csv grain_profiles.csv run_info.txt)
run(study path-depth --quick --out "${OUT}/path-depth")
expect_files("${OUT}/path-depth" path_depth.csv reference.exr reference.png cdrf.png run_info.txt)
file(STRINGS "${OUT}/path-depth/path_depth.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 6)  # header, the reference's noise, three depths, the CDRF
  message(FATAL_ERROR "path_depth.csv has ${count} lines, not 6")
endif()

execute_process(COMMAND "${RICE}" render --meshes "${OUT}/no_such_mesh.ply" --out "${OUT}/bad"
                RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
if(result EQUAL 0 OR EXISTS "${OUT}/bad")
  message(FATAL_ERROR "a missing mesh was accepted or left a folder")
endif()
