// exidel: the Bowyer-Watson algorithm (Bowyer 1981, Watson 1981) as a registered
// algorithm (algorithms.hpp: `bowyer-watson`). Each point p, in BRIO order (brio.hpp):
//
//   1. locate   a visibility walk from the last triangle created: cross an edge that p
//               is strictly beyond until none is left (p in the closed triangle) or the
//               walk leaves the hull (p outside);
//   2. cavity   grow from there, across edges, the triangles in conflict with p (whose
//               circumcircle strictly contains p);
//   3. connect  delete them and join p to every edge of the cavity's boundary.
//
// No super-triangle. The textbook version (and the seeds') encloses the points in a
// large triangle and deletes it at the end; its vertices are not at infinity, so edges
// near the hull come out wrong. Here the plane is closed into a sphere by one vertex at
// infinity, `inf` (CGAL's approach): every hull edge a->b has a ghost triangle
// (b, a, inf) behind it, whose "circumcircle" is the open half-plane beyond a->b. A
// ghost is in conflict with p when p is strictly beyond its edge, or on the edge's open
// segment (then the finite triangle on the other side conflicts too, and without the
// ghost p would be joined to a->b by a flat triangle). With these rules the cavity of a
// point outside the hull is its visible ghosts plus the finite triangles whose circles
// hold it, and one code path inserts inside and outside points alike. With an exact
// kernel the result is exactly the Delaunay triangulation of the points, hull and
// collinear hull points included.
//
// The in-circle policy. With `determinant` a finite triangle conflicts iff
// k.incircle(a, b, c, p) > 0. The paper's cosine test is exact only when p and the
// opposite vertex are strictly on opposite sides of an edge (Theorem 1), and inside a
// cavity p can be on either side of the edge the search crosses. But the search always
// crosses from a conflicting triangle T1 into T2 over an edge xy of a Delaunay
// triangulation, and there T1's apex is not inside T2's circle; two circles through x
// and y are then nested on each side of the line xy, T2's being the larger on T2's side.
// So if p (strictly inside T1's circle, or beyond T1's edge for a ghost) is not strictly
// on the far side of xy from T2's apex, p is strictly inside T2's circle: T2 conflicts
// with no in-circle test. Otherwise Theorem 1's precondition holds and the cosine test
// decides. So `cosine` applies to every in-circle test bowyer-watson makes, at the price
// of one orientation before each; both policies give the same cavities with an exact
// kernel.
//
// With an inexact kernel every step is bounded and checked: the walk by the number of
// triangles (with exact signs it never revisits one: a Delaunay triangulation has no
// visibility cycle, Edelsbrunner 1990), the cavity search by marks, and the cavity's
// boundary must be one simple cycle (each vertex once), else cavity_inconsistent: then
// the sphere stays a sphere whatever the signs were, and a wrong answer is a wrong
// triangulation, never a broken structure.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/brio.hpp"
#include "exidel/delaunay/detail/counting.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

/// p lies strictly between a and b, given that the three are collinear: lexicographic
/// comparison of the coordinates is then exact and needs no kernel.
inline bool strictly_between(Point2 a, Point2 b, Point2 p) noexcept {
    const auto less = [](Point2 u, Point2 v) { return u.x < v.x || (u.x == v.x && u.y < v.y); };
    return (less(a, p) && less(p, b)) || (less(b, p) && less(p, a));
}

template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
class CavityInserter : Counting<I> {
public:
    /// `pts` distinct, in insertion order; `input_of` maps a position to its input index.
    /// run() may swap the third point of the first triangle into position 2 (in `pts`,
    /// `input_of` and, when not empty, `along`: another array of the same size, kept in
    /// step).
    CavityInserter(const K& kernel, std::span<Point2> pts, std::span<std::uint32_t> input_of,
                   std::span<std::uint32_t> along = {})
        : k_(kernel),
          pts_(pts),
          input_of_(input_of),
          along_(along),
          inf_(static_cast<std::uint32_t>(pts.size())) {}

    /// Builds into `mesh` (replaced). On failure the mesh is meaningless.
    std::optional<Failure> run(Mesh& mesh) {
        const std::size_t n = pts_.size();
        mesh = Mesh{};
        if (n < 3 || !choose_first_triangle()) {
            mesh.collinear = true;
            return std::nullopt;
        }
        m_ = &mesh;
        mesh.reset(n + 1);            // ids 0..n-1 and inf = n
        mark_.assign(2 * n + 16, 0);  // a sphere of n + 1 vertices has 2n - 2 triangles
        vertex_stamp_.assign(n + 1, 0);
        next_on_boundary_.assign(n + 1, 0);
        new_triangle_of_.assign(n + 1, 0);
        seed();
        for (std::size_t i = 3; i < n; ++i) {
            if (auto failure = insert(static_cast<std::uint32_t>(i))) return failure;
        }
        finish();
        return std::nullopt;
    }

    const Counters& counters() const noexcept { return this->counters_; }

private:
    // One edge of the cavity's boundary: u -> v, seen from inside (a half-edge of a
    // cavity triangle), and its twin outside. t: the triangle (u, v, p) that replaces it.
    struct Edge {
        std::uint32_t u, v;
        std::int32_t outside;
        std::uint32_t t;
    };

    Sign orient(std::uint64_t Counters::*counter, std::uint32_t a, std::uint32_t b, Point2 p) {
        this->count(counter);
        return k_.orient2d(pts_[a], pts_[b], p);
    }
    bool is_ghost(std::size_t t) const {
        const auto& tris = m_->triangles;
        return tris[3 * t] == inf_ || tris[3 * t + 1] == inf_ || tris[3 * t + 2] == inf_;
    }
    std::optional<Failure> fail(FailureKind kind, std::uint32_t i, std::string what) const {
        return Failure{kind, input_of_[i], i,
                       "insertion of point " + std::to_string(i) + " of the order (input index " +
                           std::to_string(input_of_[i]) + "): " + std::move(what)};
    }

    // Finds the first point off the line of points 0 and 1 and moves it to position 2,
    // counter-clockwise. False: every point is on that line.
    bool choose_first_triangle() {
        for (std::size_t j = 2; j < pts_.size(); ++j) {
            this->count(&Counters::seed_orientations);
            const Sign s = k_.orient2d(pts_[0], pts_[1], pts_[j]);
            if (s == Sign::zero) continue;
            auto swap = [&](std::size_t a, std::size_t b) {
                std::swap(pts_[a], pts_[b]);
                std::swap(input_of_[a], input_of_[b]);
                if (!along_.empty()) std::swap(along_[a], along_[b]);
            };
            swap(2, j);
            if (s == Sign::negative) swap(1, 2);
            return true;
        }
        return false;
    }

    // Triangle (0, 1, 2) and the three ghosts behind its edges, linked into a sphere.
    void seed() {
        Mesh& m = *m_;
        m.add_triangle(0, 1, 2);     // half-edges 0: 0->1, 1: 1->2, 2: 2->0
        m.add_triangle(1, 0, inf_);  // 3: 1->0, 4: 0->inf, 5: inf->1
        m.add_triangle(2, 1, inf_);  // 6: 2->1, 7: 1->inf, 8: inf->2
        m.add_triangle(0, 2, inf_);  // 9: 0->2, 10: 2->inf, 11: inf->0
        m.link(0, 3);
        m.link(1, 6);
        m.link(2, 9);
        m.link(4, 11);
        m.link(7, 5);
        m.link(10, 8);
        this->count(&Counters::triangles_created);
        last_ = 0;
    }

    // Step 1: the visibility walk from the last triangle created. Returns a triangle in
    // conflict with p: finite with p in its closed interior, or a ghost whose edge p is
    // strictly beyond. The edge the walk came in by is not tested again; the others are
    // tried from a rotating start, which keeps the walk from favouring one direction.
    std::optional<std::uint32_t> locate(Point2 p) {
        const auto& tris = m_->triangles;
        const auto& half = m_->halfedges;
        std::uint32_t t = last_;
        std::int32_t came_in = -1;
        const std::size_t bound = m_->live_triangles();
        for (std::size_t steps = 0; steps <= bound; ++steps) {
            this->count(&Counters::location_steps);
            if (is_ghost(t)) return t;
            rotation_ = rotation_ == 2 ? 0 : rotation_ + 1;
            bool crossed = false;
            for (unsigned r = 0; r < 3 && !crossed; ++r) {
                const std::size_t e = 3 * std::size_t{t} + (rotation_ + r) % 3;
                if (static_cast<std::int32_t>(e) == came_in) continue;
                if (orient(&Counters::location_orientations, tris[e], tris[next_halfedge(e)], p) ==
                    Sign::negative) {
                    came_in = half[e];
                    if (came_in < 0) return std::nullopt;  // never with a closed sphere
                    t = static_cast<std::uint32_t>(came_in / 3);
                    crossed = true;
                }
            }
            if (!crossed) return t;
        }
        return std::nullopt;
    }

    // Step 2's question for a triangle t next to the cavity, reached over its half-edge
    // `shared` (x -> y, the cavity on its right): is t in conflict with p?
    bool conflicts(std::size_t t, std::size_t shared, Point2 p) {
        const auto& tris = m_->triangles;
        if (is_ghost(t)) {
            // The ghost's finite half-edge x -> y: its hull edge is y -> x, and p conflicts
            // when strictly beyond that (on the left of x -> y) or on its open segment.
            std::size_t e = 3 * t;
            for (unsigned j = 0; j < 2 && (tris[e] == inf_ || tris[next_halfedge(e)] == inf_);
                 ++j) {
                e = next_halfedge(e);
            }
            const std::uint32_t x = tris[e], y = tris[next_halfedge(e)];
            const Sign s = orient(&Counters::cavity_orientations, x, y, p);
            return s == Sign::positive ||
                   (s == Sign::zero && strictly_between(pts_[x], pts_[y], p));
        }
        const Point2 x = pts_[tris[shared]], y = pts_[tris[next_halfedge(shared)]];
        const Point2 d = pts_[tris[prev_halfedge(shared)]];  // on the left of x -> y
        if constexpr (P == InCirclePolicy::cosine) {
            // Not strictly on the far side of x -> y: in conflict by the nesting argument
            // above (exact kernels); otherwise Theorem 1 holds and the cosine test decides.
            this->count(&Counters::cavity_orientations);
            if (k_.orient2d(x, y, p) != Sign::negative) return true;
        }
        return this->template in_circle_by_policy<P>(k_, x, y, d, p);
    }

    // Marks of the cavity search, per triangle slot: 2 stamp in the cavity, 2 stamp + 1
    // tested and not in it (a triangle can border the cavity on two edges: one test).
    std::uint64_t& mark(std::size_t t) {
        if (t >= mark_.size()) mark_.resize(2 * t + 16, 0);  // slots grow by the cavity's excess
        return mark_[t];
    }

    std::optional<Failure> insert(std::uint32_t i) {
        Mesh& m = *m_;
        const Point2 p = pts_[i];
        const auto located = locate(p);
        if (!located) {
            return fail(FailureKind::location_exceeded, i,
                        "the walk from the last triangle passed more triangles than there are");
        }

        // Step 2: the cavity, grown depth-first from the located triangle.
        ++stamp_;
        const std::uint64_t in = 2 * stamp_, out = in + 1;
        cavity_.clear();
        boundary_.clear();
        stack_.assign(1, *located);
        mark(*located) = in;
        while (!stack_.empty()) {
            const std::uint32_t c = stack_.back();
            stack_.pop_back();
            cavity_.push_back(c);
            for (std::size_t e = 3 * std::size_t{c}; e < 3 * std::size_t{c} + 3; ++e) {
                const std::int32_t h = m.halfedges[e];
                if (h < 0)
                    return fail(FailureKind::cavity_inconsistent, i,
                                "a cavity triangle has an open edge");
                const auto t = static_cast<std::uint32_t>(h / 3);
                std::uint64_t& tm = mark(t);
                if (tm == in) {
                    if (c < t && !is_ghost(c) && !is_ghost(t)) this->count(&Counters::eroded_edges);
                    continue;
                }
                if (tm != out && conflicts(t, static_cast<std::size_t>(h), p)) {
                    tm = in;
                    stack_.push_back(t);
                    continue;
                }
                tm = out;
                boundary_.push_back({m.triangles[e], m.triangles[next_halfedge(e)], h, 0});
            }
        }

        // The boundary must be one simple cycle: each vertex starts exactly one edge, and
        // following the edges from the first returns to it after all of them. An inexact
        // kernel can put every triangle of the sphere in conflict (p beyond every hull edge
        // and inside every circumcircle), which leaves no boundary at all (found by the
        // libFuzzer harness, fuzz/corpus/triangulate/double_bowyer_watson_whole_sphere.raw).
        if (boundary_.empty()) {
            return fail(FailureKind::cavity_inconsistent, i,
                        "every triangle conflicts with the point: the cavity is the whole sphere");
        }
        for (const Edge& b : boundary_) {
            if (vertex_stamp_[b.u] == stamp_) {
                return fail(FailureKind::cavity_inconsistent, i,
                            "vertex " + std::to_string(b.u) + " is twice on the cavity's boundary");
            }
            vertex_stamp_[b.u] = stamp_;
            next_on_boundary_[b.u] = b.v;
        }
        std::uint32_t v = boundary_.front().u;
        for (std::size_t k = 0; k < boundary_.size(); ++k) {
            if (vertex_stamp_[v] != stamp_ || (k > 0 && v == boundary_.front().u)) {
                return fail(FailureKind::cavity_inconsistent, i,
                            "the cavity's boundary is not one cycle");
            }
            v = next_on_boundary_[v];
        }
        if (v != boundary_.front().u || boundary_.size() < 3) {
            return fail(FailureKind::cavity_inconsistent, i,
                        "the cavity's boundary is not one cycle");
        }

        // Step 3: the cavity's triangles go, p is joined to each boundary edge.
        for (const std::uint32_t c : cavity_) {
            if (!is_ghost(c)) this->count(&Counters::triangles_destroyed);
            m.remove_triangle(c);
        }
        for (Edge& b : boundary_) {
            b.t = m.add_triangle(b.u, b.v, i);  // half-edges: u->v, v->p, p->u
            m.link(static_cast<std::int32_t>(3 * b.t), b.outside);
            new_triangle_of_[b.u] = b.t;
            if (b.u != inf_ && b.v != inf_) {
                this->count(&Counters::triangles_created);
                last_ = b.t;
            }
        }
        for (const Edge& b : boundary_) {
            m.link(static_cast<std::int32_t>(3 * b.t + 1),
                   static_cast<std::int32_t>(3 * new_triangle_of_[b.v] + 2));
        }
        return std::nullopt;
    }

    // The sphere back to a plane triangulation: each ghost (x, y, inf) names hull edge
    // y -> x, whose finite half-edge becomes a boundary edge (-1); the ghosts go. A
    // vertex off the hull has hull_next `dead`, as in the external algorithm's meshes.
    void finish() {
        Mesh& m = *m_;
        m.hull_size = 0;
        std::fill(m.hull_next.begin(), m.hull_next.end(), dead);
        const std::size_t slots = m.triangles.size() / 3;
        for (std::size_t t = 0; t < slots; ++t) {
            if (m.triangles[3 * t] == dead || !is_ghost(t)) continue;
            for (std::size_t e = 3 * t; e < 3 * t + 3; ++e) {
                if (m.triangles[e] == inf_ || m.triangles[next_halfedge(e)] == inf_) continue;
                // a -> b, finite (a ghost's finite edge always borders a finite triangle:
                // a cavity's boundary cycle has at least three vertices, inf once).
                if (m.halfedges[e] < 0 || is_ghost(static_cast<std::size_t>(m.halfedges[e]) / 3))
                    continue;
                const auto f = static_cast<std::size_t>(m.halfedges[e]);
                const std::uint32_t a = m.triangles[f], b = m.triangles[next_halfedge(f)];
                m.set_hull_next(a, b);
                m.hull_edge[a] = static_cast<std::int32_t>(f);
                m.halfedges[f] = -1;
                ++m.hull_size;
            }
            m.remove_triangle(t);
        }
    }

    const K& k_;
    std::span<Point2> pts_;
    std::span<std::uint32_t> input_of_;
    std::span<std::uint32_t> along_;
    const std::uint32_t inf_;
    Mesh* m_ = nullptr;
    std::uint32_t last_ = 0;   // a finite triangle made by the last insertion
    unsigned rotation_ = 0;    // the walk's first edge, rotating
    std::uint64_t stamp_ = 0;  // one per insertion
    std::vector<std::uint64_t> mark_;
    std::vector<std::uint64_t> vertex_stamp_;      // vertex -> stamp when on the boundary
    std::vector<std::uint32_t> next_on_boundary_;  // vertex u -> v of its boundary edge
    std::vector<std::uint32_t> new_triangle_of_;   // vertex u -> the new triangle (u, v, p)
    std::vector<std::uint32_t> cavity_, stack_;
    std::vector<Edge> boundary_;
};

struct BowyerWatson {
    template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
    static void run(const K& kernel, const SortedInput& in, const Options&, MeshOutput& out,
                    Result& result) {
        const std::size_t n = in.points.size();
        const std::vector<std::uint32_t> order = brio_order(in.points);
        std::vector<Point2> local(n);
        out.input_of.resize(n);
        for (std::size_t j = 0; j < n; ++j) {
            local[j] = in.points[order[j]];
            out.input_of[j] = in.input_of[order[j]];
        }
        CavityInserter<K, I, P> inserter(kernel, local, out.input_of);
        result.failure = inserter.run(out.mesh);
        result.counters = inserter.counters();
        // The hull is written from sorted position 0, wherever the order put it (the
        // input indices are those of first occurrences, hence distinct).
        for (std::size_t j = 0; j < n; ++j) {
            if (out.input_of[j] == in.input_of.front()) out.first = static_cast<std::uint32_t>(j);
        }
    }
};

}  // namespace exidel::delaunay::detail
