// exidel: the furthest-site Delaunay triangulation (scipy's and qhull's furthest_site).
//
// The triangulation of the points' extreme points (the corners of their convex hull; a
// point inside the hull or inside a hull edge is in none of its triangles) whose every
// triangle's circumcircle holds every point, on it or inside. Lifted to the paraboloid
// z = x^2 + y^2 it is the upper convex hull, as the Delaunay triangulation is the lower one;
// so, as for Delaunay, every edge being locally right implies the whole is: an interior
// edge ab of triangles abc and bad is right when d is not strictly outside the circle
// through a, b, c, i.e. incircle(a, b, c, d) >= 0 for abc counter-clockwise (the reverse of
// the Delaunay test). Where four or more extreme points are cocircular any triangulation of
// them is right, and which one is returned is unspecified.
//
// Chew's algorithm for a convex polygon ("Building Voronoi diagrams for convex polygons in
// linear expected time", Dartmouth TR PCS-TR90-147, 1990), with the test reversed: take the
// corners in a random order, delete them from the polygon from the last to the fourth,
// remembering each one's two neighbours when it left; then put them back from the fourth on,
// each as the triangle over the polygon edge between those two neighbours, followed by
// flips of the edges opposite it that the test says are wrong (Lawson's flips, as in
// lawson.hpp). Each flip makes the lifted surface strictly more concave, so none repeats
// with an exact kernel; every run is bounded all the same, and an inexact kernel gets a
// Failure (flips_exceeded), never a loop. Decided by the kernel's orient2d (the hull) and
// incircle alone.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exidel/delaunay/detail/brio.hpp"
#include "exidel/delaunay/hull.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay {

struct FurthestResult {
    /// triangles, halfedges: as Triangulation says (input indices, counter-clockwise);
    /// hull: the extreme points, counter-clockwise from the lexicographically smallest;
    /// collinear: fewer than three extreme points (no triangles); vertex_of_input and
    /// duplicates as for the Delaunay triangulation.
    Triangulation triangulation;
    std::optional<Failure> failure;
    bool ok() const noexcept { return !failure.has_value(); }
    /// As triangulate()'s Result (no counters), for code that handles both.
    Result to_result() && {
        Result r;
        r.triangulation = std::move(triangulation);
        r.failure = std::move(failure);
        return r;
    }
};

template <PredicateKernel K>
FurthestResult furthest_site_triangulation(std::span<const Point2> points, const K& k) {
    FurthestResult r;
    Triangulation& t = r.triangulation;
    detail::SortedInput in;
    if (auto f = detail::sort_and_dedupe(points, in)) {
        r.failure = std::move(f);
        return r;
    }
    t.vertex_of_input = std::move(in.vertex_of_input);
    t.duplicates = std::move(in.duplicates);
    SortedHull hull = sorted_convex_hull(points, k);
    if (hull.failure) {
        r.failure = std::move(hull.failure);
        return r;
    }
    const std::vector<std::uint32_t>& corner = hull.hull;  // polygon position -> input index
    const std::size_t h = corner.size();
    t.hull = corner;
    if (hull.collinear || h < 3) {
        t.collinear = true;
        return r;
    }
    // Polygon positions in a random order; delete from the last to the fourth.
    const std::vector<std::uint32_t> order = detail::random_order(h);
    std::vector<std::uint32_t> next(h), prev(h), left(h), right(h);
    for (std::uint32_t p = 0; p < h; ++p) {
        next[p] = static_cast<std::uint32_t>((p + 1) % h);
        prev[p] = static_cast<std::uint32_t>((p + h - 1) % h);
    }
    for (std::size_t i = h - 1; i >= 3; --i) {
        const std::uint32_t v = order[i];
        left[v] = prev[v], right[v] = next[v];
        next[prev[v]] = next[v];
        prev[next[v]] = prev[v];
    }
    auto& T = t.triangles;
    auto& H = t.halfedges;
    T.reserve(3 * (h - 2));
    H.reserve(3 * (h - 2));
    std::vector<std::int32_t> hull_edge(h, -1);  // position p -> the boundary half-edge p -> next
    const auto link = [&H](std::size_t a, std::int32_t b) {
        H[a] = b;
        if (b >= 0) H[static_cast<std::size_t>(b)] = static_cast<std::int32_t>(a);
    };
    const auto add_triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const std::size_t e = T.size();
        T.insert(T.end(), {a, b, c});
        H.insert(H.end(), {-1, -1, -1});
        return e;
    };
    {
        const std::uint32_t a = order[0], b = next[a], c = next[b];
        const std::size_t e = add_triangle(a, b, c);
        hull_edge[a] = static_cast<std::int32_t>(e);
        hull_edge[b] = static_cast<std::int32_t>(e + 1);
        hull_edge[c] = static_cast<std::int32_t>(e + 2);
    }
    const Point2* P = points.data();
    const auto at = [&](std::uint32_t p) { return P[corner[p]]; };
    std::uint64_t flips = 0;
    const std::uint64_t flip_bound = std::uint64_t{h} * h + 64;  // flips never repeat
    std::vector<std::size_t> stack;
    for (std::size_t i = 3; i < h; ++i) {
        const std::uint32_t v = order[i], u = left[v], w = right[v];
        // The triangle (u, v, w) over the boundary edge u -> w, which becomes interior.
        const std::size_t e = add_triangle(u, v, w);
        link(e + 2, hull_edge[u]);
        hull_edge[u] = static_cast<std::int32_t>(e);
        hull_edge[v] = static_cast<std::int32_t>(e + 1);
        next[u] = v, prev[v] = u, next[v] = w, prev[w] = v;
        stack.assign(1, e + 2);  // edges opposite v, to check
        while (!stack.empty()) {
            const std::size_t a_e = stack.back();
            stack.pop_back();
            const std::int32_t twin = H[a_e];
            if (twin < 0) continue;
            const auto f = static_cast<std::size_t>(twin);
            const std::size_t ne = next_halfedge(a_e), pe = prev_halfedge(a_e);
            const std::size_t nf = next_halfedge(f), pf = prev_halfedge(f);
            const std::uint32_t a = T[a_e], b = T[ne], c = T[pe], d = T[pf];
            if (k.incircle(at(a), at(b), at(c), at(d)) != Sign::negative) continue;
            if (++flips > flip_bound) {
                r.failure = Failure{
                    FailureKind::flips_exceeded, corner[v], i,
                    "furthest-site flips did not end after inserting corner " + std::to_string(i)};
                t.triangles.clear();
                t.halfedges.clear();
                return r;
            }
            // Flip ab to cd: (a, b, c) + (b, a, d) -> (a, d, c) + (d, b, c).
            const std::int32_t h_nf = H[nf], h_pf = H[pf], h_ne = H[ne];
            T[ne] = d;
            T[f] = d, T[nf] = b, T[pf] = c;
            link(a_e, h_nf);
            link(ne, static_cast<std::int32_t>(pf));
            link(f, h_pf);
            link(nf, h_ne);
            if (h_nf < 0) hull_edge[a] = static_cast<std::int32_t>(a_e);
            if (h_pf < 0) hull_edge[d] = static_cast<std::int32_t>(f);
            if (h_ne < 0) hull_edge[b] = static_cast<std::int32_t>(nf);
            stack.push_back(a_e);  // a -> d, opposite c = v
            stack.push_back(f);    // d -> b, opposite c = v
        }
    }
    for (std::uint32_t& p : T) p = corner[p];
    return r;
}

}  // namespace exidel::delaunay
