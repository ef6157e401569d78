// exidel: the external incremental algorithm's orders (Options::strategy) and the rules
// by which `automatic` picks one. The algorithm itself is detail/external_incremental.hpp.
#pragma once

#include <cstddef>

#include "exidel/delaunay/result.hpp"

namespace exidel::delaunay {

/// Below this many points `automatic` runs one radial pass; from it, strips.
inline constexpr std::size_t automatic_strips_from = std::size_t{1} << 15;

/// Points per strip when Options::strip_points is 0: the fastest on uniform input at
/// every size measured (docs/measurements.md): a strip's arrays stay cache-sized, and
/// the merges cost little.
constexpr std::size_t default_strip_points(std::size_t /*n*/) noexcept {
    return std::size_t{1} << 14;
}

/// Tiles per strip when Options::strip_tiles is 0.
constexpr std::size_t default_strip_tiles(std::size_t /*n*/, std::size_t /*strip_points*/) noexcept {
    return 1;
}

/// The size rule of `automatic` for n distinct points: radial below automatic_strips_from,
/// strips from there, where the shape may still choose radial (detail/curve_rule.hpp).
constexpr Strategy choose_strategy(std::size_t n, Strategy requested) noexcept {
    if (requested != Strategy::automatic) return requested;
    return n < automatic_strips_from ? Strategy::radial : Strategy::strips;
}

}  // namespace exidel::delaunay
