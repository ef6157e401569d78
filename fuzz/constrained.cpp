// libFuzzer harness: the constrained triangulation on points and segments decoded from
// arbitrary bytes.
//   - The adaptive kernel (exact): the result certifies (certify_constrained), or the run
//     fails with non_finite_input (input with a non-finite coordinate). Cascades of rounded
//     crossings that do not settle are snap-rounded (constrained.hpp), so no other failure.
//   - The double kernel (inexact): any result or typed Failure, but no crash, no sanitizer
//     report and no hang (libFuzzer's -timeout).
// Bytes: the second byte is the number of segments s (mod 64), then 2s bytes their ends
// (each mod the number of points); the first byte and the rest are the points
// (fuzz/decode.hpp).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "decode.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/floating.hpp"

namespace {

using exidel::Point2;
namespace delaunay = exidel::delaunay;

// The kernels as types of the harness's own, instantiated here (the library's
// instantiations for the registry are not in the fuzz build).
struct Adaptive : exidel::AdaptiveKernel {};
struct Double : exidel::DoubleKernel {};

[[noreturn]] void finding(const char* what, std::size_t points, std::size_t segments) {
    std::fprintf(stderr, "%s: %zu points, %zu segments\n", what, points, segments);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const std::size_t count = data[1] % 64u;
    if (size < 2 + 2 * count) return 0;
    std::vector<std::uint8_t> point_bytes{data[0]};
    point_bytes.insert(point_bytes.end(), data + 2 + 2 * count, data + size);
    const std::vector<Point2> points = exidel::fuzz::decode(point_bytes.data(), point_bytes.size());
    if (points.empty()) return 0;
    std::vector<delaunay::Segment> segments;
    for (std::size_t i = 0; i < count; ++i) {
        segments.push_back({static_cast<std::uint32_t>(data[2 + 2 * i] % points.size()),
                            static_cast<std::uint32_t>(data[3 + 2 * i] % points.size())});
    }
    const delaunay::ConstrainedResult exact =
        delaunay::constrained_delaunay(points, segments, Adaptive{});
    if (!exidel::fuzz::all_finite(points)) {
        if (exact.ok() || exact.failure->kind != delaunay::FailureKind::non_finite_input)
            finding("non-finite input not refused", points.size(), segments.size());
    } else if (!exact.ok()) {
        finding("the adaptive kernel's run failed", points.size(), segments.size());
    } else if (!delaunay::certify_constrained(points, segments, exact.cdt).ok()) {
        finding("the adaptive kernel's result does not certify", points.size(), segments.size());
    }
    (void)delaunay::constrained_delaunay(points, segments, Double{});
    return 0;
}
