// exidel: the triangulation and the sorted hull compiled once for the shipped kernels,
// in the library's own translation unit (compiled with -ffp-contract=off).
#include "exidel/delaunay/hull.hpp"
#include "exidel/delaunay/triangulate.hpp"

namespace exidel::delaunay {

#define EXIDEL_DELAUNAY_INSTANTIATE(K)                                                     \
    template Result triangulate<Instrumentation::off, K>(std::span<const Point2>, const K&, \
                                                         const Options&);                   \
    template Result triangulate<Instrumentation::counters, K>(std::span<const Point2>,      \
                                                              const K&, const Options&);    \
    template Result triangulate<Instrumentation::theorem1, K>(std::span<const Point2>,      \
                                                              const K&, const Options&);

EXIDEL_DELAUNAY_INSTANTIATE(AdaptiveKernel)
EXIDEL_DELAUNAY_INSTANTIATE(DoubleKernel)
EXIDEL_DELAUNAY_INSTANTIATE(LongDoubleKernel)
EXIDEL_DELAUNAY_INSTANTIATE(GmpExactKernel)
EXIDEL_DELAUNAY_INSTANTIATE(MpfrKernel)
#undef EXIDEL_DELAUNAY_INSTANTIATE

template SortedHull sorted_convex_hull<AdaptiveKernel>(std::span<const Point2>,
                                                       const AdaptiveKernel&);
template SortedHull sorted_convex_hull<GmpExactKernel>(std::span<const Point2>,
                                                       const GmpExactKernel&);
template SortedHull sorted_convex_hull<DoubleKernel>(std::span<const Point2>,
                                                     const DoubleKernel&);

}  // namespace exidel::delaunay
