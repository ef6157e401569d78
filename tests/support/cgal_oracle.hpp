// exidel tests: the oracles. CGAL's exact predicates for orient2d, incircle, orient3d and
// insphere, and an independent exact evaluation of the cosine expression (CGAL has no
// such predicate).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>

#include "exidel/predicates/types.hpp"

namespace exidel::test {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

inline Epick::Point_2 to_cgal(Point2 p) { return {p.x, p.y}; }

inline Sign to_sign(CGAL::Sign s) {
    return s == CGAL::POSITIVE ? Sign::positive : s == CGAL::NEGATIVE ? Sign::negative : Sign::zero;
}

/// CGAL::orientation with Epick: exact for every finite double (filters, then exact).
inline Sign cgal_orient2d(Point2 a, Point2 b, Point2 c) {
    return to_sign(CGAL::orientation(to_cgal(a), to_cgal(b), to_cgal(c)));
}

/// CGAL::side_of_oriented_circle with Epick: positive iff d is inside the circle through
/// a, b, c when abc is counter-clockwise, i.e. Shewchuk's incircle convention. For
/// collinear abc it is still the sign of the same determinant.
inline Sign cgal_incircle(Point2 a, Point2 b, Point2 c, Point2 d) {
    return to_sign(CGAL::side_of_oriented_circle(to_cgal(a), to_cgal(b), to_cgal(c), to_cgal(d)));
}

inline Epick::Point_3 to_cgal(Point3 p) { return {p.x, p.y, p.z}; }

/// orient3d from CGAL::orientation with Epick (exact). CGAL's orientation(a, b, c, d) is
/// the sign of det(b - a, c - a, d - a) = -det(a - d, b - d, c - d): the opposite of
/// Shewchuk's convention, which exidel follows (kernel.hpp).
inline Sign cgal_orient3d(Point3 a, Point3 b, Point3 c, Point3 d) {
    return -to_sign(CGAL::orientation(to_cgal(a), to_cgal(b), to_cgal(c), to_cgal(d)));
}

/// insphere from CGAL::side_of_oriented_sphere with Epick (exact): CGAL's is positive
/// when e is inside and orientation(a, b, c, d) is positive, i.e. when Shewchuk's orient3d
/// is negative, so it is the opposite of exidel's insphere.
inline Sign cgal_insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e) {
    return -to_sign(
        CGAL::side_of_oriented_sphere(to_cgal(a), to_cgal(b), to_cgal(c), to_cgal(d), to_cgal(e)));
}

/// True when c and d are strictly on opposite sides of line ab, decided by CGAL.
inline bool cgal_cosine_precondition(Point2 a, Point2 b, Point2 c, Point2 d) {
    return to_int(cgal_orient2d(a, b, c)) * to_int(cgal_orient2d(a, b, d)) < 0;
}

/// The sign of -(|a-c||b-c| u + |a-d||b-d| v), u = (a-d).(b-d), v = (a-c).(b-c), in
/// exact rationals, written independently of the kernels' cosine_decision:
/// E = X + Y with X = sqrt(P) u, Y = sqrt(Q) v, P = |a-c|^2 |b-c|^2, Q = |a-d|^2 |b-d|^2.
/// When X and Y have opposite signs, E * (X - Y) = X^2 - Y^2 = P u^2 - Q v^2 and
/// sign(X - Y) = sign(X), so sign(E) = sign(X) * sign(P u^2 - Q v^2).
inline Sign independent_cosine_sign(Point2 a, Point2 b, Point2 c, Point2 d) {
    using Q = CGAL::Gmpq;
    const auto dot_at = [](Point2 p, Point2 q, Point2 o) {
        return (Q(p.x) - Q(o.x)) * (Q(q.x) - Q(o.x)) + (Q(p.y) - Q(o.y)) * (Q(q.y) - Q(o.y));
    };
    const auto sq = [&](Point2 p, Point2 o) { return dot_at(p, p, o); };
    const Q u = dot_at(a, b, d), v = dot_at(a, b, c);
    const Q p = sq(a, c) * sq(b, c), q = sq(a, d) * sq(b, d);
    const int sx = CGAL::sign(p) == CGAL::ZERO ? 0 : int(CGAL::sign(u));
    const int sy = CGAL::sign(q) == CGAL::ZERO ? 0 : int(CGAL::sign(v));
    int se = 0;
    if (sx == 0) {
        se = sy;
    } else if (sy == 0 || sx == sy) {
        se = sx;
    } else {
        se = sx * int(CGAL::sign(p * u * u - q * v * v));
    }
    return static_cast<Sign>(-se);
}

}  // namespace exidel::test
