// exidel: the external incremental algorithm's orders (Options::strategy) and the rules
// by which `automatic` picks one. The algorithm itself is detail/external_incremental.hpp.
#pragma once

#include <cstddef>

#include "exidel/delaunay/result.hpp"

namespace exidel::delaunay {

/// Below this many points `automatic` runs one radial pass; from it, strips.
inline constexpr std::size_t automatic_strips_from = std::size_t{1} << 15;

/// Eroded edges per point beyond which `automatic` gives up a piece's radial run (or its
/// one radial run) and inserts its points by cavities in BRIO order (Bowyer-Watson,
/// detail/bowyer_watson.hpp). Points along many curves that run across the sweep (GPS
/// tracks, coastlines, borders) make every sweep order fan each new point to a far hull
/// vertex and erode that fan again at the next point; the cavity insertion's order is
/// blind to that. The value is measured (docs/benchmarks.md, "Realistic families"): a
/// cavity insertion costs about what a radial run eroding 10 to 14 edges per point costs,
/// and a limit of 8 to 12 also gave up runs that erode heavily only at their start
/// (quantized borders of 10^4 points ran 20-40% slower for it).
inline constexpr std::size_t automatic_erosion_limit = 14;

/// Points per strip when Options::strip_points is 0: the fastest on uniform input at
/// every size measured (docs/measurements.md): a strip's arrays stay cache-sized, and
/// the merges cost little.
constexpr std::size_t default_strip_points(std::size_t /*n*/) noexcept {
    return std::size_t{1} << 14;
}

/// From this many points the default cuts its strips into tiles (default_strip_tiles).
/// 2^22: from 4 x 10^6 points square tiles were faster than plain strips on five of the
/// six realistic families and on uniform points (one thread, 16384:16 against plain
/// strips at 4 x 10^6: uniform 0.79x, poisson-disc 0.75x, tracks 0.91x, borders 0.92x,
/// lonlat 0.98x, coastline 1.13x; at 10^7 every family 0.75x to 0.97x; at 2 x 10^6 mixed,
/// 0.90x to 1.10x). Measured on 2026-12-06 with a scratch program setting strip_points
/// and strip_tiles, medians of 3 to 5 interleaved runs; docs/measurements.md, "Tiles".
/// It was 2^24, where plain strips had been measured on uniform points only.
inline constexpr std::size_t tiles_from = std::size_t{1} << 22;

/// Tiles per strip when Options::strip_tiles is 0. Below tiles_from, 1: plain strips, the
/// arrays every input up to that size has always been given (tests/delaunay/
/// golden_test.cpp pins them). From there, about sqrt(n / strip_points): strips of that
/// many tiles, and as many strips, make square tiles of points spread over a square.
/// Plain strips of 2^14 points get thin as n grows (at 10^8, 6104 of them, about 1.6
/// points across), their triangulations are mostly slivers that the merges delete, and
/// the time per point rose by 1.6x from 10^7 to 10^8; square tiles keep every piece's
/// shape, and the merges cost about the square root of their pieces (docs/measurements.md,
/// "Tiles", and docs/benchmarks.md, "Scale", for the measurements).
constexpr std::size_t default_strip_tiles(std::size_t n, std::size_t strip_points) noexcept {
    if (n < tiles_from || strip_points == 0) return 1;
    const std::size_t ratio = n / strip_points;
    std::size_t tiles = 1;
    while ((tiles + 1) * (tiles + 1) <= ratio) ++tiles;
    return tiles;
}

/// The size rule of `automatic` for n distinct points: radial below automatic_strips_from,
/// strips from there, where the shape may still choose radial (detail/curve_rule.hpp).
constexpr Strategy choose_strategy(std::size_t n, Strategy requested) noexcept {
    if (requested != Strategy::automatic) return requested;
    return n < automatic_strips_from ? Strategy::radial : Strategy::strips;
}

}  // namespace exidel::delaunay
