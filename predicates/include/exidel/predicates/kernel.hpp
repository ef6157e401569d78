// exidel: the one concept every predicate kernel satisfies.
#pragma once

#include <concepts>
#include <string>

#include "exidel/predicates/types.hpp"

namespace exidel {

/// A predicate kernel decides the four predicates of exidel for points with finite
/// double coordinates and returns a Sign.
///
///   orient2d(a, b, c)            sign of (b - a) x (c - a): positive iff a, b, c turn
///                                counter-clockwise.
///   incircle(a, b, c, d)         positive iff d lies strictly inside the circle through
///                                a, b, c when a, b, c are counter-clockwise (Shewchuk's
///                                convention); the sign flips with the orientation of abc,
///                                and is zero when the four points are cocircular (or abc
///                                is degenerate and d on its line, see the proofs).
///   incircle_cosine(a, b, c, d)  the paper's test (Cai 2025, Section 5) with its roles
///                                B = a, C = b, D = c, A = d: the sign of
///                                -(|a-c||b-c| (a-d).(b-d) + |a-d||b-d| (a-c).(b-c)),
///                                i.e. positive iff cos(angle at d) + cos(angle at c) < 0.
///                                Evaluated by comparing the signs of the two dot products
///                                and, when they differ, their squares (degree 8).
///                                Precondition for the in-circle meaning (the paper's
///                                Theorem 1): c and d strictly on opposite sides of line
///                                ab. Under it, incircle_cosine == orient2d(a,b,c) *
///                                incircle(a,b,c,d) for exact kernels. When it fails,
///                                every kernel still returns (its evaluation of) the sign
///                                of the expression above, which is then not an in-circle
///                                answer: for example c and d on the same side of ab and
///                                both on the circle give cos C = cos D != 0, hence a
///                                non-zero result.
///   compare_distance(c, p, q)    sign of |p - c|^2 - |q - c|^2: positive iff p is
///                                strictly farther from c than q, zero iff p and q are
///                                exactly equally far from c (for the radial insertion
///                                order: sorting by it is sorting by exact distance).
///
/// `is_exact` is true when every sign is the exact sign for every finite input.
/// `name()` is a short identifier used in tables and on the command line.
template <class K>
concept PredicateKernel = requires(const K& k, Point2 p) {
    { k.orient2d(p, p, p) } -> std::same_as<Sign>;
    { k.incircle(p, p, p, p) } -> std::same_as<Sign>;
    { k.incircle_cosine(p, p, p, p) } -> std::same_as<Sign>;
    { k.compare_distance(p, p, p) } -> std::same_as<Sign>;
    { k.name() } -> std::convertible_to<std::string>;
    { K::is_exact } -> std::convertible_to<bool>;
};

/// A kernel that also decides the two predicates of space, on points with finite double
/// coordinates (every shipped kernel does; a user's kernel may not, and the library asks
/// with this concept, or with `has_3d_predicates<K>`):
///
///   orient3d(a, b, c, d)         Shewchuk's convention: the sign of det(a - d, b - d, c - d),
///                                positive iff d lies below the plane through a, b, c, where
///                                "below" means on the side from which a, b, c appear
///                                clockwise (a, b, c counter-clockwise seen from above);
///                                zero iff the four points are coplanar. It is the opposite
///                                of CGAL's orientation(a, b, c, d).
///   insphere(a, b, c, d, e)      positive iff e lies strictly inside the sphere through
///                                a, b, c, d when orient3d(a, b, c, d) is positive; the sign
///                                flips with orient3d(a, b, c, d), and is zero when the five
///                                points are cospherical (or a, b, c, d coplanar and e on
///                                their circle or plane, as the determinant says). It is
///                                the opposite of CGAL's side_of_oriented_sphere.
///
/// Both are the signs of determinants (proofs/bounds.md#orient3d, #insphere), so swapping
/// two arguments flips the sign and translating every point by the same vector, or
/// scaling every coordinate by the same power of two, changes nothing (for exact kernels).
template <class K>
concept PredicateKernel3D = PredicateKernel<K> && requires(const K& k, Point3 p) {
    { k.orient3d(p, p, p, p) } -> std::same_as<Sign>;
    { k.insphere(p, p, p, p, p) } -> std::same_as<Sign>;
};

template <class K>
inline constexpr bool has_3d_predicates = PredicateKernel3D<K>;

}  // namespace exidel
