// exidel: the correctly rounded circumcentre (construct.hpp).
//
// Three stages, each readable on its own (proofs/bounds.md#circumcenter for the first
// two): 1, plain doubles with an error bound; 2, a double-word proposal verified by a
// double-word evaluation; 3, exact integers rounded once. circumcenter() tries them in
// that order; each accepts only a value it has proven to be the nearest double.
#include "exidel/predicates/construct.hpp"

#include <gmp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <initializer_list>
#include <cstdint>
#include <limits>
#include <optional>

#include "binary64.hpp"
#include "double_word.hpp"
#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"

namespace exidel {

std::string_view to_string(CircumcenterStatus status) noexcept {
    switch (status) {
        case CircumcenterStatus::ok: return "ok";
        case CircumcenterStatus::collinear: return "collinear";
        case CircumcenterStatus::overflow: return "overflow";
        case CircumcenterStatus::non_finite_input: return "non_finite_input";
    }
    return "unknown";
}

std::string_view to_string(CircumcenterStage stage) noexcept {
    switch (stage) {
        case CircumcenterStage::floating: return "floating";
        case CircumcenterStage::double_word: return "double_word";
        case CircumcenterStage::exact: return "exact";
    }
    return "unknown";
}

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

bool finite(Point2 p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

Circumcenter classify(Point2 p) noexcept {
    const bool overflow = std::isinf(p.x) || std::isinf(p.y);
    return {p, overflow ? CircumcenterStatus::overflow : CircumcenterStatus::ok,
            CircumcenterStage::exact};
}

// ---- double words (double_word.hpp) --------------------------------------------------------

using detail::dw::add;
using detail::dw::mul;
using detail::dw::neg;
using detail::dw::two_sum;
using detail::dw::Word;

/// Half the smaller gap from s to a neighbouring double (below a power of two the gap is
/// half the ulp); 0 when s is too small for stage 1 to reason about its neighbours.
double half_gap(double s) noexcept {
    const detail::Binary64 bits = detail::decode(s);
    if (bits.biased_exponent < 3) return 0.0;
    const bool power_of_two = bits.significand == (std::uint64_t{1} << 52);
    return detail::pow2(bits.biased_exponent - 1075 - (power_of_two ? 2 : 1));
}

/// The differences b - a and c - a exactly (Two-Diff), when they are in the range both
/// floating-point stages are proven for (bounds.md#circumcenter, the range conditions).
struct Differences {
    Point2 a;
    Word bx, by, cx, cy;
};

std::optional<Differences> differences(Point2 a, Point2 b, Point2 c) noexcept {
    const Differences t{a, two_sum(b.x, -a.x), two_sum(b.y, -a.y), two_sum(c.x, -a.x),
                        two_sum(c.y, -a.y)};
    const double m = std::max(std::max(std::fabs(t.bx.hi), std::fabs(t.by.hi)),
                              std::max(std::fabs(t.cx.hi), std::fabs(t.cy.hi)));
    if (!(m >= bounds::circumcenter_min_scale && m <= bounds::circumcenter_max_scale))
        return std::nullopt;
    const double part = m * bounds::circumcenter_min_part;
    const auto too_small = [part](Word v) { return v.hi != 0.0 && std::fabs(v.hi) < part; };
    if (too_small(t.bx) || too_small(t.by) || too_small(t.cx) || too_small(t.cy))
        return std::nullopt;
    return t;
}

// ---- stage 1: floating point ---------------------------------------------------------------
// Delaunay triangles are small next to their coordinates, so the centre's offset from a
// is much smaller than the centre itself, and an offset with a relative error of a few
// eps usually still lies well inside one rounding interval of a.x + offset. Stage 1
// evaluates the offset in plain doubles with a proven bound (bounds.md#circumcenter,
// claims F1 to F3) and certifies the nearest double when it can.

/// The shared part of both coordinates: with d the computed determinant and ed its
/// error bound (ed < |d| / 2), half_inverse = fl(1 / (2 d)) and slack = fl(1 / (|d| - ed)).
struct FloatDenominator {
    double half_inverse;
    double slack;
    double error;
};

/// base + N / (2 D) from computed n with |n - N| <= en; the nearest double, if the bound
/// certifies it.
std::optional<double> float_coordinate(double base, double n, double en,
                                       const FloatDenominator& den) noexcept {
    const double u = n * den.half_inverse;
    const double mag = std::fabs(u);
    if (u != 0.0 && !(mag >= bounds::circumcenter_min_offset)) return std::nullopt;
    // Claim F2: |N / (2 D) - u| <= (en + |n / d| ed) / (2 (|d| - ed)) + 2 eps |u| (u has
    // two roundings), and |n / d| <= 2 |u| (1 + 3 eps); the computed e is at least the
    // bound: its own roundings are covered by the factor.
    const double e =
        (0.5 * ((en + 2.0 * mag * den.error) * den.slack) + 2.0 * bounds::epsilon * mag) *
        bounds::circumcenter_float_factor;
    if (!(e <= bounds::circumcenter_max_offset)) return std::nullopt;
    // Claim F3: base + u == s + r exactly (Two-Sum), so |x - s| <= |r| + e.
    const Word sr = two_sum(base, u);
    if (!(std::fabs(sr.hi) <= bounds::circumcenter_max_offset)) return std::nullopt;
    const double bound = (std::fabs(sr.lo) + e) * (1.0 + bounds::circumcenter_margin);
    if (!(bound < half_gap(sr.hi))) return std::nullopt;
    return sr.hi;
}

std::optional<Point2> float_stage(const Differences& t) noexcept {
    const double bx = t.bx.hi, by = t.by.hi, cx = t.cx.hi, cy = t.cy.hi;
    // Claim F1: |d - D| <= circumcenter_float_rel * (|p1| + |p2|), and alike for N.
    const double p1 = bx * cy, p2 = by * cx;
    const double d = p1 - p2;
    const double ed = bounds::circumcenter_float_rel * (std::fabs(p1) + std::fabs(p2));
    if (!(std::fabs(d) > 2.0 * ed)) return std::nullopt;
    const double bb = bx * bx + by * by, cc = cx * cx + cy * cy;
    const double nx = cy * bb - by * cc, ny = bx * cc - cx * bb;
    const double enx = bounds::circumcenter_float_rel * (std::fabs(cy) * bb + std::fabs(by) * cc);
    const double eny = bounds::circumcenter_float_rel * (std::fabs(bx) * cc + std::fabs(cx) * bb);
    const FloatDenominator den{1.0 / (2.0 * d), 1.0 / (std::fabs(d) - ed), ed};
    const std::optional<double> x = float_coordinate(t.a.x, nx, enx, den);
    if (!x) return std::nullopt;
    const std::optional<double> y = float_coordinate(t.a.y, ny, eny, den);
    if (!y) return std::nullopt;
    return Point2{*x, *y};
}

// ---- stage 2: double-word arithmetic --------------------------------------------------------
// When stage 1's bound is too wide (the offset is as large as the centre, or the triangle
// is nearly flat), stage 2 proposes the nearest double from a double-word quotient and
// verifies it with one double-word evaluation (constants.hpp, circumcenter_rel).

/// The polynomials of the centre in double-word arithmetic.
struct Frame {
    Word d;           ///< D = bx cy - by cx
    double d_error;   ///< bound on |D~ - D|
    Word nx, ny;      ///< Nx, Ny
    double tnx, tny;  ///< their permanents (from the high parts)
    double td;        ///< D's permanent
};

/// base + N / (2 D), if stage 2 certifies the nearest double (bounds.md#circumcenter).
template <bool Fma>
[[gnu::always_inline]] inline std::optional<double> coordinate(double base, Word n, double tn,
                                                               const Frame& f) noexcept {
    // Propose: x ~ base + q1 + q2, q1 the quotient of the high parts, q2 its correction.
    const double two_d = 2.0 * f.d.hi;
    const double q1 = n.hi / two_d;
    const Word r = add(n, neg(mul<Fma>({two_d, 2.0 * f.d.lo}, {q1, 0.0})));
    const double q2 = r.hi / two_d;
    const Word bq = two_sum(base, q1);
    const double s = bq.hi + (bq.lo + q2);
    constexpr double lo = bounds::circumcenter_min_offset, hi = bounds::circumcenter_max_offset;
    if (!(std::fabs(s) <= hi && std::fabs(base) <= hi)) return std::nullopt;
    // Verify: F = N + 2 D w with w = base - s exactly.
    const Word w = two_sum(base, -s);
    if (w.hi != 0.0 && !(std::fabs(w.hi) >= lo)) return std::nullopt;
    const Word fw = add(n, mul<Fma>({two_d, 2.0 * f.d.lo}, w));
    const double f_error = bounds::circumcenter_rel * (tn + 2.0 * f.td * std::fabs(w.hi));
    const double h = half_gap(s);
    const double lhs = (std::fabs(fw.hi) + f_error) * (1.0 + bounds::circumcenter_margin);
    const double rhs =
        2.0 * (std::fabs(f.d.hi) - f.d_error) * h * (1.0 - bounds::circumcenter_margin);
    if (!(lhs < rhs)) return std::nullopt;
    return s;
}

template <bool Fma>
[[gnu::always_inline]] inline std::optional<Point2> double_word_stage(
    const Differences& t) noexcept {
    const Word bx = t.bx, by = t.by, cx = t.cx, cy = t.cy;
    Frame f;
    f.d = add(mul<Fma>(bx, cy), neg(mul<Fma>(by, cx)));
    f.td = std::fabs(bx.hi * cy.hi) + std::fabs(by.hi * cx.hi);
    f.d_error = bounds::circumcenter_rel * f.td;
    if (!(std::fabs(f.d.hi) > 2.0 * f.d_error)) return std::nullopt;  // near-collinear
    const Word bb = add(mul<Fma>(bx, bx), mul<Fma>(by, by)),
               cc = add(mul<Fma>(cx, cx), mul<Fma>(cy, cy));
    f.nx = add(mul<Fma>(cy, bb), neg(mul<Fma>(by, cc)));
    f.ny = add(mul<Fma>(bx, cc), neg(mul<Fma>(cx, bb)));
    f.tnx = std::fabs(cy.hi) * bb.hi + std::fabs(by.hi) * cc.hi;
    f.tny = std::fabs(bx.hi) * cc.hi + std::fabs(cx.hi) * bb.hi;

    const std::optional<double> x = coordinate<Fma>(t.a.x, f.nx, f.tnx, f);
    if (!x) return std::nullopt;
    const std::optional<double> y = coordinate<Fma>(t.a.y, f.ny, f.tny, f);
    if (!y) return std::nullopt;
    return Point2{*x, *y};
}

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__FMA__)
[[gnu::target("fma")]] std::optional<Point2> double_word_stage_fma(const Differences& t) noexcept {
    return double_word_stage<true>(t);
}
#endif

/// Stage 2 with the processor's fused multiply-add when it has one (the result is the
/// same: both Two-Products are exact).
std::optional<Point2> double_word(const Differences& t) noexcept {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    return double_word_stage<true>(t);
#else
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
    if (detail::dw::use_fma()) return double_word_stage_fma(t);
#endif
    return double_word_stage<false>(t);
#endif
}

// ---- stage 3: exact integers ----------------------------------------------------------------

/// An mpz_t that frees itself.
class Int {
public:
    Int() { mpz_init(v_); }
    explicit Int(long value) { mpz_init_set_si(v_, value); }
    Int(const Int&) = delete;
    Int& operator=(const Int&) = delete;
    ~Int() { mpz_clear(v_); }
    mpz_ptr get() noexcept { return v_; }
    mpz_srcptr get() const noexcept { return v_; }

private:
    mpz_t v_;
};

/// Sets r to the integer v * 2^-grid (exact: v is a multiple of 2^grid).
void lift(mpz_ptr r, double v, int grid) noexcept {
    const detail::Binary64 d = detail::decode(v);
    mpz_set_ui(r, 0);
    if (d.significand == 0) return;
    mpz_import(r, 1, -1, sizeof d.significand, 0, 0, &d.significand);
    mpz_mul_2exp(r, r, static_cast<mp_bitcnt_t>(d.exponent - grid));
    if (d.negative) mpz_neg(r, r);
}

/// The exponent of the last significand bit shared by every value: each is an integer
/// multiple of 2^grid, the smallest exponent among the nonzero ones (0 when all are zero).
int common_grid(std::initializer_list<double> values) noexcept {
    int grid = 1 << 20;
    for (double v : values) {
        const detail::Binary64 d = detail::decode(v);
        if (d.significand != 0) grid = std::min(grid, d.exponent);
    }
    return grid == (1 << 20) ? 0 : grid;
}

/// num / den * 2^exp2 (den > 0) rounded to nearest, ties to even, with gradual underflow
/// and overflow to infinity: the rounding IEEE 754 prescribes for the exact value.
double round_quotient(mpz_srcptr num, mpz_srcptr den, long exp2) noexcept {
    if (mpz_sgn(num) == 0) return 0.0;
    Int n, q, r, dd;
    mpz_abs(n.get(), num);
    // |value| is in [2^(L-1), 2^(L+1)) with L = bits(n) - bits(den) + exp2.
    const long L = static_cast<long>(mpz_sizeinbase(n.get(), 2)) -
                   static_cast<long>(mpz_sizeinbase(den, 2)) + exp2;
    if (L > 1100)
        return mpz_sgn(num) < 0 ? -std::numeric_limits<double>::infinity()
                                : std::numeric_limits<double>::infinity();
    long quantum = std::max(L - 53, -1074L);  // the value's last significand bit
    for (;;) {
        // q = floor(n * 2^(exp2 - quantum) / den), r the remainder's numerator over dd.
        const long shift = exp2 - quantum;
        if (shift >= 0) {
            mpz_mul_2exp(q.get(), n.get(), static_cast<mp_bitcnt_t>(shift));
            mpz_set(dd.get(), den);
        } else {
            mpz_set(q.get(), n.get());
            mpz_mul_2exp(dd.get(), den, static_cast<mp_bitcnt_t>(-shift));
        }
        mpz_fdiv_qr(q.get(), r.get(), q.get(), dd.get());
        if (mpz_sizeinbase(q.get(), 2) <= 53) break;
        // The value was in the upper binade: one bit too many. (Also from the clamp at
        // -1074: a value in [2^-1021, 2^-1020) is normal, its last bit is 2^-1073.)
        ++quantum;
    }
    // Round: up when the remainder is above half, or exactly half and q is odd.
    mpz_mul_2exp(r.get(), r.get(), 1);
    const int cmp = mpz_cmp(r.get(), dd.get());
    if (cmp > 0 || (cmp == 0 && mpz_odd_p(q.get()))) mpz_add_ui(q.get(), q.get(), 1);
    // q <= 2^53 is a double exactly; q * 2^quantum is exact unless it overflows.
    const double magnitude = std::ldexp(mpz_get_d(q.get()), static_cast<int>(quantum));
    return mpz_sgn(num) < 0 ? -magnitude : magnitude;
}

}  // namespace

Circumcenter circumcenter_exact(Point2 a, Point2 b, Point2 c) noexcept {
    if (!finite(a) || !finite(b) || !finite(c))
        return {{nan, nan}, CircumcenterStatus::non_finite_input, CircumcenterStage::exact};
    const int grid = common_grid({a.x, a.y, b.x, b.y, c.x, c.y});
    Int ax, ay, bx, by, cx, cy;
    lift(ax.get(), a.x, grid);
    lift(ay.get(), a.y, grid);
    lift(bx.get(), b.x, grid);
    lift(by.get(), b.y, grid);
    lift(cx.get(), c.x, grid);
    lift(cy.get(), c.y, grid);
    mpz_sub(bx.get(), bx.get(), ax.get());
    mpz_sub(by.get(), by.get(), ay.get());
    mpz_sub(cx.get(), cx.get(), ax.get());
    mpz_sub(cy.get(), cy.get(), ay.get());
    // D = bx cy - by cx; the centre is a + (Nx, Ny) / (2 D) with
    // Nx = cy |b|^2 - by |c|^2 and Ny = bx |c|^2 - cx |b|^2 (b, c relative to a).
    Int d, t, bb, cc, n;
    mpz_mul(d.get(), bx.get(), cy.get());
    mpz_mul(t.get(), by.get(), cx.get());
    mpz_sub(d.get(), d.get(), t.get());
    if (mpz_sgn(d.get()) == 0)
        return {{nan, nan}, CircumcenterStatus::collinear, CircumcenterStage::exact};
    mpz_mul(bb.get(), bx.get(), bx.get());
    mpz_addmul(bb.get(), by.get(), by.get());
    mpz_mul(cc.get(), cx.get(), cx.get());
    mpz_addmul(cc.get(), cy.get(), cy.get());
    // Numerator over the positive denominator 2|D|: 2 D a + N, its sign flipped with D's.
    const bool flip = mpz_sgn(d.get()) < 0;
    Int den;
    mpz_mul_2exp(den.get(), d.get(), 1);
    mpz_abs(den.get(), den.get());
    const auto coordinate = [&](mpz_srcptr base, mpz_srcptr f1, mpz_srcptr s1, mpz_srcptr f2,
                                mpz_srcptr s2) {
        // n = f1 s1 - f2 s2 + 2 D base
        mpz_mul(n.get(), f1, s1);
        mpz_submul(n.get(), f2, s2);
        mpz_mul(t.get(), d.get(), base);
        mpz_addmul_ui(n.get(), t.get(), 2);
        if (flip) mpz_neg(n.get(), n.get());
        return round_quotient(n.get(), den.get(), grid);
    };
    const double x = coordinate(ax.get(), cy.get(), bb.get(), by.get(), cc.get());
    const double y = coordinate(ay.get(), bx.get(), cc.get(), cx.get(), bb.get());
    return classify({x, y});
}

std::string_view to_string(IntersectionStatus status) noexcept {
    switch (status) {
        case IntersectionStatus::ok: return "ok";
        case IntersectionStatus::parallel: return "parallel";
        case IntersectionStatus::overflow: return "overflow";
        case IntersectionStatus::non_finite_input: return "non_finite_input";
    }
    return "unknown";
}

Intersection intersection(Point2 a, Point2 b, Point2 c, Point2 d) noexcept {
    if (!finite(a) || !finite(b) || !finite(c) || !finite(d))
        return {{nan, nan}, IntersectionStatus::non_finite_input};
    const int grid = common_grid({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y});
    Int ax, ay, ux, uy, vx, vy, wx, wy;
    lift(ax.get(), a.x, grid);
    lift(ay.get(), a.y, grid);
    lift(ux.get(), b.x, grid);
    lift(uy.get(), b.y, grid);
    lift(vx.get(), d.x, grid);
    lift(vy.get(), d.y, grid);
    lift(wx.get(), c.x, grid);
    lift(wy.get(), c.y, grid);
    // u = b - a, v = d - c, w = c - a.
    mpz_sub(ux.get(), ux.get(), ax.get());
    mpz_sub(uy.get(), uy.get(), ay.get());
    mpz_sub(vx.get(), vx.get(), wx.get());
    mpz_sub(vy.get(), vy.get(), wy.get());
    mpz_sub(wx.get(), wx.get(), ax.get());
    mpz_sub(wy.get(), wy.get(), ay.get());
    // D = u x v, N = w x v; the point is a + (N / D) u = (D a + N u) / D.
    Int den, num, t, n;
    mpz_mul(den.get(), ux.get(), vy.get());
    mpz_submul(den.get(), uy.get(), vx.get());
    if (mpz_sgn(den.get()) == 0) return {{nan, nan}, IntersectionStatus::parallel};
    mpz_mul(num.get(), wx.get(), vy.get());
    mpz_submul(num.get(), wy.get(), vx.get());
    const bool flip = mpz_sgn(den.get()) < 0;
    const auto coordinate = [&](mpz_srcptr base, mpz_srcptr direction) {
        mpz_mul(n.get(), den.get(), base);
        mpz_addmul(n.get(), num.get(), direction);
        if (flip) mpz_neg(n.get(), n.get());
        mpz_abs(t.get(), den.get());
        return round_quotient(n.get(), t.get(), grid);
    };
    const Point2 p{coordinate(ax.get(), ux.get()), coordinate(ay.get(), uy.get())};
    const bool overflow = std::isinf(p.x) || std::isinf(p.y);
    return {p, overflow ? IntersectionStatus::overflow : IntersectionStatus::ok};
}

Sign compare_segment_distance(Point2 p, Point2 a, Point2 b, double r) noexcept {
    if (!finite(p) || !finite(a) || !finite(b) || !std::isfinite(r) || r < 0) return Sign::positive;
    const int grid = common_grid({p.x, p.y, a.x, a.y, b.x, b.y, r});
    Int ax, ay, dx, dy, wx, wy, rr;
    lift(ax.get(), a.x, grid);
    lift(ay.get(), a.y, grid);
    lift(dx.get(), b.x, grid);
    lift(dy.get(), b.y, grid);
    lift(wx.get(), p.x, grid);
    lift(wy.get(), p.y, grid);
    lift(rr.get(), r, grid);
    // d = b - a, w = p - a.
    mpz_sub(dx.get(), dx.get(), ax.get());
    mpz_sub(dy.get(), dy.get(), ay.get());
    mpz_sub(wx.get(), wx.get(), ax.get());
    mpz_sub(wy.get(), wy.get(), ay.get());
    Int dot, dd, lhs, rhs;
    mpz_mul(dot.get(), wx.get(), dx.get());
    mpz_addmul(dot.get(), wy.get(), dy.get());
    mpz_mul(dd.get(), dx.get(), dx.get());
    mpz_addmul(dd.get(), dy.get(), dy.get());
    mpz_mul(rhs.get(), rr.get(), rr.get());  // r^2
    if (mpz_sgn(dot.get()) <= 0 || mpz_sgn(dd.get()) == 0) {
        // Nearest to a: |w|^2 against r^2.
        mpz_mul(lhs.get(), wx.get(), wx.get());
        mpz_addmul(lhs.get(), wy.get(), wy.get());
    } else if (mpz_cmp(dot.get(), dd.get()) >= 0) {
        // Nearest to b: |w - d|^2 against r^2.
        mpz_sub(wx.get(), wx.get(), dx.get());
        mpz_sub(wy.get(), wy.get(), dy.get());
        mpz_mul(lhs.get(), wx.get(), wx.get());
        mpz_addmul(lhs.get(), wy.get(), wy.get());
    } else {
        // Nearest to the line: (w x d)^2 / |d|^2 against r^2, times |d|^2 > 0.
        mpz_mul(lhs.get(), wx.get(), dy.get());
        mpz_submul(lhs.get(), wy.get(), dx.get());
        mpz_mul(lhs.get(), lhs.get(), lhs.get());
        mpz_mul(rhs.get(), rhs.get(), dd.get());
    }
    const int c = mpz_cmp(lhs.get(), rhs.get());
    return c > 0 ? Sign::positive : c < 0 ? Sign::negative : Sign::zero;
}

namespace {
inline Circumcenter decide(Point2 a, Point2 b, Point2 c) noexcept {
    if (!finite(a) || !finite(b) || !finite(c))
        return {{nan, nan}, CircumcenterStatus::non_finite_input, CircumcenterStage::exact};
    if (const std::optional<Differences> t = differences(a, b, c)) {
        if (const std::optional<Point2> p = float_stage(*t))
            return {*p, CircumcenterStatus::ok, CircumcenterStage::floating};
        if (const std::optional<Point2> p = double_word(*t))
            return {*p, CircumcenterStatus::ok, CircumcenterStage::double_word};
    }
    return circumcenter_exact(a, b, c);
}

}  // namespace

Circumcenter circumcenter(Point2 a, Point2 b, Point2 c) noexcept { return decide(a, b, c); }

double round_quotient(std::span<const std::uint64_t> num, std::span<const std::uint64_t> den,
                      bool negative, long exp2) noexcept {
    Int n, d;
    mpz_import(n.get(), num.size(), -1, sizeof(std::uint64_t), 0, 0, num.data());
    mpz_import(d.get(), den.size(), -1, sizeof(std::uint64_t), 0, 0, den.data());
    if (mpz_sgn(d.get()) == 0) return nan;
    if (negative) mpz_neg(n.get(), n.get());
    return round_quotient(n.get(), d.get(), exp2);
}

void circumcenters(std::span<const Point2> points, std::span<const std::uint32_t> triangles,
                   std::span<Circumcenter> out, std::uint64_t* stage_counts) noexcept {
    const std::size_t n = std::min(out.size(), triangles.size() / 3);
    std::uint64_t counts[3] = {0, 0, 0};
    // A triangulation's vertex indices are input indices, in no spatial order: each
    // triangle's three points are a random gather. Fetching them a few triangles ahead
    // overlaps the cache misses with the arithmetic.
    constexpr std::size_t ahead = 8;
    for (std::size_t t = 0; t < n; ++t) {
        if (t + ahead < n) {
            for (int k = 0; k < 3; ++k) __builtin_prefetch(&points[triangles[3 * (t + ahead) + k]]);
        }
        out[t] = decide(points[triangles[3 * t]], points[triangles[3 * t + 1]],
                        points[triangles[3 * t + 2]]);
        ++counts[static_cast<int>(out[t].stage)];
    }
    if (stage_counts != nullptr)
        for (int i = 0; i < 3; ++i) stage_counts[i] = counts[i];
}

}  // namespace exidel
