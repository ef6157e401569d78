// exidel: the radial insertion order: ascending exact distance from a centre, ties in
// the order of the input sequence (lexicographic, since callers pass sorted points).
//
// Sorting with the exact predicate alone would cost an exact-capable comparison per step.
// Instead: sort by the floating-point key fl(fl(dx^2) + fl(dy^2)) (dx = fl(px - cx), ...),
// whose relative error is at most bounds::radial_key_rel when it lies in
// [radial_key_min, radial_key_max] (proofs/bounds.md#radial-key), then re-sort with
// k.compare_distance every run of neighbours whose keys cannot be told apart. Why that is
// exact: write d for a key, D for the exact squared distance, r = radial_key_rel, so
// d / (1 + r) <= D <= d / (1 - r). Two consecutive keys lo <= hi are "separated" when both
// are in range and fl(hi * below) > fl(lo * above), with below = fl(1 - 4r) and
// above = fl(1 + 4r). Three roundings of relative error eps <= r / 4 each turn that into
// hi (1 - 3r) > lo (1 + 3r). Then D_hi >= hi / (1 + r) >= hi (1 - 3r) > lo (1 + 3r)
// >= lo / (1 - r) >= D_lo (for r <= 1/3): the exact order agrees. Every element before a
// separation has a key <= lo and every element after it a key >= hi, so a separation
// orders all of them exactly; only inside runs without one is the predicate needed.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "exidel/delaunay/detail/radix.hpp"
#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay::detail {

/// The centre of the bounding box of `points` (non-empty), computed without overflow.
inline Point2 bounding_box_centre(std::span<const Point2> points) {
    double x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
    for (const Point2& p : points) {
        x0 = std::min(x0, p.x);
        x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y);
        y1 = std::max(y1, p.y);
    }
    // Halves first: (x0 + x1) / 2 overflows for coordinates near the largest double.
    return {x0 / 2 + x1 / 2, y0 / 2 + y1 / 2};
}

/// The circumcentre of a, b, c minus a, in plain floating point (delaunator's formula):
/// a heuristic's estimate, with no error bound. Infinite or NaN when a, b, c are collinear
/// (the determinant is zero) or the result overflows.
inline Point2 circumcentre_offset(Point2 a, Point2 b, Point2 c) {
    const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    const double bl = bx * bx + by * by, cl = cx * cx + cy * cy;
    const double det = 2 * (bx * cy - by * cx);
    return {(cy * bl - by * cl) / det, (bx * cl - cx * bl) / det};
}

/// The centre of the radial order, chosen as delaunator does: the point nearest the
/// bounding-box centre, its nearest neighbour, and the point making the smallest
/// circumcircle with them; the centre is that circumcircle's centre. Any finite centre
/// makes a correct order (the sort is exact about the centre it is given), so this is
/// computed in plain floating point and falls back to the box centre when degenerate.
/// Why not the box centre itself: on a sampled convex curve the distance from a point
/// inside the curve first falls and then rises along it, so the order starts in the
/// middle and every point added at the end nearer the curve's point of greatest
/// curvature re-triangulates all earlier ones (quadratic; docs/measurements.md). From the centre of
/// the osculating circle the distance is monotone along a convex arc of increasing curvature, and
/// the order walks the curve from one end, as the paper's order does on the favourable branch.
inline Point2 radial_centre(std::span<const Point2> points) {
    const Point2 box = bounding_box_centre(points);
    auto d2 = [](Point2 a, Point2 b) {
        const double dx = a.x - b.x, dy = a.y - b.y;
        return dx * dx + dy * dy;
    };
    auto nearest = [&](Point2 to, std::size_t skip) {
        std::size_t best = points.size();
        double best_d = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double d = d2(points[i], to);
            if (i != skip && (best == points.size() || d < best_d)) best = i, best_d = d;
        }
        return best;
    };
    if (points.size() < 3) return box;
    const std::size_t i0 = nearest(box, points.size());
    const std::size_t i1 = nearest(points[i0], i0);
    if (i1 == points.size()) return box;
    const Point2 a = points[i0], b = points[i1];
    Point2 best = box;
    double best_r = 0;
    bool found = false;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i == i0 || i == i1) continue;
        const Point2 u = circumcentre_offset(a, b, points[i]);
        const double r = u.x * u.x + u.y * u.y;
        // NaN and infinity (collinear points) fail both comparisons and are skipped.
        if (r < std::numeric_limits<double>::infinity() && (!found || r < best_r)) {
            const Point2 c{a.x + u.x, a.y + u.y};
            if (std::isfinite(c.x) && std::isfinite(c.y)) best = c, best_r = r, found = true;
        }
    }
    // Round the centre to the coarsest ulp of the coordinates. The order is exact about
    // whatever centre it gets, so this only matters for speed: on integer or grid-like
    // data the differences p - centre then come out exact, and the predicate's exact
    // stage for near-ties (a curve seen from its osculating centre is all near-ties) is
    // its cheap error-free one.
    double extent = 0;
    for (const Point2& p : points) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    if (extent > 0 && std::isfinite(extent)) {
        const double ulp = std::ldexp(1.0, std::ilogb(extent) - 52);
        const Point2 rounded{std::nearbyint(best.x / ulp) * ulp,
                             std::nearbyint(best.y / ulp) * ulp};
        if (std::isfinite(rounded.x) && std::isfinite(rounded.y)) best = rounded;
    }
    return best;
}

/// Stable bottom-up merge sort. Used for the runs decided by the kernel because an inexact
/// kernel's comparison need not be a strict weak order, and std::sort may then read out
/// of bounds; merging only ever reads inside the two halves it merges.
template <class T, class Less>
void merge_sort(std::span<T> v, Less less) {
    FreshVector<T> buffer(v.size());
    for (std::size_t width = 1; width < v.size(); width *= 2) {
        for (std::size_t lo = 0; lo < v.size(); lo += 2 * width) {
            const std::size_t mid = std::min(lo + width, v.size());
            const std::size_t hi = std::min(lo + 2 * width, v.size());
            std::size_t i = lo, j = mid, out = lo;
            while (i < mid && j < hi) buffer[out++] = less(v[j], v[i]) ? v[j++] : v[i++];
            while (i < mid) buffer[out++] = v[i++];
            while (j < hi) buffer[out++] = v[j++];
        }
        std::copy(buffer.begin(), buffer.end(), v.begin());
    }
}

/// Sorts `run` by |p - centre|^2 evaluated as a double-double (the coordinate differences
/// and squares split into exact head and tail with two_diff / fma): a guess, exact in all
/// but near-ties far below double precision. False when a key is not finite.
template <class Keyed>
bool guess_order(std::span<Keyed> run, std::span<const Point2> points, Point2 centre) {
    struct Guess {
        double hi, lo;
        Keyed keyed;
    };
    auto two_diff = [](double a, double b, double& tail) {
        const double s = a - b, bb = a - s;
        tail = (a - (s + bb)) + (bb - b);
        return s;
    };
    FreshVector<Guess> g(run.size());
    for (std::size_t j = 0; j < run.size(); ++j) {
        const Point2 p = points[run[j].i];
        double tx, ty;
        const double dx = two_diff(p.x, centre.x, tx), dy = two_diff(p.y, centre.y, ty);
        const double sx = dx * dx, sy = dy * dy;
        const double ex = std::fma(dx, dx, -sx), ey = std::fma(dy, dy, -sy);
        const double hi = sx + sy, bv = hi - sx;
        const double e = (sx - (hi - bv)) + (sy - bv);  // two_sum tail
        const double lo = e + ex + ey + 2 * (dx * tx + dy * ty) + (tx * tx + ty * ty);
        if (!std::isfinite(hi) || !std::isfinite(lo)) return false;
        g[j] = {hi + lo, lo - ((hi + lo) - hi), run[j]};
    }
    std::sort(g.begin(), g.end(), [](const Guess& a, const Guess& b) {
        return a.hi != b.hi ? a.hi < b.hi : a.lo != b.lo ? a.lo < b.lo : a.keyed.i < b.keyed.i;
    });
    for (std::size_t j = 0; j < run.size(); ++j) run[j] = g[j].keyed;
    return true;
}

/// radial_order's working arrays, kept by callers that order many point sets (the strips).
/// Fresh memory (memory.hpp): a one-off radial run over 10^6 points sorts 48 MB here.
struct RadialScratch {
    struct Keyed {
        double d;
        std::uint32_t i;
    };
    FreshVector<KeyIndex> by_key;
    FreshVector<KeyIndex> radix_buffer;
    FreshVector<Keyed> keyed;
};

/// Positions of `points` in ascending distance from `centre`, ties by position, into
/// `order`; `scratch` is working memory.
template <PredicateKernel K>
void radial_order(std::span<const Point2> points, Point2 centre, const K& kernel,
                  RadialScratch& scratch, std::vector<std::uint32_t>& order) {
    // Sorted by the key's bits, which order non-negative doubles (+inf included) as
    // numbers; the radix sort is stable, so equal keys stay in position order.
    using Keyed = RadialScratch::Keyed;
    FreshVector<KeyIndex>& by_key = scratch.by_key;
    by_key.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double dx = points[i].x - centre.x, dy = points[i].y - centre.y;
        // May be +inf (overflow), never NaN (the coordinates are finite) nor negative.
        by_key[i] = {std::bit_cast<std::uint64_t>(dx * dx + dy * dy),
                     static_cast<std::uint32_t>(i)};
    }
    radix_sort(by_key, scratch.radix_buffer);
    FreshVector<Keyed>& keyed = scratch.keyed;
    keyed.resize(points.size());
    for (std::size_t j = 0; j < keyed.size(); ++j) {
        keyed[j] = {std::bit_cast<double>(by_key[j].key), by_key[j].index};
    }
    constexpr double r = bounds::radial_key_rel;
    constexpr double below = 1 - 4 * r, above = 1 + 4 * r;
    static_assert(r >= 4 * bounds::epsilon && r <= 1.0 / 3, "the separation argument above");
    auto separated = [&](double lo, double hi) {
        return lo >= bounds::radial_key_min && hi <= bounds::radial_key_max &&
               hi * below > lo * above;
    };
    auto exact_less = [&](const Keyed& a, const Keyed& b) {
        const Sign s = kernel.compare_distance(centre, points[a.i], points[b.i]);
        return s == Sign::negative || (s == Sign::zero && a.i < b.i);
    };
    for (std::size_t lo = 0; lo < keyed.size();) {
        std::size_t hi = lo + 1;
        while (hi < keyed.size() && !separated(keyed[hi - 1].d, keyed[hi].d)) ++hi;
        if (hi - lo > 1) {
            const auto run = std::span<Keyed>(keyed).subspan(lo, hi - lo);
            // A long run (points near a circle about the centre, e.g. a convex curve seen
            // from its osculating centre) would cost n log n exact comparisons. Guess the
            // order first with a double-double key, then check it with n - 1 exact
            // comparisons of neighbours: the comparison (distance, then position) is a
            // strict total order, so neighbours in order means the run is sorted. Only a
            // wrong guess pays for the merge sort. The guess needs no error bound.
            if (run.size() > 8 && guess_order(run, points, centre) &&
                std::adjacent_find(run.begin(), run.end(), [&](const Keyed& a, const Keyed& b) {
                    return exact_less(b, a);
                }) == run.end()) {
                lo = hi;
                continue;
            }
            merge_sort(run, exact_less);
        }
        lo = hi;
    }
    order.resize(points.size());
    for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].i;
}

/// radial_order with working memory of its own.
template <PredicateKernel K>
std::vector<std::uint32_t> radial_order(std::span<const Point2> points, Point2 centre,
                                        const K& kernel) {
    RadialScratch scratch;
    std::vector<std::uint32_t> order;
    radial_order(points, centre, kernel, scratch, order);
    return order;
}

/// The radial order's collinear prefix: the first points of `order` that lie on one line
/// (by the kernel's orient2d, the test Builder::run repeats) are re-sorted by position, so
/// that the seed fans them in order along their line. They stay the nearest points, so
/// the order stays external.
template <PredicateKernel K>
void sort_collinear_prefix(std::span<const Point2> points, std::span<std::uint32_t> order,
                           const K& kernel) {
    std::size_t k = order.size();
    for (std::size_t j = 2; j < order.size(); ++j) {
        if (kernel.orient2d(points[order[0]], points[order[j - 1]], points[order[j]]) !=
            Sign::zero) {
            k = j;
            break;
        }
    }
    std::sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k));
}

}  // namespace exidel::delaunay::detail
