// exidel: the base of kernels that wrap other kernels (a budget of calls, counts, lies,
// a precision chosen per query), so that a wrapper writes what it changes once and every
// predicate of the lists, present and future, goes through it.
//
//     struct Counting : exidel::KernelWrapper<Counting> {
//         static constexpr bool is_exact = true;
//         static std::string name() { return "counting"; }
//         mutable std::uint64_t calls = 0;
//         template <class Which, class Points>
//         exidel::Sign answer(Which which, const Points& points) const {
//             ++calls;
//             return exidel::evaluate(exidel::AdaptiveKernel{}, which, points);
//         }
//     };
//
// KernelWrapper<Derived> defines one member per entry of EXIDEL_PREDICATES (orient2d,
// incircle, ...), each calling derived.answer(Predicate::<name>, std::array<Point2, N>{...})
// with its points in argument order; with Space = true, also one per entry of
// EXIDEL_SPACE_PREDICATES (SpacePredicate::<name>, std::array<Point3, N>), which makes the
// wrapper a PredicateKernel3D. `answer` is usually a template over the predicate's enum
// and its array; exidel::evaluate() dispatches both to any kernel. A wrapper that changes
// only some predicates of one kernel need not use this: it derives from that kernel and
// declares the members it changes (they hide the base's).
#pragma once

#include <array>

#include "exidel/predicates/predicate.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel {

template <class Derived, bool Space = false>
struct KernelWrapper {
#define EXIDEL_WRAPPER_MEMBER_(name, points, arguments, summary)                           \
    Sign name(EXIDEL_PREDICATE_PARAMETERS_##points(Point2)) const {                        \
        return self().answer(Predicate::name,                                              \
                             std::array<Point2, points>{EXIDEL_PREDICATE_NAMES_##points}); \
    }
    EXIDEL_PREDICATES(EXIDEL_WRAPPER_MEMBER_)
#undef EXIDEL_WRAPPER_MEMBER_

#define EXIDEL_WRAPPER_SPACE_MEMBER_(name, points, arguments, summary)                     \
    Sign name(EXIDEL_PREDICATE_PARAMETERS_##points(Point3)) const requires Space {         \
        return self().answer(SpacePredicate::name,                                         \
                             std::array<Point3, points>{EXIDEL_PREDICATE_NAMES_##points}); \
    }
    EXIDEL_SPACE_PREDICATES(EXIDEL_WRAPPER_SPACE_MEMBER_)
#undef EXIDEL_WRAPPER_SPACE_MEMBER_

private:
    const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace exidel
