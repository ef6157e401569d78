// exidel::testing: named families of predicate queries, for iterating in tests and
// research tools.
//
//   for (const FamilyInfo& f : all_families())
//       rc::check(std::string(f.name), [&] { auto q = *gen_query3(f.family); ... });
//
// A query is the argument list of one predicate: std::array<Point2, 3> for orient2d,
// std::array<Point2, 4> for incircle and incircle_cosine. See generators.hpp for how
// each family is built and why everything shrinks toward the degenerate configuration.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/types.hpp"
#include "exidel/testing/generators.hpp"

namespace exidel::testing {

using Query3 = std::array<Point2, 3>;
using Query4 = std::array<Point2, 4>;

enum class Family {
    uniform,              ///< uniform in [-1, 1]^2
    uniform_scaled,       ///< uniform in a box of scale 2^k, k in [-1074, 1023]
    wide_exponents,       ///< every coordinate at its own exponent (spread ~2100 bits)
    integer_grid,         ///< small integer grid, translated and scaled exactly
    lattice_circle,       ///< exactly cocircular, on a lattice circle
    dyadic_line,          ///< exactly collinear, on a line of dyadic slope
    near_integer_grid,    ///< integer_grid, every coordinate moved by up to 4 ulps
    near_lattice_circle,  ///< lattice_circle, every coordinate moved by up to 4 ulps
    near_dyadic_line,     ///< dyadic_line, every coordinate moved by up to 4 ulps
    near_rounded_line,    ///< points fma(t, q - p, p) on a line, rounded, then moved
    near_rounded_circle,  ///< points c + R (cos, sin), rounded, then moved
    kettner,              ///< the Kettner et al. configurations over their ulp window
    duplicates,           ///< any other family with points repeated within the query
};

struct FamilyInfo {
    Family family;
    std::string_view name;
    /// True for the families built to sit within a few ulps of a degeneracy (but not on
    /// it): where a non-robust kernel is expected to fail.
    bool near_degenerate;
    /// True for the families whose queries lie on a degeneracy (exactly cocircular,
    /// collinear, repeated points) or within a few ulps of one: every family but the
    /// uniform ones and wide_exponents.
    bool degenerate;
};

/// Every family, in declaration order, with its name (stable: used on command lines and
/// in printed measurements).
inline constexpr std::array<FamilyInfo, 13> all_families() {
    return {{
        {Family::uniform, "uniform", false, false},
        {Family::uniform_scaled, "uniform_scaled", false, false},
        {Family::wide_exponents, "wide_exponents", false, false},
        {Family::integer_grid, "integer_grid", false, true},
        {Family::lattice_circle, "lattice_circle", false, true},
        {Family::dyadic_line, "dyadic_line", false, true},
        {Family::near_integer_grid, "near_integer_grid", true, true},
        {Family::near_lattice_circle, "near_lattice_circle", true, true},
        {Family::near_dyadic_line, "near_dyadic_line", true, true},
        {Family::near_rounded_line, "near_rounded_line", true, true},
        {Family::near_rounded_circle, "near_rounded_circle", true, true},
        {Family::kettner, "kettner", true, true},
        {Family::duplicates, "duplicates", false, true},
    }};
}

/// The name of a family (as in all_families()).
inline std::string_view family_name(Family f) {
    for (const FamilyInfo& info : all_families()) {
        if (info.family == f) return info.name;
    }
    throw std::invalid_argument("family_name: not a Family value");
}

/// The family with the given name; throws std::invalid_argument for unknown names.
inline Family family_from_name(std::string_view name) {
    for (const FamilyInfo& info : all_families()) {
        if (info.name == name) return info.family;
    }
    throw std::invalid_argument("unknown point family '" + std::string(name) + "'");
}

rc::Gen<std::vector<Point2>> gen_points(Family f, std::size_t n);

/// n points of another family (any but duplicates) in which some points repeat: at
/// least one pair is forced equal, and each later point may copy an earlier one.
/// Shrinks toward every point a copy of the first ("all duplicates").
inline rc::Gen<std::vector<Point2>> gen_duplicate_points(std::size_t n) {
    return rc::gen::exec([n] {
        constexpr auto families = all_families();
        static_assert(families.back().family == Family::duplicates, "base excludes the last");
        const auto base = families[*rc::gen::inRange<std::size_t>(0, families.size() - 1)];
        std::vector<Point2> points = *gen_points(base.family, n);
        if (n < 2) return points;
        // copy_of[i] <= i: point i becomes point copy_of[i] (itself when equal).
        for (std::size_t i = 1; i < n; ++i) {
            const bool copy = !*rc::gen::arbitrary<bool>();  // shrinks toward copying
            if (copy) points[i] = points[*rc::gen::inRange<std::size_t>(0, i)];
        }
        const std::size_t later = *rc::gen::inRange<std::size_t>(1, n);
        points[later] = points[*rc::gen::inRange<std::size_t>(0, later)];
        return points;
    });
}

/// n points of family f, sharing the family's structure (one circle, one line, ...).
inline rc::Gen<std::vector<Point2>> gen_points(Family f, std::size_t n) {
    switch (f) {
        case Family::uniform: return gen_uniform_points(n);
        case Family::uniform_scaled: return gen_uniform_scaled_points(n);
        case Family::wide_exponents: return gen_wide_exponent_points(n);
        case Family::integer_grid: return gen_integer_grid_points(n);
        case Family::lattice_circle: return gen_lattice_circle_points(n);
        case Family::dyadic_line: return gen_dyadic_line_points(n);
        case Family::near_integer_grid:
            return rc::gen::mapcat(gen_integer_grid_points(n), [](std::vector<Point2> p) {
                return gen_nudged(std::move(p), 4);
            });
        case Family::near_lattice_circle:
            return rc::gen::mapcat(gen_lattice_circle_points(n), [](std::vector<Point2> p) {
                return gen_nudged(std::move(p), 4);
            });
        case Family::near_dyadic_line:
            return rc::gen::mapcat(gen_dyadic_line_points(n), [](std::vector<Point2> p) {
                return gen_nudged(std::move(p), 4);
            });
        case Family::near_rounded_line: return gen_rounded_line_points(n);
        case Family::near_rounded_circle: return gen_rounded_circle_points(n);
        case Family::kettner: return gen_kettner_points(n);
        case Family::duplicates: return gen_duplicate_points(n);
    }
    throw std::invalid_argument("gen_points: not a Family value");
}

namespace detail {
template <std::size_t N>
std::array<Point2, N> to_query(const std::vector<Point2>& points) {
    std::array<Point2, N> q{};
    std::copy_n(points.begin(), N, q.begin());
    return q;
}
}  // namespace detail

/// An orient2d query (a, b, c) of family f.
inline rc::Gen<Query3> gen_query3(Family f) {
    return rc::gen::map(gen_points(f, 3), &detail::to_query<3>);
}

/// An incircle query (a, b, c, d) of family f.
inline rc::Gen<Query4> gen_query4(Family f) {
    return rc::gen::map(gen_points(f, 4), &detail::to_query<4>);
}

/// True when c and d are strictly on opposite sides of line ab, decided exactly (by the
/// exact kernel K; the reference by default): the precondition under which
/// incircle_cosine is an in-circle test (kernel.hpp).
template <class K = GmpExactKernel>
bool cosine_precondition_holds(const Query4& q, const K& k = {}) {
    return to_int(k.orient2d(q[0], q[1], q[2])) * to_int(k.orient2d(q[0], q[1], q[3])) < 0;
}

/// The same four points reordered as (a, b, c, d) so that c and d are strictly on
/// opposite sides of line ab, when any pairing allows it: for four points with no three
/// collinear one always does (a diagonal of their convex hull, or the line from the
/// inner point through a corner). The original order is kept when it already qualifies
/// and returned unchanged when nothing qualifies (collinear or repeated points).
/// K decides the sides, as in cosine_precondition_holds.
template <class K = GmpExactKernel>
Query4 arrange_for_cosine(const Query4& q, const K& k = {}) {
    // The pair (a, b) among the six pairs of indices; c and d are the other two.
    constexpr std::array<std::array<int, 4>, 6> orders{
        {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}}};
    for (const auto& o : orders) {
        const Query4 r{q[o[0]], q[o[1]], q[o[2]], q[o[3]]};
        if (cosine_precondition_holds(r, k)) return r;
    }
    return q;
}

/// An incircle_cosine query of family f, arranged (arrange_for_cosine) so that the
/// precondition holds whenever the four points allow it, including for cocircular and
/// near-cocircular quadruples, whose diagonal becomes ab.
inline rc::Gen<Query4> gen_cosine_query(Family f) {
    return rc::gen::map(gen_query4(f), [](const Query4& q) { return arrange_for_cosine(q); });
}

}  // namespace exidel::testing
