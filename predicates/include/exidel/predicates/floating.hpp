// exidel: the plain floating-point kernel, the textbook formulas and nothing else.
//
// This is the kernel research compares against: it is meant to be wrong near degeneracy.
// The formulas are compiled in the library's own translation unit (with
// -ffp-contract=off), so its answers do not depend on the caller's compiler flags and the
// failures it shows are the failures of the formula, not of a fused multiply-add.
#pragma once

#include <string>

#include "exidel/predicates/kernel.hpp"

namespace exidel {

/// Plain kernel over the number type T. Instantiated in the library for `double` and
/// `long double` (on x86-64, the 64-bit-mantissa x87 format).
template <class T>
struct FloatingKernel {
    static constexpr bool is_exact = false;
    static std::string name();
    static Sign orient2d(Point2 a, Point2 b, Point2 c) noexcept;
    static Sign incircle(Point2 a, Point2 b, Point2 c, Point2 d) noexcept;
    static Sign incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) noexcept;
    static Sign compare_distance(Point2 c, Point2 p, Point2 q) noexcept;
    static Sign orient3d(Point3 a, Point3 b, Point3 c, Point3 d) noexcept;
    static Sign insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e) noexcept;
};

extern template struct FloatingKernel<double>;
extern template struct FloatingKernel<long double>;

using DoubleKernel = FloatingKernel<double>;
using LongDoubleKernel = FloatingKernel<long double>;

static_assert(PredicateKernel<DoubleKernel>);
static_assert(PredicateKernel<LongDoubleKernel>);
static_assert(PredicateKernel3D<DoubleKernel>);
static_assert(PredicateKernel3D<LongDoubleKernel>);

}  // namespace exidel
