// The mutable triangulation (exidel/delaunay/mutable_triangulation.hpp): random
// interleavings of insert and remove on every degenerate family, each state certified
// exactly and its forced edges compared with CGAL's Delaunay triangulation of the points
// left; cocircular stars, grids, collinear sets and copies of a point; inexact and lying
// kernels (an answer or a typed failure, never a hang); bad input.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/mutable_triangulation.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "lying_kernel.hpp"

namespace exidel::test {
namespace {

using delaunay::FailureError;
using delaunay::FailureKind;
using delaunay::LocationKind;
using delaunay::MutableTriangulation;

/// The state of `m` is the Delaunay triangulation of its live points: certified exactly,
/// and its forced edges (those every Delaunay triangulation has) are CGAL's.
template <class K>
void check_state(const MutableTriangulation<K>& m) {
    const delaunay::MutableSnapshot s = m.snapshot();
    RC_ASSERT(s.points.size() == m.size());
    const delaunay::Certificate c = delaunay::certify(s.points, s.triangulation);
    if (!c.ok()) RC_FAIL(c.summary());
    const EdgeSets ours = edge_sets(s.points, s.triangulation);
    const EdgeSets cgal = cgal_edge_sets(s.points);
    RC_ASSERT(ours.collinear == cgal.collinear);
    RC_ASSERT(ours.forced == cgal.forced);
    RC_ASSERT(s.triangulation.triangle_count() == cgal.triangles.size());
    RC_ASSERT(s.triangulation.vertex_of_input.size() == s.points.size());
}

/// Inserts every point, then removes and inserts at random (points of the set again,
/// copies of live points, removals of copies and of vertices), checking the state at
/// random moments and at the end.
template <class K>
void random_interleaving(const std::vector<Point2>& points, K kernel = K{}) {
    MutableTriangulation<K> m(kernel);
    std::vector<std::uint32_t> live;
    for (const Point2& p : points) live.push_back(m.insert(p));
    check_state(m);
    const std::size_t steps = *rc::gen::inRange<std::size_t>(0, 3 * points.size() + 4);
    for (std::size_t step = 0; step < steps; ++step) {
        const int what = *rc::gen::inRange(0, 10);
        if (what < 6 && !live.empty()) {
            const std::size_t i = *rc::gen::inRange<std::size_t>(0, live.size());
            m.remove(live[i]);
            live[i] = live.back();
            live.pop_back();
        } else if (what < 8 && !points.empty()) {
            live.push_back(m.insert(*rc::gen::elementOf(points)));
        } else if (!live.empty()) {
            live.push_back(m.insert(m.point(*rc::gen::elementOf(live))));  // a copy
        }
        RC_ASSERT(m.size() == live.size());
        if (*rc::gen::inRange(0, 8) == 0) check_state(m);
    }
    check_state(m);
    for (const std::uint32_t id : live) RC_ASSERT(m.contains(id));
}

RC_GTEST_PROP(Mutable, RandomInterleavingsAreDelaunayOnEveryFamily, ()) {
    const PointSet s = *gen_point_set(60);
    random_interleaving<AdaptiveKernel>(s.points);
}

RC_GTEST_PROP(Mutable, ExactKernelsGiveTheSameForcedEdges, ()) {
    const PointSet s = *gen_point_set(30);
    random_interleaving<GmpExactKernel>(s.points);
}

RC_GTEST_PROP(Mutable, BuiltFromPointsThenChangedStaysDelaunay, ()) {
    const PointSet s = *gen_point_set(80);
    MutableTriangulation<AdaptiveKernel> m(s.points);
    RC_ASSERT(m.size() == s.points.size());
    check_state(m);
    // Remove a random half of the ids, in a random order, then put some back.
    std::vector<std::uint32_t> ids(s.points.size());
    for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
    std::mt19937_64 rng(*rc::gen::arbitrary<std::uint64_t>());
    std::shuffle(ids.begin(), ids.end(), rng);
    const std::size_t half = ids.size() / 2;
    for (std::size_t i = 0; i < half; ++i) m.remove(ids[i]);
    check_state(m);
    for (std::size_t i = 0; i < half; i += 2) m.insert(s.points[ids[i]]);
    check_state(m);
}

RC_GTEST_PROP(Mutable, LocateAndNearestAreExact, ()) {
    const PointSet s = *gen_point_set(50);
    MutableTriangulation<AdaptiveKernel> m;
    for (const Point2& p : s.points) m.insert(p);
    const auto snap = m.snapshot();
    std::vector<Point2> queries = s.points;
    for (const Point2& r : uniform_points(8, *rc::gen::arbitrary<std::uint32_t>())) {
        queries.push_back({r.x * 2 - 0.5, r.y * 2 - 0.5});
    }
    for (const Point2& q : queries) {
        const auto loc = m.locate(q);
        bool is_point = false;
        for (const Point2& p : s.points) is_point |= p.x == q.x && p.y == q.y;
        RC_ASSERT((loc.kind == LocationKind::on_vertex) == is_point);
        if (is_point) RC_ASSERT(m.point(loc.vertex).x == q.x && m.point(loc.vertex).y == q.y);
        if (s.points.empty()) continue;
        const std::uint32_t v = m.nearest(q);
        RC_ASSERT(m.contains(v) && m.vertex_of(v) == v);
        for (const Point2& p : s.points) {
            RC_ASSERT(CGAL::compare_distance_to_point(to_cgal(q), to_cgal(p),
                                                      to_cgal(m.point(v))) != CGAL::SMALLER);
        }
    }
}

/// Points on a circle (exactly: the 8 points (±a, ±b), (±b, ±a) of a Pythagorean triple
/// and (±c, 0), (0, ±c) on x² + y² = c²) around a centre, which is removed and put back.
TEST(Mutable, CocircularStarOfTheRemovedVertex) {
    std::vector<Point2> circle;
    for (const double a : {3.0, -3.0}) {
        for (const double b : {4.0, -4.0}) {
            circle.push_back({a, b});
            circle.push_back({b, a});
        }
    }
    for (const double c : {5.0, -5.0}) {
        circle.push_back({c, 0});
        circle.push_back({0, c});
    }
    MutableTriangulation<AdaptiveKernel> m;
    const std::uint32_t centre = m.insert({0, 0});
    for (const Point2& p : circle) m.insert(p);
    for (int round = 0; round < 3; ++round) {
        m.remove(round == 0 ? centre : m.insert({0, 0}));
        const auto s = m.snapshot();
        EXPECT_TRUE(delaunay::certify(s.points, s.triangulation).ok());
        EXPECT_EQ(s.triangulation.triangle_count(), circle.size() - 2);
    }
    // A centre with every neighbour on one circle, many of them: the star of the
    // centre of a regular-ish polygon whose vertices are exactly cocircular.
    MutableTriangulation<AdaptiveKernel> big;
    const std::uint32_t c = big.insert({0, 0});
    for (int x = -25; x <= 25; ++x) {
        for (int y = -25; y <= 25; ++y) {
            if (x * x + y * y == 625) big.insert({double(x), double(y)});
        }
    }
    big.remove(c);
    const auto s = big.snapshot();
    EXPECT_TRUE(delaunay::certify(s.points, s.triangulation).ok());
}

TEST(Mutable, GridEveryOtherPointRemoved) {
    MutableTriangulation<AdaptiveKernel> m;
    std::vector<std::uint32_t> ids;
    for (int x = 0; x < 30; ++x) {
        for (int y = 0; y < 30; ++y) ids.push_back(m.insert({double(x), double(y)}));
    }
    for (std::size_t i = 0; i < ids.size(); i += 2) m.remove(ids[i]);
    const auto s = m.snapshot();
    const auto c = delaunay::certify(s.points, s.triangulation);
    EXPECT_TRUE(c.ok()) << c.summary();
    EXPECT_EQ(s.points.size(), ids.size() / 2);
}

TEST(Mutable, CollinearAndBackAgain) {
    MutableTriangulation<AdaptiveKernel> m;
    std::vector<std::uint32_t> line;
    for (int i = 0; i < 10; ++i) line.push_back(m.insert({double(i), 2.0 * i}));
    EXPECT_TRUE(m.collinear());
    const std::uint32_t off = m.insert({0, 5});
    EXPECT_FALSE(m.collinear());
    EXPECT_EQ(m.snapshot().triangulation.triangle_count(), 9u);
    m.remove(off);
    EXPECT_TRUE(m.collinear());
    auto s = m.snapshot();
    EXPECT_TRUE(delaunay::certify(s.points, s.triangulation).ok());
    EXPECT_EQ(s.triangulation.hull.size(), 10u);
    m.remove(line[0]);
    m.remove(line[9]);
    const std::uint32_t back = m.insert({3, -1});
    EXPECT_FALSE(m.collinear());
    m.remove(back);
    s = m.snapshot();
    EXPECT_TRUE(s.triangulation.collinear);
    EXPECT_TRUE(delaunay::certify(s.points, s.triangulation).ok());
    for (std::size_t i = 1; i < 9; ++i) m.remove(line[i]);
    EXPECT_EQ(m.size(), 0u);
    EXPECT_EQ(m.nearest({1, 1}), delaunay::no_vertex);
    EXPECT_EQ(m.locate({1, 1}).kind, LocationKind::outside);
}

TEST(Mutable, CopiesOfAPointKeepTheVertexUntilTheLast) {
    MutableTriangulation<AdaptiveKernel> m;
    m.insert({0, 0});
    m.insert({1, 0});
    m.insert({0, 1});
    const std::uint32_t a = m.insert({1, 1});
    const std::uint32_t b = m.insert({1, 1});
    const std::uint32_t c = m.insert({1, 1});
    EXPECT_EQ(m.vertex_count(), 4u);
    EXPECT_EQ(m.size(), 6u);
    EXPECT_EQ(m.vertex_of(c), a);
    m.remove(a);  // the vertex is renamed b
    EXPECT_EQ(m.vertex_of(c), b);
    auto s = m.snapshot();
    EXPECT_TRUE(delaunay::certify(s.points, s.triangulation).ok());
    EXPECT_EQ(s.triangulation.duplicates.size(), 1u);
    m.remove(c);
    m.remove(b);
    EXPECT_EQ(m.vertex_count(), 3u);
    s = m.snapshot();
    EXPECT_TRUE(delaunay::certify(s.points, s.triangulation).ok());
    EXPECT_EQ(s.triangulation.triangle_count(), 1u);
}

TEST(Mutable, BadInputIsAClearError) {
    MutableTriangulation<AdaptiveKernel> m;
    const std::uint32_t a = m.insert({0, 0});
    m.insert({1, 0});
    m.insert({0, 1});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const Point2 bad : {Point2{nan, 0}, Point2{0, inf}}) {
        try {
            m.insert(bad);
            ADD_FAILURE() << "a non-finite point was inserted";
        } catch (const FailureError& e) {
            EXPECT_EQ(e.failure.kind, FailureKind::non_finite_input);
        }
        EXPECT_THROW(m.locate(bad), FailureError);
    }
    EXPECT_EQ(m.size(), 3u);  // nothing changed: still usable
    EXPECT_EQ(m.id_count(), 3u);
    m.remove(a);
    EXPECT_THROW(m.remove(a), std::out_of_range);          // twice
    EXPECT_THROW(m.remove(99), std::out_of_range);         // never issued
    EXPECT_THROW(m.insert({2, 2}, a), std::out_of_range);  // a removed hint
    EXPECT_NO_THROW(m.insert({2, 2}, 1));
    const std::vector<Point2> with_nan = {{0, 0}, {nan, 1}};
    EXPECT_THROW(MutableTriangulation<AdaptiveKernel>{with_nan}, FailureError);
}

RC_GTEST_PROP(Mutable, InexactKernelsAnswerOrFailTyped, ()) {
    const PointSet s = *gen_point_set(80);
    const auto typed = [](FailureKind k) {
        return k == FailureKind::location_exceeded || k == FailureKind::location_inconsistent ||
               k == FailureKind::flips_exceeded || k == FailureKind::update_inconsistent ||
               k == FailureKind::hull_walk_exceeded || k == FailureKind::result_inconsistent;
    };
    const auto run = [&](auto kernel) {
        using K = decltype(kernel);
        MutableTriangulation<K> m(kernel);
        std::vector<std::uint32_t> ids;
        try {
            for (const Point2& p : s.points) ids.push_back(m.insert(p));
            for (std::size_t i = 0; i < ids.size(); i += 2) m.remove(ids[i]);
            for (std::size_t i = 0; i < ids.size(); i += 4) m.insert(s.points[i]);
        } catch (const FailureError& e) {
            RC_ASSERT(typed(e.failure.kind));
            RC_ASSERT_THROWS_AS(m.insert({0, 0}), std::logic_error);
            return;
        }
        try {
            (void)m.snapshot();  // the arrays, whatever the lies made of them
        } catch (const FailureError& e) {
            RC_ASSERT(e.failure.kind == FailureKind::result_inconsistent);
        }
    };
    run(DoubleKernel{});
    for (const auto mode :
         {LyingKernel::random, LyingKernel::negative, LyingKernel::zero, LyingKernel::positive,
          LyingKernel::random_orient, LyingKernel::always_flip}) {
        run(LyingKernel{mode});
    }
}

TEST(Mutable, ManyRandomOperationsStayDelaunay) {
    // A longer run than the properties: 20000 points, 10000 removed in random order, 5000
    // put back, certified at the end.
    const auto points = uniform_points(20000, 11);
    MutableTriangulation<AdaptiveKernel> m;
    std::vector<std::uint32_t> ids;
    for (const Point2& p : points) ids.push_back(m.insert(p));
    std::mt19937_64 rng(5);
    std::shuffle(ids.begin(), ids.end(), rng);
    for (std::size_t i = 0; i < 10000; ++i) m.remove(ids[i]);
    for (std::size_t i = 0; i < 5000; ++i) m.insert(points[i]);
    const auto s = m.snapshot();
    const auto c = delaunay::certify(s.points, s.triangulation);
    EXPECT_TRUE(c.ok()) << c.summary();
    const auto fresh = delaunay::triangulate(s.points, AdaptiveKernel{});
    EXPECT_EQ(fresh.triangulation.triangle_count(), s.triangulation.triangle_count());
}

}  // namespace
}  // namespace exidel::test
