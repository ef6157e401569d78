// exidel: Delaunay triangulation by the external incremental algorithm (Yifeng Cai 2025)
// and its divide-and-conquer extension. Strategies (Options::strategy):
//
//   lexicographic  the paper's algorithm, unchanged: one run in (x, y) order. The reference,
//                  and quadratic on a sampled convex curve (each point erodes the whole
//                  visible chain).
//   radial         one run in ascending exact distance from the bounding-box centre
//                  (detail/radial.hpp): fewer flips on random input and near-linear on
//                  convex curves; still external, no point location.
//   strips         lexicographic strips, each triangulated in radial order, merged by the
//                  Guibas-Stolfi zipper, on one or more threads (detail/strips.hpp).
//   automatic      radial below automatic_strips_from points, strips above, except on
//                  points along a convex curve that the radial order follows
//                  (detail::radial_follows_curve), where radial stays.
//
// The algorithm itself is detail/builder.hpp (insertion) and detail/merge.hpp (merge).
// Header template: any exidel::PredicateKernel works. The library compiles explicit
// instantiations for the shipped kernels (see the extern declarations at the end).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/builder.hpp"
#include "exidel/delaunay/detail/radial.hpp"
#include "exidel/delaunay/detail/strips.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/floating.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/mpfr.hpp"

namespace exidel::delaunay {

/// Below this many points `automatic` runs one radial pass; from it, strips.
inline constexpr std::size_t automatic_strips_from = std::size_t{1} << 15;

/// Points per strip when Options::strip_points is 0: measured (bench/, README) as the
/// fastest on uniform input on this project's machines, at every size: a strip's arrays
/// stay cache-sized, and the merges cost little. (At 10^7 points, strips of n/64 points
/// took 6.5 s against 5.5 s for these, one thread; 4.0 s against 3.6 s with two.)
constexpr std::size_t default_strip_points(std::size_t /*n*/) noexcept {
    return std::size_t{1} << 14;
}

/// The size rule of `automatic` for n distinct points: radial below automatic_strips_from,
/// strips from there, where the shape may still choose radial (radial_follows_curve).
constexpr Strategy choose_strategy(std::size_t n, Strategy requested) noexcept {
    if (requested != Strategy::automatic) return requested;
    return n < automatic_strips_from ? Strategy::radial : Strategy::strips;
}

namespace detail {

/// The shape rule of `automatic`: whether the sorted points lie on a convex curve that the
/// radial order walks along, where `radial` beats `strips` (bench/, README: on 10^6 points
/// of a parabola 0.96x CGAL's time against 2.5x; every strip there is an arc whose radial
/// sort is all near-ties, and each merge re-triangulates two arcs' fans). Decided on at
/// most 1024 evenly spaced points: at least half of them on their convex hull, and the
/// radial order about the centre `radial` would use growing them along that hull as a few
/// arcs (on a parabola it starts in the middle of the arc and grows both ways).
/// Not on a circle (every in-circle test a near-tie whatever the order: strips, with two
/// threads, are faster), nor on scattered input (few points on the hull). A heuristic in
/// plain floating point: either answer triangulates correctly.
template <PredicateKernel K>
bool radial_follows_curve(std::span<const Point2> pts, const K& kernel) {
    const std::size_t n = pts.size(), m = std::min<std::size_t>(n, 1024);
    if (m < 8) return false;
    std::vector<std::uint32_t> sample(m);  // sorted positions, in increasing order
    for (std::size_t j = 0; j < m; ++j) {
        sample[j] = static_cast<std::uint32_t>(j * (n - 1) / (m - 1));
    }
    // Andrew's monotone chain over the sample (lexicographic already): strict turns only.
    std::vector<std::uint32_t> hull;
    auto chain = [&](auto first, auto last) {
        const std::size_t base = hull.size();
        for (auto it = first; it != last; ++it) {
            while (hull.size() >= base + 2 &&
                   kernel.orient2d(pts[hull[hull.size() - 2]], pts[hull.back()], pts[*it]) !=
                       Sign::positive) {
                hull.pop_back();
            }
            hull.push_back(*it);
        }
        hull.pop_back();  // the last point starts the other chain
    };
    chain(sample.begin(), sample.end());
    chain(sample.rbegin(), sample.rend());
    const std::size_t h = hull.size();
    if (2 * h < m) return false;
    // Points on one circle (up to rounding): every in-circle test is a near-tie whatever
    // the order, and only the strips' threads help (bench/, README).
    {
        const Point2 a = pts[hull[0]], b = pts[hull[h / 3]], c = pts[hull[2 * h / 3]];
        const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
        const double bl = bx * bx + by * by, cl = cx * cx + cy * cy, det = 2 * (bx * cy - by * cx);
        const double ux = (cy * bl - by * cl) / det, uy = (bx * cl - cx * bl) / det;
        const double r2 = ux * ux + uy * uy;
        // Off the circle by at most 10^-12 of the points' extent: |d^2 - r^2| = |d - r|
        // (d + r). (Measured against r instead, a parabola passes: from its far centre
        // of curvature it is within 4e-13 r^2 of a circle.)
        const double extent = std::max({std::abs(bx), std::abs(by), std::abs(cx), std::abs(cy)});
        const double tolerance = 1e-12 * extent * 2 * std::sqrt(r2);
        std::size_t on_circle = 0;
        for (const std::uint32_t v : hull) {
            const double dx = pts[v].x - a.x - ux, dy = pts[v].y - a.y - uy;
            if (std::abs(dx * dx + dy * dy - r2) <= tolerance) ++on_circle;  // NaN: not
        }
        if (10 * on_circle >= 9 * h) return false;
    }
    const Point2 centre = radial_centre(pts);
    std::vector<std::pair<double, std::uint32_t>> by_distance(h);  // (key, hull position)
    for (std::size_t j = 0; j < h; ++j) {
        const double dx = pts[hull[j]].x - centre.x, dy = pts[hull[j]].y - centre.y;
        by_distance[j] = {dx * dx + dy * dy, static_cast<std::uint32_t>(j)};
    }
    std::sort(by_distance.begin(), by_distance.end());
    // Visit the hull positions in radial order, counting the arcs visited so far: a new
    // position next to none starts one, next to two joins two. Walking the curve from one
    // point or two keeps two arcs, a few more where the plain keys tie (4 on a parabola of
    // 10^6 points); an order that is noise makes about h / 4.
    std::vector<std::uint8_t> seen(h, 0);
    std::size_t arcs = 0, most = 0;
    for (const auto& [key, j] : by_distance) {
        const int near = seen[(j + 1) % h] + seen[(j + h - 1) % h];
        seen[j] = 1;
        arcs = arcs + 1 - static_cast<std::size_t>(near);
        most = std::max(most, arcs);
    }
    return most <= 16;
}

/// Writes `mesh` (vertex ids; dead slots allowed) as a Triangulation of input indices,
/// `input_of[id]`, with the hull starting at id `first` (the lexicographically smallest
/// point, always a hull vertex).
std::optional<Failure> to_triangulation(Mesh& mesh, std::span<const std::uint32_t> input_of,
                                        std::uint32_t first, Triangulation& tri);

template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
Result run_strategy(const K& kernel, SortedInput& in, const Options& options) {
    Result result;
    const std::size_t n = in.points.size();
    result.strategy = choose_strategy(n, options.strategy);
    if (options.strategy == Strategy::automatic && result.strategy == Strategy::strips &&
        radial_follows_curve(in.points, kernel)) {
        result.strategy = Strategy::radial;
    }
    Mesh mesh;
    std::vector<std::uint32_t> input_of;  // mesh id -> input index, when not sorted positions
    std::uint32_t first = 0;              // mesh id of sorted position 0
    auto radial = [&](Strategy reported) {
        result.strategy = reported;
        const Point2 centre = radial_centre(in.points);
        std::vector<std::uint32_t> order = radial_order(in.points, centre, kernel);
        sort_collinear_prefix(in.points, order, kernel);
        std::vector<Point2> pts(n);
        input_of.resize(n);
        for (std::size_t j = 0; j < n; ++j) {
            pts[j] = in.points[order[j]];
            input_of[j] = in.input_of[order[j]];
            if (order[j] == 0) first = static_cast<std::uint32_t>(j);
        }
        Builder<K, I, P, Order::radial> builder(kernel, pts, input_of, centre);
        result.failure = builder.run(mesh);
        result.counters = builder.counters();
    };
    if (n < 3) {
        mesh.collinear = true;
    } else if (result.strategy == Strategy::lexicographic) {
        Builder<K, I, P, Order::lexicographic> builder(kernel, in.points, in.input_of);
        result.failure = builder.run(mesh);
        result.counters = builder.counters();
    } else if (result.strategy == Strategy::radial) {
        radial(Strategy::radial);
    } else {
        const std::size_t target =
            options.strip_points != 0 ? options.strip_points : default_strip_points(n);
        const std::vector<std::uint32_t> cuts = strip_cuts(in.points, target, kernel);
        result.strips = cuts.size() - 1;
        if (result.strips == 1) {
            radial(Strategy::strips);  // one strip: its radial run is the whole job
        } else {
            result.failure = build_strips<K, I, P>(kernel, in.points, in.input_of, cuts,
                                                   options.threads, mesh, result.counters);
        }
    }
    Triangulation& tri = result.triangulation;
    if (!result.failure) {
        if (mesh.collinear) {
            tri.collinear = true;
            tri.hull = in.input_of;  // the chain, lexicographically
        } else {
            result.failure =
                to_triangulation(mesh, input_of.empty() ? in.input_of : input_of, first, tri);
        }
    }
    tri.vertex_of_input = std::move(in.vertex_of_input);
    tri.duplicates = std::move(in.duplicates);
    return result;
}

}  // namespace detail

/// Delaunay triangulation of `points` with the predicates of `kernel`.
///
/// Every finite input is accepted, including none, one or two points and duplicates;
/// a non-finite coordinate fails before any work. With an exact kernel (AdaptiveKernel,
/// GmpExactKernel) the result is a Delaunay triangulation, the same one for both
/// in-circle policies. With an inexact kernel the result may be wrong, or the run may
/// stop with a Failure saying where the kernel contradicted itself; it never loops or
/// reads out of bounds.
template <Instrumentation I = Instrumentation::off, PredicateKernel K>
Result triangulate(std::span<const Point2> points, const K& kernel, const Options& options = {}) {
    detail::SortedInput input;
    if (auto failure = detail::sort_and_dedupe(points, input)) {
        Result r;
        r.failure = std::move(failure);
        return r;
    }
    if (options.incircle == InCirclePolicy::cosine) {
        return detail::run_strategy<K, I, InCirclePolicy::cosine>(kernel, input, options);
    }
    return detail::run_strategy<K, I, InCirclePolicy::determinant>(kernel, input, options);
}

#define EXIDEL_DELAUNAY_EXTERN(K)                                                        \
    extern template Result triangulate<Instrumentation::off, K>(std::span<const Point2>,  \
                                                                 const K&, const Options&); \
    extern template Result triangulate<Instrumentation::counters, K>(                     \
        std::span<const Point2>, const K&, const Options&);                               \
    extern template Result triangulate<Instrumentation::theorem1, K>(                     \
        std::span<const Point2>, const K&, const Options&);

EXIDEL_DELAUNAY_EXTERN(AdaptiveKernel)
EXIDEL_DELAUNAY_EXTERN(DoubleKernel)
EXIDEL_DELAUNAY_EXTERN(LongDoubleKernel)
EXIDEL_DELAUNAY_EXTERN(GmpExactKernel)
EXIDEL_DELAUNAY_EXTERN(MpfrKernel)
#undef EXIDEL_DELAUNAY_EXTERN

}  // namespace exidel::delaunay
