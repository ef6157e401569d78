// exidel: build_info(), from two generated files of the build tree (neither installed):
//   exidel_build_config.hpp  version, compiler, flags (file(GENERATE) at configure time)
//   exidel_git_commit.hpp    the commit (rewritten at every build when it changes)
#include "exidel/predicates/build_info.hpp"

#include <gmp.h>
#include <mpfr.h>

#include <boost/version.hpp>
#include <fstream>
#include <limits>
#include <string>

#include "exidel/predicates/registry.hpp"
// No geometry here, but every translation unit of the library refuses -ffast-math
// (tests/hygiene preprocesses each one with it). Before the generated headers, so that the
// refusal is reported even where they have not been generated yet.
#include "exidel/predicates/internal/fp_hygiene.hpp"
// Generated in the build tree (predicates/CMakeLists.txt).
#include "exidel_build_config.hpp"
#include "exidel_git_commit.hpp"

namespace exidel {

namespace {

std::string_view long_double_format() {
    // The significand width identifies the format on every platform exidel builds on.
    switch (std::numeric_limits<long double>::digits) {
        case 53: return "same as double (IEEE binary64, 53-bit significand)";
        case 64: return "x87 80-bit extended (64-bit significand)";
        case 106: return "double-double (106-bit significand)";
        case 113: return "IEEE binary128 (113-bit significand)";
        default: return "unrecognised format";
    }
}

BuildInfo make_build_info() {
    // BOOST_LIB_VERSION is "1_74" (or "1_74_1"); the dotted form is what users type.
    static const std::string boost = [] {
        std::string v = BOOST_LIB_VERSION;
        for (char& c : v) c = c == '_' ? '.' : c;
        return v;
    }();
    BuildInfo b;
    b.version = EXIDEL_VERSION_STRING;
    b.commit = EXIDEL_GIT_COMMIT;
    b.compiler = EXIDEL_COMPILER;
    b.build_type = EXIDEL_BUILD_TYPE;
    // The flags are concatenated from pieces that may be empty: one space between flags.
    static const std::string flags = [] {
        std::string out;
        for (const char* c = EXIDEL_CXX_FLAGS; *c; ++c) {
            const bool space = *c == ' ';
            if (space && (out.empty() || out.back() == ' ')) continue;
            out += *c;
        }
        if (!out.empty() && out.back() == ' ') out.pop_back();
        return out;
    }();
    b.cxx_flags = flags;
    b.gmp = gmp_version;
    b.mpfr = mpfr_get_version();
    b.boost = boost;
    b.long_double = long_double_format();
#define EXIDEL_KERNEL_SPELLING_(K, spelling, summary) b.kernels.emplace_back(spelling);
    EXIDEL_KERNELS(EXIDEL_KERNEL_SPELLING_)
#undef EXIDEL_KERNEL_SPELLING_
    return b;
}

}  // namespace

const BuildInfo& build_info() {
    static const BuildInfo info = make_build_info();
    return info;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        // "model name\t: Intel(R) Xeon(R) ..." (x86); other architectures have no such line.
        if (!line.starts_with("model name")) continue;
        const std::size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        const std::size_t start = line.find_first_not_of(" \t", colon + 1);
        if (start == std::string::npos) continue;
        return line.substr(start);
    }
    return "unknown";
}

}  // namespace exidel
