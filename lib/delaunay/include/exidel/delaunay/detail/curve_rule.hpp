// exidel: the shape rule of the external algorithm's `automatic` order: a heuristic that
// sends points along a convex curve to the radial order rather than to strips.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/radial.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

/// The shape rule of `automatic`: whether the sorted points lie on a convex curve that the
/// radial order walks along, where `radial` beats `strips` by a wide margin
/// (docs/measurements.md): every strip there is an arc whose radial
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
    // the order, and only the strips' threads help (bench/; docs/benchmarks.md).
    {
        const Point2 a = pts[hull[0]], b = pts[hull[h / 3]], c = pts[hull[2 * h / 3]];
        const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
        const auto [ux, uy] = circumcentre_offset(a, b, c);
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

}  // namespace exidel::delaunay::detail
