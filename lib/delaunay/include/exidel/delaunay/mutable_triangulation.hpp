// exidel: a Delaunay triangulation that changes: points inserted and removed one at a time.
//
// Ids. Every insert() issues the next id (0, 1, 2, ...), as if the point were appended to
// the input of triangulate(): a point equal to one already present gets an id too, and is
// a copy of it (as a repeated input point is), not a new vertex. An id stays valid until it
// is removed; ids are never reused. A point is a vertex while at least one of its ids is
// live, and the vertex is named by its smallest live id (the "first occurrence", as in
// Triangulation). remove(id) drops that id; when it was the point's last id the vertex
// leaves the triangulation.
//
// Insertion. The new point is located by the walk of locate.hpp (from a hint vertex, or
// from the nearest, in rounded distance, of a sample of about sqrt(n) / 2 vertices kept as
// they come: jump-and-walk), then the triangle holding it is split in three, the edge
// holding it in two or four triangles, or, outside the hull, the point is joined to every
// hull edge that sees it strictly (a hull edge it lies on the line of keeps its end as a
// collinear hull vertex). Lawson's flips then restore the Delaunay property: an edge whose
// opposite vertex lies strictly inside the circle of the triangle on its other side is
// flipped, and every flip makes the new point the apex of two edges tested in turn.
// Points on a circle never cause a flip.
//
// Removal. The triangles around the vertex v are deleted and the hole is filled.
//   - v inside the hull: the hole is the polygon of v's neighbours, simple and
//     star-shaped from v. It is cut into triangles by ear clipping: an ear u_(i-1) u_i
//     u_(i+1) is cut when u_i is a strict left turn and no other polygon vertex lies in the
//     closed triangle. While v lies strictly inside the remaining polygon, an ear with v
//     strictly left of u_(i-1) -> u_(i+1) needs no scan: the angle it spans at v is below
//     180 degrees, so it lies in the two old triangles v u_(i-1) u_i and v u_i u_(i+1), and
//     every other vertex lies in another direction from v. Such ears are taken first; the
//     scan decides the others (a grid point's neighbours on its diagonals leave none).
//   - v on the hull: its neighbours form a chain u_0 = hull_next(v), ..., u_k =
//     hull_prev(v), sorted by angle around v. The new hull between u_k and u_0 is the
//     convex hull of the chain on v's side: a stack scan over the chain that pops a point
//     where the chain turns strictly left (collinear points stay hull vertices, as
//     Triangulation requires). Each pocket between the chain and a new hull edge is a
//     simple polygon and is filled by ear clipping as above (without the shortcut). When
//     every remaining point lies on one line there are no triangles left, and the
//     triangulation becomes a chain of collinear points again.
//   Then Lawson's flips run over the new edges (and the sides of every flipped
//   quadrilateral that are inside the hole: a side on its border is locally Delaunay by
//   point 2 below) until none has its opposite vertex strictly inside a circle.
//
// Why the result is a Delaunay triangulation, cocircular points included (the tie-break
// the issue asks for is: no flip on a circle, so any triangulation of cocircular points
// that the filling and the flips leave is kept, and each of them is Delaunay):
//   1. An edge of a triangulation is locally Delaunay when the apex of either triangle is
//      not strictly inside the circle of the other. The test is symmetric: for triangles
//      (a, b, c) and (b, a, d), incircle(b, a, d, c) = incircle(a, b, c, d), two
//      transpositions of the arguments.
//   2. Every edge on the border of the hole is locally Delaunay whatever fills the hole:
//      the triangle outside it belonged to a Delaunay triangulation of the points before
//      the removal, so no point at all, and in particular no apex inside the hole, lies
//      strictly inside its circle. A new hull edge has one triangle and nothing to test.
//   3. Lawson's flips inside the hole end, with an exact kernel: a flipped edge is one
//      whose opposite vertex lies strictly inside the circle, and the quadrilateral of such
//      an edge is strictly convex (so the flip is possible) and the flip strictly lowers
//      the triangulation lifted to the paraboloid z = x^2 + y^2, so no edge flipped away
//      comes back: at most m (m - 1) / 2 flips for a hole of m vertices. They end with
//      every edge inside the hole locally Delaunay.
//   4. A triangulation of the convex hull of a point set in which every edge is locally
//      Delaunay is a Delaunay triangulation (Delaunay's lemma; the non-strict form holds
//      with the same proof, Edelsbrunner, "Geometry and Topology for Mesh Generation",
//      Section 1.2). With 2 and 3, every edge is.
//   Insertion is the same argument: Lawson's flips from the new point end (at most one
//   flip per new neighbour) with every edge locally Delaunay.
//   Ear clipping always finds an ear in a simple polygon (Meisters, "Polygons have ears",
//   Amer. Math. Monthly 82, 1975), and the hole and the pockets are simple polygons.
//
// Every loop is bounded: with an inexact kernel an operation that finds the structure
// inconsistent throws FailureError (location_exceeded, location_inconsistent,
// flips_exceeded, update_inconsistent), and the object refuses further changes
// (std::logic_error), since its triangles may then be neither Delaunay nor valid.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/flips.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/locate.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay {

/// The live points of a MutableTriangulation as triangulate() would return them: position
/// i is id ids[i] (increasing; every live id, copies of a point included), at points[i],
/// and `triangulation` indexes positions (its vertex_of_input and duplicates say which
/// positions are copies). certify(points, triangulation) judges it like any result.
struct MutableSnapshot {
    std::vector<std::uint32_t> ids;
    std::vector<Point2> points;
    Triangulation triangulation;
};

template <PredicateKernel K>
class MutableTriangulation {
public:
    /// An empty triangulation.
    explicit MutableTriangulation(K kernel = K{}) : k_(std::move(kernel)) {}
    /// The triangulation of `points` (ids 0 .. n - 1), built by triangulate() with
    /// `options`. Throws FailureError when triangulate() fails.
    explicit MutableTriangulation(std::span<const Point2> points, K kernel = K{},
                                  const Options& options = {});

    /// Inserts p and returns its id. Throws FailureError: non_finite_input for a NaN or
    /// infinite coordinate (nothing changes), too_many_points past the 32-bit limit, or an
    /// inconsistency of an inexact kernel (see the top of the file).
    std::uint32_t insert(Point2 p);
    /// The same, with the walk starting at the vertex of id `near` (a live id; else
    /// std::out_of_range).
    std::uint32_t insert(Point2 p, std::uint32_t near);
    /// Removes id. Throws std::out_of_range for an id never issued or already removed, and
    /// FailureError for an inexact kernel's inconsistency.
    void remove(std::uint32_t id);

    bool contains(std::uint32_t id) const noexcept {
        return id < rep_.size() && rep_[id] != detail::dead;
    }
    /// The vertex a live id belongs to: the smallest live id at its point.
    std::uint32_t vertex_of(std::uint32_t id) const {
        check_live(id, "vertex_of");
        return rep_[id];
    }
    /// The coordinates of any id ever issued (removed ones too).
    Point2 point(std::uint32_t id) const {
        if (id >= pts_.size()) throw std::out_of_range("point: no id " + std::to_string(id));
        return pts_[id];
    }
    std::size_t size() const noexcept { return live_ids_; }               ///< live ids
    std::size_t vertex_count() const noexcept { return live_vertices_; }  ///< distinct points
    std::uint32_t id_count() const noexcept { return static_cast<std::uint32_t>(pts_.size()); }
    /// No triangles: fewer than three distinct points, or all on one line.
    bool collinear() const noexcept { return !planar_; }

    /// Where q lies (Location of locate.hpp; `triangle` and `edge` are slots of mesh(),
    /// `vertex` an id). Throws as insert does.
    Location locate(Point2 q);
    /// The vertex (an id, see vertex_of) nearest to q, decided exactly as
    /// Locator::nearest does; no_vertex when empty.
    std::uint32_t nearest(Point2 q);

    MutableSnapshot snapshot() const;
    /// The mesh itself: triangles, twins, hull cycle, free slots, by id (mesh.hpp).
    const detail::Mesh& mesh() const noexcept { return mesh_; }
    const K& kernel() const noexcept { return k_; }

private:
    void check_live(std::uint32_t id, const char* what) const {
        if (!contains(id)) {
            throw std::out_of_range(std::string(what) + ": id " + std::to_string(id) +
                                    (id < rep_.size() ? " was removed" : " was never issued"));
        }
    }
    void check_usable() const {
        if (broken_) {
            throw std::logic_error(
                "MutableTriangulation: an earlier operation failed and left it inconsistent");
        }
    }
    [[noreturn]] void fail(FailureKind kind, std::size_t index, std::string message) {
        broken_ = true;
        throw FailureError(Failure{kind, index, no_index, std::move(message)});
    }
    std::uint32_t new_id(Point2 p);
    std::uint32_t insert_at(Point2 p, std::int32_t start);
    void insert_collinear(std::uint32_t id);
    void add_copy(std::uint32_t rep, std::uint32_t id);
    void rename_vertex(std::uint32_t from, std::uint32_t to);
    void remove_vertex(std::uint32_t v);
    std::uint32_t make(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    void attach(std::int32_t half, std::int32_t outside);
    void legalize(std::size_t budget, std::uint32_t id, bool removal);
    bool in_hole(std::uint32_t t) const noexcept;
    bool star(std::uint32_t v);
    bool fill(std::span<const std::uint32_t> poly, std::span<std::int32_t> handle,
              const Point2* centre);
    std::int32_t start_triangle(Point2 q) const;
    Location walk(Point2 q, std::int32_t start);
    bool lex_less(Point2 a, Point2 b) const noexcept {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    }

    K k_;
    std::vector<Point2> pts_;               // id -> coordinates
    std::vector<std::uint32_t> rep_;        // id -> the vertex's id, dead once removed
    std::vector<std::uint32_t> next_copy_;  // vertex/copy id -> next live copy, dead at the end
    std::vector<std::int32_t> edge_;        // vertex id -> a half-edge out of it, -1 without
    detail::Mesh mesh_;                     // triangles and hull, by vertex id
    std::vector<std::uint32_t> chain_;      // without triangles: the vertices, lexicographic
    std::vector<std::uint32_t> sample_;     // jump-and-walk starts (vertex ids, some stale)
    std::vector<Point2> sample_points_;     // their coordinates, scanned contiguously
    std::size_t live_ids_ = 0, live_vertices_ = 0;
    std::uint32_t hull_any_ = detail::dead;  // some hull vertex
    std::int32_t last_ = -1;                 // the triangle of the last operation
    bool planar_ = false;
    bool broken_ = false;
    detail::WalkRandom random_;
    // Scratch of remove(), kept to avoid allocating per call.
    std::vector<std::int32_t> star_, handle_, stack_;
    std::vector<std::uint32_t> ring_, pool_, hull_stack_, prev_, next_;
    std::vector<std::uint32_t> hole_;  // the removed vertex's triangles, sorted when many
    static constexpr std::size_t hole_scan = 32;
};

// ---------------------------------------------------------------------------------------

template <PredicateKernel K>
MutableTriangulation<K>::MutableTriangulation(std::span<const Point2> points, K kernel,
                                              const Options& options)
    : k_(std::move(kernel)) {
    Result r = triangulate(points, k_, options);
    if (!r.ok()) throw FailureError(std::move(*r.failure));
    const Triangulation& t = r.triangulation;
    const std::size_t n = points.size();
    pts_.assign(points.begin(), points.end());
    rep_ = t.vertex_of_input;
    next_copy_.assign(n, detail::dead);
    edge_.assign(n, -1);
    std::vector<std::uint32_t> tail(n);  // vertex -> its last copy so far
    for (std::uint32_t i = 0; i < n; ++i) tail[i] = i;
    for (const std::uint32_t d : t.duplicates) {
        next_copy_[tail[rep_[d]]] = d;
        tail[rep_[d]] = d;
    }
    live_ids_ = n;
    live_vertices_ = n - t.duplicates.size();
    mesh_.hull_next.assign(n, detail::dead);
    mesh_.hull_prev.assign(n, detail::dead);
    mesh_.hull_edge.assign(n, -1);
    if (t.collinear) {
        chain_ = t.hull;
    } else {
        planar_ = true;
        mesh_.triangles = t.triangles;
        mesh_.halfedges = t.halfedges;
        for (std::size_t e = 0; e < t.triangles.size(); ++e) {
            edge_[t.triangles[e]] = static_cast<std::int32_t>(e);
            if (t.halfedges[e] < 0) mesh_.hull_edge[t.triangles[e]] = static_cast<std::int32_t>(e);
        }
        for (std::size_t i = 0; i < t.hull.size(); ++i) {
            mesh_.set_hull_next(t.hull[i], t.hull[(i + 1) % t.hull.size()]);
        }
        mesh_.hull_size = t.hull.size();
        hull_any_ = t.hull.front();
        last_ = 0;
    }
    // The jump-and-walk sample: vertices spread through the input order.
    std::size_t want = 1;
    while (4 * want * want < live_vertices_) ++want;
    const std::size_t stride = std::max<std::size_t>(1, n / want);
    for (std::size_t i = 0; i < n; i += stride) {
        if (rep_[i] == i) {
            sample_.push_back(static_cast<std::uint32_t>(i));
            sample_points_.push_back(pts_[i]);
        }
    }
}

template <PredicateKernel K>
std::uint32_t MutableTriangulation<K>::new_id(Point2 p) {
    if (pts_.size() >= detail::max_points) {
        throw FailureError(Failure{FailureKind::too_many_points, pts_.size(), no_index,
                                   "more than " + std::to_string(detail::max_points) +
                                       " ids: 32-bit half-edge indices cannot address them"});
    }
    const auto id = static_cast<std::uint32_t>(pts_.size());
    pts_.push_back(p);
    rep_.push_back(id);
    next_copy_.push_back(detail::dead);
    edge_.push_back(-1);
    mesh_.hull_next.push_back(detail::dead);
    mesh_.hull_prev.push_back(detail::dead);
    mesh_.hull_edge.push_back(-1);
    ++live_ids_;
    return id;
}

/// A new triangle (a, b, c); each corner's edge_ becomes its half-edge out of it. The
/// caller links all three half-edges.
template <PredicateKernel K>
std::uint32_t MutableTriangulation<K>::make(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || c == a) {  // only an inexact kernel's answers lead here
        fail(FailureKind::update_inconsistent, a,
             "a new triangle would repeat a vertex (" + std::to_string(a) + ", " +
                 std::to_string(b) + ", " + std::to_string(c) + ")");
    }
    std::uint32_t t;
    if (!pool_.empty()) {  // a slot of the hole being filled
        t = pool_.back();
        pool_.pop_back();
        mesh_.triangles[3 * t] = a;
        mesh_.triangles[3 * t + 1] = b;
        mesh_.triangles[3 * t + 2] = c;
    } else {
        t = mesh_.add_triangle(a, b, c);
    }
    edge_[a] = static_cast<std::int32_t>(3 * t);
    edge_[b] = static_cast<std::int32_t>(3 * t + 1);
    edge_[c] = static_cast<std::int32_t>(3 * t + 2);
    return t;
}

/// Makes `half` the twin of `outside`; -1 makes it a hull edge, which hull_edge follows.
template <PredicateKernel K>
void MutableTriangulation<K>::attach(std::int32_t half, std::int32_t outside) {
    mesh_.link(half, outside);
    if (outside < 0) mesh_.hull_edge[mesh_.triangles[static_cast<std::size_t>(half)]] = half;
}

template <PredicateKernel K>
void MutableTriangulation<K>::add_copy(std::uint32_t rep, std::uint32_t id) {
    rep_[id] = rep;
    std::uint32_t c = rep;
    while (next_copy_[c] != detail::dead) c = next_copy_[c];
    next_copy_[c] = id;
}

template <PredicateKernel K>
std::uint32_t MutableTriangulation<K>::insert(Point2 p) {
    check_usable();
    if (!detail::finite(p)) {
        throw FailureError(Failure{FailureKind::non_finite_input, pts_.size(), no_index,
                                   "the point has a non-finite coordinate"});
    }
    return insert_at(p, planar_ ? start_triangle(p) : -1);
}

template <PredicateKernel K>
std::uint32_t MutableTriangulation<K>::insert(Point2 p, std::uint32_t near) {
    check_usable();
    check_live(near, "insert");
    if (!detail::finite(p)) {
        throw FailureError(Failure{FailureKind::non_finite_input, pts_.size(), no_index,
                                   "the point has a non-finite coordinate"});
    }
    return insert_at(p, planar_ ? edge_[rep_[near]] / 3 : -1);
}

/// The nearest (rounded distance) of the sample and the last triangle's first corner.
template <PredicateKernel K>
std::int32_t MutableTriangulation<K>::start_triangle(Point2 q) const {
    const auto& T = mesh_.triangles;
    std::int32_t best = -1;
    double best_d = 0;
    if (last_ >= 0 && T[3 * static_cast<std::size_t>(last_)] != detail::dead) {
        const Point2 a = pts_[T[3 * static_cast<std::size_t>(last_)]];
        best = last_;
        best_d = (a.x - q.x) * (a.x - q.x) + (a.y - q.y) * (a.y - q.y);
    }
    for (std::size_t i = 0; i < sample_.size(); ++i) {
        const Point2 a = sample_points_[i];
        const double d = (a.x - q.x) * (a.x - q.x) + (a.y - q.y) * (a.y - q.y);
        if (best < 0 || d < best_d) {
            const std::uint32_t v = sample_[i];
            if (rep_[v] != v || edge_[v] < 0) continue;  // removed, or renamed
            best = edge_[v] / 3;
            best_d = d;
        }
    }
    if (best < 0) {  // no usable start: any live triangle
        for (std::size_t t = 0; 3 * t < T.size(); ++t) {
            if (T[3 * t] != detail::dead) return static_cast<std::int32_t>(t);
        }
    }
    return best;
}

template <PredicateKernel K>
Location MutableTriangulation<K>::walk(Point2 q, std::int32_t start) {
    Location out;
    if (start < 0 || mesh_.triangles[3 * static_cast<std::size_t>(start)] == detail::dead) {
        fail(FailureKind::update_inconsistent, pts_.size(), "no live triangle to start a walk");
    }
    const std::uint64_t bound = 4 * static_cast<std::uint64_t>(mesh_.triangles.size() / 3) + 64;
    switch (detail::walk(k_, pts_.data(), mesh_.triangles.data(), mesh_.halfedges.data(), q,
                         static_cast<std::uint32_t>(start), bound, random_, out)) {
        case detail::WalkStatus::found: return out;
        case detail::WalkStatus::exceeded:
            fail(FailureKind::location_exceeded, pts_.size(),
                 "the walk passed " + std::to_string(bound) + " triangles");
        case detail::WalkStatus::inconsistent:
            fail(FailureKind::location_inconsistent, pts_.size(),
                 "the point is on all three edge lines of a triangle");
    }
    return out;
}

template <PredicateKernel K>
std::uint32_t MutableTriangulation<K>::insert_at(Point2 p, std::int32_t start) {
    if (!planar_) {
        const std::uint32_t id = new_id(p);
        insert_collinear(id);
        return id;
    }
    const Location loc = walk(p, start);
    const std::uint32_t id = new_id(p);
    if (loc.kind == LocationKind::on_vertex) {
        add_copy(loc.vertex, id);
        last_ = loc.triangle;
        return id;
    }
    ++live_vertices_;
    stack_.clear();
    auto& T = mesh_.triangles;  // the vector itself: make() may reallocate its storage
    const auto next = [](std::size_t e) { return next_halfedge(e); };
    const auto prev = [](std::size_t e) { return prev_halfedge(e); };
    const auto i32 = [](std::size_t e) { return static_cast<std::int32_t>(e); };
    if (loc.kind == LocationKind::inside) {
        // (a, b, c) -> (a, b, p) in place, (b, c, p), (c, a, p).
        const std::size_t b3 = 3 * static_cast<std::size_t>(loc.triangle);
        const std::uint32_t a = T[b3], b = T[b3 + 1], c = T[b3 + 2];
        const std::int32_t h_bc = mesh_.halfedges[b3 + 1], h_ca = mesh_.halfedges[b3 + 2];
        T[b3 + 2] = id;
        edge_[a] = i32(b3);
        const std::size_t t1 = 3 * std::size_t{make(b, c, id)};
        const std::size_t t2 = 3 * std::size_t{make(c, a, id)};
        attach(i32(t1), h_bc);
        attach(i32(t2), h_ca);
        mesh_.link(i32(b3 + 1), i32(t1 + 2));
        mesh_.link(i32(t1 + 1), i32(t2 + 2));
        mesh_.link(i32(t2 + 1), i32(b3 + 2));
        stack_.insert(stack_.end(), {i32(b3), i32(t1), i32(t2)});
    } else if (loc.kind == LocationKind::on_edge) {
        // e = a -> b in (a, b, c): (a, p, c) in place and (p, b, c); across it, f = b -> a
        // in (b, a, d): (b, p, d) in place and (p, a, d).
        const auto e = static_cast<std::size_t>(loc.edge);
        const std::uint32_t a = T[e], b = T[next(e)], c = T[prev(e)];
        const std::int32_t h_bc = mesh_.halfedges[next(e)], f = mesh_.halfedges[e];
        mesh_.triangles[next(e)] = id;
        const std::size_t n3 = 3 * std::size_t{make(id, b, c)};
        attach(i32(n3 + 1), h_bc);
        mesh_.link(i32(next(e)), i32(n3 + 2));
        stack_.insert(stack_.end(), {i32(prev(e)), i32(n3 + 1)});
        if (f >= 0) {
            const auto fu = static_cast<std::size_t>(f);
            const std::uint32_t d = mesh_.triangles[prev(fu)];
            const std::int32_t h_ad = mesh_.halfedges[next(fu)];
            mesh_.triangles[next(fu)] = id;
            const std::size_t m3 = 3 * std::size_t{make(id, a, d)};
            attach(i32(m3 + 1), h_ad);
            mesh_.link(i32(next(fu)), i32(m3 + 2));
            mesh_.link(i32(e), i32(m3));
            mesh_.link(f, i32(n3));
            stack_.insert(stack_.end(), {i32(prev(fu)), i32(m3 + 1)});
        } else {  // a hull edge: p joins the hull between a and b
            attach(i32(e), -1);
            attach(i32(n3), -1);
            mesh_.set_hull_next(a, id);
            mesh_.set_hull_next(id, b);
            ++mesh_.hull_size;
        }
    } else {
        // Outside: every hull edge that sees p strictly, a contiguous run x_0 -> ... -> x_m.
        const auto e = static_cast<std::size_t>(loc.edge);
        std::uint32_t first = T[e], last = T[next(e)];
        const auto sees = [&](std::uint32_t x, std::uint32_t y) {
            if (x == detail::dead || y == detail::dead) {  // the boundary left the hull cycle
                fail(FailureKind::update_inconsistent, id, "a hull edge is not on the hull cycle");
            }
            return k_.orient2d(pts_[x], pts_[y], p) == Sign::negative;
        };
        std::size_t steps = 0;  // visible edges besides e; at most hull_size - 2
        while (steps < mesh_.hull_size && sees(mesh_.hull_prev[first], first)) {
            first = mesh_.hull_prev[first];
            ++steps;
        }
        while (steps < mesh_.hull_size && sees(last, mesh_.hull_next[last])) {
            last = mesh_.hull_next[last];
            ++steps;
        }
        if (steps + 1 >= mesh_.hull_size) {
            fail(FailureKind::hull_walk_exceeded, id, "the point sees every hull edge");
        }
        ring_.clear();
        for (std::uint32_t x = first; x != last; x = mesh_.hull_next[x]) {
            // An inexact kernel can leave a hull cycle that does not lead from first to
            // last (fuzz corpus: double_hull_cycle_misses_last.bin ran out of memory here).
            if (ring_.size() > mesh_.hull_size || x == detail::dead) {
                fail(FailureKind::update_inconsistent, id,
                     "the hull cycle does not lead from the first visible edge to the last");
            }
            ring_.push_back(x);
        }
        ring_.push_back(last);
        std::int32_t pending = -1;  // p -> x_j of the previous triangle
        for (std::size_t j = 0; j + 1 < ring_.size(); ++j) {
            const std::uint32_t x = ring_[j], y = ring_[j + 1];
            const std::int32_t h = mesh_.hull_edge[x];
            if (h < 0 || T[static_cast<std::size_t>(h)] != x ||
                mesh_.halfedges[static_cast<std::size_t>(h)] >= 0) {
                fail(FailureKind::update_inconsistent, id,
                     "hull vertex " + std::to_string(x) + " has no hull edge");
            }
            const std::size_t s3 = 3 * std::size_t{make(y, x, id)};  // y->x, x->p, p->y
            mesh_.link(i32(s3), h);
            if (j == 0) {
                attach(i32(s3 + 1), -1);
            } else {
                mesh_.link(i32(s3 + 1), pending);
            }
            pending = i32(s3 + 2);
            stack_.push_back(i32(s3));
        }
        attach(pending, -1);
        for (std::size_t j = 1; j + 1 < ring_.size(); ++j) {
            mesh_.hull_next[ring_[j]] = mesh_.hull_prev[ring_[j]] = detail::dead;
        }
        mesh_.set_hull_next(first, id);
        mesh_.set_hull_next(id, last);
        mesh_.hull_size = mesh_.hull_size + 3 - ring_.size();
        hull_any_ = id;
    }
    legalize(live_vertices_ + 64, id, false);
    last_ = edge_[id] / 3;
    if (4 * sample_.size() * sample_.size() < live_vertices_) {
        sample_.push_back(id);
        sample_points_.push_back(p);
    }
    return id;
}

template <PredicateKernel K>
void MutableTriangulation<K>::insert_collinear(std::uint32_t id) {
    const Point2 p = pts_[id];
    if (chain_.size() < 2 ||
        k_.orient2d(pts_[chain_.front()], pts_[chain_.back()], p) == Sign::zero) {
        const auto at =
            std::lower_bound(chain_.begin(), chain_.end(), p,
                             [this](std::uint32_t v, Point2 q) { return lex_less(pts_[v], q); });
        if (at != chain_.end() && pts_[*at].x == p.x && pts_[*at].y == p.y) {
            add_copy(*at, id);
            return;
        }
        chain_.insert(at, id);
        ++live_vertices_;
        return;
    }
    // The first point off the line: the fan from it to the chain is the only
    // triangulation of these points, hence the Delaunay one.
    const bool left = k_.orient2d(pts_[chain_.front()], pts_[chain_.back()], p) == Sign::positive;
    const std::size_t k = chain_.size();
    std::int32_t pending = -1;
    std::uint32_t t = 0;
    for (std::size_t i = 0; i + 1 < k; ++i) {
        const std::uint32_t c0 = chain_[i], c1 = chain_[i + 1];
        if (left) {  // (c_i, c_i+1, p): c_i -> c_i+1 on the hull, p -> c_i meets the last
            t = make(c0, c1, id);
            attach(static_cast<std::int32_t>(3 * t), -1);
            if (i == 0) {
                attach(static_cast<std::int32_t>(3 * t + 2), -1);
            } else {
                mesh_.link(static_cast<std::int32_t>(3 * t + 2), pending);
            }
            pending = static_cast<std::int32_t>(3 * t + 1);
        } else {  // (c_i+1, c_i, p)
            t = make(c1, c0, id);
            attach(static_cast<std::int32_t>(3 * t), -1);
            if (i == 0) {
                attach(static_cast<std::int32_t>(3 * t + 1), -1);
            } else {
                mesh_.link(static_cast<std::int32_t>(3 * t + 1), pending);
            }
            pending = static_cast<std::int32_t>(3 * t + 2);
        }
    }
    attach(pending, -1);
    if (left) {
        for (std::size_t i = 0; i + 1 < k; ++i) mesh_.set_hull_next(chain_[i], chain_[i + 1]);
        mesh_.set_hull_next(chain_.back(), id);
        mesh_.set_hull_next(id, chain_.front());
    } else {
        for (std::size_t i = 0; i + 1 < k; ++i) mesh_.set_hull_next(chain_[i + 1], chain_[i]);
        mesh_.set_hull_next(chain_.front(), id);
        mesh_.set_hull_next(id, chain_.back());
    }
    mesh_.hull_size = k + 1;
    hull_any_ = id;
    ++live_vertices_;
    planar_ = true;
    chain_.clear();
    last_ = static_cast<std::int32_t>(t);
}

/// Whether triangle t is one of the removed vertex's (whose slots the hole's new
/// triangles reuse, make()): a scan of a few, a binary search of many.
template <PredicateKernel K>
bool MutableTriangulation<K>::in_hole(std::uint32_t t) const noexcept {
    if (hole_.size() <= hole_scan) return std::find(hole_.begin(), hole_.end(), t) != hole_.end();
    return std::binary_search(hole_.begin(), hole_.end(), t);
}

/// Lawson's flips from the half-edges in stack_. After an insertion (`removal` false)
/// each holds the new point as the apex of its triangle and a flip queues the two edges
/// then opposite it; after a removal a flip queues the sides of its quadrilateral that
/// are inside the hole.
template <PredicateKernel K>
void MutableTriangulation<K>::legalize(std::size_t budget, std::uint32_t id, bool removal) {
    const auto& T = mesh_.triangles;
    const auto& H = mesh_.halfedges;
    while (!stack_.empty()) {
        const auto e = static_cast<std::size_t>(stack_.back());
        stack_.pop_back();
        const std::int32_t twin = H[e];
        if (twin < 0) continue;
        const auto t = static_cast<std::size_t>(twin);
        if (k_.incircle(pts_[T[e]], pts_[T[next_halfedge(e)]], pts_[T[prev_halfedge(e)]],
                        pts_[T[prev_halfedge(t)]]) != Sign::positive) {
            continue;
        }
        if (budget-- == 0) {
            fail(FailureKind::flips_exceeded, id,
                 "Lawson's flips did not end around vertex " + std::to_string(id));
        }
        const std::uint32_t a = T[e], b = T[next_halfedge(e)];
        if (T[prev_halfedge(e)] == T[prev_halfedge(t)]) {  // no valid triangulation has it
            fail(FailureKind::update_inconsistent, id,
                 "the two triangles of edge " + std::to_string(a) + "-" + std::to_string(b) +
                     " have the same third vertex");
        }
        detail::flip_edge(mesh_, e);  // e: d -> b, t: c -> a
        edge_[a] = static_cast<std::int32_t>(next_halfedge(t));
        edge_[b] = static_cast<std::int32_t>(next_halfedge(e));
        if (!removal) {  // the sides opposite the new point
            stack_.push_back(static_cast<std::int32_t>(e));
            stack_.push_back(static_cast<std::int32_t>(next_halfedge(t)));
            continue;
        }
        // The sides of the quadrilateral inside the hole: one on its border is locally
        // Delaunay whatever fills the hole (point 2 at the top of the file), and testing
        // it would read the triangle outside, far away in memory.
        for (const std::size_t side : {e, next_halfedge(e), t, next_halfedge(t)}) {
            const std::int32_t across = H[side];
            if (across >= 0 && in_hole(static_cast<std::uint32_t>(across) / 3))
                stack_.push_back(static_cast<std::int32_t>(side));
        }
    }
}

/// Fills star_ with the half-edges out of v, counter-clockwise; for a hull vertex from
/// its hull edge to the edge before the incoming hull edge. Returns whether v is on the hull.
template <PredicateKernel K>
bool MutableTriangulation<K>::star(std::uint32_t v) {
    const auto& H = mesh_.halfedges;
    star_.clear();
    const bool on_hull = mesh_.hull_next[v] != detail::dead;
    const std::int32_t first = on_hull ? mesh_.hull_edge[v] : edge_[v];
    const std::size_t limit = mesh_.triangles.size() / 3;
    std::int32_t e = first;
    do {
        if (e < 0 || star_.size() >= limit || mesh_.triangles[static_cast<std::size_t>(e)] != v) {
            fail(FailureKind::update_inconsistent, v,
                 "the triangles around vertex " + std::to_string(v) + " do not close");
        }
        star_.push_back(e);
        // The neighbour's coordinates, which every caller reads next: requested now, the
        // load overlaps the rest of the walk around v.
        __builtin_prefetch(&pts_[mesh_.triangles[next_halfedge(static_cast<std::size_t>(e))]]);
        e = H[prev_halfedge(static_cast<std::size_t>(e))];
    } while (e != first && !(on_hull && e < 0));
    if (!on_hull && e < 0) {
        fail(FailureKind::update_inconsistent, v,
             "vertex " + std::to_string(v) + " is not on the hull but its triangles end there");
    }
    return on_hull;
}

template <PredicateKernel K>
void MutableTriangulation<K>::remove(std::uint32_t id) {
    check_usable();
    check_live(id, "remove");
    // What a removal reads first about the vertex, from five arrays (every id has an
    // entry in each, new_id): in a large triangulation each read is a cache miss, and
    // requested together they overlap.
    __builtin_prefetch(&next_copy_[id]);
    __builtin_prefetch(&edge_[id]);
    __builtin_prefetch(&mesh_.hull_next[id]);
    __builtin_prefetch(&pts_[id]);
    const std::uint32_t r = rep_[id];
    --live_ids_;
    if (id != r) {  // a copy: the point stays
        std::uint32_t c = r;
        while (next_copy_[c] != id) c = next_copy_[c];
        next_copy_[c] = next_copy_[id];
        next_copy_[id] = detail::dead;
        rep_[id] = detail::dead;
        return;
    }
    const std::uint32_t successor = next_copy_[r];
    rep_[r] = detail::dead;
    if (successor != detail::dead) {  // the point stays, named by its next copy
        for (std::uint32_t c = successor; c != detail::dead; c = next_copy_[c]) rep_[c] = successor;
        next_copy_[r] = detail::dead;
        rename_vertex(r, successor);
        return;
    }
    --live_vertices_;
    if (!planar_) {
        chain_.erase(std::find(chain_.begin(), chain_.end(), r));
        return;
    }
    remove_vertex(r);
}

/// The vertex `from` becomes `to` (a copy of the same point) wherever the mesh names it.
template <PredicateKernel K>
void MutableTriangulation<K>::rename_vertex(std::uint32_t from, std::uint32_t to) {
    if (!planar_) {
        *std::find(chain_.begin(), chain_.end(), from) = to;
        return;
    }
    star(from);
    for (const std::int32_t e : star_) mesh_.triangles[static_cast<std::size_t>(e)] = to;
    edge_[to] = edge_[from];
    edge_[from] = -1;
    if (mesh_.hull_next[from] != detail::dead) {
        const std::uint32_t n = mesh_.hull_next[from], p = mesh_.hull_prev[from];
        mesh_.hull_edge[to] = mesh_.hull_edge[from];
        mesh_.set_hull_next(p, to);
        mesh_.set_hull_next(to, n);
        mesh_.hull_next[from] = mesh_.hull_prev[from] = detail::dead;
        if (hull_any_ == from) hull_any_ = to;
    }
}

template <PredicateKernel K>
void MutableTriangulation<K>::remove_vertex(std::uint32_t v) {
    const auto& T = mesh_.triangles;
    const auto& H = mesh_.halfedges;
    const bool on_hull = star(v);
    const std::size_t d = star_.size();
    ring_.clear();
    handle_.clear();
    pool_.clear();
    hole_.clear();
    for (const std::int32_t e : star_) {
        const std::size_t n = next_halfedge(static_cast<std::size_t>(e));
        ring_.push_back(T[n]);
        handle_.push_back(H[n]);
        pool_.push_back(static_cast<std::uint32_t>(e) / 3);
        hole_.push_back(static_cast<std::uint32_t>(e) / 3);
    }
    if (hole_.size() > hole_scan) std::sort(hole_.begin(), hole_.end());
    for (const std::int32_t h : handle_) {  // the triangle outside must not be one of v's
        if (h >= 0 && in_hole(static_cast<std::uint32_t>(h) / 3)) {
            fail(FailureKind::update_inconsistent, v,
                 "the triangles around vertex " + std::to_string(v) + " fold onto each other");
        }
    }
    edge_[v] = -1;
    stack_.clear();
    if (!on_hull) {
        if (!fill(ring_, handle_, &pts_[v])) {
            fail(FailureKind::update_inconsistent, v,
                 "the hole of vertex " + std::to_string(v) + " has no ear");
        }
    } else {
        ring_.push_back(T[prev_halfedge(static_cast<std::size_t>(star_.back()))]);  // u_k
        const std::size_t k = d;
        if (ring_.front() == ring_.back()) {
            fail(FailureKind::update_inconsistent, v,
                 "hull vertex " + std::to_string(v) + " has the same neighbour on both sides");
        }
        if (d == mesh_.live_triangles()) {
            bool flat = true;
            for (std::size_t i = 1; i < k && flat; ++i) {
                flat = k_.orient2d(pts_[ring_[0]], pts_[ring_[k]], pts_[ring_[i]]) == Sign::zero;
            }
            if (flat) {  // every point left is on one line: no triangles any more
                for (const std::uint32_t u : ring_) {
                    edge_[u] = -1;
                    mesh_.hull_next[u] = mesh_.hull_prev[u] = detail::dead;
                }
                mesh_.hull_next[v] = mesh_.hull_prev[v] = detail::dead;
                mesh_.triangles.clear();
                mesh_.halfedges.clear();
                mesh_.free.clear();
                mesh_.hull_size = 0;
                chain_ = ring_;
                std::sort(chain_.begin(), chain_.end(), [this](std::uint32_t a, std::uint32_t b) {
                    return lex_less(pts_[a], pts_[b]);
                });
                pool_.clear();
                planar_ = false;
                hull_any_ = detail::dead;
                last_ = -1;
                return;
            }
        }
        // The new hull from u_0 to u_k on v's side: pop where the chain turns strictly left.
        hull_stack_.clear();
        for (std::uint32_t j = 0; j <= k; ++j) {
            while (hull_stack_.size() >= 2 &&
                   k_.orient2d(pts_[ring_[hull_stack_[hull_stack_.size() - 2]]],
                               pts_[ring_[hull_stack_.back()]], pts_[ring_[j]]) == Sign::positive) {
                hull_stack_.pop_back();
            }
            hull_stack_.push_back(j);
        }
        for (std::size_t s = 1; s + 1 < hull_stack_.size(); ++s) {
            if (mesh_.hull_next[ring_[hull_stack_[s]]] != detail::dead) {  // on the hull twice
                fail(FailureKind::update_inconsistent, v,
                     "removing hull vertex " + std::to_string(v) + " would close the hull early");
            }
        }
        std::vector<std::uint32_t> poly;
        std::vector<std::int32_t> handles;
        for (std::size_t s = 0; s + 1 < hull_stack_.size(); ++s) {
            const std::uint32_t a = hull_stack_[s], b = hull_stack_[s + 1];
            if (b == a + 1) {  // the chain edge u_a u_b becomes a hull edge u_b -> u_a
                if (handle_[a] < 0) {
                    fail(FailureKind::update_inconsistent, v,
                         "removing vertex " + std::to_string(v) + " leaves a dangling edge");
                }
                mesh_.link(handle_[a], -1);
                mesh_.hull_edge[ring_[b]] = handle_[a];
            } else {  // the pocket u_a, ..., u_b closed by the new hull edge u_b -> u_a
                poly.assign(ring_.begin() + a, ring_.begin() + b + 1);
                handles.assign(handle_.begin() + a, handle_.begin() + b);
                handles.push_back(-1);
                if (!fill(poly, handles, nullptr)) {
                    fail(FailureKind::update_inconsistent, v,
                         "a pocket left by hull vertex " + std::to_string(v) + " has no ear");
                }
            }
            mesh_.set_hull_next(ring_[b], ring_[a]);
        }
        for (const std::uint32_t j : hull_stack_) edge_[ring_[j]] = mesh_.hull_edge[ring_[j]];
        mesh_.hull_next[v] = mesh_.hull_prev[v] = detail::dead;
        mesh_.hull_size = mesh_.hull_size + hull_stack_.size() - 3;
        hull_any_ = ring_[0];
    }
    for (const std::uint32_t t : pool_) mesh_.remove_triangle(t);
    pool_.clear();
    legalize(ring_.size() * ring_.size() + 64, v, true);
    hole_.clear();
    for (const std::uint32_t u : ring_) {  // every neighbour left with a live half-edge
        const std::int32_t e = edge_[u];
        if (e < 0 || T[static_cast<std::size_t>(e)] != u) {
            fail(FailureKind::update_inconsistent, v,
                 "removing vertex " + std::to_string(v) + " left vertex " + std::to_string(u) +
                     " without triangles");
        }
    }
    last_ = edge_[ring_[0]] / 3;
    if (2 * live_vertices_ < sample_.size() * sample_.size()) {  // drop removed samples
        std::size_t kept = 0;
        for (std::size_t i = 0; i < sample_.size(); ++i) {
            const std::uint32_t s = sample_[i];
            if (rep_[s] == s && edge_[s] >= 0) {
                sample_[kept] = s;
                sample_points_[kept++] = pts_[s];
            }
        }
        sample_.resize(kept);
        sample_points_.resize(kept);
    }
}

/// Cuts the simple counter-clockwise polygon `poly` (vertex ids) into triangles by ear
/// clipping; handle[i] is the half-edge outside the side poly[i] -> poly[i + 1] (-1: the
/// side is a hull edge). With `centre`, a point strictly inside the polygon seeing all of
/// it, ears that need no scan are taken first (see the top of the file). The new inner
/// edges go to stack_. False when no ear is found (only an inexact kernel can do that).
template <PredicateKernel K>
bool MutableTriangulation<K>::fill(std::span<const std::uint32_t> poly,
                                   std::span<std::int32_t> handle, const Point2* centre) {
    const std::size_t m = poly.size();
    prev_.resize(m);
    next_.resize(m);
    for (std::uint32_t i = 0; i < m; ++i) {
        next_[i] = static_cast<std::uint32_t>(i + 1 == m ? 0 : i + 1);
        prev_[i] = static_cast<std::uint32_t>(i == 0 ? m - 1 : i - 1);
    }
    const auto P = [&](std::uint32_t j) { return pts_[poly[j]]; };
    const auto i32 = [](std::size_t e) { return static_cast<std::int32_t>(e); };
    std::size_t remaining = m, misses = 0;
    std::uint32_t i = 0;
    bool shortcut = centre != nullptr;
    while (remaining > 3) {
        const std::uint32_t p = prev_[i], n = next_[i];
        bool ear = k_.orient2d(P(p), P(i), P(n)) == Sign::positive;
        if (ear && shortcut) {
            ear = k_.orient2d(P(p), P(n), *centre) == Sign::positive;
        } else if (ear) {
            for (std::uint32_t j = next_[n]; j != p && ear; j = next_[j]) {
                const Point2 x = P(j);
                ear = k_.orient2d(P(p), P(i), x) == Sign::negative ||
                      k_.orient2d(P(i), P(n), x) == Sign::negative ||
                      k_.orient2d(P(n), P(p), x) == Sign::negative;
            }
        }
        if (!ear) {
            i = n;
            if (++misses > remaining) {
                if (!shortcut) return false;
                shortcut = false;  // no ear without a scan: scan from now on
                misses = 0;
            }
            continue;
        }
        const std::size_t t3 = 3 * std::size_t{make(poly[p], poly[i], poly[n])};
        attach(i32(t3), handle[p]);
        attach(i32(t3 + 1), handle[i]);
        handle[p] = i32(t3 + 2);  // n -> p, the twin of the new side p -> n
        stack_.push_back(i32(t3 + 2));
        next_[p] = n;
        prev_[n] = p;
        --remaining;
        misses = 0;
        i = p;
    }
    const std::uint32_t n = next_[i], nn = next_[n];
    if (k_.orient2d(P(i), P(n), P(nn)) != Sign::positive) return false;
    const std::size_t t3 = 3 * std::size_t{make(poly[i], poly[n], poly[nn])};
    attach(i32(t3), handle[i]);
    attach(i32(t3 + 1), handle[n]);
    attach(i32(t3 + 2), handle[nn]);
    return true;
}

template <PredicateKernel K>
Location MutableTriangulation<K>::locate(Point2 q) {
    check_usable();
    if (!detail::finite(q)) {
        throw FailureError(Failure{FailureKind::non_finite_input, 0, no_index,
                                   "the query has a non-finite coordinate"});
    }
    if (planar_) {
        const Location loc = walk(q, start_triangle(q));
        last_ = loc.triangle;
        return loc;
    }
    Location loc;  // outside, no edge
    if (chain_.empty()) return loc;
    if (chain_.size() >= 2 &&
        k_.orient2d(pts_[chain_.front()], pts_[chain_.back()], q) != Sign::zero) {
        return loc;
    }
    const auto at =
        std::lower_bound(chain_.begin(), chain_.end(), q,
                         [this](std::uint32_t v, Point2 x) { return lex_less(pts_[v], x); });
    if (at != chain_.end() && pts_[*at].x == q.x && pts_[*at].y == q.y) {
        loc.kind = LocationKind::on_vertex;
        loc.vertex = *at;
    } else if (at != chain_.begin() && at != chain_.end()) {
        loc.kind = LocationKind::on_edge;
        loc.edge = static_cast<std::int32_t>(at - chain_.begin() - 1);
    }
    return loc;
}

template <PredicateKernel K>
std::uint32_t MutableTriangulation<K>::nearest(Point2 q) {
    if (live_vertices_ == 0) {
        check_usable();
        return no_vertex;
    }
    const Location loc = locate(q);
    if (loc.kind == LocationKind::on_vertex) return loc.vertex;
    if (!planar_) {
        // Along the chain the squared distance to q is a convex function of the position:
        // the first vertex no farther than the next one is a nearest.
        std::size_t lo = 0, hi = chain_.size() - 1;
        while (lo < hi) {
            const std::size_t mid = lo + (hi - lo) / 2;
            if (k_.compare_distance(q, pts_[chain_[mid]], pts_[chain_[mid + 1]]) !=
                Sign::positive) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return chain_[lo];
    }
    const std::size_t b3 = 3 * static_cast<std::size_t>(loc.triangle);
    std::uint32_t best = mesh_.triangles[b3];
    for (std::size_t j = 1; j < 3; ++j) {
        const std::uint32_t c = mesh_.triangles[b3 + j];
        if (k_.compare_distance(q, pts_[c], pts_[best]) == Sign::negative) best = c;
    }
    // Greedy: move to a strictly nearer neighbour while there is one (Locator::nearest
    // says why that ends at a nearest vertex of a Delaunay triangulation).
    for (std::size_t steps = 0;; ++steps) {
        if (steps > live_vertices_) {
            fail(FailureKind::location_exceeded, 0, "the nearest-vertex walk did not end");
        }
        const bool on_hull = star(best);
        std::uint32_t better = best;
        const auto consider = [&](std::uint32_t u) {
            if (k_.compare_distance(q, pts_[u], pts_[better]) == Sign::negative) better = u;
        };
        for (const std::int32_t e : star_) {
            consider(mesh_.triangles[next_halfedge(static_cast<std::size_t>(e))]);
        }
        if (on_hull) {
            consider(mesh_.triangles[prev_halfedge(static_cast<std::size_t>(star_.back()))]);
        }
        if (better == best) return best;
        best = better;
    }
}

template <PredicateKernel K>
MutableSnapshot MutableTriangulation<K>::snapshot() const {
    MutableSnapshot s;
    std::vector<std::uint32_t> position(pts_.size(), detail::dead);
    for (std::uint32_t id = 0; id < pts_.size(); ++id) {
        if (rep_[id] == detail::dead) continue;
        position[id] = static_cast<std::uint32_t>(s.ids.size());
        s.ids.push_back(id);
        s.points.push_back(pts_[id]);
    }
    Triangulation& t = s.triangulation;
    t.vertex_of_input.resize(s.ids.size());
    for (std::uint32_t i = 0; i < s.ids.size(); ++i) {
        t.vertex_of_input[i] = position[rep_[s.ids[i]]];
        if (t.vertex_of_input[i] != i) t.duplicates.push_back(i);
    }
    if (!planar_) {
        t.collinear = true;
        for (const std::uint32_t v : chain_) t.hull.push_back(position[v]);
        return s;
    }
    detail::Mesh copy;
    copy.triangles = mesh_.triangles;
    copy.halfedges = mesh_.halfedges;
    copy.hull_next = mesh_.hull_next;
    std::uint32_t first = hull_any_;
    std::uint32_t v = hull_any_;
    for (std::size_t i = 0; i < mesh_.hull_size; ++i, v = mesh_.hull_next[v]) {
        if (v >= pts_.size()) {
            throw FailureError(Failure{FailureKind::result_inconsistent, no_index, no_index,
                                       "the hull cycle does not close"});
        }
        if (lex_less(pts_[v], pts_[first])) first = v;
    }
    if (auto f = detail::to_triangulation(copy, position, first, t)) throw FailureError(*f);
    return s;
}

}  // namespace exidel::delaunay
