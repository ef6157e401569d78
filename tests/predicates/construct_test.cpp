// exidel::circumcenter is correctly rounded: both coordinates equal CGAL's exact rational
// circumcentre rounded to nearest by MPFR (circumcenter_oracle.hpp), on every point family,
// at every scale from subnormal to huge; collinear input is reported, never divided by.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <CGAL/squared_distance_2.h>
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "circumcenter_oracle.hpp"
#include "double_word.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/construct.hpp"
#include "exidel/testing/all.hpp"

namespace exidel::test {
namespace {

// Bit equality: +0 and -0 differ, NaN equals NaN.
bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// The result of `construct` against the oracle for one triangle (RapidCheck assertions).
template <class Construct>
void check_against_oracle(Construct construct, Point2 a, Point2 b, Point2 c) {
    const Circumcenter got = construct(a, b, c);
    const std::optional<Point2> want = oracle_circumcenter(a, b, c);
    if (!want) {
        RC_ASSERT(got.status == CircumcenterStatus::collinear);
        RC_ASSERT(std::isnan(got.point.x) && std::isnan(got.point.y));
        return;
    }
    const bool overflow = std::isinf(want->x) || std::isinf(want->y);
    RC_ASSERT(got.status == (overflow ? CircumcenterStatus::overflow : CircumcenterStatus::ok));
    RC_ASSERT(same_bits(got.point.x, want->x));
    RC_ASSERT(same_bits(got.point.y, want->y));
}

template <class Construct>
void check_every_family(const std::string& what, Construct construct) {
    for (const testing::FamilyInfo& f : testing::all_families()) {
        const bool ok = rc::check(what + " on " + std::string(f.name), [&] {
            const auto [a, b, c] = *testing::gen_query3(f.family);
            check_against_oracle(construct, a, b, c);
        });
        EXPECT_TRUE(ok) << what << " failed on family " << f.name;
    }
}

TEST(Circumcenter, IsCorrectlyRoundedOnEveryFamily) {
    check_every_family("circumcenter", circumcenter);
}

// The double-word stage has two exact Two-Products: the fused multiply-add (used when
// the processor has one) and Dekker's split. Both must give the same, correct, values.
TEST(Circumcenter, DekkersTwoProductIsCorrectlyRoundedToo) {
    bool& use_fma = detail::dw::use_fma();
    const bool saved = use_fma;
    use_fma = false;
    check_every_family("circumcenter (Dekker's split)", circumcenter);
    use_fma = saved;
}

TEST(Circumcenter, ExactStageIsCorrectlyRoundedOnEveryFamily) {
    check_every_family("circumcenter_exact", circumcenter_exact);
}

// The same queries scaled by 2^k for k from -1100 to 1000 and translated: subnormal
// centres, centres that underflow to zero or overflow to infinity, tiny triangles far
// from the origin.
TEST(Circumcenter, IsCorrectlyRoundedAtEveryScale) {
    for (const testing::FamilyInfo& f : testing::all_families()) {
        const bool ok = rc::check("circumcenter scaled, " + std::string(f.name), [&] {
            const auto [a, b, c] = *testing::gen_query3(f.family);
            const int k = *rc::gen::inRange(-1100, 1001);
            const double shift = *rc::gen::element(0.0, 1.0, -3.0e5, 0x1p-1060);
            const auto move = [&](Point2 p) {
                return Point2{std::ldexp(p.x, k) + shift, std::ldexp(p.y, k) - shift};
            };
            const Point2 sa = move(a), sb = move(b), sc = move(c);
            RC_PRE(std::isfinite(sa.x) && std::isfinite(sa.y) && std::isfinite(sb.x) &&
                   std::isfinite(sb.y) && std::isfinite(sc.x) && std::isfinite(sc.y));
            check_against_oracle(circumcenter, sa, sb, sc);
        });
        EXPECT_TRUE(ok) << f.name;
    }
}

// Regression (found by the Voronoi property test on near_lattice_circle): a centre in
// [2^-1021, 2^-1020), just above the subnormal range, was rounded with the subnormal
// quantum 2^-1074 (one bit too many) by stage 3. The same queries scaled to put the
// centre near the normal/subnormal boundary, where that clamp matters.
TEST(Circumcenter, IsCorrectlyRoundedAtTheSubnormalBoundary) {
    for (const testing::FamilyInfo& f : testing::all_families()) {
        const bool ok = rc::check("circumcenter near 2^-1022, " + std::string(f.name), [&] {
            const auto [a, b, c] = *testing::gen_query3(f.family);
            const int k = *rc::gen::inRange(-1026, -1014);
            const auto move = [&](Point2 p) {
                return Point2{std::ldexp(p.x, k), std::ldexp(p.y, k)};
            };
            check_against_oracle(circumcenter, move(a), move(b), move(c));
        });
        EXPECT_TRUE(ok) << f.name;
    }
}

TEST(Circumcenter, FastStageDecidesRandomTriangles) {
    // Uniform random triangles in the unit square are far from every tie and every range
    // limit: stage 1 must decide nearly all of them (a filter that never fires would still
    // be correct, and this test is what catches it).
    std::uint64_t state = 12345;
    const auto next = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) * 0x1p-53;
    };
    int fast = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const Point2 a{next(), next()}, b{next(), next()}, c{next(), next()};
        const Circumcenter got = circumcenter(a, b, c);
        if (got.stage != CircumcenterStage::exact) ++fast;
        const auto want = oracle_circumcenter(a, b, c);
        ASSERT_TRUE(want);
        ASSERT_TRUE(same_bits(got.point.x, want->x) && same_bits(got.point.y, want->y));
    }
    EXPECT_GT(fast, n * 99 / 100);
}

constexpr double tiny = std::numeric_limits<double>::denorm_min();
constexpr double huge = std::numeric_limits<double>::max();

TEST(Circumcenter, SubnormalCentreIsExact) {
    const Circumcenter r = circumcenter({0, 0}, {2 * tiny, 0}, {0, 2 * tiny});
    EXPECT_EQ(r.status, CircumcenterStatus::ok);
    EXPECT_EQ(r.point.x, tiny);
    EXPECT_EQ(r.point.y, tiny);
}

TEST(Circumcenter, HalfOfTheSmallestSubnormalRoundsToEvenZero) {
    const Circumcenter r = circumcenter({0, 0}, {tiny, 0}, {0, tiny});
    EXPECT_EQ(r.status, CircumcenterStatus::ok);
    EXPECT_TRUE(same_bits(r.point.x, 0.0) && same_bits(r.point.y, 0.0));
    // Three halves of it: ties to the even neighbour, 2 * tiny.
    const Circumcenter s = circumcenter({0, 0}, {3 * tiny, 0}, {0, -3 * tiny});
    EXPECT_EQ(s.point.x, 2 * tiny);
    EXPECT_EQ(s.point.y, -2 * tiny);
}

TEST(Circumcenter, OverflowIsInfinityWithItsSign) {
    // A nearly flat triangle of huge points: the centre is far beyond the largest double.
    const Circumcenter r = circumcenter({-huge, 0}, {huge, 0}, {0, 1});
    EXPECT_EQ(r.status, CircumcenterStatus::overflow);
    EXPECT_EQ(r.point.x, 0.0);
    EXPECT_EQ(r.point.y, -std::numeric_limits<double>::infinity());
    // Differences that overflow but a representable centre.
    const Circumcenter s = circumcenter({-huge, -huge}, {huge, -huge}, {-huge, huge});
    EXPECT_EQ(s.status, CircumcenterStatus::ok);
    EXPECT_EQ(s.point.x, 0.0);
    EXPECT_EQ(s.point.y, 0.0);
}

TEST(Circumcenter, CollinearAndDuplicatePointsAreReported) {
    for (const auto& [a, b, c] :
         {std::tuple{Point2{0, 0}, Point2{1, 1}, Point2{2, 2}},
          std::tuple{Point2{0, 0}, Point2{0, 0}, Point2{1, 0}},
          std::tuple{Point2{3, 3}, Point2{3, 3}, Point2{3, 3}},
          std::tuple{Point2{0.1, 0.2}, Point2{0.3, 0.6}, Point2{0.5, 1.0}}}) {
        const Circumcenter r = circumcenter(a, b, c);
        const bool collinear = !oracle_circumcenter(a, b, c);
        EXPECT_EQ(r.status == CircumcenterStatus::collinear, collinear);
        if (collinear) {
            EXPECT_TRUE(std::isnan(r.point.x) && std::isnan(r.point.y));
        }
    }
}

TEST(Circumcenter, NonFiniteInputIsReported) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(circumcenter({0, 0}, {inf, 0}, {0, 1}).status, CircumcenterStatus::non_finite_input);
    EXPECT_EQ(circumcenter({0, nan}, {1, 0}, {0, 1}).status, CircumcenterStatus::non_finite_input);
}

TEST(Circumcenter, CocircularTrianglesShareTheirCentreBitForBit) {
    // The 12 lattice points of x^2 + y^2 = 25 moved to (0.1, 0.3) (rounded): every
    // triangle of them whose vertices are still exactly cocircular gives one double.
    std::vector<Point2> pts;
    for (int x = -5; x <= 5; ++x)
        for (int y = -5; y <= 5; ++y)
            if (x * x + y * y == 25) pts.push_back({x * 0x1p-3 + 1024, y * 0x1p-3 - 7});
    const Circumcenter first = circumcenter(pts[0], pts[1], pts[2]);
    ASSERT_TRUE(first.ok());
    for (std::size_t i = 0; i + 2 < pts.size(); ++i) {
        const Circumcenter r = circumcenter(pts[i], pts[i + 1], pts[i + 2]);
        EXPECT_TRUE(same_bits(r.point.x, first.point.x) && same_bits(r.point.y, first.point.y));
    }
    EXPECT_EQ(first.point.x, 1024.0);
    EXPECT_EQ(first.point.y, -7.0);
}

// ---- intersection ----------------------------------------------------------------------------

/// CGAL's exact crossing of lines ab and cd over Gmpq, rounded by MPFR; nullopt when the
/// lines are parallel (or a point pair coincides).
std::optional<Point2> oracle_intersection(Point2 a, Point2 b, Point2 c, Point2 d) {
    using Q = CGAL::Gmpq;
    const auto lift = [](Point2 p) { return std::pair<Q, Q>{Q(p.x), Q(p.y)}; };
    const auto [ax, ay] = lift(a);
    const auto [bx, by] = lift(b);
    const auto [cx, cy] = lift(c);
    const auto [dx, dy] = lift(d);
    // Written independently of construct.cpp: Cramer's rule on a + s (b - a) = c + t (d - c).
    const Q m11 = bx - ax, m12 = cx - dx, m21 = by - ay, m22 = cy - dy;
    const Q det = m11 * m22 - m12 * m21;
    if (det == 0) return std::nullopt;
    const Q s = ((cx - ax) * m22 - m12 * (cy - ay)) / det;
    return Point2{round_to_double(ax + s * m11), round_to_double(ay + s * m21)};
}

void check_intersection(Point2 a, Point2 b, Point2 c, Point2 d) {
    const Intersection got = intersection(a, b, c, d);
    const std::optional<Point2> want = oracle_intersection(a, b, c, d);
    if (!want) {
        RC_ASSERT(got.status == IntersectionStatus::parallel);
        return;
    }
    const bool overflow = std::isinf(want->x) || std::isinf(want->y);
    RC_ASSERT(got.status == (overflow ? IntersectionStatus::overflow : IntersectionStatus::ok));
    RC_ASSERT(same_bits(got.point.x, want->x));
    RC_ASSERT(same_bits(got.point.y, want->y));
}

TEST(Intersection, IsCorrectlyRoundedOnEveryFamilyAndScale) {
    for (const testing::FamilyInfo& f : testing::all_families()) {
        const bool ok = rc::check("intersection, " + std::string(f.name), [&] {
            const auto [a, b, c, d] = *testing::gen_query4(f.family);
            const int k = *rc::gen::inRange(-1100, 1001);
            const double shift = *rc::gen::element(0.0, 1.0, -3.0e5, 0x1p-1060);
            const bool scaled = *rc::gen::arbitrary<bool>();
            const auto move = [&](Point2 p) {
                return scaled ? Point2{std::ldexp(p.x, k) + shift, std::ldexp(p.y, k) - shift} : p;
            };
            const Point2 sa = move(a), sb = move(b), sc = move(c), sd = move(d);
            for (const Point2 p : {sa, sb, sc, sd})
                RC_PRE(std::isfinite(p.x) && std::isfinite(p.y));
            check_intersection(sa, sb, sc, sd);
        });
        EXPECT_TRUE(ok) << f.name;
    }
}

TEST(Intersection, CrossingSegmentsGiveAPointInBothBoxes) {
    const bool ok = rc::check("intersection of crossing segments", [] {
        const auto [a, b, c, d] = *testing::gen_query4(testing::Family::uniform);
        const Intersection x = intersection(a, b, c, d);
        RC_PRE(x.ok());
        const AdaptiveKernel k;
        RC_PRE(to_int(k.orient2d(a, b, c)) * to_int(k.orient2d(a, b, d)) < 0 &&
               to_int(k.orient2d(c, d, a)) * to_int(k.orient2d(c, d, b)) < 0);
        for (const auto& [p, q] : {std::pair{a, b}, std::pair{c, d}}) {
            RC_ASSERT(std::min(p.x, q.x) <= x.point.x && x.point.x <= std::max(p.x, q.x));
            RC_ASSERT(std::min(p.y, q.y) <= x.point.y && x.point.y <= std::max(p.y, q.y));
        }
    });
    EXPECT_TRUE(ok);
}

TEST(Intersection, ParallelAndNonFiniteInputAreReported) {
    EXPECT_EQ(intersection({0, 0}, {1, 1}, {0, 1}, {1, 2}).status, IntersectionStatus::parallel);
    EXPECT_EQ(intersection({0, 0}, {0, 0}, {0, 1}, {1, 2}).status, IntersectionStatus::parallel);
    EXPECT_EQ(intersection({0, 0}, {1, 1}, {0, 1}, {std::nan(""), 2}).status,
              IntersectionStatus::non_finite_input);
    // Nearly parallel lines far apart: the crossing is beyond the largest double.
    const Intersection far = intersection({0, 0}, {1, 0}, {0, 1}, {0x1p1000, 1 - 0x1p-52});
    EXPECT_EQ(far.status, IntersectionStatus::overflow);
    EXPECT_TRUE(std::isinf(far.point.x));
    // An exact tie between two doubles goes to the even one: (1 + 2^-53, 0) is halfway.
    const Intersection tie = intersection({1, -1}, {1 + 0x1p-52, 1}, {0, 0}, {4, 0});
    EXPECT_TRUE(tie.ok());
    EXPECT_EQ(tie.point.x, 1.0);
}

// ---- compare_segment_distance ------------------------------------------------------------

// CGAL's exact squared distance from a point to a segment (over Gmpq) against r^2.
Sign oracle_segment_distance(Point2 p, Point2 a, Point2 b, double r) {
    using CK = CGAL::Simple_cartesian<CGAL::Gmpq>;
    const CK::Point_2 cp(p.x, p.y), ca(a.x, a.y), cb(b.x, b.y);
    const CGAL::Gmpq d2 = (a.x == b.x && a.y == b.y)
                              ? CGAL::squared_distance(cp, ca)
                              : CGAL::squared_distance(cp, CK::Segment_2(ca, cb));
    const CGAL::Gmpq r2 = CGAL::Gmpq(r) * CGAL::Gmpq(r);
    return d2 < r2 ? Sign::negative : d2 > r2 ? Sign::positive : Sign::zero;
}

TEST(SegmentDistance, AgreesWithCgalOnEveryFamilyAndScale) {
    for (const testing::FamilyInfo& f : testing::all_families()) {
        const bool ok = rc::check("compare_segment_distance, " + std::string(f.name), [&] {
            const auto [p, a, b] = *testing::gen_query3(f.family);
            const int k = *rc::gen::inRange(-1100, 1001);
            const auto move = [&](Point2 q) {
                return Point2{std::ldexp(q.x, k), std::ldexp(q.y, k)};
            };
            const Point2 sp = move(p), sa = move(a), sb = move(b);
            for (const Point2 q : {sp, sa, sb}) RC_PRE(std::isfinite(q.x) && std::isfinite(q.y));
            // r: near the true distance (long double), one of its neighbours, or arbitrary.
            const long double dx = static_cast<long double>(sb.x) - sa.x,
                              dy = static_cast<long double>(sb.y) - sa.y;
            const long double guess = std::fabs(dx * (static_cast<long double>(sp.y) - sa.y) -
                                                dy * (static_cast<long double>(sp.x) - sa.x)) /
                                      std::sqrt(dx * dx + dy * dy);
            double r = std::isfinite(static_cast<double>(guess)) ? static_cast<double>(guess) : 1.0;
            r = *rc::gen::element(r, std::nextafter(r, 0.0), std::nextafter(r, HUGE_VAL), 0.0,
                                  std::fabs(sp.x));
            RC_PRE(std::isfinite(r));
            RC_ASSERT(compare_segment_distance(sp, sa, sb, r) ==
                      oracle_segment_distance(sp, sa, sb, r));
        });
        EXPECT_TRUE(ok) << f.name;
    }
}

TEST(SegmentDistance, EndsLineAndDegenerateCases) {
    // (2, 3) is 3 from the segment (0, 0)-(4, 0) (its foot is inside); (-3, 4) and (7, 4) are 5
    // from its ends.
    for (const int k : {0, -1070, 1000}) {
        const auto s = [k](double v) { return std::ldexp(v, k); };
        const Point2 a{s(0), s(0)}, b{s(4), s(0)};
        EXPECT_EQ(compare_segment_distance({s(2), s(3)}, a, b, s(3)), Sign::zero);
        EXPECT_EQ(compare_segment_distance({s(2), s(3)}, a, b, s(2.5)), Sign::positive);
        EXPECT_EQ(compare_segment_distance({s(2), s(3)}, a, b, s(3.5)), Sign::negative);
        EXPECT_EQ(compare_segment_distance({s(-3), s(4)}, a, b, s(5)), Sign::zero);
        EXPECT_EQ(compare_segment_distance({s(7), s(4)}, a, b, s(5)), Sign::zero);
        EXPECT_EQ(compare_segment_distance({s(7), s(4)}, a, b, s(4)), Sign::positive);
        EXPECT_EQ(compare_segment_distance({s(3), s(4)}, a, a, s(5)), Sign::zero);  // a == b
    }
    EXPECT_EQ(compare_segment_distance({0, 0}, {0, 0}, {1, 0}, 0), Sign::zero);
    EXPECT_EQ(compare_segment_distance({0, 0x1p-1074}, {-1, 0}, {1, 0}, 0), Sign::positive);
    EXPECT_EQ(compare_segment_distance({std::nan(""), 0}, {0, 0}, {1, 0}, 1), Sign::positive);
    EXPECT_EQ(compare_segment_distance({0, 0}, {0, 0}, {1, 0}, -1), Sign::positive);
    EXPECT_EQ(compare_segment_distance({0, 0}, {0, 0}, {HUGE_VAL, 0}, 1), Sign::positive);
}

}  // namespace
}  // namespace exidel::test
