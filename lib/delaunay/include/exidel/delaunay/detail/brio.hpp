// exidel: insertion orders for the algorithms that locate points (bowyer-watson,
// randomized): a uniformly random permutation, and the biased randomized insertion order
// (BRIO) of Amenta, Choi and Rote ("Incremental constructions con BRIO", SoCG 2003) with
// a Hilbert curve order inside each round, as CGAL's spatial_sort and geogram do.
//
// Why BRIO: a random order keeps the expected work of incremental Delaunay insertion at
// O(n log n) whatever the input, but each point lands far from the previous one, so a
// walk from the last triangle is long and every step misses the cache. A space-filling
// curve order makes consecutive points neighbours (short walks, warm cache) but can be
// adversarial. BRIO keeps the randomness across rounds and the locality inside them:
// the points are shuffled, then cut into rounds of geometrically growing size (the last
// 7/8 of the points, the 7/8 of the rest before them, ...), and each round is sorted along
// the Hilbert curve. Amenta et al. prove the expected cost stays that of a random order.
//
// Both orders are pure functions of the points and a fixed seed, computed with integer
// arithmetic (splitmix64, Fisher-Yates, Hilbert indices of quantized coordinates), so the
// output is the same on every platform. The Hilbert key only steers locality: a poor key
// (points too close to quantize apart, a bounding box that overflows) costs time, never
// correctness.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/radix.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay::detail {

/// splitmix64 (Steele, Lea and Flood 2014): a 64-bit generator with a specified output,
/// unlike the distributions and std::shuffle of the standard library.
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() noexcept {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, bound) (bound > 0) up to a bias below bound / 2^64, immaterial for
    /// an insertion order.
    std::uint64_t below(std::uint64_t bound) noexcept { return next() % bound; }
};

/// The seed of every insertion order: fixed, so that a run is reproducible.
inline constexpr std::uint64_t order_seed = 0x65786964656c2131ull;  // "exidel!1"

/// 0, 1, ..., n-1 in a uniformly random order (Fisher-Yates).
inline std::vector<std::uint32_t> random_order(std::size_t n, std::uint64_t seed = order_seed) {
    std::vector<std::uint32_t> ids(n);
    std::iota(ids.begin(), ids.end(), 0u);
    SplitMix64 rng{seed};
    for (std::size_t i = n; i > 1; --i) {
        std::swap(ids[i - 1], ids[rng.below(i)]);
    }
    return ids;
}

/// The position of cell (x, y) along the Hilbert curve through a 2^16 x 2^16 grid (finer
/// cells would not shorten walks: 2^32 cells already hold 10^7 points thinly). At each
/// scale, from the coarsest: the cell's quadrant (visited in the order lower-left,
/// upper-left, upper-right, lower-right) is the next base-4 digit, and the finer scales
/// are read in that quadrant's own frame. The frames are the four maps "swap x and y"
/// to the power s times "complement both" to the power f, which commute, so the frame is
/// the two bits (s, f): a lower quadrant swaps, the lower-right one also complements.
/// `levels` scales from bit `level` of x and y down, starting in frame `frame` (s + 2 f):
/// the digits, and the frame left after them in bits 2 levels and up (not for all 16
/// levels: the 32 bits of digits fill the word).
constexpr std::uint32_t hilbert_steps(std::uint32_t x, std::uint32_t y, int level, int levels,
                                      std::uint32_t frame) noexcept {
    std::uint32_t d = 0, s = frame & 1, f = frame >> 1;
    for (int l = level; l > level - levels; --l) {
        std::uint32_t bx = ((x >> l) & 1) ^ f, by = ((y >> l) & 1) ^ f;
        const std::uint32_t t = (bx ^ by) & s;  // swap when s
        bx ^= t;
        by ^= t;
        d = (d << 2) | ((3 * bx) ^ by);
        s ^= 1 ^ by;         // ry == 0: swap
        f ^= bx & (1 ^ by);  // ry == 0 and rx == 1: complement
    }
    // A shift by 32 of a 32-bit word is undefined (UBSan found it in the test's 16 levels).
    return levels < 16 ? d | (s + 2 * f) << (2 * levels) : d;
}

/// hilbert_steps over four scales for every frame and every 4-bit x and y: entry
/// frame * 256 + x * 16 + y holds the 8 bits of digits and the frame after them.
inline constexpr auto hilbert_table = [] {
    std::array<std::uint16_t, 4 * 256> table{};
    for (std::uint32_t frame = 0; frame < 4; ++frame) {
        for (std::uint32_t x = 0; x < 16; ++x) {
            for (std::uint32_t y = 0; y < 16; ++y) {
                table[frame * 256 + x * 16 + y] =
                    static_cast<std::uint16_t>(hilbert_steps(x, y, 3, 4, frame));
            }
        }
    }
    return table;
}();

/// hilbert_steps over all 16 scales, four at a time through hilbert_table (a quarter of
/// the dependent steps; tests/delaunay compare it with the scale-by-scale form).
constexpr std::uint32_t hilbert_key(std::uint32_t x, std::uint32_t y) noexcept {
    std::uint32_t d = 0, frame = 0;
    for (int shift = 12; shift >= 0; shift -= 4) {
        const std::uint32_t e =
            hilbert_table[frame * 256 + ((x >> shift) & 15) * 16 + ((y >> shift) & 15)];
        d = (d << 8) | (e & 0xff);
        frame = e >> 8;
    }
    return d;
}

/// A point's Hilbert key over a bounding box of points. Halved coordinates keep the box's
/// width finite for any finite input (|x| / 2 - |y| / 2 cannot overflow).
class HilbertMap {
public:
    explicit HilbertMap(std::span<const Point2> pts) noexcept {
        for (const Point2& p : pts) {
            lo_x_ = std::min(lo_x_, p.x), hi_x_ = std::max(hi_x_, p.x);
            lo_y_ = std::min(lo_y_, p.y), hi_y_ = std::max(hi_y_, p.y);
        }
        sx_ = scale(lo_x_, hi_x_), sy_ = scale(lo_y_, hi_y_);
    }
    std::uint32_t operator()(Point2 p) const noexcept {
        return hilbert_key(cell((p.x * 0.5 - lo_x_ * 0.5) * sx_),
                           cell((p.y * 0.5 - lo_y_ * 0.5) * sy_));
    }

private:
    static constexpr double cells = 65535.0;  // 2^16 - 1
    static double scale(double lo, double hi) noexcept {
        const double w = hi * 0.5 - lo * 0.5;
        return w > 0 && std::isfinite(w) ? cells / w : 0.0;
    }
    static std::uint32_t cell(double v) noexcept {  // NaN and out-of-range values clamp
        if (!(v > 0)) return 0;
        return v >= cells ? static_cast<std::uint32_t>(cells) : static_cast<std::uint32_t>(v);
    }
    double lo_x_ = INFINITY, lo_y_ = INFINITY, hi_x_ = -INFINITY, hi_y_ = -INFINITY;
    double sx_ = 0, sy_ = 0;
};

/// Hilbert keys of the points over their bounding box.
inline std::vector<std::uint32_t> hilbert_keys(std::span<const Point2> pts) {
    const HilbertMap key(pts);
    std::vector<std::uint32_t> keys(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) keys[i] = key(pts[i]);
    return keys;
}

/// The points' indices along the Hilbert curve over their bounding box (stably sorted
/// (key, index) records), for the batch queries that take their points in curve order.
inline FreshVector<KeyIndex> hilbert_sorted(std::span<const Point2> pts) {
    const HilbertMap key(pts);
    FreshVector<KeyIndex> sorted(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
        sorted[i] = {key(pts[i]), static_cast<std::uint32_t>(i)};
    radix_sort(sorted);
    return sorted;
}

/// BRIO: a random order, cut into rounds, each round sorted along the Hilbert curve. The
/// last round holds the last 7/8 of the points, the one before it 7/8 of the rest, and
/// so on down to a first round of at most `first_round` points (Amenta et al. use
/// halves; CGAL's multiscale sort uses this ratio of 1/8, which keeps more locality).
inline std::vector<std::uint32_t> brio_order(std::span<const Point2> pts,
                                             std::uint64_t seed = order_seed) {
    constexpr std::size_t first_round = 64;
    std::vector<std::uint32_t> ids = random_order(pts.size(), seed);
    const std::vector<std::uint32_t> keys = hilbert_keys(pts);
    std::vector<KeyIndex> round;
    for (std::size_t end = ids.size(); end > 0;) {
        const std::size_t begin = end <= first_round ? 0 : end / 8;
        round.clear();
        for (std::size_t j = begin; j < end; ++j) round.push_back({keys[ids[j]], ids[j]});
        radix_sort(round);
        for (std::size_t j = begin; j < end; ++j) ids[j] = round[j - begin].index;
        end = begin;
    }
    return ids;
}

}  // namespace exidel::delaunay::detail
