// exidel: divide and conquer of external strips. The sorted points are cut into runs of
// consecutive positions (vertical strips, lexicographically separated); each strip is
// triangulated by the external incremental algorithm in radial order about its own
// bounding-box centre (short hull walks, few flips, and a convex curve costs O(n log n)
// instead of the lexicographic order's O(n^2)); neighbouring pieces are then merged
// pairwise by the Guibas-Stolfi zipper (merge.hpp), in a fixed merge tree. Blocks of
// strips (built and merged depth first) and the merges of one level above them are
// independent and run on `threads` threads; which thread does which job never changes
// the result, so the output is the same for every thread count.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exidel/delaunay/detail/builder.hpp"
#include "exidel/delaunay/detail/memory.hpp"
#include "exidel/delaunay/detail/merge.hpp"
#include "exidel/delaunay/detail/radial.hpp"
#include "exidel/delaunay/parallel.hpp"
#include "exidel/delaunay/result.hpp"

namespace exidel::delaunay::detail {

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

/// Triangulates positions [a, b) of `pts` (sorted lexicographically, at least three, not
/// all collinear) into the shared arrays: vertex ids are positions, triangle slots
/// [2a, 2b) (a triangulation of b - a points has at most 2 (b - a) - 5 triangles). Three points are one triangle,
/// written directly; more are triangulated in their own radial order (build_radial) and
/// copied in. `piece` receives the range and its unused slots; counters go to `into`.
/// `work` is working memory, reused from piece to piece.
struct PieceWorkspace {
    RadialIds ids;
    Mesh part;
    RadialWorkspace radial;
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
    auto failure = build_radial<K, I, P>(kernel, part_points, input_of.subspan(a, b - a), ids,
                                         part, into, work.radial);
    if (failure) return failure;
    const std::vector<std::uint32_t>& order = ids.order;
    if (part.collinear) {
        return Failure{FailureKind::merge_inconsistent, input_of[a], a,
                       "piece [" + std::to_string(a) + ", " + std::to_string(b) +
                           ") came out collinear although a point off its line was found"};
    }
    // Local vertex j is position a + order[j], local triangle t is slot 2a + t.
    const std::size_t base = 6 * static_cast<std::size_t>(a);
    for (std::size_t e = 0; e < part.triangles.size(); ++e) {
        mesh.triangles[base + e] = a + order[part.triangles[e]];
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
    piece.free.clear();
    for (std::size_t t = 2 * a + part.triangles.size() / 3; t < 2 * std::size_t{b}; ++t) {
        piece.free.push_back(static_cast<std::uint32_t>(t));
    }
    return std::nullopt;
}

/// Triangulates the sorted points by strips into `mesh` (over sorted positions). With a
/// single strip, returns std::nullopt with mesh.collinear possibly set, as Builder does.
template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
std::optional<Failure> build_strips(const K& kernel, std::span<const Point2> pts,
                                    std::span<const std::uint32_t> input_of,
                                    std::span<const std::uint32_t> cuts, unsigned threads,
                                    Mesh& mesh, Counters& counters) {
    const std::size_t n = pts.size();
    const std::size_t strips = cuts.size() - 1;
    mesh = Mesh{};
    assign_fresh(mesh.triangles, 6 * n, dead);
    assign_fresh(mesh.halfedges, 6 * n, -1);
    assign_fresh(mesh.hull_next, n, dead);
    assign_fresh(mesh.hull_prev, n, dead);
    assign_fresh(mesh.hull_edge, n, -1);
    std::vector<Piece> pieces(strips);

    auto build_strip = [&](std::size_t s, Counters& into, PieceWorkspace& work) {
        return build_piece<K, I, P>(kernel, pts, input_of, cuts[s], cuts[s + 1], mesh, pieces[s],
                                    into, work);
    };

    auto merge = [&](std::size_t left, std::size_t right, Counters& into) {
        Merger<K, I> merger(kernel, pts, mesh);
        auto failure = merger.merge(pieces[left], pieces[right]);
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
    parallel_for(blocks, threads, [&](std::size_t j) {
        Counters& into = block_counters[j];
        PieceWorkspace work;  // one per block: its strips reuse the memory
        auto solve = [&](auto& self, std::size_t lo, std::size_t size) -> std::optional<Failure> {
            if (size == 1) return build_strip(lo, into, work);
            const std::size_t half = size / 2;
            if (auto failure = self(self, lo, half)) return failure;
            if (lo + half >= strips) return std::nullopt;
            if (auto failure = self(self, lo + half, half)) return failure;
            return merge(lo, lo + half, into);
        };
        block_failures[j] = solve(solve, j * block, block);
    });
    for (std::size_t j = 0; j < blocks; ++j) {
        counters += block_counters[j];
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
    return std::nullopt;
}

}  // namespace exidel::delaunay::detail
