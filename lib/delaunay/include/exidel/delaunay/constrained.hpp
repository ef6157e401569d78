// exidel: the constrained Delaunay triangulation of points and segments.
//
// What the output is. Let P be the input points and S the input segments (pairs of input
// indices). The segments are first made into a set of non-crossing pieces:
//   - a segment is split at every vertex that lies exactly on it (decided by orient2d): an
//     input point on a segment, or an end of another segment touching it;
//   - segments that overlap along a line share the pieces of their common part (merged);
//   - two segments that cross at a point interior to both get a new vertex there, each
//     coordinate the double nearest to the exact intersection (exidel::intersection,
//     construct.hpp), and both are split there. The rounded point need not lie exactly on
//     either segment: the pieces are straight between the vertices, so a crossed segment
//     becomes a chain that may bend by less than an ulp at its crossings.
// The result is the constrained Delaunay triangulation of P plus the added crossing points
// with the pieces as constraints: every piece is an edge, and every other edge is locally
// Delaunay (no vertex of the triangle on one side lies strictly inside the circle of the
// triangle on the other), which makes the whole a constrained Delaunay triangulation (Lee
// and Lin 1986, Chew 1989: a triangulation whose non-constraint edges are all locally
// Delaunay is the CDT). The triangles tile the convex hull of all vertices.
//
// Where rounding moves a crossing point by up to half an ulp, a piece may cross another
// segment or pass exactly through a vertex that the exact segment missed (a cascade). That
// is resolved without leaving the segment's neighbourhood: a crossing of the two input
// segments where they cross properly; else the piece is routed through an end of the other
// piece (or the other piece through an end of this one) that lies within chain_tolerance()
// of the segment (2^-44 of its largest coordinate, at least 256 ulps of it), making no
// vertex; else the rounded crossing of the two pieces. A bent piece still stops at every
// vertex exactly on its segment, and a chain that comes back to a vertex has the loop cut
// out, so the pieces never cross. Every chain vertex is thus on its segment, a rounded
// crossing of it, or within chain_tolerance() of it (the certifier checks which, exactly).
// Pieces are built by inserting the segments in input order; without cascades (crossings
// farther apart than a few ulps) the output does not depend on the order of the segments.
// A crossing of two segments that rounds onto a vertex already on one of their chains is
// treated as a cascade too (splitting there would bend the chain back into a loop).
//
// A cascade that does not settle (more crossing points than pairs of segments; or, with
// exact signs, any inconsistency once a cascade began: exact signs cause none otherwise)
// is not a failure: the run starts again from the Delaunay triangulation with snap
// rounding on the grid of doubles (Hobby 1999; Guibas and Marimont 1998). The pixel of a
// double point is the set of reals that round to it; the hot pixels are those of the
// segments' ends, of the input points exactly inside a segment, and of the rounded
// crossing of every two input segments that cross properly (the pixel that holds their
// exact crossing); each segment becomes the chain through the vertices of the hot pixels
// it meets, in order along it, decided in exact rational arithmetic. No vertex is made
// but the crossings, each rounded once; a chain may bend by up to a pixel (two ulps) at
// each vertex and may share pieces with another. Chains do not cross on a uniform grid
// (Hobby's theorem); the doubles are one only within each binade, and the rare pieces
// that still cross where pixel sizes change are resolved as cascades (above), within the
// same limits.
// Measured: no failure and every output certified in 400 bundles of 10-39 segments within
// 64 ulps of a line (and 20 of 60-99), where the cascade alone failed in 3%, 20% and 52%
// of the bundles of 10-19, 20-29 and 30-39 segments (tests/delaunay/constrained_test.cpp,
// BundlesOfSegmentsAreCertified and RegressionBundleCascadeIsSnapRounded).
//
// How. The Delaunay triangulation of P (triangulate(), any algorithm of Options) is the
// start. Each segment is inserted from its first end: a walk finds the edges it crosses, a
// vertex on it ends a piece, the crossed triangles are replaced by the Delaunay
// triangulations of the two pseudo-polygons beside the piece (Anglada 1997; where a vertex
// hangs inside one side, by Sloan's flips and Lawson's, which never flip a piece); a piece it
// crosses is split at the rounded crossing, which is inserted as a point (a split and
// Lawson's flips). Every loop is bounded: with an inexact kernel a run gives a result or a
// typed Failure.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/registry.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay {

/// A segment between two input points, by input index.
struct Segment {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    friend bool operator==(const Segment&, const Segment&) = default;
};

struct ConstrainedOptions {
    /// How the Delaunay triangulation of the points, the starting point, is built.
    Options delaunay{};
    /// Most crossing points added before the run stops with too_many_crossings; 0 means
    /// the largest the 32-bit indices allow.
    std::size_t max_added_points = 0;
};

/// A constrained Delaunay triangulation (see the top of the file for what it is).
struct ConstrainedTriangulation {
    /// The input points, then the added crossing points (input_count onwards).
    std::vector<Point2> points;
    std::size_t input_count = 0;
    /// The triangles over `points`, in Triangulation's layout; vertex_of_input has one entry
    /// per element of `points` (an added point is its own vertex).
    Triangulation triangulation;
    /// Each input segment s as the chain of vertices it became, from the vertex of its
    /// first end to the vertex of its second: chain_vertices[chain_offsets[s] ..
    /// chain_offsets[s + 1]). A segment whose two ends are the same point has one vertex.
    /// Consecutive vertices of a chain are a constraint piece, an edge of the triangulation.
    std::vector<std::uint32_t> chain_offsets;
    std::vector<std::uint32_t> chain_vertices;
    /// For added point input_count + i: the two input segments whose crossing it rounds
    /// (the first pair found; others may cross there too), and the four vertices a, b, c, d
    /// it is the rounded crossing of, line ab with line cd: the segments' ends, or, where
    /// rounding has bent two pieces so far that their segments no longer cross properly,
    /// the pieces' ends.
    std::vector<std::array<std::uint32_t, 2>> crossings;
    std::vector<std::array<std::uint32_t, 4>> crossing_lines;
    /// Every constraint piece once, as (u, v) with u < v, sorted.
    std::vector<std::array<std::uint32_t, 2>> constraints;

    std::span<const std::uint32_t> chain(std::size_t s) const noexcept {
        return {chain_vertices.data() + chain_offsets[s], chain_offsets[s + 1] - chain_offsets[s]};
    }
    std::size_t added_count() const noexcept { return points.size() - input_count; }
};

struct ConstrainedResult {
    ConstrainedTriangulation cdt;  ///< meaningful only when ok()
    std::optional<Failure> failure;
    bool ok() const noexcept { return !failure.has_value(); }
};

/// The constrained Delaunay triangulation of `points` with `segments` as constraints.
/// Failures: non_finite_input, too_many_points, invalid_segment (an index past the points;
/// its position in Failure::input_index), too_many_crossings, and the inconsistencies of an
/// inexact kernel (constraint_inconsistent, location_exceeded, flips_exceeded, and those of
/// triangulate()).
template <PredicateKernel K>
ConstrainedResult constrained_delaunay(std::span<const Point2> points,
                                       std::span<const Segment> segments, const K& kernel = K{},
                                       const ConstrainedOptions& options = {});

/// How far from segment ab a vertex of its chain may lie when it is neither on the segment
/// nor a rounded crossing of it: 2^-44 times the largest magnitude of the ends' coordinates
/// (at least 256 ulps of it), and at least 2^-1066 (256 times the smallest subnormal). Such
/// vertices come from cascades: a piece bent by a rounded crossing meets a vertex or another
/// bent piece, each step off by at most half an ulp of the coordinates near the segment.
inline double chain_tolerance(Point2 a, Point2 b) noexcept {
    const double m = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
    return std::max(std::ldexp(m, -44), std::ldexp(1.0, -1066));
}

/// Certifies `cdt` as the constrained Delaunay triangulation of `points` and `segments`
/// (the input given to constrained_delaunay), with exact predicates:
///   - cdt.points starts with `points` (bit for bit); every added point is the correctly
///     rounded crossing of its two segments, which cross properly;
///   - the triangulation over cdt.points passes certify()'s checks 1-6 (shape, twins,
///     counter-clockwise triangles, a convex boundary winding once, every point a vertex,
///     Euler's count), so the triangles tile the convex hull exactly once;
///   - every chain runs from its segment's first end to its second, never visiting a vertex
///     twice; each consecutive pair is an edge; each interior vertex lies exactly on the open
///     segment, or is a rounded crossing of that segment with another, or lies within
///     chain_tolerance() of it (compare_segment_distance, exact); `constraints` lists
///     exactly the chains' pieces;
///   - every edge that is not a piece is locally Delaunay.
/// Findings are certify()'s kinds, plus the constrained ones (FindingKind).
namespace detail {
/// The kernel the builder runs for K: K itself, but for the adaptive kernel its filters
/// inlined (InlineConstrainedKernel, defined in src/constrained.cpp, where the library's
/// floating-point flags hold; the same predicates, so the same output).
struct InlineConstrainedKernel;
template <PredicateKernel K>
struct ConstrainedRunKernel {
    using type = K;
    static const K& from(const K& kernel) { return kernel; }
};
template <>
struct ConstrainedRunKernel<AdaptiveKernel> {
    using type = InlineConstrainedKernel;
    static InlineConstrainedKernel from(const AdaptiveKernel&);
};
/// All points on one line: no triangles; each chain is the points from one end to the
/// other in order along the line (src/constrained.cpp).
void constrained_on_a_line(std::span<const Point2> points, std::span<const Segment> segments,
                           Triangulation tri, ConstrainedTriangulation& out);
}  // namespace detail

Certificate certify_constrained(std::span<const Point2> points, std::span<const Segment> segments,
                                const ConstrainedTriangulation& cdt,
                                const CertifyOptions& options = {});

}  // namespace exidel::delaunay

// The machinery, which needs the types above.
#include "exidel/delaunay/detail/constrained.hpp"  // IWYU pragma: keep

namespace exidel::delaunay {

template <PredicateKernel K>
ConstrainedResult constrained_delaunay(std::span<const Point2> points,
                                       std::span<const Segment> segments, const K& kernel,
                                       const ConstrainedOptions& options) {
    ConstrainedResult result;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        if (segments[s].a >= points.size() || segments[s].b >= points.size()) {
            result.failure = Failure{FailureKind::invalid_segment, s, no_index,
                                     "segment " + std::to_string(s) + " names point " +
                                         std::to_string(std::max(segments[s].a, segments[s].b)) +
                                         " of " + std::to_string(points.size())};
            return result;
        }
    }
    Result dt = triangulate<Instrumentation::off>(points, kernel, options.delaunay);
    if (!dt.ok()) {
        result.failure = std::move(dt.failure);
        return result;
    }
    ConstrainedTriangulation& out = result.cdt;
    if (dt.triangulation.collinear) {
        detail::constrained_on_a_line(points, segments, std::move(dt.triangulation), out);
        return result;
    }
    const std::size_t room =
        detail::max_points > points.size() ? detail::max_points - points.size() : 0;
    const std::size_t max_added =
        options.max_added_points == 0 ? room : std::min(room, options.max_added_points);
    // A crossing cascade that does not settle is run again with snap rounding (the
    // builder's run_snapped(), from a fresh Delaunay triangulation).
    for (int attempt = 0; attempt < 2; ++attempt) {
        if (attempt == 1) {
            dt = triangulate<Instrumentation::off>(points, kernel, options.delaunay);
            if (!dt.ok()) {
                result.failure = std::move(dt.failure);
                return result;
            }
        }
        try {
            using Run = detail::ConstrainedRunKernel<K>;
            const auto& run_kernel = Run::from(kernel);
            detail::ConstrainedBuilder<typename Run::type> builder(
                run_kernel, std::vector<Point2>(points.begin(), points.end()),
                std::move(dt.triangulation), max_added);
            if (attempt == 0)
                builder.run(segments, out);
            else
                builder.run_snapped(segments, out);
            result.failure.reset();
            return result;
        } catch (const detail::ConstrainedStop& stop) {
            result.cdt = {};
            result.failure = stop.failure;
            if (!stop.cascade) return result;
        }
    }
    return result;
}

#define EXIDEL_CONSTRAINED_EXTERN(K, spelling, summary)        \
    extern template ConstrainedResult constrained_delaunay<K>( \
        std::span<const Point2>, std::span<const Segment>, const K&, const ConstrainedOptions&);
EXIDEL_KERNELS(EXIDEL_CONSTRAINED_EXTERN)
#undef EXIDEL_CONSTRAINED_EXTERN

}  // namespace exidel::delaunay
