// exidel: the Voronoi diagram's kernel-independent work (voronoi.hpp).
#include "exidel/delaunay/voronoi.hpp"

#include "exidel/delaunay/parallel.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>
#include <utility>

namespace exidel::delaunay {
namespace detail {

namespace {

bool same_bits(Point2 a, Point2 b) noexcept {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y);
}

/// b - a, rounded: each component has the exact difference's sign. A difference that
/// overflows is taken of the halves instead (exact: such coordinates are huge).
double difference(double b, double a) noexcept {
    const double d = b - a;
    return std::isfinite(d) ? d : b / 2 - a / 2;
}

/// The outward normal of hull edge p -> q (counter-clockwise hull: the inside is on the
/// left), exact in sign.
Point2 outward_normal(Point2 p, Point2 q) noexcept {
    return {difference(q.y, p.y), -difference(q.x, p.x)};
}

/// For every first occurrence, its duplicates (input order), as offsets into one array.
struct Duplicates {
    std::vector<std::uint32_t> offsets, items;
    Duplicates(const Triangulation& t, std::size_t n) : offsets(n + 1, 0) {
        for (const std::uint32_t d : t.duplicates) ++offsets[t.vertex_of_input[d] + 1];
        std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
        items.resize(t.duplicates.size());
        std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
        for (const std::uint32_t d : t.duplicates) items[fill[t.vertex_of_input[d]]++] = d;
    }
    /// Appends site s and then its duplicates.
    void append(std::uint32_t s, std::vector<std::uint32_t>& out) const {
        out.push_back(s);
        if (items.empty()) return;  // no duplicates: skip the lookup (a cache miss per site)
        out.insert(out.end(), items.begin() + offsets[s], items.begin() + offsets[s + 1]);
    }
};

}  // namespace

/// Pieces of the parallel loops: enough to balance two threads, few enough that a job is
/// long next to handing it out. The output never depends on the thread count.
constexpr std::size_t parallel_pieces = 64;

VoronoiBuilder::VoronoiBuilder(std::span<const Point2> points, const Triangulation& t,
                               unsigned threads)
    : points_(points),
      t_(t),
      threads_(threads),
      centres_(t.triangle_count()),
      parent_(t.triangle_count()) {
    const std::size_t count = centres_.size();
    const std::size_t pieces = std::min(parallel_pieces, std::max<std::size_t>(count / 4096, 1));
    std::vector<std::array<std::uint64_t, 3>> stages(pieces);
    parallel_for(pieces, threads, [&](std::size_t j) {
        const std::size_t begin = count * j / pieces, end = count * (j + 1) / pieces;
        circumcenters(points, std::span(t.triangles).subspan(3 * begin, 3 * (end - begin)),
                      std::span(centres_).subspan(begin, end - begin), stages[j].data());
    });
    for (const auto& piece : stages)
        for (int k = 0; k < 3; ++k) stage_counts_[k] += piece[k];
    for (std::size_t i = 0; i < centres_.size(); ++i) {
        if (centres_[i].ok()) continue;
        const std::uint32_t* v = &t.triangles[3 * i];
        throw VoronoiError(
            i, centres_[i].status,
            "the Voronoi vertex of Delaunay triangle (" + std::to_string(v[0]) + ", " +
                std::to_string(v[1]) + ", " + std::to_string(v[2]) + ") is not a finite point: " +
                (centres_[i].status == CircumcenterStatus::overflow
                     ? "its exact centre is beyond the largest double"
                     : "the triangle is " + std::string(to_string(centres_[i].status))));
    }
    std::iota(parent_.begin(), parent_.end(), 0u);
    for (std::size_t e = 0; e < t.halfedges.size(); ++e) {
        const std::int32_t twin = t.halfedges[e];
        if (twin <= static_cast<std::int32_t>(e)) continue;  // boundary, or seen from the twin
        if (same_bits(centres_[e / 3].point, centres_[static_cast<std::size_t>(twin) / 3].point))
            candidates_.push_back(static_cast<std::uint32_t>(e));
    }
}

void VoronoiBuilder::incircle_query(std::uint32_t e, Point2 q[4]) const noexcept {
    const std::size_t t = e / 3;
    for (int k = 0; k < 3; ++k) q[k] = points_[t_.triangles[3 * t + k]];
    const auto twin = static_cast<std::size_t>(t_.halfedges[e]);
    q[3] = points_[t_.triangles[prev_halfedge(twin)]];
}

std::uint32_t VoronoiBuilder::find(std::uint32_t t) noexcept {
    while (parent_[t] != t) {
        parent_[t] = parent_[parent_[t]];
        t = parent_[t];
    }
    return t;
}

void VoronoiBuilder::merge(std::uint32_t e) noexcept {
    const std::uint32_t a = find(e / 3);
    const std::uint32_t b = find(static_cast<std::uint32_t>(t_.halfedges[e]) / 3);
    if (a == b) return;
    parent_[std::max(a, b)] = std::min(a, b);  // the root is the group's first triangle
    ++merges_;
}

VoronoiDiagram VoronoiBuilder::finish(std::uint64_t tests) && {
    VoronoiDiagram d;
    const std::vector<std::uint32_t>& tri = t_.triangles;
    const std::vector<std::int32_t>& twin = t_.halfedges;
    const std::size_t triangles = centres_.size(), n = points_.size();
    std::copy(std::begin(stage_counts_), std::end(stage_counts_), d.stage_counts);
    d.cocircular_tests = tests;
    d.cocircular_merges = merges_;

    // One vertex per group, numbered in the order of the groups' first triangles (a
    // group's root is its smallest triangle, so it is numbered before its members).
    d.vertex_of_triangle.resize(triangles);
    std::vector<std::uint32_t> first_triangle, group_size;
    d.vertices.reserve(triangles);
    first_triangle.reserve(triangles);
    group_size.reserve(triangles);
    for (std::uint32_t t = 0; t < triangles; ++t) {
        const std::uint32_t root = find(t);
        if (root == t) {
            d.vertex_of_triangle[t] = static_cast<std::uint32_t>(d.vertices.size());
            d.vertices.push_back(centres_[t].point);
            first_triangle.push_back(t);
            group_size.push_back(0);
        } else {
            d.vertex_of_triangle[t] = d.vertex_of_triangle[root];
        }
        ++group_size[d.vertex_of_triangle[t]];
    }
    const auto vertex_of_edge = [&](std::size_t e) { return d.vertex_of_triangle[e / 3]; };

    // The sites of each vertex: a triangle's three corners, or the boundary of a group's
    // union (a convex polygon inscribed in the circle), counter-clockwise, from the
    // smallest index. Boundary half-edges of the merged groups, bucketed by vertex:
    std::vector<std::uint32_t> boundary_offsets(merges_ > 0 ? d.vertices.size() + 1 : 0, 0),
        boundary;
    const auto on_group_boundary = [&](std::size_t e) {
        const std::uint32_t v = vertex_of_edge(e);
        return group_size[v] > 1 && (twin[e] < 0 || vertex_of_edge(twin[e]) != v);
    };
    if (merges_ > 0) {  // else every group is one triangle
        for (std::size_t e = 0; e < tri.size(); ++e)
            if (on_group_boundary(e)) ++boundary_offsets[vertex_of_edge(e) + 1];
        std::partial_sum(boundary_offsets.begin(), boundary_offsets.end(),
                         boundary_offsets.begin());
        boundary.resize(boundary_offsets.back());
        std::vector<std::uint32_t> fill(boundary_offsets.begin(), boundary_offsets.end() - 1);
        for (std::size_t e = 0; e < tri.size(); ++e)
            if (on_group_boundary(e))
                boundary[fill[vertex_of_edge(e)]++] = static_cast<std::uint32_t>(e);
    }
    const Duplicates dups(t_, n);
    std::vector<std::uint32_t> ring;
    d.sites.reserve(3 * d.vertices.size() + t_.duplicates.size());
    d.site_offsets.reserve(d.vertices.size() + 1);
    const bool corners_only = merges_ == 0 && t_.duplicates.empty();
    if (corners_only) {
        // Every vertex is one triangle and no site repeats: its three corners, from the
        // smallest (a rotation of a counter-clockwise triangle stays counter-clockwise).
        d.sites.resize(3 * d.vertices.size());
        d.site_offsets.resize(d.vertices.size() + 1);
        for (std::size_t v = 0; v < d.vertices.size(); ++v) {
            const std::uint32_t* c = &tri[3 * first_triangle[v]];
            const int k = c[0] < c[1] ? (c[0] < c[2] ? 0 : 2) : (c[1] < c[2] ? 1 : 2);
            for (int j = 0; j < 3; ++j) d.sites[3 * v + j] = c[(k + j) % 3];
            d.site_offsets[v + 1] = static_cast<std::uint32_t>(3 * v + 3);
        }
    }
    for (std::size_t v = 0; !corners_only && v < d.vertices.size(); ++v) {
        ring.clear();
        if (group_size[v] == 1) {
            const std::uint32_t* c = &tri[3 * first_triangle[v]];
            ring.assign(c, c + 3);
        } else {
            // Follow the boundary: the edge leaving a corner starts where the previous ended.
            const auto begin = boundary.begin() + boundary_offsets[v];
            const auto end = boundary.begin() + boundary_offsets[v + 1];
            std::sort(begin, end,
                      [&](std::uint32_t a, std::uint32_t b) { return tri[a] < tri[b]; });
            std::uint32_t e = *begin;
            for (std::ptrdiff_t k = 0; k < end - begin; ++k) {
                ring.push_back(tri[e]);
                const std::uint32_t to = tri[next_halfedge(e)];
                if (to == ring.front()) break;
                const auto it = std::lower_bound(
                    begin, end, to,
                    [&](std::uint32_t a, std::uint32_t value) { return tri[a] < value; });
                if (it == end || tri[*it] != to) break;  // not a disc: only an inexact kernel
                e = *it;
            }
        }
        std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
        for (const std::uint32_t s : ring) dups.append(s, d.sites);
        d.site_offsets.push_back(static_cast<std::uint32_t>(d.sites.size()));
    }

    // The cells: walk counter-clockwise around every site from its hull edge (if it is on
    // the hull) through the triangles' vertices, merging repeats of one vertex. Sites are
    // walked in the order they first appear in the triangle array, not in input order:
    // neighbouring sites then touch neighbouring triangles (the walk's memory accesses
    // stay in cache), and the cells are put in input order afterwards.
    // Each site with the first half-edge leaving it, in triangle order. (A byte per site
    // to mark it seen: the scan's random accesses stay in cache.)
    struct Start {
        std::uint32_t site, edge;
    };
    std::vector<std::uint8_t> seen(n, 0);
    std::vector<Start> order;
    order.reserve(n);
    for (std::size_t e = 0; e < tri.size(); ++e) {
        if (seen[tri[e]]) continue;
        seen[tri[e]] = 1;
        order.push_back({tri[e], static_cast<std::uint32_t>(e)});
    }
    d.unbounded.assign(n, 0);
    d.entry_ray.assign(n, Point2{0, 0});
    d.exit_ray.assign(n, Point2{0, 0});
    // One step of the walk, precomputed in a sequential pass so that the walk itself
    // touches one 8-byte entry per step: the half-edge after e counter-clockwise around
    // its origin (the twin of e's predecessor in its triangle; -1 at the hull) and e's
    // Voronoi vertex.
    struct Step {
        std::int32_t next;
        std::uint32_t vertex;
    };
    std::vector<Step> steps(tri.size());
    for (std::size_t e = 0; e < tri.size(); ++e)
        steps[e] = {twin[prev_halfedge(e)], vertex_of_edge(e)};
    // The walks of consecutive pieces of `order`, each into its own buffer.
    struct Walked {
        std::uint32_t at, size, piece;
    };
    const std::size_t pieces =
        std::min(parallel_pieces, std::max<std::size_t>(order.size() / 4096, 1));
    std::vector<std::vector<std::uint32_t>> buffers(pieces);
    std::vector<Walked> walked_cell(n, Walked{0, 0, 0});
    parallel_for(pieces, threads_, [&](std::size_t j) {
        std::vector<std::uint32_t>& walked = buffers[j];
        const std::size_t begin = order.size() * j / pieces, end = order.size() * (j + 1) / pieces;
        walked.reserve(7 * (end - begin));
        for (std::size_t o = begin; o < end; ++o) {
            const std::uint32_t s = order[o].site;
            const std::size_t first = walked.size();
            std::uint32_t e0 = order[o].edge;
            std::int32_t exit_edge = -1;
            for (int attempt = 0; attempt < 2; ++attempt) {
                std::uint32_t e = e0;
                for (std::size_t step = 0; step < tri.size(); ++step) {
                    const Step here = steps[e];
                    if (walked.size() == first || walked.back() != here.vertex)
                        walked.push_back(here.vertex);
                    if (here.next <
                        0) {  // e's predecessor (previous neighbour -> s) is on the hull
                        exit_edge = static_cast<std::int32_t>(prev_halfedge(e));
                        break;
                    }
                    e = static_cast<std::uint32_t>(here.next);
                    if (e == e0) break;
                }
                if (exit_edge < 0 || attempt == 1 || twin[e0] < 0) break;
                // A hull site, entered mid-fan: turn clockwise to its hull edge (the twin
                // of a half-edge leaving s ends at s; the next one leaves s again) and
                // walk once more from there. Only hull sites pay this.
                for (std::size_t step = 0; step < tri.size() && twin[e0] >= 0; ++step)
                    e0 = static_cast<std::uint32_t>(
                        next_halfedge(static_cast<std::size_t>(twin[e0])));
                walked.resize(first);
                exit_edge = -1;
            }
            if (exit_edge >= 0) {
                d.unbounded[s] = 1;
                d.entry_ray[s] = outward_normal(points_[s], points_[tri[next_halfedge(e0)]]);
                d.exit_ray[s] =
                    outward_normal(points_[tri[static_cast<std::size_t>(exit_edge)]], points_[s]);
            } else if (walked.size() - first > 1 && walked.back() == walked[first]) {
                walked.pop_back();  // the walk closed on the vertex it started in
            }
            walked_cell[s] = {static_cast<std::uint32_t>(first),
                              static_cast<std::uint32_t>(walked.size() - first),
                              static_cast<std::uint32_t>(j)};
        }
    });
    // Input order; a duplicate gets its twin's cell, and a site in no triangle (only an
    // inconsistent structure has one) an empty unbounded cell.
    d.cell_offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t s = t_.vertex_of_input[i];
        if (!seen[s]) d.unbounded[s] = 1;
        d.cell_offsets[i + 1] = d.cell_offsets[i] + walked_cell[s].size;
        d.unbounded[i] = d.unbounded[s];
        d.entry_ray[i] = d.entry_ray[s];
        d.exit_ray[i] = d.exit_ray[s];
    }
    d.cell_vertices.resize(d.cell_offsets[n]);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t s = t_.vertex_of_input[i];
        const Walked w = walked_cell[s];
        std::copy_n(buffers[w.piece].begin() + w.at, w.size,
                    d.cell_vertices.begin() + d.cell_offsets[i]);
    }
    return d;
}

VoronoiDiagram collinear_voronoi(std::span<const Point2> points, const Triangulation& t) {
    VoronoiDiagram d;
    d.collinear = true;
    d.chain = t.hull;
    d.unbounded.assign(points.size(), 1);
    d.entry_ray.assign(points.size(), Point2{0, 0});
    d.exit_ray.assign(points.size(), Point2{0, 0});
    d.cell_offsets.assign(points.size() + 1, 0);
    return d;
}

void to_furthest(VoronoiDiagram& d, std::span<const Point2> points, const Triangulation& t) {
    const std::size_t n = d.unbounded.size();
    if (d.collinear) {
        // Only the ends of the line (the lexicographically first and last points, first
        // occurrences) are extreme; every other site's region is empty.
        d.chain.clear();
        if (n > 0) {
            const auto before = [&](std::uint32_t a, std::uint32_t b) {
                return points[a].x < points[b].x ||
                       (points[a].x == points[b].x && points[a].y < points[b].y);
            };
            std::uint32_t lo = 0, hi = 0;
            for (std::uint32_t i = 1; i < n; ++i) {
                if (before(i, lo)) lo = i;
                if (before(hi, i)) hi = i;
            }
            d.chain.push_back(t.vertex_of_input[lo]);
            if (before(lo, hi)) d.chain.push_back(t.vertex_of_input[hi]);
        }
        std::fill(d.unbounded.begin(), d.unbounded.end(), std::uint8_t{0});
        for (const std::uint32_t s : d.chain) d.unbounded[s] = 1;
        for (std::size_t i = 0; i < n; ++i) d.unbounded[i] = d.unbounded[t.vertex_of_input[i]];
        return;
    }
    std::vector<std::uint8_t> extreme(n, 0);
    for (const std::uint32_t v : t.triangles) extreme[v] = 1;
    std::vector<std::uint32_t> cells;
    std::vector<std::uint32_t> offsets(n + 1, 0);
    cells.reserve(d.cell_vertices.size());
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t s = t.vertex_of_input[i];
        if (extreme[s]) {
            // The walk around the site in the triangulation meets the region's vertices
            // counter-clockwise, from the hull edge leaving the site to the one entering
            // it, as for the nearest-site diagram; the rays are the same edges' normals
            // turned inward.
            const auto cell = d.cell(i);
            cells.insert(cells.end(), cell.begin(), cell.end());
            d.entry_ray[i] = {-d.entry_ray[i].x, -d.entry_ray[i].y};
            d.exit_ray[i] = {-d.exit_ray[i].x, -d.exit_ray[i].y};
            d.unbounded[i] = 1;
        } else {
            d.entry_ray[i] = d.exit_ray[i] = Point2{0, 0};
            d.unbounded[i] = 0;
        }
        offsets[i + 1] = static_cast<std::uint32_t>(cells.size());
    }
    d.cell_vertices = std::move(cells);
    d.cell_offsets = std::move(offsets);
}

}  // namespace detail
}  // namespace exidel::delaunay
