// The adaptive kernel's stages between the filter and the expansions, tested on their own:
// every answer is CGAL's, with either exact Two-Product (fused multiply-add or Dekker's
// split), at the edges of the range each stage is proven for, and on the inputs a stage
// must not decide (exact ties whose double-word evaluation rounds).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "cgal_oracle.hpp"
#include "double_word.hpp"
#include "small_integers.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/staged.hpp"
#include "exidel/testing/all.hpp"

namespace exidel::test {
namespace {

/// Runs `body` with the double-word stages' Two-Product set to `fma`, restoring it after.
template <class Body>
void with_two_product(bool fma, Body body) {
    bool& use = detail::dw::use_fma();
    const bool saved = use;
    use = fma;
    body();
    use = saved;
}

/// q scaled by a power of two so that its largest coordinate is in [2^k, 2^(k+1)) (exact
/// for the k used here: the families' coordinates are far from the overflow threshold and
/// scaling up loses nothing; scaling down by at most 2^-1100 can, so only up is used
/// where the query is tiny).
testing::Query4 rescaled(const testing::Query4& q, int k) {
    double m = 0;
    for (const Point2& p : q) m = std::max({m, std::fabs(p.x), std::fabs(p.y)});
    if (m == 0) return q;
    const int shift = k - std::ilogb(m);
    testing::Query4 r;
    for (std::size_t i = 0; i < 4; ++i)
        r[i] = {std::ldexp(q[i].x, shift), std::ldexp(q[i].y, shift)};
    return r;
}

using StageCounts = std::array<std::uint64_t, adaptive_stage_count>;

std::uint64_t count(const StageCounts& c, AdaptiveStage s) {
    return c[static_cast<std::size_t>(s)];
}

/// Runs `check(query, counts)` on every family's queries as generated, where the families
/// spread them over the whole exponent range, and rescaled to [1, 2) (where a near-
/// degenerate query is in the double-word stages' range); only the rescaled queries of the
/// near-degenerate families are counted.
template <class Check>
StageCounts on_every_family(const std::string& what, bool cosine_arrangement, Check check) {
    StageCounts near{};
    for (const testing::FamilyInfo& f : testing::all_families()) {
        const bool ok = rc::check(what + " on " + std::string(f.name), [&] {
            const bool arranged = cosine_arrangement && *rc::gen::arbitrary<bool>();
            const testing::Query4 q =
                arranged ? *testing::gen_cosine_query(f.family) : *testing::gen_query4(f.family);
            StageCounts ignored{};
            check(q, ignored);
            check(rescaled(q, 0), f.near_degenerate ? near : ignored);
        });
        EXPECT_TRUE(ok) << what << " failed on family " << f.name;
    }
    return near;
}

/// For every family: staged incircle == CGAL. Fails if the double-word stage decides fewer
/// near-degenerate queries than the expansions after it (the property would then say
/// little about it).
void incircle_matches_cgal_on_every_family(const std::string& what) {
    const StageCounts near =
        on_every_family(what, false, [](const testing::Query4& q, StageCounts& c) {
            const auto [a, b, c4, d] = q;
            AdaptiveStage stage{};
            RC_ASSERT(incircle_staged(a, b, c4, d, stage) == cgal_incircle(a, b, c4, d));
            ++c[static_cast<std::size_t>(stage)];
        });
    const auto dw = count(near, AdaptiveStage::double_word);
    const auto later = count(near, AdaptiveStage::stage_b) + count(near, AdaptiveStage::stage_c) +
                       count(near, AdaptiveStage::exact);
    EXPECT_GT(dw, later) << "the double-word stage decided fewer near-degenerate queries than "
                            "the expansion stages after it";
}

TEST(IncircleDoubleWord, MatchesCgalOnEveryFamilyWithFusedMultiplyAdd) {
    with_two_product(true, [] { incircle_matches_cgal_on_every_family("incircle (fma)"); });
}

TEST(IncircleDoubleWord, MatchesCgalOnEveryFamilyWithDekkersSplit) {
    with_two_product(false, [] { incircle_matches_cgal_on_every_family("incircle (Dekker)"); });
}

/// The same for incircle_cosine, against the independent exact evaluation of the cosine
/// expression, on queries arranged for the cosine form (c and d on opposite sides of ab
/// where the family allows it) and as generated.
void cosine_matches_oracle_on_every_family(const std::string& what) {
    // Without the precondition (c and d not strictly on opposite sides of ab) the kernel
    // cannot hand the query to incircle; these count the cosine form's own stages.
    StageCounts without_precondition{};
    const StageCounts near =
        on_every_family(what, true, [&](const testing::Query4& q, StageCounts& c) {
            const auto [a, b, c4, d] = q;
            AdaptiveStage stage{};
            RC_ASSERT(incircle_cosine_staged(a, b, c4, d, stage) ==
                      independent_cosine_sign(a, b, c4, d));
            ++c[static_cast<std::size_t>(stage)];
            if (!cgal_cosine_precondition(a, b, c4, d))
                ++without_precondition[static_cast<std::size_t>(stage)];
        });
    EXPECT_GT(count(without_precondition, AdaptiveStage::double_word), 0u)
        << "the cosine form's own double-word stage decided nothing";
    std::cout << what << ", near-degenerate families rescaled, calls per stage:";
    for (const std::uint64_t n : near) std::cout << " " << n;
    std::cout << "\n";
    EXPECT_GT(count(near, AdaptiveStage::double_word), count(near, AdaptiveStage::exact))
        << "the double-word stage decided fewer near-degenerate queries than the exact stage";
}

TEST(CosineDoubleWord, MatchesTheOracleOnEveryFamilyWithFusedMultiplyAdd) {
    with_two_product(true, [] { cosine_matches_oracle_on_every_family("cosine (fma)"); });
}

TEST(CosineDoubleWord, MatchesTheOracleOnEveryFamilyWithDekkersSplit) {
    with_two_product(false, [] { cosine_matches_oracle_on_every_family("cosine (Dekker)"); });
}

// Near-cocircular queries scaled so that their differences straddle the stage's range
// limits: just inside, the stage may decide; just outside, it must leave the query to
// stage B or GMP. Either way the sign is CGAL's.
TEST(IncircleDoubleWord, IsExactAtTheEdgesOfItsRange) {
    EXPECT_TRUE(rc::check("incircle near the double-word range limits", [] {
        const auto q = *testing::gen_query4(testing::Family::near_rounded_circle);
        const int edge = *rc::gen::element(-220, 220);
        const auto s = rescaled(q, edge + *rc::gen::inRange(-3, 4));
        AdaptiveStage stage{};
        RC_ASSERT(incircle_staged(s[0], s[1], s[2], s[3], stage) ==
                  cgal_incircle(s[0], s[1], s[2], s[3]));
    }));
}

// Exact ties on circles of large integer radius: the squares need more than 53 bits, so
// the double-word lifts round and the computed determinant need not be zero. The bound
// must keep the stage from deciding (a zero bound would decide some of these wrongly);
// the same for the cosine form's L - R.
TEST(IncircleDoubleWord, NeverDecidesAnExactTieWhoseEvaluationRounds) {
    int rounded = 0;
    const bool ok = rc::check("exact ties with wide integer coordinates", [&] {
        // Pythagorean triples from (m, n): (m^2 - n^2, 2 m n), radius m^2 + n^2 < 2^51.
        const auto m = *rc::gen::inRange<std::int64_t>(1 << 20, 1 << 25);
        const auto n = *rc::gen::inRange<std::int64_t>(1, m);
        const double x = static_cast<double>(m * m - n * n), y = static_cast<double>(2 * m * n);
        const double cx = static_cast<double>(*rc::gen::inRange<std::int64_t>(-(1 << 20), 1 << 20));
        const double cy = static_cast<double>(*rc::gen::inRange<std::int64_t>(-(1 << 20), 1 << 20));
        const std::array<Point2, 8> on_circle{{{cx + x, cy + y},
                                               {cx - y, cy + x},
                                               {cx - x, cy - y},
                                               {cx + y, cy - x},
                                               {cx + y, cy + x},
                                               {cx - x, cy + y},
                                               {cx - y, cy - x},
                                               {cx + x, cy - y}}};
        const auto pick = *rc::gen::unique<std::vector<std::size_t>>(
            4, rc::gen::inRange<std::size_t>(0, on_circle.size()));
        const Point2 a = on_circle[pick[0]], b = on_circle[pick[1]], c = on_circle[pick[2]],
                     d = on_circle[pick[3]];
        AdaptiveStage stage{};
        RC_ASSERT(incircle_staged(a, b, c, d, stage) == Sign::zero);
        RC_ASSERT(stage != AdaptiveStage::double_word);
        if (stage != AdaptiveStage::filter) ++rounded;
        // The cosine form: a tie L = R when c and d are on opposite sides of ab.
        RC_ASSERT(incircle_cosine_staged(a, b, c, d, stage) == independent_cosine_sign(a, b, c, d));
        RC_ASSERT(stage != AdaptiveStage::double_word);
    });
    EXPECT_TRUE(ok);
    EXPECT_GT(rounded, 0);
}

// Fixtures: one query decided by each of the double-word stage and the stages after it.
TEST(IncircleDoubleWord, DecidesARoundedCocircularQuery) {
    // (cos t, sin t) rounded to doubles for t = 0.3, 2.0, 3.4, 4.7: off the unit circle by
    // about eps, which stage A cannot resolve; some differences round (the exponents of the
    // coordinates differ), so the small-integer stage does not apply either.
    const Point2 a{0x1.e921dd42f09bap-1, 0x1.2e9cd95baba33p-2};
    const Point2 b{-0x1.aa22657537205p-2, 0x1.d18f6ead1b446p-1};
    const Point2 c{-0x1.ef002c35ebe04p-1, -0x1.05ac910ff4c6cp-2};
    const Point2 d{-0x1.95f3a43506a34p-7, -0x1.fff5f0f37ec52p-1};
    AdaptiveStage stage{};
    const Sign s = incircle_staged(a, b, c, d, stage);
    EXPECT_EQ(s, cgal_incircle(a, b, c, d));
    EXPECT_NE(s, Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::double_word);
}

TEST(IncircleDoubleWord, LeavesDifferencesOutsideItsRangeToTheExpansions) {
    // The same query at 2^300: the differences exceed icc_dw_max.
    const double k = 0x1p300;
    AdaptiveStage stage{};
    const Point2 a{0x1.e921dd42f09bap-1 * k, 0x1.2e9cd95baba33p-2 * k};
    const Point2 b{-0x1.aa22657537205p-2 * k, 0x1.d18f6ead1b446p-1 * k};
    const Point2 c{-0x1.ef002c35ebe04p-1 * k, -0x1.05ac910ff4c6cp-2 * k};
    const Point2 d{-0x1.95f3a43506a34p-7 * k, -0x1.fff5f0f37ec52p-1 * k};
    EXPECT_EQ(incircle_staged(a, b, c, d, stage), cgal_incircle(a, b, c, d));
    EXPECT_NE(stage, AdaptiveStage::double_word);
    EXPECT_NE(stage, AdaptiveStage::filter);
}

// Exact ties on a lattice: the differences are small integers times one power of two, so
// the small-integer stage decides them, before any expansion.
TEST(SmallIntegers, DecideExactTiesOnALatticeCircle) {
    for (const double scale : {1.0, 0x1p-30, 0x1p40}) {
        for (const double shift : {0.0, 0x1p20, -12345.0}) {
            const auto at = [&](double x, double y) {
                return Point2{(x + shift) * scale, (y - shift) * scale};
            };
            // Points of the circle x^2 + y^2 = 25; c and d on opposite sides of ab, and
            // neither angle at c or d a right angle (a zero dot product decides earlier).
            const Point2 a = at(5, 0), b = at(0, 5), c = at(-4, 3), d = at(4, 3);
            AdaptiveStage stage{};
            EXPECT_EQ(incircle_staged(a, b, c, d, stage), Sign::zero);
            EXPECT_EQ(stage, AdaptiveStage::small_integer) << scale << " " << shift;
            // The cosine form's tie L = R.
            EXPECT_EQ(incircle_cosine_staged(a, b, c, d, stage), Sign::zero);
            EXPECT_EQ(independent_cosine_sign(a, b, c, d), Sign::zero);
            EXPECT_EQ(stage, AdaptiveStage::small_integer) << scale << " " << shift;
        }
    }
}

TEST(SmallIntegers, DecideNonzeroValuesToo) {
    // (0, 4) is inside the circle through (5, 0), (0, 5), (-5, 0) (counter-clockwise), (0, -6)
    // outside. Stage A decides both, so the integer evaluation is checked directly, on the
    // differences from the fourth point.
    const Point2 a{5, 0}, c{0, 5}, b{-5, 0}, inside{0, 4}, outside{0, -6};
    AdaptiveStage stage{};
    std::int64_t in[6] = {5, -4, 0, 1, -5, -4}, out[6] = {5, 6, 0, 11, -5, 6};
    EXPECT_EQ(detail::incircle_small_sign(in), to_int(cgal_incircle(a, c, b, inside)));
    EXPECT_EQ(detail::incircle_small_sign(out), to_int(cgal_incircle(a, c, b, outside)));
    EXPECT_EQ(incircle_staged(a, c, b, inside, stage), Sign::positive);
}

TEST(SmallIntegers, TakeTheWideWindowWhenTheNarrowOneIsTooSmall) {
    // 2^31 + 1 needs 32 bits: beyond the 30-bit window, inside the 62-bit one.
    const double r = 0x1p31 + 1;
    const Point2 a{r, 0}, b{-r, 0}, c{0, r}, d{0, -r};
    AdaptiveStage stage{};
    EXPECT_EQ(incircle_staged(a, b, c, d, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    std::int64_t n[6];
    const double v[6] = {r, r, -r, r, 0, 2 * r};
    EXPECT_FALSE(detail::to_small_integers(v, n));
    EXPECT_TRUE(detail::to_small_integers<detail::wide_bits>(v, n));
    EXPECT_EQ(detail::incircle_wide_sign(n), 0);
}

TEST(SmallIntegers, FullPrecisionTiesReachTheIntegersAfterTheDoubleWordStage) {
    // The corners of a rectangle with odd 46-bit sides: cocircular, and the differences'
    // significands do not end in zero bits, so incircle tries the double-word stage first
    // (a near-tie is likelier on such data); it cannot decide a tie, and the 62-bit window
    // then does. Both orders must give the same exact answer.
    const double x = 0x1p45 + 1, y = 0x1p45 + 3;
    const Point2 a{0, 0}, b{x, 0}, c{x, y}, d{0, y};
    AdaptiveStage stage{};
    EXPECT_EQ(incircle_staged(a, b, c, d, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    EXPECT_EQ(cgal_incircle(a, b, c, d), Sign::zero);
    // Moved by one ulp, the same data are a near-tie that the double-word stage decides.
    const Point2 e{0, std::nextafter(y, 0x1p46)};
    EXPECT_EQ(incircle_staged(a, b, c, e, stage), cgal_incircle(a, b, c, e));
    EXPECT_EQ(stage, AdaptiveStage::double_word);
}

TEST(SmallIntegers, LeaveWiderDifferencesToTheOtherStages) {
    // Differences such as (2^52 + 1) - 2^-11 need 64 bits: they round, so no window applies.
    const double r = 0x1p52 + 1, s = 0x1p-11;
    const Point2 a{r, s}, b{-r, s}, c{s, r}, d{s, -r};
    AdaptiveStage stage{};
    EXPECT_EQ(incircle_staged(a, b, c, d, stage), cgal_incircle(a, b, c, d));
    EXPECT_NE(stage, AdaptiveStage::small_integer);
}

TEST(SmallIntegers, TwoEqualPointsAreATie) {
    const Point2 a{0.1, 0.7}, b{0.3, 0.2}, c{0.9, 0.4};
    for (const auto& q : {std::array<Point2, 4>{a, a, b, c},
                          {a, b, a, c},
                          {a, b, c, a},
                          {b, a, a, c},
                          {b, a, c, a},
                          {b, c, a, a}}) {
        AdaptiveStage stage{};
        EXPECT_EQ(incircle_staged(q[0], q[1], q[2], q[3], stage), Sign::zero);
        EXPECT_EQ(cgal_incircle(q[0], q[1], q[2], q[3]), Sign::zero);
    }
}

TEST(SmallIntegers, TwoEqualPointsMakeOrient2dAndCompareDistanceZero) {
    // Coordinates whose differences round (no integer window): the equality check decides.
    const Point2 a{0.1, 0.7}, b{0.3, 0.2}, c{0.9, 0.4};
    for (const auto& q : {std::array<Point2, 3>{a, a, c}, {a, c, c}, {c, b, c}, {b, b, b}}) {
        AdaptiveStage stage{};
        EXPECT_EQ(orient2d_staged(q[0], q[1], q[2], stage), Sign::zero);
        EXPECT_EQ(stage, AdaptiveStage::small_integer);
        EXPECT_EQ(cgal_orient2d(q[0], q[1], q[2]), Sign::zero);
    }
    AdaptiveStage stage{};
    EXPECT_EQ(compare_distance_staged(a, b, b, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    // One coordinate equal is not enough.
    EXPECT_EQ(orient2d_staged(a, {a.x, 0.2}, c, stage), cgal_orient2d(a, {a.x, 0.2}, c));
    EXPECT_NE(orient2d_staged(a, {a.x, 0.2}, c, stage), Sign::zero);
}

TEST(SmallIntegers, DecideExactTiesOfOrient2dAndCompareDistance) {
    // Collinear points with 40-bit differences, and a distance tie on a lattice circle.
    const double big = 0x1p40 + 1;
    AdaptiveStage stage{};
    EXPECT_EQ(orient2d_staged({0, 0}, {big, 3 * big}, {2 * big, 6 * big}, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    EXPECT_EQ(compare_distance_staged({1e6, -1e6}, {1e6 + 3, -1e6 + 4}, {1e6 - 5, -1e6}, stage),
              Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    EXPECT_EQ(compare_distance_staged({1e6, -1e6}, {1e6 + 3, -1e6 + 4}, {1e6 - 6, -1e6}, stage),
              Sign::negative);
}

// The window test scales by powers of two far beyond one double's range
// (proofs/bounds.md#small-integers): values at both ends of the exponent range.
TEST(SmallIntegers, ScalingAtTheEndsOfTheExponentRange) {
    std::int64_t n[3];
    // Subnormal differences, scaled up by 2^1099 (two factors): exact integers.
    const double tiny[3] = {0x1p-1074, 3 * 0x1p-1074, -0x1p-1070};
    ASSERT_TRUE(detail::to_small_integers(tiny, n));
    EXPECT_EQ(n[0], std::int64_t{1} << 25);
    EXPECT_EQ(n[1], 3 * (std::int64_t{1} << 25));
    EXPECT_EQ(n[2], -(std::int64_t{1} << 29));
    // The largest doubles, scaled down by 2^-994.
    const double huge[3] = {0x1.8p1023, -0x1p1023, 0};
    ASSERT_TRUE(detail::to_small_integers(huge, n));
    EXPECT_EQ(n[0], 3 * (std::int64_t{1} << 28));
    EXPECT_EQ(n[1], -(std::int64_t{1} << 29));
    EXPECT_EQ(n[2], 0);
    // A value that the scaling underflows to zero is not an integer of the window.
    const double spread[3] = {0x1p1000, 0x1p-1074, 0};
    EXPECT_FALSE(detail::to_small_integers(spread, n));
    EXPECT_FALSE(detail::to_small_integers<detail::wide_bits>(spread, n));
    // The window's bottom bit: 2^-29 below 1 fits 30 bits, 2^-30 does not.
    const double edge[3] = {1.0, 0x1p-29, -0.0};
    ASSERT_TRUE(detail::to_small_integers(edge, n));
    EXPECT_EQ(n[0], std::int64_t{1} << 29);
    EXPECT_EQ(n[1], 1);
    EXPECT_EQ(n[2], 0);
    const double past[3] = {1.0, 0x1p-30, 0};
    EXPECT_FALSE(detail::to_small_integers(past, n));
    EXPECT_TRUE(detail::to_small_integers<detail::wide_bits>(past, n));
    // Not finite: refused before any conversion.
    const double bad[3][3] = {{1.0, std::numeric_limits<double>::infinity(), 0},
                              {std::numeric_limits<double>::quiet_NaN(), 1.0, 0},
                              {0, 0, -std::numeric_limits<double>::infinity()}};
    for (const auto& v : bad) EXPECT_FALSE(detail::to_small_integers<detail::wide_bits>(v, n));
}

// Found by UBSan (the batch property on integer_grid): when every difference is zero, the
// window's lowest exponent stayed INT_MAX and the shift exponent - INT_MAX overflowed.
TEST(SmallIntegers, AllDifferencesZero) {
    const double zeros[4] = {0.0, -0.0, 0.0, 0.0};
    std::int64_t n[4] = {1, 1, 1, 1};
    EXPECT_TRUE(detail::to_small_integers<detail::wide_bits>(zeros, n));
    for (const std::int64_t v : n) EXPECT_EQ(v, 0);
    const Point2 p{0x1.8p-3, 7.0};
    AdaptiveStage stage{};
    EXPECT_EQ(orient2d_staged(p, p, p, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
    EXPECT_EQ(compare_distance_staged(p, p, p, stage), Sign::zero);
    EXPECT_EQ(stage, AdaptiveStage::small_integer);
}

}  // namespace
}  // namespace exidel::test
