// exidel: divide and conquer of external strips. The sorted points are cut into runs of
// consecutive positions (vertical strips, lexicographically separated); each strip is
// triangulated by the external incremental algorithm in radial order about its own
// bounding-box centre (short hull walks, few flips, and a convex curve costs O(n log n)
// instead of the lexicographic order's O(n^2)); neighbouring pieces are then merged
// pairwise by the Guibas-Stolfi zipper (merge.hpp), in a fixed merge tree. Blocks of
// strips (built and merged depth first) and the merges of one level above them are
// independent and run on `threads` threads; which thread does which job never changes
// the result, so the output is the same for every thread count.
//
// Tiles (Options::strip_tiles > 1; the default from 2^22 points, external.hpp): each strip
// is cut across by horizontal lines into tiles (tile_strip), whose points it permutes in
// place so that each tile is a run of positions; a strip's tiles are triangulated and
// merged bottom up first (the zipper in the plane turned by 90 degrees, merge.hpp), then
// the strips as above. Thin strips made mostly slivers for the merges to delete; square
// tiles do not.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/builder.hpp"
#include "exidel/delaunay/detail/memory.hpp"
#include "exidel/delaunay/detail/merge.hpp"
#include "exidel/delaunay/detail/radial.hpp"
#include "exidel/delaunay/parallel.hpp"
#include "exidel/delaunay/result.hpp"

namespace exidel::delaunay::detail {

/// Whether `pts` (distinct) lie on one line, by the kernel's orient2d against the first
/// two; fewer than three points always do.
template <PredicateKernel K>
bool all_on_one_line(std::span<const Point2> pts, const K& kernel) {
    for (std::size_t j = 2; j < pts.size(); ++j) {
        if (kernel.orient2d(pts[0], pts[1], pts[j]) != Sign::zero) return false;
    }
    return true;
}

/// Cut positions: strips [cuts[s], cuts[s+1]) of at least `target` points, each extended
/// until its points are not all collinear (by the kernel's orient2d); a collinear tail
/// joins the last strip. Returns {0, n} when no cut is possible.
template <PredicateKernel K>
std::vector<std::uint32_t> strip_cuts(std::span<const Point2> pts, std::size_t target,
                                      const K& kernel) {
    const std::size_t n = pts.size();
    target = std::max<std::size_t>(target, 3);
    std::vector<std::uint32_t> cuts{0};
    std::size_t a = 0;
    while (a < n) {
        if (n - a < 3) {  // one or two points are collinear: they join the last strip
            if (cuts.size() > 1) {
                cuts.back() = static_cast<std::uint32_t>(n);
            } else {
                cuts.push_back(static_cast<std::uint32_t>(n));
            }
            return cuts;
        }
        std::size_t b = std::min(a + target, n);
        // Points a, a+1 are distinct; the strip needs one point off their line.
        std::size_t off = a + 2;
        while (off < b && kernel.orient2d(pts[a], pts[a + 1], pts[off]) == Sign::zero) ++off;
        if (off == b) {
            while (off < n && kernel.orient2d(pts[a], pts[a + 1], pts[off]) == Sign::zero) ++off;
            b = std::min(off + 1, n);
        }
        if (off >= n && cuts.size() > 1) {
            cuts.back() = static_cast<std::uint32_t>(n);  // collinear tail: join the last strip
            return cuts;
        }
        cuts.push_back(static_cast<std::uint32_t>(b));
        a = b;
    }
    return cuts;
}

/// A strip cut across into tiles (tile_strip): tile j is positions [cuts[j], cuts[j+1]),
/// every point of a tile below every point of the next (a horizontal line between them).
/// low[j] and high[j]: tile j's smallest and largest point in the order (y, -x), where the
/// zipper starts a merge of stacked pieces (merge.hpp); first and last: the strip's
/// lexicographically smallest and largest point, where it starts a merge of strips.
struct StripTiles {
    std::vector<std::uint32_t> cuts, low, high;
    std::uint32_t first = 0, last = 0;
};

/// Working memory of tile_strip, reused from strip to strip.
struct TilingScratch {
    std::vector<std::uint32_t> count, tile_of, offset;
    std::vector<std::pair<Point2, std::uint32_t>> items;
};

/// Cuts a strip, the lexicographically sorted `pts` (not all collinear) with their
/// `input_of`, across into about `tiles` tiles of consecutive y, and writes its points and
/// input indices to `to_pts` and `to_ids` (of the same size), tile after tile, each tile
/// in lexicographic order (build_piece's requirement) and not all collinear (the
/// zipper's). Positions in the result are positions in these arrays.
///
/// Why the tiles are separated: a point's bucket is fl(fl(fl(y/2) - fl(y0/2)) * scale),
/// clamped, with y0 the strip's smallest y and scale > 0 finite. Each operation is
/// monotone in y (rounding is monotone; halving avoids the overflow of y - y0 near the
/// largest double), so a smaller bucket means a strictly smaller y, and a tile is a run of
/// consecutive buckets. Points with equal y share a bucket, hence a tile. A strip whose
/// y range leaves scale infinite or zero (all y equal, or within a few subnormals) stays
/// one tile. Tiles that came out all collinear (fewer than three points, or on one line)
/// are joined to the next tile (the last to the one before) and that union re-sorted;
/// the strip itself is not collinear, so the joining ends with at least one tile.
template <PredicateKernel K>
StripTiles tile_strip(const K& kernel, std::span<const Point2> pts,
                      std::span<const std::uint32_t> input_of, std::size_t tiles,
                      std::span<Point2> to_pts, std::span<std::uint32_t> to_ids,
                      TilingScratch& scratch) {
    StripTiles out;
    const auto m = static_cast<std::uint32_t>(pts.size());
    double y0 = pts[0].y, y1 = y0;
    for (std::uint32_t j = 0; j < m; ++j) {
        y0 = std::min(y0, pts[j].y);
        y1 = std::max(y1, pts[j].y);
    }
    tiles = std::min(tiles, std::max<std::size_t>(1, m / 3));  // a tile needs three points
    // 64 buckets per tile: tiles within about 1/64 of their target size on smooth input.
    const std::size_t buckets = 64 * std::max<std::size_t>(tiles, 1);
    const double scale = static_cast<double>(buckets) / (y1 / 2 - y0 / 2);
    const double y0_half = y0 / 2;
    const bool one_tile = tiles <= 1 || !(scale > 0) || !std::isfinite(scale);
    auto bucket = [&](double y) {
        const double f = (y / 2 - y0_half) * scale;  // in [0, buckets (1 + 2^-52)]
        return std::min(buckets - 1, static_cast<std::size_t>(f));
    };
    std::vector<std::uint32_t>& count = scratch.count;
    std::vector<std::uint32_t>& tile_of = scratch.tile_of;
    std::vector<std::uint32_t>& offset = scratch.offset;
    offset.clear();
    if (one_tile) {
        count.assign(1, 0);
        tile_of.assign(1, 0);
        offset.push_back(m);
    } else {
        count.assign(buckets, 0);
        for (std::uint32_t j = 0; j < m; ++j) ++count[bucket(pts[j].y)];
        // Consecutive buckets fill a tile up to the target; a short last tile joins the
        // one before it. (With the target rounded up, at most `tiles` tiles.)
        const std::size_t target = (m + tiles - 1) / tiles;
        tile_of.assign(buckets, 0);
        std::size_t filled = 0;
        for (std::size_t k = 0; k < buckets; ++k) {
            tile_of[k] = static_cast<std::uint32_t>(offset.size());
            filled += count[k];
            if (filled >= target) {
                offset.push_back(static_cast<std::uint32_t>(filled));
                filled = 0;
            }
        }
        if (filled > 0 && (offset.empty() || filled >= target / 2)) {
            offset.push_back(static_cast<std::uint32_t>(filled));
        } else if (filled > 0) {
            offset.back() += static_cast<std::uint32_t>(filled);
        }
        for (std::uint32_t& t : tile_of)
            t = std::min(t, static_cast<std::uint32_t>(offset.size() - 1));
    }
    // offset: tile sizes -> each tile's next free position (a stable scatter by tile).
    std::uint32_t start = 0;
    out.cuts.assign(1, 0);
    for (std::uint32_t& o : offset) {
        const std::uint32_t size = o;
        o = start;
        start += size;
        out.cuts.push_back(start);
    }
    for (std::uint32_t j = 0; j < m; ++j) {
        const std::uint32_t to = offset[one_tile ? 0 : tile_of[bucket(pts[j].y)]]++;
        to_pts[to] = pts[j];
        to_ids[to] = input_of[j];
    }
    // Join collinear tiles to their neighbours.
    auto collinear = [&](std::uint32_t lo, std::uint32_t hi) {
        return all_on_one_line(std::span<const Point2>(to_pts).subspan(lo, hi - lo), kernel);
    };
    auto resort = [&](std::uint32_t lo, std::uint32_t hi) {
        auto& items = scratch.items;
        items.clear();
        for (std::uint32_t j = lo; j < hi; ++j) items.emplace_back(to_pts[j], to_ids[j]);
        std::sort(items.begin(), items.end(),
                  [](const auto& p, const auto& q) { return cut_less(p.first, q.first, false); });
        for (std::uint32_t j = lo; j < hi; ++j) std::tie(to_pts[j], to_ids[j]) = items[j - lo];
    };
    std::vector<std::uint32_t> joined{0};
    std::size_t parts = 0;  // tiles in the union since the last kept cut
    for (std::size_t t = 1; t < out.cuts.size(); ++t) {
        ++parts;
        if (collinear(joined.back(), out.cuts[t])) continue;
        if (parts > 1) resort(joined.back(), out.cuts[t]);
        joined.push_back(out.cuts[t]);
        parts = 0;
    }
    if (joined.back() != m) {  // a collinear tail joins the last tile
        // (None kept at all only if an inexact kernel contradicts strip_cuts' answer: one
        // tile, which build_piece then reports as collinear.)
        if (joined.size() == 1) {
            joined.push_back(m);
        } else {
            joined.back() = m;
        }
        resort(joined[joined.size() - 2], m);
    }
    out.cuts = std::move(joined);
    // The start points of the merges.
    const std::size_t count_tiles = out.cuts.size() - 1;
    out.low.resize(count_tiles);
    out.high.resize(count_tiles);
    out.first = 0;
    out.last = 0;
    for (std::size_t t = 0; t < count_tiles; ++t) {
        std::uint32_t lo = out.cuts[t], hi = lo;
        for (std::uint32_t j = out.cuts[t] + 1; j < out.cuts[t + 1]; ++j) {
            if (cut_less(to_pts[j], to_pts[lo], true)) lo = j;
            if (cut_less(to_pts[hi], to_pts[j], true)) hi = j;
        }
        out.low[t] = lo;
        out.high[t] = hi;
        const std::uint32_t first = out.cuts[t], last = out.cuts[t + 1] - 1;
        if (cut_less(to_pts[first], to_pts[out.first], false)) out.first = first;
        if (cut_less(to_pts[out.last], to_pts[last], false)) out.last = last;
    }
    return out;
}

/// Triangulates positions [a, b) of `pts` (sorted lexicographically, at least three, not
/// all collinear) into the shared arrays: vertex ids are positions, triangle slots
/// [2a, 2b) (a triangulation of b - a points has at most 2 (b - a) - 5 triangles). Three points are
/// one triangle, written directly; more are triangulated in their own radial order (build_radial)
/// and copied in. `piece` receives the range and its unused slots; counters go to `into`. `work` is
/// working memory, reused from piece to piece.
struct PieceWorkspace {
    RadialIds ids;
    Mesh part;
    RadialWorkspace radial;
    TilingScratch tiling;
    FreshVector<Point2> strip_points;  // a strip being tiled, as it was sorted
    FreshVector<std::uint32_t> strip_ids;
    std::size_t cavity_pieces = 0;  // pieces whose radial run gave up (build_by_cavities)
};

template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
std::optional<Failure> build_piece(const K& kernel, std::span<const Point2> pts,
                                   std::span<const std::uint32_t> input_of, std::uint32_t a,
                                   std::uint32_t b, Mesh& mesh, Piece& piece, Counters& into,
                                   PieceWorkspace& work) {
    piece.first = a;
    piece.end = b;
    if (b - a == 3) {
        const bool ccw = kernel.orient2d(pts[a], pts[a + 1], pts[a + 2]) == Sign::positive;
        const std::uint32_t v[3] = {a, ccw ? a + 1 : a + 2, ccw ? a + 2 : a + 1};
        const std::size_t base = 6 * static_cast<std::size_t>(a);
        for (std::size_t j = 0; j < 3; ++j) {
            mesh.triangles[base + j] = v[j];
            mesh.halfedges[base + j] = -1;
            mesh.hull_next[v[j]] = v[(j + 1) % 3];
            mesh.hull_prev[v[(j + 1) % 3]] = v[j];
            mesh.hull_edge[v[j]] = static_cast<std::int32_t>(base + j);
        }
        if constexpr (I != Instrumentation::off) ++into.triangles_created;
        piece.free = {2 * a + 1, 2 * a + 2, 2 * a + 3, 2 * a + 4, 2 * a + 5};
        return std::nullopt;
    }
    const auto part_points = pts.subspan(a, b - a);
    RadialIds& ids = work.ids;
    Mesh& part = work.part;
    auto failure = build_radial<K, I, P>(kernel, part_points, input_of.subspan(a, b - a), ids, part,
                                         into, work.radial);
    if (failure) return failure;
    const std::vector<std::uint32_t>& order = ids.order;
    if (part.collinear) {
        return Failure{FailureKind::merge_inconsistent, input_of[a], a,
                       "piece [" + std::to_string(a) + ", " + std::to_string(b) +
                           ") came out collinear although a point off its line was found"};
    }
    // Local vertex j is position a + order[j], local triangle t is slot 2a + t. Both
    // builders use at most 2 (b - a) - 2 slots (the cavity insertion's sphere, ghosts
    // included, has that many triangles and reuses freed slots first); more would write
    // into the next piece's.
    if (part.triangles.size() / 3 > 2 * std::size_t{b - a}) {
        return Failure{FailureKind::merge_inconsistent, input_of[a], a,
                       "piece [" + std::to_string(a) + ", " + std::to_string(b) +
                           ") used more triangle slots than its range holds"};
    }
    const std::size_t base = 6 * static_cast<std::size_t>(a);
    for (std::size_t e = 0; e < part.triangles.size(); ++e) {
        const std::uint32_t v = part.triangles[e];
        mesh.triangles[base + e] = v == dead ? dead : a + order[v];  // dead: a free slot
        mesh.halfedges[base + e] =
            part.halfedges[e] < 0 ? -1 : part.halfedges[e] + static_cast<std::int32_t>(base);
    }
    for (std::size_t j = 0; j < order.size(); ++j) {
        const std::uint32_t g = a + order[j];
        if (part.hull_next[j] != dead) {
            mesh.hull_next[g] = a + order[part.hull_next[j]];
            mesh.hull_prev[g] = a + order[part.hull_prev[j]];
            mesh.hull_edge[g] =
                part.hull_edge[j] < 0 ? -1 : part.hull_edge[j] + static_cast<std::int32_t>(base);
        }
    }
    // Free: the part's own deleted slots (a cavity insertion's ghosts; a radial run
    // leaves none), then the slots it did not reach.
    piece.free.clear();
    for (const std::uint32_t t : part.free) piece.free.push_back(2 * a + t);
    for (std::size_t t = 2 * a + part.triangles.size() / 3; t < 2 * std::size_t{b}; ++t) {
        piece.free.push_back(static_cast<std::uint32_t>(t));
    }
    if (work.radial.gave_up) ++work.cavity_pieces;
    return std::nullopt;
}

/// Triangulates the sorted points by strips into `mesh`, over positions of `pts`: the
/// strips [cuts[s], cuts[s+1]), each cut across into about `tiles` tiles (tile_strip)
/// when `tiles` > 1. Tiles permute each strip's positions in `pts` and `input_of`
/// together (plain strips leave them as they are); `first` receives the position of the
/// lexicographically smallest point. `pieces_built`: the strips, or their tiles, that
/// were triangulated and merged. Every strip must be non-collinear (strip_cuts); a single
/// strip is only worth this with tiles (one plain strip is one radial run).
/// `erosion_limit`: each piece's RadialWorkspace::erosion_limit; `cavity_pieces` receives
/// the number of pieces that fell back to cavity insertion (a property of each piece's
/// points alone, so of the input, never of `threads`).
template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
std::optional<Failure> build_strips(const K& kernel, std::span<Point2> pts,
                                    std::span<std::uint32_t> input_of,
                                    std::span<const std::uint32_t> cuts, std::size_t tiles,
                                    unsigned threads, Mesh& mesh, std::uint32_t& first_point,
                                    Counters& counters, std::size_t& pieces_built,
                                    std::size_t erosion_limit, std::size_t& cavity_pieces) {
    const std::size_t n = pts.size();
    const std::size_t strips = cuts.size() - 1;
    mesh = Mesh{};
    assign_fresh(mesh.triangles, 6 * n, dead);
    assign_fresh(mesh.halfedges, 6 * n, -1);
    assign_fresh(mesh.hull_next, n, dead);
    assign_fresh(mesh.hull_prev, n, dead);
    assign_fresh(mesh.hull_edge, n, -1);
    std::vector<Piece> pieces(strips);
    // Each strip's lexicographically smallest and largest point, where the merges of
    // strips start: its first and last position, unless tiles permuted it.
    std::vector<std::uint32_t> first(strips), last(strips), pieces_of(strips, 1);

    auto build_strip = [&](std::size_t s, Counters& into,
                           PieceWorkspace& work) -> std::optional<Failure> {
        const std::uint32_t a = cuts[s], b = cuts[s + 1];
        if (tiles <= 1) {
            first[s] = a;
            last[s] = b - 1;
            return build_piece<K, I, P>(kernel, pts, input_of, a, b, mesh, pieces[s], into, work);
        }
        // The strip's sorted points are copied out and scattered back tile by tile.
        work.strip_points.assign(pts.begin() + a, pts.begin() + b);
        work.strip_ids.assign(input_of.begin() + a, input_of.begin() + b);
        StripTiles t = tile_strip(kernel, std::span<const Point2>(work.strip_points),
                                  std::span<const std::uint32_t>(work.strip_ids), tiles,
                                  pts.subspan(a, b - a), input_of.subspan(a, b - a), work.tiling);
        for (auto* v : {&t.cuts, &t.low, &t.high}) {
            for (std::uint32_t& j : *v) j += a;
        }
        first[s] = a + t.first;
        last[s] = a + t.last;
        // The tiles of the strip, merged bottom up in pairs like the strips (below), each
        // merge as soon as both its halves exist.
        const std::size_t count = t.cuts.size() - 1;
        pieces_of[s] = static_cast<std::uint32_t>(count);
        std::vector<Piece> stack(count);
        Merger<K, I> merger(kernel, pts, mesh);
        auto solve = [&](auto& self, std::size_t lo, std::size_t size) -> std::optional<Failure> {
            if (size == 1) {
                return build_piece<K, I, P>(kernel, pts, input_of, t.cuts[lo], t.cuts[lo + 1], mesh,
                                            stack[lo], into, work);
            }
            const std::size_t half = size / 2;
            if (auto failure = self(self, lo, half)) return failure;
            if (lo + half >= count) return std::nullopt;
            if (auto failure = self(self, lo + half, half)) return failure;
            return merger.merge(stack[lo], stack[lo + half], t.high[lo + half - 1],
                                t.low[lo + half]);
        };
        auto failure = solve(solve, 0, std::bit_ceil(count));
        into += merger.counters();
        pieces[s] = std::move(stack[0]);
        return failure;
    };

    auto merge = [&](std::size_t left, std::size_t right, Counters& into) {
        Merger<K, I> merger(kernel, pts, mesh);
        auto failure = merger.merge(pieces[left], pieces[right], last[right - 1], first[right]);
        into += merger.counters();
        return failure;
    };

    // The merge tree pairs neighbours level by level: (0,1), (2,3), ... then (0,2),
    // (4,6), ...: a node joins the two halves of an aligned block of 2^k strips. Its
    // lower levels run depth first, one block of `block` strips at a time (build two
    // strips, merge them, build the next two, ...), so that a merge finds the fans it
    // walks still in L3 rather than evicted by every later strip's build
    // (docs/measurements.md); the blocks are the parallel jobs, and the levels above them
    // run level by level. The block size
    // depends on the strip count only, never on `threads`, and failures are reported in
    // one fixed order (the first failing block, then level by level), so the result,
    // a failure included, is the same for every thread count.
    const std::size_t block = std::bit_floor(std::max<std::size_t>(1, strips / 8));
    const std::size_t blocks = (strips + block - 1) / block;
    std::vector<std::optional<Failure>> block_failures(blocks);
    std::vector<Counters> block_counters(blocks);
    std::vector<std::size_t> block_cavity_pieces(blocks, 0);
    parallel_for(blocks, threads, [&](std::size_t j) {
        Counters& into = block_counters[j];
        PieceWorkspace work;  // one per block: its strips reuse the memory
        work.radial.erosion_limit = erosion_limit;
        auto solve = [&](auto& self, std::size_t lo, std::size_t size) -> std::optional<Failure> {
            if (size == 1) return build_strip(lo, into, work);
            const std::size_t half = size / 2;
            if (auto failure = self(self, lo, half)) return failure;
            if (lo + half >= strips) return std::nullopt;
            if (auto failure = self(self, lo + half, half)) return failure;
            return merge(lo, lo + half, into);
        };
        block_failures[j] = solve(solve, j * block, block);
        block_cavity_pieces[j] = work.cavity_pieces;
    });
    cavity_pieces = 0;
    for (std::size_t j = 0; j < blocks; ++j) {
        counters += block_counters[j];
        cavity_pieces += block_cavity_pieces[j];
        if (block_failures[j]) return block_failures[j];
    }
    for (std::size_t width = block; width < strips; width *= 2) {
        const std::size_t merges = (strips + 2 * width - 1) / (2 * width);
        std::vector<std::optional<Failure>> merge_failures(merges);
        std::vector<Counters> merge_counters(merges);
        parallel_for(merges, threads, [&](std::size_t j) {
            const std::size_t left = 2 * width * j, right = left + width;
            if (right < strips) merge_failures[j] = merge(left, right, merge_counters[j]);
        });
        for (std::size_t j = 0; j < merges; ++j) {
            counters += merge_counters[j];
            if (merge_failures[j]) return merge_failures[j];
        }
    }
    first_point = first[0];
    pieces_built = 0;
    for (const std::uint32_t p : pieces_of) pieces_built += p;
    return std::nullopt;
}

}  // namespace exidel::delaunay::detail
