# ctest fuzz.build: configures and builds the libFuzzer harnesses of fuzz/ with clang in
# WORK_DIR (everything instrumented with ASan + UBSan), or says "SKIPPED:" and why (the
# test's SKIP_REGULAR_EXPRESSION) when clang or its libFuzzer runtime is missing.
#   cmake -DSOURCE_DIR=<exidel> -DWORK_DIR=<dir> -DCLANGXX=<clang++ or empty> -DGENERATOR=<g> -P build.cmake
if(NOT CLANGXX)
  message("SKIPPED: clang++ not found (Debian: apt-get install clang libclang-rt-dev); the fuzz tests need it")
  return()
endif()
file(MAKE_DIRECTORY ${WORK_DIR}/probe)
file(WRITE ${WORK_DIR}/probe/probe.cpp
     "#include <cstddef>\n#include <cstdint>\nextern \"C\" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }\n")
execute_process(COMMAND ${CLANGXX} -fsanitize=fuzzer,address,undefined ${WORK_DIR}/probe/probe.cpp
                        -o ${WORK_DIR}/probe/probe
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message("SKIPPED: ${CLANGXX} cannot link -fsanitize=fuzzer (Debian: apt-get install libclang-rt-dev):\n${err}")
  return()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/fuzz -B ${WORK_DIR}/build -G ${GENERATOR}
                        -DCMAKE_CXX_COMPILER=${CLANGXX}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configuring fuzz/ failed")
endif()
# One job: ctest runs the rest of the suite on the other core meanwhile.
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build -j 1 RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "building the fuzz harnesses failed")
endif()
