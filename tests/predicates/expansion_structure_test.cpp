// The run-time structure checks of the expansion arithmetic (predicates/src/expansion.hpp):
// the adaptive kernel reads an expansion's sign from its largest component, and trusts its
// estimate, only after these checks, because Fast-Expansion-Sum does not guarantee the
// structure Shewchuk's Theorem 13 claims (proofs/bounds.md#expansion-estimate). A white-box
// test of a private header: the values are built bit by bit with std::ldexp.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "expansion.hpp"

namespace {

using exidel::Sign;
using namespace exidel::detail;

double p2(int k) { return std::ldexp(1.0, k); }

TEST(ExpansionStructure, BitRange) {
    EXPECT_EQ(bit_range(1.0).lo, 0);
    EXPECT_EQ(bit_range(1.0).hi, 0);
    EXPECT_EQ(bit_range(-3.0).lo, 0);
    EXPECT_EQ(bit_range(-3.0).hi, 1);
    EXPECT_EQ(bit_range(0.75).lo, -2);
    EXPECT_EQ(bit_range(0.75).hi, -1);
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(bit_range(tiny).lo, -1074);
    EXPECT_EQ(bit_range(3 * tiny).hi, -1073);
    const double big = std::numeric_limits<double>::max();
    EXPECT_EQ(bit_range(big).lo, 1023 - 52);
    EXPECT_EQ(bit_range(big).hi, 1023);
}

// The counterexample to Theorem 13 (bounds.md): two strongly nonoverlapping (indeed
// nonadjacent) expansions whose Fast-Expansion-Sum is not strongly nonoverlapping: 2^-57
// is adjacent to 2^-6 - 2^-56, which is not a power of two. It is in class W.
TEST(ExpansionStructure, ShewchukTheorem13Counterexample) {
    const double e[2] = {-(p2(-4) + p2(-56)), -p2(50)};
    const double f[3] = {p2(-6) + p2(-57), p2(-4), p2(60)};
    ASSERT_TRUE(in_class_w(2, e));
    ASSERT_TRUE(in_class_w(3, f));
    double h[5];
    const int n = expansion_sum(2, e, 3, f, h);
    ASSERT_EQ(n, 3);
    EXPECT_EQ(h[0], p2(-57));
    EXPECT_EQ(h[1], p2(-6) - p2(-56));
    EXPECT_EQ(h[2], p2(60) - p2(50));
    EXPECT_TRUE(nonoverlapping(n, h));
    EXPECT_TRUE(in_class_w(n, h));
    EXPECT_EQ(checked_sign(n, h), Sign::positive);
}

TEST(ExpansionStructure, ClassWRejectsWhatLemmaEDoesNotCover) {
    const double overlapping[2] = {1.0, 1.5};
    EXPECT_FALSE(nonoverlapping(2, overlapping));
    EXPECT_FALSE(in_class_w(2, overlapping));
    // Adjacent (3 2^-58 has its highest bit at -57, just below 2^-56), the smaller not a
    // power of two.
    const double not_power[2] = {3 * p2(-58), p2(-56)};
    EXPECT_TRUE(nonoverlapping(2, not_power));
    EXPECT_FALSE(in_class_w(2, not_power));
    const double power[2] = {p2(-57), 3 * p2(-56)};  // the larger need not be one
    EXPECT_TRUE(in_class_w(2, power));
    // 2^-57 adjacent to both neighbours.
    const double chain[3] = {p2(-58), p2(-57), p2(-56)};
    EXPECT_TRUE(nonoverlapping(3, chain));
    EXPECT_FALSE(in_class_w(3, chain));
    const double gap[3] = {p2(-58), p2(-57), p2(-54)};
    EXPECT_TRUE(in_class_w(3, gap));
    EXPECT_TRUE(in_class_w(0, chain));
}

TEST(ExpansionStructure, ExactSignOfAnySum) {
    // The largest component is last and negative, but the sum is positive.
    const double misleading[3] = {p2(-60), 1.0, -1.0};
    EXPECT_FALSE(nonoverlapping(3, misleading));
    EXPECT_EQ(exact_sign_of_sum(3, misleading), Sign::positive);
    EXPECT_EQ(checked_sign(3, misleading), Sign::positive);
    const double cancel[2] = {1.0, -1.0};
    EXPECT_EQ(checked_sign(2, cancel), Sign::zero);
    const double tiny = std::numeric_limits<double>::denorm_min();
    const double subnormal[3] = {tiny, -tiny, -tiny};
    EXPECT_EQ(exact_sign_of_sum(3, subnormal), Sign::negative);
    const double wide[3] = {-p2(-1000), p2(1000), -p2(1000)};
    EXPECT_EQ(exact_sign_of_sum(3, wide), Sign::negative);
    const double with_zero[3] = {0.0, p2(-3), 0.0};
    EXPECT_EQ(exact_sign_of_sum(3, with_zero), Sign::positive);
    EXPECT_EQ(checked_sign(0, with_zero), Sign::zero);
}

}  // namespace
