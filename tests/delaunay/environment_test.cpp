// The library's triangulation with the adaptive kernel checks the floating-point
// environment once per run, not once per predicate (lib/delaunay/src/inline_adaptive.hpp):
// a caller's directed rounding or flush-to-zero / denormals-are-zero is replaced by the
// standard environment for the whole run, the strips' worker threads included, and
// restored afterwards. Here every environment the hygiene tests try
// (tests/hygiene/fp_environment.hpp) must give the arrays of the default environment, on
// inputs where it matters: a grid of subnormal points (denormals-are-zero would read every
// coordinate as zero) and a near-cocircular set decided by the later stages (directed
// rounding would move the filter's value past its bound).
#include <gtest/gtest.h>

#include <cfenv>
#include <string>
#include <vector>

#include "../hygiene/fp_environment.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;
using namespace exidel::hygiene;

/// A 70 x 70 integer grid times 2^-1070: every coordinate subnormal (or zero), every
/// difference exact, cocircular quadruples everywhere.
std::vector<Point2> subnormal_grid() {
    std::vector<Point2> p;
    for (int i = 0; i < 70 * 70; ++i) {
        p.push_back({(i * 37 % 70) * 0x1p-1070, (i / 70) * 0x1p-1070});
    }
    return p;
}

/// Points of the unit circle, rational up to rounding (so nearly cocircular), with the
/// centre's neighbourhood filled by a small grid: in-circle tests whose values are far
/// below the filter's bound.
std::vector<Point2> near_cocircular() {
    std::vector<Point2> p;
    for (int i = -2000; i < 2000; ++i) {
        const double t = i / 1000.0, d = 1 + t * t;
        p.push_back({(1 - t * t) / d, 2 * t / d});
    }
    for (int i = 0; i < 400; ++i) p.push_back({(i % 20) / 40.0 - 0.25, (i / 20) / 40.0 - 0.25});
    return p;
}

Result run(const std::vector<Point2>& points, unsigned threads) {
    Options options;
    options.threads = threads;
    options.strategy = Strategy::strips;
    options.strip_points = 500;  // several strips, so the merges and worker threads run
    return triangulate(std::span<const Point2>(points), AdaptiveKernel{}, options);
}

void expect_same_in_every_environment(const std::vector<Point2>& points) {
    const Result reference = in_default_environment([&] { return run(points, 1); });
    ASSERT_TRUE(reference.ok()) << reference.failure->message;
    ASSERT_FALSE(reference.triangulation.collinear);
    ASSERT_TRUE(certify(points, reference.triangulation).ok());
    for (const Environment& env : environments) {
        for (unsigned threads : {1u, 2u}) {
            SCOPED_TRACE(std::string(env.name) + ", threads " + std::to_string(threads));
            set_controls(env.rounding, env.ftz_daz);
            const FpControls before = current_controls();
            const Result got = run(points, threads);
            const FpControls after = current_controls();
            set_controls(FE_TONEAREST, 0);
            EXPECT_TRUE(before == after) << "the caller's environment was not restored";
            ASSERT_TRUE(got.ok()) << got.failure->message;
            EXPECT_EQ(got.triangulation.triangles, reference.triangulation.triangles);
            EXPECT_EQ(got.triangulation.halfedges, reference.triangulation.halfedges);
            EXPECT_EQ(got.triangulation.hull, reference.triangulation.hull);
            EXPECT_EQ(got.triangulation.vertex_of_input, reference.triangulation.vertex_of_input);
        }
    }
}

TEST(AdaptiveTriangulationEnvironment, SubnormalGridIsTheSameInEveryEnvironment) {
    expect_same_in_every_environment(subnormal_grid());
}

TEST(AdaptiveTriangulationEnvironment, NearCocircularSetIsTheSameInEveryEnvironment) {
    expect_same_in_every_environment(near_cocircular());
}

}  // namespace
