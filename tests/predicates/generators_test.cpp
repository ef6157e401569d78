// The generators build what they promise: exact structure where it is claimed, and
// shrinking that ends at the exactly degenerate configuration. Checked with CGAL.
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "cgal_oracle.hpp"
#include "exidel/testing/all.hpp"

namespace exidel::test {
namespace {

using testing::Family;

TEST(Lattice, EveryPointIsOnTheCircleAndTheCountIsFourTimesThreeToThePrimes) {
    std::int64_t expected = 4;
    for (int primes = 1; primes <= testing::lattice_prime_count; ++primes) {
        expected *= 3;
        const std::int64_t r = testing::lattice_circle_radius(primes);
        const auto points = testing::lattice_circle_points(primes);
        EXPECT_EQ(std::int64_t(points.size()), expected) << "primes=" << primes;
        for (const auto& [x, y] : points) ASSERT_EQ(x * x + y * y, r * r);
    }
    EXPECT_THROW(testing::lattice_circle_radius(0), std::invalid_argument);
    EXPECT_THROW(testing::lattice_circle_radius(7), std::invalid_argument);
}

TEST(Families, NamesAreUniqueAndRoundTrip) {
    std::set<std::string_view> names;
    for (const auto& f : testing::all_families()) {
        EXPECT_TRUE(names.insert(f.name).second) << f.name;
        EXPECT_EQ(testing::family_from_name(f.name), f.family);
        EXPECT_EQ(testing::family_name(f.family), f.name);
    }
    EXPECT_THROW(testing::family_from_name("no-such-family"), std::invalid_argument);
}

TEST(Nudge, StepsAreUlpsAndStopAtTheFiniteRange) {
    EXPECT_EQ(testing::nudge(1.0, 1), 1 + 0x1p-52);
    EXPECT_EQ(testing::nudge(1.0, -1), 1 - 0x1p-53);
    EXPECT_EQ(testing::nudge(0.0, 2), 0x1p-1073);
    EXPECT_EQ(testing::nudge(0x1.fffffffffffffp+1023, 3), 0x1.fffffffffffffp+1023);
    EXPECT_EQ(testing::grid_bits(std::array<Point2, 2>{{{1, 0}, {0x1p-10, 0}}}), 63);
}

RC_GTEST_PROP(Families, LatticeCircleQueriesAreExactlyCocircular, ()) {
    const auto [a, b, c, d] = *testing::gen_query4(Family::lattice_circle);
    RC_ASSERT(cgal_incircle(a, b, c, d) == Sign::zero);
}

RC_GTEST_PROP(Families, DyadicLineQueriesAreExactlyCollinear, ()) {
    const auto [a, b, c] = *testing::gen_query3(Family::dyadic_line);
    RC_ASSERT(cgal_orient2d(a, b, c) == Sign::zero);
}

RC_GTEST_PROP(Families, DuplicateQueriesRepeatAPoint, ()) {
    const auto q = *testing::gen_query4(Family::duplicates);
    const std::set<std::pair<double, double>> distinct{
        {q[0].x, q[0].y}, {q[1].x, q[1].y}, {q[2].x, q[2].y}, {q[3].x, q[3].y}};
    RC_ASSERT(distinct.size() < 4u);
}

RC_GTEST_PROP(Families, EveryCoordinateIsFinite, ()) {
    for (const auto& f : testing::all_families()) {
        for (const Point2& p : *testing::gen_points(f.family, 5)) {
            RC_ASSERT(std::isfinite(p.x) && std::isfinite(p.y));
        }
    }
}

// Follows the first shrink of every step down to a value with no shrinks left.
template <class T>
T fully_shrunk(const rc::Gen<T>& gen, std::uint64_t seed) {
    auto s = gen(rc::Random(seed));
    for (int steps = 0; steps < 100000; ++steps) {
        auto next = s.shrinks().next();
        if (!next) break;
        s = std::move(*next);
    }
    return s.value();
}

TEST(Shrinking, NearFamiliesShrinkToTheDegenerateConfiguration) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const auto [a, b, c] = fully_shrunk(testing::gen_query3(Family::near_dyadic_line), seed);
        EXPECT_EQ(cgal_orient2d(a, b, c), Sign::zero) << "seed " << seed;
        const auto [p, q, r] = fully_shrunk(testing::gen_query3(Family::kettner), seed);
        EXPECT_EQ(cgal_orient2d(p, q, r), Sign::zero) << "seed " << seed;
        const auto [e, f, g, h] =
            fully_shrunk(testing::gen_query4(Family::near_lattice_circle), seed);
        EXPECT_EQ(cgal_incircle(e, f, g, h), Sign::zero) << "seed " << seed;
        const auto [i, j, k, l] =
            fully_shrunk(testing::gen_query4(Family::near_integer_grid), seed);
        EXPECT_EQ(cgal_incircle(i, j, k, l), Sign::zero) << "seed " << seed;
    }
}

TEST(Cosine, ArrangementFindsASeparatingPairForFourPointsInGeneralPosition) {
    // Convex position (a square) and one point inside a triangle.
    for (const testing::Query4& q : {testing::Query4{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
                                     testing::Query4{{{0, 0}, {4, 0}, {0, 4}, {1, 1}}}}) {
        const auto r = testing::arrange_for_cosine(q);
        EXPECT_TRUE(cgal_cosine_precondition(r[0], r[1], r[2], r[3]));
    }
}

}  // namespace
}  // namespace exidel::test
