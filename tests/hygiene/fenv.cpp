// exidel hygiene test: every exact kernel must give the exact sign in any floating-point
// environment a caller can leave behind: directed rounding (fesetround), and on x86
// flush-to-zero / denormals-are-zero (what -ffast-math, many audio and game engines set),
// including on subnormal coordinates. Each kernel must also leave the environment as it
// found it. The reference answers are GMP's, computed in the default environment.
//
//   exidel-hygiene-fenv adaptive|exact|exact-cpp    one kernel; exit code 1 on any wrong sign
#include <cstdio>
#include <cstring>
#include <string>

#include "evaluate.hpp"
#include "fp_environment.hpp"
#include "queries.hpp"

using namespace exidel;
using namespace exidel::hygiene;

namespace {

// Evaluates `kernel` over `family` in `env`; counts wrong signs and environment changes.
template <class Kernel>
std::size_t check(const Kernel& kernel, const Environment& env, const QueryFamily& family,
                  const Signs& exact) {
    set_controls(env.rounding, env.ftz_daz);
    const FpControls before = current_controls();
    const Signs got = evaluate(kernel, family);
    const FpControls after = current_controls();
    set_controls(FE_TONEAREST, 0);

    const std::string label = kernel.name() + " in " + env.name;
    std::size_t bad = count_mismatches(label.c_str(), family, got, exact);
    if (!(before == after)) {
        std::printf(
            "  %s: environment changed by the kernel (rounding %d -> %d, mxcsr %#x -> %#x)\n",
            label.c_str(), before.rounding, after.rounding, before.mxcsr, after.mxcsr);
        ++bad;
    }
    return bad;
}

// Queries some kernel once got wrong in some environment, with their exact signs.
struct Fixture {
    const char* name;
    Orient2dQuery orient2d;
    Sign orient2d_sign;
    IncircleQuery incircle;
    Sign incircle_sign;
};

// Found by this test (first run): the exact kernels split coordinates with
// std::frexp/std::ldexp, which glibc computes with a multiplication for subnormal
// arguments, so DAZ read every subnormal coordinate as zero: orient2d of three subnormal
// points came out 0, and a circle of radius ~2^-88 with d moved one subnormal step off
// (0, -r) came out cocircular.
const Fixture fixtures[] = {
    {"daz_subnormal_orient2d",
     {{0x0.0000000000041p-1022, 0x0p+0},
      {0x0.000000000003fp-1022, 0x0.000000000001p-1022},
      {0x0.000000000003cp-1022, 0x0.000000000001fp-1022}},
     Sign::positive,
     {{0x1.04p-94, 0x0p+0},
      {0x1.38p-95, 0x1.ap-95},
      {-0x1.ap-95, 0x1.38p-95},
      {-0x0.0000000000001p-1022, -0x1.04p-94}},
     Sign::negative},
    {"daz_subnormal_step_off_huge_circle",
     {{0x0.0000000000041p-1022, 0x0p+0},
      {0x0.000000000003fp-1022, 0x0.000000000001p-1022},
      {0x0.000000000003dp-1022, 0x0.0000000000021p-1022}},
     Sign::negative,
     {{0x1.04p+956, 0x0p+0},
      {0x1.38p+955, 0x1.ap+955},
      {-0x1.ap+955, 0x1.38p+955},
      {-0x0.0000000000001p-1022, -0x1.04p+956}},
     Sign::negative},
};

template <class Kernel>
int run(const Kernel& kernel) {
    std::size_t total_bad = 0;

    // The named fixtures first: the reference itself is checked against the recorded
    // signs, then every environment against them.
    QueryFamily fixture_family{"fixtures", false, {}, {}, {}, {}};
    Signs fixture_signs;
    for (const Fixture& f : fixtures) {
        fixture_family.orient2d.push_back(f.orient2d);
        fixture_family.incircle.push_back(f.incircle);
        fixture_signs.orient2d.push_back(f.orient2d_sign);
        fixture_signs.incircle.push_back(f.incircle_sign);
    }
    // Only orient2d and incircle were recorded (d is on the same side of ab as c, outside
    // the cosine test's precondition); its reference is GMP's in the default environment.
    set_controls(FE_TONEAREST, 0);
    fixture_signs.incircle_cosine = evaluate(GmpExactKernel{}, fixture_family).incircle_cosine;
    total_bad += count_mismatches("exact (default environment)", fixture_family,
                                  evaluate(GmpExactKernel{}, fixture_family), fixture_signs);

    // Thinner grids than the consumer test: the kernel runs once per environment.
    std::vector<QueryFamily> families = all_families(4);
    families.insert(families.begin(), std::move(fixture_family));
    for (const QueryFamily& family : families) {
        set_controls(FE_TONEAREST, 0);
        const Signs exact = evaluate(GmpExactKernel{}, family);
        for (const Environment& env : environments) {
            const std::size_t bad = check(kernel, env, family, exact);
            std::printf("%-10s %-10s %-20s wrong %zu\n", kernel.name().c_str(), family.name.c_str(),
                        env.name, bad);
            total_bad += bad;
        }
    }
    return total_bad == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    const char* kernel = argc == 2 ? argv[1] : "";
    if (std::strcmp(kernel, "adaptive") == 0) return run(AdaptiveKernel{});
    if (std::strcmp(kernel, "exact") == 0) return run(GmpExactKernel{});
    if (std::strcmp(kernel, "exact-cpp") == 0) {
        // The two exact backends must agree in the default environment before the
        // environments are tried (GMP is the reference below).
        set_controls(FE_TONEAREST, 0);
        std::size_t bad = 0;
        for (const QueryFamily& family : all_families(4)) {
            bad += count_mismatches("exact-cpp (default environment)", family,
                                    evaluate(CppIntExactKernel{}, family),
                                    evaluate(GmpExactKernel{}, family));
        }
        return run(CppIntExactKernel{}) | (bad == 0 ? 0 : 1);
    }
    std::fprintf(stderr, "usage: %s adaptive|exact|exact-cpp\n", argv[0]);
    return 2;
}
