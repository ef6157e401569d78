// The constrained certifier must accept constrained Delaunay triangulations built by hand
// and catch planted defects in the input, the added points, the chains and the constraints,
// besides certify()'s own findings on the mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/construct.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;

using Chain = std::vector<std::uint32_t>;

// The Delaunay triangulation of all the points (input and added), which is the constrained
// one whenever every piece is a Delaunay edge.
Triangulation delaunay(const std::vector<Point2>& pts) {
    Result r = triangulate<Instrumentation::off>(pts, AdaptiveKernel{});
    EXPECT_TRUE(r.ok());
    EXPECT_TRUE(certify(pts, r.triangulation).ok());
    return std::move(r.triangulation);
}

// The triangulation with these triangles, as given (a clockwise one stays clockwise): twins
// matched, the hull the boundary from the smallest point, the vertex map of the points.
Triangulation with_triangles(const std::vector<Point2>& pts, std::vector<std::uint32_t> tris) {
    ProducedTriangulation produced;
    produced.triangles = std::move(tris);
    return normalize(pts, std::move(produced), nullptr, /*strict=*/true);
}

// A constrained triangulation of `pts` (the first `input_count` of them the input) with
// these chains, one per segment, and `constraints` their pieces. The added points are the
// crossings of the listed pairs of segments, of the lines through their chains' ends.
ConstrainedTriangulation make_cdt(const std::vector<Point2>& pts, std::size_t input_count,
                                  Triangulation tri, const std::vector<Chain>& chains,
                                  std::vector<std::array<std::uint32_t, 2>> crossings = {}) {
    ConstrainedTriangulation cdt;
    cdt.points = pts;
    cdt.input_count = input_count;
    cdt.triangulation = std::move(tri);
    cdt.chain_offsets.push_back(0);
    for (const Chain& c : chains) {
        cdt.chain_vertices.insert(cdt.chain_vertices.end(), c.begin(), c.end());
        cdt.chain_offsets.push_back(static_cast<std::uint32_t>(cdt.chain_vertices.size()));
        for (std::size_t j = 1; j < c.size(); ++j) {
            if (c[j - 1] == c[j]) continue;  // no piece (a defect some tests plant)
            cdt.constraints.push_back({std::min(c[j - 1], c[j]), std::max(c[j - 1], c[j])});
        }
    }
    std::sort(cdt.constraints.begin(), cdt.constraints.end());
    cdt.constraints.erase(std::unique(cdt.constraints.begin(), cdt.constraints.end()),
                          cdt.constraints.end());
    for (const auto& [s, t] : crossings) {
        const auto ends = [&](std::uint32_t k) -> std::array<std::uint32_t, 2> {
            if (k >= chains.size() || chains[k].empty()) return {0, 0};
            return {chains[k].front(), chains[k].back()};
        };
        cdt.crossing_lines.push_back({ends(s)[0], ends(s)[1], ends(t)[0], ends(t)[1]});
    }
    cdt.crossings = std::move(crossings);
    return cdt;
}

// Exactly these kinds among the findings (each at least once), none other.
::testing::AssertionResult only(const Certificate& c, std::vector<FindingKind> kinds) {
    for (FindingKind k : kinds) {
        if (!c.has(k)) {
            return ::testing::AssertionFailure() << "no " << to_string(k) << " finding; found:\n"
                                                 << c.summary();
        }
    }
    for (const Finding& f : c.findings) {
        if (std::find(kinds.begin(), kinds.end(), f.kind) == kinds.end()) {
            return ::testing::AssertionFailure() << "unexpected finding:\n" << c.summary();
        }
    }
    return ::testing::AssertionSuccess();
}

// The unit square and its diagonal from (0, 0) to (1, 1). The corners are cocircular, so
// either diagonal is Delaunay; the diagonal is the one triangulate() chose.
struct Square {
    std::vector<Point2> pts{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    Triangulation tri = delaunay(pts);
    std::vector<Segment> segments;
    Square() {
        const auto has_edge = [&](std::uint32_t u, std::uint32_t v) {
            for (std::size_t e = 0; e < tri.triangles.size(); ++e) {
                if (tri.triangles[e] == u && tri.triangles[next_halfedge(e)] == v) return true;
            }
            return false;
        };
        segments = {has_edge(0, 2) ? Segment{0, 2} : Segment{1, 3}};
    }
};

TEST(ConstrainedCertify, DelaunayDiagonalOfASquare) {
    const Square sq;
    const Segment d = sq.segments[0];
    const ConstrainedTriangulation cdt = make_cdt(sq.pts, 4, sq.tri, {{d.a, d.b}});
    ASSERT_EQ(cdt.constraints, (std::vector<std::array<std::uint32_t, 2>>{{d.a, d.b}}));
    const Certificate c = certify_constrained(sq.pts, sq.segments, cdt);
    EXPECT_TRUE(c.ok()) << c.summary();

    // A hull edge, the diagonal given from its other end, and a segment from a point to
    // itself (its chain is that one vertex) are constraints too.
    const std::vector<Segment> more{{0, 1}, {d.b, d.a}, {3, 3}};
    const ConstrainedTriangulation cdt2 = make_cdt(sq.pts, 4, sq.tri, {{0, 1}, {d.b, d.a}, {3}});
    const Certificate c2 = certify_constrained(sq.pts, more, cdt2);
    EXPECT_TRUE(c2.ok()) << c2.summary();
}

// A kite long along x: its short diagonal (1, 3) is the Delaunay one, the long one (0, 2)
// is not. The triangulation with the long diagonal is written out in full.
struct Kite {
    std::vector<Point2> pts{{0, 0}, {2, -1}, {4, 0}, {2, 1}};
    Triangulation tri;
    Kite() {
        tri.triangles = {0, 1, 2, 0, 2, 3};
        tri.halfedges = {-1, -1, 3, 2, -1, -1};
        tri.hull = {0, 1, 2, 3};
        tri.vertex_of_input = {0, 1, 2, 3};
    }
};

TEST(ConstrainedCertify, NonDelaunayEdgeIsExemptOnlyAsAConstraint) {
    const Kite k;
    ASSERT_TRUE(certify(k.pts, k.tri).has(FindingKind::not_delaunay));

    const std::vector<Segment> long_diagonal{{2, 0}};
    const Certificate ok =
        certify_constrained(k.pts, long_diagonal, make_cdt(k.pts, 4, k.tri, {{2, 0}}));
    EXPECT_TRUE(ok.ok()) << ok.summary();

    // Without constraints, or with a constraint elsewhere, the long diagonal must be
    // Delaunay, and is not.
    const Certificate none = certify_constrained(k.pts, {}, make_cdt(k.pts, 4, k.tri, {}));
    EXPECT_TRUE(only(none, {FindingKind::not_delaunay}));
    const std::vector<Segment> hull_edge{{0, 1}};
    const Certificate other =
        certify_constrained(k.pts, hull_edge, make_cdt(k.pts, 4, k.tri, {{0, 1}}));
    EXPECT_TRUE(only(other, {FindingKind::not_delaunay}));

    // Listing the diagonal in `constraints` is not enough: it must be a piece of a chain.
    ConstrainedTriangulation listed = make_cdt(k.pts, 4, k.tri, {});
    listed.constraints = {{0, 2}};
    const Certificate c = certify_constrained(k.pts, {}, listed);
    EXPECT_TRUE(only(c, {FindingKind::not_delaunay, FindingKind::constraints_mismatch}));
}

// A segment from (0, 0) to (2, 0) through the input point (1, 0), with a point above and
// one below: the chain must stop at the middle point.
struct Through {
    std::vector<Point2> pts{{0, 0}, {2, 0}, {1, 0}, {1, 1}, {1, -1}};
    std::vector<Segment> segments{{0, 1}};
    Triangulation tri = delaunay(pts);
};

TEST(ConstrainedCertify, SegmentThroughAnInputPoint) {
    const Through t;
    const Certificate ok =
        certify_constrained(t.pts, t.segments, make_cdt(t.pts, 5, t.tri, {{0, 2, 1}}));
    EXPECT_TRUE(ok.ok()) << ok.summary();

    // Skipping the middle point: (0, 1) is no edge.
    const Certificate skip =
        certify_constrained(t.pts, t.segments, make_cdt(t.pts, 5, t.tri, {{0, 1}}));
    EXPECT_TRUE(only(skip, {FindingKind::chain_broken}));

    // Through the point above: its pieces are edges, but it is not on the segment.
    const Certificate off =
        certify_constrained(t.pts, t.segments, make_cdt(t.pts, 5, t.tri, {{0, 3, 1}}));
    EXPECT_TRUE(only(off, {FindingKind::chain_off_segment}));
    ASSERT_FALSE(off.findings.empty());
    EXPECT_EQ(off.findings[0].message,
              "segment 0 (0, 1): chain vertex 1 (point 3) is neither on the segment nor a "
              "crossing of it, and lies farther from it than the tolerance "
              "1.1368683772161603e-13");

    // Coming back to its own end: the end is in the hull of the anchors, but the chain
    // doubles back.
    const Certificate back =
        certify_constrained(t.pts, t.segments, make_cdt(t.pts, 5, t.tri, {{0, 2, 0, 2, 1}}));
    EXPECT_TRUE(only(back, {FindingKind::chain_broken}));
}

TEST(ConstrainedCertify, ChainMustRunFromTheFirstEndToTheSecond) {
    const Through t;
    const auto run = [&](std::vector<Chain> chains) {
        return certify_constrained(t.pts, t.segments, make_cdt(t.pts, 5, t.tri, chains));
    };
    EXPECT_TRUE(only(run({{1, 2, 0}}), {FindingKind::chain_broken}));     // backwards
    EXPECT_TRUE(only(run({{0, 2}}), {FindingKind::chain_broken}));        // stops short
    EXPECT_TRUE(only(run({{2, 1}}), {FindingKind::chain_broken}));        // starts late
    EXPECT_TRUE(only(run({{}}), {FindingKind::chain_broken}));            // empty
    EXPECT_TRUE(only(run({{0, 2, 2, 1}}), {FindingKind::chain_broken}));  // a vertex twice

    // A segment from a point to itself is one vertex, not more.
    const std::vector<Segment> loop{{2, 2}};
    EXPECT_TRUE(certify_constrained(t.pts, loop, make_cdt(t.pts, 5, t.tri, {{2}})).ok());
    EXPECT_TRUE(only(certify_constrained(t.pts, loop, make_cdt(t.pts, 5, t.tri, {{2, 2}})),
                     {FindingKind::chain_broken}));
}

// Segments (0, 0)-(2, 2) and (0, 2)-(2, 0) cross at (1, 1), a double: added point 4.
struct Cross {
    std::vector<Point2> pts{{0, 0}, {2, 2}, {0, 2}, {2, 0}, {1, 1}};
    std::vector<Point2> input{pts.begin(), pts.begin() + 4};
    std::vector<Segment> segments{{0, 1}, {2, 3}};
    std::vector<Chain> chains{{0, 4, 1}, {2, 4, 3}};
};

TEST(ConstrainedCertify, TwoSegmentsCrossingAtADouble) {
    const Cross x;
    const Certificate ok = certify_constrained(
        x.input, x.segments, make_cdt(x.pts, 4, delaunay(x.pts), x.chains, {{0, 1}}));
    EXPECT_TRUE(ok.ok()) << ok.summary();

    // One ulp off the crossing: the fan around it is still a valid mesh and Delaunay.
    std::vector<Point2> moved = x.pts;
    moved[4].x = std::nextafter(1.0, 2.0);
    const Certificate ulp = certify_constrained(
        x.input, x.segments, make_cdt(moved, 4, delaunay(moved), x.chains, {{0, 1}}));
    EXPECT_TRUE(only(ulp, {FindingKind::added_point_wrong}));

    // The crossing of a segment with itself, of segments that do not cross, of a segment
    // that does not exist.
    const Triangulation tri = delaunay(x.pts);
    EXPECT_TRUE(
        only(certify_constrained(x.input, x.segments, make_cdt(x.pts, 4, tri, x.chains, {{1, 1}})),
             {FindingKind::added_point_wrong}));
    const std::vector<Segment> three{{0, 1}, {2, 3}, {0, 3}};
    const Certificate apart = certify_constrained(
        x.input, three, make_cdt(x.pts, 4, tri, {{0, 4, 1}, {2, 4, 3}, {0, 3}}, {{1, 2}}));
    EXPECT_TRUE(only(apart, {FindingKind::added_point_wrong}));
    EXPECT_TRUE(
        only(certify_constrained(x.input, x.segments, make_cdt(x.pts, 4, tri, x.chains, {{0, 7}})),
             {FindingKind::added_point_wrong}));

    // The crossing point of segments 0 and 1 on the chain of segment 2, which neither
    // passes through it nor crosses them at a point interior to both.
    const Certificate stray = certify_constrained(
        x.input, three, make_cdt(x.pts, 4, tri, {{0, 4, 1}, {2, 4, 3}, {0, 4, 3}}, {{0, 1}}));
    EXPECT_TRUE(only(stray, {FindingKind::chain_off_segment}));
}

TEST(ConstrainedCertify, CrossingRoundedOntoAnInputPoint) {
    // Segment 0 ends at point 2, one ulp below point 1, where segment 1 starts: they cross
    // within an ulp of both, and the crossing rounds to point 2, which is not exactly on
    // segment 1. No point is added; segment 1's chain passes through point 2.
    const std::vector<Point2> pts{{2097257, 0},
                                  {2097152.9999999991, 52},
                                  {2097152.9999999991, 51.999999999999993},
                                  {2097159, -56}};
    const std::vector<Segment> segments{{0, 2}, {1, 3}};
    const Intersection i = intersection(pts[0], pts[2], pts[1], pts[3]);
    ASSERT_TRUE(i.ok());
    ASSERT_EQ(i.point, pts[2]);
    ASSERT_NE(AdaptiveKernel::orient2d(pts[1], pts[3], pts[2]), Sign::zero);
    const Triangulation tri = with_triangles(pts, {0, 1, 2, 0, 2, 3});
    const Certificate ok =
        certify_constrained(pts, segments, make_cdt(pts, 4, tri, {{0, 2}, {1, 2, 3}}));
    EXPECT_TRUE(ok.ok()) << ok.summary();

    // Without segment 0, point 2 is neither on segment 1 nor a crossing of it, but it lies
    // an ulp from it: within chain_tolerance(), where cascades may put a chain's vertex.
    const std::vector<Segment> alone{{1, 3}};
    const Certificate c = certify_constrained(pts, alone, make_cdt(pts, 4, tri, {{1, 2, 3}}));
    EXPECT_TRUE(c.ok()) << c.summary();
}

TEST(ConstrainedCertify, ChainVertexWithinTheToleranceOnly) {
    // Point 2 above the middle of segment (0, 0)-(2, 0): at exactly chain_tolerance() it may
    // be a vertex of the chain, one ulp farther it may not.
    const double tolerance = chain_tolerance({0, 0}, {2, 0});
    EXPECT_EQ(tolerance, 0x1p-43);
    for (const double h : {tolerance, std::nextafter(tolerance, 1.0)}) {
        const std::vector<Point2> pts{{0, 0}, {2, 0}, {1, h}, {1, 1}, {1, -1}};
        const std::vector<Segment> segments{{0, 1}};
        const Triangulation tri = with_triangles(pts, {0, 2, 3, 2, 1, 3, 0, 4, 2, 2, 4, 1});
        const Certificate c =
            certify_constrained(pts, segments, make_cdt(pts, 5, tri, {{0, 2, 1}}));
        if (h == tolerance)
            EXPECT_TRUE(c.ok()) << c.summary();
        else
            EXPECT_TRUE(only(c, {FindingKind::chain_off_segment})) << c.summary();
    }
    // Near zero the tolerance is 2^-1066, not 2^-44 of the coordinates.
    EXPECT_EQ(chain_tolerance({0, 0}, {0x1p-1070, 0}), 0x1p-1066);
}

TEST(ConstrainedCertify, VertexOnABentPiece) {
    // Segment 0 from (0, 0) to (3, 1) bends at its rounded crossing P with segment 1; the
    // input point P / 2 lies exactly on the piece from (0, 0) to P, not on the segment, and
    // is a vertex of the chain there.
    std::vector<Point2> pts{{0, 0}, {3, 1}, {0, 1}, {2, 0}};
    const std::vector<Segment> segments{{0, 1}, {2, 3}};
    const Point2 p = intersection(pts[0], pts[1], pts[2], pts[3]).point;
    ASSERT_NE(AdaptiveKernel::orient2d(pts[0], pts[1], p), Sign::zero);
    pts.push_back({p.x / 2, p.y / 2});  // 4, exact
    pts.push_back(p);                   // 5, added
    const std::vector<Point2> input{pts.begin(), pts.begin() + 5};
    const Triangulation tri =
        with_triangles(pts, {0, 3, 4, 4, 3, 5, 5, 3, 1, 5, 1, 2, 4, 5, 2, 0, 4, 2});
    const Certificate ok = certify_constrained(
        input, segments, make_cdt(pts, 5, tri, {{0, 4, 5, 1}, {2, 5, 3}}, {{0, 1}}));
    EXPECT_TRUE(ok.ok()) << ok.summary();

    // Point 4 is on no piece of segment 1.
    const Certificate c = certify_constrained(
        input, segments, make_cdt(pts, 5, tri, {{0, 5, 1}, {2, 5, 4, 3}}, {{0, 1}}));
    EXPECT_TRUE(c.has(FindingKind::chain_off_segment)) << c.summary();
}

TEST(ConstrainedCertify, CrossingLinesAreOfEarlierPoints) {
    // Segments 0 (y = x) and 1 (x + y = 2) cross at (1, 1), and the horizontal segment 2 at
    // y = 1/2 crosses them at (1/2, 1/2) and (3/2, 1/2): added points 6, 7 and 8.
    const std::vector<Point2> pts{{0, 0},   {2, 2}, {0, 2},     {2, 0},    {0, 0.5},
                                  {2, 0.5}, {1, 1}, {0.5, 0.5}, {1.5, 0.5}};
    const std::vector<Point2> input{pts.begin(), pts.begin() + 6};
    const std::vector<Segment> segments{{0, 1}, {2, 3}, {4, 5}};
    const std::vector<Chain> chains{{0, 7, 6, 1}, {2, 6, 8, 3}, {4, 7, 8, 5}};
    ConstrainedTriangulation cdt =
        make_cdt(pts, 6, delaunay(pts), chains, {{0, 1}, {0, 2}, {1, 2}});
    const Certificate ok = certify_constrained(input, segments, cdt);
    EXPECT_TRUE(ok.ok()) << ok.summary();
    // Point 7 is on segment 0's line, which it is a vertex of, but it comes after point 6.
    cdt.crossing_lines[0] = {7, 1, 2, 3};
    EXPECT_TRUE(only(certify_constrained(input, segments, cdt), {FindingKind::added_point_wrong}));
    // Point 6 may serve for point 8.
    cdt.crossing_lines[0] = {0, 1, 2, 3};
    cdt.crossing_lines[2] = {6, 3, 4, 5};
    EXPECT_TRUE(certify_constrained(input, segments, cdt).ok());
}

TEST(ConstrainedCertify, CrossingLinesAreEarlierPoints) {
    const Cross x;
    const Triangulation tri = delaunay(x.pts);
    const auto run = [&](const std::vector<Segment>& segments, const std::vector<Chain>& chains,
                         std::array<std::uint32_t, 2> pair, std::array<std::uint32_t, 4> lines) {
        ConstrainedTriangulation cdt = make_cdt(x.pts, 4, tri, chains, {pair});
        cdt.crossing_lines = {lines};
        return certify_constrained(x.input, segments, cdt);
    };
    // The lines in either order.
    EXPECT_TRUE(run(x.segments, x.chains, {0, 1}, {2, 3, 0, 1}).ok());
    EXPECT_TRUE(run(x.segments, x.chains, {0, 1}, {3, 2, 1, 0}).ok());
    // Through the point itself, or a point past it.
    EXPECT_TRUE(
        only(run(x.segments, x.chains, {0, 1}, {0, 1, 2, 4}), {FindingKind::added_point_wrong}));
    EXPECT_TRUE(
        only(run(x.segments, x.chains, {0, 1}, {0, 1, 9, 3}), {FindingKind::added_point_wrong}));
    // Lines that do not cross at a point interior to both.
    EXPECT_TRUE(
        only(run(x.segments, x.chains, {0, 1}, {0, 2, 1, 3}), {FindingKind::added_point_wrong}));
}

TEST(ConstrainedCertify, CrossingOfLinesIsNotACrossingOfSegments) {
    // Segment 1 runs along x + y = 2 from (0, 2) and stops at (0.5, 1.5), short of segment
    // 0's line y = x: the lines meet at (1, 1), exactly, but the segments do not.
    const std::vector<Point2> pts{{0, 0}, {2, 2}, {0, 2}, {0.5, 1.5}, {1, 1}};
    const std::vector<Point2> input{pts.begin(), pts.begin() + 4};
    const std::vector<Segment> segments{{0, 1}, {2, 3}};
    ASSERT_TRUE(intersection(pts[0], pts[1], pts[2], pts[3]).ok());
    const Certificate c = certify_constrained(
        input, segments, make_cdt(pts, 4, delaunay(pts), {{0, 4, 1}, {2, 3}}, {{0, 1}}));
    EXPECT_TRUE(only(c, {FindingKind::added_point_wrong}));
}

TEST(ConstrainedCertify, CrossingRoundedToTheNearestDoubles) {
    // y = x / 3 and y = 1 - x / 2 meet at (6/5, 2/5): neither coordinate is a double.
    const std::vector<Point2> input{{0, 0}, {3, 1}, {0, 1}, {2, 0}};
    const std::vector<Segment> segments{{0, 1}, {2, 3}};
    const Intersection i = intersection(input[0], input[1], input[2], input[3]);
    ASSERT_TRUE(i.ok());
    std::vector<Point2> pts = input;
    pts.push_back(i.point);
    // The rounded point is off at least one of the segments: the chain bends there.
    ASSERT_TRUE(AdaptiveKernel::orient2d(input[0], input[1], i.point) != Sign::zero ||
                AdaptiveKernel::orient2d(input[2], input[3], i.point) != Sign::zero);
    const std::vector<Chain> chains{{0, 4, 1}, {2, 4, 3}};
    // The fan around the crossing, whose every interior edge is a piece.
    const std::vector<std::uint32_t> fan{4, 0, 3, 4, 3, 1, 4, 1, 2, 4, 2, 0};
    const Certificate ok = certify_constrained(
        input, segments, make_cdt(pts, 4, with_triangles(pts, fan), chains, {{0, 1}}));
    EXPECT_TRUE(ok.ok()) << ok.summary();

    // A neighbouring double is wrong.
    for (const Point2 q : {Point2{std::nextafter(i.point.x, 2.0), i.point.y},
                           Point2{i.point.x, std::nextafter(i.point.y, 0.0)}}) {
        pts[4] = q;
        const Certificate c = certify_constrained(
            input, segments, make_cdt(pts, 4, with_triangles(pts, fan), chains, {{0, 1}}));
        EXPECT_TRUE(only(c, {FindingKind::added_point_wrong}));
    }
}

TEST(ConstrainedCertify, ThreeSegmentsThroughOneRoundedPoint) {
    // y = x, x + 2y = 1 and 2x + y = 1 all pass through (1/3, 1/3); each pair's crossing
    // rounds to the same double, which only the first pair (0, 1) is listed for. Segment
    // 2's line misses the rounded point, yet its chain may pass through it.
    const std::vector<Point2> input{{0, 0}, {1, 1}, {1, 0}, {-1, 1}, {0, 1}, {1, -1}};
    const std::vector<Segment> segments{{0, 1}, {2, 3}, {4, 5}};
    const Intersection i = intersection(input[0], input[1], input[2], input[3]);
    ASSERT_TRUE(i.ok());
    ASSERT_NE(AdaptiveKernel::orient2d(input[4], input[5], i.point), Sign::zero);
    std::vector<Point2> pts = input;
    pts.push_back(i.point);
    const std::vector<Chain> chains{{0, 6, 1}, {2, 6, 3}, {4, 6, 5}};
    // Every piece joins point 6 to a hull vertex: the fan around it.
    std::vector<std::uint32_t> fan;
    const std::vector<std::uint32_t> ring{0, 5, 2, 1, 4, 3};  // counter-clockwise round 6
    for (std::size_t j = 0; j < ring.size(); ++j) {
        fan.insert(fan.end(), {6, ring[j], ring[(j + 1) % ring.size()]});
    }
    const Triangulation tri = with_triangles(pts, fan);
    const Certificate ok =
        certify_constrained(input, segments, make_cdt(pts, 6, tri, chains, {{0, 1}}));
    EXPECT_TRUE(ok.ok()) << ok.summary();

    // One ulp lower, the point is no crossing of segment 2, nor on it.
    std::vector<Point2> moved = pts;
    moved[6].y = std::nextafter(pts[6].y, 0.0);
    const Certificate c = certify_constrained(
        input, segments, make_cdt(moved, 6, with_triangles(moved, fan), chains, {{0, 1}}));
    // (It lies within chain_tolerance() of segment 2, so chain 2 may still pass through it.)
    EXPECT_TRUE(only(c, {FindingKind::added_point_wrong}));
    // One ulp higher it is exactly on segment 2 (2x + y = 3 r + ulp = 1 with r the double
    // below 1/3): wrong as the crossing of segments 0 and 1, but a fine vertex of chain 2.
    moved[6].y = std::nextafter(pts[6].y, 1.0);
    ASSERT_EQ(AdaptiveKernel::orient2d(input[4], input[5], moved[6]), Sign::zero);
    const Certificate on = certify_constrained(
        input, segments, make_cdt(moved, 6, with_triangles(moved, fan), chains, {{0, 1}}));
    EXPECT_TRUE(only(on, {FindingKind::added_point_wrong}));
}

TEST(ConstrainedCertify, ConstraintsMustListExactlyThePieces) {
    const Through t;
    const ConstrainedTriangulation good = make_cdt(t.pts, 5, t.tri, {{0, 2, 1}});
    ASSERT_EQ(good.constraints, (std::vector<std::array<std::uint32_t, 2>>{{0, 2}, {1, 2}}));
    const auto run = [&](std::vector<std::array<std::uint32_t, 2>> constraints) {
        ConstrainedTriangulation cdt = good;
        cdt.constraints = std::move(constraints);
        return certify_constrained(t.pts, t.segments, cdt);
    };
    EXPECT_TRUE(only(run({{0, 2}}), {FindingKind::constraints_mismatch}));  // missing
    EXPECT_TRUE(only(run({{0, 2}, {0, 3}, {1, 2}}), {FindingKind::constraints_mismatch}));  // extra
    EXPECT_TRUE(only(run({{1, 2}, {0, 2}}), {FindingKind::constraints_mismatch}));          // order
    EXPECT_TRUE(only(run({{0, 2}, {2, 1}}), {FindingKind::constraints_mismatch}));  // reversed
    EXPECT_TRUE(only(run({{0, 2}, {0, 2}, {1, 2}}), {FindingKind::constraints_mismatch}));  // twice
    EXPECT_TRUE(only(run({}), {FindingKind::constraints_mismatch}));

    // Every missing piece counts; the first is named.
    const Certificate c = run({});
    EXPECT_EQ(c.total_findings, 2u);
    ASSERT_EQ(c.findings.size(), 1u);
    EXPECT_EQ(c.findings[0].points, (std::vector<std::int64_t>{0, 2}));
}

TEST(ConstrainedCertify, InputMismatchStopsBeforeIndexing) {
    const Through t;
    const ConstrainedTriangulation good = make_cdt(t.pts, 5, t.tri, {{0, 2, 1}});
    ASSERT_TRUE(certify_constrained(t.pts, t.segments, good).ok());
    const auto expect_mismatch = [&](const std::vector<Point2>& input,
                                     const std::vector<Segment>& segments,
                                     const ConstrainedTriangulation& cdt) {
        const Certificate c = certify_constrained(input, segments, cdt);
        EXPECT_TRUE(only(c, {FindingKind::input_mismatch}));
    };
    {  // -0.0 is not 0.0, bit for bit
        ConstrainedTriangulation cdt = good;
        cdt.points[0].x = -0.0;
        expect_mismatch(t.pts, t.segments, cdt);
    }
    {  // a NaN for a NaN is the same input, and the mesh check then says it is not finite
        std::vector<Point2> input = t.pts;
        input[3].y = std::numeric_limits<double>::quiet_NaN();
        ConstrainedTriangulation cdt = good;
        cdt.points = input;
        EXPECT_TRUE(
            only(certify_constrained(input, t.segments, cdt), {FindingKind::non_finite_input}));
    }
    {  // more input than the triangulation was made of
        std::vector<Point2> input = t.pts;
        input.push_back({5, 5});
        expect_mismatch(input, t.segments, good);
    }
    {  // input_count wrong
        ConstrainedTriangulation cdt = good;
        cdt.input_count = 4;
        cdt.crossings.push_back({0, 0});
        expect_mismatch(t.pts, t.segments, cdt);
    }
    // A segment naming a point past the input.
    expect_mismatch(t.pts, {{0, 99}}, good);
    expect_mismatch(t.pts, {{99, 1}}, good);
    {  // chains for fewer segments than given
        expect_mismatch(t.pts, {{0, 1}, {3, 4}}, good);
    }
    {  // offsets not ending at the vertices' count, decreasing, not from 0
        for (std::vector<std::uint32_t> off :
             {std::vector<std::uint32_t>{0, 2}, std::vector<std::uint32_t>{1, 3},
              std::vector<std::uint32_t>{0, 4}}) {
            ConstrainedTriangulation cdt = good;
            cdt.chain_offsets = off;
            expect_mismatch(t.pts, t.segments, cdt);
        }
        ConstrainedTriangulation cdt = good;
        cdt.chain_offsets = {0, 3, 2, 3};
        expect_mismatch(t.pts, {{0, 1}, {3, 3}, {3, 3}}, cdt);
    }
    {  // a chain vertex out of range
        ConstrainedTriangulation cdt = good;
        cdt.chain_vertices[1] = 77;
        expect_mismatch(t.pts, t.segments, cdt);
    }
    {  // crossings for points that are not there
        ConstrainedTriangulation cdt = good;
        cdt.crossings.push_back({0, 0});
        expect_mismatch(t.pts, t.segments, cdt);
    }
    {  // the lines of a crossing missing
        Cross x;
        ConstrainedTriangulation cdt = make_cdt(x.pts, 4, delaunay(x.pts), x.chains, {{0, 1}});
        ASSERT_TRUE(certify_constrained(x.input, x.segments, cdt).ok());
        cdt.crossing_lines.clear();
        expect_mismatch(x.input, x.segments, cdt);
    }
}

TEST(ConstrainedCertify, MeshFindingsAreCertifysOwn) {
    const Through t;
    {  // a clockwise triangle (its twins derived again: none match across its edges)
        std::vector<std::uint32_t> tris = t.tri.triangles;
        std::swap(tris[0], tris[1]);
        const ConstrainedTriangulation cdt =
            make_cdt(t.pts, 5, with_triangles(t.pts, tris), {{0, 2, 1}});
        const Certificate c = certify_constrained(t.pts, t.segments, cdt);
        EXPECT_TRUE(c.has(FindingKind::not_ccw)) << c.summary();
    }
    {  // a dropped triangle: twins point past the half-edges
        ConstrainedTriangulation cdt = make_cdt(t.pts, 5, t.tri, {{0, 2, 1}});
        cdt.triangulation.triangles.resize(cdt.triangulation.triangles.size() - 3);
        cdt.triangulation.halfedges.resize(cdt.triangulation.triangles.size());
        const Certificate c = certify_constrained(t.pts, t.segments, cdt);
        EXPECT_TRUE(c.has(FindingKind::index_out_of_range)) << c.summary();
    }
    {  // no triangles at all: the chain's pieces are no edges
        ConstrainedTriangulation cdt = make_cdt(t.pts, 5, t.tri, {{0, 2, 1}});
        cdt.triangulation.triangles.clear();
        cdt.triangulation.halfedges.clear();
        const Certificate c = certify_constrained(t.pts, t.segments, cdt);
        EXPECT_TRUE(c.has(FindingKind::chain_broken)) << c.summary();
    }
    {  // no vertex map: certify() takes that from other producers, this certifier not
        ConstrainedTriangulation cdt = make_cdt(t.pts, 5, t.tri, {{0, 2, 1}});
        cdt.triangulation.vertex_of_input.clear();
        EXPECT_TRUE(
            only(certify_constrained(t.pts, t.segments, cdt), {FindingKind::bad_vertex_map}));
    }
    {  // an added point that is not finite, and not a vertex either
        Cross x;
        ConstrainedTriangulation cdt =
            make_cdt(x.pts, 4, delaunay(x.input), {{0, 1}, {2, 3}}, {{0, 1}});
        cdt.points[4] = {std::numeric_limits<double>::infinity(), 0};
        cdt.triangulation.vertex_of_input.push_back(4);
        const Certificate c = certify_constrained(x.input, x.segments, cdt);
        EXPECT_TRUE(c.has(FindingKind::non_finite_input)) << c.summary();
        ASSERT_TRUE(c.has(FindingKind::added_point_wrong)) << c.summary();
        EXPECT_EQ(c.findings[0].message, "added point 0 (point 4) has a non-finite coordinate");
    }
}

TEST(ConstrainedCertify, RepeatedPointsAreNamedByTheirFirstOccurrence) {
    // Point 4 repeats point 1 and point 5 repeats point 2: a chain ends at the vertex.
    const std::vector<Point2> pts{{0, 0}, {2, 0}, {1, 0}, {1, 1}, {2, 0}, {1, 0}, {1, -1}};
    const Triangulation tri = delaunay(pts);
    ASSERT_EQ(tri.duplicates, (std::vector<std::uint32_t>{4, 5}));
    const std::vector<Segment> segments{{0, 4}, {5, 2}, {3, 5}};
    const Certificate ok =
        certify_constrained(pts, segments, make_cdt(pts, 7, tri, {{0, 2, 1}, {2}, {3, 2}}));
    EXPECT_TRUE(ok.ok()) << ok.summary();
    const Certificate c =
        certify_constrained(pts, segments, make_cdt(pts, 7, tri, {{0, 5, 4}, {2}, {3, 2}}));
    EXPECT_TRUE(only(c, {FindingKind::chain_broken}));
}

TEST(ConstrainedCertify, CollinearPointsHaveTheChainsEdges) {
    const std::vector<Point2> pts{{0, 0}, {2, 0}, {1, 0}, {3, 0}};
    const Triangulation tri = delaunay(pts);
    ASSERT_TRUE(tri.collinear);
    const std::vector<Segment> segments{{0, 1}, {3, 2}};
    EXPECT_TRUE(
        certify_constrained(pts, segments, make_cdt(pts, 4, tri, {{0, 2, 1}, {3, 1, 2}})).ok());
    EXPECT_TRUE(only(certify_constrained(pts, segments, make_cdt(pts, 4, tri, {{0, 1}, {3, 1, 2}})),
                     {FindingKind::chain_broken}));
}

TEST(ConstrainedCertify, EveryEdgeButOneIsAConstraint) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point2> pts(300);
    for (auto& p : pts) p = {u(rng), u(rng)};
    Triangulation tri = delaunay(pts);

    // An interior edge (a, b) whose quadrilateral is strictly convex and not cocircular:
    // flipped, it is not Delaunay.
    std::size_t e = 0;
    for (;; ++e) {
        ASSERT_LT(e, tri.halfedges.size());
        if (tri.halfedges[e] < 0) continue;
        const auto tw = static_cast<std::size_t>(tri.halfedges[e]);
        const Point2 a = pts[tri.triangles[e]], b = pts[tri.triangles[next_halfedge(e)]];
        const Point2 c = pts[tri.triangles[prev_halfedge(e)]];
        const Point2 d = pts[tri.triangles[prev_halfedge(tw)]];
        const Sign ca = AdaptiveKernel::orient2d(c, d, a), cb = AdaptiveKernel::orient2d(c, d, b);
        if (ca != cb && ca != Sign::zero && cb != Sign::zero &&
            AdaptiveKernel::incircle(a, b, c, d) != Sign::zero) {
            break;
        }
    }
    const auto tw = static_cast<std::size_t>(tri.halfedges[e]);
    const std::uint32_t a = tri.triangles[e], b = tri.triangles[next_halfedge(e)];
    const std::uint32_t c = tri.triangles[prev_halfedge(e)], d = tri.triangles[prev_halfedge(tw)];

    // Every other edge is a segment, given from its end in the half-edge of lower index.
    std::vector<Segment> segments;
    std::vector<Chain> chains;
    for (std::size_t h = 0; h < tri.triangles.size(); ++h) {
        const std::uint32_t u = tri.triangles[h], v = tri.triangles[next_halfedge(h)];
        if (tri.halfedges[h] >= 0 && static_cast<std::size_t>(tri.halfedges[h]) < h) continue;
        if ((u == a && v == b) || (u == b && v == a)) continue;
        segments.push_back({u, v});
        chains.push_back({u, v});
    }
    const Certificate ok =
        certify_constrained(pts, segments, make_cdt(pts, pts.size(), tri, chains));
    EXPECT_TRUE(ok.ok()) << ok.summary();

    // Triangles (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c); the quadrilateral's
    // sides, all segments, remain edges.
    const std::size_t t0 = 3 * (e / 3), t1 = 3 * (tw / 3);
    tri.triangles[t0] = c, tri.triangles[t0 + 1] = a, tri.triangles[t0 + 2] = d;
    tri.triangles[t1] = d, tri.triangles[t1 + 1] = b, tri.triangles[t1 + 2] = c;
    test::rebuild_twins(tri);
    const Certificate flipped =
        certify_constrained(pts, segments, make_cdt(pts, pts.size(), tri, chains));
    EXPECT_TRUE(only(flipped, {FindingKind::not_delaunay}));
    ASSERT_EQ(flipped.total_findings, 1u) << flipped.summary();
    std::vector<std::int64_t> named(flipped.findings[0].points.begin(),
                                    flipped.findings[0].points.begin() + 2);
    std::sort(named.begin(), named.end());
    EXPECT_EQ(named, (std::vector<std::int64_t>{std::min(c, d), std::max(c, d)}));

    // As a constraint too, the flipped edge is accepted.
    segments.push_back({d, c});
    chains.push_back({d, c});
    const Certificate constrained =
        certify_constrained(pts, segments, make_cdt(pts, pts.size(), tri, chains));
    EXPECT_TRUE(constrained.ok()) << constrained.summary();
}

TEST(ConstrainedCertify, MaxFindingsKeepsThatManyAndCountsAll) {
    const Kite k;
    // Not Delaunay, a chain from the wrong point over a non-edge, a missing constraint and
    // an extra one.
    const std::vector<Segment> segments{{0, 1}};
    ConstrainedTriangulation cdt = make_cdt(k.pts, 4, k.tri, {{3, 1}});
    cdt.constraints = {{0, 3}};
    const Certificate all = certify_constrained(k.pts, segments, cdt);
    ASSERT_GE(all.total_findings, 4u) << all.summary();
    EXPECT_EQ(all.findings.size(), all.total_findings);
    for (std::size_t limit : {0, 1, 2}) {
        const Certificate c = certify_constrained(k.pts, segments, cdt, CertifyOptions{limit});
        EXPECT_EQ(c.findings.size(), limit);
        EXPECT_EQ(c.total_findings, all.total_findings);
        EXPECT_FALSE(c.ok());
    }
}

}  // namespace
