// exidel: the adaptive kernel's predicates over arrays of queries.
//
// out[i] = AdaptiveKernel::orient2d(a[i], b[i], c[i]) for every i, and likewise for the
// other predicates: the same exact signs, at a fraction of the cost of one call per query.
// The floating-point environment is checked once per array rather than once per query;
// on processors with AVX2 (detected at run time) orient2d's and incircle's filters run on
// four queries at once, operation for operation the scalar filters (so with the same
// proven bounds), and the few queries they leave undecided take the scalar stages one by
// one. Everything is compiled in the library's own translation units with
// -ffp-contract=off: exact whatever flags the caller uses.
//
// Every span must have the same length as `out`; otherwise std::invalid_argument.
#pragma once

#include <span>

#include "exidel/predicates/types.hpp"

namespace exidel::batch {

void orient2d(std::span<const Point2> a, std::span<const Point2> b, std::span<const Point2> c,
              std::span<Sign> out);

void incircle(std::span<const Point2> a, std::span<const Point2> b, std::span<const Point2> c,
              std::span<const Point2> d, std::span<Sign> out);

void incircle_cosine(std::span<const Point2> a, std::span<const Point2> b,
                     std::span<const Point2> c, std::span<const Point2> d, std::span<Sign> out);

/// out[i] = sign(|p[i] - c[i]|^2 - |q[i] - c[i]|^2).
void compare_distance(std::span<const Point2> c, std::span<const Point2> p,
                      std::span<const Point2> q, std::span<Sign> out);

/// Which implementation the batched filters use: "avx2" or "scalar".
const char* implementation() noexcept;

}  // namespace exidel::batch
