// exidel: the randomized incremental Delaunay triangulation with a history DAG for point
// location (de Berg, Cheong, van Kreveld, Overmars, Computational Geometry, 3rd ed.,
// ch. 9), as a registered algorithm (algorithms.hpp: `randomized`). Unlike the book it
// has no bounding super-triangle: a symbolic vertex at infinity closes the triangulation
// into a sphere with "ghost" triangles (as CGAL does), so that with an exact kernel the
// result is exactly a Delaunay triangulation of the points, hull and collinear hull
// points included, with nothing to remove afterwards.
//
// Order. The sorted distinct points are put in a uniformly random order by a
// Fisher-Yates shuffle driven by splitmix64 from a fixed seed (not std::shuffle, whose
// result differs between standard libraries): the output is the same on every platform.
// A vertex's id is its position in that order. The first two points are kept; the first
// later point off their line is swapped into position 2, and positions 1 and 2 are
// swapped when that makes the first triangle counter-clockwise. Fewer than three points,
// or all of them on one line, give no triangle (the mesh is marked collinear).
//
// Structure. Every triangle ever created has its own slot, never reused, which is also
// its node of the history DAG: three vertex ids (counter-clockwise, fixed at creation),
// the twin of each of its half-edges, and, once it is destroyed, its children. Each
// operation below creates its triangles in consecutive slots and gives a destroyed
// triangle some of them as children, so children are a range of slots (first, count): a
// destroyed node has at least two, a live node none. Vertex `inf` = n is the vertex at
// infinity. A ghost triangle is (b, a, inf) for the hull edge a -> b, inf always at
// position 2: its half-edge b -> a is the twin of the finite hull half-edge, a -> inf
// and inf -> b are twins of the neighbouring ghosts' half-edges, so every half-edge has
// a twin (the surface is closed like a sphere) and going from ghost to ghost follows the
// hull. The first triangle (a, b, c) and its three ghosts are the four roots.
//
// Regions. A finite node stands for its closed triangle; a ghost node (b, a, inf) for
// the open half-plane strictly outside its hull edge a -> b, orient2d(b, a, x) > 0. The
// roots cover the plane (a point outside the closed triangle is strictly outside one of
// its edges). A point is located by descending from the roots, at each node to a child
// whose region contains it, until a live node. That always exists with an exact kernel
// because every destroyed node's region is covered by its children's:
//   - a split (1 -> 3), an edge split (2 -> 2 + 2) and a flip (2 -> 2) replace closed
//     triangles by closed triangles with the same union; both triangles of a flip are
//     children of both destroyed ones;
//   - a ghost split by a point on its hull edge becomes two ghosts on the same line:
//     the same half-plane;
//   - when a point x outside the hull makes the visible ghosts die, each of them gets as
//     children all the new triangles of x: the fan triangles on the visible chain
//     u_0 .. u_k and the two new ghosts of u_0 -> x and x -> u_k. Let y be strictly
//     outside a dead visible edge u_i u_(i+1), in its open half-plane H. If y is outside
//     the new hull, join it to a point z of the open edge u_i u_(i+1), which is now
//     interior: the open segment yz lies in H, which the old hull does not meet, so it
//     leaves the new hull across u_0 x or x u_k, and for all but finitely many z it does
//     so transversally in the relative interior of that edge: y is strictly outside it,
//     in that new ghost's region. If y is inside the new hull, it lies in the cone at x
//     spanned by the chain, in the wedge of some fan triangle x u_j u_(j+1); not beyond
//     the segment u_j u_(j+1), since the ray from x has left H there (it met the old
//     hull) and cannot come back into a convex set: y is in that closed triangle.
//   The fan's children are not tested one by one (k can be large: points on a circle
//   and one far point make every later point pass through ghosts with Theta(n) fan
//   triangles): its two ghosts are tested first, then the rays x -> u_j, which turn
//   clockwise with j through less than a half-turn, are binary-searched for the wedge
//   of y (the sign of orient2d(x, u_j, y) changes at most once along j), and the one
//   fan triangle found is tested as usual. That is O(log k) orientations instead of k.
// Children are created after their parents, so a descent visits increasing slots and
// ends. With an inexact kernel no child may contain the point: location_exceeded. The
// descent is bound by memory latency, not by arithmetic (each step jumps to a node
// created at a random later time): a node's vertices and children share one record, the
// points of the current node are kept at hand, since a child has at most one vertex its
// parent lacks, and the grandchildren are prefetched while the children are tested.
//
// Insertion of x at a leaf.
//   - finite leaf (a, b, c), x strictly inside: three triangles (a, b, x), (b, c, x),
//     (c, a, x);
//   - x on one of its edges (orientation zero; strictly inside the edge, the points
//     being distinct): the triangle and its neighbour across that edge are split in two
//     each; if the neighbour is a ghost (x on a hull edge) it becomes two ghosts and x
//     a hull vertex between the edge's ends;
//   - ghost leaf (x strictly outside its hull edge): walk the hull both ways from it,
//     ghost to ghost, while x is strictly outside the next edge (a point on the line of
//     a hull edge does not see it, so collinear hull points stay vertices and no flat
//     triangle is made); each walk is bounded by the hull size (hull_walk_exceeded).
//     Every visible edge u_i -> u_(i+1) gets the fan triangle (u_(i+1), u_i, x) in place
//     of its ghost, and the ghosts (x, u_0, inf), (u_k, x, inf) close the new hull.
//     The fan edges x-u_i need no test: the open half-plane beyond a visible hull edge
//     holds no point, and the circle through x and u_i tangent at u_i to the edge's line
//     lies in it, so x u_i is a Delaunay edge (de Berg's argument that new edges are
//     legal, with the ghost's "circle" being its half-plane).
// Then every edge a-b opposite x in the new finite triangles (a, b, x) is legalized
// (Lawson), with an explicit stack: a hull edge (a ghost behind it) is legal; otherwise
// with d the apex of (b, a, d) behind it, the edge is flipped to x-d iff x is strictly
// inside the circle of (b, a, d), and the two edges a-d, d-b, now opposite x, are pushed.
// Every new edge at x is a Delaunay edge (the circle through x and d inside the circle
// of (b, a, d), which held no point but x), so when the stack is empty every edge is
// locally Delaunay and the triangulation is Delaunay. Points on a circle keep their
// edge (strictly inside only), which makes cocircular input terminate.
//
// The in-circle test is decided in one place, in_circle. With exact orientations both
// triangles at every tested edge are strictly counter-clockwise (splits put x strictly
// inside a triangle or an edge, the fan only uses strictly visible edges, and a flip of
// an edge whose opposite point is strictly inside the circle makes a strictly convex
// quadrilateral), so x and d are strictly on opposite sides of a-b: the precondition of
// the paper's Theorem 1 (Cai 2025) holds at every test, and the cosine policy is valid
// everywhere in this algorithm, not only where it is in the external one.
//
// Counters: location_steps (DAG nodes a descent entered, the leaf included),
// location_orientations, tangent_orientations (the hull walks), seed_orientations,
// incircle_tests, lawson_flips; triangles_created and triangles_destroyed count finite
// triangles only, so their difference is the final triangle count.
//
// Bounds (any kernel, however wrong its signs). Each flip gives x one more neighbour,
// so an insertion flips at most as many edges as there are earlier points, else
// flips_exceeded. A flip whose apex is x itself, a dead triangle met where a live one
// must be, and a hull that does not close are reported, never followed. Slots are 32-bit:
// a history outgrowing them is too_many_points.
//
// Output: the live finite triangles, renumbered, as the shared Mesh (twins into ghosts
// become -1), and the hull from the live ghosts.
#pragma once

#include <algorithm>
#include <cstddef>
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

/// The seed of the randomized algorithm's insertion order (brio.hpp's random_order):
/// fixed, so that its output is deterministic.
inline constexpr std::uint64_t randomized_seed = 0x0e1de1u;

template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
class RandomizedBuilder : Counting<I> {
public:
    /// The points of `in` in random order (see above).
    RandomizedBuilder(const K& kernel, const SortedInput& in) : k_(kernel) {
        const std::size_t n = in.points.size();
        order_ = random_order(n, randomized_seed);
        pts_.resize(n);
        input_of_.resize(n);
        for (std::size_t j = 0; j < n; ++j) {
            pts_[j] = in.points[order_[j]];
            input_of_[j] = in.input_of[order_[j]];
        }
        inf_ = static_cast<std::uint32_t>(n);
    }

    /// Triangulates into `out` (mesh, input_of, first). On failure `out` is meaningless.
    std::optional<Failure> run(MeshOutput& out) {
        const std::size_t n = pts_.size();
        out.mesh = Mesh{};
        if (n < 3 || !choose_first_triangle()) {
            out.mesh.collinear = true;
            return std::nullopt;
        }
        // About 9n triangles are created on random input (de Berg's bound on the
        // expectation; the realisation fluctuates around it), and the history keeps them
        // all. Reserving is free until the memory is touched, so leave a margin.
        const std::size_t expected = 10 * n + 64;
        node_.reserve(expected);
        adj_.reserve(3 * expected);
        start();
        for (std::size_t i = 3; i < n; ++i) {
            if (auto failure = insert(static_cast<std::uint32_t>(i))) return failure;
        }
        return output(out);
    }

    const Counters& counters() const noexcept { return this->counters_; }

private:
    static constexpr std::uint32_t fan_bit = 0x80000000u;  // in Node::count: a fan's children
    static constexpr std::uint32_t none = 0xffffffffu;
    // Half-edge indices 3t + j must fit in 32 bits.
    static constexpr std::size_t max_slots = 0xffffffffu / 3;

    // The three orientations of a point against a finite triangle's edges j -> j+1.
    struct Signs {
        Sign s[3];
    };

    // A slot: its triangle's vertices and its children, the slots first .. first +
    // count - 1 (every operation creates its triangles in consecutive slots, and the
    // children of a destroyed triangle are always some of them); count 0: alive. One
    // record, so that a descent step finds a child's vertices and its children in the
    // same cache line.
    struct Node {
        std::uint32_t v[3];
        std::uint32_t first = 0;
        std::uint32_t count = 0;  // with fan_bit for the ghosts destroyed by an outside point
    };

    std::size_t slots() const noexcept { return node_.size(); }
    bool alive(std::uint32_t t) const noexcept { return node_[t].count == 0; }
    bool ghost(std::uint32_t t) const noexcept { return node_[t].v[2] == inf_; }
    Point2 pt(std::uint32_t v) const noexcept { return pts_[v]; }
    std::uint32_t vert(std::size_t h) const noexcept { return node_[h / 3].v[h % 3]; }

    Sign orient(std::uint32_t a, std::uint32_t b, const Point2& x) const {
        return k_.orient2d(pts_[a], pts_[b], x);
    }

    std::optional<Failure> fail(FailureKind kind, std::uint32_t i, std::string what) const {
        return Failure{kind, input_of_[i], i,
                       "insertion of point " + std::to_string(i) +
                           " of the random order (input index " + std::to_string(input_of_[i]) +
                           "): " + std::move(what)};
    }

    /// Swaps the first point off the line of points 0 and 1 into position 2, and makes
    /// (0, 1, 2) counter-clockwise. False when there is none: all points are collinear.
    bool choose_first_triangle() {
        const std::size_t n = pts_.size();
        for (std::size_t j = 2; j < n; ++j) {
            this->count(&Counters::seed_orientations);
            const Sign s = k_.orient2d(pts_[0], pts_[1], pts_[j]);
            if (s == Sign::zero) continue;
            swap_positions(2, j);
            if (s == Sign::negative) swap_positions(1, 2);
            return true;
        }
        return false;
    }
    void swap_positions(std::size_t a, std::size_t b) {
        std::swap(pts_[a], pts_[b]);
        std::swap(input_of_[a], input_of_[b]);
        std::swap(order_[a], order_[b]);
    }

    std::uint32_t new_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (c != inf_) this->count(&Counters::triangles_created);
        const auto t = static_cast<std::uint32_t>(slots());
        node_.push_back(Node{{a, b, c}, 0, 0});
        adj_.resize(adj_.size() + 3, none);
        return t;
    }
    void link(std::uint32_t a, std::uint32_t b) {
        adj_[a] = b;
        adj_[b] = a;
    }
    /// Destroys t; its children are the `count` slots from `first`.
    void kill(std::uint32_t t, std::uint32_t first, std::uint32_t count, bool fan = false) {
        if (!ghost(t)) this->count(&Counters::triangles_destroyed);
        node_[t].first = first;
        node_[t].count = count | (fan ? fan_bit : 0u);
    }
    bool room(std::size_t more) const noexcept { return slots() + more <= max_slots; }

    // The first triangle (0, 1, 2) and its three ghosts, the roots (slots 0 .. 3).
    void start() {
        const std::uint32_t a = 0, b = 1, c = 2;
        new_triangle(a, b, c);     // 0: a->b, b->c, c->a
        new_triangle(b, a, inf_);  // 1: hull edge a->b
        new_triangle(c, b, inf_);  // 2: hull edge b->c
        new_triangle(a, c, inf_);  // 3: hull edge c->a
        link(0, 3);
        link(1, 6);
        link(2, 9);
        link(4, 11);  // a->inf with inf->a
        link(7, 5);   // b->inf with inf->b
        link(10, 8);  // c->inf with inf->c
        hull_size_ = 3;
    }

    // The points a descent has at hand: the current node's three vertices (entries 0-2; the
    // vertex at infinity has none) and the last other one read (entry 3). A child shares all
    // but at most one vertex with its parent (a split or a flip adds one, a fan adds its
    // apex and chain, read by the binary search), so a step reads about one point from
    // the big array instead of three per child tested: the descent is memory-bound.
    struct Descent {
        std::uint32_t id[4] = {none, none, none, none};
        Point2 p[4] = {};
    };
    Point2 point(Descent& d, std::uint32_t v) const {
        for (std::size_t j = 0; j < 4; ++j) {
            if (d.id[j] == v) return d.p[j];
        }
        d.id[3] = v;
        d.p[3] = pts_[v];
        return d.p[3];
    }

    /// Whether triangle t's region contains x; for a finite t, `signs` gets the three
    /// orientations (when none is negative). `tp` gets t's points (two for a ghost).
    bool contains(Descent& d, std::uint32_t t, const Point2& x, Signs& signs, Point2 (&tp)[3]) {
        const std::size_t b = 3 * std::size_t{t};
        tp[0] = point(d, vert(b));
        tp[1] = point(d, vert(b + 1));
        if (ghost(t)) {
            this->count(&Counters::location_orientations);
            return k_.orient2d(tp[0], tp[1], x) == Sign::positive;
        }
        tp[2] = point(d, vert(b + 2));
        for (std::size_t j = 0; j < 3; ++j) {
            this->count(&Counters::location_orientations);
            signs.s[j] = k_.orient2d(tp[j], tp[(j + 1) % 3], x);
            if (signs.s[j] == Sign::negative) return false;
        }
        return true;
    }

    /// The child of a dead outside ghost whose region contains x: the fan's two ghosts,
    /// else the fan triangle whose wedge at the apex holds x (binary search).
    std::uint32_t fan_child(Descent& d, std::uint32_t first, std::uint32_t count, const Point2& x,
                            Signs& signs, Point2 (&tp)[3]) {
        const std::uint32_t k = count - 2;  // fan triangles (u_(j+1), u_j, apex), j < k
        if (contains(d, first + k, x, signs, tp)) return first + k;
        if (contains(d, first + k + 1, x, signs, tp)) return first + k + 1;
        const Point2 apex = point(d, vert(3 * std::size_t{first} + 2));
        std::uint32_t lo = 0, hi = k;  // orient(apex, u_lo, x) <= 0 <= orient(apex, u_hi, x)
        while (hi - lo > 1) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            this->count(&Counters::location_orientations);
            const Point2 u = point(d, vert(3 * std::size_t{first + mid} + 1));
            if (k_.orient2d(apex, u, x) == Sign::positive) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return contains(d, first + lo, x, signs, tp) ? first + lo : none;
    }

    struct Leaf {
        std::uint32_t t;
        Signs signs;
    };

    static void prefetch([[maybe_unused]] const void* p) noexcept {
#if defined(__GNUC__)
        __builtin_prefetch(p);
#endif
    }

    /// Descends the DAG from the roots to the live triangle whose region contains x.
    std::optional<Failure> locate(std::uint32_t i, Leaf& leaf) {
        const Point2 x = pt(i);
        Descent d;
        Point2 tp[3];
        std::uint32_t first = 0, children = 4;  // the roots
        std::uint32_t node = none;
        for (std::size_t steps = 0;; ++steps) {
            std::uint32_t found = none;
            if ((children & fan_bit) == 0) {
                // The next step reads the children of the child chosen now: ask for all
                // of them while the orientations decide.
                for (std::uint32_t c = first; c < first + children; ++c) {
                    if (node_[c].count != 0) prefetch(&node_[node_[c].first]);
                }
            }
            if ((children & fan_bit) != 0) {
                found = fan_child(d, first, children & ~fan_bit, x, leaf.signs, tp);
            } else {
                for (std::uint32_t c = first; c < first + children; ++c) {
                    if (contains(d, c, x, leaf.signs, tp)) {
                        found = c;
                        break;
                    }
                }
            }
            if (found == none) {
                return fail(FailureKind::location_exceeded, i,
                            node == none
                                ? std::string("no root of the history DAG contains the point")
                                : "no child of history node " + std::to_string(node) +
                                      " contains the point");
            }
            this->count(&Counters::location_steps);
            node = found;
            const Node& at = node_[node];
            if (at.count == 0) {
                leaf.t = node;
                return std::nullopt;
            }
            if (steps > slots()) {
                return fail(FailureKind::location_exceeded, i, "the descent did not end");
            }
            for (std::size_t j = 0; j < 3; ++j) {
                d.id[j] = at.v[j];
                d.p[j] = tp[j];
            }
            if (at.v[2] == inf_) d.id[2] = none;
            first = at.first;
            children = at.count;
        }
    }

    std::optional<Failure> insert(std::uint32_t i) {
        Leaf leaf{};
        if (auto failure = locate(i, leaf)) return failure;
        stack_.clear();
        std::optional<Failure> failure;
        if (ghost(leaf.t)) {
            failure = insert_outside(i, leaf.t);
        } else {
            int zeros = 0;
            std::size_t on = 0;
            for (std::size_t j = 0; j < 3; ++j) {
                if (leaf.signs.s[j] == Sign::zero) {
                    ++zeros;
                    on = j;
                }
            }
            if (zeros == 0) {
                failure = split(i, leaf.t);
            } else if (zeros == 1) {
                failure = split_edge(i, 3 * leaf.t + static_cast<std::uint32_t>(on));
            } else {
                return fail(FailureKind::location_exceeded, i,
                            "the point lies on two edges of triangle " + std::to_string(leaf.t) +
                                ", at a vertex");
            }
        }
        if (failure) return failure;
        return legalize(i);
    }

    // x strictly inside finite triangle t = (v0, v1, v2): (v_j, v_j+1, x) for j = 0, 1, 2.
    std::optional<Failure> split(std::uint32_t x, std::uint32_t t) {
        if (!room(3)) return too_big(x);
        const std::uint32_t b = 3 * t;
        const auto first = static_cast<std::uint32_t>(slots());
        for (std::uint32_t j = 0; j < 3; ++j) new_triangle(vert(b + j), vert(b + (j + 1) % 3), x);
        for (std::uint32_t j = 0; j < 3; ++j) {
            const std::uint32_t T = 3 * (first + j), U = 3 * (first + (j + 1) % 3);
            link(T, adj_[b + j]);
            link(T + 1, U + 2);  // v_j+1 -> x with x -> v_j+1
            stack_.push_back(T);
        }
        kill(t, first, 3);
        return std::nullopt;
    }

    // x strictly inside the edge p -> q of half-edge h (of finite triangle (p, q, r)).
    std::optional<Failure> split_edge(std::uint32_t x, std::uint32_t h) {
        if (!room(4)) return too_big(x);
        const std::uint32_t t = h / 3, hn = next3(h), hp = prev3(h);
        const std::uint32_t p = vert(h), q = vert(hn), r = vert(hp);
        const std::uint32_t h2 = adj_[h], t2 = h2 / 3;
        if (!alive(t2) || (ghost(t2) && h2 % 3 != 0)) {
            return fail(FailureKind::location_exceeded, x,
                        "the triangle across the edge is not a live neighbour");
        }
        const std::uint32_t A = new_triangle(q, r, x), B = new_triangle(r, p, x);
        link(3 * A, adj_[hn]);
        link(3 * B, adj_[hp]);
        link(3 * A + 1, 3 * B + 2);  // r -> x with x -> r
        stack_.push_back(3 * A);
        stack_.push_back(3 * B);
        if (ghost(t2)) {
            // Ghost (q, p, inf) of hull edge p -> q: ghosts (x, p, inf) and (q, x, inf).
            const std::uint32_t G = new_triangle(x, p, inf_), H = new_triangle(q, x, inf_);
            link(3 * B + 1, 3 * G);         // p -> x with x -> p
            link(3 * H, 3 * A + 2);         // q -> x with x -> q
            link(3 * G + 1, adj_[h2 + 1]);  // p -> inf
            link(3 * H + 2, adj_[h2 + 2]);  // inf -> q
            link(3 * G + 2, 3 * H + 1);     // inf -> x with x -> inf
            ++hull_size_;
        } else {
            // (q, p, s): (p, s, x) and (s, q, x).
            const std::uint32_t h2n = next3(h2), h2p = prev3(h2);
            const std::uint32_t s = vert(h2p);
            const std::uint32_t C = new_triangle(p, s, x), D = new_triangle(s, q, x);
            link(3 * C, adj_[h2n]);
            link(3 * D, adj_[h2p]);
            link(3 * B + 1, 3 * C + 2);  // p -> x with x -> p
            link(3 * C + 1, 3 * D + 2);  // s -> x with x -> s
            link(3 * D + 1, 3 * A + 2);  // q -> x with x -> q
            stack_.push_back(3 * C);
            stack_.push_back(3 * D);
        }
        kill(t, A, 2);
        kill(t2, A + 2, 2);
        return std::nullopt;
    }

    // x strictly outside the hull edge of ghost g0: the visible chain, its fan, two ghosts.
    std::optional<Failure> insert_outside(std::uint32_t x, std::uint32_t g0) {
        const Point2 px = pt(x);
        chain_.clear();
        std::size_t visible = 1;
        // A neighbouring ghost, checked: live and a ghost, or the hull does not close.
        auto step = [&](std::uint32_t h, std::uint32_t& g) {
            g = adj_[h] / 3;
            return alive(g) && ghost(g);
        };
        for (std::uint32_t g = g0;;) {  // clockwise: the ghost of the previous hull edge
            std::uint32_t prev_g;
            if (!step(3 * g + 1, prev_g)) return broken_hull(x);
            this->count(&Counters::tangent_orientations);
            if (orient(vert(3 * prev_g), vert(3 * prev_g + 1), px) != Sign::positive) break;
            chain_.push_back(prev_g);
            g = prev_g;
            if (++visible >= hull_size_) {
                return fail(FailureKind::hull_walk_exceeded, x,
                            "the lower tangent walk passed every hull edge");
            }
        }
        std::reverse(chain_.begin(), chain_.end());
        chain_.push_back(g0);
        for (std::uint32_t g = g0;;) {  // counter-clockwise: the next hull edge's ghost
            std::uint32_t next_g;
            if (!step(3 * g + 2, next_g)) return broken_hull(x);
            this->count(&Counters::tangent_orientations);
            if (orient(vert(3 * next_g), vert(3 * next_g + 1), px) != Sign::positive) break;
            chain_.push_back(next_g);
            g = next_g;
            if (++visible >= hull_size_) {
                return fail(FailureKind::hull_walk_exceeded, x,
                            "the upper tangent walk passed every hull edge");
            }
        }
        const auto k = static_cast<std::uint32_t>(chain_.size());
        if (!room(k + 2)) return too_big(x);
        // Ghost g_i = (u_(i+1), u_i, inf) becomes the fan triangle (u_(i+1), u_i, x).
        const auto first = static_cast<std::uint32_t>(slots());
        for (std::uint32_t i = 0; i < k; ++i) {
            const std::uint32_t g = chain_[i];
            const std::uint32_t F = new_triangle(vert(3 * g), vert(3 * g + 1), x);
            link(3 * F, adj_[3 * g]);                     // u_(i+1) -> u_i: the old hull edge
            if (i > 0) link(3 * F + 1, 3 * (F - 1) + 2);  // u_i -> x with x -> u_i
            stack_.push_back(3 * F);
        }
        const std::uint32_t g_first = chain_.front(), g_last = chain_.back();
        const std::uint32_t u0 = vert(3 * g_first + 1), uk = vert(3 * g_last);
        const std::uint32_t L = new_triangle(x, u0, inf_), U = new_triangle(uk, x, inf_);
        link(3 * L, 3 * first + 1);              // x -> u_0 with u_0 -> x
        link(3 * U, 3 * (first + k - 1) + 2);    // u_k -> x with x -> u_k
        link(3 * L + 1, adj_[3 * g_first + 1]);  // u_0 -> inf
        link(3 * U + 2, adj_[3 * g_last + 2]);   // inf -> u_k
        link(3 * L + 2, 3 * U + 1);              // inf -> x with x -> inf
        for (const std::uint32_t g : chain_) kill(g, first, k + 2, true);
        hull_size_ = hull_size_ + 2 - k;
        return std::nullopt;
    }

    /// The one place where the in-circle question is decided: x strictly inside the
    /// circle of (b, a, d), the counter-clockwise triangle behind edge b -> a, with x on
    /// the right of b -> a (the roles of Builder::in_circle).
    bool in_circle(Point2 b, Point2 a, Point2 d, Point2 x) {
        return this->template in_circle_by_policy<P>(k_, b, a, d, x);
    }

    // Lawson's flips of the edges opposite x (half-edge 0 of a triangle (a, b, x)).
    std::optional<Failure> legalize(std::uint32_t x) {
        std::size_t flips = 0;
        while (!stack_.empty()) {
            const std::uint32_t e = stack_.back();
            stack_.pop_back();
            const std::uint32_t t = e / 3;
            const std::uint32_t h = adj_[e], t2 = h / 3;
            if (!alive(t) || !alive(t2)) {
                return fail(FailureKind::flips_exceeded, x,
                            "an edge to legalize borders a destroyed triangle");
            }
            if (ghost(t2)) continue;  // a hull edge
            const std::uint32_t a = vert(e), b = vert(e + 1), d = vert(prev3(h));
            if (d == x) {
                return fail(FailureKind::flips_exceeded, x,
                            "the new point is on both sides of an edge");
            }
            if (!in_circle(pt(b), pt(a), pt(d), pt(x))) continue;
            if (++flips > x) {
                return fail(FailureKind::flips_exceeded, x,
                            "more flips than the point can have neighbours");
            }
            if (!room(2)) return too_big(x);
            this->count(&Counters::lawson_flips);
            // (a, b, x) and (b, a, d) become (a, d, x) and (d, b, x).
            const std::uint32_t o_ad = adj_[next3(h)], o_db = adj_[prev3(h)];
            const std::uint32_t o_bx = adj_[e + 1], o_xa = adj_[e + 2];
            const std::uint32_t N = new_triangle(a, d, x), M = new_triangle(d, b, x);
            link(3 * N, o_ad);
            link(3 * M, o_db);
            link(3 * N + 1, 3 * M + 2);  // d -> x with x -> d
            link(3 * N + 2, o_xa);
            link(3 * M + 1, o_bx);
            kill(t, N, 2);
            kill(t2, N, 2);
            stack_.push_back(3 * N);
            stack_.push_back(3 * M);
        }
        return std::nullopt;
    }

    std::optional<Failure> broken_hull(std::uint32_t x) const {
        return fail(FailureKind::hull_walk_exceeded, x, "the hull walk left the ghost triangles");
    }
    std::optional<Failure> too_big(std::uint32_t x) const {
        return fail(FailureKind::too_many_points, x,
                    "the history DAG outgrew 32-bit half-edge indices");
    }

    static std::uint32_t next3(std::uint32_t h) noexcept { return h % 3 == 2 ? h - 2 : h + 1; }
    static std::uint32_t prev3(std::uint32_t h) noexcept { return h % 3 == 0 ? h + 2 : h - 1; }

    // The live finite triangles as the shared mesh, the hull from the live ghosts.
    std::optional<Failure> output(MeshOutput& out) {
        const std::size_t n = pts_.size();
        Mesh& mesh = out.mesh;
        mesh.reset(n);
        auto inconsistent = [](std::string what) {
            return Failure{FailureKind::result_inconsistent, no_index, no_index, std::move(what)};
        };
        // Node::first of a live slot is unused: it becomes the slot's new number.
        std::uint32_t live = 0;
        for (std::uint32_t t = 0; t < slots(); ++t) {
            if (alive(t) && !ghost(t)) node_[t].first = live++;
        }
        mesh.triangles.resize(3 * std::size_t{live});
        mesh.halfedges.resize(3 * std::size_t{live});
        for (std::uint32_t t = 0; t < slots(); ++t) {
            if (!alive(t)) continue;
            if (ghost(t)) {
                // Hull edge u -> v, its finite half-edge across.
                const std::uint32_t v = vert(3 * t), u = vert(3 * t + 1);
                const std::uint32_t h = adj_[3 * t], f = h / 3;
                if (!alive(f) || ghost(f) || mesh.hull_edge[u] >= 0) {
                    return inconsistent("the ghost triangles do not form the hull");
                }
                mesh.set_hull_next(u, v);
                mesh.hull_edge[u] = static_cast<std::int32_t>(3 * node_[f].first + h % 3);
                ++mesh.hull_size;
                continue;
            }
            const std::size_t u = node_[t].first;
            for (std::uint32_t j = 0; j < 3; ++j) {
                const std::uint32_t h = adj_[3 * t + j], f = h / 3;
                mesh.triangles[3 * u + j] = vert(3 * t + j);
                if (!alive(f)) return inconsistent("a live triangle borders a destroyed one");
                mesh.halfedges[3 * u + j] =
                    ghost(f) ? -1 : static_cast<std::int32_t>(3 * node_[f].first + h % 3);
            }
        }
        for (std::size_t j = 0; j < n; ++j) {
            if (order_[j] == 0) out.first = static_cast<std::uint32_t>(j);
        }
        out.input_of = std::move(input_of_);
        return std::nullopt;
    }

    const K& k_;
    std::vector<Point2> pts_;              // in insertion order
    std::vector<std::uint32_t> input_of_;  // insertion position -> input index
    std::vector<std::uint32_t> order_;     // insertion position -> sorted position
    std::uint32_t inf_ = 0;
    std::vector<std::uint32_t> adj_;    // 3 per slot
    std::vector<Node> node_;            // 1 per slot
    std::vector<std::uint32_t> stack_;  // half-edges opposite the new point, to legalize
    std::vector<std::uint32_t> chain_;  // the visible ghosts, in hull order
    std::size_t hull_size_ = 0;
};

struct RandomizedIncremental {
    template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
    static void run(const K& kernel, const SortedInput& in, const Options&, MeshOutput& out,
                    Result& result) {
        if (in.points.size() < 3) {
            out.mesh.collinear = true;
            return;
        }
        RandomizedBuilder<K, I, P> builder(kernel, in);
        result.failure = builder.run(out);
        result.counters = builder.counters();
    }
};

}  // namespace exidel::delaunay::detail
