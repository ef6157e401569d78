# cmake -DBUILD_DIR=... -DTARGET=... [-DCONFIG=...] -DEXPECTED=<text> -P expect_build_failure.cmake
# Builds TARGET and passes only if the build fails with EXPECTED in its output: a build
# that fails for any other reason (a missing header, a syntax error) is a test failure.
foreach(var BUILD_DIR TARGET EXPECTED)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_build_failure.cmake: -D${var}=... is required")
  endif()
endforeach()
set(config_args)
if(CONFIG)
  set(config_args --config ${CONFIG})
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${TARGET} ${config_args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0)
  message(FATAL_ERROR "${TARGET} built, but it must be refused:\n${out}")
endif()
string(FIND "${out}" "${EXPECTED}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${TARGET} failed, but not with \"${EXPECTED}\":\n${out}")
endif()
message(STATUS "${TARGET} refused as expected")
