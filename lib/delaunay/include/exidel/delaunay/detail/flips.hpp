// exidel: Lawson's edge flips on the shared mesh (mesh.hpp), the repair step of the
// algorithms that first build some triangulation and then make it Delaunay:
//
//   legalize   after a point p was fanned to part of the hull (sweep-hull): the edges
//              opposite p are tested, and every flip makes p the apex of two new edges
//              opposite it, tested in turn (delaunator's `legalize`, iteratively);
//   flip_all   Lawson (1977): every interior edge is queued, a flipped edge queues the
//              four edges of its quadrilateral, until no edge is illegal.
//
// An edge a -> b (half-edge e) with triangles (a, b, c) and (b, a, d) is illegal when d
// lies strictly inside the circle through a, b, c; it is then replaced by c -> d. Points
// on the circle keep their edge: with an exact kernel both loops end on a Delaunay
// triangulation, and where four or more points are cocircular the diagonals of their
// polygon are whichever the first triangulation and the flips left (any of them is
// Delaunay; the tests compare only the edges every Delaunay triangulation has).
//
// Why the cosine policy is allowed here: both triangles of a tested edge are triangles of
// a valid triangulation, so c and d lie strictly on opposite sides of a -> b, which is
// Theorem 1's precondition.
//
// Why the loops end, and their bounds: with an exact kernel every flip strictly lowers the
// lifted triangulation on the paraboloid z = x^2 + y^2, so an edge that was flipped away
// never comes back, and Lawson's algorithm flips at most n (n - 1) / 2 edges (Edelsbrunner,
// "Geometry and Topology for Mesh Generation", Section 1.3). An inexact kernel can flip in
// circles; the callers give a budget and stop with FailureKind::flips_exceeded.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "exidel/delaunay/detail/counting.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

/// Replaces the edge of half-edge e (with twin t = halfedges[e] >= 0) by the other
/// diagonal of its quadrilateral. With triangle E = (a, b, c) holding e = a -> b and
/// triangle T = (b, a, d) holding t: afterwards E's slots read (d, b, c) and T's (c, a,
/// d), so e is d -> b, t is c -> a, and prev(e) / prev(t) are the new diagonal c -> d /
/// d -> c. Hull edges moved to another slot are re-pointed in hull_edge.
inline void flip_edge(Mesh& m, std::size_t e) {
    auto& tris = m.triangles;
    auto& half = m.halfedges;
    const auto t = static_cast<std::size_t>(half[e]);
    const std::size_t e_prev = prev_halfedge(e), t_prev = prev_halfedge(t);
    const std::uint32_t c = tris[e_prev], d = tris[t_prev];
    const std::int32_t across_e_prev = half[e_prev];  // c -> a
    const std::int32_t across_t_prev = half[t_prev];  // d -> b
    tris[e] = d;
    tris[t] = c;
    // e now runs d -> b (the edge t_prev had), t runs c -> a (the edge e_prev had).
    m.link(static_cast<std::int32_t>(e), across_t_prev);
    m.link(static_cast<std::int32_t>(t), across_e_prev);
    m.link(static_cast<std::int32_t>(e_prev), static_cast<std::int32_t>(t_prev));
    if (across_t_prev < 0) m.hull_edge[d] = static_cast<std::int32_t>(e);
    if (across_e_prev < 0) m.hull_edge[c] = static_cast<std::int32_t>(t);
}

/// Whether the edge of half-edge e (twin t >= 0) is illegal, decided by the policy P:
/// the apex of t's triangle strictly inside the circle of e's triangle.
template <InCirclePolicy P, PredicateKernel K, Instrumentation I>
bool illegal(const K& k, std::span<const Point2> pts, const Mesh& m, Counting<I>& counting,
             std::size_t e) {
    const auto t = static_cast<std::size_t>(m.halfedges[e]);
    const auto& tris = m.triangles;
    return counting.template in_circle_by_policy<P>(k, pts[tris[e]], pts[tris[next_halfedge(e)]],
                                                    pts[tris[prev_halfedge(e)]],
                                                    pts[tris[prev_halfedge(t)]]);
}

/// Legalizes the edges opposite a new vertex: `stack` holds half-edges whose triangles'
/// third vertex is the new point (the edges to test); each flip pushes the two edges now
/// opposite it. `budget` flips at most; false when it ran out (the mesh is then valid as
/// a triangulation but not Delaunay).
template <InCirclePolicy P, PredicateKernel K, Instrumentation I>
bool legalize(const K& k, std::span<const Point2> pts, Mesh& m, Counting<I>& counting,
              std::vector<std::int32_t>& stack, std::size_t budget) {
    while (!stack.empty()) {
        const auto e = static_cast<std::size_t>(stack.back());
        stack.pop_back();
        if (m.halfedges[e] < 0 || !illegal<P>(k, pts, m, counting, e)) continue;
        if (budget-- == 0) return false;
        const auto t = static_cast<std::size_t>(m.halfedges[e]);
        flip_edge(m, e);
        counting.count(&Counters::lawson_flips);
        // The new point p was c, the apex of e's triangle (a, b, p). After the flip e's
        // triangle is (d, b, p) with d -> b at e, t's is (p, a, d) with a -> d at next(t):
        // the two edges now opposite p.
        stack.push_back(static_cast<std::int32_t>(e));
        stack.push_back(static_cast<std::int32_t>(next_halfedge(t)));
    }
    return true;
}

/// Lawson's algorithm over the whole mesh: flips illegal edges until none is left.
/// `budget` flips at most; false when it ran out.
template <InCirclePolicy P, PredicateKernel K, Instrumentation I>
bool flip_all(const K& k, std::span<const Point2> pts, Mesh& m, Counting<I>& counting,
              std::size_t budget) {
    const std::size_t slots = m.halfedges.size();
    // One mark per half-edge slot: an edge is queued at most once at a time (either of its
    // slots marked). A slot whose edge a flip replaced keeps its mark and is tested as
    // whatever edge it holds then: testing any edge is harmless.
    std::vector<std::uint8_t> queued(slots, 0);
    std::vector<std::int32_t> stack;
    stack.reserve(slots / 2);
    for (std::size_t e = slots; e-- > 0;) {
        const std::int32_t t = m.halfedges[e];
        if (t > static_cast<std::int32_t>(e) && m.triangles[e] != dead) {
            stack.push_back(static_cast<std::int32_t>(e));
            queued[e] = 1;
        }
    }
    auto push = [&](std::size_t e) {
        const std::int32_t t = m.halfedges[e];
        if (t < 0 || queued[e] || queued[static_cast<std::size_t>(t)]) return;
        queued[e] = 1;
        stack.push_back(static_cast<std::int32_t>(e));
    };
    while (!stack.empty()) {
        const auto e = static_cast<std::size_t>(stack.back());
        stack.pop_back();
        queued[e] = 0;
        if (m.halfedges[e] < 0 || !illegal<P>(k, pts, m, counting, e)) continue;
        if (budget-- == 0) return false;
        const auto t = static_cast<std::size_t>(m.halfedges[e]);
        flip_edge(m, e);
        counting.count(&Counters::lawson_flips);
        // The quadrilateral's four sides: e (d -> b), next(e) (b -> c), t (c -> a),
        // next(t) (a -> d).
        push(e);
        push(next_halfedge(e));
        push(t);
        push(next_halfedge(t));
    }
    return true;
}

}  // namespace exidel::delaunay::detail
