// The README's example of a user's own property test, compiled and run here so that the
// README stays true. A user's geometry code (here: a point-in-triangle test built on the
// adaptive kernel) is checked against the exact certifier on near-degenerate input that
// shrinks toward the exactly degenerate configuration.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <exidel/predicates/adaptive.hpp>
#include <exidel/predicates/exact.hpp>
#include <exidel/testing/all.hpp>

namespace {

using exidel::Point2;
using exidel::Sign;
namespace xt = exidel::testing;

// README example begins
// The code under test: is p inside or on the boundary of triangle abc?
bool in_closed_triangle(Point2 a, Point2 b, Point2 c, Point2 p) {
    using K = exidel::AdaptiveKernel;
    const Sign s = K::orient2d(a, b, c);
    return K::orient2d(a, b, p) != -s && K::orient2d(b, c, p) != -s && K::orient2d(c, a, p) != -s;
}

RC_GTEST_PROP(MyGeometry, PointOnAnEdgeIsInside, ()) {
    // Three points within a few ulps of one line, and a fourth from the same family.
    const auto [a, b, c, p] = *xt::gen_query4(xt::Family::near_rounded_line);
    using Exact = exidel::GmpExactKernel;  // the certifier
    const Sign s = Exact::orient2d(a, b, c);
    const bool expected = Exact::orient2d(a, b, p) != -s && Exact::orient2d(b, c, p) != -s &&
                          Exact::orient2d(c, a, p) != -s;
    RC_ASSERT(in_closed_triangle(a, b, c, p) == expected);
}
// README example ends

}  // namespace
