// exidel (private): the adaptive kernel with its two hottest filters inline, for the
// library's own compilation of triangulate<..., AdaptiveKernel> (instantiate.cpp).
//
// Same answers as AdaptiveKernel, call for call: orient2d and incircle first run the
// kernel's own stage-A filters (exidel/predicates/internal/adaptive_filter.hpp, the very
// functions adaptive.cpp runs), and whatever a filter leaves undecided goes to the later
// stages (adaptive_unchecked.hpp), which decide it exactly. Two things change, both
// measured (docs/measurements.md, "The adaptive kernel inside the triangulation"): the filter's
// instructions are in the triangulation's loop rather than behind a call, and the floating-point
// environment is checked once per run instead of once per call (reading MXCSR was half of every
// in-circle test's time).
//
// Precondition: the run is in the standard floating-point environment (round to nearest,
// no flush-to-zero or denormals-are-zero). detail::triangulate_adaptive
// (instantiate.cpp) establishes it for the whole run; the threads a run starts inherit it
// (POSIX: a new thread starts with the floating-point environment of the thread that
// created it, and parallel_for starts its threads inside the run).
//
// This header is compiled in the library with its floating-point flags only; a user's
// code never sees it.
#pragma once

#include <string>

#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/internal/adaptive_filter.hpp"
#include "exidel/predicates/internal/adaptive_unchecked.hpp"

namespace exidel::delaunay::detail {

/// Derives from AdaptiveKernel: a predicate it does not declare (a new one of the list,
/// the predicates of space) is the adaptive kernel's own, with its environment check.
struct InlineAdaptiveKernel : AdaptiveKernel {
    [[gnu::always_inline]] static Sign orient2d(Point2 a, Point2 b, Point2 c) {
        Sign s;
        double detsum;
        if (exidel::detail::orient2d_filter(a, b, c, s, detsum)) [[likely]]
            return s;
        return exidel::detail::orient2d_unchecked(a, b, c);
    }
    [[gnu::always_inline]] static Sign incircle(Point2 a, Point2 b, Point2 c, Point2 d) {
        Sign s;
        exidel::detail::IncircleDifferences v;
        if (exidel::detail::incircle_filter(a, b, c, d, v, s)) [[likely]]
            return s;
        return exidel::detail::incircle_unchecked(a, b, c, d);
    }
    static Sign incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) {
        return exidel::detail::incircle_cosine_unchecked(a, b, c, d);
    }
    static Sign compare_distance(Point2 c, Point2 p, Point2 q) {
        return exidel::detail::compare_distance_unchecked(c, p, q);
    }
};

static_assert(PredicateKernel<InlineAdaptiveKernel>);

}  // namespace exidel::delaunay::detail
