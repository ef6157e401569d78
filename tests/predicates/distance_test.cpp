// compare_distance(c, p, q) of every kernel that claims exactness against CGAL's
// compare_distance_to_point, on every shared family and on exact, rounded and
// ulp-perturbed ties; and where the adaptive kernel decides them (ties on grids must not
// reach GMP: a radial sort of a grid meets them all the time).
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "distance_queries.hpp"
#include "exidel/predicates/staged.hpp"
#include "exidel/testing/all.hpp"
#include "kernels_under_test.hpp"

namespace exidel::test {
namespace {

template <class K>
class DistanceVsCgal : public ::testing::Test {};
TYPED_TEST_SUITE(DistanceVsCgal, ExactKernels, KernelName);

TYPED_TEST(DistanceVsCgal, MatchesCgalOnEveryFamily) {
    for (const testing::FamilyInfo& f : testing::all_families()) {
        const bool ok = rc::check(
            TypeParam::name() + " compare_distance == CGAL on " + std::string(f.name), [&] {
                const auto [c, p, q] = *testing::gen_query3(f.family);
                RC_ASSERT(TypeParam{}.compare_distance(c, p, q) == cgal_compare_distance(c, p, q));
            });
        EXPECT_TRUE(ok) << "failed on family " << f.name;
    }
}

TYPED_TEST(DistanceVsCgal, ExactTiesAreZero) {
    EXPECT_TRUE(rc::check(TypeParam::name() + " exact ties", [] {
        const auto [c, p, q] = *gen_exact_tie();
        RC_ASSERT(cgal_compare_distance(c, p, q) == Sign::zero);  // the generator's claim
        RC_ASSERT(TypeParam{}.compare_distance(c, p, q) == Sign::zero);
    }));
}

TYPED_TEST(DistanceVsCgal, MatchesCgalOnRoundedTies) {
    EXPECT_TRUE(rc::check(TypeParam::name() + " rounded ties", [] {
        const auto [c, p, q] = *gen_rounded_tie();
        RC_ASSERT(TypeParam{}.compare_distance(c, p, q) == cgal_compare_distance(c, p, q));
    }));
}

TYPED_TEST(DistanceVsCgal, MatchesCgalOnNudgedTies) {
    EXPECT_TRUE(rc::check(TypeParam::name() + " ulp-perturbed ties", [] {
        const auto [c, p, q] = *gen_nudged_tie();
        RC_ASSERT(TypeParam{}.compare_distance(c, p, q) == cgal_compare_distance(c, p, q));
    }));
}

// ---- The adaptive kernel's stages -------------------------------------------------------

// Found by ExactTiesOnGridsEndInStageB (now ...EndInTheSmallIntegerStage) with the test's
// first range limit (2^-500): a tie at 2^-486 is below the expansion range
// (2 (-486 - 52) < -1074), and was decided by GMP, correctly. Since the small-integer stage
// (exact differences in a 62-bit window, 128-bit integers) it is decided there at every
// scale, before the expansion range matters.
TEST(DistanceStages, TieAtTheLowerEdgeOfTheExpansionRange) {
    AdaptiveStage stage{};
    EXPECT_EQ(compare_distance_staged({0, 0}, {0, 0x1p-486}, {0x1p-486, 0}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    EXPECT_EQ(compare_distance_staged({0, 0}, {0, 0x1p-485}, {0x1p-485, 0}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
}

TEST(DistanceStages, ExactTiesOnGridsEndInTheSmallIntegerStage) {
    EXPECT_TRUE(rc::check("grid ties decided from exact differences", [] {
        const DistanceQuery q = *gen_exact_tie();
        AdaptiveStage stage{};
        RC_ASSERT(compare_distance_staged(q[0], q[1], q[2], stage) == Sign::zero);
        RC_ASSERT(stage == AdaptiveStage::small_integer);
    }));
}

TEST(DistanceStages, RoundedTiesNeverReachGmp) {
    EXPECT_TRUE(rc::check("rounded ties stay in the expansion stages", [] {
        const DistanceQuery q = *gen_rounded_tie();
        AdaptiveStage stage{};
        const Sign s = compare_distance_staged(q[0], q[1], q[2], stage);
        RC_ASSERT(s == cgal_compare_distance(q[0], q[1], q[2]));
        RC_ASSERT(stage != AdaptiveStage::gmp);
    }));
}

TEST(DistanceStages, EachStageIsReached) {
    AdaptiveStage stage{};
    // Far apart: the filter.
    EXPECT_EQ(compare_distance_staged({0, 0}, {3, 0}, {1, 1}, stage), Sign::positive);
    EXPECT_EQ(stage, AdaptiveStage::filter);
    // Ties with exact differences: the small-integer stage, squares exact or not
    // ((2^30 + 1)^2 needs 61 bits).
    EXPECT_EQ(compare_distance_staged({1, 2}, {4, 6}, {6, 2}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    const double big = 0x1p30 + 1;
    EXPECT_EQ(compare_distance_staged({0, 0}, {big, 0}, {0, -big}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    // Exact differences beyond the 62-bit window (2^60 + 1 next to 2^-10): stage B.
    EXPECT_EQ(compare_distance_staged({0, 0}, {0x1p60, 0x1p-10}, {0x1p-10, 0x1p60}, stage),
              Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::stage_b);
    // Differences that round: 1 - 2^-60 is not a double; p is 2^-60 closer than q.
    EXPECT_EQ(compare_distance_staged({0x1p-60, 0}, {1, 0}, {0, 1}, stage), Sign::negative);
    EXPECT_EQ(stage, AdaptiveStage::exact);
    // Beyond the expansion range, differences that round: GMP. |p - c|^2 = 1e600 - 1e300 +
    // 1/4 and |q - c|^2 = 1e600 + 1/4 (exactly, in the doubles these decimals round to).
    EXPECT_EQ(compare_distance_staged({0.5, 0}, {1e300, 0}, {0, -1e300}, stage),
              cgal_compare_distance({0.5, 0}, {1e300, 0}, {0, -1e300}));
    EXPECT_EQ(stage, AdaptiveStage::gmp);
}

}  // namespace
}  // namespace exidel::test
