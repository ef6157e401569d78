// exidel: the adaptive kernel. Each predicate reads as: filter, then (rarely) the adaptive
// stages, then (very rarely) exact expansions, or exact integers when the magnitudes are
// outside the range where expansion arithmetic is error-free.
#include "exidel/predicates/adaptive.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <span>
#include <stdexcept>

#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/internal/adaptive_filter.hpp"
#include "adaptive_stages.hpp"
#include "exidel/predicates/internal/adaptive_unchecked.hpp"
#include "double_word.hpp"
#include "expansion.hpp"
#include "formulas.hpp"
#include "exidel/predicates/internal/fp_environment.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"
#include "exidel/predicates/staged.hpp"
#include "small_integers.hpp"

namespace exidel {

namespace {

using detail::Expansion;
using detail::exact_differences;
using detail::exact_small_differences;
using detail::expansion_safe;
using detail::filter_decides;
using detail::IncircleDifferences;
namespace eb = bounds;

constexpr int orient_max_log = 500;    // degree 2: 2 terms of (2^(E+2))^2 < 2^1023
constexpr int incircle_max_log = 250;  // degree 4: 3 terms of 2^(2E+5) * 2^(2E+6) < 2^1023
constexpr int distance_max_log = 500;  // degree 2: 4 squares of 2^(E+2), 2^(2E+8) < 2^1023

Expansion lift_expansion(double v) { return Expansion(v); }

/// Sign of an expansion given as raw components (zeros allowed).
template <std::size_t N>
Sign sign_of_components(const double (&x)[N]) {
    return Expansion::from_components(x).sign();
}

bool same_point(Point2 p, Point2 q) { return p.x == q.x && p.y == q.y; }

// ---- Two products of differences: orient2d, and the dot products of the cosine test ----
// value = (p0 - p1)(q0 - q1) - (r0 - r1)(s0 - s1)   (Plus = false: orient2d)
// value = (p0 - p1)(q0 - q1) + (r0 - r1)(s0 - s1)   (Plus = true: a dot product)
struct ProductPair {
    double p0, p1, q0, q1, r0, r1, s0, s1;
};

template <bool Plus>
Expansion product_pair_exact(const ProductPair& t) {
    const Expansion first =
        (Expansion(t.p0) - Expansion(t.p1)) * (Expansion(t.q0) - Expansion(t.q1));
    const Expansion second =
        (Expansion(t.r0) - Expansion(t.r1)) * (Expansion(t.s0) - Expansion(t.s1));
    return Plus ? first + second : first - second;
}

/// Shewchuk's orient2dadapt stages B, C and D for either sign of the pair. `sum_abs` is
/// the permanent the filter computed. The caller has checked expansion_safe.
template <bool Plus>
Sign product_pair_adapt(const ProductPair& t, double sum_abs, AdaptiveStage& stage) {
    const double p = t.p0 - t.p1, q = t.q0 - t.q1, r = t.r0 - t.r1, s = t.s0 - t.s1;

    // Stage B: the exact value of the rounded differences' expression, estimated.
    double first, first_tail, second, second_tail, B[4];
    detail::two_product(p, q, first, first_tail);
    detail::two_product(r, s, second, second_tail);
    if constexpr (Plus) {
        detail::two_two_sum(first, first_tail, second, second_tail, B);
    } else {
        detail::two_two_diff(first, first_tail, second, second_tail, B);
    }
    double det = B[0] + B[1] + B[2] + B[3];
    double errbound = eb::ccw_b * sum_abs;
    stage = AdaptiveStage::stage_b;
    if (Sign s; filter_decides(det, errbound, s)) return s;

    const double p_tail = detail::two_diff_tail(t.p0, t.p1, p);
    const double q_tail = detail::two_diff_tail(t.q0, t.q1, q);
    const double r_tail = detail::two_diff_tail(t.r0, t.r1, r);
    const double s_tail = detail::two_diff_tail(t.s0, t.s1, s);
    if (p_tail == 0 && q_tail == 0 && r_tail == 0 && s_tail == 0) {
        return sign_of_components(B);  // the differences were exact, so B is the value
    }

    // Stage C: first-order correction by the tails of the differences.
    stage = AdaptiveStage::stage_c;
    errbound = eb::ccw_c * sum_abs + eb::result_err * std::fabs(det);
    const double correction_first = p * q_tail + q * p_tail;
    const double correction_second = r * s_tail + s * r_tail;
    det += Plus ? correction_first + correction_second : correction_first - correction_second;
    if (Sign s; filter_decides(det, errbound, s)) return s;

    stage = AdaptiveStage::exact;
    return product_pair_exact<Plus>(t).sign();
}

// ---- orient2d ---------------------------------------------------------------------------

[[gnu::noinline]] Sign orient2d_adapt(Point2 a, Point2 b, Point2 c, double detsum,
                                      AdaptiveStage& stage) {
    stage = AdaptiveStage::small_integer;
    // Two equal points: zero, which only the expansions would otherwise reach (the rounded
    // differences are not small integers; measured 78 ns a query on duplicates).
    if (same_point(a, b) || same_point(b, c) || same_point(a, c)) return Sign::zero;
    // Exact ties on lattices and lines: exact differences in a 62-bit window, in 128 bits.
    std::int64_t n[4];
    if (exact_small_differences<detail::wide_bits>({a.x, a.y, b.x, b.y}, {c.x, c.y, c.x, c.y},
                                                   {a.x - c.x, a.y - c.y, b.x - c.x, b.y - c.y},
                                                   n)) {
        return static_cast<Sign>(detail::orient2d_small_sign(n));
    }
    if (!expansion_safe({a.x, a.y, b.x, b.y, c.x, c.y}, 2, orient_max_log)) {
        stage = AdaptiveStage::gmp;
        return GmpExactKernel::orient2d(a, b, c);
    }
    return product_pair_adapt<false>({a.x, c.x, b.y, c.y, a.y, c.y, b.x, c.x}, detsum, stage);
}

inline Sign orient2d_impl(Point2 a, Point2 b, Point2 c, AdaptiveStage* stage) {
    *stage = AdaptiveStage::filter;
    double detsum;
    if (Sign s; detail::orient2d_filter(a, b, c, s, detsum)) [[likely]]
        return s;
    return orient2d_adapt(a, b, c, detsum, *stage);
}

// ---- incircle ---------------------------------------------------------------------------

/// lift * (p - q) for one row of the incircle determinant: (x^2 + y^2) times the
/// two-product difference p1 q1 - p2 q2, as an expansion of at most 32 components.
int incircle_row(double x, double y, double p1, double q1, double p2, double q2, double* out) {
    double a1, a0, b1, b0, cross[4], xc[8], xxc[16], yc[8], yyc[16];
    detail::two_product(p1, q1, a1, a0);
    detail::two_product(p2, q2, b1, b0);
    detail::two_two_diff(a1, a0, b1, b0, cross);
    const int xc_length = detail::expansion_scale(4, cross, x, xc);
    const int xxc_length = detail::expansion_scale(xc_length, xc, x, xxc);
    const int yc_length = detail::expansion_scale(4, cross, y, yc);
    const int yyc_length = detail::expansion_scale(yc_length, yc, y, yyc);
    return detail::expansion_sum(xxc_length, xxc, yyc_length, yyc, out);
}

/// The incircle determinant of six doubles (the rounded differences), exactly.
int incircle_of_rounded_differences(double adx, double ady, double bdx, double bdy, double cdx,
                                    double cdy, double* fin /* [96] */) {
    double adet[32], bdet[32], cdet[32], abdet[64];
    const int alen = incircle_row(adx, ady, bdx, cdy, cdx, bdy, adet);
    const int blen = incircle_row(bdx, bdy, cdx, ady, adx, cdy, bdet);
    const int clen = incircle_row(cdx, cdy, adx, bdy, bdx, ady, cdet);
    const int ablen = detail::expansion_sum(alen, adet, blen, bdet, abdet);
    return detail::expansion_sum(ablen, abdet, clen, cdet, fin);
}

/// Exact ties in small integers: the 30-bit window in 64/128-bit integers, then the 62-bit
/// window in 256-bit integers.
[[gnu::noinline]] bool incircle_small_integers(Point2 a, Point2 b, Point2 c, Point2 d,
                                               const IncircleDifferences& v, Sign& sign) {
    const double difference[6] = {v.adx, v.ady, v.bdx, v.bdy, v.cdx, v.cdy};
    if (!exact_differences({a.x, a.y, b.x, b.y, c.x, c.y}, {d.x, d.y, d.x, d.y, d.x, d.y},
                           difference)) {
        return false;
    }
    std::int64_t n[6];
    const int top = detail::window_top(difference);
    if (detail::to_small_integers(difference, top, n)) {
        sign = static_cast<Sign>(detail::incircle_small_sign(n));
        return true;
    }
    if (detail::to_small_integers<detail::wide_bits>(difference, top, n)) {
        sign = static_cast<Sign>(detail::incircle_wide_sign(n));
        return true;
    }
    return false;
}

// ---- incircle: the double-word stage ---------------------------------------------------
// Between stage A and the expansions. The differences are exact double words (Two-Diff);
// the determinant is evaluated from them in double-word arithmetic (double_word.hpp), with
// an error of at most (36 + O(eps)) eps^2 T, T the permanent of the exact differences
// (proofs/bounds.md#incircle-double-word). Rounding a cocircular configuration to doubles
// leaves values of order eps T, so this decides nearly every query whose value is not
// zero, at a fraction of the cost of stage B's 96-component expansion. It runs only when
// every nonzero difference is in [icc_dw_min, icc_dw_max], the range the proof covers.

using detail::dw::Word;
using detail::in_double_word_range;

template <bool Fma>
[[gnu::always_inline]] inline bool incircle_double_word_eval(const Word (&w)[6], Sign& sign) {
    using detail::dw::add, detail::dw::mul, detail::dw::neg;
    const auto [adx, ady, bdx, bdy, cdx, cdy] = w;
    const Word alift = add(mul<Fma>(adx, adx), mul<Fma>(ady, ady));
    const Word blift = add(mul<Fma>(bdx, bdx), mul<Fma>(bdy, bdy));
    const Word clift = add(mul<Fma>(cdx, cdx), mul<Fma>(cdy, cdy));
    const Word bc = add(mul<Fma>(bdx, cdy), neg(mul<Fma>(cdx, bdy)));
    const Word ca = add(mul<Fma>(cdx, ady), neg(mul<Fma>(adx, cdy)));
    const Word ab = add(mul<Fma>(adx, bdy), neg(mul<Fma>(bdx, ady)));
    const Word det = add(add(mul<Fma>(alift, bc), mul<Fma>(blift, ca)), mul<Fma>(clift, ab));
    // An upper bound of T / kappa from the high parts (bounds.md: T <= kappa t).
    const double t = (alift.hi * (std::fabs(bdx.hi * cdy.hi) + std::fabs(cdx.hi * bdy.hi)) +
                      blift.hi * (std::fabs(cdx.hi * ady.hi) + std::fabs(adx.hi * cdy.hi))) +
                     clift.hi * (std::fabs(adx.hi * bdy.hi) + std::fabs(bdx.hi * ady.hi));
    return filter_decides(det.hi, eb::icc_dw * t, sign);
}

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__FMA__)
[[gnu::target("fma")]] bool incircle_double_word_fma(const Word (&w)[6], Sign& sign) {
    return incircle_double_word_eval<true>(w, sign);
}
#endif

/// True (and the sign) when the double-word stage decides.
[[gnu::noinline]] bool incircle_double_word(Point2 a, Point2 b, Point2 c, Point2 d, Sign& sign) {
    using detail::dw::two_sum;
    const Word w[6] = {two_sum(a.x, -d.x), two_sum(a.y, -d.y), two_sum(b.x, -d.x),
                       two_sum(b.y, -d.y), two_sum(c.x, -d.x), two_sum(c.y, -d.y)};
    if (!in_double_word_range(w, eb::icc_dw_min, eb::icc_dw_max)) return false;
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    return incircle_double_word_eval<true>(w, sign);
#else
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
    if (detail::dw::use_fma()) return incircle_double_word_fma(w, sign);
#endif
    return incircle_double_word_eval<false>(w, sign);
#endif
}

[[gnu::noinline]] Sign incircle_adapt(Point2 a, Point2 b, Point2 c, Point2 d,
                                      const IncircleDifferences& v, double permanent,
                                      AdaptiveStage& stage) {
    // Two equal points make two equal rows of the lifted 4 x 4 determinant, so zero:
    // checked first, being cheap (on uniform data the 62-bit window would often hold, and
    // the 256-bit evaluation cost more).
    stage = AdaptiveStage::small_integer;
    if (same_point(a, b) || same_point(a, c) || same_point(a, d) || same_point(b, c) ||
        same_point(b, d) || same_point(c, d)) {
        return Sign::zero;
    }
    // The small-integer stage decides exact ties, the double-word stage near-ties; the
    // order only saves time (adaptive_stages.hpp, tie_likely).
    const bool ties = detail::tie_likely({v.adx, v.ady, v.bdx, v.bdy, v.cdx, v.cdy});
    if (ties) {
        if (Sign s; incircle_small_integers(a, b, c, d, v, s)) return s;
    }
    stage = AdaptiveStage::double_word;
    if (Sign s; incircle_double_word(a, b, c, d, s)) return s;
    if (!ties) {
        stage = AdaptiveStage::small_integer;
        if (Sign s; incircle_small_integers(a, b, c, d, v, s)) return s;
    }
    if (!expansion_safe({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y}, 4, incircle_max_log)) {
        stage = AdaptiveStage::gmp;
        return GmpExactKernel::incircle(a, b, c, d);
    }
    const auto [adx, ady, bdx, bdy, cdx, cdy] = v;

    // Stage B: the determinant of the rounded differences, exactly (Shewchuk's schedule:
    // lengths 4, 8, 16, 32, 64, 96, on the stack).
    double fin[96];
    const int fin_length = incircle_of_rounded_differences(adx, ady, bdx, bdy, cdx, cdy, fin);
    // Stages B and C trust the estimate of fin only as far as lemma E bounds it, which
    // needs fin in class W; Fast-Expansion-Sum does not guarantee that (Shewchuk's
    // Theorem 13 is false: proofs/bounds.md#expansion-estimate), so it is checked. Outside
    // W (never seen in sampling, bounds.md), straight to the exact stage.
    if (!detail::in_class_w(fin_length, fin)) {
        stage = AdaptiveStage::exact;
        return detail::incircle_formula<Expansion>(a, b, c, d, lift_expansion);
    }
    double det = detail::expansion_estimate(fin_length, fin);
    double errbound = eb::icc_b * permanent;
    stage = AdaptiveStage::stage_b;
    if (Sign s; filter_decides(det, errbound, s)) return s;

    const double adxtail = detail::two_diff_tail(a.x, d.x, adx);
    const double adytail = detail::two_diff_tail(a.y, d.y, ady);
    const double bdxtail = detail::two_diff_tail(b.x, d.x, bdx);
    const double bdytail = detail::two_diff_tail(b.y, d.y, bdy);
    const double cdxtail = detail::two_diff_tail(c.x, d.x, cdx);
    const double cdytail = detail::two_diff_tail(c.y, d.y, cdy);
    if (adxtail == 0 && bdxtail == 0 && cdxtail == 0 && adytail == 0 && bdytail == 0 &&
        cdytail == 0) {
        return detail::checked_sign(fin_length, fin);
    }

    // Stage C: Shewchuk's first-order tail correction.
    stage = AdaptiveStage::stage_c;
    errbound = eb::icc_c * permanent + eb::result_err * std::fabs(det);
    det += ((adx * adx + ady * ady) *
                ((bdx * cdytail + cdy * bdxtail) - (bdy * cdxtail + cdx * bdytail)) +
            2.0 * (adx * adxtail + ady * adytail) * (bdx * cdy - bdy * cdx)) +
           ((bdx * bdx + bdy * bdy) *
                ((cdx * adytail + ady * cdxtail) - (cdy * adxtail + adx * cdytail)) +
            2.0 * (bdx * bdxtail + bdy * bdytail) * (cdx * ady - cdy * adx)) +
           ((cdx * cdx + cdy * cdy) *
                ((adx * bdytail + bdy * adxtail) - (ady * bdxtail + bdx * adytail)) +
            2.0 * (cdx * cdxtail + cdy * cdytail) * (adx * bdy - ady * bdx));
    if (Sign s; filter_decides(det, errbound, s)) return s;

    stage = AdaptiveStage::exact;
    return detail::incircle_formula<Expansion>(a, b, c, d, lift_expansion);
}

/// Shewchuk's stage A: a bound relative to the permanent, tighter than the semi-static one
/// near degeneracy. Out of line, so the semi-static fast path keeps few values live.
[[gnu::noinline]] Sign incircle_stage_a(Point2 a, Point2 b, Point2 c, Point2 d,
                                        const IncircleDifferences& v, AdaptiveStage& stage) {
    const auto [adx, ady, bdx, bdy, cdx, cdy] = v;
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double alift = adx * adx + ady * ady;
    const double blift = bdx * bdx + bdy * bdy;
    const double clift = cdx * cdx + cdy * cdy;
    const double det =
        alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    const double sa = std::fabs(bdxcdy) + std::fabs(cdxbdy);
    const double sb = std::fabs(cdxady) + std::fabs(adxcdy);
    const double sc = std::fabs(adxbdy) + std::fabs(bdxady);
    const double permanent = sa * alift + sb * blift + sc * clift;
    // The second term bounds what gradual underflow can add (constants.hpp). Computing it
    // costs a multiplication with a subnormal result (a microcode assist, about a hundred
    // cycles on x86: measured as 78% of this function on a circle's triangulation), so it
    // is skipped where it cannot change the sum: when the first term is at least 2^-960
    // and the second below 2^-1022 (its factor below 2^46), the second is less than half
    // an ulp of the first and fl(first + second) == first. The bound is the same double.
    const double first = eb::icc_a * permanent;
    const double spread = ((alift + blift) + (clift + sa)) + ((sb + sc) + 1.0);
    const bool negligible = first >= 0x1p-960 && spread < 0x1p46;
    const double errbound = negligible ? first : first + eb::underflow_incircle * spread;
    stage = AdaptiveStage::filter;
    if (Sign s; filter_decides(det, errbound, s)) return s;
    return incircle_adapt(a, b, c, d, v, permanent, stage);
}

inline Sign incircle_impl(Point2 a, Point2 b, Point2 c, Point2 d, AdaptiveStage* stage) {
    *stage = AdaptiveStage::filter;
    IncircleDifferences v;
    if (Sign s; detail::incircle_filter(a, b, c, d, v, s)) [[likely]]
        return s;
    return incircle_stage_a(a, b, c, d, v, *stage);
}

// ---- incircle_cosine --------------------------------------------------------------------

/// The sign of a dot product (p - o).(q - o), filter then stages.
Sign dot_sign_adapt(Point2 p, Point2 q, Point2 o, AdaptiveStage& stage) {
    const double px = p.x - o.x, py = p.y - o.y, qx = q.x - o.x, qy = q.y - o.y;
    const double first = px * qx, second = py * qy;
    const double dot = first + second;
    const double sum_abs = std::fabs(first) + std::fabs(second);
    const double errbound = eb::ccw_a * sum_abs + eb::underflow_orient;
    if (Sign s; filter_decides(dot, errbound, s)) return s;
    return product_pair_adapt<true>({p.x, o.x, q.x, o.x, p.y, o.y, q.y, o.y}, sum_abs, stage);
}

// ---- incircle_cosine: the double-word stage --------------------------------------------
// When the two dot products have opposite exact signs, the answer is the sign of
// L - R = |a-c|^2 |b-c|^2 u^2 - |a-d|^2 |b-d|^2 v^2 (cosine.md). This evaluates it from
// the exact differences in double-word arithmetic, with an error of at most
// (71 + O(eps)) eps^2 T, T = |a-c|^2 |b-c|^2 T_u^2 + |a-d|^2 |b-d|^2 T_v^2 with T_u the
// permanent of u (proofs/bounds.md#cosine-double-word), for differences in
// [cos_dw_min, cos_dw_max]. Returns the sign of L - R, or nothing.

template <bool Fma>
[[gnu::always_inline]] inline bool cosine_double_word_eval(const Word (&w)[8], Sign& sign) {
    using detail::dw::add, detail::dw::mul, detail::dw::neg;
    const auto [adx, ady, bdx, bdy, acx, acy, bcx, bcy] = w;
    const Word u = add(mul<Fma>(adx, bdx), mul<Fma>(ady, bdy));  // (a-d).(b-d)
    const Word v = add(mul<Fma>(acx, bcx), mul<Fma>(acy, bcy));  // (a-c).(b-c)
    const Word ad2 = add(mul<Fma>(adx, adx), mul<Fma>(ady, ady));
    const Word bd2 = add(mul<Fma>(bdx, bdx), mul<Fma>(bdy, bdy));
    const Word ac2 = add(mul<Fma>(acx, acx), mul<Fma>(acy, acy));
    const Word bc2 = add(mul<Fma>(bcx, bcx), mul<Fma>(bcy, bcy));
    const Word left = mul<Fma>(mul<Fma>(ac2, bc2), mul<Fma>(u, u));
    const Word right = mul<Fma>(mul<Fma>(ad2, bd2), mul<Fma>(v, v));
    const Word diff = add(left, neg(right));
    // An upper bound of T / kappa from the high parts (bounds.md: T <= kappa t).
    const double tu = std::fabs(adx.hi * bdx.hi) + std::fabs(ady.hi * bdy.hi);
    const double tv = std::fabs(acx.hi * bcx.hi) + std::fabs(acy.hi * bcy.hi);
    const double t = (ac2.hi * bc2.hi) * (tu * tu) + (ad2.hi * bd2.hi) * (tv * tv);
    return filter_decides(diff.hi, eb::cos_dw * t, sign);
}

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__FMA__)
[[gnu::target("fma")]] bool cosine_double_word_fma(const Word (&w)[8], Sign& sign) {
    return cosine_double_word_eval<true>(w, sign);
}
#endif

[[gnu::noinline]] bool cosine_double_word(Point2 a, Point2 b, Point2 c, Point2 d, Sign& sign) {
    using detail::dw::two_sum;
    const Word w[8] = {two_sum(a.x, -d.x), two_sum(a.y, -d.y), two_sum(b.x, -d.x),
                       two_sum(b.y, -d.y), two_sum(a.x, -c.x), two_sum(a.y, -c.y),
                       two_sum(b.x, -c.x), two_sum(b.y, -c.y)};
    if (!in_double_word_range(w, eb::cos_dw_min, eb::cos_dw_max)) return false;
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    return cosine_double_word_eval<true>(w, sign);
#else
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
    if (detail::dw::use_fma()) return cosine_double_word_fma(w, sign);
#endif
    return cosine_double_word_eval<false>(w, sign);
#endif
}

[[gnu::noinline]] bool cosine_small_integers(Point2 a, Point2 b, Point2 c, Point2 d, Sign& sign) {
    const double minuend[8] = {a.x, a.y, b.x, b.y, a.x, a.y, b.x, b.y};
    const double subtrahend[8] = {d.x, d.y, d.x, d.y, c.x, c.y, c.x, c.y};
    double difference[8];
    for (int i = 0; i < 8; ++i) difference[i] = minuend[i] - subtrahend[i];
    std::int64_t n[8];
    if (!exact_small_differences(minuend, subtrahend, difference, n)) return false;
    sign = static_cast<Sign>(detail::cosine_small_sign(n));
    return true;
}

[[gnu::noinline]] Sign incircle_cosine_adapt(Point2 a, Point2 b, Point2 c, Point2 d,
                                             AdaptiveStage& stage) {
    // The signs of the two dot products, exactly, by the orient2d-shaped stages (degree 2):
    // when they agree, that is the answer.
    if (expansion_safe({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y}, 2, orient_max_log)) {
        AdaptiveStage stage_u = AdaptiveStage::filter, stage_v = AdaptiveStage::filter;
        const Sign su = dot_sign_adapt(a, b, d, stage_u);
        const Sign sv = dot_sign_adapt(a, b, c, stage_v);
        stage = std::max({stage_u, stage_v, AdaptiveStage::stage_b});
        if (su == sv) return -su;
        // One dot product zero: E is the other term, |a-d||b-d| v (u = 0) or |a-c||b-c| u
        // (v = 0), whose length factor is zero only when two points coincide.
        const auto differs = [](Point2 p, Point2 q) { return p.x != q.x || p.y != q.y; };
        if (su == Sign::zero) return differs(a, d) && differs(b, d) ? -sv : Sign::zero;
        if (sv == Sign::zero) return differs(a, c) && differs(b, c) ? -su : Sign::zero;

        // Opposite signs. When c and d are strictly on opposite sides of ab (the paper's
        // precondition, the only case a triangulation asks), the cosine test is the in-circle
        // test: -sign(E) = orient2d(a, b, c) * incircle(a, b, c, d) (proofs/cosine.md,
        // section 1), and incircle's stages resolve near-ties the degree-8 form leaves at
        // eps^2 (near lines, E is second order in the deviation). `stage` is incircle's.
        AdaptiveStage orient_stage{};
        const Sign oc = orient2d_impl(a, b, c, &orient_stage);
        if (oc != Sign::zero && orient2d_impl(a, b, d, &orient_stage) == -oc) {
            return static_cast<Sign>(to_int(oc) * to_int(incircle_impl(a, b, c, d, &stage)));
        }

        // Otherwise the sign of L - R decides: -su if L > R, -sv if L < R, and a tie means
        // |X| = |Y| with opposite signs, E = 0 (only the integers can decide a tie).
        Sign s = Sign::zero;
        stage = AdaptiveStage::small_integer;
        bool decided = cosine_small_integers(a, b, c, d, s);
        if (!decided) {
            stage = AdaptiveStage::double_word;
            decided = cosine_double_word(a, b, c, d, s);
        }
        if (decided) return s == Sign::positive ? -su : s == Sign::negative ? -sv : Sign::zero;
    }
    // The degree-8 comparison, exactly. Measured on near-cocircular queries (bench/,
    // proofs/README.md): Boost's cpp_int, whose small values live inline, evaluates it about
    // twice as fast as our expansions and as GMP, and it has no range limit.
    stage = AdaptiveStage::exact;
    return CppIntExactKernel::incircle_cosine(a, b, c, d);
}

inline Sign incircle_cosine_impl(Point2 a, Point2 b, Point2 c, Point2 d, AdaptiveStage* stage) {
    const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
    const double acx = a.x - c.x, acy = a.y - c.y, bcx = b.x - c.x, bcy = b.y - c.y;
    const double u1 = adx * bdx, u2 = ady * bdy, v1 = acx * bcx, v2 = acy * bcy;
    const double u = u1 + u2;  // (a-d).(b-d)
    const double v = v1 + v2;  // (a-c).(b-c)
    const double eu = eb::ccw_a * (std::fabs(u1) + std::fabs(u2)) + eb::underflow_orient;
    const double ev = eb::ccw_a * (std::fabs(v1) + std::fabs(v2)) + eb::underflow_orient;
    *stage = AdaptiveStage::filter;
    if (std::fabs(u) > eu && std::fabs(v) > ev) {
        const Sign su = sign_of(u), sv = sign_of(v);
        if (su == sv) return -su;

        // Opposite signs: compare L = |a-c|^2 |b-c|^2 u^2 with R = |a-d|^2 |b-d|^2 v^2.
        const double du = eu / (std::fabs(u) - eu), dv = ev / (std::fabs(v) - ev);
        if (du <= eb::cos_max_dot_rel && dv <= eb::cos_max_dot_rel) {
            const double ac2 = acx * acx + acy * acy, bc2 = bcx * bcx + bcy * bcy;
            const double ad2 = adx * adx + ady * ady, bd2 = bdx * bdx + bdy * bdy;
            const double uu = u * u, vv = v * v;
            const double left_lengths = ac2 * bc2, right_lengths = ad2 * bd2;
            const double left = left_lengths * uu, right = right_lengths * vv;
            // Nothing subnormal: not a factor, not a partial product, not a side.
            const double smallest =
                std::min({ac2, bc2, ad2, bd2, uu, vv, left_lengths, right_lengths, left, right});
            constexpr double largest = std::numeric_limits<double>::max();
            // Written so that a NaN fails the test.
            if (smallest >= eb::cos_min_factor && left <= largest && right <= largest) {
                const double errbound = (eb::cos_rel + eb::cos_rel_dot * du) * left +
                                        (eb::cos_rel + eb::cos_rel_dot * dv) * right;
                const double diff = left - right;
                if (diff > errbound) return -su;   // the d-term of E dominates
                if (-diff > errbound) return -sv;  // the c-term of E dominates
            }
        }
    }
    return incircle_cosine_adapt(a, b, c, d, *stage);
}

// ---- compare_distance -------------------------------------------------------------------

/// Drops the zero components of x[0..n) in place (expansion_sum wants none); returns the
/// new length.
int without_zeros(int n, double* x) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
        if (x[i] != 0) x[m++] = x[i];
    }
    return m;
}

/// (h + l)^2 for the two-component expansion l + h of an exact difference: at most 8
/// components.
int expansion_square(double h, double l, double* out /* [8] */) {
    double x[2] = {l, h}, by_l[4], by_h[4];
    const int n = without_zeros(2, x);
    const int nl = detail::expansion_scale(n, x, l, by_l);
    const int nh = detail::expansion_scale(n, x, h, by_h);
    return detail::expansion_sum(nl, by_l, nh, by_h, out);
}

/// |p - c|^2 - |q - c|^2 for coordinates inside the expansion range: first the exact
/// value for the rounded differences (which is the answer when no difference rounded,
/// the common case of exact ties on grids), then the exact value from the differences as
/// two-component expansions. No allocation: at most 32 components, on the stack.
[[gnu::noinline]] Sign compare_distance_adapt(Point2 c, Point2 p, Point2 q, AdaptiveStage& stage) {
    stage = AdaptiveStage::small_integer;
    if (same_point(p, q)) return Sign::zero;
    std::int64_t n[4];
    if (exact_small_differences<detail::wide_bits>({p.x, p.y, q.x, q.y}, {c.x, c.y, c.x, c.y},
                                                   {p.x - c.x, p.y - c.y, q.x - c.x, q.y - c.y},
                                                   n)) {
        return static_cast<Sign>(detail::distance_small_sign(n));
    }
    if (!expansion_safe({c.x, c.y, p.x, p.y, q.x, q.y}, 2, distance_max_log)) {
        stage = AdaptiveStage::gmp;
        return GmpExactKernel::compare_distance(c, p, q);
    }
    double pcx, pcx_tail, pcy, pcy_tail, qcx, qcx_tail, qcy, qcy_tail;
    detail::two_diff(p.x, c.x, pcx, pcx_tail);
    detail::two_diff(p.y, c.y, pcy, pcy_tail);
    detail::two_diff(q.x, c.x, qcx, qcx_tail);
    detail::two_diff(q.y, c.y, qcy, qcy_tail);

    if (pcx_tail == 0 && pcy_tail == 0 && qcx_tail == 0 && qcy_tail == 0) {
        // pcx^2 + pcy^2 - qcx^2 - qcy^2 from four Two-Products.
        // Branch-free (Four_Four_Sum): on grids the ties are as frequent as they are
        // unpredictable, and a merge by magnitude mispredicts on them.
        double a1, a0, b1, b0, c1, c0, d1, d0, plen[4], qlen[4], det[8];
        detail::two_product(pcx, pcx, a1, a0);
        detail::two_product(pcy, pcy, b1, b0);
        detail::two_product(qcx, qcx, c1, c0);
        detail::two_product(qcy, qcy, d1, d0);
        stage = AdaptiveStage::stage_b;
        if (a0 == 0 && b0 == 0 && c0 == 0 && d0 == 0) {
            // Exact squares too (grid coordinates below 2^26): (a1 + b1) - (c1 + d1) in
            // four components, a short dependency chain.
            double s1, s0, t1, t0, diff[4];
            detail::two_sum(a1, b1, s1, s0);
            detail::two_sum(c1, d1, t1, t0);
            detail::two_two_diff(s1, s0, t1, t0, diff);
            return detail::sign_of_largest(diff);
        }
        detail::two_two_sum(a1, a0, b1, b0, plen);
        detail::two_two_sum(-c1, -c0, -d1, -d0, qlen);  // negation is exact
        detail::four_four_sum(plen, qlen, det);
        return detail::sign_of_largest(det);
    }

    double px2[8], py2[8], qx2[8], qy2[8], plen[16], qlen[16], det[32];
    const int npx = expansion_square(pcx, pcx_tail, px2);
    const int npy = expansion_square(pcy, pcy_tail, py2);
    const int nqx = expansion_square(qcx, qcx_tail, qx2);
    const int nqy = expansion_square(qcy, qcy_tail, qy2);
    const int np = detail::expansion_sum(npx, px2, npy, py2, plen);
    const int nq = detail::expansion_sum(nqx, qx2, nqy, qy2, qlen);
    for (int i = 0; i < nq; ++i) qlen[i] = -qlen[i];
    stage = AdaptiveStage::exact;
    return detail::checked_sign(detail::expansion_sum(np, plen, nq, qlen, det), det);
}

// Orient2d's filter with the squared lengths as the two terms (constants.hpp: dist_a).
inline Sign compare_distance_impl(Point2 c, Point2 p, Point2 q, AdaptiveStage* stage) {
    const double pcx = p.x - c.x, pcy = p.y - c.y, qcx = q.x - c.x, qcy = q.y - c.y;
    const double plen = pcx * pcx + pcy * pcy;
    const double qlen = qcx * qcx + qcy * qcy;
    const double det = plen - qlen;
    const double permanent = plen + qlen;  // both terms are nonnegative
    const double errbound = eb::dist_a * permanent + eb::underflow_dist;
    *stage = AdaptiveStage::filter;
    if (Sign s; filter_decides(det, errbound, s)) [[likely]]
        return s;
    return compare_distance_adapt(c, p, q, *stage);
}

}  // namespace

// ---- The kernel -------------------------------------------------------------------------

namespace detail {

Sign orient2d_unchecked(Point2 a, Point2 b, Point2 c) {
    AdaptiveStage stage;
    return orient2d_impl(a, b, c, &stage);
}

Sign incircle_unchecked(Point2 a, Point2 b, Point2 c, Point2 d) {
    AdaptiveStage stage;
    return incircle_impl(a, b, c, d, &stage);
}

Sign incircle_cosine_unchecked(Point2 a, Point2 b, Point2 c, Point2 d) {
    AdaptiveStage stage;
    return incircle_cosine_impl(a, b, c, d, &stage);
}

Sign compare_distance_unchecked(Point2 c, Point2 p, Point2 q) {
    AdaptiveStage stage;
    return compare_distance_impl(c, p, q, &stage);
}

}  // namespace detail

Sign orient2d_staged(Point2 a, Point2 b, Point2 c, AdaptiveStage& stage) {
    return detail::in_standard_environment<orient2d_impl>(a, b, c, &stage);
}

Sign incircle_staged(Point2 a, Point2 b, Point2 c, Point2 d, AdaptiveStage& stage) {
    return detail::in_standard_environment<incircle_impl>(a, b, c, d, &stage);
}

Sign incircle_cosine_staged(Point2 a, Point2 b, Point2 c, Point2 d, AdaptiveStage& stage) {
    return detail::in_standard_environment<incircle_cosine_impl>(a, b, c, d, &stage);
}

Sign compare_distance_staged(Point2 c, Point2 p, Point2 q, AdaptiveStage& stage) {
    return detail::in_standard_environment<compare_distance_impl>(c, p, q, &stage);
}

Sign staged(Predicate which, std::span<const Point2> p, AdaptiveStage& stage) {
    switch (which) {
        case Predicate::orient2d: return orient2d_staged(p[0], p[1], p[2], stage);
        case Predicate::incircle: return incircle_staged(p[0], p[1], p[2], p[3], stage);
        case Predicate::incircle_cosine:
            return incircle_cosine_staged(p[0], p[1], p[2], p[3], stage);
        case Predicate::compare_distance: return compare_distance_staged(p[0], p[1], p[2], stage);
    }
    throw std::invalid_argument("exidel::staged: not a Predicate");
}

Sign AdaptiveKernel::orient2d(Point2 a, Point2 b, Point2 c) {
    AdaptiveStage stage;
    return orient2d_staged(a, b, c, stage);
}

Sign AdaptiveKernel::incircle(Point2 a, Point2 b, Point2 c, Point2 d) {
    AdaptiveStage stage;
    return incircle_staged(a, b, c, d, stage);
}

Sign AdaptiveKernel::incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) {
    AdaptiveStage stage;
    return incircle_cosine_staged(a, b, c, d, stage);
}

Sign AdaptiveKernel::compare_distance(Point2 c, Point2 p, Point2 q) {
    AdaptiveStage stage;
    return compare_distance_staged(c, p, q, stage);
}

}  // namespace exidel
