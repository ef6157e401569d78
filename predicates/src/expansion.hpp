// exidel (private): error-free transformations and expansion arithmetic.
//
// An expansion is a sum of doubles, stored by increasing magnitude, nonoverlapping, with
// zero components eliminated; its sign is the sign of its largest component (Shewchuk
// 1997, Section 2). Every operation below is exact provided the floating-point
// environment is IEEE binary64, round to nearest, no contraction (this header is compiled
// only in the library's own translation units, with -ffp-contract=off), and no
// intermediate overflows or underflows; the adaptive kernel checks the last condition on
// its input before it gets here (adaptive.cpp, `expansion_safe`).
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "exidel/predicates/types.hpp"
#include "fp_hygiene.hpp"

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
/// written explicitly (FIELD_NOTES: Dekker's split breaks when the compiler contracts).
inline void two_product(double a, double b, double& x, double& y) {
    x = a * b;
    y = std::fma(a, b, -x);
}

/// (a1 + a0) - (b1 + b0) as a four-component expansion, exact (Shewchuk's Two_Two_Diff).
/// x[0] is the smallest component; zeros are not eliminated.
inline void two_two_diff(double a1, double a0, double b1, double b0, double x[4]) {
    double i, j, k;
    two_diff(a0, b0, i, x[0]);
    two_sum(a1, i, j, k);
    two_diff(k, b1, i, x[1]);
    two_sum(j, i, x[3], x[2]);
}

/// (a1 + a0) + (b1 + b0) as a four-component expansion, exact (Two_Two_Sum).
inline void two_two_sum(double a1, double a0, double b1, double b0, double x[4]) {
    double i, j, k;
    two_sum(a0, b0, i, x[0]);
    two_sum(a1, i, j, k);
    two_sum(k, b1, i, x[1]);
    two_sum(j, i, x[3], x[2]);
}

/// An exact sum of doubles. The component vector lives on the heap: expansions are the
/// rare slow path, and clarity wins there.
class Expansion {
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

    Sign sign() const { return c_.empty() ? Sign::zero : sign_of(c_.back()); }
    /// A floating approximation of the value (the sum, smallest first).
    double estimate() const {
        double s = 0;
        for (double v : c_) s += v;
        return s;
    }

    friend Expansion operator+(const Expansion& e, const Expansion& f) { return sum(e, f); }
    friend Expansion operator-(const Expansion& e, const Expansion& f) {
        return sum(e, f.negated());
    }
    friend Expansion operator*(const Expansion& e, const Expansion& f) {
        Expansion r;
        for (double b : f.c_) r = sum(r, e.scaled(b));
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
    Expansion negated() const {
        Expansion r = *this;
        for (double& v : r.c_) v = -v;
        return r;
    }

    /// Shewchuk's fast expansion sum with zero elimination: merge the components by
    /// magnitude, then one pass of Two-Sum.
    static Expansion sum(const Expansion& e, const Expansion& f) {
        if (e.c_.empty()) return f;
        if (f.c_.empty()) return e;
        std::vector<double> g;
        g.reserve(e.c_.size() + f.c_.size());
        std::size_t i = 0, j = 0;
        while (i < e.c_.size() && j < f.c_.size()) {
            g.push_back(std::fabs(e.c_[i]) < std::fabs(f.c_[j]) ? e.c_[i++] : f.c_[j++]);
        }
        while (i < e.c_.size()) g.push_back(e.c_[i++]);
        while (j < f.c_.size()) g.push_back(f.c_[j++]);
        Expansion h;
        double q = g[0];
        for (std::size_t k = 1; k < g.size(); ++k) {
            double qn, hh;
            two_sum(q, g[k], qn, hh);
            if (hh != 0) h.c_.push_back(hh);
            q = qn;
        }
        if (q != 0 || h.c_.empty()) h.c_.push_back(q);
        if (h.c_.size() == 1 && h.c_[0] == 0) h.c_.clear();
        return h;
    }

    /// Shewchuk's scale_expansion_zeroelim: this * b, exact.
    Expansion scaled(double b) const {
        Expansion h;
        if (c_.empty() || b == 0) return h;
        double q, hh;
        two_product(c_[0], b, q, hh);
        if (hh != 0) h.c_.push_back(hh);
        for (std::size_t i = 1; i < c_.size(); ++i) {
            double p1, p0, s;
            two_product(c_[i], b, p1, p0);
            two_sum(q, p0, s, hh);
            if (hh != 0) h.c_.push_back(hh);
            two_sum(p1, s, q, hh);
            if (hh != 0) h.c_.push_back(hh);
        }
        if (q != 0 || h.c_.empty()) h.c_.push_back(q);
        if (h.c_.size() == 1 && h.c_[0] == 0) h.c_.clear();
        return h;
    }

    /// Shewchuk's compress: the same value in (usually far) fewer components.
    void compress() {
        const std::size_t n = c_.size();
        if (n < 2) return;
        std::vector<double> g(n);
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
        std::vector<double> h;
        for (std::size_t k = bottom + 1; k < n; ++k) {
            double qn, r;
            two_sum(g[k], q, qn, r);
            if (r != 0) h.push_back(r);
            q = qn;
        }
        if (q != 0 || h.empty()) h.push_back(q);
        if (h.size() == 1 && h[0] == 0) h.clear();
        c_ = std::move(h);
    }

    std::vector<double> c_;
};

}  // namespace exidel::detail
