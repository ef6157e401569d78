// exidel: linear interpolation over a triangulation, from exact locations (locate.hpp).
//
// Where each query lies is exact; the interpolated value is a floating-point construction:
//   on a vertex   the vertex's value, exactly;
//   on an edge    (1 - t) v_a + t v_b with t = (q - a).(b - a) / |b - a|^2, from the edge's
//                 two ends alone (the third corner's weight is exactly 0, so both
//                 triangles of the edge give the same value);
//   inside        the barycentric combination w_a v_a + w_b v_b + w_c v_c, with w_a =
//                 A / (A + B + C) for A = (b - q) x (c - q), B = (c - q) x (a - q),
//                 C = (a - q) x (b - q), each rounded to double;
//   outside       `fill`.
// The weights are rounded, with no proven bound: their error relative to the triangle
// grows as it gets thinner. Coordinates beyond 2^500 or below 2^-400 are first scaled by
// a power of two, so that no product overflows or vanishes (finite values at any finite
// coordinates give finite results). Collinear points (no triangles) interpolate along
// their chain.
#pragma once

#include <span>

#include "exidel/delaunay/locate.hpp"
#include "exidel/delaunay/result.hpp"

namespace exidel::delaunay {

/// out[i] = the linear interpolant of `values` (one per input point; a repeated point's
/// value is its first occurrence's) at queries[i], located at where[i] in `t` (the
/// triangulation of `points`). Throws std::invalid_argument when the sizes differ.
void interpolate_linear(std::span<const Point2> points, const Triangulation& t,
                        std::span<const double> values, std::span<const Point2> queries,
                        std::span<const Location> where, std::span<double> out, double fill);

}  // namespace exidel::delaunay
