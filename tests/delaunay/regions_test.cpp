// Regions of a constrained triangulation (exidel/delaunay/regions.hpp): fill rules, hole
// seeds, open polylines, and the area of the domain against the polygons' exact area.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "exidel/delaunay/constrained.hpp"
#include "exidel/delaunay/regions.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::test {
namespace {

using delaunay::classify_regions;
using delaunay::ConstrainedResult;
using delaunay::ConstrainedTriangulation;
using delaunay::FillRule;
using delaunay::RegionOptions;
using delaunay::Regions;
using delaunay::Segment;

/// Points and the segments of closed rings over them.
struct Rings {
    std::vector<Point2> points;
    std::vector<Segment> segments;
    void ring(const std::vector<Point2>& corners) {
        const auto first = static_cast<std::uint32_t>(points.size());
        const auto k = static_cast<std::uint32_t>(corners.size());
        for (std::uint32_t i = 0; i < k; ++i) {
            points.push_back(corners[i]);
            segments.push_back({first + i, first + (i + 1) % k});
        }
    }
};

ConstrainedTriangulation triangulate(const Rings& r) {
    const ConstrainedResult res =
        delaunay::constrained_delaunay<AdaptiveKernel>(r.points, r.segments);
    EXPECT_TRUE(res.ok()) << res.failure->message;
    return res.cdt;
}

/// Twice the area of the triangles in the domain, exact for integer coordinates below 2^26.
std::int64_t twice_inside_area(const ConstrainedTriangulation& cdt, const Regions& r) {
    std::int64_t sum = 0;
    const auto& t = cdt.triangulation.triangles;
    for (const std::uint32_t i : r.inside_triangles()) {
        const Point2 a = cdt.points[t[3 * i]], b = cdt.points[t[3 * i + 1]],
                     c = cdt.points[t[3 * i + 2]];
        sum += static_cast<std::int64_t>((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    }
    return sum;
}

/// Twice the signed area of a polygon with integer corners (the shoelace formula).
std::int64_t twice_area(const std::vector<Point2>& p) {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Point2 a = p[i], b = p[(i + 1) % p.size()];
        sum += static_cast<std::int64_t>(a.x * b.y - b.x * a.y);
    }
    return sum;
}

const std::vector<Point2> outer{{0, 0}, {4, 0}, {4, 4}, {0, 4}};      // counter-clockwise
const std::vector<Point2> inner_cw{{1, 1}, {1, 3}, {3, 3}, {3, 1}};   // clockwise
const std::vector<Point2> inner_ccw{{1, 1}, {3, 1}, {3, 3}, {1, 3}};  // counter-clockwise

TEST(Regions, SquareWithAHoleUnderBothRules) {
    Rings r;
    r.ring(outer);
    r.ring(inner_cw);
    const ConstrainedTriangulation cdt = triangulate(r);
    for (const FillRule rule : {FillRule::even_odd, FillRule::non_zero}) {
        RegionOptions o;
        o.rule = rule;
        const Regions g = classify_regions(cdt, o);
        EXPECT_TRUE(g.closed);
        EXPECT_EQ(twice_inside_area(cdt, g), 2 * (16 - 4));
        EXPECT_EQ(g.region_count, 2u);  // the band and the hole; the hull is the outer ring
        for (std::size_t t = 0; t < g.inside.size(); ++t) {
            EXPECT_EQ(g.depth[t] == 1, g.inside[t] == 1);
            EXPECT_EQ(g.winding[t], g.depth[t] == 1 ? 1 : 0);
        }
    }
}

TEST(Regions, SameOrientationRingsDifferBetweenTheRules) {
    // Both rings counter-clockwise: the inner square has winding number 2, depth 2.
    Rings r;
    r.ring(outer);
    r.ring(inner_ccw);
    const ConstrainedTriangulation cdt = triangulate(r);
    RegionOptions o;
    o.rule = FillRule::even_odd;
    EXPECT_EQ(twice_inside_area(cdt, classify_regions(cdt, o)), 2 * 12);
    o.rule = FillRule::non_zero;
    const Regions g = classify_regions(cdt, o);
    EXPECT_TRUE(g.closed);
    EXPECT_EQ(twice_inside_area(cdt, g), 2 * 16);
    EXPECT_EQ(*std::max_element(g.winding.begin(), g.winding.end()), 2);
}

TEST(Regions, EnclosedKeepsWhatTheSegmentsCloseOff) {
    // Triangle's convention: an L-shaped outline with a material region (a closed ring, no
    // hole seed) inside it and a lone point outside; the concavity and the outside go, the
    // ring's inside stays. Even-odd would remove the ring's inside (depth 2).
    const std::vector<Point2> l_shape{{0, 0}, {8, 0}, {8, 4}, {4, 4}, {4, 8}, {0, 8}};
    Rings r;
    r.ring(l_shape);
    r.ring(inner_ccw);
    r.points.push_back({12, 12});
    const ConstrainedTriangulation cdt = triangulate(r);
    RegionOptions o;
    o.rule = FillRule::enclosed;
    EXPECT_EQ(twice_inside_area(cdt, classify_regions(cdt, o)), twice_area(l_shape));
    o.rule = FillRule::even_odd;
    EXPECT_EQ(twice_inside_area(cdt, classify_regions(cdt, o)), twice_area(l_shape) - 2 * 4);
    o.rule = FillRule::enclosed;
    o.holes = {{2, 2}};
    EXPECT_EQ(twice_inside_area(cdt, classify_regions(cdt, o)), twice_area(l_shape) - 2 * 4);
}

TEST(Regions, AttributesLabelTheirRegions) {
    Rings r;
    r.ring(outer);
    r.ring(inner_ccw);
    const ConstrainedTriangulation cdt = triangulate(r);
    RegionOptions o;
    o.rule = FillRule::all;
    o.attributes = {{{2, 2.5}, 7},    // the inner square
                    {{0.5, 0.5}, 1},  // the ring between the squares
                    {{3.5, 3.5}, 2},  // the same region again: overrides 1
                    {{1, 2}, 9},      // on a piece: labels nothing
                    {{9, 9}, 9}};     // outside
    const Regions g = classify_regions(cdt, o);
    ASSERT_EQ(g.attribute.size(), cdt.triangulation.triangle_count());
    const auto& t = cdt.triangulation.triangles;
    for (std::size_t i = 0; i < g.attribute.size(); ++i) {
        // The centroid's side: inside the inner square [1, 3]^2 or not.
        const double cx =
            (cdt.points[t[3 * i]].x + cdt.points[t[3 * i + 1]].x + cdt.points[t[3 * i + 2]].x) / 3;
        const double cy =
            (cdt.points[t[3 * i]].y + cdt.points[t[3 * i + 1]].y + cdt.points[t[3 * i + 2]].y) / 3;
        const bool inner = cx > 1 && cx < 3 && cy > 1 && cy < 3;
        EXPECT_EQ(g.attribute[i], inner ? 7.0 : 2.0) << i;
    }
    EXPECT_EQ(g.unplaced_attributes, (std::vector<std::size_t>{3, 4}));
    EXPECT_TRUE(classify_regions(cdt, {}).attribute.empty());
}

TEST(Regions, HoleSeedsRemoveTheirRegionOnly) {
    Rings r;
    r.ring(outer);
    r.ring(inner_ccw);
    const ConstrainedTriangulation cdt = triangulate(r);
    RegionOptions o;
    o.rule = FillRule::all;
    EXPECT_EQ(twice_inside_area(cdt, classify_regions(cdt, o)), 2 * 16);
    o.holes = {{2, 2.5},                                       // in the inner square
               {1, 2},                                         // on a piece
               {9, 9},                                         // outside the hull
               {std::numeric_limits<double>::quiet_NaN(), 0},  // not a point
               {1, 1}};                                        // a vertex
    const Regions g = classify_regions(cdt, o);
    EXPECT_EQ(twice_inside_area(cdt, g), 2 * 12);
    EXPECT_EQ(g.unplaced_holes, (std::vector<std::size_t>{1, 2, 3, 4}));
}

TEST(Regions, OpenPolylineIsNotClosed) {
    // A breakline inside the square: walks on either side of its end disagree.
    Rings r;
    r.ring(outer);
    r.points.push_back({1, 2});
    r.points.push_back({3, 2});
    r.segments.push_back({4, 5});
    const ConstrainedTriangulation cdt = triangulate(r);
    const Regions g = classify_regions(cdt);
    EXPECT_FALSE(g.closed);
    EXPECT_EQ(g.region_count, 1u);  // the breakline cuts nothing off
}

TEST(Regions, CrossingRingsUnderEvenOdd) {
    // Two overlapping squares: even-odd leaves out their intersection, non-zero keeps it.
    Rings r;
    r.ring({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    r.ring({{2, 2}, {6, 2}, {6, 6}, {2, 6}});
    const ConstrainedTriangulation cdt = triangulate(r);
    RegionOptions o;
    o.rule = FillRule::even_odd;
    EXPECT_EQ(twice_inside_area(cdt, classify_regions(cdt, o)), 2 * (16 + 16 - 2 * 4));
    o.rule = FillRule::non_zero;
    const Regions g = classify_regions(cdt, o);
    EXPECT_TRUE(g.closed);
    EXPECT_EQ(twice_inside_area(cdt, g), 2 * (16 + 16 - 4));
}

TEST(Regions, NoTriangles) {
    Rings r;
    r.points = {{0, 0}, {1, 1}, {2, 2}};
    r.segments = {{0, 2}};
    const ConstrainedTriangulation cdt = triangulate(r);
    RegionOptions o;
    o.holes = {{1, 0}};
    const Regions g = classify_regions(cdt, o);
    EXPECT_TRUE(g.inside.empty());
    EXPECT_EQ(g.unplaced_holes, (std::vector<std::size_t>{0}));
}

/// A star-shaped polygon around (cx, cy) with integer corners, radii in [lo, hi).
std::vector<Point2> star(double cx, double cy, int count, int lo, int hi, bool clockwise) {
    std::vector<Point2> p;
    const double step = 2 * std::numbers::pi / count;
    for (int i = 0; i < count; ++i) {
        const double angle = (i + *rc::gen::inRange(0, 50) / 100.0) * step;
        const double radius = *rc::gen::inRange(lo, hi);
        p.push_back(
            {std::round(cx + radius * std::cos(angle)), std::round(cy + radius * std::sin(angle))});
    }
    if (clockwise) std::reverse(p.begin(), p.end());
    return p;
}

RC_GTEST_PROP(Regions, DomainAreaIsThePolygonsAreaExactly, ()) {
    // An outer star, one to three star holes around points inside it, and interior points.
    const double cx = *rc::gen::inRange(-1000000, 1000000), cy = *rc::gen::inRange(-1000, 1000);
    Rings r;
    const std::vector<Point2> shell = star(cx, cy, *rc::gen::inRange(8, 64), 3000, 9000, false);
    r.ring(shell);
    std::int64_t area = twice_area(shell);
    const int holes = *rc::gen::inRange(0, 4);
    RegionOptions seeds;
    seeds.rule = FillRule::all;
    for (int h = 0; h < holes; ++h) {
        // Hole centres 2000 apart on a circle of radius 1400: holes of radius < 700 are
        // disjoint and inside the shell (radius >= 3000).
        const double a = h * 2 * std::numbers::pi / 3;
        const double hx = std::round(cx + 1400 * std::cos(a)),
                     hy = std::round(cy + 1400 * std::sin(a));
        const std::vector<Point2> hole = star(hx, hy, *rc::gen::inRange(3, 24), 200, 600, true);
        r.ring(hole);
        area += twice_area(hole);  // negative: clockwise
        seeds.holes.push_back({hx, hy});
    }
    const int extra = *rc::gen::inRange(0, 40);
    for (int i = 0; i < extra; ++i)
        r.points.push_back(
            {cx + *rc::gen::inRange(-2000, 2000), cy + *rc::gen::inRange(-2000, 2000)});
    const ConstrainedResult res =
        delaunay::constrained_delaunay<AdaptiveKernel>(r.points, r.segments);
    RC_ASSERT(res.ok());
    RC_ASSERT(res.cdt.added_count() == 0u);
    for (const FillRule rule : {FillRule::even_odd, FillRule::non_zero}) {
        RegionOptions o;
        o.rule = rule;
        const Regions g = classify_regions(res.cdt, o);
        RC_ASSERT(g.closed);
        RC_ASSERT(twice_inside_area(res.cdt, g) == area);
        // Counter-clockwise shell, clockwise holes, disjoint: winding 1 inside, 0 elsewhere.
        for (std::size_t t = 0; t < g.inside.size(); ++t)
            RC_ASSERT(g.winding[t] == (g.inside[t] != 0 ? 1 : 0));
    }
    // FillRule::all with the holes' centres as seeds: every triangle of the hull but those
    // of the holes.
    const Regions g = classify_regions(res.cdt, seeds);
    RC_ASSERT(g.unplaced_holes.empty());
    const std::int64_t holes_area = area - twice_area(shell);  // negative: clockwise
    RC_ASSERT(twice_inside_area(res.cdt, g) ==
              twice_inside_area(res.cdt, classify_regions(res.cdt, {FillRule::all, {}})) +
                  holes_area);
}

}  // namespace
}  // namespace exidel::test
