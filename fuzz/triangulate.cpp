// libFuzzer harness: every algorithm of the registry, in every insertion order and under
// both in-circle policies, on points decoded from arbitrary bytes.
//   - The adaptive kernel (exact): the result is certified Delaunay, or, for input with a
//     non-finite coordinate, the run fails with non_finite_input before any work.
//   - The double kernel (inexact): any result or Failure is allowed, but no crash, no
//     sanitizer report and no hang (libFuzzer's -timeout): triangulate() promises that it
//     "never loops or reads out of bounds".
// Decoding (the first byte's low two bits): 0 raw float64 pairs, little-endian (any
// double, NaN and infinities included); 1 pairs of signed bytes, a small integer grid full
// of collinear, cocircular and repeated points; 2 the same grid scaled by 2^k (k from the
// second byte, -1100 to 1100: subnormals, and products that overflow); 3 the grid plus an
// ulp-sized nudge per coordinate (the third byte's bits), near-degenerate.
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

namespace {

using exidel::Point2;
namespace delaunay = exidel::delaunay;

// The two kernels as types of the harness's own: exidel::delaunay compiles triangulate()
// for the registry's kernels in one translation unit (instantiate.cpp, every kernel, two
// instrumentation levels), which takes minutes under the sanitizers and which this build
// leaves out; for these types the compiler instantiates it here, for the two kernels only.
struct Adaptive : exidel::AdaptiveKernel {};
struct Double : exidel::DoubleKernel {};
static_assert(exidel::PredicateKernel<Adaptive> && exidel::PredicateKernel<Double>);

std::vector<Point2> decode(const std::uint8_t* data, std::size_t size) {
    std::vector<Point2> points;
    if (size == 0) return points;
    const unsigned mode = data[0] & 3u;
    ++data;
    --size;
    if (mode == 0) {
        for (std::size_t i = 0; i + 16 <= size; i += 16) {
            std::uint64_t x = 0, y = 0;
            std::memcpy(&x, data + i, 8);
            std::memcpy(&y, data + i + 8, 8);
            points.push_back({std::bit_cast<double>(x), std::bit_cast<double>(y)});
        }
        return points;
    }
    int k = 0;
    std::uint8_t nudge = 0;
    if (mode >= 2 && size >= 2) {
        k = mode == 2 ? int(data[0]) * 2200 / 255 - 1100 : 0;
        nudge = data[1];
        data += 2;
        size -= 2;
    }
    for (std::size_t i = 0; i + 2 <= size; i += 2) {
        double x = std::ldexp(double(std::int8_t(data[i])), k);
        double y = std::ldexp(double(std::int8_t(data[i + 1])), k);
        if (mode == 3) {
            // One ulp up or down per coordinate, from the nudge byte's bits in turn.
            const unsigned bit = unsigned(i) % 8;
            x = std::nextafter(x, (nudge >> bit) & 1u ? INFINITY : -INFINITY);
            y = std::nextafter(y, (nudge >> ((bit + 1) % 8)) & 1u ? INFINITY : -INFINITY);
        }
        points.push_back({x, y});
    }
    return points;
}

bool all_finite(const std::vector<Point2>& points) {
    for (const Point2& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    }
    return true;
}

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
