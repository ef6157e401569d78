// exidel: the MPFR kernel, the floating kernel's formulas at a chosen precision.
//
// The instrument for precision research: exactly the same operations, in the same order,
// as FloatingKernel, each rounded to nearest at `bits` bits of significand. Inputs are
// doubles, so every coordinate is exact at bits >= 53. For bits at or above the counts in
// proofs/bitcounts.md (2b+3 for orient2d and compare_distance, 4b+8 for incircle, 8b+12 for
// incircle_cosine, 3b+6 for orient3d, 5b+12 for insphere, b = 53 + the exponent spread of
// the query) every result equals the exact kernel's.
#pragma once

#include <string>

#include "exidel/predicates/kernel.hpp"

namespace exidel {

class MpfrKernel {
public:
    static constexpr bool is_exact = false;

    /// `bits` is the significand precision of every intermediate value, in
    /// [min_bits, max_bits]; anything else throws std::invalid_argument.
    explicit MpfrKernel(unsigned bits);

    static constexpr unsigned min_bits = 2;
    static constexpr unsigned max_bits = 1u << 20;

    unsigned bits() const noexcept { return bits_; }
    std::string name() const;  // "mpfr:<bits>"

    Sign orient2d(Point2 a, Point2 b, Point2 c) const;
    Sign incircle(Point2 a, Point2 b, Point2 c, Point2 d) const;
    Sign incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) const;
    Sign compare_distance(Point2 c, Point2 p, Point2 q) const;
    Sign orient3d(Point3 a, Point3 b, Point3 c, Point3 d) const;
    Sign insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e) const;

private:
    unsigned bits_;
};

static_assert(PredicateKernel<MpfrKernel>);
static_assert(PredicateKernel3D<MpfrKernel>);

}  // namespace exidel
