# Shared by the packaging scripts (run.cmake, readme.cmake), included in script mode.
include_guard(GLOBAL)

# run(<what> <command>...): run a step, fail the test with its output if it fails; the
# output is left in `last_output` for the caller.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (exit ${rc}):\n${out}")
  endif()
  message(STATUS "${what}: ok")
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
