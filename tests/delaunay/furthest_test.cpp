// The furthest-site Delaunay triangulation (exidel/delaunay/furthest.hpp): on every family,
// every triangle counter-clockwise with every point on or inside its circumcircle (CGAL's
// exact side_of_oriented_circle), twins consistent, the boundary the hull of extreme
// points, h - 2 triangles; inexact and lying kernels give a result or a typed failure.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/furthest.hpp"
#include "exidel/delaunay/voronoi.hpp"
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

RC_GTEST_PROP(Furthest, VoronoiRegionsOnEveryFamily, ()) {
    // The furthest-site diagram (voronoi.hpp): vertices the correctly rounded centres of
    // the triangles, a region (unbounded) exactly for the extreme points, each of its
    // vertices having its site among theirs, counter-clockwise with its rays.
    const PointSet s = *gen_point_set(80);
    const FurthestResult r = delaunay::furthest_site_triangulation(s.points, AdaptiveKernel{});
    RC_ASSERT(r.ok());
    const delaunay::Triangulation& t = r.triangulation;
    delaunay::VoronoiDiagram d;
    try {
        d = delaunay::furthest_site_voronoi(s.points, t, AdaptiveKernel{});
    } catch (const delaunay::VoronoiError&) {
        RC_DISCARD("a centre beyond the largest double");
    }
    const std::size_t n = s.points.size();
    std::vector<std::uint8_t> extreme(n, 0);
    for (const std::uint32_t v : t.triangles) extreme[v] = 1;
    if (t.collinear && n > 0) {  // the two ends of the line
        const auto lex = [&](std::uint32_t a, std::uint32_t b) {
            return std::pair(s.points[a].x, s.points[a].y) <
                   std::pair(s.points[b].x, s.points[b].y);
        };
        std::vector<std::uint32_t> all(n);
        for (std::uint32_t i = 0; i < n; ++i) all[i] = i;
        extreme[t.vertex_of_input[*std::min_element(all.begin(), all.end(), lex)]] = 1;
        extreme[t.vertex_of_input[*std::max_element(all.begin(), all.end(), lex)]] = 1;
    }
    for (std::size_t tr = 0; tr < t.triangle_count(); ++tr) {
        const Point2 c =
            circumcenter(s.points[t.triangles[3 * tr]], s.points[t.triangles[3 * tr + 1]],
                         s.points[t.triangles[3 * tr + 2]])
                .point;
        const Point2 v = d.vertices[d.vertex_of_triangle[tr]];
        RC_ASSERT(v.x == c.x && v.y == c.y);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t site = t.vertex_of_input[i];
        RC_ASSERT((d.unbounded[i] != 0) == (extreme[site] != 0));
        const auto cell = d.cell(i);
        if (t.collinear || !extreme[site]) {
            RC_ASSERT(cell.empty());
            continue;
        }
        RC_ASSERT(!cell.empty());
        for (const std::uint32_t v : cell) {
            const auto sites = d.vertex_sites(v);
            RC_ASSERT(std::find(sites.begin(), sites.end(), site) != sites.end());
        }
        // Counter-clockwise: the polygon from far along the entry ray, through the
        // vertices, to far along the exit ray.
        std::vector<Point2> poly;
        const Point2 first = d.vertices[cell.front()], last = d.vertices[cell.back()];
        double scale = 1;
        for (const std::uint32_t v : cell)
            scale = std::max({scale, std::abs(d.vertices[v].x), std::abs(d.vertices[v].y)});
        const auto far = [&](Point2 p, Point2 ray, double sign) {
            const double len = std::hypot(ray.x, ray.y);
            return Point2{p.x + sign * ray.x / len * 4 * scale,
                          p.y + sign * ray.y / len * 4 * scale};
        };
        poly.push_back(far(first, d.entry_ray[i], 1));
        for (const std::uint32_t v : cell) poly.push_back(d.vertices[v]);
        poly.push_back(far(last, d.exit_ray[i], 1));
        long double area = 0;
        for (std::size_t j = 0; j < poly.size(); ++j) {
            const Point2 a = poly[j], b = poly[(j + 1) % poly.size()];
            area += static_cast<long double>(a.x) * b.y - static_cast<long double>(a.y) * b.x;
        }
        // Exactly: the region's directions to infinity, from exit_ray to entry_ray, turn
        // counter-clockwise (the hull's corners are strictly convex): the boundary comes
        // in along -entry_ray and leaves along exit_ray with the region on its left.
        // (The rays are rounded differences, exact in sign only: where the corner is
        // nearly flat their rounded directions may cross, so only clear turns count.)
        const Point2 a = d.exit_ray[i], b = d.entry_ray[i];
        const double turn = a.x * b.y - a.y * b.x;
        if (std::abs(turn) > 1e-10 * std::hypot(a.x, a.y) * std::hypot(b.x, b.y)) {
            RC_ASSERT(turn > 0);
            if (scale < 1e6) RC_ASSERT(area > 0);  // well-conditioned: rounding cannot matter
        }
    }
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
