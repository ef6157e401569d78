// The certifier must catch planted defects and say which check failed where.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <vector>

#include <CGAL/IO/OFF.h>

#include "delaunay_support.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/io/triangulation_input.hpp"

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
    test::rebuild_twins(t);
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
    test::rebuild_twins(t);
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
    test::rebuild_twins(t);
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
    test::rebuild_twins(t);
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

// ---------------------------------------------------------------------------------------
// Findings name where they are.

TEST(Certify, FindingsNameTheirTriangleEdgeAndPoints) {
    const auto pts = uniform(60, 11);
    Triangulation t = triangulated(pts);
    const std::size_t e = flippable_edge(pts, t);
    const auto tw = static_cast<std::size_t>(t.halfedges[e]);
    const std::uint32_t a = t.triangles[e], b = t.triangles[next_halfedge(e)];
    const std::uint32_t c = t.triangles[prev_halfedge(e)], d = t.triangles[prev_halfedge(tw)];
    const std::size_t t0 = 3 * (e / 3), t1 = 3 * (tw / 3);
    t.triangles[t0] = c, t.triangles[t0 + 1] = a, t.triangles[t0 + 2] = d;
    t.triangles[t1] = d, t.triangles[t1 + 1] = b, t.triangles[t1 + 2] = c;
    test::rebuild_twins(t);
    const Certificate cert = certify(pts, t);
    ASSERT_EQ(cert.total_findings, 1u) << cert.summary();
    const Finding& f = cert.findings.front();
    ASSERT_EQ(f.points.size(), 4u);
    // The new diagonal (c, d), its triangle, and the point inside the circumcircle.
    EXPECT_EQ(test::make_edge(std::uint32_t(f.points[0]), std::uint32_t(f.points[1])),
              test::make_edge(c, d));
    EXPECT_TRUE(f.points[3] == a || f.points[3] == b);
    EXPECT_TRUE(f.triangle == std::int64_t(t0 / 3) || f.triangle == std::int64_t(t1 / 3));
    const std::string tri = "triangle " + std::to_string(f.triangle) + " (";
    EXPECT_NE(f.message.find(tri), std::string::npos) << f.message;
    EXPECT_NE(f.message.find("point " + std::to_string(f.points[3])), std::string::npos);

    // A clockwise triangle: "triangle T (a, b, c) is clockwise".
    const std::vector<Point2> three{{0, 0}, {1, 0}, {0, 1}};
    Triangulation cw;
    cw.triangles = {0, 2, 1};
    cw.halfedges = {-1, -1, -1};
    cw.hull = {0, 2, 1};
    const Certificate c2 = certify(three, cw);
    ASSERT_TRUE(c2.has(FindingKind::not_ccw)) << c2.summary();
    EXPECT_EQ(c2.findings.front().triangle, 0);
    EXPECT_EQ(c2.findings.front().points, (std::vector<std::int64_t>{0, 2, 1}));
    EXPECT_EQ(c2.findings.front().message, "triangle 0 (0, 2, 1) is clockwise");
}

TEST(Certify, MaxFindingsKeepsThatManyAndCountsAll) {
    const auto pts = uniform(200, 12);
    Triangulation t = triangulated(pts);
    for (std::size_t i = 0; i < t.triangles.size(); i += 3)
        std::swap(t.triangles[i + 1], t.triangles[i + 2]);
    const Certificate some = certify(pts, t);
    EXPECT_EQ(some.findings.size(), Certificate::max_findings);
    EXPECT_GT(some.total_findings, Certificate::max_findings);
    const Certificate all =
        certify(pts, t, CertifyOptions{std::numeric_limits<std::size_t>::max()});
    EXPECT_EQ(all.findings.size(), all.total_findings);
    EXPECT_EQ(all.total_findings, some.total_findings);
}

// ---------------------------------------------------------------------------------------
// normalize: the producers' conventions.

// `t` as delaunator writes it in y-up coordinates: every triangle clockwise (its twins
// following), the hull clockwise from another start, a later copy for each repeated point.
ProducedTriangulation delaunator_style(const Triangulation& t, std::span<const Point2> pts) {
    ProducedTriangulation p;
    const auto moved = [](std::size_t e) { return 3 * (e / 3) + 2 - e % 3; };
    p.triangles = t.triangles;
    std::vector<std::uint32_t> last(pts.size());
    for (std::uint32_t i = 0; i < pts.size(); ++i) last[t.vertex_of_input[i]] = i;
    for (std::size_t i = 0; i < p.triangles.size(); i += 3)
        std::swap(p.triangles[i + 1], p.triangles[i + 2]);
    for (std::uint32_t& v : p.triangles) v = last[v];
    std::vector<std::int32_t> h(t.halfedges.size(), -1);
    for (std::size_t e = 0; e < h.size(); ++e) {
        if (t.halfedges[e] >= 0) h[moved(e)] = std::int32_t(moved(std::size_t(t.halfedges[e])));
    }
    p.halfedges = std::move(h);
    std::vector<std::uint32_t> hull(t.hull.rbegin(), t.hull.rend());
    std::rotate(hull.begin(), hull.begin() + 2, hull.end());
    for (std::uint32_t& v : hull) v = last[v];
    p.hull = std::move(hull);
    return p;
}

std::vector<Point2> with_repeats(std::size_t n, std::uint64_t seed) {
    auto pts = uniform(n, seed);
    for (std::size_t i = 0; i < n / 10; ++i) pts.push_back(pts[(i * 7) % n]);
    return pts;
}

TEST(Normalize, DelaunatorScipyAndTriangleLayoutsCertify) {
    const auto pts = with_repeats(300, 21);
    const Triangulation t = triangulated(pts);
    Normalization did;
    const Triangulation back = normalize(pts, delaunator_style(t, pts), &did);
    EXPECT_TRUE(certify(pts, back).ok()) << certify(pts, back).summary();
    EXPECT_EQ(back.triangles, t.triangles);
    EXPECT_EQ(back.halfedges, t.halfedges);
    EXPECT_EQ(back.hull, t.hull);
    EXPECT_EQ(did.reoriented, t.triangle_count());
    EXPECT_GT(did.copies_renamed, 0u);
    EXPECT_TRUE(did.hull_reversed && did.hull_rotated);
    EXPECT_FALSE(did.twins_derived || did.hull_derived);
    EXPECT_EQ(did.notes().size(), 4u);
    // Triangles alone (scipy, Triangle, CGAL): twins and hull derived.
    ProducedTriangulation bare;
    bare.triangles = delaunator_style(t, pts).triangles;
    Normalization derived;
    EXPECT_TRUE(certify(pts, normalize(pts, bare, &derived)).ok());
    EXPECT_TRUE(derived.twins_derived && derived.hull_derived);
    // exidel's own layout changes nothing.
    ProducedTriangulation own{t.triangles, t.halfedges, t.hull, t.duplicates};
    Normalization none;
    EXPECT_TRUE(certify(pts, normalize(pts, own, &none)).ok());
    EXPECT_TRUE(none.notes().empty());
    // --strict: delaunator's layout is held to exidel's and fails.
    const Certificate strict =
        certify(pts, normalize(pts, delaunator_style(t, pts), nullptr, true));
    EXPECT_TRUE(strict.has(FindingKind::duplicate_vertex)) << strict.summary();
}

// Twins derived from triangles alone pair a -> b with b -> a when each runs exactly once,
// in two different triangles; anything else (a repeated half-edge, a triangle with a
// repeated vertex) gets none. Against that rule written out directly, on small soups of
// triangles over six vertices, where repeats are common.
RC_GTEST_PROP(Normalize, DerivedTwinsAreTheUniqueReversedHalfEdges, ()) {
    const auto pts = uniform(6, 5);
    const std::size_t k = *rc::gen::inRange<std::size_t>(1, 12);
    ProducedTriangulation p;
    p.triangles = *rc::gen::container<std::vector<std::uint32_t>>(3 * k, rc::gen::inRange(0u, 6u));
    const std::vector<std::uint32_t> T = p.triangles;
    const Triangulation t = normalize(pts, std::move(p), nullptr, true);
    const auto head = [&](std::size_t e) { return T[next_halfedge(e)]; };
    std::vector<std::int32_t> expected(T.size(), -1);
    for (std::size_t e = 0; e < T.size(); ++e) {
        std::size_t same = 0, reversed = 0, twin = 0;
        for (std::size_t f = 0; f < T.size(); ++f) {
            same += T[f] == T[e] && head(f) == head(e);
            if (T[f] == head(e) && head(f) == T[e]) ++reversed, twin = f;
        }
        if (same == 1 && reversed == 1 && twin / 3 != e / 3 && T[e] != head(e))
            expected[e] = static_cast<std::int32_t>(twin);
    }
    RC_ASSERT(t.halfedges == expected);
}

TEST(Normalize, CollinearChainInEitherDirection) {
    const std::vector<Point2> line{{2, 2}, {0, 0}, {1, 1}, {0, 0}};
    ProducedTriangulation p;
    p.hull = std::vector<std::uint32_t>{0, 2, 3};  // backwards, with a later copy
    Normalization did;
    const Triangulation t = normalize(line, p, &did);
    EXPECT_TRUE(certify(line, t).ok()) << certify(line, t).summary();
    EXPECT_TRUE(did.hull_reversed);
    EXPECT_TRUE(certify(line, normalize(line, {})).ok());
}

// Normalising conventions never hides a corrupted entry: a vertex or a twin of a
// delaunator-style copy changed is still found (and a changed vertex with the twins
// derived too). Orientation itself is a convention here: a triangle listed clockwise is
// the same triangle, so a fold of one row's orientation alone is not a defect.
RC_GTEST_PROP(Normalize, NoCorruptionIsNormalisedAway, ()) {
    const auto pts =
        uniform(*rc::gen::inRange<std::size_t>(4, 60), *rc::gen::arbitrary<std::uint32_t>());
    Result r = triangulate(pts, AdaptiveKernel{});
    RC_ASSERT(r.ok());
    RC_PRE(!r.triangulation.collinear);
    ProducedTriangulation p = delaunator_style(r.triangulation, pts);
    const std::size_t e = *rc::gen::inRange<std::size_t>(0, p.triangles.size());
    const int what = *rc::gen::inRange(0, 2);
    if (what == 0) {
        const auto v = *rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(pts.size()));
        RC_PRE(v != p.triangles[e]);
        p.triangles[e] = v;
    } else {
        const auto h =
            *rc::gen::inRange<std::int32_t>(-1, static_cast<std::int32_t>(p.triangles.size()));
        RC_PRE(h != (*p.halfedges)[e]);
        (*p.halfedges)[e] = h;
    }
    RC_ASSERT(!certify(pts, normalize(pts, p)).ok());
    if (what == 0) {  // a corrupted triangle is found with the twins derived too
        p.halfedges.reset();
        p.hull.reset();
        RC_ASSERT(!certify(pts, normalize(pts, p)).ok());
    }
}

// CGAL's own OFF writer (vertices in CGAL's order, duplicates merged): read by exidel's
// OFF reader, matched to the input points by coordinates, certified.
TEST(Normalize, CgalOffOutputCertifies) {
    const auto pts = with_repeats(400, 31);
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, test::Epick>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb>;
    CGAL::Delaunay_triangulation_2<test::Epick, Tds> dt;
    for (std::uint32_t i = 0; i < pts.size(); ++i)
        dt.insert(test::Epick::Point_2(pts[i].x, pts[i].y))->info() = i;
    std::vector<test::Epick::Point_3> vertices;
    std::map<std::uint32_t, std::size_t> index;
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
        index[v->info()] = vertices.size();
        vertices.emplace_back(v->point().x(), v->point().y(), 0);
    }
    std::vector<std::vector<std::size_t>> faces;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
        faces.push_back({index[f->vertex(0)->info()], index[f->vertex(1)->info()],
                         index[f->vertex(2)->info()]});
    }
    std::ostringstream off;
    ASSERT_TRUE(CGAL::IO::write_OFF(off, vertices, faces, CGAL::parameters::stream_precision(17)));
    const ProducedTriangulation p = io::read_produced(off.str(), io::ProducedFormat::off, pts);
    const Certificate cert = certify(pts, normalize(pts, p));
    EXPECT_TRUE(cert.ok()) << cert.summary();
    // At CGAL's default 6 digits the vertices are not the input points: a clear error.
    std::ostringstream rounded;
    ASSERT_TRUE(
        CGAL::IO::write_OFF(rounded, vertices, faces, CGAL::parameters::stream_precision(6)));
    EXPECT_THROW(io::read_produced(rounded.str(), io::ProducedFormat::off, pts), io::ReadError);
}

}  // namespace
