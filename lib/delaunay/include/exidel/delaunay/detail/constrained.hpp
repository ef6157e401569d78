// exidel: the constrained triangulation's machinery (constrained.hpp says what it builds).
//
// The mesh is Triangulation's arrays (triangles, twins) grown in place, plus per half-edge
// the pieces it carries (seg_: -1 for none, else the head of a list in carry_ of (segment,
// chain node) pairs: several segments when they overlap) and per vertex one half-edge out
// of it (out_). Each segment's chain is a linked list of nodes (nodes_, from head_[s]);
// a piece is a node and its successor, and splitting a piece at a vertex inserts a node.
// The chain is therefore kept in the order the pieces were made, never rebuilt from the
// edges: where rounding makes a chain pass a vertex twice, it is still one walk. Every operation
// rewrites whole triangles and gives each vertex of a rewritten triangle a half-edge of it, so out_
// never names a slot that changed hands.
//
// Rotation around a vertex x: for a half-edge h out of x, twin(prev(h)) is the next
// half-edge out of x counter-clockwise, next(twin(h)) the next clockwise; -1 ends the fan at
// the boundary.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "exidel/delaunay/result.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/construct.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay {

struct Segment;
struct ConstrainedOptions;
struct ConstrainedResult;

namespace detail {

/// Thrown inside the builder and turned into ConstrainedResult::failure at its edge.
/// `cascade`: the failure is the crossing cascade's (a run with snap rounding may succeed).
struct ConstrainedStop {
    Failure failure;
    bool cascade = false;
};

/// The vertices among `candidates` (indices into `points`, distinct points) whose pixels
/// segment a -> b meets, in order from a to b. The pixel of a double point is the set of
/// reals that round to it (to nearest, ties to even, per coordinate); exact rational
/// arithmetic (src/snap_pixels.cpp).
std::vector<std::uint32_t> pixels_on_segment(Point2 a, Point2 b, std::span<const Point2> points,
                                             std::span<const std::uint32_t> candidates);

template <PredicateKernel K>
class ConstrainedBuilder {
public:
    static constexpr std::int32_t none = -1;

    ConstrainedBuilder(const K& kernel, std::vector<Point2> points, Triangulation tri,
                       std::size_t max_added)
        : k_(kernel),
          pts_(std::move(points)),
          tri_(std::move(tri.triangles)),
          twin_(std::move(tri.halfedges)),
          vertex_of_(std::move(tri.vertex_of_input)),
          duplicates_(std::move(tri.duplicates)),
          input_count_(pts_.size()),
          max_added_(max_added) {
        seg_.assign(tri_.size(), none);
        out_.assign(pts_.size(), none);
        for (std::size_t e = 0; e < tri_.size(); ++e) out_[tri_[e]] = static_cast<std::int32_t>(e);
    }

    std::size_t added() const noexcept { return pts_.size() - input_count_; }

    // ---- the mesh ------------------------------------------------------------------------

    static std::int32_t nxt(std::int32_t e) noexcept { return e % 3 == 2 ? e - 2 : e + 1; }
    static std::int32_t prv(std::int32_t e) noexcept { return e % 3 == 0 ? e + 2 : e - 1; }
    std::uint32_t from(std::int32_t e) const noexcept { return tri_[static_cast<std::size_t>(e)]; }
    std::uint32_t to(std::int32_t e) const noexcept { return from(nxt(e)); }
    std::int32_t twin(std::int32_t e) const noexcept { return twin_[static_cast<std::size_t>(e)]; }
    std::int32_t seg(std::int32_t e) const noexcept { return seg_[static_cast<std::size_t>(e)]; }
    const Point2& pt(std::uint32_t v) const noexcept { return pts_[v]; }
    [[gnu::always_inline]] Sign orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
        return k_.orient2d(pts_[a], pts_[b], pts_[c]);
    }

    [[noreturn]] void stop(FailureKind kind, std::size_t index, std::string message) const {
        // The crossing cascade's failures: its own limit, and, with exact signs, anything
        // after a cascade began (exact signs are never inconsistent otherwise).
        const bool cascade =
            !snapping_ &&
            (kind == FailureKind::too_many_crossings ? natural_cap_ : K::is_exact && events_ > 0);
        throw ConstrainedStop{Failure{kind, index, no_index, std::move(message)}, cascade};
    }

    /// Makes half-edges e and f twins (either may be -1: a boundary side).
    void link(std::int32_t e, std::int32_t f) noexcept {
        if (e >= 0) twin_[static_cast<std::size_t>(e)] = f;
        if (f >= 0) twin_[static_cast<std::size_t>(f)] = e;
    }
    /// Writes triangle slot t as (a, b, c), its half-edges' segments (sab: a -> b, ...) and
    /// twins (oab: the twin of a -> b, ...), and gives a, b, c a half-edge each.
    void write(std::int32_t t, std::array<std::uint32_t, 3> v, std::array<std::int32_t, 3> s,
               std::array<std::int32_t, 3> o) noexcept {
        for (int i = 0; i < 3; ++i) {
            const std::int32_t e = 3 * t + i;
            tri_[static_cast<std::size_t>(e)] = v[static_cast<std::size_t>(i)];
            seg_[static_cast<std::size_t>(e)] = s[static_cast<std::size_t>(i)];
            link(e, o[static_cast<std::size_t>(i)]);
            out_[v[static_cast<std::size_t>(i)]] = e;
        }
    }
    std::int32_t new_triangle() {
        if (tri_.size() + 3 > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
            stop(FailureKind::too_many_points, pts_.size(),
                 "too many triangles for 32-bit indices");
        tri_.resize(tri_.size() + 3, 0);
        twin_.resize(twin_.size() + 3, none);
        seg_.resize(seg_.size() + 3, none);
        return static_cast<std::int32_t>(tri_.size() / 3 - 1);
    }

    /// Flips the edge of half-edge e (both sides must exist and e must not be a segment):
    /// triangles (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c), in the same slots.
    /// Returns the new half-edges a -> d and d -> b (the sides opposite c).
    std::pair<std::int32_t, std::int32_t> flip(std::int32_t e) noexcept {
        const std::int32_t f = twin(e);
        const std::int32_t e1 = nxt(e), e2 = prv(e), f1 = nxt(f), f2 = prv(f);
        const std::uint32_t a = from(e), b = to(e), c = from(e2), d = from(f2);
        const std::int32_t obc = twin(e1), oca = twin(e2), oad = twin(f1), odb = twin(f2);
        const std::int32_t sbc = seg(e1), sca = seg(e2), sad = seg(f1), sdb = seg(f2);
        const std::int32_t t1 = e / 3, t2 = f / 3;
        write(t1, {c, a, d}, {sca, sad, none}, {oca, oad, 3 * t2 + 2});
        write(t2, {d, b, c}, {sdb, sbc, none}, {odb, obc, 3 * t1 + 2});
        return {3 * t1 + 1, 3 * t2};
    }

    /// Splits triangle t = (a, b, c) at new vertex x: (a, b, x), (b, c, x), (c, a, x).
    /// Returns the three half-edges opposite x.
    std::array<std::int32_t, 3> split_triangle(std::int32_t t, std::uint32_t x) {
        const std::int32_t e0 = 3 * t, e1 = e0 + 1, e2 = e0 + 2;
        const std::uint32_t a = from(e0), b = from(e1), c = from(e2);
        const std::int32_t oab = twin(e0), obc = twin(e1), oca = twin(e2);
        const std::int32_t sab = seg(e0), sbc = seg(e1), sca = seg(e2);
        const std::int32_t t1 = new_triangle(), t2 = new_triangle();
        write(t, {a, b, x}, {sab, none, none}, {oab, 3 * t1 + 2, 3 * t2 + 1});
        write(t1, {b, c, x}, {sbc, none, none}, {obc, 3 * t2 + 2, 3 * t + 1});
        write(t2, {c, a, x}, {sca, none, none}, {oca, 3 * t + 2, 3 * t1 + 1});
        return {3 * t, 3 * t1, 3 * t2};
    }

    /// Splits the edge of half-edge e = a -> b at new vertex x lying on it: triangle
    /// (a, b, c) becomes (a, x, c) and (x, b, c), its twin (b, a, d), when there is one,
    /// (b, x, d) and (x, a, d). Both halves keep the edge's segments. Returns the
    /// half-edges opposite x (two or four; -1 for the missing ones).
    std::array<std::int32_t, 4> split_edge(std::int32_t e, std::uint32_t x) {
        const std::int32_t f = twin(e);
        const std::int32_t s = seg(e);
        const std::int32_t e1 = nxt(e), e2 = prv(e);
        const std::uint32_t a = from(e), b = to(e), c = from(e2);
        const std::int32_t obc = twin(e1), oca = twin(e2), sbc = seg(e1), sca = seg(e2);
        const std::int32_t t = e / 3, n1 = new_triangle();
        if (f < 0) {
            write(t, {a, x, c}, {s, none, sca}, {none, 3 * n1 + 2, oca});
            write(n1, {x, b, c}, {s, sbc, none}, {none, obc, 3 * t + 1});
            return {3 * t + 2, 3 * n1 + 1, -1, -1};
        }
        const std::int32_t f1 = nxt(f), f2 = prv(f);
        const std::uint32_t d = from(f2);
        const std::int32_t oad = twin(f1), odb = twin(f2), sad = seg(f1), sdb = seg(f2);
        const std::int32_t u = f / 3, n2 = new_triangle();
        // (a, x, c) | (x, b, c) | (b, x, d) | (x, a, d); a -> x pairs with x -> a, x -> b
        // with b -> x.
        write(t, {a, x, c}, {s, none, sca}, {3 * n2, 3 * n1 + 2, oca});
        write(n1, {x, b, c}, {s, sbc, none}, {3 * u, obc, 3 * t + 1});
        write(u, {b, x, d}, {s, none, sdb}, {3 * n1, 3 * n2 + 2, odb});
        write(n2, {x, a, d}, {s, sad, none}, {3 * t, oad, 3 * u + 1});
        return {3 * t + 2, 3 * n1 + 1, 3 * u + 2, 3 * n2 + 1};
    }

    /// Lawson's flips from new vertex x: `stack` holds the half-edges opposite x; an edge
    /// that is not a segment is flipped when the vertex across it lies strictly inside
    /// the circle of x's triangle. Bounded by `budget` flips.
    void legalize(std::vector<std::int32_t>& stack, std::uint32_t x) {
        std::size_t budget = 8 * tri_.size() / 3 + 64;
        while (!stack.empty()) {
            const std::int32_t e = stack.back();
            stack.pop_back();
            if (e < 0 || seg(e) != none) continue;
            const std::int32_t f = twin(e);
            if (f < 0) continue;
            const std::uint32_t a = from(e), b = to(e), c = from(prv(e)), d = from(prv(f));
            if (c != x) continue;  // the slot was rewritten by an earlier flip
            if (k_.incircle(pts_[a], pts_[b], pts_[c], pts_[d]) != Sign::positive) continue;
            // A strictly convex quadrilateral is needed; an exact kernel guarantees it.
            if (orient(c, d, b) != Sign::positive || orient(c, d, a) != Sign::negative)
                stop(FailureKind::flips_exceeded, x, "a flip's quadrilateral is not convex");
            if (budget-- == 0) stop(FailureKind::flips_exceeded, x, "too many flips");
            const auto [p, q] = flip(e);
            stack.push_back(p);
            stack.push_back(q);
        }
    }

    /// Lawson's flip algorithm over every edge: an edge that is not a piece is flipped
    /// while the vertex across it lies strictly inside the circle of its triangle, and the
    /// four sides of the flipped quadrilateral are tested again. From any triangulation
    /// whose pieces are edges it ends at the constrained Delaunay triangulation (every flip
    /// lowers the triangulation lifted to the paraboloid; Lawson 1977, Chew 1989). It
    /// runs once at the end when crossings freed edges that were pieces: such an edge was
    /// not held to the Delaunay test while it was one, and the insertions since need not
    /// reach it.
    void flip_everything() {
        std::vector<std::int32_t> queue;
        for (std::size_t e = 0; e < twin_.size(); ++e) {
            const auto h = static_cast<std::int32_t>(e);
            if (twin(h) > h && seg(h) == none) queue.push_back(h);
        }
        flip_queue(queue);
    }
    /// Lawson's flips from the edges of `queue` (half-edges), spreading to the sides of
    /// every flipped quadrilateral.
    void flip_queue(std::vector<std::int32_t>& queue) {
        std::size_t budget = 64 * (tri_.size() / 3) + 1024;
        while (!queue.empty()) {
            const std::int32_t e = queue.back();
            queue.pop_back();
            const std::int32_t f = twin(e);
            if (f < 0 || seg(e) != none) continue;
            const std::uint32_t a = from(e), b = to(e), c = from(prv(e)), d = from(prv(f));
            if (k_.incircle(pts_[a], pts_[b], pts_[c], pts_[d]) != Sign::positive) continue;
            // With exact signs the quadrilateral is strictly convex: d lies strictly inside
            // the circle through a, b, c and strictly on the other side of ab, so the open
            // segment cd lies inside the disk (c on its circle, d inside) and crosses line
            // ab inside the disk, that is strictly between a and b. An inexact kernel's signs
            // may contradict that, and a flip then would fold the mesh: checked.
            if constexpr (!K::is_exact) {
                if (orient(c, d, b) != Sign::positive || orient(c, d, a) != Sign::negative)
                    stop(FailureKind::flips_exceeded, a, "a flip's quadrilateral is not convex");
            }
            if (budget-- == 0) stop(FailureKind::flips_exceeded, a, "too many flips");
            const std::int32_t t1 = e / 3, t2 = f / 3;
            flip(e);
            for (const std::int32_t h : {3 * t1, 3 * t1 + 1, 3 * t2, 3 * t2 + 1})
                queue.push_back(h);
        }
    }

    /// A half-edge of edge a-b (a -> b, or b -> a on the boundary), or -1.
    std::int32_t find_edge(std::uint32_t a, std::uint32_t b) const {
        std::int32_t found = none;
        for_fan(a, [&](std::int32_t h) {
            if (to(h) == b)
                found = h;
            else if (from(prv(h)) == b)
                found = prv(h);
            return found != none;
        });
        return found;
    }

    // ---- pieces on half-edges -------------------------------------------------------------

    struct Carry {
        std::uint32_t segment;
        std::uint32_t node;  ///< the chain node whose piece this edge is
        std::int32_t next;   ///< the next entry of the edge's list, or -1
    };
    struct Node {
        std::uint32_t vertex;
        std::uint32_t next;  ///< the next node of the chain, or end
    };
    static constexpr std::uint32_t end_of_chain = std::numeric_limits<std::uint32_t>::max();

    /// The pieces half-edge e carries.
    void carried(std::int32_t e, std::vector<Carry>& out) const {
        out.clear();
        for (std::int32_t c = seg(e); c >= 0; c = carry_[static_cast<std::size_t>(c)].next)
            out.push_back(carry_[static_cast<std::size_t>(c)]);
    }
    /// Makes the edge of half-edge e (both half-edges) carry the piece of `node` of s.
    void add_piece(std::int32_t e, std::uint32_t s, std::uint32_t node) {
        carry_.push_back({s, node, seg(e)});
        const auto c = static_cast<std::int32_t>(carry_.size() - 1);
        seg_[static_cast<std::size_t>(e)] = c;
        if (twin(e) >= 0) seg_[static_cast<std::size_t>(twin(e))] = c;
    }
    void clear_segments(std::int32_t e) {
        seg_[static_cast<std::size_t>(e)] = none;
        if (twin(e) >= 0) seg_[static_cast<std::size_t>(twin(e))] = none;
    }
    /// Inserts vertex x after `node` in its chain; returns the new node.
    std::uint32_t split_node(std::uint32_t node, std::uint32_t x) {
        nodes_.push_back({x, nodes_[node].next});
        const auto m = static_cast<std::uint32_t>(nodes_.size() - 1);
        nodes_[node].next = m;
        return m;
    }
    std::uint32_t after(std::uint32_t node) const { return nodes_[nodes_[node].next].vertex; }

    // ---- walking -----------------------------------------------------------------------------

    /// Calls f(h) for every half-edge h out of v (one per triangle around v):
    /// counter-clockwise from out_[v] to the boundary, then clockwise from out_[v].
    /// f returns true to stop. Bounded by the number of triangles.
    template <class F>
    void for_fan(std::uint32_t v, F&& f) const {
        const std::int32_t start = out_[v];
        if (start < 0) return;
        std::size_t budget = tri_.size() / 3 + 1;
        std::int32_t h = start;
        for (;;) {
            if (f(h)) return;
            const std::int32_t g = twin(prv(h));
            if (g < 0) break;
            if (g == start) return;  // around an interior vertex
            h = g;
            if (budget-- == 0)
                stop(FailureKind::constraint_inconsistent, v, "a vertex's fan does not close");
        }
        h = start;
        for (;;) {
            const std::int32_t g = twin(h);
            if (g < 0) return;
            h = nxt(g);
            if (f(h)) return;
            if (budget-- == 0)
                stop(FailureKind::constraint_inconsistent, v, "a vertex's fan does not close");
        }
    }

    /// The boundary half-edge after / before boundary half-edge e.
    std::int32_t next_boundary(std::int32_t e) const {
        std::int32_t h = nxt(e);
        for (std::size_t budget = tri_.size() / 3 + 1; twin(h) >= 0; h = nxt(twin(h)))
            if (budget-- == 0)
                stop(FailureKind::constraint_inconsistent, from(h), "the boundary does not close");
        return h;
    }
    std::int32_t prev_boundary(std::int32_t e) const {
        std::int32_t h = prv(e);
        for (std::size_t budget = tri_.size() / 3 + 1; twin(h) >= 0; h = prv(twin(h)))
            if (budget-- == 0)
                stop(FailureKind::constraint_inconsistent, from(h), "the boundary does not close");
        return h;
    }

    enum class Where { inside, on_edge, on_vertex, outside };
    struct Located {
        Where where;
        std::int32_t e;   ///< inside: a half-edge of the triangle; on_edge, outside: the edge
        std::uint32_t v;  ///< on_vertex: the vertex
    };

    /// Where q lies, by a remembering stochastic walk from triangle t (every edge that q
    /// is strictly right of leads out; the first edge tested rotates pseudo-randomly, so
    /// the walk ends on any triangulation, Delaunay or not). Bounded.
    Located locate(Point2 q, std::int32_t t, std::size_t index) {
        std::int32_t entered = none;
        for (std::size_t steps = 0;; ++steps) {
            if (steps > 4 * tri_.size() / 3 + 64)
                stop(FailureKind::location_exceeded, index,
                     "a walk to a crossing point did not end");
            for (int i = 0; i < 3; ++i)
                if (pts_[from(3 * t + i)] == q)
                    return {Where::on_vertex, 3 * t + i, from(3 * t + i)};
            rng_ ^= rng_ << 13;
            rng_ ^= rng_ >> 7;
            rng_ ^= rng_ << 17;
            const int first = static_cast<int>(rng_ % 3);
            std::int32_t zero = none;
            int zeros = 0;
            bool moved = false;
            for (int j = 0; j < 3 && !moved; ++j) {
                const std::int32_t e = 3 * t + (first + j) % 3;
                if (e == entered) continue;
                const Sign o = k_.orient2d(pts_[from(e)], pts_[to(e)], q);
                if (o == Sign::negative) {
                    if (twin(e) < 0) return {Where::outside, e, 0};
                    entered = twin(e);
                    t = entered / 3;
                    moved = true;
                } else if (o == Sign::zero) {
                    ++zeros;
                    zero = e;
                }
            }
            if (moved) continue;
            if (zeros == 0) return {Where::inside, 3 * t, 0};
            if (zeros == 1) return {Where::on_edge, zero, 0};
            // q on two edge lines of a triangle is its shared vertex, which it is not.
            if (entered == none || zeros > 1)
                stop(FailureKind::location_inconsistent, index,
                     "a crossing point is on two edge lines of a triangle but not a vertex");
        }
    }

    /// Joins new vertex x, outside the boundary, to every boundary edge that sees it
    /// strictly, starting from boundary half-edge e. Returns the half-edges opposite x.
    void hull_insert(std::int32_t e, std::uint32_t x, std::vector<std::int32_t>& opposite) {
        // The visible chain, in boundary order: back from e, then forward.
        std::vector<std::int32_t> chain{e};
        const std::size_t cap = tri_.size() + 3;
        for (std::int32_t h = prev_boundary(e);
             h != e && orient(from(h), to(h), x) == Sign::negative; h = prev_boundary(h)) {
            chain.insert(chain.begin(), h);
            if (chain.size() > cap)
                stop(FailureKind::constraint_inconsistent, x, "a point sees the whole boundary");
        }
        for (std::int32_t h = next_boundary(e);
             h != chain.front() && orient(from(h), to(h), x) == Sign::negative;
             h = next_boundary(h)) {
            chain.push_back(h);
            if (chain.size() > cap)
                stop(FailureKind::constraint_inconsistent, x, "a point sees the whole boundary");
        }
        // Triangle (v_i, v_(i-1), x) on boundary half-edge v_(i-1) -> v_i.
        std::int32_t previous = none;
        for (const std::int32_t h : chain) {
            const std::int32_t t = new_triangle();
            write(t, {to(h), from(h), x}, {seg(h), none, none},
                  {h, previous < 0 ? none : 3 * previous + 2, none});
            if (previous >= 0) link(3 * previous + 2, 3 * t + 1);
            previous = t;
            opposite.push_back(3 * t);
        }
    }

    /// Inserts q as a vertex (or finds it), walking from triangle t; `lines` are the four
    /// vertices whose lines it is the crossing of, `pair` the two segments. A point on a
    /// segment's piece splits the piece: the edge is freed for the flips, and the two
    /// halves go to restores_, to be inserted again before anything else.
    std::uint32_t insert_point(Point2 q, std::int32_t t, std::array<std::uint32_t, 2> pair,
                               std::array<std::uint32_t, 4> lines) {
        const Located at = locate(q, t, pts_.size());
        if (at.where == Where::on_vertex) return at.v;
        if (added() >= max_added_)
            stop(FailureKind::too_many_crossings, pts_.size(),
                 "more than " + std::to_string(max_added_) + " crossing points" +
                     (natural_cap_ ? " (more than the pairs of segments: rounded crossings "
                                     "keep bending pieces across one another)"
                                   : ""));
        const auto x = static_cast<std::uint32_t>(pts_.size());
        pts_.push_back(q);
        out_.push_back(none);
        vertex_of_.push_back(x);
        crossings_.push_back(pair);
        crossing_lines_.push_back(lines);
        std::vector<std::int32_t>& opposite = stack_;
        opposite.clear();
        if (at.where == Where::inside) {
            for (const std::int32_t h : split_triangle(at.e / 3, x)) opposite.push_back(h);
        } else if (at.where == Where::on_edge) {
            carried(at.e, on_edge_);
            clear_segments(at.e);
            for (const std::int32_t h : split_edge(at.e, x))
                if (h >= 0) opposite.push_back(h);
            for (const Carry& c : on_edge_) split_piece(c, x, restores_);
        } else {
            hull_insert(at.e, x, opposite);
        }
        legalize(opposite, x);
        return x;
    }

    // ---- segments ------------------------------------------------------------------------------

    /// Collinear b and c lie in the same direction from a (exact: coordinate comparisons).
    bool same_direction(std::uint32_t a, std::uint32_t b, std::uint32_t c) const noexcept {
        const Point2 &p = pts_[a], &q = pts_[b], &r = pts_[c];
        const auto side = [](double from, double to) { return (to > from) - (to < from); };
        return side(p.x, q.x) == side(p.x, r.x) && side(p.y, q.y) == side(p.y, r.y);
    }

    /// Where the ray from u towards w leaves u: a neighbour x on it (returned with its
    /// edge), or the half-edge R -> L opposite u that it crosses (R strictly right of it,
    /// L strictly left).
    struct Exit {
        std::int32_t edge = none;  ///< u -> x or x -> u: the edge to x
        std::uint32_t x = 0;
        std::int32_t crossed = none;
    };
    Exit find_exit(std::uint32_t u, std::uint32_t w) {
        Exit exit;
        // w a neighbour of u (an edge already: no orientation needed).
        for_fan(u, [&](std::int32_t h) {
            if (to(h) == w) {
                exit.edge = h;
            } else if (from(prv(h)) == w) {
                exit.edge = prv(h);
            }
            return exit.edge != none;
        });
        if (exit.edge != none) {
            exit.x = w;
            return exit;
        }
        // Consecutive triangles of the fan share a vertex: its side of u -> w is asked
        // once (the last answer is kept).
        std::uint32_t last = end_of_chain;
        Sign last_side = Sign::zero;
        const auto side = [&](std::uint32_t x) {
            if (x != last) {
                last = x;
                last_side = orient(u, w, x);
            }
            return last_side;
        };
        for_fan(u, [&](std::int32_t h) {
            const std::uint32_t p = to(h), q = from(prv(h));
            const Sign op = side(p), oq = side(q);
            if (op == Sign::zero && same_direction(u, p, w)) {
                exit.edge = h;
                exit.x = p;
                return true;
            }
            if (oq == Sign::zero && same_direction(u, q, w)) {
                exit.edge = prv(h);
                exit.x = q;
                return true;
            }
            if (op == Sign::negative && oq == Sign::positive) {
                exit.crossed = nxt(h);
                return true;
            }
            return false;
        });
        if (exit.edge == none && exit.crossed == none)
            stop(FailureKind::constraint_inconsistent, u,
                 "no triangle around a segment's vertex lies towards its other end");
        return exit;
    }

    struct Piece {
        std::uint32_t u, w, s;
        std::uint32_t node;  ///< s's chain node at u, followed by the node at w
    };

    /// The piece of carry c is split at vertex x (unless x is one of its ends): the two
    /// halves are pushed on `to`, the first half last (it is inserted first).
    void split_piece(const Carry& c, std::uint32_t x, std::vector<Piece>& to) {
        const std::uint32_t a = nodes_[c.node].vertex, b = after(c.node);
        if (x == a || x == b) {
            to.push_back({a, b, c.segment, c.node});
            return;
        }
        const std::uint32_t m = split_node(c.node, x);
        to.push_back({x, b, c.segment, m});
        to.push_back({a, x, c.segment, c.node});
    }

    /// Inserts segment s from vertex a to vertex b, with every piece a crossing creates.
    void insert_segment(std::uint32_t a, std::uint32_t b, std::uint32_t s) {
        const auto first = static_cast<std::uint32_t>(nodes_.size());
        nodes_.push_back({a, first + 1});
        nodes_.push_back({b, end_of_chain});
        head_[s] = first;
        pending_.clear();
        pending_.push_back({a, b, s, first});
        while (!pending_.empty()) {
            const Piece piece = pending_.back();
            pending_.pop_back();
            advance(piece);
        }
    }

    /// Inserts piece u -> w of segment s up to its end, or up to a crossing with a
    /// segment (which pushes the pieces that replace it).
    void advance(Piece piece) {
        std::uint32_t u = piece.u, node = piece.node;
        const std::uint32_t w = piece.w, s = piece.s;
        std::vector<std::int32_t>& crossed = crossed_;
        for (std::size_t hops = 0; u != w; ++hops) {
            if (hops > pts_.size())
                stop(FailureKind::constraint_inconsistent, u, "a segment's vertices repeat");
            const Exit exit = find_exit(u, w);
            if (exit.edge != none) {  // along an existing edge, to x (w or a vertex before it)
                add_piece(exit.edge, s, node);
                if (exit.x != w) node = split_node(node, exit.x);
                u = exit.x;
                continue;
            }
            // Walk across the triangles the piece crosses, up to w or a vertex on it. A piece
            // bent by a rounded crossing (an end off the segment's line) still ends at every
            // vertex exactly on the segment that the walk meets: the rest is inserted again
            // as two straight pieces through it.
            const bool bent = !on_line(s, u) || !on_line(s, w);
            crossed.clear();
            std::int32_t e = exit.crossed;
            std::uint32_t end = 0;
            for (;;) {
                if (bent) {
                    for (const std::uint32_t v : {from(e), to(e)}) {
                        if (v != u && v != w && between(s, u, v, w) && on_segment(s, v)) {
                            if (++events_ > 8 * (added() + segments_->size()) + 64)
                                stop(FailureKind::constraint_inconsistent, s,
                                     "bent pieces keep meeting vertices of their segment");
                            const std::uint32_t m = split_node(node, v);
                            pending_.push_back({v, w, s, m});
                            pending_.push_back({u, v, s, node});
                            return;
                        }
                    }
                }
                if (seg(e) != none) {
                    cross(e, {u, w, s, node});
                    return;
                }
                crossed.push_back(e);
                if (crossed.size() > tri_.size() / 3 + 1)
                    stop(FailureKind::constraint_inconsistent, u,
                         "a segment crosses every triangle");
                const std::int32_t f = twin(e);
                if (f < 0)
                    stop(FailureKind::constraint_inconsistent, u, "a segment leaves the hull");
                const std::uint32_t v = from(prv(f));
                if (v == w) {
                    end = v;
                    break;
                }
                const Sign o = orient(u, w, v);
                if (o == Sign::zero) {
                    end = v;
                    break;
                }
                e = o == Sign::positive ? nxt(f) : prv(f);
            }
            carry_.push_back({s, node, none});
            const auto carried_piece = static_cast<std::int32_t>(carry_.size() - 1);
            if (!insert_by_retriangulation(u, end, carried_piece))
                insert_by_flips(u, end, carried_piece);
            if (end != w) node = split_node(node, end);
            u = end;
        }
    }

    /// Piece p of segment s crosses half-edge e, which carries pieces of other segments: a
    /// vertex at the crossing (the rounded crossing of the two input segments, or of the
    /// two pieces when rounding has bent them so far that the input segments no longer
    /// cross properly), and the pieces split there.
    void cross(std::int32_t e, Piece p) {
        // Every crossing makes a vertex but where segments meet at a vertex already made,
        // at most once per segment and vertex in exact arithmetic; far more events than
        // vertices and segments means the pieces are going round in circles.
        if (++events_ > 8 * (added() + segments_->size()) + 64)
            stop(FailureKind::constraint_inconsistent, p.s,
                 "crossings repeat without making vertices");
        std::vector<Carry> others;
        carried(e, others);
        std::uint32_t t = others.front().segment;
        for (const Carry& c : others) t = std::min(t, c.segment);
        const std::uint32_t r = from(e), l = to(e);
        std::array<std::uint32_t, 4> lines{end_vertex(p.s, 0), end_vertex(p.s, 1), end_vertex(t, 0),
                                           end_vertex(t, 1)};
        // Segments that share the crossed piece only because rounding bent them onto it
        // (not all on one line) cross p at different points: the crossing is then the
        // pieces' own, a point of the shared piece for every one of them.
        const bool shared_line = std::all_of(others.begin(), others.end(), [&](const Carry& c) {
            return on_line(t, end_vertex(c.segment, 0)) && on_line(t, end_vertex(c.segment, 1));
        });
        bool of_segments = shared_line && properly_cross(lines);
        // A crossing of the segments that rounds onto a vertex already on one of the chains
        // (not an end of the crossing pieces) would bend that chain back to it, a loop:
        // among segments crossing within ulps of one another such splits go round in
        // circles. The pieces are then treated as a cascade.
        Intersection i{};
        if (of_segments) {
            i = intersection(pts_[lines[0]], pts_[lines[1]], pts_[lines[2]], pts_[lines[3]]);
            if (i.ok()) {
                const Located at = locate(i.point, e / 3, pts_.size());
                if (at.where == Where::on_vertex) {
                    const std::uint32_t v = at.v;
                    const bool loops =
                        (v != p.u && v != p.w && on_chain(p.s, v)) ||
                        (v != r && v != l &&
                         std::any_of(others.begin(), others.end(),
                                     [&](const Carry& c) { return on_chain(c.segment, v); }));
                    if (loops) of_segments = false;
                }
            }
        }
        // Pieces that cross only because rounding bent them (a cascade: their segments do not
        // cross there) are first snapped to a vertex that is already there: an end of the
        // crossed piece within chain_tolerance() of p's segment joins p's chain, or an end of
        // p within the tolerance of every segment of the crossed piece joins theirs. No
        // vertex is made, so a cascade among near-collinear segments runs out of vertices
        // instead of making ever more.
        if (!of_segments) {
            // (By index, not by side: the choice must not depend on orientation, so that a
            // mirrored input gives the mirrored output.)
            for (const std::uint32_t v : {std::min(r, l), std::max(r, l)}) {
                if (!near_segment(p.s, v) || on_chain(p.s, v)) continue;
                split_piece({p.s, p.node, none}, v, pending_);
                return;
            }
            for (const std::uint32_t v : {p.u, p.w}) {
                if (!std::all_of(others.begin(), others.end(), [&](const Carry& c) {
                        return near_segment(c.segment, v) && !on_chain(c.segment, v);
                    }))
                    continue;
                clear_segments(e);
                pending_.push_back(p);
                for (const Carry& c : others) split_piece(c, v, pending_);
                return;
            }
        }
        if (!of_segments) {  // the pieces' own crossing
            lines = {p.u, p.w, r, l};
            i = intersection(pts_[lines[0]], pts_[lines[1]], pts_[lines[2]], pts_[lines[3]]);
        }
        // A crossing of the segments that rounds onto an end of one of the two pieces
        // splits the other there, and the pieces no longer meet. When the same pair does
        // that a second time at the same point, rounding has bent the pieces into a cycle
        // (each split makes the other pair cross again): the crossing of the two pieces
        // themselves, which lies inside both, breaks it.
        if (i.ok() && of_segments) {
            for (const std::uint32_t end : {p.u, p.w, r, l}) {
                if (!(pts_[end] == i.point)) continue;
                const std::array<std::uint32_t, 3> key{std::min(p.s, t), std::max(p.s, t), end};
                if (!snapped_.insert(key).second) {
                    lines = {p.u, p.w, r, l};
                    i = intersection(pts_[p.u], pts_[p.w], pts_[r], pts_[l]);
                }
                break;
            }
        }
        if (!i.ok() || !properly_cross(lines))
            stop(FailureKind::constraint_inconsistent, p.s,
                 "crossing pieces of segments do not meet");
        clear_segments(e);
        restores_.clear();
        const std::uint32_t x =
            insert_point(i.point, e / 3, {std::min(p.s, t), std::max(p.s, t)}, lines);
        split_piece({p.s, p.node, none}, x, pending_);
        for (const Carry& c : others) split_piece(c, x, pending_);
        pending_.insert(pending_.end(), restores_.begin(), restores_.end());
    }

    std::uint32_t end_vertex(std::uint32_t s, int which) const {
        const Segment& g = (*segments_)[s];
        return vertex_of_[which == 0 ? g.a : g.b];
    }
    /// Vertex v lies exactly on the line of segment s / on the open segment s.
    bool on_line(std::uint32_t s, std::uint32_t v) const {
        return orient(end_vertex(s, 0), end_vertex(s, 1), v) == Sign::zero;
    }
    bool on_segment(std::uint32_t s, std::uint32_t v) const {
        if (!on_line(s, v)) return false;
        const Point2 a = pts_[end_vertex(s, 0)], b = pts_[end_vertex(s, 1)], p = pts_[v];
        if (a.x != b.x) return std::min(a.x, b.x) < p.x && p.x < std::max(a.x, b.x);
        return std::min(a.y, b.y) < p.y && p.y < std::max(a.y, b.y);
    }
    /// Vertex v is on the chain of segment s (a walk of the chain: only cascades ask).
    bool on_chain(std::uint32_t s, std::uint32_t v) const {
        std::size_t count = 0;
        for (std::uint32_t n = head_[s]; n != end_of_chain; n = nodes_[n].next) {
            if (nodes_[n].vertex == v) return true;
            if (++count > nodes_.size())
                stop(FailureKind::constraint_inconsistent, s, "a segment's chain does not end");
        }
        return false;
    }
    /// Vertex v lies within chain_tolerance() of segment s (exact).
    bool near_segment(std::uint32_t s, std::uint32_t v) const {
        const Point2 a = pts_[end_vertex(s, 0)], b = pts_[end_vertex(s, 1)];
        return compare_segment_distance(pts_[v], a, b, chain_tolerance(a, b)) != Sign::positive;
    }
    /// v lies strictly between u and w along the axis on which segment s extends most
    /// (each split of a bent piece at a vertex then narrows the piece, so it ends).
    bool between(std::uint32_t s, std::uint32_t u, std::uint32_t v, std::uint32_t w) const {
        const Point2 a = pts_[end_vertex(s, 0)], b = pts_[end_vertex(s, 1)];
        const bool by_x = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
        const double pu = by_x ? pts_[u].x : pts_[u].y, pv = by_x ? pts_[v].x : pts_[v].y,
                     pw = by_x ? pts_[w].x : pts_[w].y;
        return std::min(pu, pw) < pv && pv < std::max(pu, pw);
    }
    /// Segments ab and cd (by vertex) cross at a point interior to both.
    bool properly_cross(const std::array<std::uint32_t, 4>& v) const {
        const int ab_c = to_int(orient(v[0], v[1], v[2])), ab_d = to_int(orient(v[0], v[1], v[3]));
        const int cd_a = to_int(orient(v[2], v[3], v[0])), cd_b = to_int(orient(v[2], v[3], v[1]));
        return ab_c * ab_d < 0 && cd_a * cd_b < 0;
    }

    /// Makes u -> v an edge, the piece of carry entry `piece`, by flipping the edges it
    /// crosses (crossed_, in order along it; none is a piece), then restores the
    /// constrained Delaunay property around the new edges (Sloan 1993). A crossed edge whose
    /// quadrilateral is strictly convex is flipped, and its new diagonal goes back to the
    /// list while it still crosses u -> v; one that is not convex waits at the end of the
    /// list. Some crossed edge always has a convex quadrilateral (Sloan's lemma), so every
    /// round flips, and the list empties. Unlike removing the crossed triangles and filling
    /// the two sides, this needs no care for a vertex whose every triangle the segment
    /// crosses (it hangs inside one side, joined to the rest by one edge).
    ///
    /// The edges waiting (crossing ones, and the new diagonals that no longer cross, for
    /// Lawson's flips after) are held by half-edge, kept current through the flips: a flip
    /// rewrites only its two triangles, so only the four sides of its quadrilateral move
    /// to other slots, and the slot map entry_of_ (slot -> waiting entry) says which
    /// entries to update. No edge is searched for in a fan but the finished piece.
    void insert_by_flips(std::uint32_t u, std::uint32_t v, std::int32_t piece) {
        std::vector<std::int32_t>& waiting = waiting_;  // entry -> its half-edge
        std::vector<std::uint32_t>& list = crossing_entries_;
        std::vector<std::uint32_t>& fresh = fresh_entries_;
        waiting.clear();
        list.clear();
        fresh.clear();
        if (entry_of_.size() < tri_.size()) entry_of_.resize(tri_.size(), none);
        const auto hold = [&](std::int32_t h) {
            const auto entry = static_cast<std::uint32_t>(waiting.size());
            waiting.push_back(h);
            entry_of_[static_cast<std::size_t>(h)] = static_cast<std::int32_t>(entry);
            return entry;
        };
        // Every vertex the flips meet is an end of a crossed edge, whose side of u -> v the
        // walk decided (each crossed edge runs from right to left): kept, not asked again.
        if (side_.size() < pts_.size()) side_.resize(pts_.size(), 0);
        ++side_stamp_;
        const std::uint64_t right = side_stamp_ << 1, left = right | 1;
        for (const std::int32_t e : crossed_) {
            list.push_back(hold(e));
            side_[from(e)] = right;
            side_[to(e)] = left;
        }
        const auto side_of = [&](std::uint32_t x) {
            const std::uint64_t mark = side_[x];
            if (mark == left) return 1;
            if (mark == right) return -1;
            return to_int(orient(u, v, x));  // u or v themselves: zero
        };
        const std::size_t k = list.size();
        std::size_t budget = 8 * (k + 1) * (k + 1) + 64;
        for (std::size_t head = 0; head < list.size(); ++head) {
            if (budget-- == 0)
                stop(FailureKind::constraint_inconsistent, u,
                     "flipping the edges a segment crosses does not end");
            const std::uint32_t entry = list[head];
            const std::int32_t e = waiting[entry];
            if (e < 0 || twin(e) < 0)
                stop(FailureKind::constraint_inconsistent, u,
                     "an edge a segment crosses has vanished");
            const std::uint32_t c = from(prv(e)), d = from(prv(twin(e)));
            const std::uint32_t p = from(e), q = to(e);
            if (orient(c, d, q) != Sign::positive || orient(c, d, p) != Sign::negative) {
                list.push_back(entry);  // not convex: later
                continue;
            }
            // The sides of the quadrilateral (e's triangle's, then its twin's), where the
            // flip puts each: (p, q, c), (q, p, d) become (c, p, d), (d, q, c).
            const std::int32_t f = twin(e);
            const std::int32_t t1 = e / 3, t2 = f / 3;
            const std::array<std::int32_t, 4> before{nxt(e), prv(e), nxt(f), prv(f)};
            const std::array<std::int32_t, 4> after{3 * t2 + 1, 3 * t1, 3 * t1 + 1, 3 * t2};
            std::array<std::int32_t, 4> moved{};
            for (int i = 0; i < 4; ++i) {
                moved[i] = entry_of_[static_cast<std::size_t>(before[i])];
                entry_of_[static_cast<std::size_t>(before[i])] = none;
            }
            entry_of_[static_cast<std::size_t>(e)] = none;
            entry_of_[static_cast<std::size_t>(f)] = none;
            flip(e);
            for (int i = 0; i < 4; ++i) {
                if (moved[i] < 0) continue;
                waiting[static_cast<std::size_t>(moved[i])] = after[i];
                entry_of_[static_cast<std::size_t>(after[i])] = moved[i];
            }
            // The new diagonal c -> d is half-edge 3 t2 + 2 (d -> c is 3 t1 + 2); it takes
            // over e's entry.
            const std::int32_t diagonal = 3 * t1 + 2;
            waiting[entry] = diagonal;
            entry_of_[static_cast<std::size_t>(diagonal)] = static_cast<std::int32_t>(entry);
            const int side_c = side_of(c), side_d = side_of(d);
            (side_c * side_d < 0 ? list : fresh).push_back(entry);
        }
        for (const std::int32_t h : waiting)
            if (h >= 0) entry_of_[static_cast<std::size_t>(h)] = none;
        const std::int32_t h = find_edge(u, v);
        if (h < 0)
            stop(FailureKind::constraint_inconsistent, u, "flips did not make a segment an edge");
        seg_[static_cast<std::size_t>(h)] = piece;
        if (twin(h) >= 0) seg_[static_cast<std::size_t>(twin(h))] = piece;
        // The new edges that no longer cross, then Lawson.
        std::vector<std::int32_t>& queue = stack_;
        queue.clear();
        for (const std::uint32_t entry : fresh) queue.push_back(waiting[entry]);
        flip_queue(queue);
    }
    /// Makes u -> v an edge, the piece of carry entry `piece`, by removing the triangles it
    /// crosses (crossed_, in order along it; none of their edges is a piece) and filling
    /// the two pseudo-polygons on its sides, each with the Delaunay triangulation of its
    /// vertices (Anglada 1997): on a base edge, the apex is the vertex whose circle with
    /// the base holds no other vertex of the polygon part over that base (one scan, each
    /// vertex strictly inside the current circle taking its place), and the two parts on
    /// either side of the apex are filled the same way. The triangles the segment crossed
    /// are constrained Delaunay, so the new ones are too, and no flip follows. Returns
    /// false, having changed nothing, when a vertex hangs inside one side (every one of its
    /// triangles crossed: it would appear twice on its side's chain); insert_by_flips()
    /// handles that. Slots are reused: k crossed edges free k + 1 triangles, and the two
    /// polygons of k + 3 vertices make k + 1.
    bool insert_by_retriangulation(std::uint32_t u, std::uint32_t v, std::int32_t piece) {
        const std::size_t k = crossed_.size();
        // The chains along each side, u first and v last, with the half-edge of each of
        // their sides in a crossed triangle (inside[i] joins chain[i] and chain[i + 1];
        // left: chain[i + 1] -> chain[i], right: chain[i] -> chain[i + 1]).
        std::vector<std::uint32_t>& left = chain_left_;
        std::vector<std::uint32_t>& right = chain_right_;
        std::vector<std::int32_t>& inside_left = inside_left_;
        std::vector<std::int32_t>& inside_right = inside_right_;
        left.assign(1, u);
        right.assign(1, u);
        inside_left.clear();
        inside_right.clear();
        if (side_.size() < pts_.size()) side_.resize(pts_.size(), 0);
        ++side_stamp_;
        const std::uint64_t mark = side_stamp_ << 1;
        const auto append = [&](std::vector<std::uint32_t>& chain, std::uint32_t x) {
            if (side_[x] == mark) return false;  // seen before on this walk: a hanging vertex
            side_[x] = mark;
            chain.push_back(x);
            return true;
        };
        side_[u] = mark;
        const std::int32_t e0 = crossed_.front();
        if (!append(left, to(e0)) || !append(right, from(e0))) return false;
        inside_left.push_back(nxt(e0));
        inside_right.push_back(prv(e0));
        for (std::size_t i = 0; i + 1 < k; ++i) {
            const std::int32_t f = twin(crossed_[i]);
            const std::int32_t next = crossed_[i + 1];
            if (next == nxt(f)) {  // the triangle's third vertex is on the left
                if (!append(left, to(next))) return false;
                inside_left.push_back(prv(f));
            } else {
                if (!append(right, from(next))) return false;
                inside_right.push_back(nxt(f));
            }
        }
        const std::int32_t last = twin(crossed_.back());
        if (side_[v] == mark) return false;
        left.push_back(v);
        right.push_back(v);
        inside_left.push_back(prv(last));
        inside_right.push_back(nxt(last));
        // The cavity's slots and its sides' outer twins and pieces, before any is rewritten.
        std::vector<std::int32_t>& slots = cavity_slots_;
        slots.clear();
        slots.push_back(e0 / 3);
        for (const std::int32_t e : crossed_) slots.push_back(twin(e) / 3);
        std::vector<std::array<std::int32_t, 2>>& outer_left = outer_left_;
        std::vector<std::array<std::int32_t, 2>>& outer_right = outer_right_;
        outer_left.clear();
        outer_right.clear();
        for (const std::int32_t h : inside_left) outer_left.push_back({twin(h), seg(h)});
        for (const std::int32_t h : inside_right) outer_right.push_back({twin(h), seg(h)});
        // Fill each side: a stack of (i, j, the half-edge across base chain[i] - chain[j]).
        std::size_t next_slot = 0;
        const std::int32_t base_left = fill_side(left, outer_left, true, none, piece, next_slot);
        fill_side(right, outer_right, false, base_left, piece, next_slot);
        return true;
    }

    /// A part of a pseudo-polygon to fill: chain[i..j] over base chain[i] - chain[j], and
    /// the half-edge across that base (none: not written yet).
    struct FillPart {
        std::uint32_t i, j;
        std::int32_t across;
    };
    /// Fills one side of insert_by_retriangulation(): `chain` runs from the piece's u to
    /// its v, on the left of u -> v (`is_left`) or on its right; `outer` holds, for each
    /// side chain[i] - chain[i + 1], its outer twin and pieces. `across` is the half-edge
    /// the base u - v pairs with (none for the first side filled). Returns the base's
    /// half-edge.
    std::int32_t fill_side(const std::vector<std::uint32_t>& chain,
                           const std::vector<std::array<std::int32_t, 2>>& outer, bool is_left,
                           std::int32_t across, std::int32_t piece, std::size_t& next_slot) {
        std::vector<FillPart>& parts = fill_parts_;
        parts.clear();
        parts.push_back({0, static_cast<std::uint32_t>(chain.size() - 1), across});
        std::int32_t base = none;
        while (!parts.empty()) {
            const FillPart p = parts.back();
            parts.pop_back();
            // The triangle over base chain[i] - chain[j] is counter-clockwise as (i, j, c) on
            // the left, (j, i, c) on the right.
            const std::uint32_t a = chain[is_left ? p.i : p.j], b = chain[is_left ? p.j : p.i];
            std::uint32_t c = p.i + 1;
            for (std::uint32_t m = p.i + 2; m < p.j; ++m) {
                if (k_.incircle(pts_[a], pts_[b], pts_[chain[c]], pts_[chain[m]]) == Sign::positive)
                    c = m;
            }
            if (next_slot >= cavity_slots_.size())
                stop(FailureKind::constraint_inconsistent, a,
                     "refilling the triangles a segment crosses needs more of them");
            const std::int32_t t = cavity_slots_[next_slot++];
            // Half-edges 3t: a -> b (the base), 3t + 1: b -> chain[c], 3t + 2: chain[c] -> a.
            // On the left b -> c joins (c, j) and c -> a joins (i, c); on the right b -> c
            // joins (i, c) and c -> a joins (c, j).
            using Range = std::array<std::uint32_t, 2>;
            const std::array<Range, 2> sides = is_left ? std::array{Range{c, p.j}, Range{p.i, c}}
                                                       : std::array{Range{p.i, c}, Range{c, p.j}};
            std::array<std::int32_t, 3> segs{p.i == 0 && p.j + 1 == chain.size() ? piece : none,
                                             none, none};
            std::array<std::int32_t, 3> twins{p.across, none, none};
            for (int s = 0; s < 2; ++s) {
                const auto [x, y] = sides[static_cast<std::size_t>(s)];
                if (y == x + 1) {  // a side of the chain
                    twins[static_cast<std::size_t>(s + 1)] = outer[x][0];
                    segs[static_cast<std::size_t>(s + 1)] = outer[x][1];
                } else {
                    parts.push_back({x, y, 3 * t + 1 + s});
                }
            }
            write(t, {a, b, chain[c]}, segs, twins);
            if (base == none) base = 3 * t;  // the first part is the whole side
        }
        return base;
    }

    // ---- the result ------------------------------------------------------------------------

    /// Runs every segment and writes the result.
    void run(std::span<const Segment> segments, ConstrainedTriangulation& out) {
        start(segments);
        for (std::size_t s = 0; s < segments.size(); ++s) {
            const std::uint32_t a = vertex_of_[segments[s].a], b = vertex_of_[segments[s].b];
            if (a != b) insert_segment(a, b, static_cast<std::uint32_t>(s));
        }
        finish(segments, out);
    }

    /// Snap rounding (Hobby 1999; Guibas and Marimont 1998) on the grid of doubles, for an
    /// input whose crossing cascade did not settle in run(). The hot pixels are those of
    /// the segments' ends, of the input points exactly inside a segment, and of the rounded
    /// crossing of every two input segments that cross properly: rounding to nearest maps
    /// a point to the double whose pixel holds it, so each crossing's pixel is the one
    /// that holds the exact crossing, as snap rounding requires. Each segment becomes the
    /// chain of the vertices of the hot pixels it meets, in order along it (exact:
    /// pixels_on_segment()). On a uniform grid snap-rounded chains do not cross one
    /// another (they may share pieces and meet at vertices: Hobby's theorem); the doubles
    /// are a uniform grid only within a binade, and a long piece that ends in a binade of
    /// larger pixels can still cross another (found by `exidel study constrained`: nearly
    /// parallel segments of slope 7 across y = 8). Such a leftover crossing is resolved as
    /// in run(), a small cascade, within the same limits; a failure here is final. Every
    /// snapped chain vertex lies in a pixel the segment meets, within two ulps of it.
    void run_snapped(std::span<const Segment> segments, ConstrainedTriangulation& out) {
        start(segments);
        snapping_ = true;
        struct Box {
            double x0, x1, y0, y1;
            std::uint32_t a, b, s;
        };
        std::vector<Box> boxes;
        for (std::size_t s = 0; s < segments.size(); ++s) {
            const std::uint32_t a = vertex_of_[segments[s].a], b = vertex_of_[segments[s].b];
            if (a == b) continue;
            const Point2 p = pts_[a], q = pts_[b];
            boxes.push_back({std::min(p.x, q.x), std::max(p.x, q.x), std::min(p.y, q.y),
                             std::max(p.y, q.y), a, b, static_cast<std::uint32_t>(s)});
        }
        std::sort(boxes.begin(), boxes.end(), [](const Box& g, const Box& h) {
            return g.x0 < h.x0 || (g.x0 == h.x0 && g.s < h.s);
        });
        // Every two segments that cross properly (a sweep over x): the rounded crossing
        // becomes a vertex, or is one already.
        std::vector<std::uint32_t> crossing_vertices;
        {
            std::vector<std::size_t> active;
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                const Box& g = boxes[i];
                std::erase_if(active, [&](std::size_t j) { return boxes[j].x1 < g.x0; });
                for (const std::size_t j : active) {
                    const Box& h = boxes[j];
                    if (h.y1 < g.y0 || g.y1 < h.y0) continue;
                    const std::array<std::uint32_t, 4> lines{h.a, h.b, g.a, g.b};
                    if (!properly_cross(lines)) continue;
                    const Intersection x = intersection(pts_[h.a], pts_[h.b], pts_[g.a], pts_[g.b]);
                    if (!x.ok())
                        stop(FailureKind::constraint_inconsistent, g.s,
                             "the crossing of two segments cannot be rounded");
                    crossing_vertices.push_back(insert_point(
                        x.point, out_[g.a] / 3, {std::min(g.s, h.s), std::max(g.s, h.s)}, lines));
                }
                active.push_back(i);
            }
        }
        std::vector<char> hot(pts_.size(), 0);
        for (const Box& g : boxes) hot[g.a] = hot[g.b] = 1;
        for (const std::uint32_t v : crossing_vertices) hot[v] = 1;
        // The vertices by x, to find those near a segment.
        std::vector<std::uint32_t> by_x;
        for (std::uint32_t v = 0; v < pts_.size(); ++v)
            if (vertex_of_[v] == v) by_x.push_back(v);
        std::sort(by_x.begin(), by_x.end(),
                  [&](std::uint32_t u, std::uint32_t v) { return lex_less(pts_[u], pts_[v]); });
        const auto near = [&](const Box& g, double pad, const std::vector<std::uint32_t>& from,
                              auto&& f) {
            auto it = std::lower_bound(from.begin(), from.end(), g.x0 - pad,
                                       [&](std::uint32_t v, double x) { return pts_[v].x < x; });
            for (; it != from.end() && pts_[*it].x <= g.x1 + pad; ++it) {
                const double y = pts_[*it].y;
                if (g.y0 - pad <= y && y <= g.y1 + pad) f(*it);
            }
        };
        // Input points exactly inside a segment.
        for (const Box& g : boxes)
            near(g, 0.0, by_x, [&](std::uint32_t v) {
                if (!hot[v] && on_segment(g.s, v)) hot[v] = 1;
            });
        std::vector<std::uint32_t> hot_by_x;
        for (const std::uint32_t v : by_x)
            if (hot[v]) hot_by_x.push_back(v);
        // Each segment's chain: the hot pixels it meets. A pixel is at most two ulps of its
        // point's largest coordinate wide, so the pad below (2^-50 of the box's largest
        // coordinate, plus a few subnormals) lets every pixel the segment meets through;
        // the exact test decides.
        std::vector<std::uint32_t> candidates;
        for (const Box& g : boxes) {
            const double m =
                std::max({std::abs(g.x0), std::abs(g.x1), std::abs(g.y0), std::abs(g.y1)});
            const double pad = std::ldexp(m, -50) + std::ldexp(1.0, -1070);
            candidates.clear();
            near(g, pad, hot_by_x, [&](std::uint32_t v) { candidates.push_back(v); });
            const std::vector<std::uint32_t> chain =
                pixels_on_segment(pts_[g.a], pts_[g.b], pts_, candidates);
            if (chain.size() < 2 || chain.front() != g.a || chain.back() != g.b)
                stop(FailureKind::constraint_inconsistent, g.s,
                     "a snap-rounded segment does not run from its first end to its second");
            const auto first = static_cast<std::uint32_t>(nodes_.size());
            for (std::size_t k = 0; k < chain.size(); ++k)
                nodes_.push_back({chain[k], k + 1 < chain.size()
                                                ? first + static_cast<std::uint32_t>(k + 1)
                                                : end_of_chain});
            head_[g.s] = first;
        }
        // The pieces, each from its node to the next (a vertex met exactly on the way splits
        // it, as in run()).
        for (const Box& g : boxes) {
            for (std::uint32_t n = head_[g.s]; nodes_[n].next != end_of_chain;) {
                const std::uint32_t next = nodes_[n].next;
                pending_.clear();
                pending_.push_back({nodes_[n].vertex, after(n), g.s, n});
                while (!pending_.empty()) {
                    const Piece piece = pending_.back();
                    pending_.pop_back();
                    advance(piece);
                }
                n = next;
            }
        }
        finish(segments, out);
    }

    void start(const std::span<const Segment>& segments) {  // segments_ points at the caller's span
        segments_ = &segments;
        // Two segments cross at most once, so exact crossings make at most s (s - 1) / 2
        // points; the allowance beyond that is for crossings of bent pieces. A run that
        // needs more is one where rounding keeps bending pieces across each other, and it
        // stops instead of growing without end.
        const std::size_t m = segments.size();
        const std::size_t pairs = m < (std::size_t{1} << 31) ? m * (m - (m > 0)) / 2 : max_added_;
        natural_cap_ = pairs + 2 * m + 64 < max_added_;
        if (natural_cap_) max_added_ = pairs + 2 * m + 64;
        head_.assign(segments.size(), end_of_chain);
    }

    /// The chains' final fix-ups and the result.
    void finish(std::span<const Segment> segments, ConstrainedTriangulation& out) {
        if (events_ > 0) {
            for (std::size_t s = 0; s < segments.size(); ++s)
                cut_loops(static_cast<std::uint32_t>(s));
            mark_pieces();
            flip_everything();
        }
        out.input_count = input_count_;
        // The chains, in the order of their nodes.
        out.chain_offsets.assign(1, 0);
        out.chain_vertices.clear();
        std::vector<std::array<std::uint32_t, 2>> pieces;
        for (std::size_t s = 0; s < segments.size(); ++s) {
            if (head_[s] == end_of_chain) {
                out.chain_vertices.push_back(vertex_of_[segments[s].a]);
            } else {
                std::size_t count = 0;
                for (std::uint32_t n = head_[s]; n != end_of_chain; n = nodes_[n].next) {
                    if (++count > nodes_.size())
                        stop(FailureKind::constraint_inconsistent, s,
                             "a segment's chain does not end");
                    const std::uint32_t v = nodes_[n].vertex;
                    if (nodes_[n].next != end_of_chain) {
                        const std::uint32_t w = after(n);
                        pieces.push_back({std::min(v, w), std::max(v, w)});
                    }
                    out.chain_vertices.push_back(v);
                }
            }
            out.chain_offsets.push_back(static_cast<std::uint32_t>(out.chain_vertices.size()));
        }
        out.constraints = sorted_pieces(pieces);
        out.crossings = std::move(crossings_);
        out.crossing_lines = std::move(crossing_lines_);
        // The boundary cycle from its lexicographically smallest vertex.
        Triangulation& t = out.triangulation;
        std::int32_t first = none;
        for (std::size_t e = 0; e < twin_.size(); ++e) {
            if (twin_[e] >= 0) continue;
            const auto h = static_cast<std::int32_t>(e);
            if (first < 0 || lex_less(pts_[from(h)], pts_[from(first)])) first = h;
        }
        t.hull.clear();
        if (first >= 0) {
            std::int32_t h = first;
            do {
                t.hull.push_back(from(h));
                if (t.hull.size() > twin_.size())
                    stop(FailureKind::constraint_inconsistent, from(h),
                         "the boundary does not close");
                h = next_boundary(h);
            } while (h != first);
        }
        t.triangles = std::move(tri_);
        t.halfedges = std::move(twin_);
        t.vertex_of_input = std::move(vertex_of_);
        t.duplicates = std::move(duplicates_);
        t.collinear = false;
        out.points = std::move(pts_);
    }
    /// `pieces` (u < v each) sorted and without repeats, in linear time: counted by u, then
    /// each vertex's few sorted in place (a comparison sort of 10^6 pieces cost about a
    /// tenth of a polygon's whole insertion).
    std::vector<std::array<std::uint32_t, 2>> sorted_pieces(
        const std::vector<std::array<std::uint32_t, 2>>& pieces) const {
        std::vector<std::uint32_t> start(pts_.size() + 1, 0);
        for (const auto& piece : pieces) ++start[piece[0] + 1];
        for (std::size_t v = 0; v < pts_.size(); ++v) start[v + 1] += start[v];
        std::vector<std::array<std::uint32_t, 2>> sorted(pieces.size());
        {
            std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
            for (const auto& piece : pieces) sorted[fill[piece[0]]++] = piece;
        }
        std::size_t kept = 0;
        for (std::size_t v = 0; v < pts_.size(); ++v) {
            const auto first = sorted.begin() + start[v], last = sorted.begin() + start[v + 1];
            std::sort(first, last);
            for (auto it = first; it != last; ++it)
                if (it == first || (*it)[1] != (*(it - 1))[1]) sorted[kept++] = *it;
        }
        sorted.resize(kept);
        return sorted;
    }
    /// Where rounding has bent pieces back across each other, a chain can pass a vertex
    /// twice; the loop between the two visits is cut out (the chain keeps its first visit
    /// and continues from the second), and its pieces stop carrying the segment. An edge
    /// that no longer carries any segment is then judged by the final flips.
    void cut_loops(std::uint32_t s) {
        if (head_[s] == end_of_chain) return;
        seen_.resize(pts_.size(), {0, 0});
        const std::uint32_t stamp = s + 1;
        std::size_t count = 0;
        for (std::uint32_t n = head_[s]; n != end_of_chain; n = nodes_[n].next) {
            if (++count > nodes_.size())
                stop(FailureKind::constraint_inconsistent, s, "a segment's chain does not end");
            const std::uint32_t x = nodes_[n].vertex;
            auto& [mark, first] = seen_[x];
            if (mark != stamp) {
                mark = stamp;
                first = n;
                continue;
            }
            // first -> ... -> n is a loop through x: drop its pieces.
            for (std::uint32_t m = first; m != n; m = nodes_[m].next) {
                drop_piece(s, m);
                if (m != first) seen_[nodes_[m].vertex] = {0, 0};
            }
            nodes_[first].next = nodes_[n].next;
            n = first;
        }
    }
    /// After cascades, the edges that are pieces are marked again from the chains alone:
    /// an edge left marked by a piece that a later split or cut replaced would otherwise
    /// escape the final flips without being a constraint.
    void mark_pieces() {
        seg_.assign(seg_.size(), none);
        carry_.clear();
        for (std::uint32_t s = 0; s < head_.size(); ++s) {
            std::size_t count = 0;
            for (std::uint32_t n = head_[s]; n != end_of_chain && nodes_[n].next != end_of_chain;
                 n = nodes_[n].next) {
                if (++count > nodes_.size())
                    stop(FailureKind::constraint_inconsistent, s, "a segment's chain does not end");
                const std::int32_t e = find_edge(nodes_[n].vertex, after(n));
                if (e < 0)
                    stop(FailureKind::constraint_inconsistent, s,
                         "a piece of a segment is not an edge");
                add_piece(e, s, n);
            }
        }
    }
    /// The edge of node m's piece stops carrying segment s.
    void drop_piece(std::uint32_t s, std::uint32_t m) {
        const std::int32_t e = find_edge(nodes_[m].vertex, after(m));
        if (e < 0)
            stop(FailureKind::constraint_inconsistent, s, "a piece of a segment is not an edge");
        std::int32_t head = none;
        std::vector<Carry> kept;
        carried(e, kept);
        for (auto it = kept.rbegin(); it != kept.rend(); ++it) {
            if (it->segment == s && it->node == m) continue;
            carry_.push_back({it->segment, it->node, head});
            head = static_cast<std::int32_t>(carry_.size() - 1);
        }
        seg_[static_cast<std::size_t>(e)] = head;
        if (twin(e) >= 0) seg_[static_cast<std::size_t>(twin(e))] = head;
    }

    static bool lex_less(Point2 a, Point2 b) noexcept {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    }

private:
    const K& k_;
    std::vector<Point2> pts_;
    std::vector<std::uint32_t> tri_;
    std::vector<std::int32_t> twin_;
    std::vector<std::uint32_t> vertex_of_;
    std::vector<std::uint32_t> duplicates_;
    std::size_t input_count_;
    std::size_t max_added_;
    std::vector<std::int32_t> seg_;
    std::vector<std::int32_t> out_;
    std::vector<std::array<std::uint32_t, 2>> crossings_;
    std::vector<std::array<std::uint32_t, 4>> crossing_lines_;
    std::vector<Carry> carry_, on_edge_;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> head_;
    struct Seen {
        std::uint32_t mark, first;
    };
    std::vector<Seen> seen_;
    const std::span<const Segment>* segments_ = nullptr;
    std::size_t events_ = 0;
    bool natural_cap_ = false;
    bool snapping_ = false;  ///< in run_snapped(): a failure is final
    std::set<std::array<std::uint32_t, 3>> snapped_;
    std::uint64_t rng_ = 0x9e3779b97f4a7c15ULL;
    // Scratch, reused.
    std::vector<Piece> pending_, restores_;
    std::vector<std::int32_t> stack_, crossed_;
    std::vector<std::int32_t> waiting_, entry_of_;
    std::vector<std::uint64_t> side_;  ///< per vertex: 2 stamp + 1 left of it, 2 stamp right
    std::uint64_t side_stamp_ = 0;     ///< one per piece inserted by flips (never wraps)
    std::vector<std::uint32_t> crossing_entries_, fresh_entries_;
    std::vector<std::uint32_t> chain_left_, chain_right_;
    std::vector<std::int32_t> inside_left_, inside_right_, cavity_slots_;
    std::vector<std::array<std::int32_t, 2>> outer_left_, outer_right_;
    std::vector<FillPart> fill_parts_;
};

}  // namespace detail
}  // namespace exidel::delaunay
