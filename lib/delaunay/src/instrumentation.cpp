// exidel: the exact checks of Instrumentation::theorem1 (counting.hpp).
#include "exidel/delaunay/detail/counting.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::delaunay::detail {

bool theorem1_holds(Point2 a, Point2 b, Point2 c, Point2 p) {
    return AdaptiveKernel::orient2d(a, b, c) == Sign::positive &&
           AdaptiveKernel::orient2d(a, b, p) == Sign::negative;
}

}  // namespace exidel::delaunay::detail
