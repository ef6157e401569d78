// Constructs the stage fixtures of tests/predicates/stage_fixtures_test.cpp that reach the
// filter of incircle_cosine comparing L with R and the exact stages of compare_distance
// (docs/mutation.md: the survivors of a campaign on predicates/src/adaptive.cpp), and
// prints each as a fixture line with the sign GMP gives and the stage the adaptive kernel
// reports. Deterministic: constructions, bisections and scans, and one fixed
// pseudo-random sequence (a linear congruential generator written out here).
//
// Build and run from the top of the tree, with a Release build of the library in BUILD:
//
//     g++ -std=c++20 -O2 -ffp-contract=off -I predicates/include -I predicates/internal
//         -I predicates/src -o /tmp/stage_fixture_search scripts/stage_fixture_search.cpp
//         BUILD/predicates/libexidel_predicates.a -lgmpxx -lgmp -lmpfr   (one line)
//     /tmp/stage_fixture_search
//
// The filter is replayed here with the formulas of incircle_cosine_impl (adaptive.cpp)
// and the constants of constants.hpp, so that the search can aim at its boundaries, and
// compare_distance's expansion_square with the private expansion.hpp; the kernel itself is
// only called through its public staged interface.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/staged.hpp"
#include "expansion.hpp"  // private (predicates/src): the component count of a square

using namespace exidel;
namespace eb = exidel::bounds;

namespace {

const char* stage_name(AdaptiveStage s) {
    static const char* names[] = {"filter",  "small_integer", "double_word", "stage_b",
                                  "stage_c", "exact",         "gmp"};
    return names[static_cast<int>(s)];
}

const char* sign_name(Sign s) {
    return s == Sign::positive ? "positive" : s == Sign::negative ? "negative" : "zero";
}

void print_fixture(const char* name, Predicate which, const std::vector<Point2>& p) {
    AdaptiveStage stage{};
    const Sign sign = staged(which, p, stage);
    const Sign gmp = which == Predicate::compare_distance
                         ? GmpExactKernel::compare_distance(p[0], p[1], p[2])
                         : GmpExactKernel::incircle_cosine(p[0], p[1], p[2], p[3]);
    std::printf("    {\"%s\",\n     Predicate::%s,\n     {", name,
                which == Predicate::compare_distance ? "compare_distance" : "incircle_cosine");
    for (std::size_t i = 0; i < p.size(); ++i) {
        std::printf("%s{%a, %a}", i ? ", " : "", p[i].x, p[i].y);
    }
    std::printf("},\n     AdaptiveStage::%s,\n     Sign::%s},%s\n", stage_name(stage),
                sign_name(gmp), sign == gmp ? "" : "   // WRONG SIGN FROM THE KERNEL");
}

// ---- incircle_cosine's filter, replayed -----------------------------------------------

struct CosineFilter {
    double u, v, eu, ev, du, dv, left, right, errbound, diff, smallest;
    bool entered;   // |u| > eu && |v| > ev
    bool opposite;  // opposite signs of u and v
    bool compared;  // du, dv <= cos_max_dot_rel and the factors in range
};

CosineFilter cosine_filter(Point2 a, Point2 b, Point2 c, Point2 d) {
    CosineFilter f{};
    const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
    const double acx = a.x - c.x, acy = a.y - c.y, bcx = b.x - c.x, bcy = b.y - c.y;
    const double u1 = adx * bdx, u2 = ady * bdy, v1 = acx * bcx, v2 = acy * bcy;
    f.u = u1 + u2;
    f.v = v1 + v2;
    f.eu = eb::ccw_a * (std::fabs(u1) + std::fabs(u2)) + eb::underflow_orient;
    f.ev = eb::ccw_a * (std::fabs(v1) + std::fabs(v2)) + eb::underflow_orient;
    f.entered = std::fabs(f.u) > f.eu && std::fabs(f.v) > f.ev;
    f.opposite = (f.u > 0) != (f.v > 0);
    f.du = f.eu / (std::fabs(f.u) - f.eu);
    f.dv = f.ev / (std::fabs(f.v) - f.ev);
    const double ac2 = acx * acx + acy * acy, bc2 = bcx * bcx + bcy * bcy;
    const double ad2 = adx * adx + ady * ady, bd2 = bdx * bdx + bdy * bdy;
    const double uu = f.u * f.u, vv = f.v * f.v;
    const double left_lengths = ac2 * bc2, right_lengths = ad2 * bd2;
    f.left = left_lengths * uu;
    f.right = right_lengths * vv;
    f.smallest =
        std::min({ac2, bc2, ad2, bd2, uu, vv, left_lengths, right_lengths, f.left, f.right});
    constexpr double largest = std::numeric_limits<double>::max();
    f.compared = f.entered && f.opposite && f.du <= eb::cos_max_dot_rel &&
                 f.dv <= eb::cos_max_dot_rel && f.smallest >= eb::cos_min_factor &&
                 f.left <= largest && f.right <= largest;
    f.errbound = (eb::cos_rel + eb::cos_rel_dot * f.du) * f.left +
                 (eb::cos_rel + eb::cos_rel_dot * f.dv) * f.right;
    f.diff = f.left - f.right;
    return f;
}

Sign orient(Point2 a, Point2 b, Point2 c) { return GmpExactKernel::orient2d(a, b, c); }

/// c and d not strictly on opposite sides of ab: the cosine test does not hand the query to
/// incircle, whose filter would report `filter` too.
bool same_side(Point2 a, Point2 b, Point2 c, Point2 d) {
    const Sign oc = orient(a, b, c), od = orient(a, b, d);
    return oc == Sign::zero || od != -oc;
}

double next_up(double x, long k) {
    for (; k > 0; --k) x = std::nextafter(x, INFINITY);
    for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
    return x;
}

// ---- The geometry of the near-tie search -----------------------------------------------
// a = (A, 0), b = (0, B) and c = (-s, 0) for a small s > 0: a - c lies on an axis, so
// v = (A + s) s > 0 has one term (dv is about 3 eps, no cancellation), and c is just
// outside the circle on the diameter ab. d sits just inside that circle (u < 0), on c's
// side of ab, where both terms of u are large and cancel: d's y coordinate is tuned until
// |u| is `ratio` times its error bound eu, which makes du = 1 / (ratio - 1). u does not
// depend on s; R grows as s^2, so s is then tuned until diff - errbound crosses zero, and
// each double s near the crossing is tried for an exact equality.

struct Query {
    Point2 a, b, c, d;
};

/// d's y coordinate tuned so that -u / eu is just above `ratio` (u < 0: d inside the
/// circle on the diameter ab, on its lower arc, where moving d up moves it inwards).
bool tune_d(Query& q, double ratio) {
    auto measure = [&](double y) {
        Query r = q;
        r.d.y = y;
        const CosineFilter f = cosine_filter(r.a, r.b, r.c, r.d);
        return -f.u / f.eu;
    };
    // Bracket: y_lo with -u/eu < ratio, y_hi with -u/eu >= ratio.
    double y_lo = q.d.y, y_hi = q.d.y;
    const double step = std::ldexp(1.0, std::ilogb(q.b.y) - 12);
    for (int i = 0; i < 400 && measure(y_lo) >= ratio; ++i) y_lo -= step;
    for (int i = 0; i < 400 && measure(y_hi) < ratio; ++i) y_hi += step;
    if (measure(y_lo) >= ratio || measure(y_hi) < ratio) return false;
    for (int i = 0; i < 2000; ++i) {
        const double mid = y_lo + (y_hi - y_lo) / 2;
        if (mid == y_lo || mid == y_hi) break;
        (measure(mid) >= ratio ? y_hi : y_lo) = mid;
    }
    q.d.y = y_hi;
    return true;
}

/// s (c = (-s, 0)) tuned so that the filter's margin `sign * diff - errbound` crosses zero,
/// then the doubles around the crossing tried for margin == 0 exactly. sign = +1: diff ==
/// errbound (L > R); sign = -1: -diff == errbound (R > L).
bool tune_s(Query& q, int sign) {
    auto at = [&](double s) {
        Query r = q;
        r.c.x = -s;
        return r;
    };
    auto margin = [&](double s) {
        const Query r = at(s);
        const CosineFilter f = cosine_filter(r.a, r.b, r.c, r.d);
        return sign * f.diff - f.errbound;
    };
    double lo = 0x1p-60, hi = 0x1p+10;  // margin(lo) and margin(hi) of opposite signs
    if (!(margin(lo) * margin(hi) < 0)) return false;
    for (int i = 0; i < 3000; ++i) {
        double m = std::sqrt(lo * hi);  // geometric bisection: s spans many binades
        if (!(m > lo && m < hi)) m = lo + (hi - lo) / 2;
        if (m == lo || m == hi) break;
        ((margin(m) > 0) == (margin(lo) > 0) ? lo : hi) = m;
    }
    for (long k = -4000; k <= 4000; ++k) {
        const Query r = at(next_up(lo, k));
        const CosineFilter f = cosine_filter(r.a, r.b, r.c, r.d);
        if (f.compared && sign * f.diff == f.errbound && same_side(r.a, r.b, r.c, r.d)) {
            q = r;
            return true;
        }
    }
    return false;
}

constexpr double A = 0x1p+26, B = 0x1p+26;

/// d on the circle on the diameter ab at `angle` degrees from its centre, rounded to
/// integers.
Query base_query(int angle, double s) {
    Query q{{A, 0}, {0, B}, {-s, 0}, {0, 0}};
    const double cx = A / 2, cy = B / 2, r = std::hypot(A, B) / 2;
    const double th = angle * M_PI / 180;
    q.d = {std::round(cx + r * std::cos(th)), std::round(cy + r * std::sin(th))};
    return q;
}

void cosine_boundaries() {
    for (const int sign : {+1, -1}) {
        bool found = false;
        // Try d at several angles on the lower arc and several ratios |u| / eu.
        for (int angle = 185; angle < 265 && !found; angle += 3) {
            for (const double ratio : {6.0, 7.0, 8.5, 11.0}) {
                Query q = base_query(angle, 0x1p-20);
                if (!tune_d(q, ratio) || !tune_s(q, sign)) continue;
                const CosineFilter f = cosine_filter(q.a, q.b, q.c, q.d);
                std::printf(
                    "// %s == errbound: d at %d degrees, |u| / eu = %.17g, du = %.17g, "
                    "diff = %a, errbound = %a\n",
                    sign > 0 ? "diff" : "-diff", angle, std::fabs(f.u) / f.eu, f.du, f.diff,
                    f.errbound);
                print_fixture(sign > 0 ? "incircle_cosine, L - R exactly the filter's bound"
                                       : "incircle_cosine, R - L exactly the filter's bound",
                              Predicate::incircle_cosine, {q.a, q.b, q.c, q.d});
                found = true;
                break;
            }
        }
        if (!found) std::printf("// no exact equality found for sign %d\n", sign);
    }
}

/// The same geometry with |u| / eu in [4, 5) (du in (0.25, 1/3]: the filter must fall
/// through, while du = eu / |u| or eu / (|u| + eu) would be at most 0.25) and t chosen so
/// that R is far from L: the filter with either wrong du would decide.
void cosine_du_window() {
    for (const bool swap : {false, true}) {
        Query q = base_query(220, 0x1p-20);
        if (!tune_d(q, 4.5)) {
            std::printf("// du window: tune_d failed\n");
            continue;
        }
        // With s = 2^-20, v is about 2^6 and R is thousands of times L: far from a tie.
        Query s = q;
        if (swap) std::swap(s.c, s.d);  // the roles of u and v exchanged
        const CosineFilter f = cosine_filter(s.a, s.b, s.c, s.d);
        std::printf(
            "// du window%s: |u| / eu = %.17g, |v| / ev = %.17g, du = %.17g, dv = %.17g, "
            "L / R = %.17g, same side %d\n",
            swap ? " (c and d exchanged)" : "", std::fabs(f.u) / f.eu, std::fabs(f.v) / f.ev, f.du,
            f.dv, f.left / f.right, same_side(s.a, s.b, s.c, s.d));
        print_fixture(swap ? "incircle_cosine, |v| between 4 and 5 times its bound"
                           : "incircle_cosine, |u| between 4 and 5 times its bound",
                      Predicate::incircle_cosine, {s.a, s.b, s.c, s.d});
    }
}

/// Hand constructions around the filter's entry test and its two returns.
void cosine_constructed() {
    const double tiny = 0x1p-535;  // tiny^2 = 2^-1070 = underflow_orient, exactly
    // |u| == eu exactly: u = 2^-1070 (one term; fl(ccw_a * 2^-1070) is zero), v = 1.
    print_fixture("incircle_cosine, |u| exactly its bound", Predicate::incircle_cosine,
                  {{tiny, 0}, {tiny, 1}, {-1, 0}, {0, 0}});
    print_fixture("incircle_cosine, |v| exactly its bound", Predicate::incircle_cosine,
                  {{tiny, 0}, {tiny, 1}, {0, 0}, {-1, 0}});
    // u = 1 - (1 - 2^-53) = 2^-53 below eu (about 6 eps), v = 120 of the same sign.
    print_fixture("incircle_cosine, u below its bound, v above, same signs",
                  Predicate::incircle_cosine,
                  {{1, 0x1.fffffffffffffp-1}, {1, -1}, {-10, 0}, {0, 0}});
    // Both dot products negative (c and d inside the circle on the diameter ab).
    print_fixture("incircle_cosine, both dot products negative", Predicate::incircle_cosine,
                  {{0, 0}, {4, 0}, {2, 1}, {1, 1}});
    // Opposite signs, same side: u = 7, v = -1, L = 490 > R = 130.
    print_fixture("incircle_cosine, opposite dot products, L above R", Predicate::incircle_cosine,
                  {{0, 0}, {3, 0}, {1, 1}, {1, 3}});
    // u = 0.25, v = -1, L = 0.625 < R = 20.3125.
    print_fixture("incircle_cosine, opposite dot products, R above L", Predicate::incircle_cosine,
                  {{0, 0}, {3, 0}, {1, 1}, {1, 1.5}});
    // The du window's d (|u| = 4.56 eu) with c = (2^-20, 0) inside the circle: both dot
    // products negative, certain, but du > 1/4.
    Query q = base_query(220, 0x1p-20);
    if (tune_d(q, 4.5)) {
        q.c.x = 0x1p-20;
        const CosineFilter f = cosine_filter(q.a, q.b, q.c, q.d);
        std::printf("// same signs, du = %.17g\n", f.du);
        print_fixture("incircle_cosine, same signs, |u| between 4 and 5 times its bound",
                      Predicate::incircle_cosine, {q.a, q.b, q.c, q.d});
    }
}

// ---- compare_distance -------------------------------------------------------------------

/// |p - c|^2 - |q - c|^2 with the filter of compare_distance_impl replayed (plen + qlen or
/// plen alone as the permanent): the first query of a scan whose computed difference lies
/// between the two bounds.
void distance_filter_permanent() {
    const Point2 c{0, 0}, q{1, 0};
    for (long k = 1; k < 64; ++k) {
        const Point2 p{next_up(1.0, k), 0};
        const double pcx = p.x - c.x, pcy = p.y - c.y, qcx = q.x - c.x, qcy = q.y - c.y;
        const double plen = pcx * pcx + pcy * pcy, qlen = qcx * qcx + qcy * qcy;
        const double det = plen - qlen;
        const double full = eb::dist_a * (plen + qlen) + eb::underflow_dist;
        const double half = eb::dist_a * plen + eb::underflow_dist;
        if (std::fabs(det) > half && !(std::fabs(det) > full)) {
            std::printf("// distance filter: p.x = 1 + %ld ulps, det = %a, bounds %a and %a\n", k,
                        det, half, full);
            print_fixture("compare_distance, beyond half the filter's bound",
                          Predicate::compare_distance, {c, p, q});
            return;
        }
    }
}

void distance_stage_b() {
    // N^2 = m^2 + n^2 with N = s^2 + r^2, m = 2 s r, n = s^2 - r^2, s = 2^13 + 1, r = 2^13:
    // m and n have exact squares, N^2 needs 55 bits (its Two-Product tail is 1), and t =
    // 2^-40 puts the differences 68 bits apart (no small integers).
    const double N = 0x1p+27 + 0x1p+14 + 1, m = 0x1p+27 + 0x1p+14, n = 0x1p+14 + 1, t = 0x1p-40;
    const Point2 o{0, 0};
    print_fixture("compare_distance stage B, the low part of |p-c|^2 in x decides",
                  Predicate::compare_distance, {o, {N, t}, {m, n}});
    print_fixture("compare_distance stage B, the low part of |p-c|^2 in y decides",
                  Predicate::compare_distance, {o, {t, N}, {m, n}});
    print_fixture("compare_distance stage B, the low part of |q-c|^2 in x decides",
                  Predicate::compare_distance, {o, {m, n}, {N, t}});
    print_fixture("compare_distance stage B, the low part of |q-c|^2 in y decides",
                  Predicate::compare_distance, {o, {m, n}, {t, N}});
    print_fixture("compare_distance stage B, exact squares, not a tie", Predicate::compare_distance,
                  {o, {0x1p-60, 0x1p+10}, {0x1p+10, 0}});
    print_fixture("compare_distance exact, a difference of 1 and a tail of 1",
                  Predicate::compare_distance, {{0, -1}, {1, 0x1p+60}, {0, 0x1p+60}});
}

/// expansion_square of adaptive.cpp, replayed: (h + l)^2 as an expansion.
int expansion_square(double h, double l, double* out /* [8] */) {
    double x[2] = {l, h}, by_l[4], by_h[4];
    int n = 0;
    for (double v : {l, h}) {
        if (v != 0) x[n++] = v;
    }
    const int nl = detail::expansion_scale(n, x, l, by_l);
    const int nh = detail::expansion_scale(n, x, h, by_h);
    return detail::expansion_sum(nl, by_l, nh, by_h, out);
}

/// A query whose |q - c|^2 has 16 components in the exact stage (the most its array
/// holds): a scan of points from a fixed linear congruential sequence, the first q found;
/// p is q moved by one ulp in x, far below the filter's reach.
void distance_sixteen_components() {
    std::uint64_t state = 20261207;
    auto next = [&]() {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return state >> 11;  // 53 bits
    };
    auto coordinate = [&]() {
        const double m = 1 + static_cast<double>(next()) * 0x1p-53;  // [1, 2)
        const int e = static_cast<int>(next() % 161) - 80;           // [-80, 80]
        return (next() & 1 ? -1 : 1) * std::ldexp(m, e);
    };
    for (long i = 0; i < 100000000; ++i) {
        const Point2 c{coordinate(), coordinate()}, q{coordinate(), coordinate()};
        double hx, lx, hy, ly, x2[8], y2[8], sum[16];
        detail::two_diff(q.x, c.x, hx, lx);
        detail::two_diff(q.y, c.y, hy, ly);
        const int nx = expansion_square(hx, lx, x2), ny = expansion_square(hy, ly, y2);
        if (detail::expansion_sum(nx, x2, ny, y2, sum) < 16) continue;
        const Point2 p{std::nextafter(q.x, INFINITY), q.y};
        std::printf("// 16 components at candidate %ld\n", i);
        print_fixture("compare_distance exact, 16 components in |q-c|^2",
                      Predicate::compare_distance, {c, p, q});
        return;
    }
    std::printf("// no query with 16 components\n");
}

}  // namespace

int main() {
    std::printf("// ---- incircle_cosine: L - R at the filter's bound\n");
    cosine_boundaries();
    std::printf("// ---- incircle_cosine: du and dv just above the filter's limit\n");
    cosine_du_window();
    std::printf("// ---- incircle_cosine: constructed\n");
    cosine_constructed();
    std::printf("// ---- compare_distance\n");
    distance_filter_permanent();
    distance_stage_b();
    distance_sixteen_components();
}
