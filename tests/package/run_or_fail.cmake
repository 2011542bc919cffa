# run(COMMAND...): runs a command in a cmake -P script and stops the script with the command and
# its output when it fails (tests/package and tests/embed drive CMake builds with it).
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${ARGN}\n${out}")
  endif()
endfunction()
