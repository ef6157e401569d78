// exidel: the finished mesh as a Triangulation of input indices.
#include "exidel/delaunay/detail/mesh.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "exidel/delaunay/detail/memory.hpp"
#include "exidel/delaunay/parallel.hpp"

namespace exidel::delaunay::detail {

std::optional<Failure> to_triangulation(Mesh& mesh, std::span<const std::uint32_t> input_of,
                                        std::uint32_t first, Triangulation& tri, unsigned threads) {
    auto& tris = mesh.triangles;
    auto& half = mesh.halfedges;
    // Compact: live triangles keep their relative order, in fixed chunks of slots on
    // `threads` threads. Each chunk first packs its live slots, already renumbered, at
    // its own start (new positions inside a chunk never pass old ones, so the copy runs
    // forwards in place); then the packed blocks move down to their final place in chunk
    // order, where each lands on slots already read.
    constexpr std::size_t chunk = std::size_t{1} << 15;
    const std::size_t slots = tris.size() / 3;
    const std::size_t chunks = (slots + chunk - 1) / chunk;
    auto chunk_end = [&](std::size_t c) { return std::min(slots, (c + 1) * chunk); };
    std::vector<std::size_t> base(chunks + 1, 0);  // live slots before chunk c
    parallel_for(chunks, threads, [&](std::size_t c) {
        std::size_t live = 0;
        for (std::size_t t = c * chunk; t < chunk_end(c); ++t) live += tris[3 * t] != dead;
        base[c + 1] = live;
    });
    for (std::size_t c = 0; c < chunks; ++c) base[c + 1] += base[c];
    const std::size_t live = base[chunks];
    FreshVector<std::uint32_t> new_slot;
    resize_fresh(new_slot, slots);
    parallel_for(chunks, threads, [&](std::size_t c) {
        auto u = static_cast<std::uint32_t>(base[c]);
        for (std::size_t t = c * chunk; t < chunk_end(c); ++t) {
            new_slot[t] = tris[3 * t] != dead ? u++ : dead;
        }
    });
    std::vector<std::int32_t> lost(chunks, -1);  // per chunk, the first half-edge whose
                                                 // neighbour was destroyed
    parallel_for(chunks, threads, [&](std::size_t c) {
        std::size_t u = c * chunk;
        for (std::size_t t = c * chunk; t < chunk_end(c); ++t) {
            if (new_slot[t] == dead) continue;
            for (std::size_t j = 0; j < 3; ++j) {
                const std::int32_t h = half[3 * t + j];
                tris[3 * u + j] = input_of[tris[3 * t + j]];
                if (h >= 0 && new_slot[static_cast<std::size_t>(h) / 3] == dead) {
                    lost[c] = h;
                    return;
                }
                half[3 * u + j] =
                    h < 0
                        ? -1
                        : static_cast<std::int32_t>(3 * new_slot[static_cast<std::size_t>(h) / 3] +
                                                    static_cast<std::size_t>(h) % 3);
            }
            ++u;
        }
    });
    for (const std::int32_t h : lost) {
        if (h >= 0) {
            return Failure{
                FailureKind::result_inconsistent, no_index, no_index,
                "a triangle's neighbour across half-edge " + std::to_string(h) + " was destroyed"};
        }
    }
    for (std::size_t c = 0; c < chunks; ++c) {
        const std::size_t count = 3 * (base[c + 1] - base[c]);
        if (base[c] == c * chunk || count == 0) continue;  // already in place
        std::memmove(tris.data() + 3 * base[c], tris.data() + 3 * c * chunk,
                     count * sizeof(tris[0]));
        std::memmove(half.data() + 3 * base[c], half.data() + 3 * c * chunk,
                     count * sizeof(half[0]));
    }
    tris.resize(3 * live);
    half.resize(3 * live);
    tri.triangles = std::move(tris);
    tri.halfedges = std::move(half);
    // The hull cycle, bounded: a broken cycle is reported, never walked forever.
    tri.hull.clear();
    std::uint32_t v = first;
    do {
        if (tri.hull.size() >= mesh.hull_next.size() || v >= mesh.hull_next.size()) {
            return Failure{FailureKind::result_inconsistent, no_index, no_index,
                           "the hull cycle does not close"};
        }
        tri.hull.push_back(input_of[v]);
        v = mesh.hull_next[v];
    } while (v != first);
    return std::nullopt;
}

}  // namespace exidel::delaunay::detail
