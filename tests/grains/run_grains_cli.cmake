# `rice grains` end to end: the same seed writes byte-identical files twice on one thread, and
# on two threads the same render meshes and sections (the level sets do not depend on the
# scheduling; the simulation meshes can, rarely: README "Known limits"); instancing writes
# only the variants; bad input exits non-zero and leaves no output folder. Called by CTest
# with -DRICE=<rice binary> -DOUT=<scratch folder>.
file(REMOVE_RECURSE "${OUT}")

function(run_rice expect_success)
  execute_process(COMMAND "${RICE}" ${ARGN} RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE error)
  if(expect_success AND NOT result EQUAL 0)
    message(FATAL_ERROR "rice ${ARGN} exited with ${result}: ${error}")
  elseif(NOT expect_success AND result EQUAL 0)
    message(FATAL_ERROR "rice ${ARGN} succeeded but should have failed")
  endif()
endfunction()

run_rice(TRUE --threads 1 grains --count 3 --seed 7 --out "${OUT}/a")
run_rice(TRUE --threads 1 grains --count 3 --seed 7 --out "${OUT}/b")
run_rice(TRUE --threads 2 grains --count 3 --seed 7 --out "${OUT}/c")
file(GLOB files RELATIVE "${OUT}/a" "${OUT}/a/*")
list(LENGTH files count)
if(count LESS 13)
  message(FATAL_ERROR "expected 4 files per grain and grains.csv, found ${files}")
endif()
foreach(name ${files})
  if(name STREQUAL "run_info.txt")  # holds timings
    continue()
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/a/${name}" "${OUT}/b/${name}"
                  RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "same seed, different ${name}")
  endif()
  if(name MATCHES "\\.ply$|_section\\.png$")
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/a/${name}" "${OUT}/c/${name}"
                    RESULT_VARIABLE different)
    if(different)
      message(FATAL_ERROR "same seed, different ${name} on two threads")
    endif()
  endif()
endforeach()

run_rice(TRUE grains --cultivar aromatic --count 50 --variants 2 --no-sections --out "${OUT}/instanced")
file(GLOB variant_meshes "${OUT}/instanced/variant_*.ply")
list(LENGTH variant_meshes variant_count)
file(STRINGS "${OUT}/instanced/grains.csv" rows)
list(LENGTH rows row_count)
if(NOT variant_count EQUAL 2 OR NOT row_count EQUAL 51)
  message(FATAL_ERROR "instancing: ${variant_count} variant meshes, ${row_count} CSV lines")
endif()

foreach(bad "--cultivar;arborio" "--pore-radius-min;-1e-4" "--swell-max;1.6" "--count;0")
  run_rice(FALSE grains ${bad} --out "${OUT}/bad")
  if(EXISTS "${OUT}/bad")
    message(FATAL_ERROR "rice grains ${bad} wrote ${OUT}/bad")
  endif()
endforeach()
file(WRITE "${OUT}/open.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n")
run_rice(FALSE grains --base-mesh "${OUT}/open.obj" --out "${OUT}/bad")
if(EXISTS "${OUT}/bad")
  message(FATAL_ERROR "an open base mesh wrote ${OUT}/bad")
endif()
