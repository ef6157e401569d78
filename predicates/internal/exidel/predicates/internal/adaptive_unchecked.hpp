// exidel (private): the adaptive kernel's predicates without the floating-point
// environment check, for callers that have made the environment standard themselves
// (batch.cpp checks it once per array; the library's triangulation with the adaptive
// kernel once per run, lib/delaunay/src/inline_adaptive.hpp). Defined in adaptive.cpp.
#pragma once

#include "exidel/predicates/types.hpp"

namespace exidel::detail {

Sign orient2d_unchecked(Point2 a, Point2 b, Point2 c);
Sign incircle_unchecked(Point2 a, Point2 b, Point2 c, Point2 d);
Sign incircle_cosine_unchecked(Point2 a, Point2 b, Point2 c, Point2 d);
Sign compare_distance_unchecked(Point2 c, Point2 p, Point2 q);

}  // namespace exidel::detail
