// exidel (private): exact ties in fixed-width integers.
//
// No filter can decide an exact tie (a value of exactly zero: lattice circles, grids,
// exactly collinear points); the expansions can, at the price of their longest schedule.
// When the differences a predicate starts from are exact doubles whose bits all fit in a
// window of `small_bits` bits (common on lattices and grids: every difference is then an
// integer multiple of one power of two, 2^g, and below 2^(g + small_bits)), the
// predicate's polynomial in the integers d / 2^g is evaluated exactly in 64- and 128-bit
// integer arithmetic, and its sign is the predicate's (the polynomials are homogeneous,
// so scaling every difference by 2^-g scales the value by a positive power of two).
//
// Ranges (every bound strict; |d| < 2^30 for the integers of the 30-bit window, < 2^62
// for the 62-bit window of orient2d, compare_distance and incircle's second try, whose
// ranges are stated beside each function):
//   incircle: lifts dx^2 + dy^2 < 2^61, crosses |p q - r s| < 2^61, each lift x cross
//   < 2^122, the sum of three < 2^124 < 2^127: signed 128-bit;
//   incircle_cosine: squared lengths and |u|, |v| < 2^61, ac2 bc2 and u^2 < 2^122 (unsigned
//   128-bit), L = ac2 bc2 u^2 < 2^244: an unsigned 256-bit product compared exactly.
// The static_asserts in the code check the first of these; proofs/bounds.md#small-integers
// has the argument.
#pragma once

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>

#include "binary64.hpp"

namespace exidel::detail {

inline constexpr int small_bits = 30;
/// The wider window of the 128/256-bit evaluations (orient2d, compare_distance, and
/// incircle's second try).
inline constexpr int wide_bits = 62;

// GCC's and Clang's 128-bit integers (__extension__: not ISO C++, so -Wpedantic would warn).
__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

/// The window's top: the least h with |v_i| < 2^h for every i (0 when all are zero), or
/// no_top when one is not finite.
inline constexpr int no_top = INT_MIN;
template <int N>
int window_top(const double (&v)[N]) noexcept {
    // Two running maxima (even and odd indices): half the dependency chain of one.
    double m[2] = {0, 0};
    bool finite = true;
    for (int i = 0; i < N; ++i) {
        finite &= std::fabs(v[i]) <= std::numeric_limits<double>::max();  // false for NaN too
        m[i % 2] = std::max(m[i % 2], std::fabs(v[i]));
    }
    if (!finite) return no_top;
    const Binary64 top = decode(std::max(m[0], m[1]));
    return top.significand == 0 ? 0 : top.exponent + std::bit_width(top.significand);
}

/// Converts n exact differences, all below 2^h (window_top), to integers D_i = v_i 2^k
/// sharing one power of two, when every one is an integer multiple of 2^(h - Bits): then
/// |D_i| < 2^Bits. False otherwise, or if h is no_top.
///
/// The test is the scaling itself (why it is exact: proofs/bounds.md#small-integers):
/// x = (v 2^k1) 2^k2 with k1 + k2 = k = Bits - h, truncated to an integer n, must give
/// back x, and n must be nonzero when v is. A few multiplications and conversions per
/// value, without branches: decoding each value's exponent and trailing zeros instead
/// cost about a third of an exact tie's incircle (measured: 30 of 106 ns).
template <int Bits = small_bits, int N>
bool to_small_integers(const double (&v)[N], int h, std::int64_t (&out)[N]) noexcept {
    static_assert(Bits <= 62, "the integers are int64_t");
    if (h == no_top) return false;
    // h in [-1073, 1024], so k in [Bits - 1024, Bits + 1073]: two factors, each a normal
    // power of two.
    const int k = Bits - h, k1 = k / 2, k2 = k - k1;
    const double s1 = pow2(k1), s2 = pow2(k2);
    bool integers = true;
    for (int i = 0; i < N; ++i) {
        // |x| <= 2^Bits <= 2^62 (the exact value is below 2^Bits, and rounding cannot pass
        // that power of two), so the truncation is defined.
        const double x = (v[i] * s1) * s2;
        const auto n = static_cast<std::int64_t>(x);
        integers &= (static_cast<double>(n) == x) & ((n != 0) | (v[i] == 0));  // no branches
        out[i] = n;
    }
    return integers;
}

template <int Bits = small_bits, int N>
bool to_small_integers(const double (&v)[N], std::int64_t (&out)[N]) noexcept {
    return to_small_integers<Bits>(v, window_top(v), out);
}

/// The incircle determinant of integer differences below 2^small_bits, exactly.
inline int incircle_small_sign(const std::int64_t (&d)[6]) noexcept {
    static_assert(2 * small_bits + 1 <= 62, "a lift or a cross fits in 63 bits");
    static_assert(2 * (2 * small_bits + 1) + 2 <= 127, "three lift x cross products fit");
    const auto [adx, ady, bdx, bdy, cdx, cdy] = d;
    const std::int64_t alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy,
                       clift = cdx * cdx + cdy * cdy;
    const std::int64_t bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy,
                       ab = adx * bdy - bdx * ady;
    const i128 det = i128{alift} * bc + i128{blift} * ca + i128{clift} * ab;
    return (det > 0) - (det < 0);
}

/// orient2d of integer differences (a - c, b - c) below 2^wide_bits: each product is below
/// 2^124 and their difference below 2^125, in signed 128 bits.
inline int orient2d_small_sign(const std::int64_t (&d)[4]) noexcept {
    static_assert(2 * wide_bits + 1 <= 127, "two products and their difference fit");
    const auto [acx, acy, bcx, bcy] = d;
    const i128 det = i128{acx} * bcy - i128{acy} * bcx;
    return (det > 0) - (det < 0);
}

/// |p - c|^2 - |q - c|^2 of integer differences below 2^wide_bits: each sum of squares is
/// below 2^125, their difference below 2^125 in magnitude, in signed 128 bits.
inline int distance_small_sign(const std::int64_t (&d)[4]) noexcept {
    const auto [pcx, pcy, qcx, qcy] = d;
    const i128 det = (i128{pcx} * pcx + i128{pcy} * pcy) - (i128{qcx} * qcx + i128{qcy} * qcy);
    return (det > 0) - (det < 0);
}

/// An unsigned 256-bit value as two 128-bit halves, for comparing products exactly.
struct U256 {
    u128 hi, lo;
    friend bool operator<(const U256& x, const U256& y) noexcept {
        return x.hi != y.hi ? x.hi < y.hi : x.lo < y.lo;
    }
};

/// x * y exactly, from four 64 x 64 -> 128-bit products.
inline U256 mul_wide(u128 x, u128 y) noexcept {
    const auto lo64 = [](u128 v) { return static_cast<u128>(static_cast<std::uint64_t>(v)); };
    const u128 x0 = lo64(x), x1 = x >> 64, y0 = lo64(y), y1 = y >> 64;
    const u128 p00 = x0 * y0, p01 = x0 * y1, p10 = x1 * y0, p11 = x1 * y1;
    // Middle column: the high half of p00 plus the low halves of p01 and p10 (< 3 * 2^64).
    const u128 middle = (p00 >> 64) + lo64(p01) + lo64(p10);
    return {p11 + (p01 >> 64) + (p10 >> 64) + (middle >> 64), (middle << 64) | lo64(p00)};
}

/// a + b, for values whose sum stays below 2^256.
inline U256 add_wide(const U256& a, const U256& b) noexcept {
    const u128 lo = a.lo + b.lo;
    return {a.hi + b.hi + (lo < a.lo ? 1 : 0), lo};
}

/// The incircle determinant of integer differences below 2^wide_bits, exactly: lifts below
/// 2^125 (unsigned 128 bits), crosses below 2^125 in magnitude (signed 128 bits), each
/// lift x |cross| below 2^250 (mul_wide), and the positive and negative terms summed
/// apart (each sum below 3 * 2^250) and compared.
inline int incircle_wide_sign(const std::int64_t (&d)[6]) noexcept {
    static_assert(2 * wide_bits + 1 <= 126, "a lift or a cross fits in 127 bits");
    const auto [adx, ady, bdx, bdy, cdx, cdy] = d;
    const auto lift = [](std::int64_t x, std::int64_t y) {
        return u128(i128{x} * x + i128{y} * y);
    };
    const auto cross = [](std::int64_t p, std::int64_t q, std::int64_t r, std::int64_t s) {
        return i128{p} * q - i128{r} * s;
    };
    const u128 lifts[3] = {lift(adx, ady), lift(bdx, bdy), lift(cdx, cdy)};
    const i128 crosses[3] = {cross(bdx, cdy, cdx, bdy), cross(cdx, ady, adx, cdy),
                             cross(adx, bdy, bdx, ady)};
    U256 positive{0, 0}, negative{0, 0};
    for (int i = 0; i < 3; ++i) {
        const U256 term = mul_wide(lifts[i], u128(crosses[i] < 0 ? -crosses[i] : crosses[i]));
        (crosses[i] < 0 ? negative : positive) =
            add_wide(crosses[i] < 0 ? negative : positive, term);
    }
    return (negative < positive) - (positive < negative);
}

/// For incircle_cosine with dot products of opposite nonzero signs: the sign of
/// L - R = |a-c|^2 |b-c|^2 u^2 - |a-d|^2 |b-d|^2 v^2 from integer differences below
/// 2^small_bits, exactly (d = adx, ady, bdx, bdy, acx, acy, bcx, bcy).
inline int cosine_small_sign(const std::int64_t (&d)[8]) noexcept {
    static_assert(2 * small_bits + 1 <= 63, "a squared length or |u| fits in 64 bits");
    const auto [adx, ady, bdx, bdy, acx, acy, bcx, bcy] = d;
    const auto magnitude = [](std::int64_t v) {
        return static_cast<std::uint64_t>(v < 0 ? -v : v);
    };
    const auto ad2 = static_cast<std::uint64_t>(adx * adx + ady * ady);
    const auto bd2 = static_cast<std::uint64_t>(bdx * bdx + bdy * bdy);
    const auto ac2 = static_cast<std::uint64_t>(acx * acx + acy * acy);
    const auto bc2 = static_cast<std::uint64_t>(bcx * bcx + bcy * bcy);
    const std::uint64_t u = magnitude(adx * bdx + ady * bdy), v = magnitude(acx * bcx + acy * bcy);
    const U256 left = mul_wide(u128{ac2} * bc2, u128{u} * u);
    const U256 right = mul_wide(u128{ad2} * bd2, u128{v} * v);
    return (right < left) - (left < right);
}

// ---- The predicates of space ------------------------------------------------------------

/// orient3d of integer differences (a - d, b - d, c - d) below 2^small_bits: each 2 x 2
/// minor below 2^61 (int64), each z x minor below 2^91, their sum below 2^93 (signed 128
/// bits).
inline int orient3d_small_sign(const std::int64_t (&d)[9]) noexcept {
    static_assert(2 * small_bits + 1 <= 62, "a minor fits in 63 bits");
    static_assert(3 * small_bits + 3 <= 127, "three z x minor products and their sum fit");
    const auto [adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz] = d;
    const i128 det = i128{adz} * (bdx * cdy - cdx * bdy) + i128{bdz} * (cdx * ady - adx * cdy) +
                     i128{cdz} * (adx * bdy - bdx * ady);
    return (det > 0) - (det < 0);
}

/// The window of insphere's integers: degree 5 has to fit in signed 128 bits.
inline constexpr int insphere_bits = 24;

/// insphere of integer differences (p - e for p = a, b, c, d) below 2^insphere_bits, in
/// formulas.hpp's order: minors below 2^49 (int64), each z x minor below 2^73 and each
/// 3 x 3 orientation (three of them) below 2^75, lifts below 3 * 2^48 < 2^50 (int64), each
/// lift x orientation below 2^125, the two differences of two below 2^126 and the sum
/// below 2^127 (signed 128 bits).
inline int insphere_small_sign(const std::int64_t (&d)[12]) noexcept {
    static_assert(5 * insphere_bits + 7 <= 127, "the determinant fits in signed 128 bits");
    const auto [aex, aey, aez, bex, bey, bez, cex, cey, cez, dex, dey, dez] = d;
    const std::int64_t ab = aex * bey - bex * aey, bc = bex * cey - cex * bey,
                       cd = cex * dey - dex * cey, da = dex * aey - aex * dey,
                       ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
    const i128 abc = i128{aez} * bc - i128{bez} * ac + i128{cez} * ab;
    const i128 bcd = i128{bez} * cd - i128{cez} * bd + i128{dez} * bc;
    const i128 cda = i128{cez} * da + i128{dez} * ac + i128{aez} * cd;
    const i128 dab = i128{dez} * ab + i128{aez} * bd + i128{bez} * da;
    const std::int64_t alift = aex * aex + aey * aey + aez * aez;
    const std::int64_t blift = bex * bex + bey * bey + bez * bez;
    const std::int64_t clift = cex * cex + cey * cey + cez * cez;
    const std::int64_t dlift = dex * dex + dey * dey + dez * dez;
    const i128 det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
    return (det > 0) - (det < 0);
}

}  // namespace exidel::detail
