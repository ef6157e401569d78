// exidel: the adaptive kernel's predicates of space, orient3d and insphere. Each reads as
// its plane counterpart in adaptive.cpp: a filter with a proven bound decides almost every
// call; then two equal points and exact ties (small integers), near-ties (double words),
// and last exact expansions, or GMP integers outside the expansions' range.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/internal/adaptive_filter.hpp"
#include "adaptive_stages.hpp"
#include "double_word.hpp"
#include "expansion.hpp"
#include "formulas.hpp"
#include "exidel/predicates/internal/fp_environment.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"
#include "small_integers.hpp"

namespace exidel {

namespace {

using detail::filter_decides;
using detail::dw::Word;
namespace eb = bounds;

// The points go by reference between the stages: by value, every call out of line copied
// them (twelve or fifteen doubles) to the stack, about a sixth of a slow call's time
// (measured with bench/predicates3d_bench.cpp).
using P3 = const Point3&;

// proofs/bounds.md#expansion-range: with every |coordinate| < 2^(max_log + 1) no
// intermediate of the formula overflows.
constexpr int orient3d_max_log = 330;  // degree 3: 6 terms of (2^(E+2))^3 < 2^1023
constexpr int insphere_max_log = 195;  // degree 5: 72 x 2^(5E+10) < 2^1023

bool same_point(Point3 p, Point3 q) { return p.x == q.x && p.y == q.y && p.z == q.z; }

detail::Expansion lift_expansion(double v) { return detail::Expansion(v); }

/// The filter skips the underflow term where it cannot change the bound: when the first
/// term is at least 2^-960 and the spread below 2^46, underflow * spread < 2^-1020 is less
/// than half an ulp of the first term, so fl(first + second) == first (the same double),
/// and the multiplication, whose result would be subnormal (a microcode assist of about a
/// hundred cycles on x86), is not executed.
inline double filter_bound(double first, double underflow, double spread) {
    const bool negligible = first >= 0x1p-960 && spread < 0x1p46;
    return negligible ? first : first + underflow * spread;
}

// ---- orient3d ---------------------------------------------------------------------------

/// Stage A: formulas.hpp's orient3d_of_differences, operation for operation, against
/// o3d_a times the permanent (constants.hpp). `v` gets the nine rounded differences.
inline bool orient3d_filter(P3 a, P3 b, P3 c, P3 d, double (&v)[9], Sign& sign) {
    v[0] = a.x - d.x, v[1] = a.y - d.y, v[2] = a.z - d.z;
    v[3] = b.x - d.x, v[4] = b.y - d.y, v[5] = b.z - d.z;
    v[6] = c.x - d.x, v[7] = c.y - d.y, v[8] = c.z - d.z;
    const auto [adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz] = v;
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
    const double spread = (std::fabs(adz) + std::fabs(bdz)) + (std::fabs(cdz) + 1.0);
    return filter_decides(det, filter_bound(eb::o3d_a * permanent, eb::underflow_orient3d, spread),
                          sign);
}

/// The double-word stage (proofs/bounds.md#orient3d-double-word): the exact differences,
/// the minors and the determinant in double words, in the filter's order.
template <bool Fma>
[[gnu::always_inline]] inline bool orient3d_double_word_eval(const Word (&w)[9], Sign& sign) {
    using detail::dw::add, detail::dw::mul, detail::dw::neg;
    const auto [adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz] = w;
    const Word bc = add(mul<Fma>(bdx, cdy), neg(mul<Fma>(cdx, bdy)));
    const Word ca = add(mul<Fma>(cdx, ady), neg(mul<Fma>(adx, cdy)));
    const Word ab = add(mul<Fma>(adx, bdy), neg(mul<Fma>(bdx, ady)));
    const Word det = add(add(mul<Fma>(adz, bc), mul<Fma>(bdz, ca)), mul<Fma>(cdz, ab));
    // An upper bound of T / kappa from the high parts (bounds.md: T <= kappa t).
    const double t =
        (std::fabs(adz.hi) * (std::fabs(bdx.hi * cdy.hi) + std::fabs(cdx.hi * bdy.hi)) +
         std::fabs(bdz.hi) * (std::fabs(cdx.hi * ady.hi) + std::fabs(adx.hi * cdy.hi))) +
        std::fabs(cdz.hi) * (std::fabs(adx.hi * bdy.hi) + std::fabs(bdx.hi * ady.hi));
    return filter_decides(det.hi, eb::o3d_dw * t, sign);
}

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__FMA__)
[[gnu::target("fma")]] bool orient3d_double_word_fma(const Word (&w)[9], Sign& sign) {
    return orient3d_double_word_eval<true>(w, sign);
}
#endif

[[gnu::noinline]] bool orient3d_double_word(P3 a, P3 b, P3 c, P3 d, Sign& sign) {
    using detail::dw::two_sum;
    const Word w[9] = {two_sum(a.x, -d.x), two_sum(a.y, -d.y), two_sum(a.z, -d.z),
                       two_sum(b.x, -d.x), two_sum(b.y, -d.y), two_sum(b.z, -d.z),
                       two_sum(c.x, -d.x), two_sum(c.y, -d.y), two_sum(c.z, -d.z)};
    if (!detail::in_double_word_range(w, eb::o3d_dw_min, eb::o3d_dw_max)) return false;
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    return orient3d_double_word_eval<true>(w, sign);
#else
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
    if (detail::dw::use_fma()) return orient3d_double_word_fma(w, sign);
#endif
    return orient3d_double_word_eval<false>(w, sign);
#endif
}

/// Every difference exact and all in a window of 30 bits: the determinant in 64/128-bit
/// integers (small_integers.hpp).
[[gnu::noinline]] bool orient3d_small_integers(P3 a, P3 b, P3 c, P3 d, const double (&v)[9],
                                               Sign& sign) {
    std::int64_t n[9];
    if (!detail::exact_small_differences({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z},
                                         {d.x, d.y, d.z, d.x, d.y, d.z, d.x, d.y, d.z}, v, n)) {
        return false;
    }
    sign = static_cast<Sign>(detail::orient3d_small_sign(n));
    return true;
}

[[gnu::noinline]] Sign orient3d_adapt(P3 a, P3 b, P3 c, P3 d, const double (&v)[9],
                                      AdaptiveStage& stage) {
    stage = AdaptiveStage::small_integer;
    if (same_point(a, b) || same_point(a, c) || same_point(a, d) || same_point(b, c) ||
        same_point(b, d) || same_point(c, d)) {
        return Sign::zero;
    }
    const bool ties = detail::tie_likely(v);
    if (ties) {
        if (Sign s; orient3d_small_integers(a, b, c, d, v, s)) return s;
    }
    stage = AdaptiveStage::double_word;
    if (Sign s; orient3d_double_word(a, b, c, d, s)) return s;
    if (!ties) {
        stage = AdaptiveStage::small_integer;
        if (Sign s; orient3d_small_integers(a, b, c, d, v, s)) return s;
    }
    if (!detail::expansion_safe({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z}, 3,
                                orient3d_max_log)) {
        stage = AdaptiveStage::gmp;
        return GmpExactKernel::orient3d(a, b, c, d);
    }
    stage = AdaptiveStage::exact;
    return detail::orient3d_formula<detail::Expansion>(a, b, c, d, lift_expansion);
}

inline Sign orient3d_impl(P3 a, P3 b, P3 c, P3 d, AdaptiveStage* stage) {
    *stage = AdaptiveStage::filter;
    double v[9];
    if (Sign s; orient3d_filter(a, b, c, d, v, s)) [[likely]]
        return s;
    return orient3d_adapt(a, b, c, d, v, *stage);
}

// ---- insphere ---------------------------------------------------------------------------

/// The twelve rounded differences every stage of insphere starts from.
inline void insphere_differences(P3 a, P3 b, P3 c, P3 d, P3 e, double (&v)[12]) {
    v[0] = a.x - e.x, v[1] = a.y - e.y, v[2] = a.z - e.z;
    v[3] = b.x - e.x, v[4] = b.y - e.y, v[5] = b.z - e.z;
    v[6] = c.x - e.x, v[7] = c.y - e.y, v[8] = c.z - e.z;
    v[9] = d.x - e.x, v[10] = d.y - e.y, v[11] = d.z - e.z;
}

/// The semi-static filter: formulas.hpp's insphere_of_differences, operation for operation,
/// against isp_static * M^5, M the largest |difference|, for M in [isp_static_min,
/// isp_static_max] (constants.hpp). True when it decides. (The later stages compute the
/// differences again: keeping them for the rare slow path costs twelve stores on the
/// fast one.)
inline bool insphere_filter(P3 a, P3 b, P3 c, P3 d, P3 e, Sign& sign) {
    double v[12];
    insphere_differences(a, b, c, d, e, v);
    double m[2] = {std::fabs(v[0]), std::fabs(v[1])};  // two running maxima: half the chain
    for (int i = 2; i < 12; ++i) m[i % 2] = std::max(m[i % 2], std::fabs(v[i]));
    const double mm = std::max(m[0], m[1]);
    const double det = detail::insphere_of_differences<double>(
        {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]});
    if (mm >= eb::isp_static_min && mm <= eb::isp_static_max) [[likely]] {
        const double m2 = mm * mm;
        return filter_decides(det, eb::isp_static * ((m2 * m2) * mm), sign);
    }
    return false;
}

/// Stage A: formulas.hpp's insphere_of_differences, operation for operation, against
/// isp_a times Shewchuk's permanent (constants.hpp), tighter than the semi-static bound
/// near degeneracy.
bool insphere_stage_a(const double (&v)[12], Sign& sign) {
    const auto [aex, aey, aez, bex, bey, bez, cex, cey, cez, dex, dey, dez] = v;
    const double aexbey = aex * bey, bexaey = bex * aey, ab = aexbey - bexaey;
    const double bexcey = bex * cey, cexbey = cex * bey, bc = bexcey - cexbey;
    const double cexdey = cex * dey, dexcey = dex * cey, cd = cexdey - dexcey;
    const double dexaey = dex * aey, aexdey = aex * dey, da = dexaey - aexdey;
    const double aexcey = aex * cey, cexaey = cex * aey, ac = aexcey - cexaey;
    const double bexdey = bex * dey, dexbey = dex * bey, bd = bexdey - dexbey;
    const double abc = aez * bc - bez * ac + cez * ab;
    const double bcd = bez * cd - cez * bd + dez * bc;
    const double cda = cez * da + dez * ac + aez * cd;
    const double dab = dez * ab + aez * bd + bez * da;
    const double alift = aex * aex + aey * aey + aez * aez;
    const double blift = bex * bex + bey * bey + bez * bez;
    const double clift = cex * cex + cey * cey + cez * cez;
    const double dlift = dex * dex + dey * dey + dez * dez;
    const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);

    const double aezp = std::fabs(aez), bezp = std::fabs(bez), cezp = std::fabs(cez),
                 dezp = std::fabs(dez);
    const double abp = std::fabs(aexbey) + std::fabs(bexaey);
    const double bcp = std::fabs(bexcey) + std::fabs(cexbey);
    const double cdp = std::fabs(cexdey) + std::fabs(dexcey);
    const double dap = std::fabs(dexaey) + std::fabs(aexdey);
    const double acp = std::fabs(aexcey) + std::fabs(cexaey);
    const double bdp = std::fabs(bexdey) + std::fabs(dexbey);
    const double permanent = ((cdp * bezp + bdp * cezp) + bcp * dezp) * alift +
                             ((dap * cezp + acp * dezp) + cdp * aezp) * blift +
                             ((abp * dezp + bdp * aezp) + dap * bezp) * clift +
                             ((bcp * aezp + acp * bezp) + abp * cezp) * dlift;
    // Underflow's share (constants.hpp): S = L Z + L + C + 1.
    const double lifts = (alift + blift) + (clift + dlift);
    const double zs = (aezp + bezp) + (cezp + dezp);
    const double orientations =
        (std::fabs(abc) + std::fabs(bcd)) + (std::fabs(cda) + std::fabs(dab));
    const double spread = (lifts * zs + lifts) + (orientations + 1.0);
    return filter_decides(det, filter_bound(eb::isp_a * permanent, eb::underflow_insphere, spread),
                          sign);
}

/// The double-word stage (proofs/bounds.md#insphere-double-word), in the filter's order.
template <bool Fma>
[[gnu::always_inline]] inline bool insphere_double_word_eval(const Word (&w)[12], Sign& sign) {
    using detail::dw::add, detail::dw::mul, detail::dw::neg;
    const auto [aex, aey, aez, bex, bey, bez, cex, cey, cez, dex, dey, dez] = w;
    const auto minor = [](Word p, Word q, Word r, Word s) {
        return add(mul<Fma>(p, q), neg(mul<Fma>(r, s)));
    };
    const Word ab = minor(aex, bey, bex, aey), bc = minor(bex, cey, cex, bey);
    const Word cd = minor(cex, dey, dex, cey), da = minor(dex, aey, aex, dey);
    const Word ac = minor(aex, cey, cex, aey), bd = minor(bex, dey, dex, bey);
    const Word abc = add(add(mul<Fma>(aez, bc), neg(mul<Fma>(bez, ac))), mul<Fma>(cez, ab));
    const Word bcd = add(add(mul<Fma>(bez, cd), neg(mul<Fma>(cez, bd))), mul<Fma>(dez, bc));
    const Word cda = add(add(mul<Fma>(cez, da), mul<Fma>(dez, ac)), mul<Fma>(aez, cd));
    const Word dab = add(add(mul<Fma>(dez, ab), mul<Fma>(aez, bd)), mul<Fma>(bez, da));
    const auto lift = [](Word x, Word y, Word z) {
        return add(add(mul<Fma>(x, x), mul<Fma>(y, y)), mul<Fma>(z, z));
    };
    const Word alift = lift(aex, aey, aez), blift = lift(bex, bey, bez);
    const Word clift = lift(cex, cey, cez), dlift = lift(dex, dey, dez);
    const Word det = add(add(mul<Fma>(dlift, abc), neg(mul<Fma>(clift, dab))),
                         add(mul<Fma>(blift, cda), neg(mul<Fma>(alift, bcd))));
    // An upper bound of T / kappa from the high parts (bounds.md: T <= kappa t), the
    // filter's permanent.
    const auto pair = [](Word p, Word q, Word r, Word s) {
        return std::fabs(p.hi * q.hi) + std::fabs(r.hi * s.hi);
    };
    const double abp = pair(aex, bey, bex, aey), bcp = pair(bex, cey, cex, bey);
    const double cdp = pair(cex, dey, dex, cey), dap = pair(dex, aey, aex, dey);
    const double acp = pair(aex, cey, cex, aey), bdp = pair(bex, dey, dex, bey);
    const double aezp = std::fabs(aez.hi), bezp = std::fabs(bez.hi), cezp = std::fabs(cez.hi),
                 dezp = std::fabs(dez.hi);
    const double t = ((cdp * bezp + bdp * cezp) + bcp * dezp) * alift.hi +
                     ((dap * cezp + acp * dezp) + cdp * aezp) * blift.hi +
                     ((abp * dezp + bdp * aezp) + dap * bezp) * clift.hi +
                     ((bcp * aezp + acp * bezp) + abp * cezp) * dlift.hi;
    return filter_decides(det.hi, eb::isp_dw * t, sign);
}

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__FMA__)
[[gnu::target("fma")]] bool insphere_double_word_fma(const Word (&w)[12], Sign& sign) {
    return insphere_double_word_eval<true>(w, sign);
}
#endif

[[gnu::noinline]] bool insphere_double_word(P3 a, P3 b, P3 c, P3 d, P3 e, Sign& sign) {
    using detail::dw::two_sum;
    const Word w[12] = {two_sum(a.x, -e.x), two_sum(a.y, -e.y), two_sum(a.z, -e.z),
                        two_sum(b.x, -e.x), two_sum(b.y, -e.y), two_sum(b.z, -e.z),
                        two_sum(c.x, -e.x), two_sum(c.y, -e.y), two_sum(c.z, -e.z),
                        two_sum(d.x, -e.x), two_sum(d.y, -e.y), two_sum(d.z, -e.z)};
    if (!detail::in_double_word_range(w, eb::isp_dw_min, eb::isp_dw_max)) return false;
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    return insphere_double_word_eval<true>(w, sign);
#else
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
    if (detail::dw::use_fma()) return insphere_double_word_fma(w, sign);
#endif
    return insphere_double_word_eval<false>(w, sign);
#endif
}

/// Every difference exact and all in a window of 24 bits: the determinant in 64/128-bit
/// integers (small_integers.hpp).
[[gnu::noinline]] bool insphere_small_integers(P3 a, P3 b, P3 c, P3 d, P3 e, const double (&v)[12],
                                               Sign& sign) {
    std::int64_t n[12];
    if (!detail::exact_small_differences<detail::insphere_bits>(
            {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z},
            {e.x, e.y, e.z, e.x, e.y, e.z, e.x, e.y, e.z, e.x, e.y, e.z}, v, n)) {
        return false;
    }
    sign = static_cast<Sign>(detail::insphere_small_sign(n));
    return true;
}

[[gnu::noinline]] Sign insphere_adapt(P3 a, P3 b, P3 c, P3 d, P3 e, const double (&v)[12],
                                      AdaptiveStage& stage) {
    // Two equal points make two equal rows of the lifted 5 x 5 determinant: zero.
    stage = AdaptiveStage::small_integer;
    const Point3 p[5] = {a, b, c, d, e};
    for (int i = 0; i < 5; ++i) {
        for (int j = i + 1; j < 5; ++j) {
            if (same_point(p[i], p[j])) return Sign::zero;
        }
    }
    const bool ties = detail::tie_likely(v);
    if (ties) {
        if (Sign s; insphere_small_integers(a, b, c, d, e, v, s)) return s;
    }
    stage = AdaptiveStage::double_word;
    if (Sign s; insphere_double_word(a, b, c, d, e, s)) return s;
    if (!ties) {
        stage = AdaptiveStage::small_integer;
        if (Sign s; insphere_small_integers(a, b, c, d, e, v, s)) return s;
    }
    if (!detail::expansion_safe(
            {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z, e.x, e.y, e.z}, 5,
            insphere_max_log)) {
        stage = AdaptiveStage::gmp;
        return GmpExactKernel::insphere(a, b, c, d, e);
    }
    stage = AdaptiveStage::exact;
    return detail::insphere_formula<detail::Expansion>(a, b, c, d, e, lift_expansion);
}

/// Stage A, then the exact stages. Out of line, so the semi-static fast path keeps few
/// values live.
[[gnu::noinline]] Sign insphere_after_filter(P3 a, P3 b, P3 c, P3 d, P3 e, AdaptiveStage& stage) {
    double v[12];
    insphere_differences(a, b, c, d, e, v);
    if (Sign s; insphere_stage_a(v, s)) return s;
    return insphere_adapt(a, b, c, d, e, v, stage);
}

inline Sign insphere_impl(P3 a, P3 b, P3 c, P3 d, P3 e, AdaptiveStage* stage) {
    *stage = AdaptiveStage::filter;
    if (Sign s; insphere_filter(a, b, c, d, e, s)) [[likely]]
        return s;
    return insphere_after_filter(a, b, c, d, e, *stage);
}

}  // namespace

Sign orient3d_staged(Point3 a, Point3 b, Point3 c, Point3 d, AdaptiveStage& stage) {
    return detail::in_standard_environment<orient3d_impl>(a, b, c, d, &stage);
}

Sign insphere_staged(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e, AdaptiveStage& stage) {
    return detail::in_standard_environment<insphere_impl>(a, b, c, d, e, &stage);
}

// Not through the *_staged functions: their by-value parameters, inlined here, were
// copied to a frame of their own (fifteen doubles for insphere) before the filter ran.
Sign AdaptiveKernel::orient3d(Point3 a, Point3 b, Point3 c, Point3 d) {
    AdaptiveStage stage;
    return detail::in_standard_environment<orient3d_impl>(a, b, c, d, &stage);
}

Sign AdaptiveKernel::insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e) {
    AdaptiveStage stage;
    return detail::in_standard_environment<insphere_impl>(a, b, c, d, e, &stage);
}

}  // namespace exidel
