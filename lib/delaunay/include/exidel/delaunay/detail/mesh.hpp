// exidel: the mesh every algorithm builds on: a triangulation under construction in the
// index arrays of Triangulation (delaunator's layout), plus the hull as a linked cycle and
// a free list of deleted triangle slots. Vertex ids are positions in the point sequence
// the algorithm was given (sorted positions, or an insertion order); to_triangulation
// turns a finished mesh into input indices.
//
//   triangles[3t..3t+2]  the vertices of slot t, counter-clockwise; `dead` in all three
//                        when the slot is free
//   halfedges[e]         the twin of half-edge e (from triangles[e] to
//                        triangles[next_halfedge(e)]), -1 on the boundary
//   hull_next/hull_prev  the hull as a counter-clockwise cycle of vertex ids; hull_edge[v]
//                        the half-edge v -> hull_next[v]
//
// Algorithms that rebuild parts of the arrays in parallel (the strips' merges) keep their
// own free lists per piece, since one shared list would be written by several threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <vector>

#include "exidel/delaunay/detail/memory.hpp"
#include "exidel/delaunay/result.hpp"

namespace exidel::delaunay::detail {

/// Vertex slot of a deleted triangle, and hull_next of a vertex no longer on the hull.
inline constexpr std::uint32_t dead = 0xffffffffu;

struct Mesh {
    std::vector<std::uint32_t> triangles;
    std::vector<std::int32_t> halfedges;
    // Internal arrays, in fresh memory (memory.hpp); triangles and halfedges become the
    // Triangulation's.
    FreshVector<std::uint32_t> hull_next, hull_prev;  // the hull as a linked cycle
    FreshVector<std::int32_t> hull_edge;              // v -> the half-edge v -> hull_next[v]
    std::size_t hull_size = 0;
    bool collinear = false;           // no triangle: every point on one line
    std::vector<std::uint32_t> free;  // slots of deleted triangles, reused first (LIFO)

    /// Empties the mesh and sizes the hull arrays for `vertices` ids, with room for the
    /// 2 vertices - 5 triangles (plus a margin for deleted slots) of a triangulation.
    /// Keeps the arrays' memory, so a mesh reused run after run (the strips') allocates
    /// once.
    void reset(std::size_t vertices) {
        clear();
        hull_next.assign(vertices, 0);
        hull_prev.assign(vertices, 0);
        hull_edge.assign(vertices, -1);
        triangles.reserve(6 * vertices);
        halfedges.reserve(6 * vertices);
    }

    /// An empty mesh (no triangle, not collinear), keeping the arrays' memory.
    void clear() noexcept {
        triangles.clear();
        halfedges.clear();
        hull_next.clear();
        hull_prev.clear();
        hull_edge.clear();
        hull_size = 0;
        collinear = false;
        free.clear();
    }

    /// Triangles in use (slots minus free slots).
    std::size_t live_triangles() const noexcept { return triangles.size() / 3 - free.size(); }

    /// A new triangle (a, b, c), counter-clockwise, in the most recently freed slot or a
    /// new one. Its half-edges' twins are left to the caller (new slots start at -1).
    [[gnu::always_inline]] std::uint32_t add_triangle(std::uint32_t a, std::uint32_t b,
                                                      std::uint32_t c) {
        std::uint32_t t;
        if (!free.empty()) {
            t = free.back();
            free.pop_back();
            triangles[3 * t] = a;
            triangles[3 * t + 1] = b;
            triangles[3 * t + 2] = c;
        } else {
            t = static_cast<std::uint32_t>(triangles.size() / 3);
            // push_back each: inserting an initializer_list is not inlined as well.
            triangles.push_back(a);
            triangles.push_back(b);
            triangles.push_back(c);
            halfedges.push_back(-1);
            halfedges.push_back(-1);
            halfedges.push_back(-1);
        }
        return t;
    }

    /// Frees slot t (its vertices become `dead`; its half-edges are left as they were).
    void remove_triangle(std::size_t t) {
        triangles[3 * t] = triangles[3 * t + 1] = triangles[3 * t + 2] = dead;
        free.push_back(static_cast<std::uint32_t>(t));
    }

    /// Makes a and b twins; b may be -1 (a becomes a boundary half-edge).
    void link(std::int32_t a, std::int32_t b) {
        halfedges[static_cast<std::size_t>(a)] = b;
        if (b >= 0) halfedges[static_cast<std::size_t>(b)] = a;
    }

    /// b follows a on the hull.
    void set_hull_next(std::uint32_t a, std::uint32_t b) {
        hull_next[a] = b;
        hull_prev[b] = a;
    }
};

/// What an algorithm hands to triangulate(): its finished mesh and how to read its ids.
struct MeshOutput {
    Mesh mesh;
    /// Mesh vertex id -> input index; empty when the ids are sorted positions.
    std::vector<std::uint32_t> input_of;
    /// The mesh id of sorted position 0 (the lexicographically smallest point, always a
    /// hull vertex: the hull is written from it).
    std::uint32_t first = 0;
};

/// Writes `mesh` (vertex ids; dead slots allowed) as a Triangulation of input indices,
/// `input_of[id]`, with the hull starting at id `first` (the lexicographically smallest
/// point, always a hull vertex). Live triangles keep their relative order. Consumes the
/// mesh's triangle arrays. `threads` share the work; the result does not depend on it.
std::optional<Failure> to_triangulation(Mesh& mesh, std::span<const std::uint32_t> input_of,
                                        std::uint32_t first, Triangulation& tri,
                                        unsigned threads = 1);

}  // namespace exidel::delaunay::detail
