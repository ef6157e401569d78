# Install and export exidel as a CMake package, the way fmt does: the targets under the
# exidel:: namespace, headers under include/exidel/, and exidelConfig.cmake +
# exidelConfigVersion.cmake in <libdir>/cmake/exidel.
#
# The package is made of components, one export set each, so that a dependency only one
# target needs (rapidcheck for exidel::testing) is only looked for when that target is
# wanted:
#
#   find_package(exidel 0.1 REQUIRED)                      default components
#   find_package(exidel 0.1 REQUIRED COMPONENTS testing)   and the optional ones asked for
#
# Adding a target to the package is one call in the top-level CMakeLists.txt:
#
#   exidel_install_component(<name> TARGETS <target>...
#       [DEFAULT]                   load it on a plain find_package(exidel)
#       [DEPENDENCIES <args>...]    each element: the arguments of one find_dependency()
#       [MODULES <file>...]         CMake files installed next to the config and included
#                                   before the targets (e.g. exidelFindNumerics.cmake)
#       [HEADERS <dir>...])         directories whose *contents* go to include/; default:
#                                   <target's source dir>/include if it exists
#
# Components must be added after the components their targets link to. Finish with
# exidel_install_finalize().
include_guard(GLOBAL)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(EXIDEL_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/exidel
    CACHE STRING "Where exidelConfig.cmake is installed, relative to the prefix")

function(exidel_install_component name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "DEFAULT" "" "TARGETS;DEPENDENCIES;MODULES;HEADERS")
  if(NOT arg_TARGETS)
    message(FATAL_ERROR "exidel_install_component(${name}): no TARGETS")
  endif()

  foreach(target IN LISTS arg_TARGETS)
    # exidel_predicates is exported as exidel::predicates: the same name the ALIAS gives
    # add_subdirectory users, so consumer code does not depend on how it found exidel.
    string(REGEX REPLACE "^exidel_" "" export_name ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
    if(NOT arg_HEADERS)
      get_target_property(source_dir ${target} SOURCE_DIR)
      if(IS_DIRECTORY ${source_dir}/include)
        list(APPEND arg_HEADERS ${source_dir}/include)
      endif()
    endif()
  endforeach()

  install(TARGETS ${arg_TARGETS} EXPORT exidel-${name}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  foreach(dir IN LISTS arg_HEADERS)
    # Trailing slash: install what is inside include/ (that is, exidel/...), so every
    # header lands under include/exidel/ and never at the include root.
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
            FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
  endforeach()
  install(EXPORT exidel-${name} NAMESPACE exidel:: FILE exidel-${name}-targets.cmake
          DESTINATION ${EXIDEL_INSTALL_CMAKEDIR})

  # The config file's section for this component: its dependencies, then its targets.
  set(section "\n# Component ${name}: ${arg_TARGETS}\n")
  string(APPEND section "if(\"${name}\" IN_LIST _exidel_load)\n")
  foreach(module IN LISTS arg_MODULES)
    get_filename_component(module_name ${module} NAME)
    install(FILES ${module} DESTINATION ${EXIDEL_INSTALL_CMAKEDIR})
    string(APPEND section "  include(\"\${CMAKE_CURRENT_LIST_DIR}/${module_name}\")\n")
  endforeach()
  foreach(dependency IN LISTS arg_DEPENDENCIES)
    string(APPEND section "  find_dependency(${dependency})\n")
  endforeach()
  string(APPEND section
    "  include(\"\${CMAKE_CURRENT_LIST_DIR}/exidel-${name}-targets.cmake\")\n"
    "  set(exidel_${name}_FOUND TRUE)\n"
    "endif()\n")

  set_property(GLOBAL APPEND_STRING PROPERTY EXIDEL_CONFIG_SECTIONS "${section}")
  set_property(GLOBAL APPEND PROPERTY EXIDEL_COMPONENTS ${name})
  if(arg_DEFAULT)
    set_property(GLOBAL APPEND PROPERTY EXIDEL_DEFAULT_COMPONENTS ${name})
  endif()
endfunction()

function(exidel_install_finalize)
  get_property(EXIDEL_CONFIG_SECTIONS GLOBAL PROPERTY EXIDEL_CONFIG_SECTIONS)
  get_property(EXIDEL_COMPONENTS GLOBAL PROPERTY EXIDEL_COMPONENTS)
  get_property(EXIDEL_DEFAULT_COMPONENTS GLOBAL PROPERTY EXIDEL_DEFAULT_COMPONENTS)
  set(build_dir ${PROJECT_BINARY_DIR}/exidel-package)
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/exidelConfig.cmake.in
    ${build_dir}/exidelConfig.cmake
    INSTALL_DESTINATION ${EXIDEL_INSTALL_CMAKEDIR})
  # 0.x releases follow fmt: a consumer asking for 0.1 accepts any 0.y >= 0.1.
  write_basic_package_version_file(${build_dir}/exidelConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
  install(FILES ${build_dir}/exidelConfig.cmake ${build_dir}/exidelConfigVersion.cmake
          DESTINATION ${EXIDEL_INSTALL_CMAKEDIR})
endfunction()

# exidel_install_pkgconfig(<target>...): installs <libdir>/pkgconfig/exidel.pc, whose
# Libs name the targets in the order given (a library before the ones it uses, as a static
# link needs). GMP and MPFR come from their own .pc files (Debian ships gmp.pc and mpfr.pc).
function(exidel_install_pkgconfig)
  set(libs "")
  foreach(target IN LISTS ARGN)
    get_target_property(name ${target} OUTPUT_NAME)
    if(NOT name)
      set(name ${target})
    endif()
    string(APPEND libs " -l${name}")
  endforeach()
  set(EXIDEL_PC_LIBS "${libs}")
  # A static exidel_predicates leaves GMP and MPFR to the final link, so every consumer
  # needs them: Requires. A shared one carries them as its own dependencies: Requires.private,
  # needed only by `pkg-config --static`.
  get_target_property(type exidel_predicates TYPE)
  if(type STREQUAL "STATIC_LIBRARY")
    set(EXIDEL_PC_REQUIRES "Requires: gmp mpfr")
  else()
    set(EXIDEL_PC_REQUIRES "Requires.private: gmp mpfr")
  endif()
  set(pcdir ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
  # Paths relative to the prefix unless the install directories were given as absolute.
  foreach(kind LIBDIR INCLUDEDIR)
    if(IS_ABSOLUTE "${CMAKE_INSTALL_${kind}}")
      set(EXIDEL_PC_${kind} "${CMAKE_INSTALL_${kind}}")
    else()
      set(EXIDEL_PC_${kind} "\${prefix}/${CMAKE_INSTALL_${kind}}")
    endif()
  endforeach()
  if(IS_ABSOLUTE "${pcdir}")
    set(EXIDEL_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  else()
    file(RELATIVE_PATH up /exidel-prefix/${pcdir} /exidel-prefix)
    string(REGEX REPLACE "/$" "" up "${up}")
    set(EXIDEL_PC_PREFIX "\${pcfiledir}/${up}")
  endif()
  set(output ${PROJECT_BINARY_DIR}/exidel-package/exidel.pc)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/exidel.pc.in ${output} @ONLY)
  install(FILES ${output} DESTINATION ${pcdir})
endfunction()
