// exidel: what this copy of the library is and how it was built.
//
// For version banners (`exidel --version`) and for the reports of `exidel study`, whose
// long-double and MPFR results depend on the build and the machine: a reader must be able
// to tell which exidel, compiler, flags and number libraries produced a table.
//
//   const exidel::BuildInfo& b = exidel::build_info();
//   std::cout << "exidel " << b.version << " (" << b.commit << ")\n";
//
// Every field is fixed for the life of the process; the views point into static storage
// (string literals of the library, or GMP's and MPFR's own version strings).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace exidel {

struct BuildInfo {
    /// The project version, "0.1.0".
    std::string_view version;
    /// `git describe --always --dirty --abbrev=12` of the source tree when the library was
    /// last built (refreshed at every build, not only at configure time): a commit such as
    /// "2fd2885a1b2c", with "-dirty" appended when tracked files had uncommitted changes.
    /// "unknown" when the sources are not a git checkout or git is not installed.
    std::string_view commit;
    /// Compiler id and version as CMake identified them, "GNU 12.2.0".
    std::string_view compiler;
    /// The build type (CMAKE_BUILD_TYPE), "Release"; empty when none was set.
    std::string_view build_type;
    /// The flags the library's own sources were compiled with: the global C++ flags of the
    /// build type, the language standard, then the library's own options (floating-point
    /// hygiene, warnings).
    std::string_view cxx_flags;
    /// GMP and MPFR versions of the libraries linked at run time (gmp_version,
    /// mpfr_get_version()), which may differ from the headers exidel was compiled against.
    std::string_view gmp, mpfr;
    /// Boost version of the headers exidel was compiled against ("1.74"): Boost is used
    /// header-only, so there is no run-time version.
    std::string_view boost;
    /// The format of long double on this target: "x87 80-bit extended (64-bit significand)",
    /// "IEEE binary128 (113-bit significand)", "same as double (53-bit significand)", ...
    /// from std::numeric_limits<long double>::digits. The long-double kernel's results
    /// depend on it.
    std::string_view long_double;
    /// The spelling of every shipped predicate kernel, in the order of EXIDEL_KERNELS
    /// (exidel/predicates/registry.hpp): "double", "long-double", ..., "mpfr:<bits>".
    std::vector<std::string_view> kernels;
};

/// The facts above, computed once (thread-safe).
const BuildInfo& build_info();

/// The processor this process runs on: the first "model name" of /proc/cpuinfo, or
/// "unknown" where there is none (not Linux, or an architecture that does not report it).
/// A run-time fact, not a build fact, hence not a field of BuildInfo.
std::string cpu_model();

}  // namespace exidel
