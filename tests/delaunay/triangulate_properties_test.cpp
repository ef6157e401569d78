// Properties of exidel::delaunay::triangulate against CGAL's Delaunay_triangulation_2
// with exact predicates, on every point family (delaunay_support.hpp).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>

#include "delaunay_support.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;
using exidel::test::EdgeSets;

// Size limits keep the default run (2000 cases per property) to about a minute; the
// GMP kernel is ~100x slower than the adaptive one and gets smaller sets.
constexpr std::size_t max_points = 120;
constexpr std::size_t max_points_gmp = 40;

template <class K>
void check_against_cgal(const test::PointSet& s, const K& kernel, InCirclePolicy policy,
                        const EdgeSets& oracle) {
    const Result r = triangulate<Instrumentation::theorem1>(s.points, kernel, Options{policy});
    RC_ASSERT(r.ok());
    const Certificate c = certify(s.points, r.triangulation);
    if (!c.ok()) RC_FAIL(K::name() + ": certify: " + c.summary());
    RC_ASSERT(r.counters.theorem1_violations == 0u);
    RC_ASSERT(r.counters.theorem1_checks == r.counters.incircle_tests);
    const EdgeSets ours = test::edge_sets(s.points, r.triangulation);
    RC_ASSERT(ours.collinear == oracle.collinear);
    RC_ASSERT(ours.forced == oracle.forced);
    if (ours.free_edges == 0) RC_ASSERT(ours.triangles == oracle.triangles);
    // Counters are consistent with each other: each eroded edge destroyed one triangle,
    // and the final count is what was created minus what was destroyed.
    RC_ASSERT(r.counters.eroded_edges == r.counters.triangles_destroyed);
    RC_ASSERT(r.counters.triangles_created - r.counters.triangles_destroyed ==
              r.triangulation.triangle_count());
}

RC_GTEST_PROP(DelaunayProperties, AdaptiveMatchesCgalUnderBothPolicies, ()) {
    const auto s = *test::gen_point_set(max_points);
    RC_TAG(s.family);
    const EdgeSets oracle = test::cgal_edge_sets(s.points);
    check_against_cgal(s, AdaptiveKernel{}, InCirclePolicy::determinant, oracle);
    check_against_cgal(s, AdaptiveKernel{}, InCirclePolicy::cosine, oracle);
}

RC_GTEST_PROP(DelaunayProperties, GmpExactMatchesCgalUnderBothPolicies, ()) {
    const auto s = *test::gen_point_set(max_points_gmp);
    RC_TAG(s.family);
    const EdgeSets oracle = test::cgal_edge_sets(s.points);
    check_against_cgal(s, GmpExactKernel{}, InCirclePolicy::determinant, oracle);
    check_against_cgal(s, GmpExactKernel{}, InCirclePolicy::cosine, oracle);
}

// With exact predicates the algorithm's every decision is determined by the input, and
// the two policies decide every in-circle question the same way (Theorem 1 holds): the
// arrays themselves are equal, not only the triangulations. Same for the two kernels.
RC_GTEST_PROP(DelaunayProperties, PoliciesAndExactKernelsGiveIdenticalArrays, ()) {
    const auto s = *test::gen_point_set(max_points_gmp);
    RC_TAG(s.family);
    const Result det = triangulate(s.points, AdaptiveKernel{});
    const Result cos = triangulate(s.points, AdaptiveKernel{}, Options{InCirclePolicy::cosine});
    const Result gmp = triangulate(s.points, GmpExactKernel{}, Options{InCirclePolicy::cosine});
    RC_ASSERT(det.ok() && cos.ok() && gmp.ok());
    for (const Result* other : {&cos, &gmp}) {
        RC_ASSERT(det.triangulation.triangles == other->triangulation.triangles);
        RC_ASSERT(det.triangulation.halfedges == other->triangulation.halfedges);
        RC_ASSERT(det.triangulation.hull == other->triangulation.hull);
        RC_ASSERT(det.triangulation.collinear == other->triangulation.collinear);
    }
}

// Exact a + b, or nothing: Knuth's TwoSum error term is zero exactly when the sum is exact.
bool exact_sum(double a, double b, double& s) {
    s = a + b;
    const double bb = s - a;
    const double err = (a - (s - bb)) + (b - bb);
    return err == 0 && std::isfinite(s);
}

bool exact_scale(double a, int k, double& s) {
    s = std::ldexp(a, k);
    return std::isfinite(s) && std::ldexp(s, -k) == a;
}

// The forced edges, renamed by input index through `to_original`.
std::set<test::Edge> forced_edges(const std::vector<Point2>& pts,
                                  const std::vector<std::uint32_t>& to_original,
                                  const Options& options) {
    const Result r = triangulate(pts, AdaptiveKernel{}, options);
    RC_ASSERT(r.ok());
    const Certificate c = certify(pts, r.triangulation);
    if (!c.ok()) RC_FAIL("certify: " + c.summary());
    // Renaming can pick another member of a group of duplicates: map to the smallest
    // original index with the same coordinates.
    std::set<test::Edge> out;
    for (const test::Edge& e : test::edge_sets(pts, r.triangulation).forced) {
        out.insert(test::make_edge(to_original[e.first], to_original[e.second]));
    }
    return out;
}

// Every algorithm of the registry (the external one in its default order): the forced
// edges do not depend on how the points are numbered, mirrored, swapped, or exactly scaled
// and translated.
void check_metamorphic(const AlgorithmInfo& algorithm) {
    const auto s = *test::gen_point_set(max_points);
    RC_TAG(s.family);
    Options options;
    options.algorithm = algorithm.id;
    const auto forced_edges = [&](const std::vector<Point2>& pts,
                                  const std::vector<std::uint32_t>& to_original) {
        return ::forced_edges(pts, to_original, options);
    };
    const std::size_t n = s.points.size();
    const auto first = test::first_occurrence(s.points);
    std::vector<std::uint32_t> identity(n);
    std::iota(identity.begin(), identity.end(), 0u);
    const auto base = forced_edges(s.points, identity);
    // Renamings below go through `first` so that duplicates collapse the same way.
    const auto canon = [&](std::vector<std::uint32_t> to_original) {
        for (auto& v : to_original) v = first[v];
        return to_original;
    };

    // Permutation.
    const auto perm = *rc::gen::map(rc::gen::arbitrary<std::uint32_t>(), [n](std::uint32_t seed) {
        std::vector<std::uint32_t> p(n);
        std::iota(p.begin(), p.end(), 0u);
        std::shuffle(p.begin(), p.end(), std::mt19937(seed));
        return p;
    });
    std::vector<Point2> permuted(n);
    for (std::size_t i = 0; i < n; ++i) permuted[i] = s.points[perm[i]];
    RC_ASSERT(forced_edges(permuted, canon(perm)) == base);

    const auto same_names = canon(identity);
    const auto transformed = [&](auto f) {
        std::vector<Point2> out(n);
        for (std::size_t i = 0; i < n; ++i) {
            if (!f(s.points[i], out[i])) return std::optional<std::vector<Point2>>{};
        }
        return std::optional<std::vector<Point2>>{out};
    };
    // Mirror x, swap the axes: always exact.
    RC_ASSERT(forced_edges(*transformed([](Point2 p, Point2& q) {
                  q = {-p.x, p.y};
                  return true;
              }),
                           same_names) == base);
    RC_ASSERT(forced_edges(*transformed([](Point2 p, Point2& q) {
                  q = {p.y, p.x};
                  return true;
              }),
                           same_names) == base);
    // Scale by 2^k and translate: only when every coordinate stays exact.
    const int k = *rc::gen::inRange(-80, 81);
    if (auto scaled = transformed([k](Point2 p, Point2& q) {
            return exact_scale(p.x, k, q.x) && exact_scale(p.y, k, q.y);
        })) {
        RC_TAG("scaled exactly");
        RC_ASSERT(forced_edges(*scaled, same_names) == base);
    }
    const double tx =
        std::ldexp(static_cast<double>(*rc::gen::inRange(-1000, 1001)), *rc::gen::inRange(-30, 31));
    const double ty =
        std::ldexp(static_cast<double>(*rc::gen::inRange(-1000, 1001)), *rc::gen::inRange(-30, 31));
    if (auto moved = transformed([tx, ty](Point2 p, Point2& q) {
            return exact_sum(p.x, tx, q.x) && exact_sum(p.y, ty, q.y);
        })) {
        RC_TAG("translated exactly");
        RC_ASSERT(forced_edges(*moved, same_names) == base);
    }
}

class MetamorphicEveryAlgorithm : public ::testing::TestWithParam<AlgorithmInfo> {};

TEST_P(MetamorphicEveryAlgorithm, TransformsKeepForcedEdges) {
    EXPECT_TRUE(rc::check(std::string(GetParam().name), [&] { check_metamorphic(GetParam()); }));
}

INSTANTIATE_TEST_SUITE_P(Registry, MetamorphicEveryAlgorithm,
                         ::testing::ValuesIn(algorithms().begin(), algorithms().end()),
                         [](const ::testing::TestParamInfo<AlgorithmInfo>& info) {
                             std::string name(info.param.name);
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// The plain double kernel may be wrong, but must never crash, hang or produce arrays
// that point outside themselves. Its outcomes per family are counted and printed, not
// asserted (they are the research result, not a requirement).
template <class K>
void survey_inexact_kernel(const char* kernel_name) {
    struct Outcome {
        std::size_t certified = 0, not_delaunay = 0, invalid = 0, failure = 0;
    };
    std::printf("%s kernel outcomes (certified / not Delaunay / invalid / failure reported):\n",
                kernel_name);
    bool all_passed = true;
    std::map<FailureKind, std::size_t> failures;  // over all families
    for (const std::string& family : test::point_set_family_names()) {
        Outcome o;
        const bool passed = rc::check(family + " with the " + kernel_name + " kernel", [&] {
            const std::size_t n = *rc::gen::inRange<std::size_t>(0, 200);
            const auto pts = *test::gen_family_points(family, n);
            const Result r = triangulate<Instrumentation::counters>(pts, K{});
            if (!r.ok()) {
                RC_ASSERT(r.failure->kind != FailureKind::non_finite_input);
                RC_ASSERT(!r.failure->message.empty());
                // Merges and the final structure belong to no single insertion.
                RC_ASSERT(r.failure->insertion < pts.size() ||
                          r.failure->kind == FailureKind::merge_inconsistent ||
                          r.failure->kind == FailureKind::result_inconsistent);
                ++o.failure;
                ++failures[r.failure->kind];
                return;
            }
            const Certificate c = certify(pts, r.triangulation);
            RC_ASSERT(!c.has(FindingKind::bad_shape));
            RC_ASSERT(!c.has(FindingKind::index_out_of_range));
            const bool only_delaunay =
                std::all_of(c.findings.begin(), c.findings.end(),
                            [](const Finding& f) { return f.kind == FindingKind::not_delaunay; });
            if (c.ok()) {
                ++o.certified;
            } else if (only_delaunay && c.total_findings == c.findings.size()) {
                ++o.not_delaunay;
            } else {
                ++o.invalid;
            }
        });
        all_passed = all_passed && passed;
        std::printf("  %-22s %6zu %6zu %6zu %6zu\n", family.c_str(), o.certified, o.not_delaunay,
                    o.invalid, o.failure);
    }
    std::printf("  failures reported by kind:");
    for (const auto& [kind, count] : failures) {
        std::printf(" %s %zu", std::string(to_string(kind)).c_str(), count);
    }
    std::printf("\n");
    EXPECT_TRUE(all_passed);
}

TEST(DelaunayInexactKernels, DoubleKernelNeverCrashesOnAnyFamily) {
    survey_inexact_kernel<DoubleKernel>("double");
}

TEST(DelaunayInexactKernels, LongDoubleKernelNeverCrashesOnAnyFamily) {
    survey_inexact_kernel<LongDoubleKernel>("long double");
}

}  // namespace
