// exidel: another producer's triangulation in the certifier's layout (certify.hpp,
// normalize). Every decision here is exact: orientations by the adaptive kernel's
// orient2d, equal points by equal coordinates.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>

#include "exidel/delaunay/certify.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::delaunay {

std::vector<std::string> Normalization::notes() const {
    std::vector<std::string> n;
    const auto count = [](std::size_t k, const char* one, const char* many) {
        return std::to_string(k) + " " + (k == 1 ? one : many);
    };
    if (copies_renamed) {
        n.push_back(count(copies_renamed, "vertex entry named a later copy of a repeated point",
                          "vertex entries named a later copy of a repeated point") +
                    ": renamed to its first occurrence");
    }
    if (reoriented) {
        n.push_back(count(reoriented, "clockwise triangle", "clockwise triangles") +
                    " turned counter-clockwise");
    }
    if (twins_derived) n.push_back("no halfedges given: twins matched from the triangles");
    if (hull_derived) n.push_back("no hull given: the boundary cycle is taken as the hull");
    if (hull_reversed) n.push_back("the hull ran clockwise (or backwards): reversed");
    if (hull_rotated)
        n.push_back("the hull started elsewhere: rotated to start at its smallest point");
    return n;
}

namespace {

using K = AdaptiveKernel;

bool lex_less(Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// vertex_of_input (each input index -> the smallest index with its coordinates), and the
// distinct points in lexicographic order.
std::vector<std::uint32_t> first_occurrences(std::span<const Point2> p,
                                             std::vector<std::uint32_t>& chain) {
    std::vector<std::uint32_t> order(p.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return p[a] == p[b] ? a < b : lex_less(p[a], p[b]);
    });
    std::vector<std::uint32_t> first(p.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::uint32_t i = order[k];
        if (k > 0 && p[order[k - 1]] == p[i]) {
            first[i] = first[order[k - 1]];
        } else {
            first[i] = i;
            chain.push_back(i);
        }
    }
    return first;
}

// Twins by matching reversed edges: a -> b with b -> a, when each runs exactly once (and
// in two different triangles). The half-edges sorted by their undirected edge, then by
// direction, put the two of an edge next to each other: one sort, no hashing (a hash
// map of every half-edge was most of certifying a peer's 2 * 10^6 triangles).
std::vector<std::int32_t> match_twins(const std::vector<std::uint32_t>& T) {
    const std::size_t n = T.size() - T.size() % 3;
    std::vector<std::int32_t> H(T.size(), -1);
    struct Entry {
        std::uint64_t edge;  // min << 32 | max
        std::uint32_t e;
        bool forward;  // runs min -> max
    };
    std::vector<Entry> entries(n);
    for (std::size_t e = 0; e < n; ++e) {
        const std::uint64_t a = T[e], b = T[next_halfedge(e)];
        entries[e] = {std::min(a, b) << 32 | std::max(a, b), static_cast<std::uint32_t>(e), a < b};
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
        return x.edge != y.edge ? x.edge < y.edge : x.forward < y.forward;
    });
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i;
        while (j < n && entries[j].edge == entries[i].edge) ++j;
        // Exactly one backward and one forward half-edge, in different triangles.
        if (j - i == 2 && !entries[i].forward && entries[i + 1].forward &&
            entries[i].e / 3 != entries[i + 1].e / 3) {
            H[entries[i].e] = static_cast<std::int32_t>(entries[i + 1].e);
            H[entries[i + 1].e] = static_cast<std::int32_t>(entries[i].e);
        }
        i = j;
    }
    return H;
}

// The boundary (twin-less half-edges) followed from its lexicographically smallest
// vertex; stops where it does not continue or returns (the certifier reports why).
std::vector<std::uint32_t> boundary_cycle(std::span<const Point2> p,
                                          const std::vector<std::uint32_t>& T,
                                          const std::vector<std::int32_t>& H) {
    const std::size_t n = std::min(T.size() - T.size() % 3, H.size());
    std::unordered_map<std::uint32_t, std::uint32_t> next;  // start vertex -> end vertex
    std::int64_t first = -1;
    for (std::size_t e = 0; e < n; ++e) {
        if (H[e] >= 0 || T[e] >= p.size() || T[next_halfedge(e)] >= p.size()) continue;
        next.emplace(T[e], T[next_halfedge(e)]);
        if (first < 0 || lex_less(p[T[e]], p[static_cast<std::size_t>(first)])) first = T[e];
    }
    std::vector<std::uint32_t> cycle;
    if (first < 0) return cycle;
    auto v = static_cast<std::uint32_t>(first);
    while (cycle.size() <= next.size()) {
        cycle.push_back(v);
        const auto it = next.find(v);
        if (it == next.end() || it->second == cycle.front()) break;
        v = it->second;
    }
    return cycle;
}

}  // namespace

Triangulation normalize(std::span<const Point2> points, ProducedTriangulation produced,
                        Normalization* what, bool strict) {
    Normalization did;
    Triangulation t;
    const std::size_t N = points.size();
    std::vector<std::uint32_t> chain;
    t.vertex_of_input = first_occurrences(points, chain);
    if (produced.duplicates) {
        t.duplicates = std::move(*produced.duplicates);
    } else {
        for (std::uint32_t i = 0; i < N; ++i) {
            if (t.vertex_of_input[i] != i) t.duplicates.push_back(i);
        }
    }
    const auto rename = [&](std::uint32_t& v) {
        if (!strict && v < N && t.vertex_of_input[v] != v) {
            v = t.vertex_of_input[v];
            ++did.copies_renamed;
        }
    };
    t.triangles = std::move(produced.triangles);
    for (std::uint32_t& v : t.triangles) rename(v);
    std::vector<std::uint32_t> hull;
    if (produced.hull) {
        hull = std::move(*produced.hull);
        for (std::uint32_t& v : hull) rename(v);
    }

    if (t.triangles.empty()) {
        // No triangles: the claim is that the points are collinear, and the hull the chain.
        t.collinear = true;
        if (produced.halfedges) t.halfedges = std::move(*produced.halfedges);
        if (!produced.hull) {
            t.hull = std::move(chain);
            did.hull_derived = true;
        } else {
            if (!strict && hull != chain &&
                std::equal(hull.rbegin(), hull.rend(), chain.begin(), chain.end())) {
                std::reverse(hull.begin(), hull.end());
                did.hull_reversed = true;
            }
            t.hull = std::move(hull);
        }
        if (what) *what = did;
        return t;
    }

    // Clockwise triangles turned; flipped[t] remembers which, for their twins.
    const std::size_t nt = t.triangles.size() / 3;
    std::vector<std::uint8_t> flipped(nt, 0);
    for (std::size_t i = 0; i < (strict ? 0 : nt); ++i) {
        std::uint32_t* v = &t.triangles[3 * i];
        if (v[0] >= N || v[1] >= N || v[2] >= N) continue;
        if (K::orient2d(points[v[0]], points[v[1]], points[v[2]]) == Sign::negative) {
            std::swap(v[1], v[2]);
            flipped[i] = 1;
            ++did.reoriented;
        }
    }
    if (produced.halfedges) {
        std::vector<std::int32_t>& H = *produced.halfedges;
        if (did.reoriented && H.size() == t.triangles.size()) {
            // Half-edge k of a turned triangle (a, b, c) is half-edge 2 - k of (a, c, b).
            const auto moved = [&](std::size_t e) {
                return flipped[e / 3] ? 3 * (e / 3) + 2 - e % 3 : e;
            };
            t.halfedges.assign(H.size(), -1);
            for (std::size_t e = 0; e < H.size(); ++e) {
                const std::int32_t h = H[e];
                const bool valid = h >= 0 && static_cast<std::size_t>(h) < H.size();
                t.halfedges[moved(e)] =
                    valid ? static_cast<std::int32_t>(moved(static_cast<std::size_t>(h))) : h;
            }
        } else {
            t.halfedges = std::move(H);
        }
    } else {
        t.halfedges = match_twins(t.triangles);
        did.twins_derived = true;
    }

    if (!produced.hull) {
        t.hull = boundary_cycle(points, t.triangles, t.halfedges);
        did.hull_derived = true;
    } else {
        const bool in_range =
            std::all_of(hull.begin(), hull.end(), [&](std::uint32_t v) { return v < N; });
        if (!strict && in_range && hull.size() >= 3) {
            const auto smallest = [&] {
                return std::min_element(hull.begin(), hull.end(), [&](auto a, auto b) {
                    return lex_less(points[a], points[b]);
                });
            };
            auto j = static_cast<std::size_t>(smallest() - hull.begin());
            const std::size_t h = hull.size();
            if (K::orient2d(points[hull[(j + h - 1) % h]], points[hull[j]],
                            points[hull[(j + 1) % h]]) == Sign::negative) {
                std::reverse(hull.begin(), hull.end());
                did.hull_reversed = true;
                j = static_cast<std::size_t>(smallest() - hull.begin());
            }
            if (j != 0) {
                std::rotate(hull.begin(), hull.begin() + static_cast<std::ptrdiff_t>(j),
                            hull.end());
                did.hull_rotated = true;
            }
        }
        t.hull = std::move(hull);
    }
    if (what) *what = did;
    return t;
}

}  // namespace exidel::delaunay
