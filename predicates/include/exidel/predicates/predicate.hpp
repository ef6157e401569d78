// exidel: the one list of predicates every kernel provides.
//
// Each line of EXIDEL_PREDICATES is X(name, points): the PredicateKernel member of that
// name, and how many points it takes. Everything that names, parses, counts or dispatches
// predicates (the `exidel predicate` query format, the research studies, the agreement
// table) derives from this list, so a new predicate is one line here plus its kernels.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/types.hpp"

// clang-format off
#define EXIDEL_PREDICATES(X) \
    X(orient2d, 3)           \
    X(incircle, 4)           \
    X(incircle_cosine, 4)    \
    X(compare_distance, 3)
// clang-format on

namespace exidel {

enum class Predicate {
#define EXIDEL_PREDICATE_ENUMERATOR(name, points) name,
    EXIDEL_PREDICATES(EXIDEL_PREDICATE_ENUMERATOR)
#undef EXIDEL_PREDICATE_ENUMERATOR
};

/// Every predicate, in the order of the list.
inline constexpr std::array all_predicates{
#define EXIDEL_PREDICATE_VALUE(name, points) Predicate::name,
    EXIDEL_PREDICATES(EXIDEL_PREDICATE_VALUE)
#undef EXIDEL_PREDICATE_VALUE
};

/// The predicate's name, as the kernels' member and the query format spell it.
constexpr std::string_view predicate_name(Predicate p) noexcept {
    switch (p) {
#define EXIDEL_PREDICATE_NAME(name, points) \
    case Predicate::name: return #name;
        EXIDEL_PREDICATES(EXIDEL_PREDICATE_NAME)
#undef EXIDEL_PREDICATE_NAME
    }
    return "?";
}

/// How many points the predicate takes: 3 for orient2d and compare_distance, 4 for the
/// in-circle tests.
constexpr std::size_t point_count(Predicate p) noexcept {
    switch (p) {
#define EXIDEL_PREDICATE_POINTS(name, points) \
    case Predicate::name: return points;
        EXIDEL_PREDICATES(EXIDEL_PREDICATE_POINTS)
#undef EXIDEL_PREDICATE_POINTS
    }
    return 0;
}

/// The predicate of that name, or nothing.
constexpr std::optional<Predicate> predicate_from_name(std::string_view name) noexcept {
    for (Predicate p : all_predicates) {
        if (predicate_name(p) == name) return p;
    }
    return std::nullopt;
}

/// Evaluates predicate p of kernel k on its point_count(p) first points, in argument order
/// (compare_distance(c, p, q) takes c first).
template <PredicateKernel K>
Sign evaluate(const K& k, Predicate p, std::span<const Point2> args) {
    switch (p) {
        case Predicate::orient2d: return k.orient2d(args[0], args[1], args[2]);
        case Predicate::incircle: return k.incircle(args[0], args[1], args[2], args[3]);
        case Predicate::incircle_cosine:
            return k.incircle_cosine(args[0], args[1], args[2], args[3]);
        case Predicate::compare_distance: return k.compare_distance(args[0], args[1], args[2]);
    }
    return Sign::zero;  // unreachable: every enumerator is handled above
}

}  // namespace exidel
