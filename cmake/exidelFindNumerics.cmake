# Imported targets for GMP and MPFR through pkg-config (Debian ships gmp.pc and mpfr.pc,
# no CMake config). Used both by the build and by the installed exidelConfig.cmake.
include_guard(GLOBAL)
find_package(PkgConfig REQUIRED)
if(NOT TARGET PkgConfig::GMP)
  pkg_check_modules(GMP REQUIRED IMPORTED_TARGET GLOBAL gmp)
endif()
if(NOT TARGET PkgConfig::MPFR)
  pkg_check_modules(MPFR REQUIRED IMPORTED_TARGET GLOBAL mpfr)
endif()
