// Named fixtures of exidel::delaunay::triangulate: input handling, the seed, degenerate
// inputs with known answers, and the counts of docs/background.md section 5.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;

// These fixtures describe the paper's algorithm: its order is asked for explicitly
// (the default strategy is automatic; strategies_test.cpp covers the others).
constexpr Options paper{InCirclePolicy::determinant, Strategy::lexicographic};

Result run_certified(const std::vector<Point2>& pts,
                     InCirclePolicy policy = InCirclePolicy::determinant) {
    Result r = triangulate<Instrumentation::theorem1>(pts, AdaptiveKernel{},
                                                      Options{policy, Strategy::lexicographic});
    EXPECT_TRUE(r.ok()) << (r.failure ? r.failure->message : "");
    const Certificate c = certify(pts, r.triangulation);
    EXPECT_TRUE(c.ok()) << c.summary();
    EXPECT_EQ(r.counters.theorem1_violations, 0u);
    return r;
}

TEST(DelaunayInput, NonFiniteCoordinateIsRejectedNamingTheFirstBadIndex) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<Point2> pts{{0, 0}, {1, 0}, {0, inf}, {nan, 1}, {1, 1}};
    const Result r = triangulate(pts, AdaptiveKernel{});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.failure->kind, FailureKind::non_finite_input);
    EXPECT_EQ(r.failure->input_index, 2u);
    EXPECT_NE(r.failure->message.find('2'), std::string::npos);
    EXPECT_TRUE(r.triangulation.triangles.empty());
}

TEST(DelaunayInput, EmptyOneAndTwoPointsHaveNoTriangles) {
    for (const std::vector<Point2>& pts : {std::vector<Point2>{}, std::vector<Point2>{{3, 4}},
                                           std::vector<Point2>{{3, 4}, {-1, 2}}}) {
        const Result r = run_certified(pts);
        EXPECT_TRUE(r.triangulation.collinear);
        EXPECT_TRUE(r.triangulation.triangles.empty());
        EXPECT_EQ(r.triangulation.hull.size(), pts.size());
    }
    // The chain of two points is in lexicographic order.
    EXPECT_EQ(run_certified({{3, 4}, {-1, 2}}).triangulation.hull,
              (std::vector<std::uint32_t>{1, 0}));
}

TEST(DelaunayInput, DuplicatesMapToTheFirstOccurrence) {
    const std::vector<Point2> pts{{0, 0}, {1, 0}, {0, 1}, {1, 0}, {-0.0, 0.0}, {0, 1}, {1, 0}};
    const Result r = run_certified(pts);
    EXPECT_EQ(r.triangulation.triangle_count(), 1u);
    EXPECT_EQ(r.triangulation.vertex_of_input, (std::vector<std::uint32_t>{0, 1, 2, 1, 0, 2, 1}));
    EXPECT_EQ(r.triangulation.duplicates, (std::vector<std::uint32_t>{3, 4, 5, 6}));
    EXPECT_EQ(r.triangulation.hull, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(DelaunayInput, AllCollinearGivesTheChainAndNoTriangles) {
    std::vector<Point2> pts;
    for (int i = 9; i >= 0; --i) pts.push_back({0.5 * i, 0.25 * i});
    pts.push_back(pts[3]);
    const Result r = run_certified(pts);
    EXPECT_TRUE(r.triangulation.collinear);
    EXPECT_TRUE(r.triangulation.triangles.empty());
    EXPECT_EQ(r.triangulation.hull, (std::vector<std::uint32_t>{9, 8, 7, 6, 5, 4, 3, 2, 1, 0}));
}

// The seed of a collinear prefix P0..P(k-1) is the fan from Pk (the paper's "try to
// create a triangle" with k1 > 3), on either side of the line, and every collinear
// point stays a hull vertex.
TEST(DelaunaySeed, CollinearPrefixIsFannedFromTheFirstPointOffTheLine) {
    for (const double side : {1.0, -1.0}) {
        const std::vector<Point2> pts{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, side}, {5, 0.5 * side}};
        const Result r = run_certified(pts);
        EXPECT_EQ(r.counters.seed_orientations, 3u);  // k1 - 2 with k1 = 5
        const auto& hull = r.triangulation.hull;
        for (std::uint32_t v : {0u, 1u, 2u, 3u}) {
            EXPECT_NE(std::find(hull.begin(), hull.end(), v), hull.end()) << v;
        }
    }
}

// A point collinear with a hull edge connects to the nearer endpoint: (2, 0) sees no
// edge strictly, so the collinear hull vertex (1, 0) stays and gets the edge.
TEST(DelaunayTangents, PointCollinearWithAHullEdgeConnectsToTheNearerEndpoint) {
    const std::vector<Point2> pts{{0, 0}, {0, 1}, {1, 0}, {2, 0}};
    const Result r = run_certified(pts);
    EXPECT_EQ(r.triangulation.hull, (std::vector<std::uint32_t>{0, 2, 3, 1}));
    const auto edges = test::edge_sets(pts, r.triangulation);
    EXPECT_TRUE(edges.forced.count(test::make_edge(2, 3)));
    EXPECT_FALSE(edges.forced.count(test::make_edge(0, 3)));
}

// Cocircular input: points on the circle keep their edge, so the answer is a valid
// triangulation and the same on every run and under both policies.
TEST(DelaunayCocircular, RegularOctagonOnALatticeCircleIsDeterministic) {
    const std::vector<Point2> pts{{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                                  {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    const Result det = run_certified(pts, InCirclePolicy::determinant);
    const Result cos = run_certified(pts, InCirclePolicy::cosine);
    EXPECT_EQ(det.triangulation.triangles, cos.triangulation.triangles);
    EXPECT_EQ(det.triangulation.triangle_count(), pts.size() - 2);
    EXPECT_EQ(det.counters.eroded_edges, 0u);  // nothing is strictly inside any circle
}

TEST(DelaunayCocircular, IntegerGridSquares) {
    std::vector<Point2> pts;
    for (int x = 0; x < 7; ++x) {
        for (int y = 0; y < 5; ++y) pts.push_back({double(x), double(y)});
    }
    const Result r = run_certified(pts);
    EXPECT_EQ(r.triangulation.triangle_count(), 2u * 6 * 4);
    EXPECT_EQ(r.triangulation.hull.size(), 2u * (6 + 4));
}

// docs/background.md section 5: inserting the left branch of a parabola in ascending x rebuilds the
// whole triangulation every time, (n-2)(n-3)/2 destroyed triangles in total.
TEST(DelaunayCounts, AscendingParabolaLeftBranchDestroysQuadraticallyMany) {
    const int n = 60;
    std::vector<Point2> pts;
    for (int i = 0; i < n; ++i) {
        const double x = -n + i;
        pts.push_back({x, x * x});
    }
    const Result r = run_certified(pts);
    EXPECT_EQ(r.counters.triangles_destroyed, std::uint64_t((n - 2) * (n - 3) / 2));
}

// The certifier accepts what MpfrKernel produces at a generous precision.
TEST(DelaunayKernels, MpfrKernelObjectIsAccepted) {
    const std::vector<Point2> pts{{0, 0}, {1, 0.1}, {0.3, 1}, {0.5, 0.5}, {2, 2}, {-1, 0.7}};
    const Result r = triangulate(pts, MpfrKernel(400), paper);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(certify(pts, r.triangulation).ok());
}

// Regression fixtures for the plain double kernel, found by the DelaunayInexactKernels
// survey on the kettner family: p = (0.5, 0.5) moved up by j ulps, with (12, 12),
// (24, 24), (2, 2), (6, 6) on the diagonal. The exact answer is a proper triangulation
// (p is off the line); the double kernel must give a wrong answer the certifier names,
// or stop with a typed failure, and never crash.
std::vector<Point2> kettner_diagonal(int ulps_up) {
    Point2 p{0.5, 0.5};
    for (int s = 0; s < ulps_up; ++s) p.y = std::nextafter(p.y, 1.0);
    return {p, {12, 12}, {24, 24}, {2, 2}, {6, 6}};
}

TEST(DelaunayDoubleKernelRegression, KettnerOneUlpAboveIsWronglyCalledCollinear) {
    const auto pts = kettner_diagonal(1);
    EXPECT_FALSE(run_certified(pts).triangulation.collinear);
    const Result r = triangulate(pts, DoubleKernel{}, paper);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.triangulation.collinear);
    const Certificate c = certify(pts, r.triangulation);
    ASSERT_TRUE(c.has(FindingKind::collinear_mismatch)) << c.summary();
    EXPECT_EQ(c.findings.front().index, 3);  // (2, 2): off the line through p and (24, 24)
}

TEST(DelaunayDoubleKernelRegression, KettnerTwoUlpsAboveReportsNoVisibleEdge) {
    const auto pts = kettner_diagonal(2);
    run_certified(pts);
    const Result r = triangulate(pts, DoubleKernel{}, paper);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.failure->kind, FailureKind::no_visible_edge);
    EXPECT_EQ(r.failure->insertion, 3u);  // the fourth point in sorted order, (12, 12)
    EXPECT_EQ(r.failure->input_index, 1u);
}

}  // namespace
