// exidel: the constrained triangulation of points on one line (no triangles), kernel-
// independent: part of exidel_delaunay_core, which the fuzz build links alone.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "exidel/delaunay/constrained.hpp"

namespace exidel::delaunay {

void detail::constrained_on_a_line(std::span<const Point2> points,
                                   std::span<const Segment> segments, Triangulation tri,
                                   ConstrainedTriangulation& out) {
    // tri.hull is every distinct point in lexicographic order, which is their order along
    // the line; a segment's chain is the run of it between its two ends.
    std::vector<std::uint32_t> rank(points.size(), 0);
    for (std::size_t i = 0; i < tri.hull.size(); ++i)
        rank[tri.hull[i]] = static_cast<std::uint32_t>(i);
    out.points.assign(points.begin(), points.end());
    out.input_count = points.size();
    out.chain_offsets.assign(1, 0);
    out.chain_vertices.clear();
    out.crossings.clear();
    std::vector<std::array<std::uint32_t, 2>> pieces;
    for (const Segment& s : segments) {
        const std::uint32_t a = rank[tri.vertex_of_input[s.a]], b = rank[tri.vertex_of_input[s.b]];
        const std::uint32_t step = a <= b ? 1 : static_cast<std::uint32_t>(-1);
        for (std::uint32_t i = a;; i += step) {
            out.chain_vertices.push_back(tri.hull[i]);
            if (i == b) break;
            const std::uint32_t u = tri.hull[i], v = tri.hull[i + step];
            pieces.push_back({std::min(u, v), std::max(u, v)});
        }
        out.chain_offsets.push_back(static_cast<std::uint32_t>(out.chain_vertices.size()));
    }
    std::sort(pieces.begin(), pieces.end());
    pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
    out.constraints = std::move(pieces);
    out.triangulation = std::move(tri);
}

}  // namespace exidel::delaunay
