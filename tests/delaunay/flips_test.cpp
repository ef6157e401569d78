// Lawson's algorithm, the sweep-hull and the divide and conquer (detail/lawson.hpp,
// sweep_hull.hpp, divide_and_conquer.hpp): the flip primitive on a quadrilateral, the
// flip counts against the paper's erosion in the same order, Theorem 1 at every in-circle
// test of the flipping algorithms, the work Dwyer's cuts save, and kernels that never
// stop asking for flips. Exactness on every family is algorithms_test.cpp's.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/detail/flips.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "lying_kernel.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;
using exidel::test::LyingKernel;
using exidel::test::uniform_points;
namespace dd = exidel::delaunay::detail;

Options with(Algorithm a, InCirclePolicy policy = InCirclePolicy::determinant) {
    Options o;
    o.algorithm = a;
    o.incircle = policy;
    return o;
}

std::vector<Point2> grid(int side) {
    std::vector<Point2> p;
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) p.push_back({double(i), double(j)});
    }
    return p;
}

// Two triangles (a, b, c) and (b, a, d) of the square a = (0, 0), b = (1, 1), c = (0, 1),
// d = (1, 0), sharing the diagonal a -> b: the flip makes them (d, b, c) and (c, a, d),
// keeps every twin and moves the hull edges that changed slots.
TEST(FlipEdge, ReplacesTheDiagonalAndKeepsTwinsAndHull) {
    dd::Mesh m;
    m.reset(4);
    const std::uint32_t a = 0, b = 1, c = 2, d = 3;
    m.add_triangle(a, b, c);  // half-edges 0: a->b, 1: b->c, 2: c->a
    m.add_triangle(b, a, d);  // 3: b->a, 4: a->d, 5: d->b
    m.link(0, 3);
    m.hull_edge[b] = 1;  // hull a -> d -> b -> c -> a
    m.hull_edge[c] = 2;
    m.hull_edge[a] = 4;
    m.hull_edge[d] = 5;
    dd::flip_edge(m, 0);
    EXPECT_EQ(m.triangles, (std::vector<std::uint32_t>{d, b, c, c, a, d}));
    // The new diagonal c -> d / d -> c is half-edges 2 and 5; the rest is hull.
    EXPECT_EQ(m.halfedges, (std::vector<std::int32_t>{-1, -1, 5, -1, -1, 2}));
    EXPECT_EQ(m.hull_edge[d], 0);  // d -> b moved from slot 5 to slot 0
    EXPECT_EQ(m.hull_edge[c], 3);  // c -> a moved from slot 2 to slot 3
    EXPECT_EQ(m.hull_edge[b], 1);
    EXPECT_EQ(m.hull_edge[a], 4);
}

// Lawson from the sorted fan flips, in total, what the paper's algorithm erodes in the
// same (lexicographic) order: on a grid exactly, s^3 / 2 to leading order (each column's
// first point is fanned to the whole previous column), on uniform points within a
// fraction of a percent. docs/research.md ("The work each algorithm does") explains the cost from
// this.
TEST(LawsonWork, FlipsFromTheSortedFanMatchThePapersLexicographicErosion) {
    auto erosions = [](const std::vector<Point2>& pts) {
        Options o = with(Algorithm::external);
        o.strategy = Strategy::lexicographic;
        const Result r = triangulate<Instrumentation::counters>(pts, AdaptiveKernel{}, o);
        EXPECT_TRUE(r.ok());
        return r.counters.eroded_edges;
    };
    for (const int side : {20, 40}) {
        const auto pts = grid(side);
        const Result r =
            triangulate<Instrumentation::counters>(pts, AdaptiveKernel{}, with(Algorithm::lawson));
        ASSERT_TRUE(r.ok());
        EXPECT_TRUE(certify(pts, r.triangulation).ok());
        const double s3 = double(side) * side * side;
        EXPECT_EQ(r.counters.lawson_flips, erosions(pts)) << side;
        EXPECT_GT(double(r.counters.lawson_flips), 0.4 * s3) << side;
        EXPECT_LT(double(r.counters.lawson_flips), 0.5 * s3) << side;
    }
    const auto pts = uniform_points(4000, 5);
    const Result r =
        triangulate<Instrumentation::counters>(pts, AdaptiveKernel{}, with(Algorithm::lawson));
    ASSERT_TRUE(r.ok());
    const double lex = double(erosions(pts));
    EXPECT_NEAR(double(r.counters.lawson_flips) / lex, 1.0, 0.01);
    std::printf(
        "lawson, 4000 uniform points: %.2f flips per point (paper's order: %.2f "
        "erosions)\n",
        double(r.counters.lawson_flips) / 4000, lex / 4000);
}

// Every in-circle test of Lawson and of the sweep-hull is across an edge of two valid
// triangles, so Theorem 1 holds at each, and the two policies give the same arrays.
TEST(FlippingAlgorithms, Theorem1HoldsAtEveryInCircleTestAndPoliciesAgree) {
    std::vector<std::vector<Point2>> sets{uniform_points(1500, 9), grid(12)};
    std::vector<Point2> circle;
    for (int i = 0; i < 64; ++i) {
        const int q[8][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}};
        circle.push_back({double(q[i % 8][0] * (1 + i / 8)), double(q[i % 8][1] * (1 + i / 8))});
    }
    sets.push_back(circle);  // concentric integer circles: many cocircular quadruples
    for (const Algorithm a : {Algorithm::lawson, Algorithm::sweep_hull}) {
        for (const auto& pts : sets) {
            const Result det =
                triangulate<Instrumentation::theorem1>(pts, AdaptiveKernel{}, with(a));
            const Result cos = triangulate<Instrumentation::theorem1>(
                pts, AdaptiveKernel{}, with(a, InCirclePolicy::cosine));
            ASSERT_TRUE(det.ok() && cos.ok()) << to_string(a);
            EXPECT_TRUE(certify(pts, det.triangulation).ok()) << to_string(a);
            EXPECT_EQ(det.counters.theorem1_checks, det.counters.incircle_tests);
            EXPECT_EQ(det.counters.theorem1_violations, 0u) << to_string(a);
            EXPECT_EQ(cos.counters.theorem1_violations, 0u) << to_string(a);
            EXPECT_EQ(det.triangulation.triangles, cos.triangulation.triangles) << to_string(a);
            EXPECT_EQ(det.triangulation.halfedges, cos.triangulation.halfedges) << to_string(a);
        }
    }
}

// Vertical cuts triangulate thin strips into slivers that the merges above delete;
// Dwyer's alternating cuts keep pieces square. Measured: about 4.8 deleted edges per
// point against 1.1 at 10^4 uniform points.
TEST(DivideAndConquerWork, AlternatingCutsDeleteFewerEdges) {
    const auto pts = uniform_points(10000, 4);
    const Result vertical = triangulate<Instrumentation::counters>(
        pts, AdaptiveKernel{}, with(Algorithm::divide_and_conquer));
    const Result dwyer =
        triangulate<Instrumentation::counters>(pts, AdaptiveKernel{}, with(Algorithm::dwyer));
    ASSERT_TRUE(vertical.ok() && dwyer.ok());
    EXPECT_EQ(vertical.triangulation.triangles.size(), dwyer.triangulation.triangles.size());
    EXPECT_LT(3 * dwyer.counters.merge_deleted_edges, vertical.counters.merge_deleted_edges);
    std::printf("10^4 uniform points, merge-deleted edges per point: vertical %.2f, dwyer %.2f\n",
                double(vertical.counters.merge_deleted_edges) / 1e4,
                double(dwyer.counters.merge_deleted_edges) / 1e4);
}

// A kernel that calls every point inside every circle: Lawson stops at its bound of
// n (n - 1) / 2 flips, the sweep-hull at the insertion whose flips outnumber the
// earlier points.
TEST(FlippingAlgorithms, EndlessFlipsAreBounded) {
    const auto pts = uniform_points(60, 3);
    const Result lawson =
        triangulate(pts, LyingKernel{LyingKernel::always_flip}, with(Algorithm::lawson));
    ASSERT_FALSE(lawson.ok());
    EXPECT_EQ(lawson.failure->kind, FailureKind::flips_exceeded);
    EXPECT_NE(lawson.failure->message.find("1770"), std::string::npos) << lawson.failure->message;
    const Result sweep =
        triangulate(pts, LyingKernel{LyingKernel::always_flip}, with(Algorithm::sweep_hull));
    ASSERT_FALSE(sweep.ok());
    EXPECT_EQ(sweep.failure->kind, FailureKind::flips_exceeded);
    EXPECT_NE(sweep.failure->message.find("insertion of point"), std::string::npos);
    EXPECT_LT(sweep.failure->input_index, pts.size());
}

// Found by EveryAlgorithm.AdaptiveMatchesCgal and ExactKernelsMatchCgal (kettner family,
// shrunk by RapidCheck): points on the diagonal y = x, two of them a few ulps off it.
// dwyer's median partition left a leaf of four points unsorted, and the radial sweep fanned
// its collinear first points out of order along their line: a clockwise triangle
// (certify: not_ccw). Leaves of more than three points are now sorted first.
TEST(DwyerRegression, UnsortedLeafOfNearlyCollinearPoints) {
    const std::vector<std::vector<Point2>> sets{
        {{0x1.00000000000e4p-1, 0x1.000000000009ap-1},
         {0x1.14ccccccccccdp+4, 0x1.14ccccccccccdp+4},
         {0x1.800000000000ep+4, 0x1.800000000000fp+4},
         {0x1p-1, 0x1p-1},
         {0x1p-1, 0x1p-1},
         {0x1p-1, 0x1p-1},
         {0x1.000000000004p-1, 0x1.000000000004p-1},
         {0x1.000000000008p-1, 0x1.000000000008p-1},
         {0x1p-1, 0x1p-1},
         {0x1p-1, 0x1p-1},
         {0x1.4856335aa011p+1, 0x1.4856335aa011p+1}},
        {{0x1.00000000000e4p-1, 0x1.000000000009ap-1},
         {0x1.14ccccccccccdp+4, 0x1.14ccccccccccdp+4},
         {0x1.800000000000ep+4, 0x1.800000000000fp+4},
         {0x1p-1, 0x1p-1},
         {0x1p-1, 0x1p-1},
         {0x1p-1, 0x1p-1},
         {0x1.000000000004p-1, 0x1.000000000004p-1},
         {0x1p-1, 0x1p-1},
         {0x1p-1, 0x1p-1},
         {0x1.00000000001p-1, 0x1.00000000001p-1},
         {0x1.657521c849ad8p+2, 0x1.657521c849ad8p+2},
         {0x1p-1, 0x1p-1},
         {0x1.000000000014p-1, 0x1.000000000014p-1},
         {0x1.000000000008p-1, 0x1.000000000008p-1}},
    };
    for (const auto& pts : sets) {
        for (const AlgorithmInfo& a : algorithms()) {
            for (const InCirclePolicy p : {InCirclePolicy::determinant, InCirclePolicy::cosine}) {
                const Result r = triangulate(pts, AdaptiveKernel{}, with(a.id, p));
                ASSERT_TRUE(r.ok()) << a.name;
                EXPECT_TRUE(certify(pts, r.triangulation).ok()) << a.name;
                const Result e = triangulate(pts, CppIntExactKernel{}, with(a.id, p));
                ASSERT_TRUE(e.ok()) << a.name;
                EXPECT_TRUE(certify(pts, e.triangulation).ok()) << a.name;
            }
        }
    }
}

}  // namespace
