// A predicate kernel that lies, for the tests that every algorithm stops with a typed
// failure or returns arrays of the right shape whatever its kernel answers.
#pragma once

#include <string>

#include "exidel/delaunay/detail/brio.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/wrapper.hpp"

namespace exidel::test {

/// A kernel whose every answer is chosen by `mode`: constant signs, or random ones (a
/// splitmix64 stream, so that the same answer never comes twice in a row by design).
struct LyingKernel : KernelWrapper<LyingKernel> {
    enum Mode { positive, negative, zero, random, random_orient, always_flip };
    Mode mode = positive;
    mutable delaunay::detail::SplitMix64 rng{1};
    static constexpr bool is_exact = false;

    LyingKernel() = default;
    LyingKernel(Mode m) : mode(m) {}  // NOLINT(google-explicit-constructor): LyingKernel{mode}

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
    /// Every predicate of the list (KernelWrapper): orientations and in-circle tests as
    /// the mode says; any other predicate a constant or a coin.
    template <class Points>
    Sign answer(Predicate which, const Points& p) const {
        switch (which) {
            case Predicate::orient2d:
                if (mode == always_flip) return AdaptiveKernel{}.orient2d(p[0], p[1], p[2]);
                return mode == random || mode == random_orient ? coin() : constant();
            case Predicate::incircle:
            case Predicate::incircle_cosine:
                if (mode == always_flip) return Sign::positive;
                if (mode == random_orient) return AdaptiveKernel{}.incircle(p[0], p[1], p[2], p[3]);
                return mode == random ? coin() : constant();
            default: return mode == random ? coin() : constant();
        }
    }
    std::string name() const { return "lying"; }
};
static_assert(PredicateKernel<LyingKernel>);

}  // namespace exidel::test
