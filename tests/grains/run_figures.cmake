# `rice figure 8`, `9` (two grains per cultivar) and `11` end to end: their tables and images
# are written, the tables have the expected rows, and run_info.txt records a 64-bit seed. Called by CTest with
# -DRICE=<rice binary> -DOUT=<scratch folder>.
file(REMOVE_RECURSE "${OUT}")

function(run_figure number)
  execute_process(COMMAND "${RICE}" figure ${number} ${ARGN} --out "${OUT}/${number}" RESULT_VARIABLE result
                  OUTPUT_QUIET)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "rice figure ${number} exited with ${result}")
  endif()
endfunction()

function(expect_lines file count)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "missing ${file}")
  endif()
  file(STRINGS "${file}" rows)
  list(LENGTH rows lines)
  if(NOT lines EQUAL count)
    message(FATAL_ERROR "${file} has ${lines} lines, expected ${count}")
  endif()
endfunction()

run_figure(8)
expect_lines("${OUT}/8/figure8.csv" 6)  # header and five sizes
# The largest seed, which a signed cell would have written as -1.
run_figure(9 --count 2 --seed 18446744073709551615)
expect_lines("${OUT}/9/figure9.csv" 10)  # header and 3 cultivars x 3 dimensions
file(STRINGS "${OUT}/9/run_info.txt" seed_line REGEX "^seed: ")
if(NOT seed_line STREQUAL "seed: 18446744073709551615")
  message(FATAL_ERROR "run_info.txt of figure 9 has '${seed_line}', expected the seed given")
endif()
run_figure(11)
expect_lines("${OUT}/11/damping_fits.csv" 5)  # header and the table's 4 temperatures
foreach(file 8/figure8_sections.png 9/figure9_sections.png 11/peleg_fits.csv 11/absorption_curves.csv)
  if(NOT EXISTS "${OUT}/${file}")
    message(FATAL_ERROR "missing ${OUT}/${file}")
  endif()
endforeach()
