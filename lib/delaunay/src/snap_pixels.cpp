// exidel: the pixels of the double grid that a segment meets, exactly (snap rounding of a
// constrained triangulation's segments, detail/constrained.hpp).
//
// The pixel of a double point p is the set of real points that round to p, coordinate by
// coordinate, to nearest with ties to even: in x, the interval between the midpoints of
// p.x and its two neighbouring doubles, each end included when p.x is the even one of the
// two doubles it separates (its last significand bit is 0, which ties go to), else
// excluded; the same in y. The pixels of all doubles thus tile the plane without overlap,
// and the rounded crossing of two segments is exactly the double whose pixel holds their
// exact crossing (Hobby's hot pixel). Everything below is rational arithmetic (GMP):
// midpoints of doubles and parameters along a segment are exact quotients.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <boost/multiprecision/gmp.hpp>

#include "exidel/delaunay/constrained.hpp"

namespace exidel::delaunay::detail {

namespace {

using Rational = boost::multiprecision::mpq_rational;

/// One end of an interval: a value, and whether the value itself belongs to it.
struct Bound {
    Rational value;
    bool closed = true;
};

struct Interval {
    Bound lo, hi;
    bool empty() const {
        return lo.value > hi.value || (lo.value == hi.value && !(lo.closed && hi.closed));
    }
};

bool even(double x) { return (std::bit_cast<std::uint64_t>(x) & 1U) == 0; }

/// The pixel of coordinate x: the reals that round to x.
Interval pixel_range(double x) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double below = std::nextafter(x, -inf), above = std::nextafter(x, inf);
    const Rational rx(x);
    // At the largest finite magnitude, the neighbour beyond is infinity: the pixel is as
    // wide on that side as on the other (the values that still round to x, not beyond).
    const Rational lo =
        std::isinf(below) ? rx - (Rational(above) - rx) / 2 : (Rational(below) + rx) / 2;
    const Rational hi =
        std::isinf(above) ? rx + (rx - Rational(below)) / 2 : (Rational(above) + rx) / 2;
    return {{lo, even(x)}, {hi, even(x)}};
}

/// The parameters t in [0, 1] of a + t (b - a) whose coordinate lies in `range`
/// (a coordinate of the segment: from a to b).
Interval slab(double a, double b, const Interval& range) {
    const Rational ra(a), d = Rational(b) - ra;
    if (d == 0) {
        const bool in = (range.lo.value < ra || (range.lo.value == ra && range.lo.closed)) &&
                        (ra < range.hi.value || (ra == range.hi.value && range.hi.closed));
        if (in) return {{Rational(0), true}, {Rational(1), true}};
        return {{Rational(1), true}, {Rational(0), true}};  // empty
    }
    Bound lo{(range.lo.value - ra) / d, range.lo.closed},
        hi{(range.hi.value - ra) / d, range.hi.closed};
    if (d < 0) std::swap(lo, hi);
    return {lo, hi};
}

Bound tighter_lo(const Bound& x, const Bound& y) {
    if (x.value != y.value) return x.value > y.value ? x : y;
    return {x.value, x.closed && y.closed};
}
Bound tighter_hi(const Bound& x, const Bound& y) {
    if (x.value != y.value) return x.value < y.value ? x : y;
    return {x.value, x.closed && y.closed};
}

}  // namespace

std::vector<std::uint32_t> pixels_on_segment(Point2 a, Point2 b, std::span<const Point2> points,
                                             std::span<const std::uint32_t> candidates) {
    struct Hit {
        Bound entry;
        std::uint32_t vertex;
    };
    std::vector<Hit> hits;
    const double dx = b.x - a.x, dy = b.y - a.y;
    for (const std::uint32_t v : candidates) {
        const Point2 p = points[v];
        // A quick rejection in doubles: the line through a and b passes within hx |dy| +
        // hy |dx| (in the cross product's units) of p when it meets p's pixel, whose half
        // widths hx, hy are at most half an ulp of p's coordinates (2^-53 of them, plus
        // half the smallest subnormal). The computed cross product is off by less than
        // 10^-14 of the sum of its terms' magnitudes (five roundings of 2^-53 each, counting
        // those of dx and dy), plus, where products underflow, a few subnormals: 2^-1060
        // covers those; doubling the reach covers the roundings of the bound itself
        // (proofs/bounds.md#snap-pixels).
        {
            const double ux = p.x - a.x, uy = p.y - a.y;
            const double cross = dx * uy - dy * ux;
            const double hx =
                std::ldexp(std::abs(p.x), -52) + std::numeric_limits<double>::denorm_min();
            const double hy =
                std::ldexp(std::abs(p.y), -52) + std::numeric_limits<double>::denorm_min();
            const double reach = 2 * (hx * std::abs(dy) + hy * std::abs(dx)) +
                                 1e-14 * (std::abs(dx * uy) + std::abs(dy * ux)) +
                                 std::ldexp(1.0, -1060);
            if (std::abs(cross) > reach) continue;
        }
        const Interval tx = slab(a.x, b.x, pixel_range(p.x));
        if (tx.empty()) continue;
        const Interval ty = slab(a.y, b.y, pixel_range(p.y));
        if (ty.empty()) continue;
        Interval t{tighter_lo(tx.lo, ty.lo), tighter_hi(tx.hi, ty.hi)};
        t.lo = tighter_lo(t.lo, {Rational(0), true});
        t.hi = tighter_hi(t.hi, {Rational(1), true});
        if (t.empty()) continue;
        hits.push_back({t.lo, v});
    }
    // The pixels are disjoint, so their intervals along the segment are too: ordered by
    // where they begin (a closed beginning before an open one at the same parameter).
    std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) {
        if (x.entry.value != y.entry.value) return x.entry.value < y.entry.value;
        return x.entry.closed && !y.entry.closed;
    });
    std::vector<std::uint32_t> out;
    out.reserve(hits.size());
    for (const Hit& h : hits) out.push_back(h.vertex);
    return out;
}

}  // namespace exidel::delaunay::detail
