// exidel: the regions of a constrained triangulation (regions.hpp says what they are).
#include "exidel/delaunay/regions.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <utility>
#include <vector>

#include "exidel/delaunay/locate.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::delaunay {

namespace {

/// The pieces of every chain as directed edges (u, w), sorted by their undirected key:
/// crossing(a, b) sums them over the edge a - b.
class PieceTable {
public:
    explicit PieceTable(const ConstrainedTriangulation& cdt) {
        const auto& c = cdt.chain_vertices;
        for (std::size_t s = 0; s + 1 < cdt.chain_offsets.size(); ++s) {
            for (std::size_t j = cdt.chain_offsets[s]; j + 1 < cdt.chain_offsets[s + 1]; ++j) {
                const std::uint32_t u = c[j], w = c[j + 1];
                if (u != w) pieces_.push_back({std::min(u, w), std::max(u, w), u < w ? 1 : -1});
            }
        }
        std::sort(pieces_.begin(), pieces_.end());
    }
    struct Crossing {
        std::uint32_t count = 0;  ///< pieces on the edge
        std::int32_t turn = 0;    ///< the winding number's change
    };
    /// Crossing edge a -> b from the triangle on its left to the one on its right: each
    /// piece a -> b is crossed from its left to its right (-1), each piece b -> a from its
    /// right to its left (+1).
    Crossing crossing(std::uint32_t a, std::uint32_t b) const {
        const std::array<std::int64_t, 3> key{std::min(a, b), std::max(a, b),
                                              std::numeric_limits<std::int64_t>::min()};
        Crossing x;
        for (auto it = std::lower_bound(pieces_.begin(), pieces_.end(), key);
             it != pieces_.end() && (*it)[0] == key[0] && (*it)[1] == key[1]; ++it) {
            ++x.count;
            // (*it)[2] is +1 for a piece from the smaller vertex to the larger.
            const bool along = ((*it)[2] > 0) == (a < b);
            x.turn += along ? -1 : 1;
        }
        return x;
    }
    bool empty() const noexcept { return pieces_.empty(); }

private:
    std::vector<std::array<std::int64_t, 3>> pieces_;
};

}  // namespace

std::vector<std::uint32_t> Regions::inside_triangles() const {
    std::vector<std::uint32_t> out;
    for (std::size_t t = 0; t < inside.size(); ++t)
        if (inside[t] != 0) out.push_back(static_cast<std::uint32_t>(t));
    return out;
}

Regions classify_regions(const ConstrainedTriangulation& cdt, const RegionOptions& options) {
    const Triangulation& tri = cdt.triangulation;
    const std::size_t n = tri.triangles.size() / 3;
    Regions r;
    r.region.assign(n, 0);
    r.depth.assign(n, std::numeric_limits<std::uint32_t>::max());
    r.winding.assign(n, 0);
    r.inside.assign(n, 0);
    if (n == 0) {
        r.unplaced_holes.resize(options.holes.size());
        for (std::size_t i = 0; i < options.holes.size(); ++i) r.unplaced_holes[i] = i;
        return r;
    }
    const PieceTable table(cdt);
    const auto from = [&](std::size_t e) { return tri.triangles[e]; };
    const auto to = [&](std::size_t e) { return tri.triangles[e % 3 == 2 ? e - 2 : e + 1]; };

    // Dijkstra from outside: every triangle with a hull edge starts at the crossing of that
    // edge from the outside (on its right) into the triangle (on its left).
    using Entry = std::pair<std::uint32_t, std::uint32_t>;  // (depth, triangle)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t e = 0; e < tri.halfedges.size(); ++e) {
        if (tri.halfedges[e] >= 0) continue;
        const PieceTable::Crossing x = table.crossing(to(e), from(e));
        const std::size_t t = e / 3;
        if (x.count < r.depth[t]) {
            r.depth[t] = x.count;
            r.winding[t] = x.turn;
            queue.push({x.count, static_cast<std::uint32_t>(t)});
        }
    }
    std::vector<std::uint8_t> done(n, 0);
    while (!queue.empty()) {
        const auto [d, t] = queue.top();
        queue.pop();
        if (done[t] != 0 || d != r.depth[t]) continue;
        done[t] = 1;
        for (std::size_t e = 3 * std::size_t{t}; e < 3 * std::size_t{t} + 3; ++e) {
            const std::int32_t f = tri.halfedges[e];
            if (f < 0) continue;
            const std::size_t u = static_cast<std::size_t>(f) / 3;
            if (done[u] != 0) continue;
            const PieceTable::Crossing x = table.crossing(from(e), to(e));
            if (d + x.count < r.depth[u]) {
                r.depth[u] = d + x.count;
                r.winding[u] = r.winding[t] + x.turn;
                queue.push({r.depth[u], static_cast<std::uint32_t>(u)});
            }
        }
    }
    // Closed curves: the winding numbers agree across every edge and the hull.
    for (std::size_t e = 0; e < tri.halfedges.size() && r.closed; ++e) {
        const std::int32_t f = tri.halfedges[e];
        const std::int32_t here = r.winding[e / 3];
        if (f < 0) {
            r.closed = here == table.crossing(to(e), from(e)).turn;
        } else {
            const std::int32_t there = r.winding[static_cast<std::size_t>(f) / 3];
            r.closed = there == here + table.crossing(from(e), to(e)).turn;
        }
    }
    for (std::size_t t = 0; t < n; ++t) {
        switch (options.rule) {
            case FillRule::even_odd: r.inside[t] = r.depth[t] % 2 == 1; break;
            case FillRule::non_zero: r.inside[t] = r.winding[t] != 0; break;
            case FillRule::enclosed: r.inside[t] = r.depth[t] > 0; break;
            case FillRule::all: r.inside[t] = 1; break;
        }
    }

    // Regions: flood fill without crossing a piece.
    constexpr std::uint32_t unset = std::numeric_limits<std::uint32_t>::max();
    std::fill(r.region.begin(), r.region.end(), unset);
    std::vector<std::uint32_t> stack;
    const auto flood = [&](std::uint32_t start, std::uint32_t label) {
        stack.assign(1, start);
        r.region[start] = label;
        while (!stack.empty()) {
            const std::uint32_t t = stack.back();
            stack.pop_back();
            for (std::size_t e = 3 * std::size_t{t}; e < 3 * std::size_t{t} + 3; ++e) {
                const std::int32_t f = tri.halfedges[e];
                if (f < 0) continue;
                const auto u = static_cast<std::uint32_t>(f / 3);
                if (r.region[u] != unset || table.crossing(from(e), to(e)).count != 0) continue;
                r.region[u] = label;
                stack.push_back(u);
            }
        }
    };
    for (std::uint32_t t = 0; t < n; ++t)
        if (r.region[t] == unset) flood(t, r.region_count++);

    // Seeds (holes, attributes): the region holding each, or none when it lies outside the
    // hull, exactly on a piece or a vertex, or is not a point.
    std::optional<Locator<AdaptiveKernel>> locator;
    const auto region_of = [&](Point2 q) -> std::optional<std::uint32_t> {
        if (!locator) locator.emplace(cdt.points, tri);
        Location at;
        try {
            at = locator->locate(q);
        } catch (const FailureError&) {
            return std::nullopt;  // a NaN or infinite seed
        }
        bool placed = false;
        if (at.kind == LocationKind::inside) {
            placed = true;
        } else if (at.kind == LocationKind::on_edge) {
            // On an edge that is no piece, both triangles are in one region.
            const auto e = static_cast<std::size_t>(at.edge);
            placed = table.crossing(from(e), to(e)).count == 0;
        }
        if (!placed || at.triangle < 0) return std::nullopt;
        return r.region[static_cast<std::size_t>(at.triangle)];
    };
    // Hole seeds remove their region.
    if (!options.holes.empty()) {
        std::vector<std::uint8_t> removed(r.region_count, 0);
        for (std::size_t i = 0; i < options.holes.size(); ++i) {
            const std::optional<std::uint32_t> g = region_of(options.holes[i]);
            if (g)
                removed[*g] = 1;
            else
                r.unplaced_holes.push_back(i);
        }
        for (std::size_t t = 0; t < n; ++t)
            if (removed[r.region[t]] != 0) r.inside[t] = 0;
    }
    // Regional attributes label their region; a later seed in the same region overrides.
    if (!options.attributes.empty()) {
        std::vector<double> of_region(r.region_count, 0.0);
        for (std::size_t i = 0; i < options.attributes.size(); ++i) {
            const std::optional<std::uint32_t> g = region_of(options.attributes[i].seed);
            if (g)
                of_region[*g] = options.attributes[i].attribute;
            else
                r.unplaced_attributes.push_back(i);
        }
        r.attribute.resize(n);
        for (std::size_t t = 0; t < n; ++t) r.attribute[t] = of_region[r.region[t]];
    }
    return r;
}

}  // namespace exidel::delaunay
