// exidel::testing: exact moves on the double grid.
//
// Every helper here is exact or rounds exactly once by definition (std::nextafter,
// std::ldexp, std::frexp, integer arithmetic), so its result does not depend on whether
// the caller's translation unit contracts a*b+c into a fused multiply-add (docs/background.md
// section 2: inputs generated under contraction come out different).
#pragma once

#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "exidel/predicates/predicate.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::testing {

/// v moved by |steps| representable doubles, up if steps > 0, down if steps < 0.
/// Stops at the largest finite magnitude instead of reaching infinity, so the result is
/// finite whenever v is. Crosses zero and the subnormals like any other step.
inline double nudge(double v, std::int64_t steps) {
    constexpr double top = std::numeric_limits<double>::max();
    for (; steps > 0 && v < top; --steps) v = std::nextafter(v, top);
    for (; steps < 0 && v > -top; ++steps) v = std::nextafter(v, -top);
    return v;
}

/// p with x moved by dx and y by dy representable doubles (see nudge).
inline Point2 nudge(Point2 p, std::int64_t dx, std::int64_t dy) {
    return {nudge(p.x, dx), nudge(p.y, dy)};
}

/// The integer n times 2^k, exact when |n| < 2^53 and the result is representable
/// (no overflow, and k >= -1074 so no bit falls below the subnormal grid).
inline double dyadic(std::int64_t n, int k) { return std::ldexp(static_cast<double>(n), k); }

/// The exponent q of the last significand bit of v != 0: v = m * 2^q with |m| < 2^53
/// an integer. Subnormals get q < -1074 with trailing zero bits in m, which is harmless.
inline int low_exponent(double v) {
    int e = 0;
    (void)std::frexp(v, &e);
    return e - std::numeric_limits<double>::digits;
}

/// b of proofs/bitcounts.md: the number of bits of the largest coordinate of `points` once all
/// coordinates are written as integers on the common grid 2^min(q), i.e. 53 + the
/// spread of the low exponents. 0 when every coordinate is zero.
template <class P>
int grid_bits_of(std::span<const P> points) {
    int lo = INT_MAX, hi = INT_MIN;
    for (const P& p : points) {
        double coordinates[3] = {p.x, p.y, 0};
        if constexpr (requires { p.z; }) coordinates[2] = p.z;
        for (double v : coordinates) {
            if (v == 0) continue;
            const int q = low_exponent(v);
            lo = q < lo ? q : lo;
            hi = q > hi ? q : hi;
        }
    }
    return lo == INT_MAX ? 0 : std::numeric_limits<double>::digits + (hi - lo);
}
inline int grid_bits(std::span<const Point2> points) { return grid_bits_of(points); }
inline int grid_bits(std::span<const Point3> points) { return grid_bits_of(points); }

/// Significand bits with which the textbook formulas (predicates/src/formulas.hpp) are
/// exact for a query of grid width b: differences take b+1 bits, each product doubles and
/// each sum adds one. proofs/bitcounts.md derives them per intermediate for our evaluation
/// order; the cosine form needs 8b+12 there (an earlier count, 8b+13, included a final
/// subtraction that our comparison of the two sides does not perform).
/// Never below 53, so that the inputs themselves are exact.
constexpr unsigned at_least_53(int bits) { return bits < 53 ? 53u : unsigned(bits); }
constexpr unsigned orient2d_bits(int b) { return at_least_53(2 * b + 3); }
constexpr unsigned incircle_bits(int b) { return at_least_53(4 * b + 8); }
constexpr unsigned incircle_cosine_bits(int b) { return at_least_53(8 * b + 12); }
/// The predicates of space (proofs/bitcounts.md): degree 3 and degree 5 with lifts.
constexpr unsigned orient3d_bits(int b) { return at_least_53(3 * b + 6); }
constexpr unsigned insphere_bits(int b) { return at_least_53(5 * b + 12); }
/// The count for predicate p (compare_distance has degree 2, like orient2d).
constexpr unsigned exact_bits(Predicate p, int b) {
    switch (p) {
        case Predicate::orient2d:
        case Predicate::compare_distance: return orient2d_bits(b);
        case Predicate::incircle: return incircle_bits(b);
        case Predicate::incircle_cosine: return incircle_cosine_bits(b);
    }
    return 0;
}
constexpr unsigned exact_bits(SpacePredicate p, int b) {
    switch (p) {
        case SpacePredicate::orient3d: return orient3d_bits(b);
        case SpacePredicate::insphere: return insphere_bits(b);
    }
    return 0;
}

}  // namespace exidel::testing
