// exidel: the one list of predicates every kernel provides, and the list of the predicates
// of space (PredicateKernel3D).
//
// Each line of EXIDEL_PREDICATES is X(name, points, "arguments", "summary"): the
// PredicateKernel member of that name, how many points it takes (3, 4 or 5), the names of
// its arguments as Python and the documentation spell them, and one sentence on its sign.
// Everything that names, parses, counts, forwards or dispatches predicates derives from
// this list: the Predicate enum, evaluate(), KernelWrapper (wrapper.hpp), DynamicKernel
// (dynamic.hpp), the `exidel predicate` query format, the research studies and the
// Python functions. A new predicate (docs/architecture.md, "Adding a predicate") is:
//   1. one line here (in EXIDEL_SPACE_PREDICATES if its points are Point3);
//   2. its requirement and meaning in kernel.hpp (PredicateKernel, or PredicateKernel3D);
//   3. its member in every shipped kernel: floating.hpp/.cpp and formulas.hpp (double,
//      long double and MPFR evaluate the same formula), exact.hpp/.cpp, mpfr.hpp/.cpp,
//      adaptive.hpp and adaptive.cpp or adaptive3d.cpp (the filter and stages);
//   4. its proofs: every error bound and bit count of those stages in proofs/, the
//      constants in constants.hpp (proofs/checker compares them), and exact_bits in
//      exidel/testing/ulp.hpp;
//   5. its tests: generators of its degenerate inputs, a property against CGAL, and
//      its CGAL column in bench/agreement.cpp.
// Derived without an edit: evaluate(), every KernelWrapper and DynamicKernel, the Python
// function, the query format of `exidel predicate`.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/types.hpp"

// clang-format off
#define EXIDEL_PREDICATES(X)                                                                   \
    X(orient2d, 3, "a,b,c",                                                                    \
      "Sign of the orientation of (a, b, c): +1 counter-clockwise, -1 clockwise, 0 collinear.") \
    X(incircle, 4, "a,b,c,d",                                                                  \
      "Shewchuk's in-circle determinant: +1 when d is inside the circle through a, b, c "      \
      "(counter-clockwise), -1 outside, 0 on it; the sign flips for a clockwise abc.")         \
    X(incircle_cosine, 4, "a,b,c,d",                                                           \
      "Cai's cosine in-circle test (the paper's Section 5): +1 when d is inside the circle "   \
      "through a, b, c. An in-circle test only when c and d are strictly on opposite sides "   \
      "of line ab (kernel.hpp states the precondition).")                                     \
    X(compare_distance, 3, "c,p,q", "Sign of |p - c|^2 - |q - c|^2.")

// The predicates of space (PredicateKernel3D), in a list of their own: their points are
// Point3, and a kernel may lack them (has_3d_predicates).
#define EXIDEL_SPACE_PREDICATES(X)                                                             \
    X(orient3d, 4, "a,b,c,d",                                                                  \
      "Shewchuk's orient3d: the sign of det(a - d, b - d, c - d); +1 when d lies below the "   \
      "plane through a, b, c (a, b, c counter-clockwise seen from above), -1 above, 0 "        \
      "coplanar. The opposite of CGAL's orientation.")                                        \
    X(insphere, 5, "a,b,c,d,e",                                                                \
      "Shewchuk's insphere: +1 when e is inside the sphere through a, b, c, d with "           \
      "orient3d(a, b, c, d) positive, -1 outside, 0 on it; the sign flips with "              \
      "orient3d(a, b, c, d). The opposite of CGAL's side_of_oriented_sphere.")

// EXIDEL_PREDICATE_PARAMETERS_<points>(T) declares the parameters p0, p1, ... of type T;
// EXIDEL_PREDICATE_ARGUMENTS_<points>(a) passes a[0], a[1], ...: for code that writes one
// member or call per entry of the lists (a predicate of 6 points adds its two lines here).
#define EXIDEL_PREDICATE_PARAMETERS_3(T) T p0, T p1, T p2
#define EXIDEL_PREDICATE_PARAMETERS_4(T) EXIDEL_PREDICATE_PARAMETERS_3(T), T p3
#define EXIDEL_PREDICATE_PARAMETERS_5(T) EXIDEL_PREDICATE_PARAMETERS_4(T), T p4
#define EXIDEL_PREDICATE_ARGUMENTS_3(a) a[0], a[1], a[2]
#define EXIDEL_PREDICATE_ARGUMENTS_4(a) EXIDEL_PREDICATE_ARGUMENTS_3(a), a[3]
#define EXIDEL_PREDICATE_ARGUMENTS_5(a) EXIDEL_PREDICATE_ARGUMENTS_4(a), a[4]
#define EXIDEL_PREDICATE_NAMES_3 p0, p1, p2
#define EXIDEL_PREDICATE_NAMES_4 EXIDEL_PREDICATE_NAMES_3, p3
#define EXIDEL_PREDICATE_NAMES_5 EXIDEL_PREDICATE_NAMES_4, p4
// clang-format on

namespace exidel {

enum class Predicate {
#define EXIDEL_PREDICATE_ENUMERATOR(name, points, arguments, summary) name,
    EXIDEL_PREDICATES(EXIDEL_PREDICATE_ENUMERATOR)
};

enum class SpacePredicate { EXIDEL_SPACE_PREDICATES(EXIDEL_PREDICATE_ENUMERATOR) };
#undef EXIDEL_PREDICATE_ENUMERATOR

/// Every predicate, in the order of the list.
inline constexpr std::array all_predicates{
#define EXIDEL_PREDICATE_VALUE(name, points, arguments, summary) Predicate::name,
    EXIDEL_PREDICATES(EXIDEL_PREDICATE_VALUE)};
inline constexpr std::array all_space_predicates{
#define EXIDEL_SPACE_PREDICATE_VALUE(name, points, arguments, summary) SpacePredicate::name,
    EXIDEL_SPACE_PREDICATES(EXIDEL_SPACE_PREDICATE_VALUE)
#undef EXIDEL_SPACE_PREDICATE_VALUE
#undef EXIDEL_PREDICATE_VALUE
};

namespace detail {
/// Name and point count of each entry of a list, indexed by the enumerator's value.
struct PredicateFacts {
    std::string_view name;
    std::size_t points;
    std::string_view arguments;  ///< "a,b,c": the names of the points, comma-separated
    std::string_view summary;
};
#define EXIDEL_PREDICATE_FACTS(name, points, arguments, summary) \
    PredicateFacts{#name, points, arguments, summary},
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

/// The names of the predicate's points, comma-separated ("a,b,c"; "c,p,q" for
/// compare_distance), and one sentence on its sign: for help texts and the Python module.
constexpr std::string_view predicate_arguments(Predicate p) noexcept {
    return detail::facts(p).arguments;
}
constexpr std::string_view predicate_arguments(SpacePredicate p) noexcept {
    return detail::facts(p).arguments;
}
constexpr std::string_view predicate_summary(Predicate p) noexcept {
    return detail::facts(p).summary;
}
constexpr std::string_view predicate_summary(SpacePredicate p) noexcept {
    return detail::facts(p).summary;
}

/// Evaluates predicate p of kernel k on its point_count(p) first points, in argument order
/// (compare_distance(c, p, q) takes c first).
template <PredicateKernel K>
Sign evaluate(const K& k, Predicate p, std::span<const Point2> args) {
    switch (p) {
#define EXIDEL_EVALUATE_CASE_(name, points, arguments, summary) \
    case Predicate::name: return k.name(EXIDEL_PREDICATE_ARGUMENTS_##points(args));
        EXIDEL_PREDICATES(EXIDEL_EVALUATE_CASE_)
    }
    return Sign::zero;  // unreachable: every enumerator is handled above
}

/// Evaluates predicate p of space with kernel k on its point_count(p) first points.
template <PredicateKernel3D K>
Sign evaluate(const K& k, SpacePredicate p, std::span<const Point3> args) {
    switch (p) {
#define EXIDEL_EVALUATE_CASE_SPACE_(name, points, arguments, summary) \
    case SpacePredicate::name: return k.name(EXIDEL_PREDICATE_ARGUMENTS_##points(args));
        EXIDEL_SPACE_PREDICATES(EXIDEL_EVALUATE_CASE_SPACE_)
#undef EXIDEL_EVALUATE_CASE_SPACE_
#undef EXIDEL_EVALUATE_CASE_
    }
    return Sign::zero;  // unreachable: every enumerator is handled above
}

}  // namespace exidel
