# Run by ctest (see CMakeLists.txt): the program, CMakeLists.txt, pkg-config line and
# output of README.md's "Using exidel from your project", built against an installed
# exidel exactly as a user would, so that README and package cannot drift apart.
#
#   cmake -DMODE=static -DPREFIX=<installed exidel> -DREADME=... -DWORK_DIR=...
#         -DCMAKE_GENERATOR=... -DCXX_COMPILER=... -P readme.cmake
#   cmake -DMODE=shared -DEXIDEL_SOURCE_DIR=... -DREADME=... -DWORK_DIR=...
#         -DCMAKE_GENERATOR=... -DCXX_COMPILER=... -P readme.cmake
#
# static: PREFIX is the install tree packaging.find_package leaves behind (its fixture), so
#         exidel is not built once more. The program is built with CMake (-Wall -Wextra
#         -Wpedantic -Werror), with CMake and -ffast-math -O3 -march=native as its own
#         flags, and with README's pkg-config line.
# shared: builds and installs exidel's libraries with BUILD_SHARED_LIBS=ON, checks their
#         SONAME, RUNPATH and that the floating-point hygiene flags stayed PRIVATE, then
#         builds the program against them with -ffast-math -O3 -march=native.
# Each build must print exactly README's output block.
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake)

fresh_work_dir(readme.cmake MODE README WORK_DIR CMAKE_GENERATOR CXX_COMPILER)
# The flags a geometry user's build may well have; exidel's answers must not depend on them.
set(user_flags "-ffast-math -O3 -march=native")

# readme_block(<name> <var>): the fenced block right after the line
# "<!-- readme-test: <name> -->" in README.md, without its fences. The marker must occur
# once and be followed by nothing but blank space before the fence, so a marker cannot
# silently attach to a later block.
file(READ ${README} readme)
function(readme_block name out_var)
  set(marker "<!-- readme-test: ${name} -->")
  string(FIND "${readme}" "${marker}" first)
  string(FIND "${readme}" "${marker}" last REVERSE)
  if(first EQUAL -1)
    message(FATAL_ERROR "${README} has no line ${marker}")
  endif()
  if(NOT first EQUAL last)
    message(FATAL_ERROR "${README} has the line ${marker} more than once")
  endif()
  string(LENGTH "${marker}" length)
  math(EXPR after "${first} + ${length}")
  string(SUBSTRING "${readme}" ${after} -1 rest)
  string(FIND "${rest}" "```" fence)
  string(SUBSTRING "${rest}" 0 ${fence} gap)
  if(fence EQUAL -1 OR NOT gap MATCHES "^[ \t\r\n]*$")
    message(FATAL_ERROR "${README}: ${marker} must be followed by a ``` block")
  endif()
  # Skip the opening fence line (with its info string), then cut at the closing fence.
  string(SUBSTRING "${rest}" ${fence} -1 rest)
  string(FIND "${rest}" "\n" eol)
  math(EXPR eol "${eol} + 1")
  string(SUBSTRING "${rest}" ${eol} -1 rest)
  string(FIND "${rest}" "```" close)
  if(close EQUAL -1)
    message(FATAL_ERROR "${README}: the block after ${marker} is not closed")
  endif()
  string(SUBSTRING "${rest}" 0 ${close} block)
  set(${out_var} "${block}" PARENT_SCOPE)
endfunction()

readme_block(main.cpp readme_program)
readme_block(CMakeLists.txt cmakelists)
readme_block(output expected)
readme_block(pkg-config pkg_config_line)
string(STRIP "${expected}" expected)
string(STRIP "${pkg_config_line}" pkg_config_line)
if(expected STREQUAL "")
  message(FATAL_ERROR "README's output block is empty")
endif()

# check_output(<what> <command>...): runs it; its output must be README's (surrounding
# blank space aside).
function(check_output what)
  run("run ${what}" ${ARGN})
  string(STRIP "${last_output}" got)
  if(NOT got STREQUAL expected)
    message(FATAL_ERROR "${what} printed\n${got}\nbut README.md says it prints\n${expected}")
  endif()
  message(STATUS "${what} printed README's output: ${got}")
endfunction()

# user_project(<name> <prefix> <CXX flags>): README's project in WORK_DIR/<name>, built
# with CMake against <prefix>; sets `app` in the caller to the built executable.
function(user_project name prefix flags)
  set(dir ${WORK_DIR}/${name})
  file(WRITE ${dir}/main.cpp "${readme_program}")
  file(WRITE ${dir}/CMakeLists.txt "${cmakelists}")
  run("configure ${name}" ${CMAKE_COMMAND} -S ${dir} -B ${dir}/build ${common_args}
      -DCMAKE_PREFIX_PATH=${prefix} "-DCMAKE_CXX_FLAGS=${flags}")
  run("build ${name}" ${CMAKE_COMMAND} --build ${dir}/build)
  # my_app: the target README's CMakeLists.txt defines and its text runs.
  set(app ${dir}/build/my_app PARENT_SCOPE)
endfunction()

# Nothing exidel compiles with may reach a consumer: the hygiene options are PRIVATE.
function(check_no_hygiene_flags_exported prefix)
  file(GLOB exported ${prefix}/lib/cmake/exidel/exidel-*-targets*.cmake ${prefix}/lib/pkgconfig/exidel.pc)
  foreach(file IN LISTS exported)
    file(READ ${file} text)
    if(text MATCHES "ffp-contract|fast-math|-Wall|-Wextra")
      message(FATAL_ERROR "${file} passes exidel's own compile options on to consumers")
    endif()
  endforeach()
endfunction()

if(MODE STREQUAL "static")
  if(NOT EXISTS ${PREFIX}/lib/cmake/exidel/exidelConfig.cmake)
    message(FATAL_ERROR "no installed exidel in ${PREFIX} (packaging.find_package installs it)")
  endif()
  check_no_hygiene_flags_exported(${PREFIX})

  # With the project's warning set as errors: README's program, and every installed
  # header it includes, compile warning-free in a consumer's build.
  user_project(cmake ${PREFIX} "-Wall -Wextra -Wpedantic -Werror")
  check_output("README program (CMake, warnings as errors)" ${app})
  user_project(cmake-fast-math ${PREFIX} "${user_flags}")
  check_output("README program (CMake, ${user_flags})" ${app})

  # README's pkg-config line, as written, in a shell, with the prefix's exidel.pc.
  find_program(PKG_CONFIG pkg-config)
  if(NOT PKG_CONFIG)
    message(FATAL_ERROR "pkg-config not found (Debian: pkg-config; scripts/dev installs it)")
  endif()
  set(pcdir ${PREFIX}/lib/pkgconfig)
  if(NOT EXISTS ${pcdir}/exidel.pc)
    message(FATAL_ERROR "${pcdir}/exidel.pc was not installed")
  endif()
  run("pkg-config --validate exidel" ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${pcdir}
      ${PKG_CONFIG} --validate exidel)
  set(dir ${WORK_DIR}/pkg-config)
  file(WRITE ${dir}/main.cpp "${readme_program}")
  run("build README program (${pkg_config_line})" ${CMAKE_COMMAND} -E chdir ${dir}
      ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${pcdir} sh -c "${pkg_config_line}")
  check_output("README program (pkg-config)" ${dir}/my_app)
elseif(MODE STREQUAL "shared")
  if(NOT DEFINED EXIDEL_SOURCE_DIR)
    message(FATAL_ERROR "readme.cmake: MODE=shared needs -DEXIDEL_SOURCE_DIR=...")
  endif()
  set(prefix ${WORK_DIR}/prefix)
  set(build ${WORK_DIR}/exidel)
  run("configure exidel (shared)" ${CMAKE_COMMAND} -S ${EXIDEL_SOURCE_DIR} -B ${build}
      ${common_args} -DBUILD_SHARED_LIBS=ON -DEXIDEL_BUILD_TESTS=OFF -DEXIDEL_BUILD_CLI=OFF
      -DEXIDEL_BUILD_BENCH=OFF -DEXIDEL_BUILD_PYTHON=OFF -DEXIDEL_INSTALL=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)
  # Only the installed libraries: exidel::research and the example are not installed, and
  # building them would only cost time here.
  set(libraries predicates delaunay io)
  list(TRANSFORM libraries PREPEND exidel_ OUTPUT_VARIABLE targets)
  run("build exidel (shared)" ${CMAKE_COMMAND} --build ${build} --target ${targets})
  run("install exidel (shared)" ${CMAKE_COMMAND} --install ${build} --prefix ${prefix})

  # Every source of the libraries compiled with the hygiene options (and so as PIC code
  # of a shared library with them): the compile database of this build says so.
  file(READ ${build}/compile_commands.json commands)
  string(JSON count LENGTH "${commands}")
  math(EXPR last "${count} - 1")
  set(compiled 0)
  foreach(i RANGE ${last})
    string(JSON command GET "${commands}" ${i} command)
    string(JSON source GET "${commands}" ${i} file)
    if(NOT source MATCHES "/(predicates|lib/delaunay|lib/io)/src/")
      continue()
    endif()
    math(EXPR compiled "${compiled} + 1")
    if(NOT command MATCHES " -ffp-contract=off" OR NOT command MATCHES " -fno-fast-math"
       OR NOT command MATCHES " -fPIC")
      message(FATAL_ERROR "${source} is not compiled with -fPIC -ffp-contract=off -fno-fast-math:\n${command}")
    endif()
  endforeach()
  if(compiled EQUAL 0)
    message(FATAL_ERROR "no source of the libraries in ${build}/compile_commands.json")
  endif()
  message(STATUS "${compiled} library sources compiled with the hygiene options: ok")
  check_no_hygiene_flags_exported(${prefix})

  # libexidel_<name>.so -> .so.<SOVERSION> -> .so.<VERSION>, the SONAME is the middle
  # name, and RUNPATH $ORIGIN lets the libraries find each other wherever the prefix is.
  find_program(READELF readelf)
  if(NOT READELF)
    message(FATAL_ERROR "readelf not found (Debian: binutils, which g++ depends on)")
  endif()
  foreach(name IN LISTS libraries)
    set(lib ${prefix}/lib/libexidel_${name}.so)
    file(GLOB archives ${prefix}/lib/libexidel_${name}.a)
    if(archives OR NOT IS_SYMLINK ${lib})
      message(FATAL_ERROR "${lib} should be a symbolic link to a shared library, and no .a installed")
    endif()
    file(READ_SYMLINK ${lib} soname)
    file(READ_SYMLINK ${prefix}/lib/${soname} real)
    if(NOT soname MATCHES "^libexidel_${name}\\.so\\.0\\.[0-9]+$" OR
       NOT real MATCHES "^${soname}\\.[0-9]+$" OR NOT EXISTS ${prefix}/lib/${real})
      message(FATAL_ERROR "unexpected shared library names: ${lib} -> ${soname} -> ${real}")
    endif()
    run("readelf -d ${real}" ${READELF} -d ${prefix}/lib/${real})
    if(NOT last_output MATCHES "Library soname: \\[${soname}\\]")
      message(FATAL_ERROR "${real} lacks the SONAME ${soname}:\n${last_output}")
    endif()
    if(NOT last_output MATCHES "(RUNPATH|RPATH)[^\n]*\\[\\$ORIGIN\\]")
      message(FATAL_ERROR "${real} lacks the RUNPATH $ORIGIN:\n${last_output}")
    endif()
  endforeach()
  message(STATUS "shared libraries, SONAME and RUNPATH: ok")

  user_project(cmake-fast-math ${prefix} "${user_flags}")
  run("readelf -d my_app" ${READELF} -d ${app})
  if(NOT last_output MATCHES "NEEDED[^\n]*libexidel_delaunay\\.so\\.")
    message(FATAL_ERROR "the program does not use the shared libexidel_delaunay:\n${last_output}")
  endif()
  # Run with no library path: the installed libraries are found through the RUNPATH CMake
  # gave the program and the libraries' own $ORIGIN.
  check_output("README program (shared exidel, ${user_flags})"
               ${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH ${app})
else()
  message(FATAL_ERROR "readme.cmake: MODE must be static or shared, not '${MODE}'")
endif()
