// A predicate kernel that lies, for the tests that every algorithm stops with a typed
// failure or returns arrays of the right shape whatever its kernel answers.
#pragma once

#include <string>

#include "exidel/delaunay/detail/brio.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::test {

/// A kernel whose every answer is chosen by `mode`: constant signs, or random ones (a
/// splitmix64 stream, so that the same answer never comes twice in a row by design).
struct LyingKernel {
    enum Mode { positive, negative, zero, random, random_orient, always_flip };
    Mode mode = positive;
    mutable delaunay::detail::SplitMix64 rng{1};
    static constexpr bool is_exact = false;

    Sign coin() const {
        switch (rng.next() % 3) {
            case 0: return Sign::negative;
            case 1: return Sign::zero;
            default: return Sign::positive;
        }
    }
    Sign constant() const {
        return mode == negative ? Sign::negative : mode == zero ? Sign::zero : Sign::positive;
    }
    Sign orient2d(Point2 a, Point2 b, Point2 c) const {
        if (mode == always_flip) return AdaptiveKernel{}.orient2d(a, b, c);
        return mode == random || mode == random_orient ? coin() : constant();
    }
    Sign incircle(Point2 a, Point2 b, Point2 c, Point2 d) const {
        if (mode == always_flip) return Sign::positive;
        if (mode == random_orient) return AdaptiveKernel{}.incircle(a, b, c, d);
        return mode == random ? coin() : constant();
    }
    Sign incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) const {
        return incircle(a, b, c, d);
    }
    Sign compare_distance(Point2, Point2, Point2) const {
        return mode == random ? coin() : constant();
    }
    std::string name() const { return "lying"; }
};
static_assert(PredicateKernel<LyingKernel>);

}  // namespace exidel::test
