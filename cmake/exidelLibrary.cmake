# exidel_add_library(<name> <sources...>): the library exidel_<name> with alias
# exidel::<name>, public headers in <dir>/include (installed under include/), C++20, and
# the floating-point hygiene of every exidel translation unit: -ffp-contract=off (no product
# and sum fused behind our back: Dekker's split and Two-Product break, and generated test
# inputs change; docs/background.md sections 1 and 2) and -fno-fast-math (which also overrides a parent
# project's global -ffast-math). PRIVATE: these never reach a consumer's compile lines.
#
# Only the libraries of the installed package (EXIDEL_PACKAGE_LIBRARIES, set by the
# top-level CMakeLists.txt) follow BUILD_SHARED_LIBS. The others (exidel::research, the
# instruments behind `exidel study`) are static, linked into the exidel command and the
# tests only: they link RapidCheck, and Debian's librapidcheck.a is not position-
# independent code, so a shared exidel_research fails to link ("recompile with -fPIC").
include_guard(GLOBAL)

# exidel_add_object_library(<name> <sources...>): the part of a library that other exidel
# targets link on their own, as the object library exidel_<name> (no alias, never
# installed): its objects go into the library that lists $<TARGET_OBJECTS:exidel_<name>>,
# and a target that links it gets them and its usage requirements. Same hygiene and
# warnings as exidel_add_library; position-independent in a shared build (the Python
# module sets it too).
function(exidel_add_object_library name)
  set(target exidel_${name})
  add_library(${target} OBJECT ${ARGN})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_compile_options(${target} PRIVATE -ffp-contract=off -fno-fast-math)
  if(BUILD_SHARED_LIBS)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  endif()
  exidel_warnings(${target})
endfunction()

function(exidel_add_library name)
  set(target exidel_${name})
  if(name IN_LIST EXIDEL_PACKAGE_LIBRARIES)
    add_library(${target} ${ARGN})
  else()
    add_library(${target} STATIC ${ARGN})
  endif()
  add_library(exidel::${name} ALIAS ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:include>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_compile_options(${target} PRIVATE -ffp-contract=off -fno-fast-math)
  # With BUILD_SHARED_LIBS: libexidel_<name>.so.0.1.0, SONAME libexidel_<name>.so.0.1.
  # While the major version is 0, every minor release may change the ABI (the templates'
  # explicit instantiations and every struct are part of it), so the SONAME carries the
  # minor version too. Static libraries ignore both properties.
  set_target_properties(${target} PROPERTIES
    VERSION ${exidel_VERSION}
    SOVERSION ${exidel_VERSION_MAJOR}.${exidel_VERSION_MINOR})
  exidel_warnings(${target})
endfunction()
