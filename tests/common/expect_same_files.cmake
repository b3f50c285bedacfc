# expect_same(EXPECTED ACTUAL WHAT FILE...): stops the CTest script when a FILE of folder ACTUAL
# is not byte for byte EXPECTED's, naming WHAT and the file. Included by the command tests.
function(expect_same expected actual what)
  foreach(file ${ARGN})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${expected}/${file}" "${actual}/${file}"
                    RESULT_VARIABLE different)
    if(different)
      message(FATAL_ERROR "${what} differ in ${file} (${expected} and ${actual})")
    endif()
  endforeach()
endfunction()
