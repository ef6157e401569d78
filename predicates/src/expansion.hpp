// exidel (private): error-free transformations and expansion arithmetic.
//
// An expansion is a sum of doubles, stored by increasing magnitude, with zero components
// eliminated (Shewchuk 1997, Section 2). Every operation below is exact, whatever the
// structure of its operands (Two-Sum needs no ordering, Two-Product none), provided the
// floating-point environment is IEEE binary64, round to nearest, no contraction (this
// header is compiled only in the library's own translation units, with -ffp-contract=off),
// and no intermediate overflows or underflows; the adaptive kernel checks the last
// condition on its input before it gets here (adaptive.cpp, `expansion_safe`).
//
// What is NOT taken on trust is the structure of a result: Shewchuk's Theorem 13 (Fast-
// Expansion-Sum keeps strongly nonoverlapping operands strongly nonoverlapping) is false
// (proofs/bounds.md#expansion-estimate has a counterexample), and what it was to guarantee
// is what the kernel relies on: that the largest component gives the sign, and that the
// estimate errs by at most lemma E's bound. So the sign of a Fast-Expansion-Sum result is
// read only after `nonoverlapping` has checked it (`checked_sign`), with an exact integer
// sum as the fallback, and an estimate is trusted only after `in_class_w` has checked the
// class lemma E is proved for.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

#include <boost/container/small_vector.hpp>
#include <boost/multiprecision/cpp_int.hpp>

#include "binary64.hpp"
#include "exidel/predicates/types.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"

namespace exidel::detail {

/// x + y == a + b exactly, x = fl(a + b). (Knuth's Two-Sum: no ordering needed.)
inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double bv = x - a;
    const double av = x - bv;
    y = (a - av) + (b - bv);
}

/// x + y == a - b exactly, x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) {
    x = a - b;
    const double bv = a - x;
    const double av = x + bv;
    y = (a - av) + (bv - b);
}

/// The rounding error of x = fl(a - b): a - b == x + tail.
inline double two_diff_tail(double a, double b, double x) {
    const double bv = a - x;
    const double av = x + bv;
    return (a - av) + (bv - b);
}

/// x + y == a * b exactly, x = fl(a * b). The error term is one fused multiply-add,
/// written explicitly (docs/background.md section 1: Dekker's split breaks when the compiler
/// contracts).
inline void two_product(double a, double b, double& x, double& y) {
    x = a * b;
    y = std::fma(a, b, -x);
}

/// (a1 + a0) + (b1 + b0) as a four-component expansion, exact (Two_Two_Sum).
/// x[0] is the smallest component; zeros are not eliminated.
inline void two_two_sum(double a1, double a0, double b1, double b0, double x[4]) {
    double i, j, k;
    two_sum(a0, b0, i, x[0]);
    two_sum(a1, i, j, k);
    two_sum(k, b1, i, x[1]);
    two_sum(j, i, x[3], x[2]);
}

/// (a1 + a0) - (b1 + b0), exact (Shewchuk's Two_Two_Diff): the sum with b negated, which
/// is exact, and Two-Sum of a and -b gives the same rounded value and error as Two-Diff.
inline void two_two_diff(double a1, double a0, double b1, double b0, double x[4]) {
    two_two_sum(a1, a0, -b1, -b0, x);
}

/// a + b for a four-component expansion a (a[0] smallest) and a double b: five
/// components, exact, no branches (Shewchuk's Four_One_Sum; zeros are kept).
inline void four_one_sum(const double a[4], double b, double x[5]) {
    double carry = b;
    for (int i = 0; i < 4; ++i) two_sum(a[i], carry, carry, x[i]);
    x[4] = carry;
}

/// a + b for two four-component expansions: eight components, exact, no branches
/// (Shewchuk's Four_Four_Sum: four rounds of Four_One_Sum). Zeros are kept; the sign is
/// that of the largest nonzero component (sign_of_largest).
inline void four_four_sum(const double a[4], const double b[4], double x[8]) {
    double acc[8] = {a[0], a[1], a[2], a[3], 0, 0, 0, 0};
    for (int j = 0; j < 4; ++j) {
        double grown[5];
        four_one_sum(acc + j, b[j], grown);
        for (int i = 0; i < 5; ++i) acc[j + i] = grown[i];
    }
    for (int i = 0; i < 8; ++i) x[i] = acc[i];
}

/// Sign of a nonoverlapping expansion whose zero components were not eliminated.
template <std::size_t N>
Sign sign_of_largest(const double (&x)[N]) {
    for (std::size_t i = N; i-- > 0;) {
        if (x[i] != 0) return sign_of(x[i]);
    }
    return Sign::zero;
}

// ---- Fixed-size expansion arithmetic on raw arrays ---------------------------------------
// For the adaptive stages, whose expansion lengths are bounded and known: no allocation,
// the caller provides the output array (length at most elen + flen, resp. 2 elen).

/// h = e + f_sign * f (Shewchuk's fast_expansion_sum_zeroelim, merging by magnitude on
/// the fly; f_sign is +1 or -1, so the negation is exact). Returns the length of h; h may
/// not alias e or f.
inline int expansion_sum(int elen, const double* e, int flen, const double* f, double* h,
                         double f_sign = 1.0) {
    int i = 0, j = 0, n = 0;
    auto next = [&]() {
        if (j == flen || (i < elen && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
        return f_sign * f[j++];
    };
    if (elen + flen == 0) return 0;
    double q = next();
    while (i + j < elen + flen) {
        double qn, hh;
        two_sum(q, next(), qn, hh);
        if (hh != 0) h[n++] = hh;
        q = qn;
    }
    if (q != 0) h[n++] = q;
    return n;
}

/// h = e * b (Shewchuk's scale_expansion_zeroelim). Returns the length of h (<= 2 elen).
inline int expansion_scale(int elen, const double* e, double b, double* h) {
    if (elen == 0 || b == 0) return 0;
    int n = 0;
    double q, hh;
    two_product(e[0], b, q, hh);
    if (hh != 0) h[n++] = hh;
    for (int i = 1; i < elen; ++i) {
        double p1, p0, s;
        two_product(e[i], b, p1, p0);
        two_sum(q, p0, s, hh);
        if (hh != 0) h[n++] = hh;
        two_sum(p1, s, q, hh);
        if (hh != 0) h[n++] = hh;
    }
    if (q != 0) h[n++] = q;
    return n;
}

// ---- Structure checks ----------------------------------------------------------------
// Decided on the bits, so they do not depend on the caller's DAZ or rounding mode.

/// The positions of the lowest and the highest nonzero bit of a finite v != 0:
/// |v| = sum of some 2^k, lo <= k <= hi, with 2^lo and 2^hi among them.
struct BitRange {
    int lo, hi;
};
inline BitRange bit_range(double v) {
    const Binary64 d = decode(v);
    return {d.exponent + std::countr_zero(d.significand),
            d.exponent + 63 - std::countl_zero(d.significand)};
}

/// x[0..n) (no zeros) pairwise nonoverlapping: each component's highest bit is below the
/// next one's lowest. Then |x[0] + ... + x[k-1]| < 2^lo(x[k]) <= |x[k]| for every k
/// (induction: the sum stays below 2^(hi(x[k-1]) + 1)), so the last component gives the
/// sign of the sum.
inline bool nonoverlapping(int n, const double* x) {
    for (int k = 1; k < n; ++k) {
        if (bit_range(x[k - 1]).hi >= bit_range(x[k]).lo) return false;
    }
    return true;
}

/// x[0..n) (no zeros) in the class W of proofs/bounds.md#expansion-estimate, for which
/// lemma E bounds the error of expansion_estimate: pairwise nonoverlapping, no component
/// adjacent to two others (neighbours are adjacent when the smaller's highest bit is just
/// below the larger's lowest), and the smaller of an adjacent pair a power of two.
inline bool in_class_w(int n, const double* x) {
    if (n == 0) return true;
    BitRange below = bit_range(x[0]);
    bool below_adjacent = false;  // x[k-2] and x[k-1] are adjacent
    for (int k = 1; k < n; ++k) {
        const BitRange r = bit_range(x[k]);
        if (below.hi >= r.lo) return false;
        const bool adjacent = below.hi + 1 == r.lo;
        if (adjacent && (below_adjacent || below.lo != below.hi)) return false;
        below_adjacent = adjacent;
        below = r;
    }
    return true;
}

/// The sign of x[0] + ... + x[n-1] (any doubles), by exact integer arithmetic: every
/// double is m 2^e with |m| < 2^53, so the sum is an integer times 2^(smallest e).
inline Sign exact_sign_of_sum(int n, const double* x) {
    int low = 0;
    bool any = false;
    for (int k = 0; k < n; ++k) {
        if (x[k] == 0) continue;
        const int e = decode(x[k]).exponent;
        low = any ? std::min(low, e) : e;
        any = true;
    }
    boost::multiprecision::cpp_int sum = 0;
    for (int k = 0; k < n; ++k) {
        if (x[k] == 0) continue;
        const Binary64 d = decode(x[k]);
        sum += boost::multiprecision::cpp_int(d.signed_significand()) << (d.exponent - low);
    }
    return sum > 0 ? Sign::positive : (sum < 0 ? Sign::negative : Sign::zero);
}

/// Sign of the exact sum of an expansion of length n (no zeros, increasing magnitude):
/// its largest component once the structure is checked, the integer sum otherwise.
inline Sign checked_sign(int n, const double* e) {
    if (n == 0) return Sign::zero;
    return nonoverlapping(n, e) ? sign_of(e[n - 1]) : exact_sign_of_sum(n, e);
}

/// A floating approximation of an expansion's value.
inline double expansion_estimate(int n, const double* e) {
    double s = 0;
    for (int i = 0; i < n; ++i) s += e[i];
    return s;
}

/// An exact sum of doubles. Components live in an inline buffer large enough for every
/// stage-B and stage-C expansion of the kernel, so the adaptive stages do not allocate; only
/// the rare fully exact stage of incircle and incircle_cosine can spill to the heap.
class Expansion {
    using Components = boost::container::small_vector<double, 64>;

public:
    Expansion() = default;
    Expansion(double v) {  // NOLINT: implicit, so formulas can lift doubles
        if (v != 0) c_.push_back(v);
    }
    template <std::size_t N>
    static Expansion from_components(const double (&x)[N]) {
        Expansion e;
        for (double v : x) {
            if (v != 0) e.c_.push_back(v);
        }
        return e;
    }

    /// The sign of the exact value (checked_sign: the structure is not taken on trust).
    Sign sign() const { return checked_sign(static_cast<int>(c_.size()), c_.data()); }
    friend Expansion operator+(const Expansion& e, const Expansion& f) { return sum(e, f, 1.0); }
    friend Expansion operator-(const Expansion& e, const Expansion& f) { return sum(e, f, -1.0); }
    friend Expansion operator*(const Expansion& e, const Expansion& f) {
        const Expansion& small = e.c_.size() <= f.c_.size() ? e : f;
        const Expansion& large = e.c_.size() <= f.c_.size() ? f : e;
        Expansion r;
        for (double b : small.c_) r = sum(r, large.scaled(b), 1.0);
        r.compress();
        return r;
    }
    friend bool operator>(const Expansion& e, const Expansion& f) {
        return (e - f).sign() == Sign::positive;
    }
    friend bool operator>(const Expansion& e, int zero) {
        return zero == 0 ? e.sign() == Sign::positive : e > Expansion(zero);
    }
    friend bool operator<(const Expansion& e, int zero) {
        return zero == 0 ? e.sign() == Sign::negative : Expansion(zero) > e;
    }

private:
    /// e + f_sign * f (f_sign is +1 or -1), by the raw-array expansion_sum above.
    static Expansion sum(const Expansion& e, const Expansion& f, double f_sign) {
        const int ne = e.size(), nf = f.size();
        Expansion h;
        h.c_.resize(static_cast<std::size_t>(ne + nf), boost::container::default_init);
        h.c_.resize(static_cast<std::size_t>(
            expansion_sum(ne, e.c_.data(), nf, f.c_.data(), h.c_.data(), f_sign)));
        return h;
    }

    /// this * b, exact, by the raw-array expansion_scale above.
    Expansion scaled(double b) const {
        Expansion h;
        h.c_.resize(2 * c_.size(), boost::container::default_init);
        h.c_.resize(static_cast<std::size_t>(expansion_scale(size(), c_.data(), b, h.c_.data())));
        return h;
    }

    int size() const { return static_cast<int>(c_.size()); }

    /// Shewchuk's compress: the same value in (usually far) fewer components.
    void compress() {
        const std::size_t n = c_.size();
        if (n < 2) return;
        Components g(n);
        std::size_t bottom = n - 1;
        double q = c_[n - 1];
        for (std::size_t k = n - 1; k-- > 0;) {
            double qn, r;
            two_sum(q, c_[k], qn, r);
            if (r != 0) {
                g[bottom--] = qn;
                q = r;
            } else {
                q = qn;
            }
        }
        g[bottom] = q;
        Components h;
        for (std::size_t k = bottom + 1; k < n; ++k) {
            double qn, r;
            two_sum(g[k], q, qn, r);
            if (r != 0) h.push_back(r);
            q = qn;
        }
        if (q != 0) h.push_back(q);
        c_ = std::move(h);
    }

    Components c_;
};

}  // namespace exidel::detail
