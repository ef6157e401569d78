// exidel: the constrained triangulation compiled for every kernel of the registry (its case
// of points on one line is in constrained_line.cpp, with the kernel-independent code).
#include "exidel/delaunay/constrained.hpp"

#include "inline_adaptive.hpp"

namespace exidel::delaunay {

// The adaptive kernel's filters inlined into the builder (inline_adaptive.hpp): the same
// predicates, without a call per orientation.
struct detail::InlineConstrainedKernel : detail::InlineAdaptiveKernel {};
detail::InlineConstrainedKernel detail::ConstrainedRunKernel<AdaptiveKernel>::from(
    const AdaptiveKernel&) {
    return {};
}

#define EXIDEL_CONSTRAINED_INSTANTIATE(K, spelling, summary) \
    template ConstrainedResult constrained_delaunay<K>(      \
        std::span<const Point2>, std::span<const Segment>, const K&, const ConstrainedOptions&);
EXIDEL_KERNELS(EXIDEL_CONSTRAINED_INSTANTIATE)
#undef EXIDEL_CONSTRAINED_INSTANTIATE

}  // namespace exidel::delaunay
