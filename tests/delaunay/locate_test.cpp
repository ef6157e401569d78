// Point location (exidel/delaunay/locate.hpp): the classification of every query against
// CGAL's Delaunay_triangulation_2::locate on every degenerate family, each answer checked
// on its own triangle with CGAL's exact orientation, the batch forms against the single
// one, inexact and lying kernels (an answer or a typed failure, never a hang), bad input.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/interpolate.hpp"
#include "exidel/delaunay/locate.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "lying_kernel.hpp"

namespace exidel::test {
namespace {

using delaunay::Location;
using delaunay::LocationKind;
using delaunay::Locator;
using delaunay::Triangulation;

using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Epick>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using CgalDT = CGAL::Delaunay_triangulation_2<Epick, Tds>;

CgalDT cgal_triangulation(std::span<const Point2> points) {
    const auto first = first_occurrence(points);
    std::vector<std::pair<Epick::Point_2, std::uint32_t>> input;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        input.emplace_back(to_cgal(points[i]), first[i]);
    return CgalDT(input.begin(), input.end());
}

Triangulation exidel_triangulation(std::span<const Point2> points) {
    auto r = delaunay::triangulate(points, AdaptiveKernel{});
    RC_ASSERT(r.ok());
    return std::move(r.triangulation);
}

std::set<std::uint32_t> corners(const Triangulation& t, std::int32_t tri) {
    const auto b = 3 * static_cast<std::size_t>(tri);
    return {t.triangles[b], t.triangles[b + 1], t.triangles[b + 2]};
}

/// The answer checked on its own triangle with CGAL's exact orientation.
void check_on_triangle(std::span<const Point2> P, const Triangulation& t, Point2 q,
                       const Location& where) {
    if (t.collinear) {
        RC_ASSERT(where.triangle == -1);
        if (where.kind == LocationKind::on_vertex) {
            RC_ASSERT(P[where.vertex].x == q.x && P[where.vertex].y == q.y);
        }
        if (where.kind == LocationKind::on_edge) {
            const auto i = static_cast<std::size_t>(where.edge);
            RC_ASSERT(i + 1 < t.hull.size());
            RC_ASSERT(cgal_orient2d(P[t.hull[i]], P[t.hull[i + 1]], q) == Sign::zero);
        }
        return;
    }
    RC_ASSERT(where.triangle >= 0);
    RC_ASSERT(static_cast<std::size_t>(where.triangle) < t.triangle_count());
    const auto b = 3 * static_cast<std::size_t>(where.triangle);
    int zeros = 0, negatives = 0;
    for (std::size_t j = 0; j < 3; ++j) {
        const Sign s = cgal_orient2d(P[t.triangles[b + j]], P[t.triangles[b + (j + 1) % 3]], q);
        zeros += s == Sign::zero;
        negatives += s == Sign::negative;
    }
    switch (where.kind) {
        case LocationKind::inside: RC_ASSERT(zeros == 0 && negatives == 0); break;
        case LocationKind::on_edge: {
            RC_ASSERT(zeros == 1 && negatives == 0);
            const auto e = static_cast<std::size_t>(where.edge);
            RC_ASSERT(e / 3 == static_cast<std::size_t>(where.triangle));
            RC_ASSERT(cgal_orient2d(P[t.triangles[e]], P[t.triangles[delaunay::next_halfedge(e)]],
                                    q) == Sign::zero);
            break;
        }
        case LocationKind::on_vertex:
            RC_ASSERT(zeros == 2 && negatives == 0);
            RC_ASSERT(corners(t, where.triangle).count(where.vertex) == 1);
            RC_ASSERT(P[where.vertex].x == q.x && P[where.vertex].y == q.y);
            break;
        case LocationKind::outside: {
            const auto e = static_cast<std::size_t>(where.edge);
            RC_ASSERT(e / 3 == static_cast<std::size_t>(where.triangle));
            RC_ASSERT(t.halfedges[e] == -1);
            RC_ASSERT(cgal_orient2d(P[t.triangles[e]], P[t.triangles[delaunay::next_halfedge(e)]],
                                    q) == Sign::negative);
            break;
        }
    }
}

/// CGAL's triangulation of the points and the edges of both triangulations: where four
/// or more points are cocircular the two may differ, and so may the classification of a
/// query on an edge one of them has and the other has not.
struct Oracle {
    CgalDT dt;
    std::set<Edge> cgal_edges, our_edges;

    Oracle(std::span<const Point2> points, const Triangulation& t)
        : dt(cgal_triangulation(points)) {
        for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
            const auto f = e->first;
            const int i = e->second;
            const bool plane = dt.dimension() == 2;
            cgal_edges.insert(make_edge(f->vertex(plane ? f->cw(i) : 0)->info(),
                                        f->vertex(plane ? f->ccw(i) : 1)->info()));
        }
        for (std::size_t e = 0; e < t.triangles.size(); ++e) {
            our_edges.insert(make_edge(t.triangles[e], t.triangles[delaunay::next_halfedge(e)]));
        }
        for (std::size_t i = 0; i + 1 < t.hull.size() && t.collinear; ++i) {
            our_edges.insert(make_edge(t.hull[i], t.hull[i + 1]));
        }
    }
};

Edge located_edge(const Triangulation& t, const Location& where) {
    const auto e = static_cast<std::size_t>(where.edge);
    if (t.collinear) return make_edge(t.hull[e], t.hull[e + 1]);
    return make_edge(t.triangles[e], t.triangles[delaunay::next_halfedge(e)]);
}

/// The classification against CGAL's locate: the same kind and vertex; the same edge, or
/// for an edge of one triangulation only (a diagonal of cocircular points) "inside" or on
/// an edge of its own in the other; and the answer checked on its own triangle.
void check_against_cgal(std::span<const Point2> P, const Oracle& o, const Triangulation& t,
                        Point2 q, const Location& where) {
    const CgalDT& dt = o.dt;
    CgalDT::Locate_type lt;
    int li = 0;
    const auto f = dt.locate(to_cgal(q), lt, li);
    switch (lt) {
        case CgalDT::VERTEX: {
            RC_ASSERT(where.kind == LocationKind::on_vertex);
            // Below dimension 2 CGAL's face and index are not a corner: find the vertex.
            auto v = dt.finite_vertices_begin();
            while (v != dt.finite_vertices_end() && v->point() != to_cgal(q)) ++v;
            RC_ASSERT(v != dt.finite_vertices_end());
            RC_ASSERT(where.vertex == v->info());
            break;
        }
        case CgalDT::EDGE: {
            // In dimension 1 the face is the edge itself, its ends vertices 0 and 1.
            const bool plane = dt.dimension() == 2;
            const Edge edge = make_edge(f->vertex(plane ? f->cw(li) : 0)->info(),
                                        f->vertex(plane ? f->ccw(li) : 1)->info());
            if (o.our_edges.count(edge) == 0) {
                // A diagonal of cocircular points that we split the other way: q inside,
                // or where the diagonals cross, on ours.
                RC_ASSERT(where.kind == LocationKind::inside ||
                          (where.kind == LocationKind::on_edge &&
                           o.cgal_edges.count(located_edge(t, where)) == 0));
            } else {
                RC_ASSERT(where.kind == LocationKind::on_edge);
                RC_ASSERT(located_edge(t, where) == edge);
            }
            break;
        }
        case CgalDT::FACE:
            if (where.kind == LocationKind::on_edge) {
                RC_ASSERT(o.cgal_edges.count(located_edge(t, where)) == 0);
            } else {
                RC_ASSERT(where.kind == LocationKind::inside);
            }
            break;
        case CgalDT::OUTSIDE_CONVEX_HULL:
        case CgalDT::OUTSIDE_AFFINE_HULL: RC_ASSERT(where.kind == LocationKind::outside); break;
    }
    check_on_triangle(P, t, q, where);
}

RC_GTEST_PROP(Locate, EveryQueryOfEveryFamilyMatchesCgal, ()) {
    const PointSet s = *gen_point_set(120);
    const Triangulation t = exidel_triangulation(s.points);
    const Oracle oracle(s.points, t);
    const auto queries = degenerate_queries(s.points, t, *rc::gen::arbitrary<std::uint32_t>());
    Locator<AdaptiveKernel> locator(s.points, t);
    std::vector<Location> batch(queries.size());
    RC_ASSERT(!locator.locate(queries, batch).has_value());
    for (std::size_t i = 0; i < queries.size(); ++i) {
        check_against_cgal(s.points, oracle, t, queries[i], batch[i]);
        // The single form, from the previous answer: the same classification and vertex.
        const Location single = locator.locate(queries[i]);
        check_against_cgal(s.points, oracle, t, queries[i], single);
    }
}

RC_GTEST_PROP(Locate, ExactKernelsAndOrdersAgree, ()) {
    const PointSet s = *gen_point_set(80);
    const Triangulation t = exidel_triangulation(s.points);
    const Oracle oracle(s.points, t);
    const auto queries = degenerate_queries(s.points, t, 7);
    std::vector<Location> hilbert(queries.size()), given(queries.size()), jump(queries.size()),
        exact(queries.size());
    Locator<AdaptiveKernel> adaptive(s.points, t);
    RC_ASSERT(!adaptive.locate(queries, hilbert).has_value());
    RC_ASSERT(
        !adaptive.locate(queries, given, {.order = delaunay::LocateOrder::given}).has_value());
    RC_ASSERT(!adaptive.locate(queries, jump, {.order = delaunay::LocateOrder::jump}).has_value());
    Locator<GmpExactKernel> gmp(s.points, t);
    RC_ASSERT(!gmp.locate(queries, exact).has_value());
    for (std::size_t i = 0; i < queries.size(); ++i) {
        for (const Location* w : {&given[i], &jump[i], &exact[i]}) {
            check_against_cgal(s.points, oracle, t, queries[i], *w);
        }
    }
}

RC_GTEST_PROP(Locate, NearestVertexIsExactlyNearest, ()) {
    const PointSet s = *gen_point_set(60);
    const Triangulation t = exidel_triangulation(s.points);
    const auto queries = degenerate_queries(s.points, t, *rc::gen::arbitrary<std::uint32_t>());
    std::vector<std::uint32_t> nearest(queries.size());
    Locator<AdaptiveKernel> locator(s.points, t);
    RC_ASSERT(!locator.nearest(queries, nearest).has_value());
    const auto first = first_occurrence(s.points);
    for (std::size_t i = 0; i < queries.size(); ++i) {
        if (s.points.empty()) {
            RC_ASSERT(nearest[i] == delaunay::no_vertex);
            continue;
        }
        RC_ASSERT(nearest[i] < s.points.size());
        RC_ASSERT(first[nearest[i]] == nearest[i]);
        const auto q = to_cgal(queries[i]), w = to_cgal(s.points[nearest[i]]);
        for (const Point2& p : s.points) {
            // No point strictly nearer (CGAL's exact comparison).
            RC_ASSERT(CGAL::compare_distance_to_point(q, to_cgal(p), w) != CGAL::SMALLER);
        }
    }
}

TEST(Locate, BatchAnswersDoNotDependOnThreads) {
    const auto points = uniform_points(20000, 3);
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    auto queries = uniform_points(30000, 4);
    queries.insert(queries.end(), points.begin(), points.begin() + 5000);
    Locator<AdaptiveKernel> locator(points, t);
    std::vector<Location> one(queries.size()), two(queries.size());
    ASSERT_FALSE(locator.locate(queries, one, {.threads = 1}).has_value());
    ASSERT_FALSE(locator.locate(queries, two, {.threads = 2}).has_value());
    EXPECT_EQ(one, two);
    std::size_t on_vertex = 0;
    for (const Location& w : one) on_vertex += w.kind == LocationKind::on_vertex;
    EXPECT_GE(on_vertex, 5000u);
}

TEST(Locate, LatticeQueriesOnEdgesAndVerticesAreExact) {
    // A 40 x 40 lattice: every query of the finer half-step lattice is on a vertex, on an
    // edge (horizontal, vertical, or a diagonal the triangulation chose), or inside.
    std::vector<Point2> points;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) points.push_back({double(i), double(j)});
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    std::vector<Point2> queries;
    for (int i = -2; i < 82; ++i)
        for (int j = -2; j < 82; ++j) queries.push_back({i * 0.5, j * 0.5});
    Locator<AdaptiveKernel> locator(points, t);
    std::vector<Location> where(queries.size());
    ASSERT_FALSE(locator.locate(queries, where).has_value());
    const CgalDT dt = cgal_triangulation(points);
    std::size_t counts[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < queries.size(); ++i) {
        CgalDT::Locate_type lt;
        int li = 0;
        dt.locate(to_cgal(queries[i]), lt, li);
        const LocationKind expected = lt == CgalDT::VERTEX ? LocationKind::on_vertex
                                      : lt == CgalDT::EDGE ? LocationKind::on_edge
                                      : lt == CgalDT::FACE ? LocationKind::inside
                                                           : LocationKind::outside;
        ASSERT_EQ(where[i].kind, expected) << "query " << i;
        ++counts[static_cast<int>(where[i].kind)];
    }
    EXPECT_EQ(counts[static_cast<int>(LocationKind::on_vertex)], 1600u);
    // 2 x 39 x 40 axis-parallel edges, plus the 39 x 39 cells' diagonals.
    EXPECT_EQ(counts[static_cast<int>(LocationKind::on_edge)], 2u * 39 * 40 + 39 * 39);
}

TEST(Locate, NonFiniteQueriesAndBadArgumentsAreClearErrors) {
    const auto points = uniform_points(100, 5);
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> locator(points, t);
    std::vector<Point2> queries = {{0.5, 0.5}, {std::nan(""), 0.5}, {0.2, 0.2}};
    std::vector<Location> out(3);
    const auto failure = locator.locate(queries, out);
    ASSERT_TRUE(failure.has_value());
    EXPECT_EQ(failure->kind, delaunay::FailureKind::non_finite_input);
    EXPECT_EQ(failure->input_index, 1u);
    EXPECT_NE(failure->message.find("query 1"), std::string::npos);
    EXPECT_THROW(locator.locate(Point2{INFINITY, 0}), delaunay::FailureError);
    EXPECT_THROW(locator.locate(Point2{0.5, 0.5}, static_cast<std::int32_t>(t.triangle_count())),
                 std::out_of_range);
    std::vector<Location> small(2);
    EXPECT_THROW((void)locator.locate(queries, small), std::invalid_argument);
    std::vector<std::uint32_t> nearest(3);
    const auto nf = locator.nearest(queries, nearest);
    ASSERT_TRUE(nf.has_value());
    EXPECT_EQ(nf->kind, delaunay::FailureKind::non_finite_input);

    Triangulation broken = t;
    broken.triangles[4] = 1000;
    EXPECT_THROW((Locator<AdaptiveKernel>(points, broken)), std::invalid_argument);
    broken = t;
    broken.halfedges.pop_back();
    EXPECT_THROW((Locator<AdaptiveKernel>(points, broken)), std::invalid_argument);
    broken = t;
    broken.halfedges[0] = broken.halfedges[0] < 0 ? 5 : -1;
    EXPECT_THROW((Locator<AdaptiveKernel>(points, broken)), std::invalid_argument);
}

TEST(Locate, TinyAndCollinearInputs) {
    const std::vector<Point2> none;
    const auto t0 = delaunay::triangulate(none, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> l0(none, t0);
    EXPECT_EQ(l0.locate(Point2{0, 0}).kind, LocationKind::outside);

    const std::vector<Point2> line = {{0, 0}, {2, 2}, {1, 1}, {1, 1}, {3, 3}};
    const auto t1 = delaunay::triangulate(line, AdaptiveKernel{}).triangulation;
    ASSERT_TRUE(t1.collinear);
    Locator<AdaptiveKernel> l1(line, t1);
    EXPECT_EQ(l1.locate(Point2{1, 1}), (Location{LocationKind::on_vertex, -1, -1, 2}));
    const Location mid = l1.locate(Point2{1.5, 1.5});
    EXPECT_EQ(mid.kind, LocationKind::on_edge);
    EXPECT_EQ(t1.hull[static_cast<std::size_t>(mid.edge)], 2u);
    EXPECT_EQ(l1.locate(Point2{4, 4}).kind, LocationKind::outside);
    EXPECT_EQ(l1.locate(Point2{1, 1.5}).kind, LocationKind::outside);
    EXPECT_EQ(l1.locate(Point2{-1, -1}).kind, LocationKind::outside);
}

RC_GTEST_PROP(Locate, InexactKernelsAnswerOrFailTyped, ()) {
    // The double kernel on every family (the near-degenerate ones included), and kernels
    // that lie outright: every query gets an answer or the batch a typed failure, and
    // nothing hangs.
    const PointSet s = *gen_point_set(150);
    const Triangulation t = exidel_triangulation(s.points);
    const auto queries = degenerate_queries(s.points, t, 12);
    std::vector<Location> out(queries.size());
    Locator<DoubleKernel> dbl(s.points, t);
    if (const auto f = dbl.locate(queries, out)) {
        RC_ASSERT(f->kind == delaunay::FailureKind::location_exceeded ||
                  f->kind == delaunay::FailureKind::location_inconsistent);
    }
    if (t.collinear || queries.empty()) return;
    for (const auto mode :
         {LyingKernel::random, LyingKernel::negative, LyingKernel::zero, LyingKernel::positive}) {
        Locator<LyingKernel> liar(s.points, t, LyingKernel{mode});
        const auto f = liar.locate(queries, out, {.order = delaunay::LocateOrder::given});
        if (mode == LyingKernel::zero) {
            // q "on every edge line": inconsistent at the first triangle.
            RC_ASSERT(f.has_value());
            RC_ASSERT(f->kind == delaunay::FailureKind::location_inconsistent);
        } else if (mode == LyingKernel::positive) {
            // q "strictly inside every triangle": the start triangle is the answer.
            RC_ASSERT(!f.has_value());
        } else if (f) {
            // "Strictly beyond" edges: the walk leaves at the hull or reaches its bound.
            RC_ASSERT(f->kind == delaunay::FailureKind::location_exceeded ||
                      f->kind == delaunay::FailureKind::location_inconsistent);
        }
    }
}

TEST(Locate, StepBoundStopsTheWalk) {
    const auto points = uniform_points(5000, 8);
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> locator(points, t);
    const std::vector<Point2> far = {{0.01, 0.01}, {0.99, 0.99}};
    std::vector<Location> out(2);
    const auto f =
        locator.locate(far, out, {.order = delaunay::LocateOrder::given, .step_bound = 2});
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, delaunay::FailureKind::location_exceeded);
}

// Linear interpolation reproduces a linear function (up to rounding) wherever a query is
// located, and huge coordinates give finite values (products of their differences would
// overflow without the scaling in interpolate.cpp).
TEST(InterpolateLinear, ReproducesALinearFunctionAtEveryScale) {
    for (const double scale : {1.0, 0x1p-600, 0x1p600, 0x1p1000}) {
        std::vector<Point2> points = uniform_points(400, 5);
        const std::vector<Point2> unit = points;
        for (Point2& p : points) p = {p.x * scale, p.y * scale};
        const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
        std::vector<double> values;
        for (const Point2& p : unit) values.push_back(2 * p.x - 3 * p.y + 1);
        std::vector<Point2> queries = degenerate_queries(points, t, 7);
        for (const Point2& q : uniform_points(200, 6))
            queries.push_back({q.x * scale, q.y * scale});
        Locator<AdaptiveKernel> locator(points, t);
        std::vector<Location> where(queries.size());
        ASSERT_FALSE(locator.locate(queries, where).has_value());
        std::vector<double> out(queries.size());
        delaunay::interpolate_linear(points, t, values, queries, where, out, -99);
        for (std::size_t i = 0; i < queries.size(); ++i) {
            if (where[i].kind == LocationKind::outside) {
                EXPECT_EQ(out[i], -99);
                continue;
            }
            const double x = queries[i].x / scale, y = queries[i].y / scale;
            EXPECT_NEAR(out[i], 2 * x - 3 * y + 1, 1e-9) << "scale " << scale << " query " << i;
        }
    }
}

}  // namespace
}  // namespace exidel::test
