# docs/scene-keys.md is what `rice scene-keys` prints from the reader's table of keys, byte for
# byte, so the scene-file reference cannot drift from the reader.
# Called by CTest with -DRICE=<rice binary> -DDOC=<docs/scene-keys.md>.
execute_process(COMMAND "${RICE}" scene-keys RESULT_VARIABLE result OUTPUT_VARIABLE printed ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "rice scene-keys exited with ${result}: ${error}")
endif()
file(READ "${DOC}" written)
if(NOT printed STREQUAL written)
  message(FATAL_ERROR "${DOC} differs from what `rice scene-keys` prints; regenerate it with\n"
                      "  build/experiments/rice scene-keys > docs/scene-keys.md")
endif()
