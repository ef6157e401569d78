// exidel tests: the kernels that claim exactness, as one type list for typed tests
// (one test body, every kernel).
#pragma once

#include <array>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>

#include "exidel/predicates/all.hpp"
#include "exidel/predicates/wrapper.hpp"
#include "exidel/testing/ulp.hpp"

namespace exidel::test {

/// MpfrKernel at exactly the precision proofs/bitcounts.md says makes each formula exact for
/// this query: 2b+3 bits for orient2d, 4b+8 for incircle, 8b+12 for incircle_cosine,
/// with b = 53 + the exponent spread of the query's own coordinates (grid_bits).
/// Computing b per query, rather than one fixed worst case (8 * (53 + 2097) + 13 =
/// 17213 bits covers every pair of finite doubles), tests the bound itself at its
/// tightest: one bit fewer than claimed and a counterexample can exist.
/// Every predicate of both lists goes through answer() (wrapper.hpp), with the bit count
/// of testing::exact_bits (compare_distance has degree 2 like orient2d: 2b+3 bits; the
/// predicates of space 3b+6 and 5b+12).
struct MpfrAtBound : KernelWrapper<MpfrAtBound, true> {
    static constexpr bool is_exact = true;  // the claim under test
    static std::string name() { return "mpfr-at-bound"; }
    template <class Which, class Points>
    Sign answer(Which which, const Points& points) const {
        return evaluate(MpfrKernel(testing::exact_bits(which, testing::grid_bits(points))), which,
                        points);
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
