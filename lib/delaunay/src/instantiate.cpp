// exidel: the triangulation and the sorted hull compiled once for every kernel of the
// registry (exidel/predicates/registry.hpp), in the library's own translation unit
// (compiled with -ffp-contract=off), uninstrumented and with counters.
#include "exidel/delaunay/hull.hpp"
#include "exidel/delaunay/triangulate.hpp"

namespace exidel::delaunay {

#define EXIDEL_DELAUNAY_INSTANTIATE(K, spelling, summary)                                  \
    template Result triangulate<Instrumentation::off, K>(std::span<const Point2>, const K&, \
                                                         const Options&);                   \
    template Result triangulate<Instrumentation::counters, K>(std::span<const Point2>,      \
                                                              const K&, const Options&);    \
    template SortedHull sorted_convex_hull<K>(std::span<const Point2>, const K&);
EXIDEL_KERNELS(EXIDEL_DELAUNAY_INSTANTIATE)
#undef EXIDEL_DELAUNAY_INSTANTIATE

}  // namespace exidel::delaunay
