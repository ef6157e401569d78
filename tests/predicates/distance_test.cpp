// compare_distance(c, p, q) of every kernel that claims exactness against CGAL's
// compare_distance_to_point, on every shared family and on exact, rounded and
// ulp-perturbed ties; and where the adaptive kernel decides them (ties on grids must not
// reach GMP: a radial sort of a grid meets them all the time).
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "distance_queries.hpp"
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

bool in_expansion_range(const DistanceQuery& q) {
    // Inside expansion_safe's degree-2 range: every nonzero |v| < 2^501, and its grid
    // 2^(ilogb(v) - 52) at least 2^-537 (so the products' grid 2^-1074 is representable),
    // i.e. |v| >= 2^-485. (The first version said 2^-500: the fixture below.)
    for (const Point2& pt : q) {
        for (double v : {pt.x, pt.y}) {
            if (v != 0 && (std::fabs(v) < 0x1p-485 || std::fabs(v) >= 0x1p501)) return false;
        }
    }
    return true;
}

// Found by ExactTiesOnGridsEndInStageB with the test's first range limit (2^-500): a tie
// at 2^-486 is below the expansion range (2 (-486 - 52) < -1074) and is decided by GMP,
// correctly; one binade up, the expansions decide it.
TEST(DistanceStages, TieAtTheLowerEdgeOfTheExpansionRange) {
    AdaptiveStage stage{};
    EXPECT_EQ(compare_distance_staged({0, 0}, {0, 0x1p-486}, {0x1p-486, 0}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::gmp);
    EXPECT_EQ(compare_distance_staged({0, 0}, {0, 0x1p-485}, {0x1p-485, 0}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::stage_b);
}

TEST(DistanceStages, ExactTiesOnGridsEndInStageB) {
    EXPECT_TRUE(rc::check("grid ties decided from exact differences", [] {
        const DistanceQuery q = *gen_exact_tie();
        RC_PRE(in_expansion_range(q));
        AdaptiveStage stage{};
        RC_ASSERT(compare_distance_staged(q[0], q[1], q[2], stage) == Sign::zero);
        RC_ASSERT(stage == AdaptiveStage::stage_b);
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
    // A tie with exact differences and exact squares.
    EXPECT_EQ(compare_distance_staged({1, 2}, {4, 6}, {6, 2}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::stage_b);
    // A tie whose squares are not doubles: (2^30 + 1)^2 needs 61 bits.
    const double big = 0x1p30 + 1;
    EXPECT_EQ(compare_distance_staged({0, 0}, {big, 0}, {0, -big}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::stage_b);
    // Differences that round: 1 - 2^-60 is not a double; p is 2^-60 closer than q.
    EXPECT_EQ(compare_distance_staged({0x1p-60, 0}, {1, 0}, {0, 1}, stage), Sign::negative);
    EXPECT_EQ(stage, AdaptiveStage::exact);
    // Beyond the expansion range: GMP.
    EXPECT_EQ(compare_distance_staged({0, 0}, {1e300, 0}, {0, -1e300}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::gmp);
}

}  // namespace
}  // namespace exidel::test
