// libFuzzer harness: every algorithm of the registry, in every insertion order and under
// both in-circle policies, on points decoded from arbitrary bytes.
//   - The adaptive kernel (exact): the result is certified Delaunay, or, for input with a
//     non-finite coordinate, the run fails with non_finite_input before any work.
//   - The double kernel (inexact): any result or Failure is allowed, but no crash, no
//     sanitizer report and no hang (libFuzzer's -timeout): triangulate() promises that it
//     "never loops or reads out of bounds".
// Points are decoded by fuzz/decode.hpp.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/all.hpp"
#include "decode.hpp"

namespace {

using exidel::Point2;
namespace delaunay = exidel::delaunay;
using exidel::fuzz::all_finite;
using exidel::fuzz::decode;

// The two kernels as types of the harness's own: exidel::delaunay compiles triangulate()
// for the registry's kernels in one translation unit (instantiate.cpp, every kernel, two
// instrumentation levels), which takes minutes under the sanitizers and which this build
// leaves out; for these types the compiler instantiates it here, for the two kernels only.
struct Adaptive : exidel::AdaptiveKernel {};
struct Double : exidel::DoubleKernel {};
static_assert(exidel::PredicateKernel<Adaptive> && exidel::PredicateKernel<Double>);

[[noreturn]] void finding(const char* what, const delaunay::Options& o, std::size_t n) {
    std::fprintf(stderr, "%s: algorithm %s, order %s, incircle %s, strip tiles %zu, %zu points\n",
                 what, std::string(delaunay::to_string(o.algorithm)).c_str(),
                 std::string(delaunay::to_string(o.strategy)).c_str(),
                 o.incircle == delaunay::InCirclePolicy::cosine ? "cosine" : "determinant",
                 o.strip_tiles, n);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<Point2> points = decode(data, size);
    const bool finite = all_finite(points);
    auto run = [&](const delaunay::Options& o) {
        const delaunay::Result exact = delaunay::triangulate(points, Adaptive{}, o);
        if (!finite) {
            if (!exact.failure || exact.failure->kind != delaunay::FailureKind::non_finite_input) {
                finding("non-finite input not refused", o, points.size());
            }
        } else if (exact.failure) {
            finding("the adaptive kernel's run failed", o, points.size());
        } else if (!delaunay::certify(points, exact.triangulation).ok()) {
            finding("the adaptive kernel's result does not certify", o, points.size());
        }
        (void)delaunay::triangulate(points, Double{}, o);
    };
    for (const delaunay::AlgorithmInfo& a : delaunay::algorithms()) {
        for (const delaunay::Strategy s :
             {delaunay::Strategy::lexicographic, delaunay::Strategy::radial,
              delaunay::Strategy::strips}) {
            if (!a.takes_order && s != delaunay::Strategy::lexicographic) continue;
            for (const auto policy :
                 {delaunay::InCirclePolicy::determinant, delaunay::InCirclePolicy::cosine}) {
                const delaunay::Options o =
                    delaunay::Options{}
                        .with_algorithm(a.id)
                        .with_strategy(a.takes_order ? s : delaunay::Strategy::automatic)
                        .with_incircle(policy)
                        .with_strip_points(8)  // several strips and merges even for small inputs
                        .with_strip_tiles(1);
                run(o);
                if (a.takes_order && s == delaunay::Strategy::strips) {
                    // Strips cut across into tiles: stacked pieces merged.
                    run(o.with_strip_tiles(3));
                }
            }
        }
    }
    return 0;
}
