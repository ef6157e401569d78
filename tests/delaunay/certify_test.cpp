// The certifier must catch planted defects and say which check failed where.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>
#include <random>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;

std::vector<Point2> uniform(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point2> p(n);
    for (auto& q : p) q = {u(rng), u(rng)};
    return p;
}

Triangulation triangulated(const std::vector<Point2>& pts) {
    Result r = triangulate(pts, AdaptiveKernel{});
    EXPECT_TRUE(r.ok());
    EXPECT_TRUE(certify(pts, r.triangulation).ok());
    return std::move(r.triangulation);
}

// Recomputes every twin from the triangles (used after editing triangles by hand).
void rebuild_twins(Triangulation& t) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::int32_t> by_edge;
    for (std::size_t e = 0; e < t.triangles.size(); ++e) {
        by_edge[{t.triangles[e], t.triangles[next_halfedge(e)]}] = static_cast<std::int32_t>(e);
    }
    for (std::size_t e = 0; e < t.triangles.size(); ++e) {
        const auto it = by_edge.find({t.triangles[next_halfedge(e)], t.triangles[e]});
        t.halfedges[e] = it == by_edge.end() ? -1 : it->second;
    }
}

// An interior edge whose quadrilateral is strictly convex and not cocircular: flipping it
// keeps a valid triangulation that is not Delaunay.
std::size_t flippable_edge(const std::vector<Point2>& pts, const Triangulation& t) {
    for (std::size_t e = 0; e < t.halfedges.size(); ++e) {
        if (t.halfedges[e] < 0) continue;
        const auto tw = static_cast<std::size_t>(t.halfedges[e]);
        const Point2 a = pts[t.triangles[e]], b = pts[t.triangles[next_halfedge(e)]];
        const Point2 c = pts[t.triangles[prev_halfedge(e)]],
                     d = pts[t.triangles[prev_halfedge(tw)]];
        if (AdaptiveKernel::orient2d(c, d, a) != AdaptiveKernel::orient2d(c, d, b) &&
            AdaptiveKernel::orient2d(c, d, a) != Sign::zero &&
            AdaptiveKernel::orient2d(c, d, b) != Sign::zero &&
            AdaptiveKernel::incircle(a, b, c, d) != Sign::zero) {
            return e;
        }
    }
    ADD_FAILURE() << "no flippable edge";
    return 0;
}

TEST(Certify, CatchesAFlippedDelaunayEdge) {
    const auto pts = uniform(60, 1);
    Triangulation t = triangulated(pts);
    const std::size_t e = flippable_edge(pts, t);
    const auto tw = static_cast<std::size_t>(t.halfedges[e]);
    // Triangles (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c).
    const std::uint32_t a = t.triangles[e], b = t.triangles[next_halfedge(e)];
    const std::uint32_t c = t.triangles[prev_halfedge(e)], d = t.triangles[prev_halfedge(tw)];
    const std::size_t t0 = 3 * (e / 3), t1 = 3 * (tw / 3);
    t.triangles[t0] = c, t.triangles[t0 + 1] = a, t.triangles[t0 + 2] = d;
    t.triangles[t1] = d, t.triangles[t1 + 1] = b, t.triangles[t1 + 2] = c;
    rebuild_twins(t);
    const Certificate cert = certify(pts, t);
    ASSERT_FALSE(cert.ok());
    EXPECT_EQ(cert.total_findings, 1u) << cert.summary();
    ASSERT_TRUE(cert.has(FindingKind::not_delaunay)) << cert.summary();
    const Finding& f = cert.findings.front();
    const auto fe = static_cast<std::size_t>(f.index);
    EXPECT_EQ(test::make_edge(t.triangles[fe], t.triangles[next_halfedge(fe)]),
              test::make_edge(c, d));
}

TEST(Certify, CatchesADroppedPoint) {
    auto pts = uniform(40, 2);
    std::vector<Point2> fewer(pts.begin(), pts.end() - 1);
    const Triangulation t = triangulated(fewer);
    // Certified against the full input: the last point is missing.
    Triangulation shown = t;
    shown.vertex_of_input.push_back(static_cast<std::uint32_t>(pts.size() - 1));
    const Certificate cert = certify(pts, shown);
    ASSERT_TRUE(cert.has(FindingKind::missing_point)) << cert.summary();
    EXPECT_EQ(cert.findings.front().index, static_cast<std::int64_t>(pts.size() - 1));
}

TEST(Certify, CatchesABrokenTwin) {
    const auto pts = uniform(40, 3);
    Triangulation t = triangulated(pts);
    std::size_t e = 0;
    while (t.halfedges[e] < 0) ++e;
    const std::size_t other = e + 3 < t.halfedges.size() ? e + 3 : e - 3;
    t.halfedges[e] = static_cast<std::int32_t>(other);
    const Certificate cert = certify(pts, t);
    ASSERT_TRUE(cert.has(FindingKind::twin_mismatch)) << cert.summary();
    EXPECT_EQ(cert.findings.front().index, static_cast<std::int64_t>(e));
}

TEST(Certify, CatchesAReversedTriangle) {
    const auto pts = uniform(40, 4);
    Triangulation t = triangulated(pts);
    std::swap(t.triangles[3 * 5 + 1], t.triangles[3 * 5 + 2]);
    rebuild_twins(t);
    const Certificate cert = certify(pts, t);
    EXPECT_FALSE(cert.ok());
    EXPECT_TRUE(cert.has(FindingKind::not_ccw) || cert.has(FindingKind::twin_mismatch))
        << cert.summary();
    // With the twins left as they were, the reversal breaks them: found as such.
    Triangulation raw = triangulated(pts);
    std::swap(raw.triangles[3 * 5 + 1], raw.triangles[3 * 5 + 2]);
    EXPECT_TRUE(certify(pts, raw).has(FindingKind::twin_mismatch));
}

TEST(Certify, CatchesAWrongHullAndAnOutOfRangeIndex) {
    const auto pts = uniform(30, 5);
    Triangulation t = triangulated(pts);
    std::rotate(t.hull.begin(), t.hull.begin() + 1, t.hull.end());
    EXPECT_TRUE(certify(pts, t).has(FindingKind::hull_mismatch));
    Triangulation u = triangulated(pts);
    u.triangles[7] = 1000;
    EXPECT_TRUE(certify(pts, u).has(FindingKind::index_out_of_range));
    Triangulation v = triangulated(pts);
    v.halfedges.pop_back();
    EXPECT_TRUE(certify(pts, v).has(FindingKind::bad_shape));
}

TEST(Certify, CatchesADroppedTriangleAsABrokenBoundary) {
    const auto pts = uniform(30, 6);
    Triangulation t = triangulated(pts);
    // Remove an interior triangle (no boundary edge): a hole.
    std::size_t tri = 0;
    for (; tri < t.triangle_count(); ++tri) {
        if (t.halfedges[3 * tri] >= 0 && t.halfedges[3 * tri + 1] >= 0 &&
            t.halfedges[3 * tri + 2] >= 0)
            break;
    }
    t.triangles.erase(t.triangles.begin() + 3 * tri, t.triangles.begin() + 3 * tri + 3);
    t.halfedges.resize(t.triangles.size());
    rebuild_twins(t);
    const Certificate cert = certify(pts, t);
    EXPECT_TRUE(cert.has(FindingKind::boundary_broken)) << cert.summary();
}

TEST(Certify, CatchesAConcaveBoundary) {
    // A valid-looking fan that misses the hull triangle on one side: (0,0) (2,0) (1,1)
    // and (1,1) (2,0) (2,2), leaving the point (0,2) out and the boundary concave if it
    // were included. Here: the square with a notch, boundary turns right at (1,1).
    const std::vector<Point2> pts{{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}};
    Triangulation t;
    t.triangles = {0, 1, 3, 1, 2, 3, 3, 2, 4};
    t.halfedges.assign(9, -1);
    rebuild_twins(t);
    t.hull = {0, 1, 2, 4, 3};
    const Certificate cert = certify(pts, t);
    EXPECT_TRUE(cert.has(FindingKind::boundary_not_convex)) << cert.summary();
}

TEST(Certify, CollinearFlagMustMatchThePoints) {
    const std::vector<Point2> pts{{0, 0}, {1, 1}, {2, 2.5}};
    Triangulation t;
    t.collinear = true;
    t.hull = {0, 1, 2};
    EXPECT_TRUE(certify(pts, t).has(FindingKind::collinear_mismatch));
    // The chain is in lexicographic order: (0,0), (1,1), (2,2) are inputs 0, 2, 1.
    const std::vector<Point2> line{{0, 0}, {2, 2}, {1, 1}};
    t.hull = {0, 1, 2};
    EXPECT_TRUE(certify(line, t).has(FindingKind::hull_mismatch));
    t.hull = {0, 2, 1};
    EXPECT_TRUE(certify(line, t).ok()) << certify(line, t).summary();
}

// Every single-entry corruption of a valid triangulation that changes anything is found.
RC_GTEST_PROP(Certify, AnyCorruptedEntryIsFound, ()) {
    const auto pts =
        uniform(*rc::gen::inRange<std::size_t>(4, 40), *rc::gen::arbitrary<std::uint32_t>());
    Result r = triangulate(pts, AdaptiveKernel{});
    RC_ASSERT(r.ok());
    Triangulation t = r.triangulation;
    RC_PRE(!t.collinear);
    const bool vertex = *rc::gen::arbitrary<bool>();
    const std::size_t e = *rc::gen::inRange<std::size_t>(0, t.triangles.size());
    if (vertex) {
        const auto v = *rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(pts.size()));
        RC_PRE(v != t.triangles[e]);
        t.triangles[e] = v;
    } else {
        const auto h =
            *rc::gen::inRange<std::int32_t>(-1, static_cast<std::int32_t>(t.halfedges.size()));
        RC_PRE(h != t.halfedges[e]);
        t.halfedges[e] = h;
    }
    RC_ASSERT(!certify(pts, t).ok());
}

}  // namespace
