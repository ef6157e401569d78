// exidel (private): the checks that route a query between the adaptive kernel's exact
// stages, shared by the predicates of the plane (adaptive.cpp) and of space
// (adaptive3d.cpp).
#pragma once

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "binary64.hpp"
#include "double_word.hpp"
#include "expansion.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"
#include "exidel/predicates/staged.hpp"
#include "small_integers.hpp"

namespace exidel::detail {

// ---- When is expansion arithmetic error-free? -------------------------------------------
// Every nonzero double v is a multiple of 2^g(v), g(v) = max(ilogb(v) - 52, -1074). A
// polynomial of degree d in the coordinates then only ever produces multiples of
// 2^(d * min g), so Two-Sum and Two-Product never underflow when d * min g >= -1074; and
// with every |v| < 2^(max_log + 1) no intermediate of the formulas overflows
// (proofs/bounds.md#expansion-range derives max_log per predicate).
//
// The exponent is read from the bits rather than with std::ilogb, a library call that
// costs a large share of an exact tie of compare_distance (docs/measurements.md).
// A subnormal (exponent field 0) is given e = -1023 instead of its true ilogb < -1022:
// the only uses are e <= max_log, true either way, and g = max(e - 52, -1074) = -1074,
// equal either way.
inline bool expansion_safe(std::initializer_list<double> coordinates, int degree, int max_log) {
    int g_min = INT_MAX, e_max = INT_MIN;
    for (double v : coordinates) {
        if (v == 0) continue;
        const int e = decode(v).biased_exponent - 1023;
        e_max = std::max(e_max, e);
        g_min = std::min(g_min, std::max(e - 52, -1074));
    }
    return e_max == INT_MIN || (e_max <= max_log && degree * g_min >= -1074);
}

// ---- exact ties in small integers (small_integers.hpp) ----------------------------------

/// Every rounded difference exact: its Two-Diff tail is zero.
template <int N>
bool exact_differences(const double (&minuend)[N], const double (&subtrahend)[N],
                       const double (&difference)[N]) {
    bool exact = true;
    for (int i = 0; i < N; ++i) {
        exact &= two_diff_tail(minuend[i], subtrahend[i], difference[i]) == 0;
    }
    return exact;
}

/// The rounded differences as integers sharing one power of two, when every one is exact
/// and all fit in a window of Bits bits.
template <int Bits = small_bits, int N>
bool exact_small_differences(const double (&minuend)[N], const double (&subtrahend)[N],
                             const double (&difference)[N], std::int64_t (&out)[N]) {
    return exact_differences(minuend, subtrahend, difference) &&
           to_small_integers<Bits>(difference, out);
}

/// Which of the small-integer and double-word stages to try first (either order is exact;
/// each costs about 40 ns when it fails). Differences whose significands all end in eight
/// zero bits come from data of low precision (lattices, grids, scaled integers), where
/// exact ties live: those try the integers first, full-precision data the double words.
template <int N>
bool tie_likely(const double (&differences)[N]) {
    std::uint64_t low_bits = 0;
    for (double x : differences) low_bits |= std::bit_cast<std::uint64_t>(x);
    return (low_bits & 0xff) == 0;
}

// ---- the double-word stages --------------------------------------------------------------

/// Every nonzero |high part| in [lo, hi], the range a double-word stage is proven for.
/// Negated comparisons, so that an infinite difference (or NaN) fails too.
template <int N>
bool in_double_word_range(const dw::Word (&w)[N], double lo, double hi) {
    for (const dw::Word& v : w) {
        const double m = std::fabs(v.hi);
        if (!(m <= hi) || (m != 0 && m < lo)) return false;
    }
    return true;
}

}  // namespace exidel::detail
