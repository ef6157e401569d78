// exidel: the one list of predicates every kernel provides, and the list of the predicates
// of space (PredicateKernel3D).
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

// The predicates of space (PredicateKernel3D), in a list of their own: their points are
// Point3, and a kernel may lack them (has_3d_predicates).
#define EXIDEL_SPACE_PREDICATES(X) \
    X(orient3d, 4)                 \
    X(insphere, 5)
// clang-format on

namespace exidel {

enum class Predicate {
#define EXIDEL_PREDICATE_ENUMERATOR(name, points) name,
    EXIDEL_PREDICATES(EXIDEL_PREDICATE_ENUMERATOR)
};

enum class SpacePredicate { EXIDEL_SPACE_PREDICATES(EXIDEL_PREDICATE_ENUMERATOR) };
#undef EXIDEL_PREDICATE_ENUMERATOR

/// Every predicate, in the order of the list.
inline constexpr std::array all_predicates{
#define EXIDEL_PREDICATE_VALUE(name, points) Predicate::name,
    EXIDEL_PREDICATES(EXIDEL_PREDICATE_VALUE)};
inline constexpr std::array all_space_predicates{
#define EXIDEL_SPACE_PREDICATE_VALUE(name, points) SpacePredicate::name,
    EXIDEL_SPACE_PREDICATES(EXIDEL_SPACE_PREDICATE_VALUE)
#undef EXIDEL_SPACE_PREDICATE_VALUE
#undef EXIDEL_PREDICATE_VALUE
};

namespace detail {
/// Name and point count of each entry of a list, indexed by the enumerator's value.
struct PredicateFacts {
    std::string_view name;
    std::size_t points;
};
#define EXIDEL_PREDICATE_FACTS(name, points) PredicateFacts{#name, points},
inline constexpr PredicateFacts predicate_facts[] = {EXIDEL_PREDICATES(EXIDEL_PREDICATE_FACTS)};
inline constexpr PredicateFacts space_predicate_facts[] = {
    EXIDEL_SPACE_PREDICATES(EXIDEL_PREDICATE_FACTS)};
#undef EXIDEL_PREDICATE_FACTS
constexpr const PredicateFacts& facts(Predicate p) noexcept {
    return predicate_facts[static_cast<std::size_t>(p)];
}
constexpr const PredicateFacts& facts(SpacePredicate p) noexcept {
    return space_predicate_facts[static_cast<std::size_t>(p)];
}
}  // namespace detail

/// The predicate's name, as the kernels' member and the query format spell it.
constexpr std::string_view predicate_name(Predicate p) noexcept { return detail::facts(p).name; }
constexpr std::string_view predicate_name(SpacePredicate p) noexcept {
    return detail::facts(p).name;
}

/// How many points the predicate takes: 3 for orient2d and compare_distance, 4 for the
/// in-circle tests and orient3d, 5 for insphere.
constexpr std::size_t point_count(Predicate p) noexcept { return detail::facts(p).points; }
constexpr std::size_t point_count(SpacePredicate p) noexcept { return detail::facts(p).points; }

namespace detail {
template <class P, std::size_t N>
constexpr std::optional<P> from_name(const std::array<P, N>& all, std::string_view name) noexcept {
    for (P p : all) {
        if (predicate_name(p) == name) return p;
    }
    return std::nullopt;
}
}  // namespace detail

/// The predicate of that name, or nothing.
constexpr std::optional<Predicate> predicate_from_name(std::string_view name) noexcept {
    return detail::from_name(all_predicates, name);
}
constexpr std::optional<SpacePredicate> space_predicate_from_name(std::string_view name) noexcept {
    return detail::from_name(all_space_predicates, name);
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

/// Evaluates predicate p of space with kernel k on its point_count(p) first points.
template <PredicateKernel3D K>
Sign evaluate(const K& k, SpacePredicate p, std::span<const Point3> args) {
    switch (p) {
        case SpacePredicate::orient3d: return k.orient3d(args[0], args[1], args[2], args[3]);
        case SpacePredicate::insphere:
            return k.insphere(args[0], args[1], args[2], args[3], args[4]);
    }
    return Sign::zero;  // unreachable: every enumerator is handled above
}

}  // namespace exidel
