// exidel::testing: RapidCheck generators of points for fuzzing geometric code.
//
// Each generator first builds an exactly known structure (a lattice circle, a line of
// dyadic slope, an integer grid, ...) from integers, then places it with exact
// operations only (integer translation, scaling by 2^k through std::ldexp), and the
// near-degenerate variants finally move every coordinate by a few ulps with
// std::nextafter. Every random choice shrinks toward 0, which means: offsets toward
// none (the exact degenerate configuration), scales toward 2^0, translations toward 0,
// structure toward the simplest case. A failing property therefore shrinks to an
// exactly degenerate input, or to the fewest ulps away from one that still fails.
//
// Why no plain arithmetic on doubles: a caller compiled with contraction on would fuse
// a*b+c and generate different points from the same seed (docs/background.md section 2). The
// helpers in ulp.hpp are exact or round once by definition, and the only inexact step used here is
// an explicit std::fma, which rounds once under every compiler flag.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "exidel/predicates/types.hpp"
#include "exidel/testing/lattice.hpp"
#include "exidel/testing/show.hpp"
#include "exidel/testing/ulp.hpp"

namespace exidel::testing {

// ---------------------------------------------------------------------------------
// Building blocks.

/// An integer in [lo, hi] (lo <= 0 <= hi) that shrinks toward 0 from either side.
inline rc::Gen<std::int64_t> gen_toward_zero(std::int64_t lo, std::int64_t hi) {
    return rc::gen::exec([lo, hi] {
        const bool negative = lo < 0 && (hi == 0 || *rc::gen::arbitrary<bool>());
        if (negative) return -*rc::gen::inRange<std::int64_t>(0, -lo + 1);
        return *rc::gen::inRange<std::int64_t>(0, hi + 1);
    });
}

/// A signed number of ulp steps in [-max_steps, max_steps], shrinking toward none.
inline rc::Gen<std::int64_t> gen_ulp_offset(std::int64_t max_steps) {
    return gen_toward_zero(-max_steps, max_steps);
}

/// A power-of-two exponent in [lo, hi] (lo <= 0 <= hi), shrinking toward 2^0.
inline rc::Gen<int> gen_scale_exponent(int lo, int hi) {
    return rc::gen::map(gen_toward_zero(lo, hi), [](std::int64_t k) { return int(k); });
}

/// Largest exponent k for which n * 2^k is finite for every |n| < 2^bits.
constexpr int max_scale_for_bits(int bits) { return 1024 - bits; }
/// Smallest exponent k for which n * 2^k is exact for every integer n: the subnormal grid.
inline constexpr int min_exact_scale = -1074;

/// A double on the grid 2^-53 in [-1, 1]: uniform over the 2^54 + 1 grid values.
inline rc::Gen<double> gen_unit_coordinate() {
    constexpr std::int64_t one = std::int64_t{1} << 53;
    return rc::gen::map(gen_toward_zero(-one, one), [](std::int64_t m) { return dyadic(m, -53); });
}

/// A point uniform in the box [-2^k, 2^k]^2 (grid 2^(k-53), rounded once by std::ldexp
/// when that grid falls below the subnormals).
inline rc::Gen<Point2> gen_point_in_box(int k) {
    constexpr std::int64_t one = std::int64_t{1} << 53;
    return rc::gen::exec([k] {
        const std::int64_t mx = *gen_toward_zero(-one, one);
        const std::int64_t my = *gen_toward_zero(-one, one);
        return Point2{dyadic(mx, k - 53), dyadic(my, k - 53)};
    });
}

/// Any finite double: a random 53-bit significand at a random exponent over the whole
/// range, including subnormals (from 2^-1074) and magnitudes up to 2^1024 - 2^971.
inline rc::Gen<double> gen_any_finite_double() {
    constexpr std::int64_t one = std::int64_t{1} << 53;
    return rc::gen::exec([] {
        const std::int64_t m = *gen_toward_zero(-(one - 1), one - 1);
        const int k = *gen_scale_exponent(-1074, 1023);
        return dyadic(m, k - 52);  // |m| < 2^53, so |result| < 2^(k+1) <= 2^1024
    });
}

/// Each coordinate of each point moved by up to max_steps ulps (shrinking toward none).
inline rc::Gen<std::vector<Point2>> gen_nudged(std::vector<Point2> points, std::int64_t max_steps) {
    return rc::gen::exec([points = std::move(points), max_steps] {
        std::vector<Point2> moved = points;
        for (Point2& p : moved) {
            const std::int64_t dx = *gen_ulp_offset(max_steps);
            const std::int64_t dy = *gen_ulp_offset(max_steps);
            p = nudge(p, dx, dy);
        }
        return moved;
    });
}

/// Integer points translated by the integer vector t and scaled by 2^k. Exact as long
/// as every |coordinate + t| < 2^53 and k is in [min_exact_scale, max_scale_for_bits].
inline std::vector<Point2> place(const std::vector<LatticePoint>& integer_points, LatticePoint t,
                                 int k) {
    std::vector<Point2> out;
    out.reserve(integer_points.size());
    for (const auto& [x, y] : integer_points) {
        out.push_back({dyadic(x + t.first, k), dyadic(y + t.second, k)});
    }
    return out;
}

// ---------------------------------------------------------------------------------
// Point families. Each returns n points that share one structure.

/// n points uniform in [-1, 1]^2 (no structure: the easy case every kernel gets right).
inline rc::Gen<std::vector<Point2>> gen_uniform_points(std::size_t n) {
    return rc::gen::container<std::vector<Point2>>(n, gen_point_in_box(0));
}

/// n points uniform in one box [-2^k, 2^k]^2, k anywhere in the exponent range: from
/// boxes of subnormals (k near -1074, coordinates rounded onto the subnormal grid) to
/// magnitudes near 1e+300 (k up to 1023).
inline rc::Gen<std::vector<Point2>> gen_uniform_scaled_points(std::size_t n) {
    return rc::gen::exec([n] {
        const int k = *gen_scale_exponent(-1074, 1023);
        return *rc::gen::container<std::vector<Point2>>(n, gen_point_in_box(k));
    });
}

/// n points whose coordinates each have their own exponent anywhere in the range: a
/// query's exponent spread reaches ~2100 bits, the worst case for exact alignment and
/// for the MPFR precision bounds.
inline rc::Gen<std::vector<Point2>> gen_wide_exponent_points(std::size_t n) {
    return rc::gen::container<std::vector<Point2>>(
        n, rc::gen::build<Point2>(rc::gen::set(&Point2::x, gen_any_finite_double()),
                                  rc::gen::set(&Point2::y, gen_any_finite_double())));
}

/// n points of a small integer grid [-G, G]^2 (G <= 8, so many collinear and
/// cocircular subsets), translated by an integer vector of up to 2^30 and scaled by 2^k.
inline rc::Gen<std::vector<Point2>> gen_integer_grid_points(std::size_t n) {
    return rc::gen::exec([n] {
        const std::int64_t g = *rc::gen::inRange<std::int64_t>(1, 9);
        const auto coordinate = gen_toward_zero(-g, g);
        std::vector<LatticePoint> ints;
        for (std::size_t i = 0; i < n; ++i) ints.emplace_back(*coordinate, *coordinate);
        constexpr std::int64_t t = std::int64_t{1} << 30;
        const LatticePoint shift{*gen_toward_zero(-t, t), *gen_toward_zero(-t, t)};
        const int k = *gen_scale_exponent(min_exact_scale, max_scale_for_bits(32));
        return place(ints, shift, k);
    });
}

/// n points exactly on one lattice circle (lattice.hpp; radius 5 up to 48612265),
/// translated by an integer vector of up to 2^26 and scaled by 2^k: every four of them
/// are exactly cocircular (or repeat a point, which small radii do often).
inline rc::Gen<std::vector<Point2>> gen_lattice_circle_points(std::size_t n) {
    return rc::gen::exec([n] {
        const int primes = *rc::gen::inRange(1, lattice_prime_count + 1);
        std::vector<LatticePoint> ints;
        for (std::size_t i = 0; i < n; ++i) {
            const auto choices = *rc::gen::container<std::vector<int>>(
                static_cast<std::size_t>(primes), rc::gen::inRange(0, 3));
            const int unit = *rc::gen::inRange(0, 4);
            ints.push_back(lattice_circle_point(choices, unit));
        }
        constexpr std::int64_t t = std::int64_t{1} << 26;
        const LatticePoint shift{*gen_toward_zero(-t, t), *gen_toward_zero(-t, t)};
        const int k = *gen_scale_exponent(min_exact_scale, max_scale_for_bits(28));
        return place(ints, shift, k);
    });
}

/// n points exactly on one line of dyadic slope p / 2^q (|p| <= 2^20, q <= 20), or its
/// mirror in the diagonal (slope 2^q / p): base + t_i * (2^q, p) with an integer base of
/// up to 2^30 and |t_i| <= 2^10, then scaled by 2^k. Every triple is exactly collinear.
inline rc::Gen<std::vector<Point2>> gen_dyadic_line_points(std::size_t n) {
    return rc::gen::exec([n] {
        constexpr std::int64_t b = std::int64_t{1} << 30;
        const std::int64_t bx = *gen_toward_zero(-b, b), by = *gen_toward_zero(-b, b);
        const std::int64_t run = std::int64_t{1} << *rc::gen::inRange(0, 21);
        const std::int64_t rise = *gen_toward_zero(-(1 << 20), 1 << 20);
        const bool mirrored = *rc::gen::arbitrary<bool>();
        std::vector<LatticePoint> ints;
        for (std::size_t i = 0; i < n; ++i) {
            const std::int64_t t = *gen_toward_zero(-(1 << 10), 1 << 10);
            const std::int64_t x = bx + t * run, y = by + t * rise;  // |.| <= 2^31
            ints.push_back(mirrored ? LatticePoint{y, x} : LatticePoint{x, y});
        }
        const int k = *gen_scale_exponent(min_exact_scale, max_scale_for_bits(33));
        return place(ints, {0, 0}, k);
    });
}

/// n points near one line: p and q uniform in a box of scale 2^k, and every point
/// fma(t, q - p, p) for a dyadic t in [-2, 4], rounded once. The classic near-collinear
/// input: exact orientations are almost never zero and mostly far below the rounding
/// error of the plain formula. The points are further moved by up to 4 ulps.
inline rc::Gen<std::vector<Point2>> gen_rounded_line_points(std::size_t n) {
    return rc::gen::exec([n] {
        const int k = *gen_scale_exponent(-900, 900);
        const Point2 p = *gen_point_in_box(k), q = *gen_point_in_box(k);
        std::vector<Point2> points;
        for (std::size_t i = 0; i < n; ++i) {
            const double t = dyadic(*gen_toward_zero(-(1 << 21), 1 << 22), -20);
            points.push_back({std::fma(t, q.x - p.x, p.x), std::fma(t, q.y - p.y, p.y)});
        }
        return *gen_nudged(std::move(points), 4);
    });
}

/// n points near one circle: centre c uniform in a box of scale 2^kc (kc <= 30),
/// radius R in [1/8, 1], points fma(R, cos(theta), c) rounded once, then moved by up
/// to 4 ulps and scaled by 2^k. Near-cocircular queries as a mesher meets them: the
/// centre is far from the origin relative to the radius.
inline rc::Gen<std::vector<Point2>> gen_rounded_circle_points(std::size_t n) {
    return rc::gen::exec([n] {
        const Point2 c = *gen_point_in_box(*rc::gen::inRange(0, 31));
        const double r = dyadic(
            *rc::gen::inRange<std::int64_t>(std::int64_t{1} << 50, (std::int64_t{1} << 53) + 1),
            -53);
        std::vector<Point2> points;
        for (std::size_t i = 0; i < n; ++i) {
            // theta in [0, 6.5): a dyadic angle, so the same on every platform's input side.
            const double theta =
                dyadic(*rc::gen::inRange<std::int64_t>(0, std::int64_t{13} << 40), -41);
            points.push_back(
                {std::fma(r, std::cos(theta), c.x), std::fma(r, std::sin(theta), c.y)});
        }
        const int k = *gen_scale_exponent(-900, 900);
        std::vector<Point2> scaled = *gen_nudged(std::move(points), 4);
        for (Point2& p : scaled) p = {std::ldexp(p.x, k), std::ldexp(p.y, k)};
        return scaled;
    });
}

/// The three configurations of Kettner, Mehlhorn, Pion, Schirra and Yap (CGTA 2008;
/// docs/background.md section 4), as literal doubles.
inline constexpr std::array<std::array<Point2, 3>, 3> kettner_configurations{{
    {{{0.5, 0.5}, {12, 12}, {24, 24}}},
    {{{0.50000000000002531, 0.5000000000000171},
      {17.300000000000001, 17.300000000000001},
      {24.00000000000005, 24.0000000000000517765}}},
    {{{0.5, 0.5}, {8.8000000000000007, 8.8000000000000007}, {12.1, 12.1}}},
}};

/// A Kettner et al. configuration with p moved over their 256 x 256 window of ulp steps
/// (p.x + i ulp, p.y + j ulp, 0 <= i, j < 256, shrinking toward p itself); q and r as
/// published. Points beyond the third lie on the diagonal y = x (exactly collinear with
/// the first configuration) at dyadic positions in [0.5, 16) (k 2^-47, 2^46 <= k < 2^51).
inline rc::Gen<std::vector<Point2>> gen_kettner_points(std::size_t n) {
    return rc::gen::exec([n] {
        const auto& config = kettner_configurations[*rc::gen::inRange<std::size_t>(0, 3)];
        const std::int64_t i = *rc::gen::inRange<std::int64_t>(0, 256);
        const std::int64_t j = *rc::gen::inRange<std::int64_t>(0, 256);
        std::vector<Point2> points{nudge(config[0], i, j), config[1], config[2]};
        while (points.size() < n) {
            const double v = dyadic(
                *rc::gen::inRange<std::int64_t>(std::int64_t{1} << 46, std::int64_t{1} << 51), -47);
            points.push_back({v, v});
        }
        points.resize(n);
        return points;
    });
}

}  // namespace exidel::testing
