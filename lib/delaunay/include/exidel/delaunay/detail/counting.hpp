// exidel: the counters an algorithm keeps (Counters, result.hpp); with
// Instrumentation::off every increment compiles away.
#pragma once

#include <cstdint>

#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay::detail {

/// The paper's Theorem 1 at one in-circle test of the erosion: the new point p and the
/// opposite vertex c lie strictly on opposite sides of border edge ab (c on the left).
/// Decided exactly (adaptive kernel) whatever kernel runs the algorithm; compiled in the
/// library (src/instrumentation.cpp) so that no algorithm header depends on a kernel.
bool theorem1_holds(Point2 a, Point2 b, Point2 c, Point2 p);

/// Base of every builder and merge: count(&Counters::field) is free when uninstrumented,
/// check_theorem1 unless Instrumentation::theorem1. The library compiles the algorithms
/// for `off` and `counters` only; `theorem1` is for tests, which instantiate it.
template <Instrumentation I>
struct Counting {
    Counters counters_{};
    void count(std::uint64_t Counters::*field) {
        if constexpr (I != Instrumentation::off) ++(counters_.*field);
    }
    void check_theorem1([[maybe_unused]] Point2 a, [[maybe_unused]] Point2 b,
                        [[maybe_unused]] Point2 c, [[maybe_unused]] Point2 p) {
        if constexpr (I == Instrumentation::theorem1) {
            ++counters_.theorem1_checks;
            if (!theorem1_holds(a, b, c, p)) ++counters_.theorem1_violations;
        }
    }

    /// The in-circle question as every algorithm asks it, counted and checked: is p
    /// strictly inside the circle of the counter-clockwise triangle abc, p being across
    /// edge a -> b from c? Decided by the policy P: the determinant, or the paper's
    /// cosine test with its roles B = a, C = b (the edge), D = c, A = p.
    template <InCirclePolicy P, class K>
    bool in_circle_by_policy(const K& k, Point2 a, Point2 b, Point2 c, Point2 p) {
        count(&Counters::incircle_tests);
        check_theorem1(a, b, c, p);
        if constexpr (P == InCirclePolicy::determinant) {
            return k.incircle(a, b, c, p) == Sign::positive;
        } else {
            return k.incircle_cosine(a, b, c, p) == Sign::positive;
        }
    }
};

}  // namespace exidel::delaunay::detail
