// The k nearest points and the points within a radius (exidel/delaunay/neighbors.hpp):
// against a brute-force exact sort (CGAL's exact distance comparison, ties by input
// index) on every degenerate family, with radii that put points exactly on the circle;
// collinear and tiny inputs, threads, bad arguments.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/neighbors.hpp"
#include "exidel/delaunay/triangulate.hpp"

namespace exidel::test {
namespace {

using delaunay::Locator;
using delaunay::NeighborRows;

using FT = CGAL::Exact_predicates_exact_constructions_kernel::FT;

/// The distinct points (first occurrences) in exact order of distance to q, ties by index.
std::vector<std::uint32_t> brute_order(std::span<const Point2> points, Point2 q) {
    const auto first = first_occurrence(points);
    std::vector<std::uint32_t> order;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        if (first[i] == i) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const auto c =
            CGAL::compare_distance_to_point(to_cgal(q), to_cgal(points[a]), to_cgal(points[b]));
        return c == CGAL::SMALLER || (c == CGAL::EQUAL && a < b);
    });
    return order;
}

bool within(Point2 q, Point2 p, double r) {
    const FT dx = FT(p.x) - FT(q.x), dy = FT(p.y) - FT(q.y);
    return dx * dx + dy * dy <= FT(r) * FT(r);
}

std::vector<std::uint32_t> row(const NeighborRows& rows, std::size_t i) {
    return {rows.vertices.begin() + static_cast<std::ptrdiff_t>(rows.offsets[i]),
            rows.vertices.begin() + static_cast<std::ptrdiff_t>(rows.offsets[i + 1])};
}

RC_GTEST_PROP(Neighbors, NearestKAndWithinRadiusMatchABruteForceSort, ()) {
    const PointSet s = *gen_point_set(60);
    auto r = delaunay::triangulate(s.points, AdaptiveKernel{});
    RC_ASSERT(r.ok());
    const auto queries = degenerate_queries(s.points, r.triangulation, 5);
    const Locator<AdaptiveKernel> locator(s.points, r.triangulation);
    const std::size_t k = *rc::gen::inRange<std::size_t>(0, 12);
    NeighborRows nearest;
    RC_ASSERT(!delaunay::nearest_k(locator, queries, k, nearest).has_value());
    RC_ASSERT(nearest.offsets.size() == queries.size() + 1);
    // Radii through a point (exact ties on the circle when the distance is a double).
    double radius = 0;
    if (!s.points.empty()) {
        const Point2 a = s.points[0], b = s.points[s.points.size() / 2];
        radius = std::hypot(a.x - b.x, a.y - b.y);
        if (!std::isfinite(radius)) radius = 1;
    }
    NeighborRows close;
    RC_ASSERT(!delaunay::within_radius(locator, queries, radius, close).has_value());
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const auto order = brute_order(s.points, queries[i]);
        const auto got = row(nearest, i);
        RC_ASSERT(got.size() == std::min(k, order.size()));
        RC_ASSERT(std::equal(got.begin(), got.end(), order.begin()));
        std::vector<std::uint32_t> inside;
        for (const std::uint32_t v : order)
            if (within(queries[i], s.points[v], radius)) inside.push_back(v);
        RC_ASSERT(row(close, i) == inside);
    }
}

TEST(Neighbors, LatticeCirclesAreExact) {
    // The lattice points at distance exactly 5 from a lattice point: (3, 4) and the rest.
    std::vector<Point2> points;
    for (int x = -8; x <= 8; ++x)
        for (int y = -8; y <= 8; ++y) points.push_back({double(x), double(y)});
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    const Locator<AdaptiveKernel> locator(points, t);
    const std::vector<Point2> q{{0, 0}, {0.5, 0.5}, {100, 100}};
    NeighborRows rows;
    ASSERT_FALSE(delaunay::within_radius(locator, q, 5.0, rows));
    std::size_t on_circle = 0;
    for (const std::uint32_t v : row(rows, 0)) {
        const double d2 = points[v].x * points[v].x + points[v].y * points[v].y;
        EXPECT_LE(d2, 25);
        on_circle += d2 == 25;
    }
    EXPECT_EQ(on_circle, 12u);            // (0, 5), (3, 4), (4, 3) and their images
    EXPECT_EQ(row(rows, 0).size(), 81u);  // the lattice points in the closed disk
    EXPECT_EQ(row(rows, 2).size(), 0u);
    // Four points tie as nearest to a cell centre: the first four are those, by index.
    ASSERT_FALSE(delaunay::nearest_k(locator, q, 6, rows));
    const auto tied = row(rows, 1);
    ASSERT_EQ(tied.size(), 6u);
    for (std::size_t j = 0; j < 4; ++j) {
        EXPECT_EQ(std::abs(points[tied[j]].x - 0.5) + std::abs(points[tied[j]].y - 0.5), 1.0);
    }
    EXPECT_TRUE(std::is_sorted(tied.begin(), tied.begin() + 4));
}

TEST(Neighbors, CollinearTinyEmptyAndThreads) {
    const std::vector<Point2> line{{0, 0}, {3, 3}, {1, 1}, {2, 2}, {1, 1}};
    const auto t = delaunay::triangulate(line, AdaptiveKernel{}).triangulation;
    ASSERT_TRUE(t.collinear);
    const Locator<AdaptiveKernel> locator(line, t);
    const std::vector<Point2> q{{2.9, 0}, {-1, -1}};
    NeighborRows rows;
    ASSERT_FALSE(delaunay::nearest_k(locator, q, 10, rows));
    EXPECT_EQ(row(rows, 0), (std::vector<std::uint32_t>{2, 3, 0, 1}));
    EXPECT_EQ(row(rows, 1), (std::vector<std::uint32_t>{0, 2, 3, 1}));
    ASSERT_FALSE(delaunay::within_radius(locator, q, std::sqrt(2.0) * 2, rows));
    EXPECT_EQ(row(rows, 1), (std::vector<std::uint32_t>{0, 2}));

    const std::vector<Point2> none;
    const delaunay::Triangulation empty =
        delaunay::triangulate(none, AdaptiveKernel{}).triangulation;
    const Locator<AdaptiveKernel> nothing(none, empty);
    ASSERT_FALSE(delaunay::nearest_k(nothing, q, 3, rows));
    EXPECT_EQ(rows.offsets, (std::vector<std::size_t>{0, 0, 0}));

    const auto points = uniform_points(30000, 4);
    const auto big = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    const Locator<AdaptiveKernel> many(points, big);
    const auto queries = uniform_points(9000, 5);
    NeighborRows one, two;
    ASSERT_FALSE(delaunay::nearest_k(many, queries, 7, one, {.threads = 1}));
    ASSERT_FALSE(delaunay::nearest_k(many, queries, 7, two, {.threads = 2}));
    EXPECT_EQ(one.vertices, two.vertices);
    ASSERT_FALSE(delaunay::within_radius(many, queries, 0.01, one, {.threads = 1}));
    ASSERT_FALSE(delaunay::within_radius(many, queries, 0.01, two, {.threads = 2}));
    EXPECT_EQ(one.vertices, two.vertices);
    EXPECT_EQ(one.offsets, two.offsets);
}

TEST(Neighbors, BadArgumentsAreClearErrors) {
    const auto points = uniform_points(40, 2);
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    const Locator<AdaptiveKernel> locator(points, t);
    const std::vector<Point2> q{{0.5, 0.5}, {0.1, std::numeric_limits<double>::infinity()}};
    NeighborRows rows;
    const auto f = delaunay::nearest_k(locator, q, 3, rows);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, delaunay::FailureKind::non_finite_input);
    EXPECT_EQ(f->input_index, 1u);
    const std::vector<Point2> ok{{0.5, 0.5}};
    EXPECT_THROW((void)delaunay::within_radius(locator, ok, -1.0, rows), std::invalid_argument);
    EXPECT_THROW((void)delaunay::within_radius(locator, ok, std::nan(""), rows),
                 std::invalid_argument);
    EXPECT_THROW(
        (void)delaunay::within_radius(locator, ok, std::numeric_limits<double>::infinity(), rows),
        std::invalid_argument);
}

}  // namespace
}  // namespace exidel::test
