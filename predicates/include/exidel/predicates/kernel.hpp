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

}  // namespace exidel
