// The Voronoi diagram against independent exact checks and CGAL's Voronoi_diagram_2.
//
// For every point family, with the exact kernels: every vertex is the correctly rounded
// exact circumcentre of its sites (CGAL's rational construction rounded by MPFR), its
// sites are exactly the input points at the minimum distance from that exact centre
// (so the circle is empty and no equidistant site is missing), counter-clockwise; the
// vertices are one per distinct exact circumcentre of the Delaunay triangles (the maximal
// cocircular groups); every cell lists exactly the vertices its site belongs to,
// counter-clockwise around the site; and CGAL's adaptor with its exact degeneracy removal
// has the same vertices (as sets of sites) and the same unbounded cells.
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_adaptation_policies_2.h>
#include <CGAL/Delaunay_triangulation_adaptation_traits_2.h>
#include <CGAL/Voronoi_diagram_2.h>
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "circumcenter_oracle.hpp"
#include "delaunay_support.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/predicates/all.hpp"

namespace exidel::test {
namespace {

using delaunay::Triangulation;
using delaunay::VoronoiDiagram;
using Q = CGAL::Gmpq;
using ExactPoint = std::pair<Q, Q>;

Q squared_distance(const ExactPoint& c, Point2 p) {
    const Q dx = Q(p.x) - c.first, dy = Q(p.y) - c.second;
    return dx * dx + dy * dy;
}

int exact_orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
    const Q d =
        (b.first - a.first) * (c.second - a.second) - (b.second - a.second) * (c.first - a.first);
    return CGAL::sign(d);
}

ExactPoint exact(Point2 p) { return {Q(p.x), Q(p.y)}; }

/// Checks one diagram of `points` (triangulated by `t`) with RC_ASSERT.
void check_diagram(std::span<const Point2> points, const Triangulation& t,
                   const VoronoiDiagram& d) {
    const std::size_t n = points.size();
    RC_ASSERT(d.site_count() == n);
    RC_ASSERT(d.unbounded.size() == n);
    if (t.collinear) {
        RC_ASSERT(d.collinear);
        RC_ASSERT(d.vertex_count() == 0u);
        for (std::size_t i = 0; i < n; ++i) RC_ASSERT(d.cell(i).empty() && d.unbounded[i] == 1);
        return;
    }
    // The exact centre of every Delaunay triangle; the distinct ones are the vertices.
    std::map<ExactPoint, std::size_t> distinct;
    std::vector<ExactPoint> centre_of_vertex(d.vertex_count());
    for (std::size_t tr = 0; tr < t.triangle_count(); ++tr) {
        const auto c =
            exact_circumcenter(points[t.triangles[3 * tr]], points[t.triangles[3 * tr + 1]],
                               points[t.triangles[3 * tr + 2]]);
        RC_ASSERT(c.has_value());
        const std::uint32_t v = d.vertex_of_triangle[tr];
        RC_ASSERT(v < d.vertex_count());
        const auto [it, fresh] = distinct.emplace(*c, v);
        RC_ASSERT(it->second == v);  // one exact centre, one vertex
        centre_of_vertex[v] = *c;
    }
    RC_ASSERT(distinct.size() == d.vertex_count());

    std::vector<std::set<std::uint32_t>> vertices_of_site(n);
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        const ExactPoint& c = centre_of_vertex[v];
        // Correctly rounded.
        RC_ASSERT(d.vertices[v].x == round_to_double(c.first));
        RC_ASSERT(d.vertices[v].y == round_to_double(c.second));
        // The sites: exactly the points at the minimum distance.
        Q best = squared_distance(c, points[0]);
        for (const Point2& p : points) best = std::min(best, squared_distance(c, p));
        std::set<std::uint32_t> nearest;
        for (std::size_t i = 0; i < n; ++i)
            if (squared_distance(c, points[i]) == best)
                nearest.insert(static_cast<std::uint32_t>(i));
        const auto sites = d.vertex_sites(v);
        RC_ASSERT(std::set<std::uint32_t>(sites.begin(), sites.end()) == nearest);
        RC_ASSERT(nearest.size() == sites.size());
        // Counter-clockwise around the centre: the distinct sites in order form a convex
        // polygon (every turn and every fan triangle from the first site is positive).
        std::vector<ExactPoint> ring;
        for (const std::uint32_t s : sites)
            if (t.vertex_of_input[s] == s) ring.push_back(exact(points[s]));
        RC_ASSERT(ring.size() >= 3u);
        for (std::size_t k = 0; k < ring.size(); ++k) {
            RC_ASSERT(exact_orientation(ring[k], ring[(k + 1) % ring.size()],
                                        ring[(k + 2) % ring.size()]) > 0);
            if (k >= 1 && k + 1 < ring.size())
                RC_ASSERT(exact_orientation(ring[0], ring[k], ring[k + 1]) > 0);
        }
        for (const std::uint32_t s : sites)
            vertices_of_site[s].insert(static_cast<std::uint32_t>(v));
    }

    // Cells: exactly the vertices of the site, counter-clockwise around it; unbounded
    // exactly for sites on the hull.
    std::set<std::uint32_t> on_hull;
    for (const std::uint32_t h : t.hull) on_hull.insert(h);
    for (std::size_t i = 0; i < n; ++i) {
        const auto cell = d.cell(i);
        RC_ASSERT(std::set<std::uint32_t>(cell.begin(), cell.end()) == vertices_of_site[i]);
        RC_ASSERT(cell.size() == vertices_of_site[i].size());
        const bool hull = on_hull.count(t.vertex_of_input[i]) > 0;
        RC_ASSERT((d.unbounded[i] == 1) == hull);
        const ExactPoint site = exact(points[i]);
        const std::size_t m = cell.size();
        for (std::size_t k = 0; k + (hull ? 1 : 0) < m; ++k) {
            if (m < 2) break;
            const ExactPoint& a = centre_of_vertex[cell[k]];
            const ExactPoint& b = centre_of_vertex[cell[(k + 1) % m]];
            RC_ASSERT(exact_orientation(a, b, site) > 0);
        }
        if (hull) {
            // The rays point away from the site's side: the entry ray leaves the first
            // vertex, the exit ray the last, both outward normals of hull edges.
            RC_ASSERT(!(d.entry_ray[i].x == 0 && d.entry_ray[i].y == 0));
            RC_ASSERT(!(d.exit_ray[i].x == 0 && d.exit_ray[i].y == 0));
        }
    }
}

using DT = CGAL::Delaunay_triangulation_2<Epick>;
using VD =
    CGAL::Voronoi_diagram_2<DT, CGAL::Delaunay_triangulation_adaptation_traits_2<DT>,
                            CGAL::Delaunay_triangulation_caching_degeneracy_removal_policy_2<DT>>;

/// CGAL's Voronoi vertices as sets of (first-occurrence) sites, and its unbounded sites.
void check_against_cgal(std::span<const Point2> points, const Triangulation& t,
                        const VoronoiDiagram& d) {
    DT dt;
    for (const Point2& p : points) dt.insert(to_cgal(p));
    if (dt.dimension() < 2) return;
    VD vd(dt);
    std::map<std::pair<double, double>, std::uint32_t> index;
    for (std::size_t i = 0; i < points.size(); ++i)
        index.emplace(std::pair{points[i].x, points[i].y}, i);
    const auto site_of = [&](VD::Face_handle f) {
        const auto p = f->dual()->point();
        return index.at({p.x(), p.y()});
    };
    std::multiset<std::set<std::uint32_t>> cgal_vertices, ours;
    for (auto v = vd.vertices_begin(); v != vd.vertices_end(); ++v) {
        std::set<std::uint32_t> s;
        auto c = v->incident_halfedges(), done = c;
        do {
            s.insert(site_of(c->face()));
        } while (++c != done);
        cgal_vertices.insert(s);
    }
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        std::set<std::uint32_t> s;
        for (const std::uint32_t i : d.vertex_sites(v))
            if (t.vertex_of_input[i] == i) s.insert(i);
        ours.insert(s);
    }
    RC_ASSERT(cgal_vertices == ours);
    for (auto f = vd.faces_begin(); f != vd.faces_end(); ++f)
        RC_ASSERT((d.unbounded[site_of(f)] == 1) == f->is_unbounded());
}

template <class K>
void check_family(const std::string& family) {
    const bool ok = rc::check("voronoi " + K::name() + " on " + family, [&] {
        const std::size_t n = *rc::gen::inRange<std::size_t>(0, 48);
        const std::vector<Point2> points = *gen_family_points(family, n);
        const auto r = delaunay::triangulate(points, K{});
        RC_ASSERT(r.ok());
        VoronoiDiagram d;
        try {
            d = delaunay::voronoi(points, r.triangulation, K{});
        } catch (const delaunay::VoronoiError& e) {
            // Only a centre beyond the largest double may stop it (wide exponents).
            RC_ASSERT(e.status() == CircumcenterStatus::overflow);
            const std::uint32_t* v = &r.triangulation.triangles[3 * e.triangle()];
            const auto c = oracle_circumcenter(points[v[0]], points[v[1]], points[v[2]]);
            RC_ASSERT(c.has_value());
            RC_ASSERT(std::isinf(c->x) || std::isinf(c->y));
            return;
        }
        check_diagram(points, r.triangulation, d);
        check_against_cgal(points, r.triangulation, d);
    });
    EXPECT_TRUE(ok) << family;
}

TEST(Voronoi, EveryFamilyAdaptiveKernel) {
    for (const std::string& f : point_set_family_names()) check_family<AdaptiveKernel>(f);
}

TEST(Voronoi, EveryFamilyGmpExactKernel) {
    for (const std::string& f : point_set_family_names()) check_family<GmpExactKernel>(f);
}

/// The lattice points of x^2 + y^2 = r2 moved to (cx, cy).
std::vector<Point2> lattice_circle(int r2, double cx, double cy) {
    std::vector<Point2> p;
    for (int x = -100; x <= 100; ++x)
        for (int y = -100; y <= 100; ++y)
            if (x * x + y * y == r2) p.push_back({cx + x, cy + y});
    return p;
}

TEST(Voronoi, OneVertexPerLatticeCircle) {
    // 12 points on x^2 + y^2 = 25, 16 on x^2 + y^2 = 65, 36 on x^2 + y^2 = 5525
    // (= 5^2 13 17): every empty circle of many exactly cocircular sites is one vertex.
    const std::vector<std::tuple<int, double, double>> circles = {
        {25, 0, 0}, {65, 40, 3}, {5525, -300, 250}};
    std::vector<Point2> points;
    for (const auto& [r2, cx, cy] : circles) {
        const auto c = lattice_circle(r2, cx, cy);
        points.insert(points.end(), c.begin(), c.end());
    }
    const auto r = delaunay::triangulate(points, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    const VoronoiDiagram d = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{});
    std::size_t first = 0;
    for (const auto& [r2, cx, cy] : circles) {
        const std::size_t m = lattice_circle(r2, 0, 0).size();
        std::vector<std::size_t> at_centre;
        for (std::size_t v = 0; v < d.vertex_count(); ++v)
            if (d.vertices[v].x == cx && d.vertices[v].y == cy) at_centre.push_back(v);
        ASSERT_EQ(at_centre.size(), 1u) << "circle r^2 = " << r2;
        const auto sites = d.vertex_sites(at_centre[0]);
        EXPECT_EQ(sites.size(), m);
        for (const std::uint32_t i : sites) EXPECT_TRUE(i >= first && i < first + m);
        first += m;
    }
}

TEST(Voronoi, TinyAndCollinearInputs) {
    for (const std::vector<Point2>& points :
         {std::vector<Point2>{}, std::vector<Point2>{{1, 2}}, std::vector<Point2>{{0, 0}, {1, 1}},
          std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}, {1, 1}},
          std::vector<Point2>{{3, 3}, {3, 3}}}) {
        const auto r = delaunay::triangulate(points, AdaptiveKernel{});
        ASSERT_TRUE(r.ok());
        const VoronoiDiagram d = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{});
        EXPECT_TRUE(d.collinear);
        EXPECT_EQ(d.vertex_count(), 0u);
        EXPECT_EQ(d.site_count(), points.size());
        for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(d.unbounded[i], 1);
        EXPECT_EQ(d.chain, r.triangulation.hull);
    }
}

TEST(Voronoi, DuplicatesShareTheirTwinsCell) {
    const std::vector<Point2> points = {{0, 0}, {4, 0}, {0, 4}, {4, 4}, {2, 1}, {4, 0}, {2, 1}};
    const auto r = delaunay::triangulate(points, GmpExactKernel{});
    ASSERT_TRUE(r.ok());
    const VoronoiDiagram d = delaunay::voronoi(points, r.triangulation, GmpExactKernel{});
    const auto same = [&](std::size_t i, std::size_t j) {
        const auto a = d.cell(i), b = d.cell(j);
        return std::vector<std::uint32_t>(a.begin(), a.end()) ==
                   std::vector<std::uint32_t>(b.begin(), b.end()) &&
               d.unbounded[i] == d.unbounded[j];
    };
    EXPECT_TRUE(same(5, 1));
    EXPECT_TRUE(same(6, 4));
    EXPECT_FALSE(d.cell(4).empty());
    EXPECT_EQ(d.unbounded[4], 0);
    // Duplicates are listed among a vertex's sites right after their twin.
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        const auto sites = d.vertex_sites(v);
        for (std::size_t k = 0; k < sites.size(); ++k)
            if (sites[k] == 5u) {
                EXPECT_EQ(sites[k - 1], 1u);
            }
    }
}

TEST(Voronoi, CentreBeyondTheLargestDoubleIsAnError) {
    const double huge = std::numeric_limits<double>::max();
    const std::vector<Point2> points = {{-huge, 0}, {huge, 0}, {0, 1}};
    const auto r = delaunay::triangulate(points, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    EXPECT_THROW(delaunay::voronoi(points, r.triangulation, AdaptiveKernel{}),
                 delaunay::VoronoiError);
}

TEST(Voronoi, InexactKernelStillGivesCorrectlyRoundedVertices) {
    // The double kernel may group wrongly near degeneracy, but every vertex is still a
    // correctly rounded centre of a Delaunay triangle it was given.
    const auto points = uniform_points(300, 7);
    const auto r = delaunay::triangulate(points, DoubleKernel{});
    ASSERT_TRUE(r.ok());
    const VoronoiDiagram d = delaunay::voronoi(points, r.triangulation, DoubleKernel{});
    for (std::size_t tr = 0; tr < r.triangulation.triangle_count(); ++tr) {
        const std::uint32_t* v = &r.triangulation.triangles[3 * tr];
        const auto want = oracle_circumcenter(points[v[0]], points[v[1]], points[v[2]]);
        ASSERT_TRUE(want);
        EXPECT_EQ(d.vertices[d.vertex_of_triangle[tr]].x, want->x);
        EXPECT_EQ(d.vertices[d.vertex_of_triangle[tr]].y, want->y);
    }
}

/// Checks a clipped diagram against the diagram it came from (RC_ASSERT).
void check_clipped(std::span<const Point2> points, const Triangulation& t, const VoronoiDiagram& d,
                   const delaunay::ClippedVoronoi& c, const delaunay::Box& box) {
    const std::size_t n = points.size();
    RC_ASSERT(c.site_count() == n);
    for (std::size_t v = 0; v < c.vertex_count(); ++v) {
        const Point2 p = c.vertices[v];
        // Rounding is monotone and the bounds are doubles: exact inside => rounded inside.
        RC_ASSERT(box.xmin <= p.x && p.x <= box.xmax && box.ymin <= p.y && p.y <= box.ymax);
        // A point the box adds is a corner of exactly the cells of its sites. (A Voronoi
        // vertex lists every site equidistant from it, also one whose clipped cell only
        // touches the box there and is therefore empty.)
        if (v < c.voronoi_vertex_count) continue;
        for (const std::uint32_t i : c.vertex_sites(v)) {
            const auto cell = c.cell(i);
            RC_ASSERT(std::find(cell.begin(), cell.end(), v) != cell.end());
        }
    }
    long double area = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto cell = c.cell(i);
        for (const std::uint32_t v : cell) {
            const auto sites = c.vertex_sites(v);
            RC_ASSERT(std::find(sites.begin(), sites.end(), static_cast<std::uint32_t>(i)) !=
                      sites.end());
        }
        // A bounded cell strictly inside the box is kept as it is.
        const auto whole = d.cell(i);
        const bool strictly_inside =
            !d.collinear && d.unbounded[i] == 0 &&
            std::all_of(whole.begin(), whole.end(), [&](std::uint32_t v) {
                const Point2 p = d.vertices[v];
                return box.xmin < p.x && p.x < box.xmax && box.ymin < p.y && p.y < box.ymax;
            });
        if (strictly_inside) {
            RC_ASSERT(cell.size() == whole.size());
            for (std::size_t k = 0; k < cell.size(); ++k)
                RC_ASSERT(c.vertices[cell[k]] == d.vertices[whole[k]]);
        }
        if (t.vertex_of_input[i] != i) continue;  // a duplicate's cell is its twin's
        for (std::size_t k = 0; k < cell.size(); ++k) {
            // Relative to the box's corner, so the shoelace does not cancel.
            const Point2 a = c.vertices[cell[k]], b = c.vertices[cell[(k + 1) % cell.size()]];
            const long double ax = static_cast<long double>(a.x) - box.xmin,
                              ay = static_cast<long double>(a.y) - box.ymin;
            const long double bx = static_cast<long double>(b.x) - box.xmin,
                              by = static_cast<long double>(b.y) - box.ymin;
            area += ax * by - bx * ay;
        }
    }
    // The cells tile the box (up to the rounding of the corners).
    if (n > 0) {
        const long double box_area = 2.0L * (box.xmax - box.xmin) * (box.ymax - box.ymin);
        RC_ASSERT(std::fabs(static_cast<double>(area - box_area)) <=
                  1e-9 * static_cast<double>(box_area));
    }
}

TEST(Voronoi, ClippedCellsTileTheBox) {
    for (const std::string family : {"uniform", "integer_grid", "lattice_circle", "gaussian",
                                     "duplicates", "dyadic_line", "near_integer_grid"}) {
        const bool ok = rc::check("clip on " + family, [&] {
            const std::size_t n = *rc::gen::inRange<std::size_t>(0, 40);
            const std::vector<Point2> points = *gen_family_points(family, n);
            const auto r = delaunay::triangulate(points, AdaptiveKernel{});
            RC_ASSERT(r.ok());
            VoronoiDiagram d;
            try {
                d = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{});
            } catch (const delaunay::VoronoiError& e) {  // checked in EveryFamily*
                RC_DISCARD("a vertex beyond the largest double");
            }
            // A box around the middle of the points' bounding box (and one around nothing).
            double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
            if (!points.empty()) {
                x0 = x1 = points[0].x;
                y0 = y1 = points[0].y;
                for (const Point2& p : points) {
                    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
                    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
                }
            }
            const double shrink = *rc::gen::element(0.0, 0.1, 0.3, -0.2);
            const double w = std::max(x1 - x0, 1.0), h = std::max(y1 - y0, 1.0);
            const delaunay::Box box{x0 + shrink * w, y0 + shrink * h, x1 - shrink * w,
                                    y1 - shrink * h};
            RC_PRE(box.xmin < box.xmax && box.ymin < box.ymax);
            const delaunay::ClippedVoronoi c = delaunay::clip(d, points, r.triangulation, box);
            check_clipped(points, r.triangulation, d, c, box);
        });
        EXPECT_TRUE(ok) << family;
    }
}

TEST(Voronoi, VerticesOnTheBoxAreVoronoiVertices) {
    // A 5 x 5 grid: every vertex is the centre of a square of four cocircular sites, at
    // half-integers; the box's corners and sides go exactly through some of them.
    std::vector<Point2> points;
    for (int x = 0; x < 5; ++x)
        for (int y = 0; y < 5; ++y) points.push_back({double(x), double(y)});
    const auto r = delaunay::triangulate(points, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    const VoronoiDiagram d = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{});
    EXPECT_EQ(d.vertex_count(), 16u);  // one per unit square
    const delaunay::Box box{0.5, 0.5, 3.5, 2.5};
    const delaunay::ClippedVoronoi c = delaunay::clip(d, points, r.triangulation, box);
    // Vertices in the closed box: x in {0.5 .. 3.5} (4 values) times y in {0.5 .. 2.5} (3).
    EXPECT_EQ(c.voronoi_vertex_count, 12u);
    // Every bisector crosses the box's boundary at a Voronoi vertex here: nothing added.
    EXPECT_EQ(c.vertex_count(), 12u);
    std::set<std::pair<double, double>> distinct;
    for (const Point2& p : c.vertices) distinct.insert({p.x, p.y});
    EXPECT_EQ(distinct.size(), c.vertex_count());
    // The 6 sites with cells inside the box: (1..3, 1..2), each a unit square.
    std::size_t nonempty = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (c.cell(i).empty()) continue;
        ++nonempty;
        EXPECT_EQ(c.cell(i).size(), 4u) << i;
    }
    EXPECT_EQ(nonempty, 6u);
}

TEST(Voronoi, ClipRejectsABoxWithoutInterior) {
    const std::vector<Point2> points = {{0, 0}, {1, 0}, {0, 1}};
    const auto r = delaunay::triangulate(points, AdaptiveKernel{});
    const VoronoiDiagram d = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{});
    EXPECT_THROW(delaunay::clip(d, points, r.triangulation, {0, 0, 0, 1}), std::invalid_argument);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(delaunay::clip(d, points, r.triangulation, {0, 0, nan, 1}), std::invalid_argument);
}

// Regression, shrunk by RapidCheck from near_lattice_circle: a vertex just above the
// subnormal range (about 2^-1020) was rounded with one bit too many by circumcenter's
// exact stage. Now every vertex must match the oracle.
TEST(VoronoiRegression, CentreJustAboveTheSubnormalRange) {
    const double a = 0x1p-1020, tiny = 0x0.0000000000001p-1022;
    const std::vector<Point2> points = {{a, 0}, {a, 0},
                                        {a, 0}, {a, 0},
                                        {a, 0}, {a, 0},
                                        {a, 0}, {a, 0},
                                        {a, 0}, {a, tiny},
                                        {a, 0}, {a, 0},
                                        {a, 0}, {0x1.ffffffp-1021, -0x0.000006p-1022},
                                        {a, 0}, {0x1.fffffffffffffp-1021, 0},
                                        {a, 0}, {a, 0}};
    for (const bool exact_kernel : {false, true}) {
        const auto r = exact_kernel ? delaunay::triangulate(points, GmpExactKernel{})
                                    : delaunay::triangulate(points, AdaptiveKernel{});
        ASSERT_TRUE(r.ok());
        const VoronoiDiagram d = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{});
        const bool ok = rc::check("the regression's diagram",
                                  [&] { check_diagram(points, r.triangulation, d); });
        EXPECT_TRUE(ok);
    }
}

TEST(Voronoi, ThreadCountDoesNotChangeTheDiagram) {
    const auto points = uniform_points(30000, 11);
    const auto r = delaunay::triangulate(points, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    const VoronoiDiagram one = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{}, 1);
    const VoronoiDiagram two = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{}, 2);
    const VoronoiDiagram three = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{}, 3);
    for (const VoronoiDiagram* d : {&two, &three}) {
        EXPECT_EQ(d->vertices, one.vertices);
        EXPECT_EQ(d->sites, one.sites);
        EXPECT_EQ(d->cell_vertices, one.cell_vertices);
        EXPECT_EQ(d->cell_offsets, one.cell_offsets);
        EXPECT_EQ(d->unbounded, one.unbounded);
        EXPECT_EQ(d->exit_ray, one.exit_ray);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(d->stage_counts[k], one.stage_counts[k]);
    }
}

}  // namespace
}  // namespace exidel::test
