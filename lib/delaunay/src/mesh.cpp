// exidel: the finished mesh as a Triangulation of input indices.
#include "exidel/delaunay/detail/mesh.hpp"

#include <string>

namespace exidel::delaunay::detail {

std::optional<Failure> to_triangulation(Mesh& mesh, std::span<const std::uint32_t> input_of,
                                        std::uint32_t first, Triangulation& tri) {
    auto& tris = mesh.triangles;
    auto& half = mesh.halfedges;
    // Compact: live triangles keep their relative order. new_slot[t] <= t, so copying
    // forwards in place never overwrites a slot still to be read.
    const std::size_t slots = tris.size() / 3;
    std::vector<std::uint32_t> new_slot(slots, dead);
    std::size_t live = 0;
    for (std::size_t t = 0; t < slots; ++t) {
        if (tris[3 * t] != dead) new_slot[t] = static_cast<std::uint32_t>(live++);
    }
    for (std::size_t t = 0; t < slots; ++t) {
        if (new_slot[t] == dead) continue;
        const std::size_t u = new_slot[t];
        for (std::size_t j = 0; j < 3; ++j) {
            const std::int32_t h = half[3 * t + j];
            tris[3 * u + j] = input_of[tris[3 * t + j]];
            if (h >= 0 && new_slot[static_cast<std::size_t>(h) / 3] == dead) {
                return Failure{FailureKind::result_inconsistent, no_index, no_index,
                               "a triangle's neighbour across half-edge " + std::to_string(h) +
                                   " was destroyed"};
            }
            half[3 * u + j] = h < 0 ? -1
                                    : static_cast<std::int32_t>(
                                          3 * new_slot[static_cast<std::size_t>(h) / 3] +
                                          static_cast<std::size_t>(h) % 3);
        }
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
