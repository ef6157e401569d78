// exidel: the adaptive kernel, exact for every finite double and nearly as fast as the
// plain formulas.
//
// Shewchuk-style staging: a floating-point filter with a proven error bound decides
// almost every call; only when it cannot, progressively more exact stages (expansion
// arithmetic built from the error-free transformations Two-Sum and Two-Product with
// std::fma) take over, and the last stage is exact. Inputs whose magnitudes would make
// an intermediate product overflow or underflow skip the expansion stages and go to
// exact integers (ExactKernel<gmp>). Every error bound is in constants.hpp, each with the
// name of its proof in proofs/.
//
// All of it is compiled in the library's own translation unit with -ffp-contract=off, so
// the answers stay exact however the caller compiles their code.
#pragma once

#include <string>

#include "exidel/predicates/kernel.hpp"

namespace exidel {

struct AdaptiveKernel {
    static constexpr bool is_exact = true;
    static std::string name() { return "adaptive"; }
    static Sign orient2d(Point2 a, Point2 b, Point2 c);
    static Sign incircle(Point2 a, Point2 b, Point2 c, Point2 d);
    static Sign incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d);
    static Sign compare_distance(Point2 c, Point2 p, Point2 q);
    static Sign orient3d(Point3 a, Point3 b, Point3 c, Point3 d);
    static Sign insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e);
};

static_assert(PredicateKernel<AdaptiveKernel>);
static_assert(PredicateKernel3D<AdaptiveKernel>);

}  // namespace exidel
