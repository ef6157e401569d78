// exidel tests: the oracle and the query families of compare_distance(c, p, q).
//
// A query is (c, p, q). Beside the shared families (exidel::testing, read as (c, p, q) =
// the three points of an orient2d query), exact ties are what a radial sort meets on grids
// and what a sign test must get exactly zero: these generators build them from integers
// and place them with exact operations only, and the near variants move them by ulps.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <rapidcheck.h>

#include "cgal_oracle.hpp"
#include "exidel/testing/all.hpp"

namespace exidel::test {

using DistanceQuery = std::array<Point2, 3>;  // c, p, q

/// CGAL::compare_distance_to_point(c, p, q) (CGAL 5.5, Epick, exact): SMALLER iff p is
/// closer to c than q. Comparison_result is CGAL::Sign with SMALLER = NEGATIVE, so it is
/// directly the sign of |p - c|^2 - |q - c|^2.
inline Sign cgal_compare_distance(Point2 c, Point2 p, Point2 q) {
    return to_sign(CGAL::compare_distance_to_point(to_cgal(c), to_cgal(p), to_cgal(q)));
}

/// The integer offset (a, b) mapped to another offset of exactly the same length:
/// the eight symmetries of the square, or (3m, 4m) -> (5m, 0) style Pythagorean pairs.
inline std::array<testing::LatticePoint, 2> tie_offsets(std::int64_t a, std::int64_t b, int which) {
    using L = testing::LatticePoint;
    const L p{a, b};
    switch (which) {
        case 0: return {p, L{b, a}};
        case 1: return {p, L{-a, b}};
        case 2: return {p, L{a, -b}};
        case 3: return {p, L{-b, a}};
        case 4: return {p, L{b, -a}};
        case 5: return {p, L{-a, -b}};
        case 6: return {p, p};
        default: return {L{3 * a, 4 * a}, L{5 * a, 0}};  // 9a^2 + 16a^2 = 25a^2
    }
}

/// Exact ties: c an integer point translated by up to 2^30, p = c + (a, b),
/// q = c + (a', b') with a'^2 + b'^2 = a^2 + b^2, |a|, |b| up to 2^20 (so the squares can
/// exceed 2^53 and be inexact as doubles), all scaled by 2^k over the whole exact range.
/// Shrinks toward c = 0, small offsets, 2^0.
inline rc::Gen<DistanceQuery> gen_exact_tie() {
    return rc::gen::exec([] {
        constexpr std::int64_t t = std::int64_t{1} << 30, r = std::int64_t{1} << 20;
        const testing::LatticePoint c{*testing::gen_toward_zero(-t, t),
                                      *testing::gen_toward_zero(-t, t)};
        const std::int64_t a = *testing::gen_toward_zero(-r, r);
        const std::int64_t b = *testing::gen_toward_zero(-r, r);
        const auto [p, q] = tie_offsets(a, b, *rc::gen::inRange(0, 8));
        const int k =
            *testing::gen_scale_exponent(testing::min_exact_scale, testing::max_scale_for_bits(33));
        const auto pts = testing::place({{0, 0}, p, q}, c, k);
        return DistanceQuery{pts[0], pts[1], pts[2]};
    });
}

/// Ties of the offsets, but c is any point of a box of scale 2^kc and p = fl(c + (a, b) 2^j):
/// the differences p - c round, so the exact answer is usually not zero and the adaptive
/// kernel's exact stage sees nonzero tails.
inline rc::Gen<DistanceQuery> gen_rounded_tie() {
    return rc::gen::exec([] {
        const Point2 c = *testing::gen_point_in_box(*rc::gen::inRange(-60, 61));
        const std::int64_t a = *testing::gen_toward_zero(-1000, 1000);
        const std::int64_t b = *testing::gen_toward_zero(-1000, 1000);
        const auto [p, q] = tie_offsets(a, b, *rc::gen::inRange(0, 8));
        const int j = *rc::gen::inRange(-80, 41);
        const auto at = [&](testing::LatticePoint o) {
            return Point2{c.x + testing::dyadic(o.first, j), c.y + testing::dyadic(o.second, j)};
        };
        return DistanceQuery{c, at(p), at(q)};
    });
}

/// An exact tie with every coordinate moved by up to 4 ulps (shrinking toward the tie).
inline rc::Gen<DistanceQuery> gen_nudged_tie() {
    return rc::gen::mapcat(gen_exact_tie(), [](DistanceQuery q) {
        return rc::gen::map(testing::gen_nudged({q[0], q[1], q[2]}, 4),
                            [](const std::vector<Point2>& v) {
                                return DistanceQuery{v[0], v[1], v[2]};
                            });
    });
}

}  // namespace exidel::test
