// The randomized incremental algorithm (detail/randomized.hpp, `randomized`): the work of
// its history DAG against de Berg et al.'s analysis, the two in-circle policies deciding
// alike, degenerate fixtures (points on hull edges, cocircular points, collinear input,
// a point outside seeing much of the hull) certified and compared with CGAL, and kernels
// that lie: a typed failure or a result, never a crash.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "delaunay_support.hpp"
#include "lying_kernel.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/detail/randomized.hpp"
#include "exidel/delaunay/triangulate.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;
using exidel::test::EdgeSets;
using exidel::test::LyingKernel;
using exidel::test::uniform_points;
namespace rd = exidel::delaunay::detail;

Options randomized(InCirclePolicy policy = InCirclePolicy::determinant) {
    Options o;
    o.algorithm = Algorithm::randomized;
    o.incircle = policy;
    return o;
}

/// Runs `randomized` with Theorem 1 checked, certifies the result and compares it with
/// CGAL: forced edges always, triangles when no four points are cocircular.
template <class K = AdaptiveKernel>
Result check_fixture(const std::vector<Point2>& pts,
                     InCirclePolicy policy = InCirclePolicy::determinant) {
    Result r = triangulate<Instrumentation::theorem1>(pts, K{}, randomized(policy));
    EXPECT_TRUE(r.ok()) << (r.failure ? r.failure->message : "");
    if (!r.ok()) return r;
    EXPECT_EQ(r.algorithm, Algorithm::randomized);
    const Certificate c = certify(pts, r.triangulation);
    EXPECT_TRUE(c.ok()) << c.summary();
    EXPECT_EQ(r.counters.theorem1_violations, 0u);
    EXPECT_EQ(r.counters.theorem1_checks, r.counters.incircle_tests);
    EXPECT_EQ(r.counters.eroded_edges, 0u);
    EXPECT_EQ(r.counters.triangles_created - r.counters.triangles_destroyed,
              r.triangulation.triangle_count());
    const EdgeSets oracle = test::cgal_edge_sets(pts);
    const EdgeSets ours = test::edge_sets(pts, r.triangulation);
    EXPECT_EQ(ours.collinear, oracle.collinear);
    EXPECT_EQ(ours.forced, oracle.forced);
    if (ours.free_edges == 0) {
        EXPECT_EQ(ours.triangles, oracle.triangles);
    }
    return r;
}

/// check_fixture under both policies, which must give identical arrays.
void check_both_policies(const std::vector<Point2>& pts) {
    const Result det = check_fixture(pts, InCirclePolicy::determinant);
    const Result cos = check_fixture(pts, InCirclePolicy::cosine);
    EXPECT_EQ(det.triangulation.triangles, cos.triangulation.triangles);
    EXPECT_EQ(det.triangulation.halfedges, cos.triangulation.halfedges);
    EXPECT_EQ(det.triangulation.hull, cos.triangulation.hull);
}

// --- the order -------------------------------------------------------------------------

// The order is a permutation, fixed by the seed on every platform (own Fisher-Yates and
// splitmix64, nothing of the standard library's unspecified algorithms).
TEST(RandomizedOrder, IsAFixedPermutation) {
    const auto p = rd::random_order(1000, rd::randomized_seed);
    std::vector<std::uint32_t> sorted = p;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint32_t> identity(1000);
    std::iota(identity.begin(), identity.end(), 0u);
    EXPECT_EQ(sorted, identity);
    EXPECT_NE(p, identity);
    EXPECT_EQ(rd::random_order(1000, rd::randomized_seed), p);
    // splitmix64's published first outputs from state 0.
    rd::SplitMix64 rng{0};
    EXPECT_EQ(rng.next(), 0xe220a8397b1dcdafu);
    EXPECT_EQ(rng.next(), 0x6e789e6aa1b965f4u);
    EXPECT_EQ(rd::random_order(0, 1), std::vector<std::uint32_t>{});
    EXPECT_EQ(rd::random_order(1, 1), std::vector<std::uint32_t>{0});
}

TEST(RandomizedOrder, SameArraysOnEveryRun) {
    const auto pts = uniform_points(2000, 7);
    const Result a = triangulate(pts, AdaptiveKernel{}, randomized());
    const Result b = triangulate(pts, AdaptiveKernel{}, randomized());
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a.triangulation.triangles, b.triangulation.triangles);
    EXPECT_EQ(a.triangulation.halfedges, b.triangulation.halfedges);
}

// --- the work of the history DAG --------------------------------------------------------

// de Berg et al. (3rd ed.), Lemma 9.11: the expected number of triangles the algorithm
// creates is at most 9n + 1 (a split makes 3, each flip 2, and a random point's expected
// degree is below 6), the bound behind Theorem 9.12's O(n log n) expected time and O(n)
// expected storage; Lemma 9.13 bounds the point location by O(n log n) in total, so the
// steps per point grow like log n. Here the finite triangles created per point (ghosts
// are not counted) stay below 9 on uniform points, and ten times more points cost far
// less than ten times more steps per point.
// The 9 bounds an expectation, and the expectation is close to it: an interior point
// creates 2 deg - 3 triangles, and the mean degree is 6 - O(hull / n). A realisation
// fluctuates by a few sqrt(n) triangles around 9n - O(log^2 n); these fixed points give
// 8.947 n and 8.999 n (about 100 triangles below 9n at n = 10^5). Any correct
// implementation creates exactly these numbers for these points and this order (the
// sequence of Delaunay triangulations is determined), so the check is deterministic.
TEST(RandomizedWork, TrianglesCreatedAndLocationStepsMatchTheAnalysis) {
    double steps_per_point[2] = {0, 0};
    const std::size_t sizes[2] = {10'000, 100'000};
    for (int s = 0; s < 2; ++s) {
        const std::size_t n = sizes[s];
        const auto pts = uniform_points(n, 2025 + s);
        const Result r =
            triangulate<Instrumentation::counters>(pts, AdaptiveKernel{}, randomized());
        ASSERT_TRUE(r.ok()) << r.failure->message;
        const Counters& c = r.counters;
        EXPECT_EQ(c.triangles_created - c.triangles_destroyed, r.triangulation.triangle_count());
        const double created = double(c.triangles_created) / double(n);
        steps_per_point[s] = double(c.location_steps) / double(n);
        std::printf(
            "  n = %zu: triangles created %.3f n, flips %.3f n, location steps %.2f n, "
            "location orientations %.2f n\n",
            n, created, double(c.lawson_flips) / double(n), steps_per_point[s],
            double(c.location_orientations) / double(n));
        EXPECT_LT(created, 9.0);
        EXPECT_GT(created, 3.0);  // at least the split of every interior point
        EXPECT_EQ(c.eroded_edges, 0u);
        EXPECT_GT(c.lawson_flips, 0u);
    }
    // log(10^5) / log(10^4) = 1.25; linear growth would be 10.
    const double ratio = steps_per_point[1] / steps_per_point[0];
    EXPECT_GT(ratio, 1.0);
    EXPECT_LT(ratio, 2.0);
}

// --- policies ----------------------------------------------------------------------------

// Theorem 1's precondition holds at every legalization test, so with exact predicates
// the two policies take every decision alike: identical arrays, on every family.
RC_GTEST_PROP(RandomizedPolicies, CosineAndDeterminantGiveIdenticalArraysOnExactKernels, ()) {
    const auto s = *test::gen_point_set(40);
    RC_TAG(s.family);
    for (int kernel = 0; kernel < 2; ++kernel) {
        const auto run = [&](InCirclePolicy p) {
            return kernel == 0 ? triangulate<Instrumentation::theorem1>(s.points, GmpExactKernel{},
                                                                        randomized(p))
                               : triangulate<Instrumentation::theorem1>(s.points, AdaptiveKernel{},
                                                                        randomized(p));
        };
        const Result det = run(InCirclePolicy::determinant);
        const Result cos = run(InCirclePolicy::cosine);
        RC_ASSERT(det.ok());
        RC_ASSERT(cos.ok());
        RC_ASSERT(det.counters.theorem1_violations == 0u);
        RC_ASSERT(cos.counters.theorem1_violations == 0u);
        RC_ASSERT(det.triangulation.triangles == cos.triangulation.triangles);
        RC_ASSERT(det.triangulation.halfedges == cos.triangulation.halfedges);
        RC_ASSERT(det.triangulation.hull == cos.triangulation.hull);
        RC_ASSERT(det.counters.lawson_flips == cos.counters.lawson_flips);
    }
}

TEST(RandomizedPolicies, IdenticalOnUniformPoints) {
    check_both_policies(uniform_points(3000, 11));
}

// --- degenerate fixtures ------------------------------------------------------------------

// Many points on the edges of a square (collinear hull points: inserted on a hull edge,
// split its ghost; or outside it on its line, seeing no edge of that line), plus a few
// inside.
TEST(RandomizedFixtures, PointsOnHullEdges) {
    std::vector<Point2> pts;
    for (int i = 0; i <= 40; ++i) {
        pts.push_back({double(i), 0});
        pts.push_back({double(i), 40});
        pts.push_back({0, double(i)});
        pts.push_back({40, double(i)});
    }
    pts.push_back({13.5, 17.25});
    pts.push_back({30.125, 2.5});
    pts.push_back({1.0, 39.0});
    check_both_policies(pts);
    // Only the bottom edge and one point above it: every point but the apex is on the hull.
    std::vector<Point2> line;
    for (int i = 0; i < 100; ++i) line.push_back({double(i), 0});
    line.push_back({50.5, 3});
    const Result r = check_fixture(line);
    EXPECT_EQ(r.triangulation.hull.size(), line.size());
}

// Points on one circle: exactly cocircular (the 108 lattice points of radius 1105 =
// 5 * 13 * 17) and rounded (cos, sin). Every in-circle test is a tie or nearly one.
TEST(RandomizedFixtures, AllOnACircle) {
    std::vector<Point2> lattice;
    const long r = 1105;
    for (long x = -r; x <= r; ++x) {
        const long y2 = r * r - x * x;
        const long y = std::lround(std::sqrt(double(y2)));
        if (y * y != y2) continue;
        lattice.push_back({double(x), double(y)});
        if (y != 0) lattice.push_back({double(x), double(-y)});
    }
    ASSERT_EQ(lattice.size(), 108u);
    const Result exact = check_fixture(lattice);
    EXPECT_EQ(exact.counters.lawson_flips, 0u);  // nothing is strictly inside any circle
    EXPECT_EQ(exact.triangulation.hull.size(), lattice.size());
    check_both_policies(lattice);

    std::vector<Point2> rounded;
    for (int i = 0; i < 500; ++i) {
        const double t = 2 * std::numbers::pi * i / 500;
        rounded.push_back({std::cos(t), std::sin(t)});
    }
    check_both_policies(rounded);
    check_fixture<GmpExactKernel>(std::vector<Point2>(rounded.begin(), rounded.begin() + 60));
}

// An integer grid: every square is cocircular.
TEST(RandomizedFixtures, Grid) {
    std::vector<Point2> pts;
    for (int x = 0; x < 30; ++x) {
        for (int y = 0; y < 20; ++y) pts.push_back({double(x), double(y)});
    }
    const Result r = check_fixture(pts);
    EXPECT_EQ(r.triangulation.triangle_count(), 2u * 29 * 19);
    EXPECT_EQ(r.triangulation.hull.size(), 2u * (29 + 19));
    check_both_policies(pts);
}

// All points on a line but one, on either side of it and beyond either end; and all of
// them on a line: no triangle.
TEST(RandomizedFixtures, CollinearPlusOne) {
    for (const Point2 apex : {Point2{7.5, 1}, Point2{7.5, -1}, Point2{-3, 2}, Point2{100, -0.5}}) {
        std::vector<Point2> pts;
        for (int i = 0; i < 60; ++i) pts.push_back({0.25 * i, 0.5 * i});
        pts.push_back(apex);
        const Result r = check_fixture(pts);
        EXPECT_EQ(r.triangulation.triangle_count(), 59u);
    }
    std::vector<Point2> line;
    for (int i = 0; i < 50; ++i) line.push_back({3.0 * i, -1.0 * i});
    const Result r = check_fixture(line);
    EXPECT_TRUE(r.triangulation.collinear);
    EXPECT_TRUE(r.triangulation.triangles.empty());
}

// Points on a convex arc and one point far outside it that sees the whole arc: whenever
// it comes in the order, it sees every arc edge inserted so far (a fan of many
// triangles), and the arc points after it are located through that fan. Several sizes,
// so that the far point comes early and late in the order.
TEST(RandomizedFixtures, OutsidePointSeeingManyHullEdges) {
    std::uint64_t most_visible_tests = 0;
    for (const int n : {20, 57, 100, 161, 300}) {
        std::vector<Point2> pts;
        for (int i = 0; i < n; ++i) {
            const double t = std::numbers::pi * (1.05 + 0.9 * i / (n - 1));
            pts.push_back({std::cos(t), std::sin(t)});
        }
        pts.push_back({0.1, -1000});
        const Result r = check_fixture(pts);
        check_both_policies(pts);
        most_visible_tests = std::max(most_visible_tests, r.counters.tangent_orientations);
    }
    EXPECT_GT(most_visible_tests, 100u);
}

// The same at a size where testing a fan's children one by one would be quadratic: the
// binary search over the fan keeps location near n log n.
TEST(RandomizedFixtures, LocationThroughALargeFanStaysCheap) {
    const int n = 20'000;
    std::vector<Point2> pts;
    for (int i = 0; i < n; ++i) {
        const double t = std::numbers::pi * (1.05 + 0.9 * i / (n - 1));
        pts.push_back({std::cos(t), std::sin(t)});
    }
    pts.push_back({0.1, -1000});
    const Result r = triangulate<Instrumentation::counters>(pts, AdaptiveKernel{}, randomized());
    ASSERT_TRUE(r.ok()) << r.failure->message;
    EXPECT_TRUE(certify(pts, r.triangulation).ok());
    EXPECT_LT(double(r.counters.location_orientations) / n, 400.0);
}

// --- kernels that lie --------------------------------------------------------------------

// Whatever the kernel answers, a result or a typed failure: algorithms_test.cpp,
// EveryAlgorithm.LyingKernelGivesAResultOrATypedFailure.

// Named outcomes: a kernel that calls every point inside every circle makes each
// insertion flip until the bound; one that calls everything collinear gives the chain.
TEST(RandomizedInconsistentKernel, EndlessFlipsAreBounded) {
    const auto pts = uniform_points(300, 3);
    const Result r = triangulate(pts, LyingKernel{LyingKernel::always_flip}, randomized());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.failure->kind, FailureKind::flips_exceeded);
    EXPECT_NE(r.failure->message.find("insertion of point"), std::string::npos);
    EXPECT_LT(r.failure->insertion, pts.size());
    EXPECT_LT(r.failure->input_index, pts.size());

    const Result flat = triangulate(pts, LyingKernel{LyingKernel::zero}, randomized());
    ASSERT_TRUE(flat.ok());
    EXPECT_TRUE(flat.triangulation.collinear);

    const Result lost = triangulate(pts, LyingKernel{LyingKernel::negative}, randomized());
    ASSERT_FALSE(lost.ok());
    EXPECT_EQ(lost.failure->kind, FailureKind::location_exceeded);
}

TEST(RandomizedInconsistentKernel, DoubleKernelOnNearlyDegenerateInput) {
    // Points on a line up to rounding, and a near-cocircular ring: the double kernel's
    // wrong signs give a result or a typed failure.
    std::vector<Point2> pts;
    for (int i = 0; i < 400; ++i) {
        const double x = 0.5 + i * 1e-17 * 7;
        pts.push_back({x, 12.0 - x});
        const double t = 2 * std::numbers::pi * i / 400;
        pts.push_back({1e6 + std::cos(t), 1e6 + std::sin(t)});
    }
    for (const InCirclePolicy p : {InCirclePolicy::determinant, InCirclePolicy::cosine}) {
        const Result r = triangulate(pts, DoubleKernel{}, randomized(p));
        if (r.ok()) {
            EXPECT_EQ(r.triangulation.triangles.size(), r.triangulation.halfedges.size());
        } else {
            EXPECT_FALSE(r.failure->message.empty());
        }
    }
}

}  // namespace
