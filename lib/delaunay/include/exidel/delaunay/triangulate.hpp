// exidel: Delaunay triangulation, the entry point of every algorithm.
//
//   points -> validate, sort, remove duplicates (sorted_input.cpp)
//          -> the algorithm Options::algorithm names (algorithms.hpp, one header each in
//             detail/), over the shared mesh (detail/mesh.hpp)
//          -> the mesh as index arrays of input indices (Triangulation)
//
// Header template: any exidel::PredicateKernel works. The library compiles explicit
// instantiations for every kernel of the registry (see the extern declarations at the
// end), so a user's compiler flags never reach the geometry.
#pragma once

#include <span>
#include <type_traits>
#include <utility>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/detail/bowyer_watson.hpp"
#include "exidel/delaunay/detail/divide_and_conquer.hpp"
#include "exidel/delaunay/detail/external_incremental.hpp"
#include "exidel/delaunay/detail/lawson.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/detail/randomized.hpp"
#include "exidel/delaunay/detail/sweep_hull.hpp"
#include "exidel/delaunay/external.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/dynamic.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/registry.hpp"

namespace exidel::delaunay {

namespace detail {

/// One algorithm over one kernel, instrumentation and in-circle policy. Not inline: the
/// library compiles it for each of its kernels and algorithms in a translation unit of its
/// own (src/instantiate_algorithm.hpp; lib/delaunay/CMakeLists.txt generates them from the
/// two lists), so that its build spreads over every core; a user's own kernel instantiates
/// it here.
template <class Type, PredicateKernel K, Instrumentation I, InCirclePolicy P>
void run_one(const K& kernel, SortedInput& in, const Options& options, MeshOutput& out,
             Result& result) {
    Type::template run<K, I, P>(kernel, in, options, out, result);
}

/// Runs the algorithm `options` names on the sorted points and turns its mesh into the
/// result's arrays. Every algorithm is called for every input (fewer than three points
/// included: it sets out.mesh.collinear) and reports a failure instead of a mesh when its
/// kernel contradicted itself.
template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
Result run_algorithm(const K& kernel, SortedInput& in, const Options& options) {
    Result result;
    result.algorithm = options.algorithm;
    MeshOutput out;
    switch (options.algorithm) {
#define EXIDEL_RUN_ALGORITHM_(name, spelling, Type, takes_order, summary) \
    case Algorithm::name: run_one<Type, K, I, P>(kernel, in, options, out, result); break;
        EXIDEL_DELAUNAY_ALGORITHMS(EXIDEL_RUN_ALGORITHM_)
#undef EXIDEL_RUN_ALGORITHM_
        default:
            result.failure = Failure{FailureKind::unknown_algorithm, no_index, no_index,
                                     "Options::algorithm is not an Algorithm enumerator"};
            return result;
    }
    Triangulation& tri = result.triangulation;
    if (!result.failure) {
        if (out.mesh.collinear) {
            tri.collinear = true;
            tri.hull.assign(in.input_of.begin(),
                            in.input_of.end());  // the chain, lexicographically
        } else {
            result.failure = to_triangulation(out.mesh,
                                              out.input_of.empty()
                                                  ? std::span<const std::uint32_t>(in.input_of)
                                                  : std::span<const std::uint32_t>(out.input_of),
                                              out.first, tri, options.threads);
        }
    }
    tri.vertex_of_input = std::move(in.vertex_of_input);
    tri.duplicates = std::move(in.duplicates);
    // The arrays leave the library (or, after a failure, are freed here): their huge-page
    // advice must not outlive them (detail/memory.hpp).
    settle_huge_pages(tri.triangles);
    settle_huge_pages(tri.halfedges);
    settle_huge_pages(tri.vertex_of_input);
    settle_huge_pages(out.mesh.triangles);
    settle_huge_pages(out.mesh.halfedges);
    return result;
}

}  // namespace detail

/// Delaunay triangulation of `points` with the predicates of `kernel`, by the algorithm
/// options.algorithm names.
///
/// Every finite input is accepted, including none, one or two points and duplicates;
/// a non-finite coordinate fails before any work. With an exact kernel (AdaptiveKernel,
/// GmpExactKernel, CppIntExactKernel) the result is a Delaunay triangulation, the same
/// one for both in-circle policies. With an inexact kernel the result may be wrong, or
/// the run may stop with a Failure saying where the kernel contradicted itself; it never
/// loops or reads out of bounds.
template <Instrumentation I = Instrumentation::off, PredicateKernel K>
Result triangulate(std::span<const Point2> points, const K& kernel, const Options& options = {});

namespace detail {

/// Whether a run of kernel K with the cosine in-circle policy goes through DynamicKernel:
/// always, but for DynamicKernel itself and Instrumentation::theorem1 (which the tests
/// that use it compile for their own kernels). The cosine test is the paper's alternative
/// to the determinant, asked by the research studies and `--incircle cosine`; its
/// algorithm bodies are compiled once, for DynamicKernel, instead of once per kernel
/// (lib/delaunay/CMakeLists.txt compiles only the determinant's for the others). The
/// answers are the kernel's, call for call; the run pays an indirect call per predicate.
template <class K, Instrumentation I>
inline constexpr bool cosine_runs_dynamic =
    I != Instrumentation::theorem1 && !std::is_same_v<K, DynamicKernel>;

/// triangulate's body, for every kernel.
template <Instrumentation I, PredicateKernel K>
Result triangulate_with(std::span<const Point2> points, const K& kernel, const Options& options) {
    detail::SortedInput input;
    if (auto failure = detail::sort_and_dedupe(points, input, options.threads)) {
        Result r;
        r.algorithm = options.algorithm;
        r.failure = std::move(failure);
        return r;
    }
    if (options.incircle == InCirclePolicy::cosine) {
        if constexpr (cosine_runs_dynamic<K, I>) {
            // DynamicKernel's bodies are the counted ones (see triangulate).
            Result r = detail::run_algorithm<DynamicKernel, Instrumentation::counters,
                                             InCirclePolicy::cosine>(DynamicKernel(kernel), input,
                                                                     options);
            if constexpr (I == Instrumentation::off) r.counters = Counters{};
            return r;
        } else {
            return detail::run_algorithm<K, I, InCirclePolicy::cosine>(kernel, input, options);
        }
    }
    return detail::run_algorithm<K, I, InCirclePolicy::determinant>(kernel, input, options);
}

/// The adaptive kernel's run as the library compiles it (src/instantiate.cpp, for `off`
/// and `counters`): the same predicates, with the filters of orient2d and incircle inline
/// in the algorithms' loops instead of behind a call each, and the floating-point
/// environment checked once per run instead of once per call.
template <Instrumentation I>
Result triangulate_adaptive(std::span<const Point2> points, const Options& options);

// The kernels of the registry whose triangulation runs through DynamicKernel
// (exidel/predicates/dynamic.hpp): their predicates cost far more than the indirect call
// (exact integers, MPFR) or they are baselines for research (x87 long double), and the
// algorithms are then compiled once for all of them instead of once each
// (lib/delaunay/CMakeLists.txt reads this list). The answers are the kernel's, call for
// call, so the result is the same.
// clang-format off
#define EXIDEL_DELAUNAY_DYNAMIC_KERNELS(X) \
    X(LongDoubleKernel)                    \
    X(GmpExactKernel)                      \
    X(CppIntExactKernel)                   \
    X(MpfrKernel)
// clang-format on

template <class K>
inline constexpr bool listed_dynamic = false;
#define EXIDEL_DELAUNAY_LISTED_DYNAMIC_(K) \
    template <>                            \
    inline constexpr bool listed_dynamic<K> = true;
EXIDEL_DELAUNAY_DYNAMIC_KERNELS(EXIDEL_DELAUNAY_LISTED_DYNAMIC_)
#undef EXIDEL_DELAUNAY_LISTED_DYNAMIC_

/// Whether triangulate<I>(points, K) runs through DynamicKernel: with the kernels of the
/// list, and, when counting (Instrumentation::counters, a run for its counts), with every
/// kernel but the adaptive one, whose counted runs `--stats` times. Never for theorem1,
/// which the tests that use it compile for their own kernels.
template <class K, Instrumentation I>
inline constexpr bool runs_dynamic =
    I != Instrumentation::theorem1 && !std::is_same_v<K, DynamicKernel> &&
    (listed_dynamic<K> || (I == Instrumentation::counters && !std::is_same_v<K, AdaptiveKernel>));

}  // namespace detail

template <Instrumentation I, PredicateKernel K>
Result triangulate(std::span<const Point2> points, const K& kernel, const Options& options) {
    if constexpr (std::is_same_v<K, AdaptiveKernel> && I != Instrumentation::theorem1) {
        return detail::triangulate_adaptive<I>(points, options);
    } else if constexpr (detail::runs_dynamic<K, I>) {
        return triangulate<I>(points, DynamicKernel(kernel), options);
    } else if constexpr (std::is_same_v<K, DynamicKernel> && I == Instrumentation::off) {
        // The library compiles DynamicKernel's algorithm bodies counted only: its kernels'
        // predicates (exact, MPFR, or behind an indirect call) cost far more than an
        // increment, and one set of bodies instead of two halves their compile time. The
        // counts are dropped: an uninstrumented result has none.
        Result r = triangulate<Instrumentation::counters>(points, kernel, options);
        r.counters = Counters{};
        return r;
    } else {
        return detail::triangulate_with<I>(points, kernel, options);
    }
}

// Compiled once in the library for every kernel of the registry
// (exidel/predicates/registry.hpp) and DynamicKernel, uninstrumented and with counters.
// Instrumentation:: theorem1 is not: the tests that use it instantiate it.
#define EXIDEL_DELAUNAY_EXTERN(K, spelling, summary)                                               \
    extern template Result triangulate<Instrumentation::off, K>(std::span<const Point2>, const K&, \
                                                                const Options&);                   \
    extern template Result triangulate<Instrumentation::counters, K>(std::span<const Point2>,      \
                                                                     const K&, const Options&);
EXIDEL_KERNELS(EXIDEL_DELAUNAY_EXTERN)
EXIDEL_DELAUNAY_EXTERN(DynamicKernel, "", "")
#undef EXIDEL_DELAUNAY_EXTERN

}  // namespace exidel::delaunay
