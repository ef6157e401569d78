// exidel: point location compiled for every kernel of the registry and DynamicKernel, and
// the adaptive kernel's batches with its filters inline (inline_adaptive.hpp): the same
// exact answers, the floating-point environment made standard once per batch instead of
// checked at every orient2d.
#include "exidel/delaunay/locate.hpp"
#include "exidel/predicates/internal/fp_environment.hpp"
#include "inline_adaptive.hpp"

namespace exidel::delaunay {

#define EXIDEL_LOCATE_INSTANTIATE(K, spelling, summary) template class Locator<K>;
EXIDEL_KERNELS(EXIDEL_LOCATE_INSTANTIATE)
EXIDEL_LOCATE_INSTANTIATE(DynamicKernel, "", "")
#undef EXIDEL_LOCATE_INSTANTIATE

namespace {

// Never inlined, so that the compiler cannot move the batch's floating-point work across
// the MXCSR writes of the guard in locate_adaptive.
[[gnu::noinline]] std::optional<Failure> locate_inline_adaptive(
    const Locator<AdaptiveKernel>& locator, std::span<const Point2> queries,
    std::span<Location> out, const LocateOptions& options) {
    return locator.locate_with(detail::InlineAdaptiveKernel{}, queries, out, options);
}

}  // namespace

std::optional<Failure> detail::locate_adaptive(const Locator<AdaptiveKernel>& locator,
                                               std::span<const Point2> queries,
                                               std::span<Location> out,
                                               const LocateOptions& options) {
    if (exidel::detail::environment_is_standard()) [[likely]]
        return locate_inline_adaptive(locator, queries, out, options);
    const exidel::detail::StandardEnvironment guard;  // restores the caller's at the end
    return locate_inline_adaptive(locator, queries, out, options);
}

}  // namespace exidel::delaunay
