# Imported targets for GMP and MPFR through pkg-config (Debian ships gmp.pc and mpfr.pc,
# no CMake config). Used both by the build and by the installed exidelConfig.cmake.
#
# The pkg-config results use the prefixes EXIDEL_GMP / EXIDEL_MPFR, not GMP / MPFR: the
# plain names would set GMP_LIBRARIES and MPFR_LIBRARIES (bare names, e.g. "mpfr;gmp"),
# which CGAL's FindGMP/FindMPFR take for full paths and then fail. The targets keep the
# names the build uses, PkgConfig::GMP and PkgConfig::MPFR, as aliases.
include_guard(GLOBAL)
find_package(PkgConfig REQUIRED)
# The installed package's targets link PkgConfig::EXIDEL_GMP / EXIDEL_MPFR (the alias
# resolves to them on export), so those must exist even if a consumer already has its
# own PkgConfig::GMP.
foreach(lib GMP MPFR)
  if(NOT TARGET PkgConfig::EXIDEL_${lib})
    string(TOLOWER ${lib} module)
    pkg_check_modules(EXIDEL_${lib} REQUIRED IMPORTED_TARGET GLOBAL ${module})
  endif()
  if(NOT TARGET PkgConfig::${lib})
    add_library(PkgConfig::${lib} ALIAS PkgConfig::EXIDEL_${lib})
  endif()
endforeach()
