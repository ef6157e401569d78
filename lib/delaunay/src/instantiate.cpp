// exidel: the triangulation and the sorted hull compiled once for every kernel of the
// registry (exidel/predicates/registry.hpp), in the library's own translation unit
// (compiled with -ffp-contract=off), uninstrumented and with counters.
#include "exidel/delaunay/hull.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "fp_environment.hpp"
#include "inline_adaptive.hpp"

namespace exidel::delaunay {

#define EXIDEL_DELAUNAY_INSTANTIATE(K, spelling, summary)                                        \
    template Result triangulate<Instrumentation::off, K>(std::span<const Point2>, const K&,      \
                                                         const Options&);                        \
    template Result triangulate<Instrumentation::counters, K>(std::span<const Point2>, const K&, \
                                                              const Options&);                   \
    template SortedHull sorted_convex_hull<K>(std::span<const Point2>, const K&);
EXIDEL_KERNELS(EXIDEL_DELAUNAY_INSTANTIATE)
#undef EXIDEL_DELAUNAY_INSTANTIATE

// The adaptive kernel's triangulation runs InlineAdaptiveKernel: the same exact answers,
// the filters inline and the floating-point environment made standard once for the whole
// run (inline_adaptive.hpp).
namespace {

// Never inlined, so that the compiler cannot move the run's floating-point work across
// the MXCSR writes of the guard in triangulate_adaptive.
template <Instrumentation I>
[[gnu::noinline]] Result triangulate_inline_adaptive(std::span<const Point2> points,
                                                     const Options& options) {
    return detail::triangulate_with<I>(points, detail::InlineAdaptiveKernel{}, options);
}

}  // namespace

template <Instrumentation I>
Result detail::triangulate_adaptive(std::span<const Point2> points, const Options& options) {
    if (exidel::detail::environment_is_standard()) [[likely]]
        return triangulate_inline_adaptive<I>(points, options);
    const exidel::detail::StandardEnvironment guard;  // restores the caller's at the end
    return triangulate_inline_adaptive<I>(points, options);
}

template Result detail::triangulate_adaptive<Instrumentation::off>(std::span<const Point2>,
                                                                   const Options&);
template Result detail::triangulate_adaptive<Instrumentation::counters>(std::span<const Point2>,
                                                                        const Options&);

}  // namespace exidel::delaunay
