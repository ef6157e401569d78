# Search prefixes that survive a merged /usr.
#
# find_package() derives a search prefix from every PATH entry (the parent of each bin/
# directory). On a system where /bin is a symbolic link to /usr/bin (Debian 12 and most
# distributions since), PATH=/bin:/usr/bin yields the prefix "/" first, so packages are
# found as /lib/x86_64-linux-gnu/cmake/<Name>. Some package files compute their install
# prefix from their own location: CGAL's then says "/" and looks for /include/CGAL, finds
# nothing, and sets CGAL_FOUND to FALSE. Prepending the real location of each such bin/
# directory's parent (here /usr) to CMAKE_PREFIX_PATH, which is searched before PATH,
# makes the configure step independent of the order of /bin and /usr/bin in PATH.
if(CMAKE_HOST_UNIX)
  set(_exidel_path "$ENV{PATH}")
  string(REPLACE ":" ";" _exidel_path "${_exidel_path}")
  set(_exidel_real_prefixes "")
  foreach(_exidel_dir IN LISTS _exidel_path)
    if(NOT _exidel_dir MATCHES "/s?bin/?$" OR NOT IS_DIRECTORY "${_exidel_dir}")
      continue()
    endif()
    get_filename_component(_exidel_prefix "${_exidel_dir}" DIRECTORY)
    file(REAL_PATH "${_exidel_dir}" _exidel_real_dir)
    get_filename_component(_exidel_real_prefix "${_exidel_real_dir}" DIRECTORY)
    if(NOT _exidel_real_prefix STREQUAL _exidel_prefix)
      list(APPEND _exidel_real_prefixes "${_exidel_real_prefix}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES _exidel_real_prefixes)
  list(PREPEND CMAKE_PREFIX_PATH ${_exidel_real_prefixes})
  unset(_exidel_path)
  unset(_exidel_dir)
  unset(_exidel_prefix)
  unset(_exidel_real_dir)
  unset(_exidel_real_prefix)
  unset(_exidel_real_prefixes)
endif()
