// The furthest-site Delaunay triangulation (exidel/delaunay/furthest.hpp): on every family,
// every triangle counter-clockwise with every point on or inside its circumcircle (CGAL's
// exact side_of_oriented_circle), twins consistent, the boundary the hull of extreme
// points, h - 2 triangles; inexact and lying kernels give a result or a typed failure.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/furthest.hpp"
#include "lying_kernel.hpp"

namespace exidel::test {
namespace {

using delaunay::FurthestResult;

void check_furthest(std::span<const Point2> P, const delaunay::Triangulation& t) {
    const auto& T = t.triangles;
    const auto& H = t.halfedges;
    RC_ASSERT(T.size() == H.size());
    if (t.collinear) {
        RC_ASSERT(T.empty());
        return;
    }
    RC_ASSERT(T.size() / 3 == t.hull.size() - 2);
    std::set<Edge> boundary;
    for (std::size_t e = 0; e < T.size(); ++e) {
        if (H[e] < 0) {
            boundary.insert(make_edge(T[e], T[delaunay::next_halfedge(e)]));
        } else {
            const auto f = static_cast<std::size_t>(H[e]);
            RC_ASSERT(H[f] == static_cast<std::int32_t>(e));
            RC_ASSERT(T[f] == T[delaunay::next_halfedge(e)]);
            RC_ASSERT(T[delaunay::next_halfedge(f)] == T[e]);
        }
    }
    std::set<Edge> hull;
    for (std::size_t i = 0; i < t.hull.size(); ++i) {
        hull.insert(make_edge(t.hull[i], t.hull[(i + 1) % t.hull.size()]));
        // Every hull corner is strictly convex.
        const Point2 a = P[t.hull[(i + t.hull.size() - 1) % t.hull.size()]], b = P[t.hull[i]],
                     c = P[t.hull[(i + 1) % t.hull.size()]];
        RC_ASSERT(cgal_orient2d(a, b, c) == Sign::positive);
    }
    RC_ASSERT(boundary == hull);
    for (std::size_t e = 0; e < T.size(); e += 3) {
        const Point2 a = P[T[e]], b = P[T[e + 1]], c = P[T[e + 2]];
        RC_ASSERT(cgal_orient2d(a, b, c) == Sign::positive);
        for (const Point2& p : P) RC_ASSERT(cgal_incircle(a, b, c, p) != Sign::negative);
    }
}

RC_GTEST_PROP(Furthest, EveryFamilyGivesTheFurthestSiteTriangulation, ()) {
    const PointSet s = *gen_point_set(100);
    const FurthestResult r = delaunay::furthest_site_triangulation(s.points, AdaptiveKernel{});
    RC_ASSERT(r.ok());
    check_furthest(s.points, r.triangulation);
    const FurthestResult g = delaunay::furthest_site_triangulation(s.points, GmpExactKernel{});
    RC_ASSERT(g.ok());
    check_furthest(s.points, g.triangulation);
}

TEST(Furthest, RegularPolygonAndInteriorPoints) {
    // A square with interior points: the two triangles of the square (its corners are
    // cocircular, either diagonal is right); a point inside a hull edge is in neither.
    const std::vector<Point2> p = {{0, 0}, {2, 0}, {2, 2},     {0, 2},
                                   {1, 1}, {1, 0}, {0.5, 1.5}, {2, 2}};
    const FurthestResult r = delaunay::furthest_site_triangulation(p, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.triangulation.triangle_count(), 2u);
    EXPECT_EQ(r.triangulation.hull, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(r.triangulation.duplicates, (std::vector<std::uint32_t>{7}));
    const std::vector<Point2> line = {{0, 0}, {1, 1}, {2, 2}};
    EXPECT_TRUE(
        delaunay::furthest_site_triangulation(line, AdaptiveKernel{}).triangulation.collinear);
    const std::vector<Point2> bad = {{0, 0}, {1, NAN}, {2, 2}};
    const FurthestResult f = delaunay::furthest_site_triangulation(bad, AdaptiveKernel{});
    ASSERT_FALSE(f.ok());
    EXPECT_EQ(f.failure->kind, delaunay::FailureKind::non_finite_input);
}

TEST(Furthest, LyingKernelsStopOrAnswer) {
    std::vector<Point2> p;
    for (int i = 0; i < 200; ++i) p.push_back({std::cos(i * 0.0314), std::sin(i * 0.0314) * 0.5});
    for (const auto mode : {LyingKernel::random, LyingKernel::negative, LyingKernel::positive,
                            LyingKernel::zero, LyingKernel::random_orient}) {
        const FurthestResult r = delaunay::furthest_site_triangulation(p, LyingKernel{mode});
        if (!r.ok()) {
            EXPECT_TRUE(r.failure->kind == delaunay::FailureKind::flips_exceeded ||
                        r.failure->kind == delaunay::FailureKind::hull_walk_exceeded)
                << delaunay::to_string(r.failure->kind);
        }
    }
}

}  // namespace
}  // namespace exidel::test
