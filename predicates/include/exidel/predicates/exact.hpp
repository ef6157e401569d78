// exidel: the exact reference kernel, arbitrary-precision integers.
//
// Every finite double is an integer multiple of 2^-1074, and all the predicates are
// homogeneous polynomials in coordinate differences, so scaling every coordinate of one
// query by the same power of two does not change a sign. The kernel therefore shifts the
// coordinates of a query onto a common integer grid (the "exponent-aligned integer form")
// and evaluates the same formulas as the floating kernel with exact integers: obviously
// correct, and slow.
#pragma once

#include <string>

#include "exidel/predicates/kernel.hpp"

namespace exidel {

/// Which arbitrary-precision integer type evaluates the formulas.
enum class ExactBackend {
    gmp,      ///< GMP through Boost.Multiprecision's mpz_int.
    cpp_int,  ///< Boost.Multiprecision's header-only cpp_int: no GMP needed.
};

template <ExactBackend B>
struct ExactKernel {
    static constexpr bool is_exact = true;
    static std::string name();
    static Sign orient2d(Point2 a, Point2 b, Point2 c);
    static Sign incircle(Point2 a, Point2 b, Point2 c, Point2 d);
    static Sign incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d);
    static Sign compare_distance(Point2 c, Point2 p, Point2 q);
    static Sign orient3d(Point3 a, Point3 b, Point3 c, Point3 d);
    static Sign insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e);
};

extern template struct ExactKernel<ExactBackend::gmp>;
extern template struct ExactKernel<ExactBackend::cpp_int>;

using GmpExactKernel = ExactKernel<ExactBackend::gmp>;
using CppIntExactKernel = ExactKernel<ExactBackend::cpp_int>;

static_assert(PredicateKernel<GmpExactKernel>);
static_assert(PredicateKernel<CppIntExactKernel>);
static_assert(PredicateKernel3D<GmpExactKernel>);
static_assert(PredicateKernel3D<CppIntExactKernel>);

}  // namespace exidel
