// exidel (private): the textbook formulas, written once over any number type N.
//
// FloatingKernel<double>, FloatingKernel<long double>, MpfrKernel and ExactKernel all
// evaluate exactly these expressions in exactly this order; only the arithmetic differs.
// `lift` turns a double coordinate into an N. N needs +, -, *, and comparison with 0.
#pragma once

#include "exidel/predicates/types.hpp"

namespace exidel::detail {

/// (b - a) x (c - a).
template <class N, class Lift>
Sign orient2d_formula(Point2 a, Point2 b, Point2 c, Lift lift) {
    const N ax = lift(a.x), ay = lift(a.y);
    const N abx = lift(b.x) - ax, aby = lift(b.y) - ay;
    const N acx = lift(c.x) - ax, acy = lift(c.y) - ay;
    const N det = abx * acy - aby * acx;
    return sign_of(det);
}

/// |p - c|^2 - |q - c|^2: positive iff p is strictly farther from c than q. Both squared
/// lengths are nonnegative, so the difference is no larger than either of them: it needs
/// no more precision than the lengths themselves (proofs/bitcounts.md).
template <class N, class Lift>
Sign compare_distance_formula(Point2 c, Point2 p, Point2 q, Lift lift) {
    const N cx = lift(c.x), cy = lift(c.y);
    const N pcx = lift(p.x) - cx, pcy = lift(p.y) - cy;
    const N qcx = lift(q.x) - cx, qcy = lift(q.y) - cy;
    const N det = (pcx * pcx + pcy * pcy) - (qcx * qcx + qcy * qcy);
    return sign_of(det);
}

/// Shewchuk's incircle determinant with d as the pivot:
///   | ax-dx  ay-dy  (ax-dx)^2 + (ay-dy)^2 |
///   | bx-dx  by-dy  (bx-dx)^2 + (by-dy)^2 |
///   | cx-dx  cy-dy  (cx-dx)^2 + (cy-dy)^2 |
/// positive iff d is strictly inside the circle through a, b, c when abc is CCW.
template <class N>
N incircle_of_differences(const N& adx, const N& ady, const N& bdx, const N& bdy, const N& cdx,
                          const N& cdy) {
    const N alift = adx * adx + ady * ady;
    const N blift = bdx * bdx + bdy * bdy;
    const N clift = cdx * cdx + cdy * cdy;
    const N det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                  clift * (adx * bdy - bdx * ady);
    return det;
}

template <class N, class Lift>
Sign incircle_formula(Point2 a, Point2 b, Point2 c, Point2 d, Lift lift) {
    const N dx = lift(d.x), dy = lift(d.y);
    return sign_of(incircle_of_differences<N>(lift(a.x) - dx, lift(a.y) - dy, lift(b.x) - dx,
                                              lift(b.y) - dy, lift(c.x) - dx, lift(c.y) - dy));
}

/// Decides the sign of E = |a-c||b-c| u + |a-d||b-d| v without square roots, given the
/// two dot products u = (a-d).(b-d), v = (a-c).(b-c) and the squared lengths. The
/// paper's "check the signs, then square": if u and v have the same sign, E has it;
/// otherwise the term with the larger square wins (proofs/cosine.md, case analysis).
/// Returns sign(-E): positive iff cos(angle at d) + cos(angle at c) < 0.
template <class N>
Sign cosine_decision(const N& u, const N& v, const N& ac2, const N& bc2, const N& ad2,
                     const N& bd2) {
    const Sign su = sign_of(u), sv = sign_of(v);
    if (su == sv) return -su;
    // Squares of the two terms of E: |a-c|^2 |b-c|^2 u^2 against |a-d|^2 |b-d|^2 v^2.
    const N left = ac2 * bc2 * (u * u);
    const N right = ad2 * bd2 * (v * v);
    const Sign e = left > right ? su : (right > left ? sv : Sign::zero);
    return -e;
}

template <class N, class Lift>
Sign incircle_cosine_formula(Point2 a, Point2 b, Point2 c, Point2 d, Lift lift) {
    const N ax = lift(a.x), ay = lift(a.y), bx = lift(b.x), by = lift(b.y);
    const N cx = lift(c.x), cy = lift(c.y), dx = lift(d.x), dy = lift(d.y);
    const N adx = ax - dx, ady = ay - dy, bdx = bx - dx, bdy = by - dy;
    const N acx = ax - cx, acy = ay - cy, bcx = bx - cx, bcy = by - cy;
    const N u = adx * bdx + ady * bdy;  // (a-d).(b-d): |a-d||b-d| cos(angle at d)
    const N v = acx * bcx + acy * bcy;  // (a-c).(b-c): |a-c||b-c| cos(angle at c)
    return cosine_decision<N>(u, v, acx * acx + acy * acy, bcx * bcx + bcy * bcy,
                              adx * adx + ady * ady, bdx * bdx + bdy * bdy);
}

// ---- The predicates of space ----------------------------------------------------------

/// Shewchuk's orient3d with d as the pivot, det(a - d, b - d, c - d) expanded along z:
///   adz (bdx cdy - cdx bdy) + bdz (cdx ady - adx cdy) + cdz (adx bdy - bdx ady).
template <class N>
N orient3d_of_differences(const N& adx, const N& ady, const N& adz, const N& bdx, const N& bdy,
                          const N& bdz, const N& cdx, const N& cdy, const N& cdz) {
    return adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy) +
           cdz * (adx * bdy - bdx * ady);
}

template <class N, class Lift>
Sign orient3d_formula(Point3 a, Point3 b, Point3 c, Point3 d, Lift lift) {
    const N dx = lift(d.x), dy = lift(d.y), dz = lift(d.z);
    return sign_of(orient3d_of_differences<N>(lift(a.x) - dx, lift(a.y) - dy, lift(a.z) - dz,
                                              lift(b.x) - dx, lift(b.y) - dy, lift(b.z) - dz,
                                              lift(c.x) - dx, lift(c.y) - dy, lift(c.z) - dz));
}

/// Shewchuk's insphere with e as the pivot: the 4 x 4 determinant of the rows
/// (p - e, |p - e|^2) for p = a, b, c, d, expanded along the lifts, with the 3 x 3
/// orientations of the differences:
///   abc = aez bc - bez ac + cez ab   (ab = aex bey - bex aey, ...)
///   det = (dlift abc - clift dab) + (blift cda - alift bcd).
/// Positive iff e is strictly inside the sphere through a, b, c, d when orient3d(a, b, c, d)
/// is positive.
template <class N>
struct InsphereDifferences {
    N aex, aey, aez, bex, bey, bez, cex, cey, cez, dex, dey, dez;
};

template <class N>
N insphere_of_differences(const InsphereDifferences<N>& v) {
    const auto& [aex, aey, aez, bex, bey, bez, cex, cey, cez, dex, dey, dez] = v;
    const N ab = aex * bey - bex * aey;
    const N bc = bex * cey - cex * bey;
    const N cd = cex * dey - dex * cey;
    const N da = dex * aey - aex * dey;
    const N ac = aex * cey - cex * aey;
    const N bd = bex * dey - dex * bey;
    const N abc = aez * bc - bez * ac + cez * ab;
    const N bcd = bez * cd - cez * bd + dez * bc;
    const N cda = cez * da + dez * ac + aez * cd;
    const N dab = dez * ab + aez * bd + bez * da;
    const N alift = aex * aex + aey * aey + aez * aez;
    const N blift = bex * bex + bey * bey + bez * bez;
    const N clift = cex * cex + cey * cey + cez * cez;
    const N dlift = dex * dex + dey * dey + dez * dez;
    return (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
}

template <class N, class Lift>
Sign insphere_formula(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e, Lift lift) {
    const N ex = lift(e.x), ey = lift(e.y), ez = lift(e.z);
    return sign_of(insphere_of_differences<N>({lift(a.x) - ex, lift(a.y) - ey, lift(a.z) - ez,
                                               lift(b.x) - ex, lift(b.y) - ey, lift(b.z) - ez,
                                               lift(c.x) - ex, lift(c.y) - ey, lift(c.z) - ez,
                                               lift(d.x) - ex, lift(d.y) - ey, lift(d.z) - ez}));
}

}  // namespace exidel::detail
