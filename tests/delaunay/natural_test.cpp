// Natural neighbour coordinates and interpolation (exidel/delaunay/natural.hpp): the
// neighbours and the exact weights against CGAL's natural_neighbor_coordinates_2 over
// Delaunay_triangulation_2<Epeck> (exact constructions) on every degenerate family, each
// exact weight checked to be the double nearest CGAL's exact rational; Sibson's linear
// precision checked exactly; hull edges, vertices, outside, collinear input; inexact and
// lying kernels (an answer or a typed failure); bad arguments.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/natural_neighbor_coordinates_2.h>

#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/natural.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "lying_kernel.hpp"

namespace exidel::test {
namespace {

using delaunay::Locator;
using delaunay::NaturalArithmetic;
using delaunay::NaturalCoordinates;
using delaunay::Triangulation;

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactVb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Epeck>;
using ExactTds = CGAL::Triangulation_data_structure_2<ExactVb>;
using ExactDT = CGAL::Delaunay_triangulation_2<Epeck, ExactTds>;
using FT = Epeck::FT;

ExactDT exact_triangulation(std::span<const Point2> points) {
    const auto first = first_occurrence(points);
    std::vector<std::pair<Epeck::Point_2, std::uint32_t>> input;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        input.emplace_back(Epeck::Point_2(points[i].x, points[i].y), first[i]);
    return ExactDT(input.begin(), input.end());
}

Triangulation exidel_triangulation(std::span<const Point2> points) {
    auto r = delaunay::triangulate(points, AdaptiveKernel{});
    RC_ASSERT(r.ok());
    return std::move(r.triangulation);
}

/// CGAL's coordinates of q (vertex info -> exact weight), nullopt outside the hull.
std::optional<std::map<std::uint32_t, FT>> cgal_coordinates(const ExactDT& dt, Point2 q) {
    using Pair = std::pair<ExactDT::Vertex_handle, FT>;
    std::vector<Pair> coords;
    const auto r = CGAL::natural_neighbor_coordinates_2(
        dt, Epeck::Point_2(q.x, q.y), std::back_inserter(coords), CGAL::Identity<Pair>());
    if (!r.third) return std::nullopt;
    std::map<std::uint32_t, FT> out;
    for (const auto& [v, area] : coords) out[v->info()] += area / r.second;
    return out;
}

/// w is a double nearest to the exact x. Compared in GMP rationals (CGAL::exact), not in
/// Lazy_exact_nt, whose interval filters gave wrong comparisons in the sanitizer build.
bool nearest_double(double w, const FT& x) {
    const auto exact = CGAL::exact(x);
    using Q = std::decay_t<decltype(exact)>;
    const auto distance = [&](double v) {
        Q d = Q(v) - exact;
        return d < 0 ? Q(-d) : d;
    };
    const double up = std::nextafter(w, std::numeric_limits<double>::infinity());
    const double down = std::nextafter(w, -std::numeric_limits<double>::infinity());
    return distance(w) <= distance(up) && distance(w) <= distance(down);
}

NaturalCoordinates coordinates(const Locator<AdaptiveKernel>& locator,
                               std::span<const Point2> queries, NaturalArithmetic arithmetic,
                               unsigned threads = 1) {
    NaturalCoordinates out;
    const auto failure = delaunay::natural_coordinates(
        locator, queries, out, {.locate = {.threads = threads}, .arithmetic = arithmetic});
    RC_ASSERT(!failure.has_value());
    RC_ASSERT(out.offsets.size() == queries.size() + 1);
    return out;
}

RC_GTEST_PROP(Natural, ExactWeightsAreCgalsCorrectlyRounded, ()) {
    // CGAL's exact constructions are slow: small sets, and 24 of their degenerate queries.
    const PointSet s = *gen_point_set(24);
    const Triangulation t = exidel_triangulation(s.points);
    auto queries = degenerate_queries(s.points, t, *rc::gen::arbitrary<std::uint32_t>());
    delaunay::detail::SplitMix64 rng{queries.size()};
    for (std::size_t i = 0; i < queries.size() && i < 24; ++i)
        std::swap(queries[i], queries[i + rng.below(queries.size() - i)]);
    if (queries.size() > 24) queries.resize(24);
    Locator<AdaptiveKernel> locator(s.points, t);
    const NaturalCoordinates exact = coordinates(locator, queries, NaturalArithmetic::exact);
    const NaturalCoordinates rounded = coordinates(locator, queries, NaturalArithmetic::rounded);
    RC_ASSERT(rounded.offsets == exact.offsets);
    RC_ASSERT(rounded.vertices == exact.vertices);
    for (const double w : rounded.weights) RC_ASSERT(w >= 0 && w <= 1);
    if (t.collinear) return;  // CGAL's coordinates need dimension 2
    const ExactDT dt = exact_triangulation(s.points);
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const auto cgal = cgal_coordinates(dt, queries[i]);
        const std::size_t from = exact.offsets[i], to = exact.offsets[i + 1];
        RC_ASSERT(cgal.has_value() == (to > from));
        if (!cgal) continue;
        // CGAL lists the neighbours with a positive area; ours are every vertex of the
        // cavity's boundary, a few with area zero (weight 0). A positive area may round to
        // a weight of 0 (below the smallest double).
        std::map<std::uint32_t, double> ours;
        for (std::size_t j = from; j < to; ++j) {
            RC_ASSERT(ours.count(exact.vertices[j]) == 0);
            ours[exact.vertices[j]] = exact.weights[j];
        }
        for (const auto& [v, x] : *cgal) {
            RC_ASSERT(ours.count(v) == 1);
            RC_ASSERT(nearest_double(ours[v], x));
        }
        for (const auto& [v, w] : ours) RC_ASSERT(cgal->count(v) == 1 || w == 0);
    }
}

TEST(Natural, RoundedWeightsAreCloseOnUniformPoints) {
    // Measured, not a bound: on well-spread points the rounded weights differ from the
    // correctly rounded ones by a few units in the last place.
    const auto points = uniform_points(3000, 21);
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> locator(points, t);
    const auto queries = uniform_points(3000, 22);
    NaturalCoordinates exact, rounded;
    ASSERT_FALSE(delaunay::natural_coordinates(locator, queries, exact,
                                               {.arithmetic = NaturalArithmetic::exact}));
    ASSERT_FALSE(delaunay::natural_coordinates(locator, queries, rounded));
    ASSERT_EQ(exact.vertices, rounded.vertices);
    double worst = 0;
    for (std::size_t j = 0; j < exact.weights.size(); ++j)
        worst = std::max(worst, std::abs(exact.weights[j] - rounded.weights[j]));
    EXPECT_LT(worst, 1e-12);
    EXPECT_GT(exact.weights.size(), 4 * queries.size());
}

TEST(Natural, LinearPrecisionIsExact) {
    // Sibson's coordinates reproduce linear functions: sum_j w_j p_j = q. With integer
    // points (a lattice, so with cocircular stars, and random integer points), values of
    // an affine function exactly representable, and dyadic queries, the exact arithmetic's
    // value is the function's value itself.
    std::vector<Point2> points;
    for (int x = 0; x <= 12; ++x)
        for (int y = 0; y <= 12; ++y) points.push_back({double(x), double(y)});
    delaunay::detail::SplitMix64 rng{5};
    for (int i = 0; i < 200; ++i)
        points.push_back({double(rng.below(13)), double(rng.below(13))});  // duplicates too
    for (int i = 0; i < 60; ++i)
        points.push_back({double(rng.below(1200)) / 128, double(rng.below(1200)) / 128});
    const auto f = [](Point2 p) { return 3 * p.x - 2 * p.y + 7; };
    std::vector<double> values;
    for (const Point2& p : points) values.push_back(f(p));
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> locator(points, t);
    std::vector<Point2> queries;
    for (int i = 0; i < 2000; ++i)
        queries.push_back({double(rng.below(12 * 64)) / 64, double(rng.below(12 * 64)) / 64});
    std::vector<double> exact(queries.size()), rounded(queries.size());
    ASSERT_FALSE(delaunay::interpolate_natural(locator, values, 1, queries, exact, -1,
                                               {.arithmetic = NaturalArithmetic::exact}));
    ASSERT_FALSE(delaunay::interpolate_natural(locator, values, 1, queries, rounded, -1));
    for (std::size_t i = 0; i < queries.size(); ++i) {
        ASSERT_EQ(exact[i], f(queries[i])) << i;
        EXPECT_NEAR(rounded[i], f(queries[i]), 1e-10) << i;
    }
}

TEST(Natural, LargeCavityOfANearlyCircularPolygon) {
    // 300 points near one circle: every triangle's circumcircle holds the centre, so the
    // cavity is the whole triangulation (past the linear search, into the hash map), and
    // every point is a natural neighbour of the centre.
    std::vector<Point2> points;
    for (int i = 0; i < 300; ++i) {
        const double a = 2 * 3.14159265358979 * i / 300;
        points.push_back({std::cos(a), std::sin(a)});
    }
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> locator(points, t);
    const std::vector<Point2> centre{{0, 0}, {0.01, -0.02}};
    for (const auto arithmetic : {NaturalArithmetic::rounded, NaturalArithmetic::exact}) {
        NaturalCoordinates c;
        ASSERT_FALSE(delaunay::natural_coordinates(locator, centre, c, {.arithmetic = arithmetic}));
        ASSERT_EQ(c.offsets[1], 300u);
        double sx = 0, sy = 0, sum = 0;
        for (std::size_t j = 0; j < c.offsets[1]; ++j) {
            EXPECT_GE(c.weights[j], 0);
            sum += c.weights[j];
            sx += c.weights[j] * points[c.vertices[j]].x;
            sy += c.weights[j] * points[c.vertices[j]].y;
        }
        EXPECT_NEAR(sum, 1, 1e-12);
        EXPECT_NEAR(sx, 0, 1e-12);
        EXPECT_NEAR(sy, 0, 1e-12);
    }
}

TEST(Natural, VerticesHullEdgesOutsideAndCollinearInput) {
    const std::vector<Point2> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}};
    const auto t = delaunay::triangulate(square, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> locator(square, t);
    const std::vector<double> values{0, 4, 8, 4, 2};  // x + y
    const std::vector<Point2> queries{{1, 1}, {1, 0}, {4, 3}, {5, 5}, {-1, 2}};
    for (const auto arithmetic : {NaturalArithmetic::rounded, NaturalArithmetic::exact}) {
        std::vector<double> out(queries.size());
        ASSERT_FALSE(delaunay::interpolate_natural(locator, values, 1, queries, out, -7,
                                                   {.arithmetic = arithmetic}));
        EXPECT_EQ(out, (std::vector<double>{2, 1, 7, -7, -7}));
        NaturalCoordinates c;
        ASSERT_FALSE(
            delaunay::natural_coordinates(locator, queries, c, {.arithmetic = arithmetic}));
        EXPECT_EQ(c.offsets, (std::vector<std::size_t>{0, 1, 3, 5, 5, 5}));
        EXPECT_EQ(c.weights[0], 1.0);
        EXPECT_EQ(c.weights[1] + c.weights[2], 1.0);
        EXPECT_EQ(std::min(c.weights[3], c.weights[4]), 0.25);
    }
    // Collinear points: linear along the chain, nothing off it; two columns.
    const std::vector<Point2> line{{0, 0}, {2, 2}, {1, 1}, {4, 4}};
    const auto chain = delaunay::triangulate(line, AdaptiveKernel{}).triangulation;
    ASSERT_TRUE(chain.collinear);
    Locator<AdaptiveKernel> on_line(line, chain);
    const std::vector<double> two{0, 10, 2, 20, 1, 15, 4, 30};
    const std::vector<Point2> q{{3, 3}, {1, 1}, {1, 2}, {5, 5}};
    std::vector<double> out(8);
    ASSERT_FALSE(delaunay::interpolate_natural(on_line, two, 2, q, out, -1));
    EXPECT_EQ(out, (std::vector<double>{3, 25, 1, 15, -1, -1, -1, -1}));
}

TEST(Natural, AnswersDoNotDependOnThreads) {
    const auto points = uniform_points(20000, 8);
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> locator(points, t);
    auto queries = uniform_points(12000, 9);
    queries.insert(queries.end(), points.begin(), points.begin() + 100);
    NaturalCoordinates one, two;
    ASSERT_FALSE(delaunay::natural_coordinates(locator, queries, one, {.locate = {.threads = 1}}));
    ASSERT_FALSE(delaunay::natural_coordinates(locator, queries, two, {.locate = {.threads = 2}}));
    EXPECT_EQ(one.offsets, two.offsets);
    EXPECT_EQ(one.vertices, two.vertices);
    EXPECT_EQ(one.weights, two.weights);
}

TEST(Natural, BadArgumentsAreClearErrors) {
    const auto points = uniform_points(50, 1);
    const auto t = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    Locator<AdaptiveKernel> locator(points, t);
    const std::vector<Point2> queries{{0.5, 0.5}, {std::nan(""), 0.5}};
    NaturalCoordinates c;
    const auto f = delaunay::natural_coordinates(locator, queries, c);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, delaunay::FailureKind::non_finite_input);
    EXPECT_EQ(f->input_index, 1u);
    std::vector<double> values(49), out(2);
    EXPECT_THROW((void)delaunay::interpolate_natural(locator, values, 1, queries, out, 0),
                 std::invalid_argument);
    values.resize(50);
    EXPECT_THROW((void)delaunay::interpolate_natural(locator, values, 0, queries, out, 0),
                 std::invalid_argument);
}

RC_GTEST_PROP(Natural, InexactAndLyingKernelsAnswerOrFailTyped, ()) {
    const PointSet s = *gen_point_set(50);
    const Triangulation t = exidel_triangulation(s.points);
    const auto queries = degenerate_queries(s.points, t, 3);
    const auto typed = [](const std::optional<delaunay::Failure>& f) {
        if (!f) return;
        RC_ASSERT(f->kind == delaunay::FailureKind::location_exceeded ||
                  f->kind == delaunay::FailureKind::location_inconsistent);
    };
    NaturalCoordinates c;
    Locator<DoubleKernel> dbl(s.points, t);
    typed(delaunay::natural_coordinates(dbl, queries, c));
    if (t.collinear || queries.empty()) return;
    for (const auto mode : {LyingKernel::always_flip, LyingKernel::random_orient,
                            LyingKernel::random, LyingKernel::positive}) {
        Locator<LyingKernel> liar(s.points, t, LyingKernel{mode});
        for (const auto arithmetic : {NaturalArithmetic::rounded, NaturalArithmetic::exact}) {
            const auto f =
                delaunay::natural_coordinates(liar, queries, c, {.arithmetic = arithmetic});
            typed(f);
            if (!f) {
                for (const double w : c.weights) RC_ASSERT(std::isfinite(w));
            }
        }
    }
}

}  // namespace
}  // namespace exidel::test
