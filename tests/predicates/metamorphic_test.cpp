// Metamorphic relations every exact kernel must satisfy, on every family: permuting
// arguments, mirroring, translating by exactly representable offsets and scaling by
// powers of two change the signs in known ways (or not at all).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "exidel/testing/all.hpp"
#include "kernels_under_test.hpp"

namespace exidel::test {
namespace {

using testing::all_families;

template <class K>
class Metamorphic : public ::testing::Test {};
TYPED_TEST_SUITE(Metamorphic, ExactKernels, KernelName);

template <class Property>
void for_every_family(const std::string& what, Property property) {
    for (const testing::FamilyInfo& f : all_families()) {
        EXPECT_TRUE(rc::check(what + " on " + std::string(f.name), [&] { property(f.family); }))
            << what << " failed on family " << f.name;
    }
}

// Exponent of the lowest set bit of v != 0 (v = odd * 2^result).
int lowest_bit(double v) {
    const int q = testing::low_exponent(v);
    const auto m = static_cast<std::int64_t>(std::ldexp(std::fabs(v), -q));  // exact
    return q + std::countr_zero(static_cast<std::uint64_t>(m));
}

// A translation t = (m_x, m_y) * 2^g under which every coordinate of `points` moves
// exactly: all coordinates are multiples of 2^g (g = their lowest set bit), and
// |coordinate + t| stays below 2^(g+53). Degenerates to 0 when there is no room.
template <std::size_t N>
rc::Gen<Point2> gen_exact_translation(const std::array<Point2, N>& points) {
    int g = 1 << 20;
    double top = 0;
    for (const Point2& p : points) {
        for (double v : {p.x, p.y}) {
            if (v != 0) g = std::min(g, lowest_bit(v));
            top = std::max(top, std::fabs(v));
        }
    }
    if (top == 0) g = 0;
    // Sums must fit in 53 bits on the grid 2^g and stay below 2^1024 (found by this
    // test: the fixture TranslationRoomNearOverflow below).
    const double room = std::ldexp(1, std::min(53, 1024 - g)) - std::ldexp(top, -g);
    const auto limit = room > 0 ? static_cast<std::int64_t>(room) - 1 : 0;
    return rc::gen::exec([g, limit] {
        return Point2{testing::dyadic(*testing::gen_toward_zero(-limit, limit), g),
                      testing::dyadic(*testing::gen_toward_zero(-limit, limit), g)};
    });
}

// Regression: the first version of gen_exact_translation allowed 53 bits of room above
// the grid 2^974 of these points, and translated them to infinity.
TEST(Metamorphic, TranslationRoomNearOverflow) {
    const Point2 p{0x1.4p+975, 0x0p+0};
    const std::array<Point2, 4> q{p, p, p, p};
    rc::Random random(1);
    for (int i = 0; i < 1000; ++i) {
        const Point2 t = gen_exact_translation(q)(random.split()).value();
        const double s = p.x + t.x;
        ASSERT_TRUE(std::isfinite(s) && std::isfinite(t.y)) << i;
        ASSERT_EQ(s - p.x, t.x) << i;
    }
}

// A power of two 2^k that keeps every coordinate of `points` exact and finite.
template <std::size_t N>
rc::Gen<int> gen_exact_scale(const std::array<Point2, N>& points) {
    int lo = -2200, hi = 2200;
    for (const Point2& p : points) {
        for (double v : {p.x, p.y}) {
            if (v == 0) continue;
            int e = 0;
            (void)std::frexp(v, &e);  // |v| < 2^e
            lo = std::max(lo, -1074 - lowest_bit(v));
            hi = std::min(hi, 1024 - e);
        }
    }
    return testing::gen_scale_exponent(lo, hi);
}

// a + t with a check that the sum is exact (Knuth's TwoSum error term is zero).
Point2 translated(Point2 p, Point2 t) {
    const auto exact_sum = [](double a, double b) {
        const double s = a + b, bb = s - a;
        RC_ASSERT((a - (s - bb)) + (b - bb) == 0.0);
        return s;
    };
    return {exact_sum(p.x, t.x), exact_sum(p.y, t.y)};
}

Point2 mirrored(Point2 p) { return {-p.x, p.y}; }

TYPED_TEST(Metamorphic, Orient2dPermutations) {
    for_every_family(TypeParam::name() + " orient2d permutations", [](testing::Family f) {
        const auto [a, b, c] = *testing::gen_query3(f);
        const TypeParam k{};
        const Sign s = k.orient2d(a, b, c);
        RC_ASSERT(k.orient2d(b, c, a) == s);
        RC_ASSERT(k.orient2d(c, a, b) == s);
        RC_ASSERT(k.orient2d(b, a, c) == -s);
        RC_ASSERT(k.orient2d(a, c, b) == -s);
        RC_ASSERT(k.orient2d(c, b, a) == -s);
        RC_ASSERT(k.orient2d(mirrored(a), mirrored(b), mirrored(c)) == -s);
    });
}

TYPED_TEST(Metamorphic, IncirclePermutations) {
    for_every_family(TypeParam::name() + " incircle permutations", [](testing::Family f) {
        const auto [a, b, c, d] = *testing::gen_query4(f);
        const TypeParam k{};
        const Sign s = k.incircle(a, b, c, d);
        // The 4x4 lifted determinant is alternating in all four points.
        RC_ASSERT(k.incircle(b, c, a, d) == s);
        RC_ASSERT(k.incircle(b, a, c, d) == -s);
        RC_ASSERT(k.incircle(a, b, d, c) == -s);
        RC_ASSERT(k.incircle(d, b, c, a) == -s);
        RC_ASSERT(k.incircle(b, c, d, a) == -s);  // a 4-cycle is odd
        RC_ASSERT(k.incircle(mirrored(a), mirrored(b), mirrored(c), mirrored(d)) == -s);
    });
}

TYPED_TEST(Metamorphic, CosineSymmetries) {
    for_every_family(TypeParam::name() + " incircle_cosine symmetries", [](testing::Family f) {
        const auto [a, b, c, d] = *testing::gen_cosine_query(f);
        const TypeParam k{};
        const Sign s = k.incircle_cosine(a, b, c, d);
        RC_ASSERT(k.incircle_cosine(b, a, c, d) == s);  // symmetric in a, b
        RC_ASSERT(k.incircle_cosine(a, b, d, c) == s);  // and in c, d
        // Lengths and dot products ignore the orientation of abc.
        RC_ASSERT(k.incircle_cosine(mirrored(a), mirrored(b), mirrored(c), mirrored(d)) == s);
    });
}

// compare_distance(c, p, q): antisymmetric in p, q; zero for p = q; never positive for
// p = c; unchanged by the isometries that map doubles to doubles exactly (mirroring,
// swapping the axes).
TYPED_TEST(Metamorphic, DistanceSymmetries) {
    for_every_family(TypeParam::name() + " compare_distance symmetries", [](testing::Family f) {
        const auto [c, p, q] = *testing::gen_query3(f);
        const TypeParam k{};
        const Sign s = k.compare_distance(c, p, q);
        RC_ASSERT(k.compare_distance(c, q, p) == -s);
        RC_ASSERT(k.compare_distance(c, p, p) == Sign::zero);
        RC_ASSERT(k.compare_distance(c, c, p) == (p == c ? Sign::zero : Sign::negative));
        RC_ASSERT(k.compare_distance(mirrored(c), mirrored(p), mirrored(q)) == s);
        const auto swapped = [](Point2 v) { return Point2{v.y, v.x}; };
        RC_ASSERT(k.compare_distance(swapped(c), swapped(p), swapped(q)) == s);
    });
}

TYPED_TEST(Metamorphic, ExactTranslation) {
    for_every_family(TypeParam::name() + " translation", [](testing::Family f) {
        const auto q = *testing::gen_query4(f);
        const Point2 t = *gen_exact_translation(q);
        const auto [a, b, c, d] = q;
        const Point2 ta = translated(a, t), tb = translated(b, t), tc = translated(c, t),
                     td = translated(d, t);
        const TypeParam k{};
        RC_ASSERT(k.orient2d(ta, tb, tc) == k.orient2d(a, b, c));
        RC_ASSERT(k.incircle(ta, tb, tc, td) == k.incircle(a, b, c, d));
        RC_ASSERT(k.incircle_cosine(ta, tb, tc, td) == k.incircle_cosine(a, b, c, d));
        RC_ASSERT(k.compare_distance(ta, tb, tc) == k.compare_distance(a, b, c));
    });
}

TYPED_TEST(Metamorphic, PowerOfTwoScaling) {
    for_every_family(TypeParam::name() + " scaling", [](testing::Family f) {
        const auto q = *testing::gen_query4(f);
        const int e = *gen_exact_scale(q);
        const auto scale = [e](Point2 p) {
            const Point2 s{std::ldexp(p.x, e), std::ldexp(p.y, e)};
            RC_ASSERT(std::ldexp(s.x, -e) == p.x && std::ldexp(s.y, -e) == p.y);  // exact
            return s;
        };
        const auto [a, b, c, d] = q;
        const TypeParam k{};
        RC_ASSERT(k.orient2d(scale(a), scale(b), scale(c)) == k.orient2d(a, b, c));
        RC_ASSERT(k.incircle(scale(a), scale(b), scale(c), scale(d)) == k.incircle(a, b, c, d));
        RC_ASSERT(k.incircle_cosine(scale(a), scale(b), scale(c), scale(d)) ==
                  k.incircle_cosine(a, b, c, d));
        RC_ASSERT(k.compare_distance(scale(a), scale(b), scale(c)) == k.compare_distance(a, b, c));
    });
}

}  // namespace
}  // namespace exidel::test
