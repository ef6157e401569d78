// exidel: exact point location in a triangulation.
//
// A query q is classified by the kernel's orient2d alone, with no tolerance: strictly
// inside a triangle, on an edge (which one), on a vertex (which one: a query equal to a
// repeated input point is on the vertex of its first occurrence), or outside the convex
// hull (with a hull edge that sees q strictly). With an exact kernel every answer is the
// exact one, whatever the coordinates.
//
// The walk is the remembering stochastic visibility walk of Devillers, Pion and Teillaud
// ("Walking in a triangulation", Int. J. Found. Comput. Sci. 13(2), 2002): from a start
// triangle, cross an edge that has q strictly on its other side; never test again the edge
// just crossed (q is strictly on its near side); try the edges from a random one. On a
// Delaunay triangulation any visibility walk ends (Edelsbrunner, "An acyclicity theorem for
// cell complexes in d dimensions", Combinatorica 10, 1990: the power of q with respect to
// the circumcircles never increases along it, and triangles of one circumcircle form a
// triangulated convex polygon, whose dual is a tree that a walk toward q cannot go round).
// The random choice also ends the walk, with probability 1, on any triangulation. Every
// walk is bounded all the same (LocateOptions::step_bound): an inexact kernel whose answers
// contradict each other gets a Failure (location_exceeded, location_inconsistent), never
// a loop.
//
// Starts: a hint triangle; the previous answer (Locator keeps it); or jump-and-walk (Mücke,
// Saias and Zhu, "Fast randomized point location without preprocessing in two- and
// three-dimensional Delaunay triangulations", SoCG 1996): the nearest, in rounded
// distance, of a fixed sample of about n^(1/3) vertices. The batch form sorts the queries
// along a Hilbert curve (detail/brio.hpp) and walks each from the previous answer, in
// chunks of a fixed size that each start by jump-and-walk, so that its answers do not
// depend on the thread count. Where a query is on an edge or vertex, which of the
// triangles holding it is reported depends on the walk; the classification and the vertex
// do not.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "exidel/delaunay/detail/brio.hpp"
#include "exidel/delaunay/detail/memory.hpp"
#include "exidel/delaunay/detail/radix.hpp"
#include "exidel/delaunay/parallel.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/dynamic.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/registry.hpp"

namespace exidel::delaunay {

enum class LocationKind : std::uint8_t {
    inside,     ///< strictly inside `triangle`
    on_edge,    ///< on `edge` (neither end), which belongs to `triangle`
    on_vertex,  ///< equal to `vertex`, a corner of `triangle`
    outside,    ///< outside the convex hull; `edge` is a hull half-edge that sees q
};

std::string_view to_string(LocationKind kind) noexcept;

inline constexpr std::uint32_t no_vertex = 0xffffffffu;

/// Where a query lies. With triangles (Triangulation::collinear false):
///   triangle  the triangle holding q (inside, on_edge, on_vertex), or, outside, the
///             triangle of the hull edge that sees q
///   edge      on_edge: the half-edge q lies on (3 triangle + j, from triangles[edge] to
///             the next corner); outside: a hull half-edge (twin -1) with q strictly on
///             its right; -1 otherwise
///   vertex    on_vertex: the input index of the vertex (a first occurrence); else no_vertex
/// Without triangles (the points are collinear: Triangulation::hull is their chain in
/// lexicographic order), triangle is -1, and on_edge's `edge` is the position i of the
/// chain segment hull[i] -> hull[i + 1] holding q; `outside` has no edge.
struct Location {
    LocationKind kind = LocationKind::outside;
    std::int32_t triangle = -1;
    std::int32_t edge = -1;
    std::uint32_t vertex = no_vertex;

    friend bool operator==(const Location&, const Location&) = default;
};

/// A Failure thrown by the single-query forms (the batch forms return it).
class FailureError : public std::runtime_error {
public:
    explicit FailureError(Failure f)
        : std::runtime_error(std::string(to_string(f.kind)) + ": " + f.message),
          failure(std::move(f)) {}
    Failure failure;
};

/// How the batch form orders its walks.
enum class LocateOrder : std::uint8_t {
    hilbert,  ///< sort the queries along a Hilbert curve, walk each from the previous answer
    given,    ///< the queries' own order, each from the previous answer
    jump,     ///< each query on its own, from the nearest vertex of the sample
};

struct LocateOptions {
    LocateOrder order = LocateOrder::hilbert;
    /// Worker threads (the answers do not depend on it).
    unsigned threads = 1;
    /// Triangles one walk may enter before it fails with location_exceeded; 0: 4 per
    /// triangle of the triangulation plus 64, which no walk of an exact kernel on a
    /// Delaunay triangulation reaches (it enters each triangle at most once).
    std::uint64_t step_bound = 0;
};

namespace detail {

/// The walk's random edge choice: a 32-bit linear congruential generator (Numerical
/// Recipes' constants), reduced to 0, 1, 2 from its high bits. Fixed seeds: answers are
/// reproducible.
struct WalkRandom {
    std::uint32_t state = 0x2545f491u;
    unsigned below3() noexcept {
        state = state * 1664525u + 1013904223u;
        return static_cast<unsigned>((std::uint64_t{state >> 16} * 3) >> 16);
    }
};

enum class WalkStatus : std::uint8_t { found, exceeded, inconsistent };

/// A Locator's copy of the mesh, laid out for walks (see Locator's members), for the
/// queries built on location (natural.hpp, the neighbour searches): local half-edge
/// 3 k + j is the triangulation's 3 triangle_of_local[k] + j.
struct LocalMesh {
    std::span<const std::uint32_t> triangles;          // corners, as local vertices
    std::span<const std::int32_t> halfedges;           // twins, as local half-edges
    std::span<const Point2> points;                    // local vertex -> coordinates
    std::span<const std::uint32_t> input_of_local;     // local vertex -> input index
    std::span<const std::uint32_t> local_of_input;     // input index -> local, or no_vertex
    std::span<const std::uint32_t> triangle_of_local;  // local triangle -> triangle
    std::span<const std::uint32_t> local_of_triangle;  // triangle -> local triangle
    std::span<const std::int32_t> vertex_edge;         // local vertex -> a half-edge out
};

/// The remembering stochastic visibility walk from triangle t (see the top of the file).
/// P: points by input index; T, H: Triangulation::triangles and ::halfedges.
template <PredicateKernel K>
WalkStatus walk(const K& k, const Point2* P, const std::uint32_t* T, const std::int32_t* H,
                Point2 q, std::uint32_t t, std::uint64_t bound, WalkRandom& random, Location& out) {
    std::size_t came = static_cast<std::size_t>(-1);  // the half-edge of t we entered by
    for (std::uint64_t step = 0; step < bound; ++step) {
        const std::size_t base = 3 * std::size_t{t};
        const unsigned first = random.below3();
        unsigned zeros = 0, zero_edge[3] = {0, 0, 0};
        bool moved = false;
        for (unsigned i = 0; i < 3; ++i) {
            const unsigned j = first + i < 3 ? first + i : first + i - 3;
            const std::size_t e = base + j;
            if (e == came) continue;
            const std::size_t f = j == 2 ? base : e + 1;
            const Sign s = k.orient2d(P[T[e]], P[T[f]], q);
            if (s == Sign::negative) {
                const std::int32_t twin = H[e];
                if (twin < 0) {
                    out = {LocationKind::outside, static_cast<std::int32_t>(t),
                           static_cast<std::int32_t>(e), no_vertex};
                    return WalkStatus::found;
                }
                came = static_cast<std::size_t>(twin);
                t = static_cast<std::uint32_t>(twin) / 3;
                moved = true;
                break;
            }
            if (s == Sign::zero) zero_edge[zeros++] = j;
        }
        if (moved) continue;
        const auto ti = static_cast<std::int32_t>(t);
        switch (zeros) {
            case 0: out = {LocationKind::inside, ti, -1, no_vertex}; return WalkStatus::found;
            case 1:
                out = {LocationKind::on_edge, ti, static_cast<std::int32_t>(base + zero_edge[0]),
                       no_vertex};
                return WalkStatus::found;
            case 2: {
                // Edge j runs from corner j to corner j + 1: two edges meet at the corner
                // that starts the later of them (cyclically).
                const unsigned a = zero_edge[0], b = zero_edge[1];
                const unsigned corner = (a + 1) % 3 == b ? b : a;
                out = {LocationKind::on_vertex, ti, -1, T[base + corner]};
                return WalkStatus::found;
            }
            default: return WalkStatus::inconsistent;  // q on all three lines
        }
    }
    return WalkStatus::exceeded;
}

}  // namespace detail

/// Point location in a triangulation of `points` (the points it was built from, by input
/// index). Keeps references to both: they must outlive it and not change. The constructor
/// checks that the arrays fit together (sizes, indices in range) and throws
/// std::invalid_argument when they do not; it does not check that the triangulation is
/// Delaunay (the walk ends on any triangulation, see above).
///
/// Not thread-safe for the single-query form (it remembers the previous answer); the
/// batch form may run on several threads and is const.
template <PredicateKernel K>
class Locator {
public:
    Locator(std::span<const Point2> points, const Triangulation& triangulation, K kernel = K{});

    /// Locates q from the previous answer (the first time, by jump-and-walk). Throws
    /// FailureError on a non-finite coordinate or when the kernel contradicts itself.
    Location locate(Point2 q);
    /// Locates q from triangle `hint` (-1: by jump-and-walk). Throws std::out_of_range
    /// for a hint that is not a triangle, and as above.
    Location locate(Point2 q, std::int32_t hint);

    /// Locates every query into out (out.size() == queries.size(), else
    /// std::invalid_argument). Returns the first failure: a non-finite query (its index
    /// in input_index, checked before any walk) or a walk the kernel made fail (out is
    /// then partly written).
    std::optional<Failure> locate(std::span<const Point2> queries, std::span<Location> out,
                                  const LocateOptions& options = {}) const;

    /// The nearest vertex to every query (out[i], an input index: a first occurrence;
    /// no_vertex when there are no points), decided exactly by the kernel's
    /// compare_distance: each query is located, then a greedy walk goes from the nearest
    /// corner of its triangle to a strictly nearer neighbour while there is one. In a
    /// Delaunay triangulation a vertex with no strictly nearer neighbour is a nearest
    /// vertex: if v is not, the segment from v to q leaves v's Voronoi cell through the
    /// cell of a neighbour w at a point x with |xw| = |xv|, and |qw| <= |qx| + |xw| = |qv|,
    /// with equality only if w lies on the line of v and x, beyond x from q, at |xv| from
    /// x, which is v. Among several equally near vertices, which one is reported depends
    /// on the walk. Failures as for locate (and location_exceeded for a greedy walk that
    /// does not end, only possible with an inexact kernel).
    std::optional<Failure> nearest(std::span<const Point2> queries, std::span<std::uint32_t> out,
                                   const LocateOptions& options = {}) const;

    /// The batch form with the walks' orient2d taken from `walker`, a kernel with the same
    /// answers as K (the library runs the adaptive kernel's batches with its filters
    /// inline, src/locate.cpp).
    template <PredicateKernel W>
    std::optional<Failure> locate_with(const W& walker, std::span<const Point2> queries,
                                       std::span<Location> out, const LocateOptions& options) const;

    const Triangulation& triangulation() const noexcept { return tri_; }
    std::span<const Point2> points() const noexcept { return points_; }
    const K& kernel() const noexcept { return kernel_; }
    /// The walks' copy of the mesh (empty without triangles).
    detail::LocalMesh local_mesh() const noexcept {
        return {local_triangles_, local_halfedges_,   local_points_,      input_of_local_,
                local_of_input_,  triangle_of_local_, local_of_triangle_, vertex_edge_};
    }

private:
    struct Sample {
        Point2 point;
        std::uint32_t triangle;
    };
    std::uint32_t jump_start(Point2 q) const;
    std::size_t chain_position(Point2 q) const;
    Location locate_collinear(Point2 q) const;
    template <PredicateKernel W>
    Location walk_from(const W& walker, Point2 q, std::uint32_t start, detail::WalkRandom& random,
                       std::uint64_t bound, std::size_t query) const;
    Location to_triangulation(Location local) const noexcept;

    std::span<const Point2> points_;
    const Triangulation& tri_;
    K kernel_;
    // The walks run on a copy of the mesh laid out for them: the triangles renumbered
    // along a Hilbert curve through their centroids, the vertices in the order those
    // triangles first use them, so that triangles near each other in the plane are near
    // each other in memory (the Triangulation's own order need not be: its vertices are
    // the input's, often random, and every step of a walk would miss the cache). The same
    // triangles, corners in the same rotation: local half-edge 3k + j is the
    // triangulation's 3 triangle_of_local_[k] + j.
    detail::FreshVector<std::uint32_t> local_triangles_;    // corners, as local vertices
    detail::FreshVector<std::int32_t> local_halfedges_;     // twins, as local half-edges
    detail::FreshVector<Point2> local_points_;              // local vertex -> coordinates
    detail::FreshVector<std::uint32_t> input_of_local_;     // local vertex -> input index
    detail::FreshVector<std::uint32_t> local_of_input_;     // input index -> local (or none)
    detail::FreshVector<std::uint32_t> triangle_of_local_;  // local triangle -> triangle
    detail::FreshVector<std::uint32_t> local_of_triangle_;  // triangle -> local triangle
    // Local vertex -> a local half-edge out of it, the one on the hull for a hull vertex
    // (turning counter-clockwise from it then meets every triangle around the vertex).
    detail::FreshVector<std::int32_t> vertex_edge_;
    std::vector<Sample> sample_;
    std::uint64_t bound_ = 0;
    std::int32_t last_ = -1;
    detail::WalkRandom random_;
};

namespace detail {

/// The adaptive kernel's batch location, compiled in the library with its filters inline
/// and the floating-point environment made standard once (src/locate.cpp).
std::optional<Failure> locate_adaptive(const Locator<AdaptiveKernel>& locator,
                                       std::span<const Point2> queries, std::span<Location> out,
                                       const LocateOptions& options);

inline bool finite(Point2 p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

inline Failure non_finite_query(std::size_t index) {
    return Failure{FailureKind::non_finite_input, index, no_index,
                   "query " + std::to_string(index) + " has a non-finite coordinate"};
}

}  // namespace detail

namespace detail {

/// The greedy walk to a vertex nearest q (Locator::nearest says why it ends on one): from
/// the nearest corner of local triangle t, to a strictly nearer neighbour while there is
/// one. A local vertex, or nothing when the walk does not end in as many steps as there
/// are vertices (only possible with an inexact kernel).
template <PredicateKernel K>
std::optional<std::uint32_t> greedy_nearest(const K& k, const LocalMesh& m, Point2 q,
                                            std::uint32_t t) {
    const auto nearer = [&](std::uint32_t a, std::uint32_t b) {
        return k.compare_distance(q, m.points[a], m.points[b]) == Sign::negative;
    };
    const std::size_t base = 3 * std::size_t{t};
    std::uint32_t v = m.triangles[base];
    for (std::size_t j = 1; j < 3; ++j) {
        if (nearer(m.triangles[base + j], v)) v = m.triangles[base + j];
    }
    for (std::size_t steps = 0;; ++steps) {
        if (steps > m.points.size()) return std::nullopt;
        bool moved = false;
        const auto first = static_cast<std::size_t>(m.vertex_edge[v]);
        std::size_t e = first;
        do {  // every triangle around v, counter-clockwise
            const std::uint32_t a = m.triangles[next_halfedge(e)];
            const std::uint32_t b = m.triangles[prev_halfedge(e)];
            if (nearer(a, v)) {
                v = a, moved = true;
                break;
            }
            if (nearer(b, v)) {
                v = b, moved = true;
                break;
            }
            const std::int32_t twin = m.halfedges[prev_halfedge(e)];
            if (twin < 0) break;
            e = static_cast<std::size_t>(twin);
        } while (e != first);
        if (!moved) return v;
    }
}

}  // namespace detail

template <PredicateKernel K>
Locator<K>::Locator(std::span<const Point2> points, const Triangulation& triangulation, K kernel)
    : points_(points), tri_(triangulation), kernel_(std::move(kernel)) {
    const auto& T = tri_.triangles;
    const auto& H = tri_.halfedges;
    const std::size_t n = points_.size();
    const auto bad = [](const std::string& what) {
        throw std::invalid_argument("Locator: " + what);
    };
    if (T.size() % 3 != 0) bad("triangles.size() is not a multiple of 3");
    if (H.size() != T.size()) bad("halfedges.size() differs from triangles.size()");
    if (T.size() / 3 > static_cast<std::size_t>(INT32_MAX) / 3) bad("too many triangles");
    if (tri_.collinear != T.empty()) {
        bad(tri_.collinear ? "a collinear triangulation with triangles"
                           : "no triangles, and collinear is not set");
    }
    for (std::size_t e = 0; e < T.size(); ++e) {
        if (T[e] >= n) {
            bad("triangles[" + std::to_string(e) + "] = " + std::to_string(T[e]) +
                " is not a point (" + std::to_string(n) + " points)");
        }
        const std::int32_t twin = H[e];
        if (twin < -1 || twin >= static_cast<std::int64_t>(H.size()) ||
            (twin >= 0 && H[static_cast<std::size_t>(twin)] != static_cast<std::int32_t>(e))) {
            bad("halfedges[" + std::to_string(e) + "] is not a twin");
        }
    }
    for (const std::uint32_t v : tri_.hull) {
        if (v >= n) bad("hull vertex " + std::to_string(v) + " is not a point");
    }
    const std::size_t m = T.size() / 3;
    bound_ = 4 * static_cast<std::uint64_t>(m) + 64;
    if (m == 0) return;
    // The triangles along a Hilbert curve through their (rounded) centroids.
    {
        detail::FreshVector<Point2> centroids(m);
        for (std::size_t t = 0; t < m; ++t) {
            const Point2 a = points_[T[3 * t]], b = points_[T[3 * t + 1]],
                         c = points_[T[3 * t + 2]];
            centroids[t] = {a.x / 3 + b.x / 3 + c.x / 3, a.y / 3 + b.y / 3 + c.y / 3};
        }
        const detail::FreshVector<detail::KeyIndex> sorted = detail::hilbert_sorted(centroids);
        triangle_of_local_.resize(m);
        local_of_triangle_.resize(m);
        for (std::size_t k = 0; k < m; ++k) {
            triangle_of_local_[k] = sorted[k].index;
            local_of_triangle_[sorted[k].index] = static_cast<std::uint32_t>(k);
        }
    }
    local_triangles_.resize(T.size());
    local_halfedges_.resize(T.size());
    local_of_input_.assign(n, no_vertex);
    input_of_local_.reserve(n);
    local_points_.reserve(n);
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t t = triangle_of_local_[k];
        for (std::size_t j = 0; j < 3; ++j) {
            const std::uint32_t v = T[3 * t + j];
            std::uint32_t& local = local_of_input_[v];
            if (local == no_vertex) {
                local = static_cast<std::uint32_t>(input_of_local_.size());
                input_of_local_.push_back(v);
                local_points_.push_back(points_[v]);
            }
            local_triangles_[3 * k + j] = local;
            const std::int32_t twin = H[3 * t + j];
            local_halfedges_[3 * k + j] =
                twin < 0 ? -1
                         : static_cast<std::int32_t>(3 * local_of_triangle_[twin / 3] + twin % 3);
        }
    }
    vertex_edge_.assign(local_points_.size(), -1);
    for (std::size_t e = 0; e < local_triangles_.size(); ++e) {
        std::int32_t& out = vertex_edge_[local_triangles_[e]];
        if (out < 0 || local_halfedges_[e] < 0) out = static_cast<std::int32_t>(e);
    }
    // About m^(1/3) vertices, each with a triangle of its, at random half-edges.
    const auto size = std::max<std::size_t>(1, static_cast<std::size_t>(std::cbrt(double(m))));
    detail::SplitMix64 rng{detail::order_seed};
    sample_.reserve(size);
    for (std::size_t i = 0; i < size; ++i) {
        const std::size_t e = rng.below(T.size());
        sample_.push_back({local_points_[local_triangles_[e]], static_cast<std::uint32_t>(e / 3)});
    }
}

/// The sample vertex nearest to q in rounded distance (a start only: the walk decides).
template <PredicateKernel K>
std::uint32_t Locator<K>::jump_start(Point2 q) const {
    std::uint32_t best = sample_.front().triangle;
    double best_d = INFINITY;
    for (const Sample& s : sample_) {
        const double dx = s.point.x - q.x, dy = s.point.y - q.y;
        const double d = dx * dx + dy * dy;
        if (d < best_d) best_d = d, best = s.triangle;
    }
    return best;
}

/// The first position of the collinear chain whose point is not lexicographically below q
/// (exact comparisons of coordinates).
template <PredicateKernel K>
std::size_t Locator<K>::chain_position(Point2 q) const {
    const auto less = [this](std::uint32_t v, Point2 p) {
        const Point2 a = points_[v];
        return a.x < p.x || (a.x == p.x && a.y < p.y);
    };
    const auto& chain = tri_.hull;
    return static_cast<std::size_t>(std::lower_bound(chain.begin(), chain.end(), q, less) -
                                    chain.begin());
}

/// Collinear points: exact comparisons of coordinates along the chain, and orient2d for
/// whether q is on its line.
template <PredicateKernel K>
Location Locator<K>::locate_collinear(Point2 q) const {
    const auto& chain = tri_.hull;
    const std::size_t i = chain_position(q);
    if (i < chain.size() && points_[chain[i]].x == q.x && points_[chain[i]].y == q.y) {
        return {LocationKind::on_vertex, -1, -1, chain[i]};
    }
    if (i == 0 || i == chain.size() ||
        kernel_.orient2d(points_[chain.front()], points_[chain.back()], q) != Sign::zero) {
        return {};
    }
    return {LocationKind::on_edge, -1, static_cast<std::int32_t>(i - 1), no_vertex};
}

template <PredicateKernel K>
template <PredicateKernel W>
Location Locator<K>::walk_from(const W& walker, Point2 q, std::uint32_t start,
                               detail::WalkRandom& random, std::uint64_t bound,
                               std::size_t query) const {
    Location out;
    const auto status = detail::walk(walker, local_points_.data(), local_triangles_.data(),
                                     local_halfedges_.data(), q, start, bound, random, out);
    if (status == detail::WalkStatus::found) [[likely]]
        return out;
    const std::string which = query == no_index ? "the query" : "query " + std::to_string(query);
    if (status == detail::WalkStatus::exceeded) {
        throw FailureError(Failure{FailureKind::location_exceeded, query, no_index,
                                   "the walk locating " + which + " entered " +
                                       std::to_string(bound) + " triangles without ending"});
    }
    throw FailureError(Failure{FailureKind::location_inconsistent, query, no_index,
                               which + " is on all three edge lines of a triangle"});
}

/// A walk's answer (local numbers) in the triangulation's numbers.
template <PredicateKernel K>
Location Locator<K>::to_triangulation(Location out) const noexcept {
    const std::uint32_t t = triangle_of_local_[static_cast<std::uint32_t>(out.triangle)];
    if (out.edge >= 0) out.edge = static_cast<std::int32_t>(3 * t + out.edge % 3);
    out.triangle = static_cast<std::int32_t>(t);
    if (out.vertex != no_vertex) out.vertex = input_of_local_[out.vertex];
    return out;
}

template <PredicateKernel K>
Location Locator<K>::locate(Point2 q) {
    return locate(q, last_);
}

template <PredicateKernel K>
Location Locator<K>::locate(Point2 q, std::int32_t hint) {
    if (!detail::finite(q)) throw FailureError(detail::non_finite_query(no_index));
    if (tri_.collinear) return locate_collinear(q);
    if (hint < -1 || hint >= static_cast<std::int64_t>(tri_.triangle_count())) {
        throw std::out_of_range("Locator::locate: hint " + std::to_string(hint) +
                                " is not a triangle");
    }
    const std::uint32_t start =
        hint < 0 ? jump_start(q) : local_of_triangle_[static_cast<std::uint32_t>(hint)];
    const Location where =
        to_triangulation(walk_from(kernel_, q, start, random_, bound_, no_index));
    last_ = where.triangle;
    return where;
}

template <PredicateKernel K>
std::optional<Failure> Locator<K>::locate(std::span<const Point2> queries, std::span<Location> out,
                                          const LocateOptions& options) const {
    if constexpr (std::is_same_v<K, AdaptiveKernel>) {
        return detail::locate_adaptive(*this, queries, out, options);
    } else {
        return locate_with(kernel_, queries, out, options);
    }
}

template <PredicateKernel K>
template <PredicateKernel W>
std::optional<Failure> Locator<K>::locate_with(const W& walker, std::span<const Point2> queries,
                                               std::span<Location> out,
                                               const LocateOptions& options) const {
    if (out.size() != queries.size()) {
        throw std::invalid_argument("Locator::locate: " + std::to_string(queries.size()) +
                                    " queries but room for " + std::to_string(out.size()));
    }
    for (std::size_t i = 0; i < queries.size(); ++i) {
        if (!detail::finite(queries[i])) return detail::non_finite_query(i);
    }
    const std::size_t n = queries.size();
    // Fixed-size chunks, each starting afresh: the answers do not depend on the threads.
    constexpr std::size_t chunk = 4096;
    const std::size_t chunks = (n + chunk - 1) / chunk;
    if (tri_.collinear) {
        parallel_for(chunks, options.threads, [&](std::size_t c) {
            for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i)
                out[i] = locate_collinear(queries[i]);
        });
        return std::nullopt;
    }
    // Hilbert order: each chunk's queries gathered in curve order, walked, and the answers
    // scattered back, so that the walks read and write consecutive memory (buffers of a
    // chunk, in cache, not of the whole batch: fresh memory costs a page fault per 4 KiB).
    detail::FreshVector<detail::KeyIndex> sorted;
    if (options.order == LocateOrder::hilbert) sorted = detail::hilbert_sorted(queries);
    const std::uint64_t bound = options.step_bound != 0 ? options.step_bound : bound_;
    const bool jump = options.order == LocateOrder::jump;
    try {
        parallel_for(chunks, options.threads, [&](std::size_t c) {
            detail::WalkRandom random{static_cast<std::uint32_t>(0x2545f491u + 0x9e3779b9u * c)};
            const std::size_t begin = c * chunk, end = std::min(n, begin + chunk);
            std::span<const Point2> walked = queries.subspan(begin, end - begin);
            std::span<Location> written = out.subspan(begin, end - begin);
            std::vector<Point2> gathered;
            std::vector<Location> answers;
            if (!sorted.empty()) {
                gathered.resize(end - begin);
                answers.resize(end - begin);
                for (std::size_t i = begin; i < end; ++i)
                    gathered[i - begin] = queries[sorted[i].index];
                walked = gathered;
                written = answers;
            }
            // The previous answer's local triangle (a walk from it reads memory the last
            // one read; its number in the triangulation would be a lookup at random).
            std::int32_t previous = -1;
            for (std::size_t i = 0; i < walked.size(); ++i) {
                const Point2 q = walked[i];
                const std::uint32_t start =
                    jump || previous < 0 ? jump_start(q) : static_cast<std::uint32_t>(previous);
                const Location local =
                    walk_from(walker, q, start, random, bound,
                              sorted.empty() ? begin + i : sorted[begin + i].index);
                previous = local.triangle;
                written[i] = to_triangulation(local);
            }
            if (!sorted.empty()) {
                for (std::size_t i = begin; i < end; ++i) out[sorted[i].index] = answers[i - begin];
            }
        });
    } catch (FailureError& e) {
        return std::move(e.failure);
    }
    return std::nullopt;
}

template <PredicateKernel K>
std::optional<Failure> Locator<K>::nearest(std::span<const Point2> queries,
                                           std::span<std::uint32_t> out,
                                           const LocateOptions& options) const {
    if (out.size() != queries.size()) {
        throw std::invalid_argument("Locator::nearest: " + std::to_string(queries.size()) +
                                    " queries but room for " + std::to_string(out.size()));
    }
    std::vector<Location> where(queries.size());
    if (auto failure = locate(queries, where, options)) return failure;
    const std::size_t n = queries.size();
    constexpr std::size_t chunk = 4096;
    const std::size_t chunks = (n + chunk - 1) / chunk;
    const auto exceeded = [](std::size_t i) {
        return FailureError(Failure{
            FailureKind::location_exceeded, i, no_index,
            "the greedy walk to the vertex nearest query " + std::to_string(i) + " did not end"});
    };
    const auto& chain = tri_.hull;
    try {
        parallel_for(chunks, options.threads, [&](std::size_t c) {
            for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i) {
                const Point2 q = queries[i];
                if (where[i].kind == LocationKind::on_vertex) {
                    out[i] = where[i].vertex;
                    continue;
                }
                if (tri_.collinear) {
                    // Distances along a line are unimodal: step toward the nearer side.
                    if (chain.empty()) {
                        out[i] = no_vertex;
                        continue;
                    }
                    std::size_t at = std::min(chain_position(q), chain.size() - 1);
                    const auto nearer = [&](std::size_t a, std::size_t b) {
                        return kernel_.compare_distance(q, points_[chain[a]], points_[chain[b]]) ==
                               Sign::negative;
                    };
                    for (std::size_t steps = 0;; ++steps) {
                        if (steps > chain.size()) throw exceeded(i);
                        if (at > 0 && nearer(at - 1, at)) {
                            --at;
                        } else if (at + 1 < chain.size() && nearer(at + 1, at)) {
                            ++at;
                        } else {
                            break;
                        }
                    }
                    out[i] = chain[at];
                    continue;
                }
                const std::uint32_t local =
                    local_of_triangle_[static_cast<std::uint32_t>(where[i].triangle)];
                const auto v = detail::greedy_nearest(kernel_, local_mesh(), q, local);
                if (!v) throw exceeded(i);
                out[i] = input_of_local_[*v];
            }
        });
    } catch (FailureError& e) {
        return std::move(e.failure);
    }
    return std::nullopt;
}

// Compiled once in the library for every kernel of the registry and DynamicKernel.
#define EXIDEL_LOCATE_EXTERN(K, spelling, summary) extern template class Locator<K>;
EXIDEL_KERNELS(EXIDEL_LOCATE_EXTERN)
EXIDEL_LOCATE_EXTERN(DynamicKernel, "", "")
#undef EXIDEL_LOCATE_EXTERN

}  // namespace exidel::delaunay
