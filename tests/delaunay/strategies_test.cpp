// The strategies of exidel::delaunay::triangulate beyond the paper's order: radial
// insertion, strips merged by the Guibas-Stolfi zipper, threads. Every exact run is
// certified and compared with CGAL; the strategies agree with each other; thread count
// never changes the output; merge-specific degenerate families; inexact kernels fail
// cleanly.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include "delaunay_support.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/dynamic.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;
using exidel::test::EdgeSets;

constexpr std::size_t max_points = 160;
constexpr std::size_t max_points_gmp = 40;

/// A strategy with its knobs, drawn so that strips are small enough to be merged many
/// times (1, 2 and 3 mean the smallest non-collinear strips: pure divide and conquer).
rc::Gen<Options> gen_options() {
    return rc::gen::exec([] {
        Options o;
        o.strategy = *rc::gen::element(Strategy::automatic, Strategy::lexicographic,
                                       Strategy::radial, Strategy::strips, Strategy::strips);
        o.incircle = *rc::gen::element(InCirclePolicy::determinant, InCirclePolicy::cosine);
        o.strip_points = *rc::gen::inRange<std::size_t>(1, 40);
        o.strip_tiles = *rc::gen::element<std::size_t>(0, 1, 2, 3, 5);
        o.threads = *rc::gen::inRange(1u, 3u);
        return o;
    });
}

std::string describe(const Options& o) {
    return std::string(to_string(o.strategy)) + " strip_points " + std::to_string(o.strip_points) +
           " strip_tiles " + std::to_string(o.strip_tiles) + " threads " +
           std::to_string(o.threads) +
           (o.incircle == InCirclePolicy::cosine ? " cosine" : " determinant");
}

template <class K>
Result check_against_cgal(std::span<const Point2> pts, const K& kernel, const Options& o,
                          const EdgeSets& oracle) {
    const Result r = triangulate<Instrumentation::theorem1>(pts, kernel, o);
    if (!r.ok()) RC_FAIL(describe(o) + ": " + r.failure->message);
    const Certificate c = certify(pts, r.triangulation);
    if (!c.ok()) RC_FAIL(describe(o) + ": certify: " + c.summary());
    RC_ASSERT(r.strategy ==
              choose_strategy(pts.size() - r.triangulation.duplicates.size(), o.strategy));
    RC_ASSERT(r.counters.theorem1_violations == 0u);
    RC_ASSERT(r.counters.theorem1_checks == r.counters.incircle_tests);
    RC_ASSERT(r.counters.triangles_created - r.counters.triangles_destroyed ==
              r.triangulation.triangle_count());
    if (r.strips == 1) RC_ASSERT(r.counters.merge_cross_edges == 0u);
    const EdgeSets ours = test::edge_sets(pts, r.triangulation);
    RC_ASSERT(ours.collinear == oracle.collinear);
    RC_ASSERT(ours.forced == oracle.forced);
    if (ours.free_edges == 0) RC_ASSERT(ours.triangles == oracle.triangles);
    return r;
}

RC_GTEST_PROP(DelaunayStrategies, AdaptiveEveryStrategyMatchesCgal, ()) {
    const auto s = *test::gen_point_set(max_points);
    const Options o = *gen_options();
    RC_TAG(s.family);
    RC_TAG(std::string(to_string(o.strategy)));
    check_against_cgal(s.points, AdaptiveKernel{}, o, test::cgal_edge_sets(s.points));
}

RC_GTEST_PROP(DelaunayStrategies, GmpExactEveryStrategyMatchesCgal, ()) {
    const auto s = *test::gen_point_set(max_points_gmp);
    const Options o = *gen_options();
    RC_TAG(std::string(to_string(o.strategy)));
    check_against_cgal(s.points, GmpExactKernel{}, o, test::cgal_edge_sets(s.points));
}

// With no four points cocircular the Delaunay triangulation is unique: every strategy
// must produce the same triangles (as sets; the arrays' order differs by strategy).
RC_GTEST_PROP(DelaunayStrategies, StrategiesAgreeWhenNoFourPointsAreCocircular, ()) {
    const auto s = *test::gen_point_set(max_points);
    const EdgeSets oracle = test::cgal_edge_sets(s.points);
    RC_PRE(oracle.free_edges == 0u);
    std::set<test::Tri> first;
    for (const Strategy st : {Strategy::lexicographic, Strategy::radial, Strategy::strips}) {
        Options o;
        o.strategy = st;
        o.strip_points = 5;
        const Result r = triangulate(s.points, AdaptiveKernel{}, o);
        RC_ASSERT(r.ok());
        const auto tris = test::edge_sets(s.points, r.triangulation).triangles;
        if (st == Strategy::lexicographic) {
            first = tris;
        } else {
            RC_ASSERT(tris == first);
        }
    }
}

// Which thread builds which strip or merges which pair never matters: the arrays are
// identical, not only the triangulations.
RC_GTEST_PROP(DelaunayStrategies, OneAndTwoThreadsGiveIdenticalArrays, ()) {
    const auto s = *test::gen_point_set(600);
    Options o;
    o.strategy = Strategy::strips;
    o.strip_points = *rc::gen::inRange<std::size_t>(1, 60);
    o.strip_tiles = *rc::gen::inRange<std::size_t>(1, 7);
    o.threads = 1;
    const Result one = triangulate(s.points, AdaptiveKernel{}, o);
    o.threads = 2;
    const Result two = triangulate(s.points, AdaptiveKernel{}, o);
    if (!one.ok()) RC_FAIL(one.failure->message);
    if (!two.ok()) RC_FAIL(two.failure->message);
    RC_ASSERT(one.triangulation.triangles == two.triangulation.triangles);
    RC_ASSERT(one.triangulation.halfedges == two.triangulation.halfedges);
    RC_ASSERT(one.triangulation.hull == two.triangulation.hull);
}

// ---- merge-specific families -----------------------------------------------------------

/// Points on a few vertical lines x = 0, 1, ... (integer y, repeats allowed): strips cut
/// inside a column, so facing hulls are collinear and every merge starts on a common
/// tangent through several collinear points.
rc::Gen<std::vector<Point2>> gen_columns() {
    return rc::gen::exec([] {
        const int columns = *rc::gen::inRange(2, 5);
        const std::size_t n = *rc::gen::inRange<std::size_t>(3, 80);
        std::vector<Point2> p(n);
        for (auto& q : p) {
            q = {double(*rc::gen::inRange(0, columns)), double(*rc::gen::inRange(-20, 21))};
        }
        return p;
    });
}

/// Lattice points on circles x^2 + y^2 = 25 and 625 (cocircular groups of 12 and 20),
/// with a few random lattice points: strip cuts run through the circles, so the zipper
/// meets cocircular cross-edge candidates.
rc::Gen<std::vector<Point2>> gen_cocircular_across_cuts() {
    return rc::gen::exec([] {
        std::vector<Point2> p;
        for (int r : {5, 25}) {
            for (int x = -r; x <= r; ++x) {
                for (int y = -r; y <= r; ++y) {
                    if (x * x + y * y == r * r) p.push_back({double(x), double(y)});
                }
            }
        }
        const std::size_t extra = *rc::gen::inRange<std::size_t>(0, 30);
        for (std::size_t i = 0; i < extra; ++i) {
            p.push_back({double(*rc::gen::inRange(-30, 31)), double(*rc::gen::inRange(-30, 31))});
        }
        std::shuffle(p.begin(), p.end(), std::mt19937(*rc::gen::arbitrary<std::uint32_t>()));
        return p;
    });
}

void check_merges(const std::vector<Point2>& pts) {
    const EdgeSets oracle = test::cgal_edge_sets(pts);
    for (std::size_t sp : {1, 2, 3, 4, 7}) {
        for (std::size_t tiles : {1, 3}) {
            Options o;
            o.strategy = Strategy::strips;
            o.strip_points = sp;
            o.strip_tiles = tiles;
            check_against_cgal(pts, AdaptiveKernel{}, o, oracle);
        }
    }
}

/// Points on a few horizontal lines y = 0, 1, ... (integer x, repeats allowed): tiles
/// cut between the lines, a tile holding a single line is collinear and joins its
/// neighbour, and stacked pieces meet on collinear facing hulls.
rc::Gen<std::vector<Point2>> gen_rows() {
    return rc::gen::exec([] {
        const int rows = *rc::gen::inRange(2, 7);
        const std::size_t n = *rc::gen::inRange<std::size_t>(3, 120);
        std::vector<Point2> p(n);
        for (auto& q : p) {
            q = {double(*rc::gen::inRange(-30, 31)), double(*rc::gen::inRange(0, rows))};
        }
        return p;
    });
}

RC_GTEST_PROP(DelaunayMerge, PointsOnAFewVerticalLines, ()) { check_merges(*gen_columns()); }

RC_GTEST_PROP(DelaunayMerge, PointsOnAFewHorizontalLines, ()) { check_merges(*gen_rows()); }

RC_GTEST_PROP(DelaunayMerge, CocircularPointsSpanningCuts, ()) {
    check_merges(*gen_cocircular_across_cuts());
}

// All points on two vertical lines: in lexicographic order the second line comes after
// the whole first one, so every cut leaves a collinear right piece, which the merge does
// not take (it needs triangles on both sides): the strips strategy then makes a single
// strip. Three lines give real merges with collinear facing hulls.
TEST(DelaunayMerge, AllPointsOnTwoAndThreeVerticalLines) {
    for (const int lines : {2, 3}) {
        std::vector<Point2> pts;
        for (int y = 0; y < 20; ++y) {
            for (int x = 0; x < lines; ++x) pts.push_back({double(x), double((y * (3 + x)) % 20)});
        }
        for (std::size_t sp : {1, 3, 10, 19, 21}) {
            Options o;
            o.strategy = Strategy::strips;
            o.strip_points = sp;
            const Result r = triangulate(pts, AdaptiveKernel{}, o);
            ASSERT_TRUE(r.ok()) << r.failure->message;
            EXPECT_TRUE(certify(pts, r.triangulation).ok()) << lines << " lines, " << sp;
            if (lines == 2) {
                EXPECT_EQ(r.strips, 1u);
            } else if (sp < 20) {
                EXPECT_GT(r.strips, 1u) << sp;  // cuts fall inside the columns
            }
        }
    }
}

TEST(DelaunayMerge, StripsOfOneTwoAndThreePointsArePureDivideAndConquer) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Point2> pts(300);
    for (auto& p : pts) p = {u(rng), u(rng)};
    for (std::size_t sp : {1, 2, 3}) {
        Options o;
        o.strategy = Strategy::strips;
        o.strip_points = sp;
        const Result r = triangulate<Instrumentation::counters>(pts, AdaptiveKernel{}, o);
        ASSERT_TRUE(r.ok()) << r.failure->message;
        EXPECT_TRUE(certify(pts, r.triangulation).ok());
        // Random points: no three collinear, so every strip has exactly three points.
        EXPECT_EQ(r.strips, 100u);
        EXPECT_GT(r.counters.merge_cross_edges, 0u);
    }
}

// Found while writing the merge: the zipper's base swung back along a chain edge
// (cross edges 0-3, 1-3, 2-3, 2-4, 1-4, ...), so the triangle of the left strip behind
// that edge was destroyed and the edge got a new triangle on both sides. The first
// version linked it to the destroyed one.
TEST(DelaunayMergeRegression, BaseSwingsBackAlongAChainEdge) {
    const std::vector<Point2> pts{
        {0x1.82a3befaddcbcp-1, 0x1.472f1f73724ap-1},  {0x1.81192cfe1cbcfp-1, 0x1.171621fc50d6ap-3},
        {0x1.ce79451c9a6c3p-1, 0x1.814dc629c7f4fp-4}, {0x1.262e1432cba85p-1, 0x1.7dd645e8fadeep-2},
        {0x1.187273d8bae7fp-2, 0x1.8fa32b81059dfp-2}, {0x1.95c23685de9fap-7, 0x1.0c232392c1217p-1}};
    Options o;
    o.strategy = Strategy::strips;
    o.strip_points = 3;
    const Result r = triangulate(pts, AdaptiveKernel{}, o);
    ASSERT_TRUE(r.ok()) << r.failure->message;
    EXPECT_EQ(r.strips, 2u);
    EXPECT_TRUE(certify(pts, r.triangulation).ok()) << certify(pts, r.triangulation).summary();
}

std::vector<Point2> read_fixture(const std::string& name) {
    std::ifstream in(std::string(EXIDEL_DELAUNAY_FIXTURES) + "/" + name);
    EXPECT_TRUE(in) << name;
    std::vector<Point2> pts;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        char* end = nullptr;
        const double x = std::strtod(line.c_str(), &end);
        const double y = std::strtod(end, nullptr);
        pts.push_back({x, y});
    }
    return pts;
}

// Found by OneAndTwoThreadsGiveIdenticalArrays: the zipper's walk guard was 8 steps per
// point; this exact merge needs about 9 (wide exponents make vertices of very high
// degree). The guard now allows 64.
TEST(DelaunayMergeRegression, WalkGuardWideExponents) {
    const auto pts = read_fixture("merge_walk_guard_wide_exponents.xy");
    ASSERT_EQ(pts.size(), 205u);
    for (std::size_t sp : {7, 14, 30}) {
        Options o;
        o.strategy = Strategy::strips;
        o.strip_points = sp;
        const Result r = triangulate(pts, AdaptiveKernel{}, o);
        ASSERT_TRUE(r.ok()) << r.failure->message;
        EXPECT_TRUE(certify(pts, r.triangulation).ok());
    }
}

// ---- held-out real data --------------------------------------------------------------------

/// The time-zone cities of the tz database (Debian's tzdata: zone.tab, ISO 6709
/// coordinates "+DDMM[SS]+DDDMM[SS]"), as (longitude, latitude) in degrees. Real data
/// nobody tuned anything on: clustered, with near-collinear runs along coasts.
std::vector<Point2> time_zone_cities(const char* path) {
    std::ifstream in(path);
    std::vector<Point2> pts;
    auto degrees = [](const std::string& s, int deg_digits) {
        const double sign = s[0] == '-' ? -1 : 1;
        const std::string d = s.substr(1);
        const double deg = std::stod(d.substr(0, deg_digits));
        const double min = std::stod(d.substr(deg_digits, 2));
        const double sec =
            d.size() > std::size_t(deg_digits + 2) ? std::stod(d.substr(deg_digits + 2, 2)) : 0;
        return sign * (deg + min / 60 + sec / 3600);
    };
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t a = line.find('\t'), b = line.find('\t', a + 1);
        const std::string c = line.substr(a + 1, b - a - 1);  // +DDMM+DDDMM or with seconds
        const std::size_t split = c.find_first_of("+-", 1);
        const std::string lat = c.substr(0, split), lon = c.substr(split);
        pts.push_back({degrees(lon, 3), degrees(lat, 2)});
    }
    return pts;
}

TEST(DelaunayRealData, TimeZoneCitiesUnderEveryStrategy) {
    for (const char* path : {"/usr/share/zoneinfo/zone.tab", "/usr/share/zoneinfo/zone1970.tab"}) {
        const std::vector<Point2> pts = time_zone_cities(path);
        ASSERT_GT(pts.size(), 300u) << path << " (Debian package tzdata)";
        const EdgeSets oracle = test::cgal_edge_sets(pts);
        for (const Strategy st :
             {Strategy::lexicographic, Strategy::radial, Strategy::strips, Strategy::automatic}) {
            for (const std::size_t sp : {3, 40}) {
                Options o;
                o.strategy = st;
                o.strip_points = sp;
                o.threads = 2;
                const Result r = triangulate(pts, AdaptiveKernel{}, o);
                ASSERT_TRUE(r.ok()) << path << " " << describe(o) << ": " << r.failure->message;
                EXPECT_TRUE(certify(pts, r.triangulation).ok()) << path << " " << describe(o);
                const EdgeSets ours = test::edge_sets(pts, r.triangulation);
                EXPECT_EQ(ours.forced, oracle.forced) << path << " " << describe(o);
            }
        }
    }
}

// ---- the default's shape rule ------------------------------------------------------------

// Above automatic_strips_from points `automatic` runs strips, except on points along a
// convex curve that the radial order follows (a parabola), where it keeps radial; not on
// a circle (the radial order about its own centre is noise) nor on scattered points.
TEST(DelaunayAutomatic, RadialOnAConvexCurveStripsElsewhere) {
    const std::size_t n = automatic_strips_from + 7;
    std::vector<Point2> parabola(n), circle(n), scattered(n);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = static_cast<double>(i + 1);  // one branch, as in bench/
        parabola[i] = {x, x * x};
        const double t = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
        circle[i] = {std::cos(t), std::sin(t)};
        scattered[i] = {uniform(rng), uniform(rng)};
    }
    std::shuffle(parabola.begin(), parabola.end(), rng);
    const std::pair<const std::vector<Point2>*, Strategy> cases[] = {
        {&parabola, Strategy::radial}, {&circle, Strategy::strips}, {&scattered, Strategy::strips}};
    for (const auto& [pts, expected] : cases) {
        const Result r = triangulate(*pts, AdaptiveKernel{});
        ASSERT_TRUE(r.ok()) << r.failure->message;
        EXPECT_EQ(r.strategy, expected) << to_string(r.strategy);
        EXPECT_TRUE(certify(*pts, r.triangulation).ok()) << to_string(r.strategy);
    }
}

// GPS tracks (points along many curves that cross any sweep) make a radial run erode about
// 28 edges per point at 3000 points; `automatic` gives such a run up and inserts the points by
// cavities (external.hpp, automatic_erosion_limit), in the one radial run below 2^15 points and
// per strip above. Requested orders never give up; Poisson-disc points (about 4 per point)
// never do. The result is certified, agrees with CGAL and with the requested radial order on
// every edge CGAL forces, and does not depend on the thread count.
TEST(DelaunayAutomatic, RunsThatErodeTooMuchAreInsertedByCavities) {
    using exidel::testing::Realistic;
    for (const std::size_t n : {std::size_t{3000}, std::size_t{120000}}) {
        const auto tracks = exidel::testing::realistic_points(Realistic::tracks, n, 11);
        const EdgeSets oracle = test::cgal_edge_sets(tracks);
        std::vector<std::uint32_t> first;
        for (const unsigned threads : {1u, 2u}) {
            const Result r = triangulate(tracks, AdaptiveKernel{}, Options{}.with_threads(threads));
            ASSERT_TRUE(r.ok()) << r.failure->message;
            EXPECT_EQ(r.strategy, n < automatic_strips_from ? Strategy::radial : Strategy::strips);
            EXPECT_GE(r.cavity_pieces, 1u) << n;
            EXPECT_LE(r.cavity_pieces, r.strips) << n;
            EXPECT_TRUE(certify(tracks, r.triangulation).ok()) << n;
            EXPECT_EQ(test::edge_sets(tracks, r.triangulation).forced, oracle.forced) << n;
            if (threads == 1) {
                first = r.triangulation.triangles;
            } else {
                EXPECT_EQ(r.triangulation.triangles, first) << n;
            }
        }
        const Strategy requested = n < automatic_strips_from ? Strategy::radial : Strategy::strips;
        const Result plain = triangulate<Instrumentation::counters>(
            tracks, AdaptiveKernel{}, Options{}.with_strategy(requested));
        ASSERT_TRUE(plain.ok()) << plain.failure->message;
        EXPECT_EQ(plain.cavity_pieces, 0u);
        EXPECT_EQ(plain.counters.location_steps, 0u);  // no cavity insertion ran
        EXPECT_GT(plain.counters.eroded_edges, automatic_erosion_limit * n / 2)
            << "the family no longer erodes enough to exercise the fallback";
        EXPECT_EQ(test::edge_sets(tracks, plain.triangulation).forced, oracle.forced) << n;
    }
    const auto poisson =
        exidel::testing::realistic_points(exidel::testing::Realistic::poisson_disc, 120000, 11);
    const Result r = triangulate(poisson, AdaptiveKernel{});
    ASSERT_TRUE(r.ok()) << r.failure->message;
    EXPECT_EQ(r.cavity_pieces, 0u);
}

// The fallback with an inexact kernel: a result or a typed failure, never a crash.
TEST(DelaunayAutomatic, CavityFallbackWithTheDoubleKernelFailsCleanly) {
    for (const auto& f : exidel::testing::realistic_families()) {
        const auto pts = exidel::testing::realistic_points(f.family, 3000, 5);
        const Result r = triangulate(pts, DoubleKernel{});
        if (!r.ok()) {
            EXPECT_FALSE(r.failure->message.empty()) << f.name;
            continue;
        }
        const Certificate c = certify(pts, r.triangulation);
        EXPECT_FALSE(c.has(FindingKind::bad_shape)) << f.name;
        EXPECT_FALSE(c.has(FindingKind::index_out_of_range)) << f.name;
    }
}

// ---- radial order ------------------------------------------------------------------------

// A sampled convex curve: the paper's order is quadratic on the branch it inserts towards
// the vertex; radial order from delaunator's centre walks the curve from one end.
TEST(DelaunayRadial, ParabolaTowardsItsVertexIsNotQuadratic) {
    for (const std::size_t n : {1000u, 4000u}) {
        std::vector<Point2> pts(n);
        for (std::size_t i = 0; i < n; ++i) {
            const double x = -static_cast<double>(n - i);
            pts[i] = {x, x * x};
        }
        Options o;
        o.strategy = Strategy::radial;
        const Result r = triangulate<Instrumentation::counters>(pts, AdaptiveKernel{}, o);
        ASSERT_TRUE(r.ok());
        EXPECT_TRUE(certify(pts, r.triangulation).ok());
        const double flips = static_cast<double>(r.counters.flips()) / static_cast<double>(n);
        std::printf("parabola n = %zu: radial %.2f flips per point\n", n, flips);
        EXPECT_LT(flips, 4.0);  // lexicographic: (n - 5) / 2
    }
}

// Many exact distance ties: an integer grid around its centre. The order must be exact
// for the walk to stay external; the certificate checks the whole run.
TEST(DelaunayRadial, GridWithManyEqualDistances) {
    std::vector<Point2> pts;
    for (int x = -15; x <= 15; ++x) {
        for (int y = -15; y <= 15; ++y) pts.push_back({double(x), double(y)});
    }
    for (const Strategy st : {Strategy::radial, Strategy::strips}) {
        Options o;
        o.strategy = st;
        o.strip_points = 40;
        const Result r = triangulate(pts, AdaptiveKernel{}, o);
        ASSERT_TRUE(r.ok()) << r.failure->message;
        EXPECT_TRUE(certify(pts, r.triangulation).ok());
    }
}

/// The adaptive kernel with its distance comparison reversed: the radial order then
/// inserts the farthest points first, and a later point lands inside the hull.
struct ReversedDistanceKernel : AdaptiveKernel {
    static constexpr bool is_exact = false;
    static std::string name() { return "reversed-distance"; }
    Sign compare_distance(Point2 c, Point2 p, Point2 q) const {
        return AdaptiveKernel::compare_distance(c, q, p);
    }
};
static_assert(PredicateKernel<ReversedDistanceKernel>);

TEST(DelaunayRadial, AWrongDistanceComparisonIsDetectedNotMishandled) {
    // Keys are exact (small integers), so every pair is decided by the key sort except
    // ties; make all distances tie (a circle of lattice points plus its centre) so the
    // lying predicate orders them all.
    std::vector<Point2> pts{{0, 0}};
    for (int x = -5; x <= 5; ++x) {
        for (int y = -5; y <= 5; ++y) {
            if (x * x + y * y == 25) pts.push_back({double(x), double(y)});
        }
    }
    pts.push_back({0.5, 0.25});  // a second inner point, so the ring is not all ties
    Options o;
    o.strategy = Strategy::radial;
    const ReversedDistanceKernel reversed;  // through DynamicKernel: the library's bodies
    const Result r = triangulate(pts, DynamicKernel(reversed), o);
    // Either the run stops with a typed failure, or what it returns is certified; it
    // never returns silent garbage.
    if (r.ok()) {
        EXPECT_TRUE(certify(pts, r.triangulation).ok());
    } else {
        EXPECT_FALSE(r.failure->message.empty());
        std::printf("reversed distance: %s\n", r.failure->message.c_str());
    }
}

// ---- tiles ------------------------------------------------------------------------------

bool lex_less(Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
bool yx_less(Point2 a, Point2 b) { return a.y < b.y || (a.y == b.y && a.x > b.x); }

/// tile_strip's promises, on the strip pts[a..] of sorted distinct points: the strip's
/// points and indices permuted, tiles of at least three points not all collinear, each in
/// lexicographic order, every point of a tile strictly below every point of the next, and
/// the merges' start points right.
void check_tiles(const std::vector<Point2>& all, std::uint32_t a, std::size_t tiles) {
    const std::span<const Point2> pts = std::span<const Point2>(all).subspan(a);
    const auto m = static_cast<std::uint32_t>(pts.size());
    std::vector<std::uint32_t> ids(m);
    std::iota(ids.begin(), ids.end(), 100u);
    std::vector<Point2> to_pts(m);
    std::vector<std::uint32_t> to_ids(m);
    delaunay::detail::TilingScratch scratch;
    const delaunay::detail::StripTiles t =
        delaunay::detail::tile_strip(AdaptiveKernel{}, pts, ids, tiles, std::span<Point2>(to_pts),
                                     std::span<std::uint32_t>(to_ids), scratch);
    RC_ASSERT(t.cuts.front() == 0u);
    RC_ASSERT(t.cuts.back() == m);
    RC_ASSERT(t.cuts.size() - 1 <= std::max<std::size_t>(tiles, 1));
    std::vector<bool> seen(m, false);
    for (std::uint32_t j = 0; j < m; ++j) {
        RC_ASSERT(to_ids[j] >= 100u);
        RC_ASSERT(to_ids[j] < 100u + m);
        RC_ASSERT(!seen[to_ids[j] - 100]);
        seen[to_ids[j] - 100] = true;
        RC_ASSERT(to_pts[j] == pts[to_ids[j] - 100]);
    }
    for (std::size_t k = 0; k + 1 < t.cuts.size(); ++k) {
        const std::uint32_t lo = t.cuts[k], hi = t.cuts[k + 1];
        RC_ASSERT(hi >= lo + 3);
        bool off_line = false;
        for (std::uint32_t j = lo + 2; j < hi; ++j) {
            off_line = off_line || AdaptiveKernel{}.orient2d(to_pts[lo], to_pts[lo + 1],
                                                             to_pts[j]) != Sign::zero;
        }
        RC_ASSERT(off_line);
        for (std::uint32_t j = lo + 1; j < hi; ++j) RC_ASSERT(lex_less(to_pts[j - 1], to_pts[j]));
        for (std::uint32_t j = lo; j < hi; ++j) {
            RC_ASSERT(!yx_less(to_pts[j], to_pts[t.low[k]]));
            RC_ASSERT(!yx_less(to_pts[t.high[k]], to_pts[j]));
            RC_ASSERT(!lex_less(to_pts[j], to_pts[t.first]));
            RC_ASSERT(!lex_less(to_pts[t.last], to_pts[j]));
            if (k + 1 < t.cuts.size() - 1) {
                for (std::uint32_t i = hi; i < t.cuts[k + 2]; ++i)
                    RC_ASSERT(to_pts[j].y < to_pts[i].y);
            }
        }
    }
}

RC_GTEST_PROP(DelaunayTiles, TileStripCutsSeparatedSortedNonCollinearTiles, ()) {
    const std::string family = *rc::gen::elementOf(test::point_set_family_names());
    RC_TAG(family);
    auto pts = *test::gen_family_points(family, *rc::gen::inRange<std::size_t>(3, 400));
    std::sort(pts.begin(), pts.end(), lex_less);
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    const auto a =
        *rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(pts.size() / 3 + 1));
    RC_PRE(pts.size() >= a + 3);
    bool off_line = false;
    for (std::size_t j = a + 2; j < pts.size(); ++j) {
        off_line = off_line || AdaptiveKernel{}.orient2d(pts[a], pts[a + 1], pts[j]) != Sign::zero;
    }
    RC_PRE(off_line);
    check_tiles(pts, a, *rc::gen::inRange<std::size_t>(1, 12));
}

// Rows of equal y (every tile boundary falls between rows, some tiles one row and
// collinear), a y range of a few subnormals (scale infinite: one tile), and coordinates
// near the largest double (y1 - y0 would overflow; halves do not).
TEST(DelaunayTiles, TileStripOnRowsTinyAndHugeRanges) {
    EXPECT_TRUE(rc::check("rows", [] {
        std::vector<Point2> rows;
        for (int y = 0; y < 9; ++y) {
            for (int x = 0; x < (y % 3 == 0 ? 30 : 2); ++x) rows.push_back({double(x), double(y)});
        }
        std::sort(rows.begin(), rows.end(), lex_less);
        check_tiles(rows, 0, *rc::gen::inRange<std::size_t>(1, 20));
    }));
    const double d = std::numeric_limits<double>::denorm_min();
    std::vector<Point2> tiny{{0, 0}, {0, 2 * d}, {1, d}, {2, 0}, {2, 2 * d}, {3, d}};
    std::vector<Point2> huge;
    const double big = std::numeric_limits<double>::max();
    for (int j = 0; j < 40; ++j) {
        huge.push_back({j * 1e300, (j % 2 ? big : -big) * (1 - j / 64.0)});
    }
    for (auto* v : {&tiny, &huge}) std::sort(v->begin(), v->end(), lex_less);
    for (std::size_t tiles : {1, 2, 5}) {
        EXPECT_TRUE(rc::check("tiny and huge", [&] {
            check_tiles(tiny, 0, tiles);
            check_tiles(huge, 0, tiles);
        }));
    }
    // The tiny range stays one tile; the huge one is cut.
    delaunay::detail::TilingScratch scratch;
    std::vector<Point2> to(huge.size());
    std::vector<std::uint32_t> ids(huge.size()), to_ids(huge.size());
    EXPECT_EQ(
        delaunay::detail::tile_strip(AdaptiveKernel{}, tiny, std::span(ids).first(6), 2,
                                     std::span(to).first(6), std::span(to_ids).first(6), scratch)
            .cuts.size(),
        2u);
    EXPECT_GT(delaunay::detail::tile_strip(AdaptiveKernel{}, huge, ids, 4, std::span<Point2>(to),
                                           std::span<std::uint32_t>(to_ids), scratch)
                  .cuts.size(),
              2u);
}

// The default keeps plain strips (and their arrays) below 2^22 points, then square tiles.
static_assert(tiles_from == std::size_t{1} << 22);
static_assert(default_strip_tiles(tiles_from - 1, 1 << 14) == 1);
static_assert(default_strip_tiles(tiles_from, 1 << 14) == 16);
static_assert(default_strip_tiles(10'000'000, 1 << 14) == 24);
static_assert(default_strip_tiles(100'000'000, 1 << 14) == 78);
static_assert(default_strip_tiles(delaunay::detail::max_points, 1) == 18708);

// Tiled triangulations of the same degenerate and extreme families, against CGAL.
RC_GTEST_PROP(DelaunayTiles, TiledStripsMatchCgal, ()) {
    const auto s = *test::gen_point_set(max_points);
    Options o;
    o.strategy = Strategy::strips;
    o.strip_points = *rc::gen::inRange<std::size_t>(1, 30);
    o.strip_tiles = *rc::gen::inRange<std::size_t>(2, 9);
    o.threads = *rc::gen::inRange(1u, 3u);
    RC_TAG(s.family);
    check_against_cgal(s.points, AdaptiveKernel{}, o, test::cgal_edge_sets(s.points));
}

// ---- inexact kernels --------------------------------------------------------------------

// The double kernel under every strategy: wrong answers are allowed, crashes, hangs and
// arrays pointing outside themselves are not. Outcomes printed, not asserted.
TEST(DelaunayStrategiesInexact, DoubleKernelNeverCrashesUnderAnyStrategy) {
    std::map<std::string, std::map<std::string, std::size_t>> outcomes;  // strategy -> outcome
    const bool passed = rc::check("double kernel, every strategy", [&] {
        const auto s = *test::gen_point_set(200);
        const Options o = *gen_options();
        const Result r = triangulate(s.points, DoubleKernel{}, o);
        auto& counts = outcomes[std::string(to_string(o.strategy))];
        if (!r.ok()) {
            RC_ASSERT(r.failure->kind != FailureKind::non_finite_input);
            RC_ASSERT(!r.failure->message.empty());
            ++counts[std::string(to_string(r.failure->kind))];
            return;
        }
        const Certificate c = certify(s.points, r.triangulation);
        RC_ASSERT(!c.has(FindingKind::bad_shape));
        RC_ASSERT(!c.has(FindingKind::index_out_of_range));
        ++counts[c.ok() ? "certified" : "wrong"];
    });
    for (const auto& [strategy, counts] : outcomes) {
        std::printf("double kernel, %s:", strategy.c_str());
        for (const auto& [what, k] : counts) std::printf(" %s %zu", what.c_str(), k);
        std::printf("\n");
    }
    EXPECT_TRUE(passed);
}

}  // namespace
