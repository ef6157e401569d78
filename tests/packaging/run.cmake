# Run by ctest (see CMakeLists.txt):
#   cmake -DMODE=install|subdirectory -DEXIDEL_SOURCE_DIR=... -DCONSUMER_SOURCE_DIR=...
#         -DWORK_DIR=... -DCMAKE_GENERATOR=... -DCXX_COMPILER=... -P run.cmake
#
# install:      build exidel, install it into WORK_DIR/prefix, check the installed layout,
#               then build and run the consumer with find_package(exidel 0.1 REQUIRED); also
#               check that a consumer asking for an incompatible version (1.0) is refused.
#               With -DBUILD_DIR=<a built exidel tree>, exidel is not built again: that
#               tree is installed (`cmake --install`) and checked the same way.
# subdirectory: build and run the same consumer with add_subdirectory(<exidel source>).
cmake_minimum_required(VERSION 3.25)

include(${CMAKE_CURRENT_LIST_DIR}/common.cmake)  # run(), fresh_work_dir()
fresh_work_dir(run.cmake MODE EXIDEL_SOURCE_DIR CONSUMER_SOURCE_DIR WORK_DIR CMAKE_GENERATOR
               CXX_COMPILER)

if(MODE STREQUAL "install")
  set(prefix ${WORK_DIR}/prefix)
  if(DEFINED BUILD_DIR)
    # The tree ctest runs in, built already: its install rules and exported targets are
    # the ones a user's `cmake --install build` runs.
    run("install exidel from ${BUILD_DIR}" ${CMAKE_COMMAND} --install ${BUILD_DIR}
        --prefix ${prefix})
  else()
    run("configure exidel" ${CMAKE_COMMAND} -S ${EXIDEL_SOURCE_DIR} -B ${WORK_DIR}/exidel
        ${common_args} -DEXIDEL_BUILD_TESTS=OFF -DEXIDEL_BUILD_CLI=OFF
        -DEXIDEL_BUILD_BENCH=OFF -DEXIDEL_BUILD_PYTHON=OFF -DEXIDEL_INSTALL=ON)
    # Only the libraries the package installs: exidel::research (not installed) takes most
    # of a full build's time here, and the main build compiles it anyway.
    run("build exidel" ${CMAKE_COMMAND} --build ${WORK_DIR}/exidel
        --target exidel_predicates exidel_delaunay exidel_io)
    run("install exidel" ${CMAKE_COMMAND} --install ${WORK_DIR}/exidel --prefix ${prefix})
  endif()

  # The layout consumers and packagers rely on.
  set(cmakedir ${prefix}/lib/cmake/exidel)
  foreach(file ${cmakedir}/exidelConfig.cmake ${cmakedir}/exidelConfigVersion.cmake
               ${cmakedir}/exidelFindNumerics.cmake
               ${cmakedir}/exidel-predicates-targets.cmake
               ${prefix}/include/exidel/predicates/all.hpp
               ${prefix}/include/exidel/predicates/kernel.hpp
               ${prefix}/lib/pkgconfig/exidel.pc)
    if(NOT EXISTS ${file})
      message(FATAL_ERROR "installed package lacks ${file}")
    endif()
  endforeach()
  file(GLOB stray LIST_DIRECTORIES true ${prefix}/include/*)
  if(NOT stray STREQUAL "${prefix}/include/exidel")
    message(FATAL_ERROR "only include/exidel/ may be installed at the include root, found: ${stray}")
  endif()
  file(GLOB_RECURSE private_headers ${prefix}/include/*formulas.hpp ${prefix}/include/*fp_hygiene.hpp)
  if(private_headers)
    message(FATAL_ERROR "private headers were installed: ${private_headers}")
  endif()
  file(GLOB archives ${prefix}/lib/*exidel_predicates*)
  if(NOT archives)
    message(FATAL_ERROR "libexidel_predicates was not installed in ${prefix}/lib")
  endif()

  set(consumer_args -DCMAKE_PREFIX_PATH=${prefix})
  # SameMajorVersion: a consumer that needs exidel 1.0 must be refused by 0.x.
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR}
                          -B ${WORK_DIR}/consumer-wrong-version ${common_args}
                          ${consumer_args} -DEXIDEL_WANTED_VERSION=1.0
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc EQUAL 0 OR NOT out MATCHES "requested version \"1.0\"")
    message(FATAL_ERROR "find_package(exidel 1.0) should fail on a version mismatch (exit ${rc}):\n${out}")
  endif()
  message(STATUS "find_package(exidel 1.0) refused: ok")
  # An unknown required component must fail cleanly, not load half a package.
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR}
                          -B ${WORK_DIR}/consumer-bad-component ${common_args}
                          ${consumer_args} -DEXIDEL_WANTED_COMPONENTS=no_such_component
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc EQUAL 0 OR NOT out MATCHES "no_such_component")
    message(FATAL_ERROR "find_package(exidel COMPONENTS no_such_component) should fail (exit ${rc}):\n${out}")
  endif()
  message(STATUS "find_package(exidel COMPONENTS no_such_component) refused: ok")
  # The optional testing component (RapidCheck generators) is installed when exidel was
  # built with RapidCheck available; if so, asking for it must work.
  if(EXISTS ${cmakedir}/exidel-testing-targets.cmake)
    run("configure consumer with COMPONENTS testing" ${CMAKE_COMMAND}
        -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/consumer-testing ${common_args}
        ${consumer_args} -DEXIDEL_WANTED_COMPONENTS=testing)
  endif()
elseif(MODE STREQUAL "subdirectory")
  set(consumer_args -DEXIDEL_FROM_SOURCE=${EXIDEL_SOURCE_DIR})
else()
  message(FATAL_ERROR "run.cmake: MODE must be install or subdirectory, not '${MODE}'")
endif()

run("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/consumer
    ${common_args} ${consumer_args})
if(MODE STREQUAL "subdirectory" AND NOT last_output MATCHES "exidel consumer: exidel from source")
  message(FATAL_ERROR "consumer did not take exidel from the source tree:\n${last_output}")
endif()
# The consumer and what it links: with add_subdirectory, `all` would also build exidel's
# unrelated targets (exidel::research), which the main build covers.
run("build consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer --target exidel-consumer)
run("run consumer" ${WORK_DIR}/consumer/exidel-consumer)
message(STATUS "${last_output}")
