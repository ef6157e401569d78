// The two sorts every triangulation starts with, against plain comparison sorts that
// state the order they must produce: the lexicographic sort and deduplication of the
// input (radix sort by x, runs of equal x by y) and the radial order (radix sort by a
// floating-point key, exact re-sort of runs it cannot separate). Sizes reach well past
// the radix sort's small-input cut-off (256), which the triangulation property tests
// (at most 160 points) never do.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "exidel/delaunay/detail/radial.hpp"
#include "exidel/delaunay/detail/radix.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/testing/all.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay::detail;
namespace xt = exidel::testing;

TEST(OrderKey, OrdersDoublesAsNumbersAndIdentifiesSignedZeros) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    constexpr double big = std::numeric_limits<double>::max();
    constexpr double tiny = std::numeric_limits<double>::denorm_min();
    constexpr double normal = std::numeric_limits<double>::min();
    const std::vector<double> ascending = {-inf, -big,   -1.5, -1.0, -normal, -tiny, 0.0,
                                           tiny, normal, 1.0,  1.5,  big,     inf};
    for (std::size_t i = 0; i + 1 < ascending.size(); ++i) {
        EXPECT_LT(order_key(ascending[i]), order_key(ascending[i + 1]))
            << ascending[i] << " < " << ascending[i + 1];
    }
    EXPECT_EQ(order_key(-0.0), order_key(0.0));
    EXPECT_EQ(order_key(std::nextafter(0.0, 1.0)), order_key(tiny));
}

/// Keys from a few values (many ties, so stability is tested) or from every bit pattern.
rc::Gen<std::vector<KeyIndex>> gen_records() {
    return rc::gen::exec([] {
        const auto n = *rc::gen::inRange<std::size_t>(0, 3000);
        const bool ties = *rc::gen::arbitrary<bool>();
        std::vector<KeyIndex> v(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint64_t key = ties ? *rc::gen::inRange<std::uint64_t>(0, 8) << 40
                                           : *rc::gen::arbitrary<std::uint64_t>();
            v[i] = {key, static_cast<std::uint32_t>(i)};
        }
        return v;
    });
}

RC_GTEST_PROP(RadixSort, EqualsStableSortByKey, ()) {
    std::vector<KeyIndex> v = *gen_records();
    std::vector<KeyIndex> expected = v;
    std::stable_sort(expected.begin(), expected.end(),
                     [](const KeyIndex& a, const KeyIndex& b) { return a.key < b.key; });
    radix_sort(v);
    for (std::size_t i = 0; i < v.size(); ++i) {
        RC_ASSERT(v[i].key == expected[i].key);
        RC_ASSERT(v[i].index == expected[i].index);
    }
}

/// Point sets of up to 2000 points from every family, with repeated points, shared x
/// coordinates and signed zeros mixed in.
rc::Gen<std::vector<Point2>> gen_input() {
    return rc::gen::exec([] {
        const xt::Family f = *rc::gen::elementOf(std::vector<xt::Family>{
            xt::Family::uniform, xt::Family::integer_grid, xt::Family::lattice_circle,
            xt::Family::near_lattice_circle, xt::Family::near_rounded_circle,
            xt::Family::wide_exponents, xt::Family::duplicates});
        std::vector<Point2> pts = *xt::gen_points(f, *rc::gen::inRange<std::size_t>(250, 2000));
        const auto extra = *rc::gen::inRange<std::size_t>(0, pts.size() / 4);
        for (std::size_t j = 0; j < extra; ++j) {
            const Point2 p = pts[*rc::gen::inRange<std::size_t>(0, pts.size())];
            switch (*rc::gen::inRange(0, 4)) {
                case 0: pts.push_back(p); break;            // a duplicate
                case 1: pts.push_back({p.x, -p.y}); break;  // the same x
                case 2: pts.push_back({-0.0, p.y}); break;  // signed zeros
                default: pts.push_back({0.0, std::copysign(0.0, -p.y)}); break;
            }
        }
        return pts;
    });
}

RC_GTEST_PROP(SortAndDedupe, EqualsComparisonSortWithFirstOccurrenceKept, ()) {
    const std::vector<Point2> pts = *gen_input();
    std::vector<std::uint32_t> expected(pts.size());
    std::iota(expected.begin(), expected.end(), 0u);
    std::sort(expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) {
        if (pts[a].x != pts[b].x) return pts[a].x < pts[b].x;
        if (pts[a].y != pts[b].y) return pts[a].y < pts[b].y;
        return a < b;
    });
    // Chunks from one point up (many chunks, runs of a bucket across their borders) and
    // one to three threads: the result must not depend on either.
    const auto threads = *rc::gen::inRange(1u, 4u);
    const auto chunk = *rc::gen::elementOf(std::vector<std::size_t>{1, 7, 64, 1000, 1 << 16});
    SortedInput in;
    RC_ASSERT(!sort_and_dedupe(pts, in, threads, chunk));
    std::size_t k = 0;  // position in in.points
    std::vector<std::uint32_t> duplicates;
    for (std::size_t j = 0; j < expected.size(); ++j) {
        const std::uint32_t i = expected[j];
        if (j > 0 && pts[i] == pts[expected[j - 1]]) {
            duplicates.push_back(i);
            RC_ASSERT(in.vertex_of_input[i] == in.input_of[k - 1]);
            continue;
        }
        RC_ASSERT(k < in.points.size());
        RC_ASSERT(in.input_of[k] == i);
        RC_ASSERT(in.points[k] == pts[i]);
        RC_ASSERT(in.vertex_of_input[i] == i);
        ++k;
    }
    RC_ASSERT(k == in.points.size());
    std::sort(duplicates.begin(), duplicates.end());
    RC_ASSERT(duplicates == in.duplicates);
}

TEST(SortAndDedupe, NamesTheFirstNonFiniteCoordinateWhateverTheChunksAndThreads) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::vector<Point2> pts(40, Point2{1, 2});
    pts[23] = {nan, 0};
    pts[9] = {0, -inf};
    pts[31] = {inf, inf};
    for (const std::size_t chunk : {1, 3, 8, 10, 64}) {
        for (const unsigned threads : {1u, 2u, 3u}) {
            SortedInput in;
            const auto failure = sort_and_dedupe(pts, in, threads, chunk);
            ASSERT_TRUE(failure.has_value());
            EXPECT_EQ(failure->kind, exidel::delaunay::FailureKind::non_finite_input);
            EXPECT_EQ(failure->input_index, 9u) << "chunk " << chunk << ", threads " << threads;
        }
    }
}

RC_GTEST_PROP(RadialOrder, IsAscendingExactDistanceTiesByPosition, ()) {
    std::vector<Point2> pts = *gen_input();
    SortedInput in;
    RC_ASSERT(!sort_and_dedupe(pts, in));
    // The centre the triangulation would use, or a lattice point (exact ties on circles).
    const Point2 centre = *rc::gen::arbitrary<bool>() ? radial_centre(in.points) : Point2{0, 0};
    const std::vector<std::uint32_t> order = radial_order(in.points, centre, AdaptiveKernel{});
    std::vector<std::uint32_t> expected(in.points.size());
    std::iota(expected.begin(), expected.end(), 0u);
    std::sort(expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) {
        const Sign s = GmpExactKernel::compare_distance(centre, in.points[a], in.points[b]);
        return s == Sign::negative || (s == Sign::zero && a < b);
    });
    RC_ASSERT(order == expected);
}

}  // namespace
