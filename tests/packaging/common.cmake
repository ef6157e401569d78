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

# fresh_work_dir(<script> <var>...): every -D<var>=... is given, and WORK_DIR is emptied
# (fresh trees every run: a stale cache would hide a broken package). Also the build
# arguments every step uses, in common_args.
macro(fresh_work_dir script)
  foreach(var ${ARGN})
    if(NOT DEFINED ${var})
      message(FATAL_ERROR "${script}: -D${var}=... is required")
    endif()
  endforeach()
  file(REMOVE_RECURSE ${WORK_DIR})
  file(MAKE_DIRECTORY ${WORK_DIR})
  set(common_args -G ${CMAKE_GENERATOR} -DCMAKE_BUILD_TYPE=Release
      -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endmacro()
