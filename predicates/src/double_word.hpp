// exidel (private): double-word arithmetic, shared by the circumcentre's stage 2
// (construct.cpp) and the adaptive kernel's double-word stage (adaptive.cpp).
//
// A value is hi + lo with |lo| <= eps |hi| (lo is hi's rounding error). Two-Sum and
// Two-Product are exact; the sum and product below err by at most (3 + O(eps)) eps^2
// (|x| + |y|) and (8 + O(eps)) eps^2 |x| |y| (proofs/bounds.md#circumcenter, lemma DW). They
// are the classical "sloppy" sum and the product of Joldes, Muller and Popescu 2017, "Tight
// and rigorous error bounds for basic building blocks of double-word arithmetic", ACM TOMS
// 44(2): the sum has no bound relative to its result, which is why the proofs bound every
// error against the operands' magnitudes (permanents) instead.
//
// Compiled only in the library's own translation units, with -ffp-contract=off: Dekker's
// split and Two-Sum are exact only when no operation is contracted.
#pragma once

namespace exidel::detail::dw {

struct Word {
    double hi;
    double lo;
};

/// a + b exactly (Knuth's Two-Sum: no ordering needed), when nothing overflows.
[[gnu::always_inline]] inline Word two_sum(double a, double b) noexcept {
    const double s = a + b;
    const double bv = s - a;
    return {s, (a - (s - bv)) + (b - bv)};
}

/// a + b when a is zero or |a| >= |b| (Dekker's Fast-Two-Sum): exact.
[[gnu::always_inline]] inline Word fast_two_sum(double a, double b) noexcept {
    const double s = a + b;
    return {s, b - (s - a)};
}

/// a * b exactly (no under- or overflow: bounds.md#circumcenter, "Two-Product"). With a
/// fused multiply-add the error term is one instruction (Fma); without one, Dekker's
/// split. (On the x86-64 baseline std::fma is a library call costing more than the split,
/// so the FMA version is compiled separately for processors that have one; see
/// use_fma() below.)
template <bool Fma>
[[gnu::always_inline]] inline Word two_product(double a, double b) noexcept {
    const double p = a * b;
    if constexpr (Fma) {
        return {p, __builtin_fma(a, b, -p)};
    } else {
        constexpr double splitter = 134217729.0;  // 2^27 + 1
        const double ca = splitter * a, cb = splitter * b;
        const double ah = ca - (ca - a), bh = cb - (cb - b);
        const double al = a - ah, bl = b - bh;
        return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
    }
}

[[gnu::always_inline]] inline Word add(Word x, Word y) noexcept {
    const Word s = two_sum(x.hi, y.hi);
    const double v = s.lo + (x.lo + y.lo);
    return two_sum(s.hi, v);
}

[[gnu::always_inline]] inline Word neg(Word x) noexcept { return {-x.hi, -x.lo}; }

template <bool Fma>
[[gnu::always_inline]] inline Word mul(Word x, Word y) noexcept {
    const Word p = two_product<Fma>(x.hi, y.hi);
    const double c = x.hi * y.lo + x.lo * y.hi;
    return fast_two_sum(p.hi, p.lo + c);
}

/// Whether the double-word stages use the processor's fused multiply-add (detected once)
/// or Dekker's split. Both Two-Products are exact, so the results are identical; tests
/// flip it to run both.
inline bool& use_fma() noexcept {
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
    static bool use = true;
#elif (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
    static bool use = (__builtin_cpu_init(), __builtin_cpu_supports("fma") != 0);
#else
    static bool use = false;
#endif
    return use;
}

}  // namespace exidel::detail::dw
