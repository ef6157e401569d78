// exidel (private): the library's explicit instantiations of the triangulation, spread over
// translation units so that the build uses every core.
//
// For every kernel K of the registry (EXIDEL_KERNELS) and DynamicKernel,
// lib/delaunay/CMakeLists.txt generates, in the build tree:
//   - instantiate/<K>.cpp: triangulate<off and counters, K> and sorted_convex_hull<K>,
//     with every algorithm's body declared extern (EXIDEL_DELAUNAY_INSTANTIATE_KERNEL);
//   - instantiate/<K>_<algorithm>.cpp, one per algorithm of EXIDEL_DELAUNAY_ALGORITHMS:
//     that algorithm's body, detail::run_one (EXIDEL_DELAUNAY_INSTANTIATE_ALGORITHM):
//     over DynamicKernel counted, for both in-circle policies (its uninstrumented runs
//     are counted ones with the counts dropped); over the double kernel uninstrumented
//     and the adaptive one both ways, for the determinant (their cosine runs are
//     DynamicKernel's); none for the kernels of EXIDEL_DELAUNAY_DYNAMIC_KERNELS, whose
//     triangulation runs DynamicKernel's bodies.
// CMake reads the three lists from registry.hpp, algorithms.hpp and triangulate.hpp, so
// a new kernel or algorithm needs no edit here; one the generator missed is an undefined
// reference when the library's users link (triangulate.hpp declares every registry kernel
// extern).
//
// RunKernel<K> is the kernel whose bodies run K's triangulation: K itself, DynamicKernel
// for the dynamic kernels, and InlineAdaptiveKernel (inline_adaptive.hpp) for the
// adaptive kernel, whose entry is in instantiate.cpp.
#pragma once

#include <span>
#include <type_traits>

#include "exidel/delaunay/hull.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "inline_adaptive.hpp"

namespace exidel::delaunay::detail {

/// The kernel whose algorithm bodies run a registry kernel's uninstrumented triangulation
/// (a counted one runs DynamicKernel's, but the adaptive kernel's: runs_dynamic).
template <class K>
struct RunKernel {
    using type = std::conditional_t<runs_dynamic<K, Instrumentation::off>, DynamicKernel, K>;
};
template <>
struct RunKernel<AdaptiveKernel> {
    using type = InlineAdaptiveKernel;
};

}  // namespace exidel::delaunay::detail

// `prefix` is `template` (the definition) or `extern template` (the declaration), inside
// namespace exidel::delaunay::detail.
#define EXIDEL_DELAUNAY_RUN_ONE_(prefix, Type, K, I, P)                  \
    prefix void run_one<Type, K, Instrumentation::I, InCirclePolicy::P>( \
        const K&, SortedInput&, const Options&, MeshOutput&, Result&);
#define EXIDEL_DELAUNAY_RUN_ALL_(prefix, Type, K, I)          \
    EXIDEL_DELAUNAY_RUN_ONE_(prefix, Type, K, I, determinant) \
    EXIDEL_DELAUNAY_RUN_ONE_(prefix, Type, K, I, cosine)
// The policies whose bodies a kernel's translation units compile: both for DynamicKernel,
// the determinant for the others (their cosine runs are DynamicKernel's:
// detail::cosine_runs_dynamic). CMake names one of the two in each generated file.
#define EXIDEL_DELAUNAY_POLICIES_both(prefix, Type, K, I) \
    EXIDEL_DELAUNAY_RUN_ALL_(prefix, Type, K, I)
#define EXIDEL_DELAUNAY_POLICIES_determinant(prefix, Type, K, I) \
    EXIDEL_DELAUNAY_RUN_ONE_(prefix, Type, K, I, determinant)

// Every algorithm's body for detail::InstantiatedKernel, declared extern: compiled in the
// translation units of EXIDEL_DELAUNAY_INSTANTIATE_ALGORITHM, never where it is called.
#define EXIDEL_DELAUNAY_EXTERN_ALGORITHM_(name, spelling, Type, takes_order, summary) \
    EXIDEL_DELAUNAY_RUN_ALL_(extern template, Type, InstantiatedKernel, off)          \
    EXIDEL_DELAUNAY_RUN_ALL_(extern template, Type, InstantiatedKernel, counters)     \
    EXIDEL_DELAUNAY_RUN_ALL_(extern template, Type, DynamicKernel, off)               \
    EXIDEL_DELAUNAY_RUN_ALL_(extern template, Type, DynamicKernel, counters)
#define EXIDEL_DELAUNAY_EXTERN_ALGORITHMS(K)                      \
    namespace exidel::delaunay::detail {                          \
    using InstantiatedKernel = RunKernel<K>::type;                \
    EXIDEL_DELAUNAY_ALGORITHMS(EXIDEL_DELAUNAY_EXTERN_ALGORITHM_) \
    }

#define EXIDEL_DELAUNAY_INSTANTIATE_KERNEL(K)                                                    \
    EXIDEL_DELAUNAY_EXTERN_ALGORITHMS(K)                                                         \
    namespace exidel::delaunay {                                                                 \
    template Result triangulate<Instrumentation::off, K>(std::span<const Point2>, const K&,      \
                                                         const Options&);                        \
    template Result triangulate<Instrumentation::counters, K>(std::span<const Point2>, const K&, \
                                                              const Options&);                   \
    template SortedHull sorted_convex_hull<K>(std::span<const Point2>, const K&);                \
    }

// The body of algorithm Type over RunKernel<K>, uninstrumented (off) or counted
// (counters), for the in-circle policies `policies` (both or determinant).
#define EXIDEL_DELAUNAY_INSTANTIATE_ALGORITHM(K, Type, I, policies)            \
    namespace exidel::delaunay::detail {                                       \
    EXIDEL_DELAUNAY_POLICIES_##policies(template, Type, RunKernel<K>::type, I) \
    }
