// exidel: |p - q| <= r decided exactly, for the neighbour searches (neighbors.hpp).
#include "exidel/delaunay/neighbors.hpp"

#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/internal/adaptive_filter.hpp"
#include "exidel/predicates/internal/fp_environment.hpp"
#include "rational.hpp"

namespace exidel::delaunay::detail {

namespace {

namespace eb = exidel::bounds;

/// The exact sign of (p.x - q.x)^2 + (p.y - q.y)^2 - r^2.
[[gnu::noinline]] Sign radius_exact(Point2 q, Point2 p, double r) {
    const Rational dx = Rational(p.x) - Rational(q.x), dy = Rational(p.y) - Rational(q.y);
    const Rational rr = Rational(r);
    const Rational v = dx * dx + dy * dy - rr * rr;
    return v > 0 ? Sign::positive : v < 0 ? Sign::negative : Sign::zero;
}

/// compare_distance's stage A (adaptive.cpp) operation for operation, the second point's
/// differences being r and 0: the filter's proof (proofs/bounds.md#compare-distance)
/// holds for differences whose rounding error happens to be zero, so dist_a and
/// underflow_dist bound the error here too. Non-finite intermediate values (overflow)
/// never pass the filter.
Sign radius_impl(Point2 q, Point2 p, double r) {
    const double pcx = p.x - q.x, pcy = p.y - q.y, qcx = r, qcy = 0.0;
    const double plen = pcx * pcx + pcy * pcy;
    const double qlen = qcx * qcx + qcy * qcy;
    const double det = plen - qlen;
    const double permanent = plen + qlen;
    const double errbound = eb::dist_a * permanent + eb::underflow_dist;
    if (Sign s; exidel::detail::filter_decides(det, errbound, s)) [[likely]]
        return s;
    return radius_exact(q, p, r);
}

}  // namespace

Sign compare_to_radius(Point2 q, Point2 p, double r) {
    return exidel::detail::in_standard_environment<radius_impl>(q, p, r);
}

}  // namespace exidel::delaunay::detail
