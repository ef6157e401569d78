// exidel tests: the kernels that claim exactness, as one type list for typed tests
// (one test body, every kernel).
#pragma once

#include <array>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

#include "exidel/predicates/all.hpp"
#include "exidel/testing/ulp.hpp"

namespace exidel::test {

/// MpfrKernel at exactly the precision proofs/bitcounts.md says makes each formula exact for
/// this query: 2b+3 bits for orient2d, 4b+8 for incircle, 8b+12 for incircle_cosine,
/// with b = 53 + the exponent spread of the query's own coordinates (grid_bits).
/// Computing b per query, rather than one fixed worst case (8 * (53 + 2097) + 13 =
/// 17213 bits covers every pair of finite doubles), tests the bound itself at its
/// tightest: one bit fewer than claimed and a counterexample can exist.
struct MpfrAtBound {
    static constexpr bool is_exact = true;  // the claim under test
    static std::string name() { return "mpfr-at-bound"; }
    static Sign orient2d(Point2 a, Point2 b, Point2 c) {
        const std::array q{a, b, c};
        return MpfrKernel(testing::orient2d_bits(testing::grid_bits(q))).orient2d(a, b, c);
    }
    static Sign incircle(Point2 a, Point2 b, Point2 c, Point2 d) {
        const std::array q{a, b, c, d};
        return MpfrKernel(testing::incircle_bits(testing::grid_bits(q))).incircle(a, b, c, d);
    }
    static Sign incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) {
        const std::array q{a, b, c, d};
        return MpfrKernel(testing::incircle_cosine_bits(testing::grid_bits(q)))
            .incircle_cosine(a, b, c, d);
    }
    // Degree 2 like orient2d: 2b+3 bits (proofs/bitcounts.md).
    static Sign compare_distance(Point2 c, Point2 p, Point2 q) {
        const std::array pts{c, p, q};
        return MpfrKernel(testing::orient2d_bits(testing::grid_bits(pts)))
            .compare_distance(c, p, q);
    }
    // The predicates of space: 3b+6 and 5b+12 bits (proofs/bitcounts.md).
    static Sign orient3d(Point3 a, Point3 b, Point3 c, Point3 d) {
        const std::array q{a, b, c, d};
        return MpfrKernel(testing::orient3d_bits(testing::grid_bits(q))).orient3d(a, b, c, d);
    }
    static Sign insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e) {
        const std::array q{a, b, c, d, e};
        return MpfrKernel(testing::insphere_bits(testing::grid_bits(q))).insphere(a, b, c, d, e);
    }
};
static_assert(PredicateKernel3D<MpfrAtBound>);

using ExactKernels =
    ::testing::Types<GmpExactKernel, CppIntExactKernel, MpfrAtBound, AdaptiveKernel>;

/// Every kernel of the registry (exidel/predicates/registry.hpp) that claims exactness
/// runs the exact-kernel tests: adding one there without adding it here fails to compile.
template <class K, class... Ts>
constexpr bool listed(::testing::Types<Ts...>*) {
    return (std::is_same_v<K, Ts> || ...);
}
#define EXIDEL_EXACT_KERNEL_IS_TESTED_(K, spelling, summary)                      \
    static_assert(!K::is_exact || listed<K>(static_cast<ExactKernels*>(nullptr)), \
                  "add " #K " to ExactKernels: it claims exactness");
EXIDEL_KERNELS(EXIDEL_EXACT_KERNEL_IS_TESTED_)
#undef EXIDEL_EXACT_KERNEL_IS_TESTED_

/// Names the typed-test instances after the kernel ("exact", "adaptive", ...).
struct KernelName {
    template <class K>
    static std::string GetName(int) {
        std::string n = K::name();
        for (char& ch : n) {
            if (ch == '-' || ch == ':') ch = '_';
        }
        return n;
    }
};

}  // namespace exidel::test
