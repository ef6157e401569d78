// Every algorithm of the registry (exidel/delaunay/algorithms.hpp), one test body each:
// the template a new algorithm inherits by its one line in that list. With an exact
// kernel its result is certified and has CGAL's forced edges (and CGAL's triangles when
// no four points are cocircular); with the double kernel it may be wrong but returns a
// result or a typed failure. The names round-trip, and an unknown one is an error.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "delaunay_support.hpp"
#include "lying_kernel.hpp"
#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"

// Test names and failure messages show an algorithm by its name.
namespace exidel::delaunay {
void PrintTo(const AlgorithmInfo& a, std::ostream* os) { *os << a.name; }
}  // namespace exidel::delaunay

namespace {

using namespace exidel;
using namespace exidel::delaunay;
using exidel::test::EdgeSets;

/// Options for `algorithm`, its order (if it takes one) and knobs drawn at random.
rc::Gen<Options> gen_options(const AlgorithmInfo& algorithm) {
    return rc::gen::exec([algorithm] {
        Options o;
        o.algorithm = algorithm.id;
        if (algorithm.takes_order) {
            o.strategy = *rc::gen::element(Strategy::automatic, Strategy::lexicographic,
                                           Strategy::radial, Strategy::strips);
        }
        o.incircle = *rc::gen::element(InCirclePolicy::determinant, InCirclePolicy::cosine);
        o.strip_points = *rc::gen::inRange<std::size_t>(1, 40);
        o.threads = *rc::gen::inRange(1u, 3u);
        return o;
    });
}

std::string describe(const Options& o) {
    return std::string(to_string(o.algorithm)) + " " + std::string(to_string(o.strategy)) +
           (o.incircle == InCirclePolicy::cosine ? " cosine" : " determinant");
}

template <class K>
void check_exact(const AlgorithmInfo& algorithm, std::size_t max_points) {
    const auto s = *test::gen_point_set(max_points);
    const Options o = *gen_options(algorithm);
    RC_TAG(s.family);
    const Result r = triangulate<Instrumentation::counters>(s.points, K{}, o);
    if (!r.ok()) RC_FAIL(describe(o) + ": " + r.failure->message);
    RC_ASSERT(r.algorithm == algorithm.id);
    const Certificate c = certify(s.points, r.triangulation);
    if (!c.ok()) RC_FAIL(describe(o) + ": certify: " + c.summary());
    RC_ASSERT(r.counters.triangles_created - r.counters.triangles_destroyed ==
              r.triangulation.triangle_count());
    const EdgeSets oracle = test::cgal_edge_sets(s.points);
    const EdgeSets ours = test::edge_sets(s.points, r.triangulation);
    RC_ASSERT(ours.collinear == oracle.collinear);
    RC_ASSERT(ours.forced == oracle.forced);
    if (ours.free_edges == 0) RC_ASSERT(ours.triangles == oracle.triangles);
}

class EveryAlgorithm : public ::testing::TestWithParam<AlgorithmInfo> {};

TEST_P(EveryAlgorithm, AdaptiveMatchesCgal) {
    EXPECT_TRUE(rc::check(std::string(GetParam().name) + ", adaptive",
                          [&] { check_exact<AdaptiveKernel>(GetParam(), 160); }));
}

TEST_P(EveryAlgorithm, ExactKernelsMatchCgal) {
    EXPECT_TRUE(rc::check(std::string(GetParam().name) + ", exact",
                          [&] { check_exact<GmpExactKernel>(GetParam(), 40); }));
    EXPECT_TRUE(rc::check(std::string(GetParam().name) + ", exact-cpp",
                          [&] { check_exact<CppIntExactKernel>(GetParam(), 40); }));
}

// The realistic families (exidel/testing/point_sets.hpp) at sizes the property tests do
// not reach: 3000 points for every algorithm (every order of one that takes one), and for
// one that takes an order 40000 points too, where `automatic` runs strips (on two threads
// as well: the arrays must not depend on the thread count). Both policies, certified, and
// CGAL's forced edges.
TEST_P(EveryAlgorithm, RealisticFamiliesAtScaleMatchCgal) {
    const AlgorithmInfo& algorithm = GetParam();
    for (const exidel::testing::RealisticInfo& f : exidel::testing::realistic_families()) {
        for (const std::size_t n : {std::size_t{3000}, std::size_t{40000}}) {
            if (n > 3000 && !algorithm.takes_order) continue;
            const auto points = exidel::testing::realistic_points(f.family, n, 7 + n);
            const EdgeSets oracle = test::cgal_edge_sets(points);
            std::vector<Options> runs;
            for (const InCirclePolicy policy :
                 {InCirclePolicy::determinant, InCirclePolicy::cosine}) {
                if (!algorithm.takes_order) {
                    runs.push_back({.incircle = policy, .algorithm = algorithm.id});
                    continue;
                }
                for (const Strategy order : {Strategy::automatic, Strategy::radial,
                                             Strategy::strips, Strategy::lexicographic}) {
                    if (n > 3000 && order != Strategy::automatic) continue;
                    for (const unsigned threads : {1u, 2u})
                        runs.push_back({.incircle = policy,
                                        .strategy = order,
                                        .threads = threads,
                                        .algorithm = algorithm.id});
                }
            }
            std::vector<std::uint32_t> first_triangles;
            for (const Options& o : runs) {
                const std::string what = std::string(f.name) + " n=" + std::to_string(n) + " " +
                                         describe(o) + " t" + std::to_string(o.threads);
                const Result r = triangulate(points, AdaptiveKernel{}, o);
                ASSERT_TRUE(r.ok()) << what << ": " << r.failure->message;
                const Certificate c = certify(points, r.triangulation);
                ASSERT_TRUE(c.ok()) << what << ": " << c.summary();
                const EdgeSets ours = test::edge_sets(points, r.triangulation);
                EXPECT_EQ(ours.collinear, oracle.collinear) << what;
                EXPECT_EQ(ours.forced, oracle.forced) << what;
                if (o.strategy == Strategy::automatic &&
                    o.incircle == InCirclePolicy::determinant) {
                    if (o.threads == 1)
                        first_triangles = r.triangulation.triangles;
                    else
                        EXPECT_EQ(r.triangulation.triangles, first_triangles) << what;
                }
            }
        }
    }
}

// An inexact kernel may give a wrong triangulation, never a crash, a hang or an
// untyped result: either ok() with arrays of the right shape, or a failure with a
// message.
TEST_P(EveryAlgorithm, DoubleKernelReturnsAResultOrATypedFailure) {
    EXPECT_TRUE(rc::check(std::string(GetParam().name) + ", double", [&] {
        const auto s = *test::gen_point_set(160);
        const Options o = *gen_options(GetParam());
        const Result r = triangulate(s.points, DoubleKernel{}, o);
        RC_TAG(r.ok() ? std::string("ok") : std::string(to_string(r.failure->kind)));
        if (r.ok()) {
            RC_ASSERT(r.triangulation.triangles.size() == r.triangulation.halfedges.size());
            RC_ASSERT(r.triangulation.vertex_of_input.size() == s.points.size());
        } else {
            RC_ASSERT(!r.failure->message.empty());
        }
    }));
}

// Whatever a kernel answers, even at random: ok() with arrays of the right shape, or a
// failure of a kind that blames the kernel, with a message.
TEST_P(EveryAlgorithm, LyingKernelGivesAResultOrATypedFailure) {
    using exidel::test::LyingKernel;
    EXPECT_TRUE(rc::check(std::string(GetParam().name) + ", lying", [&] {
        const auto s = *test::gen_point_set(120);
        LyingKernel k;
        k.mode = *rc::gen::element(LyingKernel::positive, LyingKernel::negative, LyingKernel::zero,
                                   LyingKernel::random, LyingKernel::random,
                                   LyingKernel::random_orient, LyingKernel::always_flip);
        k.rng.state = *rc::gen::arbitrary<std::uint64_t>();
        const Options o = *gen_options(GetParam());
        const Result r = triangulate<Instrumentation::counters>(s.points, k, o);
        RC_TAG(r.ok() ? std::string("ok") : std::string(to_string(r.failure->kind)));
        if (r.ok()) {
            const Triangulation& t = r.triangulation;
            RC_ASSERT(t.triangles.size() == t.halfedges.size());
            RC_ASSERT(t.triangles.size() % 3 == 0);
            RC_ASSERT(t.vertex_of_input.size() == s.points.size());
            for (const std::uint32_t v : t.triangles) RC_ASSERT(v < s.points.size());
            for (const std::int32_t h : t.halfedges) {
                RC_ASSERT(h < static_cast<std::int32_t>(t.halfedges.size()));
            }
        } else {
            RC_ASSERT(!r.failure->message.empty());
            RC_ASSERT(r.failure->kind != FailureKind::non_finite_input);
            RC_ASSERT(r.failure->kind != FailureKind::unknown_algorithm);
            RC_ASSERT(r.failure->kind != FailureKind::too_many_points);
        }
    }));
}

// GoogleTest names allow letters, digits and '_' only: "bowyer-watson" is bowyer_watson.
std::string name_of(const ::testing::TestParamInfo<AlgorithmInfo>& info) {
    std::string name(info.param.name);
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryAlgorithm,
                         ::testing::ValuesIn(algorithms().begin(), algorithms().end()), name_of);

TEST(AlgorithmRegistry, NamesRoundTripAndAreListed) {
    ASSERT_FALSE(algorithms().empty());
    std::set<std::string> names;
    for (const AlgorithmInfo& a : algorithms()) {
        EXPECT_EQ(to_string(a.id), a.name);
        EXPECT_EQ(algorithm_from_name(a.name), a.id);
        EXPECT_FALSE(a.summary.empty()) << a.name;
        EXPECT_NE(algorithm_spellings().find(a.name), std::string::npos) << a.name;
        EXPECT_NE(algorithm_help().find(a.summary), std::string::npos) << a.name;
        EXPECT_TRUE(names.insert(std::string(a.name)).second) << "repeated name " << a.name;
    }
    EXPECT_EQ(algorithm_from_name("no-such-algorithm"), std::nullopt);
    EXPECT_EQ(algorithm_from_name(""), std::nullopt);
    EXPECT_EQ(Options{}.algorithm, Algorithm::external);  // the paper's algorithm by default
}

// A value outside the enumeration (a cast from a stale integer) is reported, not run.
TEST(AlgorithmRegistry, AnAlgorithmOutsideTheListIsATypedFailure) {
    Options o;
    o.algorithm = static_cast<Algorithm>(200);
    const std::vector<Point2> pts{{0, 0}, {1, 0}, {0, 1}};
    const Result r = triangulate(pts, AdaptiveKernel{}, o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.failure->kind, FailureKind::unknown_algorithm);
}

}  // namespace
