// exidel: how the adaptive kernel's triangulation enters InlineAdaptiveKernel. The
// explicit instantiations of every kernel's triangulation are generated from the registry
// (src/instantiate.hpp); those of AdaptiveKernel call detail::triangulate_adaptive, here.
//
// The adaptive kernel's triangulation runs InlineAdaptiveKernel: the same exact answers,
// the filters inline and the floating-point environment made standard once for the whole
// run (inline_adaptive.hpp).
#include "exidel/predicates/internal/fp_environment.hpp"
#include "instantiate.hpp"

// The algorithm bodies over InlineAdaptiveKernel: in instantiate/AdaptiveKernel_*.cpp.
EXIDEL_DELAUNAY_EXTERN_ALGORITHMS(exidel::AdaptiveKernel)

namespace exidel::delaunay {

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
