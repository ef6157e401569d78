// exidel tests: the circumcentre oracle. CGAL's exact rational circumcentre (Cartesian
// over Gmpq: CGAL's construction, not exidel's formula) rounded to the nearest double by
// MPFR with binary64's exponent range and subnormals (mpfr_subnormalize): independent of
// both stages of exidel::circumcenter.
#pragma once

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <mpfr.h>

#include <optional>

#include "exidel/predicates/types.hpp"

namespace exidel::test {

/// q rounded to nearest (ties to even) as IEEE binary64 does it, overflow to infinity.
inline double round_to_double(mpq_srcptr q) {
    const mpfr_exp_t old_min = mpfr_get_emin(), old_max = mpfr_get_emax();
    // binary64: values in [2^(emin-1), 2^emax) in MPFR's convention (significand in
    // [1/2, 1)), subnormals down to 2^-1074.
    mpfr_set_emin(-1073);
    mpfr_set_emax(1024);
    mpfr_t x;
    mpfr_init2(x, 53);
    int inexact = mpfr_set_q(x, q, MPFR_RNDN);
    inexact = mpfr_subnormalize(x, inexact, MPFR_RNDN);
    const double d = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clear(x);
    mpfr_set_emin(old_min);
    mpfr_set_emax(old_max);
    return d;
}

inline double round_to_double(const CGAL::Gmpq& q) { return round_to_double(q.mpq()); }

/// The exact circumcentre of abc as rationals; nullopt when a, b, c are collinear.
inline std::optional<std::pair<CGAL::Gmpq, CGAL::Gmpq>> exact_circumcenter(Point2 a, Point2 b,
                                                                           Point2 c) {
    using K = CGAL::Simple_cartesian<CGAL::Gmpq>;
    const K::Point_2 pa(a.x, a.y), pb(b.x, b.y), pc(c.x, c.y);
    if (CGAL::collinear(pa, pb, pc)) return std::nullopt;
    const K::Point_2 o = CGAL::circumcenter(pa, pb, pc);
    return std::pair{o.x(), o.y()};
}

/// The correctly rounded circumcentre; nullopt when collinear.
inline std::optional<Point2> oracle_circumcenter(Point2 a, Point2 b, Point2 c) {
    const auto o = exact_circumcenter(a, b, c);
    if (!o) return std::nullopt;
    return Point2{round_to_double(o->first), round_to_double(o->second)};
}

}  // namespace exidel::test
