# exidel_warnings(<target>...): the warning set every target of this project compiles
# with. PRIVATE on purpose: a consumer of exidel chooses its own warnings, so nothing here
# may reach its compile lines (so no global CMAKE_CXX_FLAGS changes either).
#
# The top-level CMakeLists.txt also calls exidel_warnings_everywhere() after every
# subdirectory is added, so a target someone forgot to mark still gets the flags; calling
# exidel_warnings() yourself documents the intent next to the target.
include_guard(GLOBAL)

option(EXIDEL_WERROR "Turn exidel's own compiler warnings into errors" OFF)

function(exidel_warnings)
  foreach(target IN LISTS ARGN)
    get_target_property(type ${target} TYPE)
    get_target_property(imported ${target} IMPORTED)
    # INTERFACE libraries compile nothing; imported targets are not ours.
    if(type STREQUAL "INTERFACE_LIBRARY" OR type STREQUAL "UTILITY" OR imported)
      continue()
    endif()
    if(MSVC)
      target_compile_options(${target} PRIVATE /W4 $<$<BOOL:${EXIDEL_WERROR}>:/WX>)
    else()
      target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic
                             $<$<BOOL:${EXIDEL_WERROR}>:-Werror>)
    endif()
  endforeach()
endfunction()

# Applies exidel_warnings to every target defined in <dir> and its subdirectories.
# Target-level compile options are de-duplicated by CMake, so targets that already call
# exidel_warnings() are not affected twice.
function(exidel_warnings_everywhere dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  exidel_warnings(${targets})
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    exidel_warnings_everywhere(${sub})
  endforeach()
endfunction()
