// exidel: the Guibas-Stolfi merge ("zipper") of two Delaunay triangulations L and R whose
// vertex sets are separated lexicographically (every point of L precedes every point of
// R in (x, y) order, so a slightly tilted line separates them), on the index arrays of
// Mesh. Guibas and Stolfi (1985), "Primitives for the manipulation of general
// subdivisions and the computation of Voronoi diagrams", Section 8.
//
// The zipper asks only orientation and in-circle questions, which a rotation of the plane
// does not change, so the pieces may as well be separated in a rotated frame: the
// divide and conquer's horizontal cuts (divide_and_conquer.hpp) separate them by (y, -x),
// the lexicographic order after turning the plane clockwise by 90 degrees. The walks
// start from the extreme points in that order, l0 the largest of L and r0 the smallest
// of R, which the caller names; by default the last point of L and the first of R.
//
//   1. the lower common tangent l0 -> r0: every point on or to its left. Of points on
//      the tangent line, the two innermost (l0 nearest R, r0 nearest L) are taken, so
//      collinear points keep their edges along the line;
//   2. from the base edge l -> r, the left candidates are l's neighbours counter-
//      clockwise from the direction of r, the right candidates r's neighbours clockwise
//      from the direction of l. A candidate is valid when strictly left of l -> r. While
//      the next candidate lies strictly inside the circle through l, r and the candidate,
//      the candidate's edge is deleted. Of the two valid candidates, the right one wins
//      if it lies strictly inside the circle through l, r and the left one (cocircular:
//      the left one, a fixed rule, so the output is deterministic); the winner and the
//      base make a new triangle, and the base rises to the edge from the winner;
//   3. with no valid candidate the base is the upper common tangent.
//
// On the arrays: a deleted edge is kept in a set of half-edges, and a triangle with a deleted edge
// is destroyed after the zipper (its final faces are the new triangles). The zipper only reads the
// arrays, so it walks the fans of L and R as they were, skipping marked edges; that is exactly
// Guibas and Stolfi's structure, where the deleted edges are gone and the new cross edges lie in
// the sectors the walk has passed. The new triangles take free slots of either side: a merged
// triangulation of V vertices has at most 2V - 5 triangles, and each side owns 2 slots per vertex.
//
// Both sides must have triangles (not all collinear). With an inexact kernel the zipper
// may contradict itself: every loop is bounded, and the merge stops with
// FailureKind::merge_inconsistent rather than write a broken mesh.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "exidel/delaunay/detail/counting.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

/// The half-edges deleted by the merge in progress: an open-addressing hash set. A merge
/// deletes edges along its seam only, a few per seam vertex, so the set stays small and
/// in cache (a byte per half-edge of the whole mesh, as before issue 17, cost 6 bytes per
/// point of fresh memory and a cache miss per test). Its common question, with nothing
/// deleted yet, is one comparison.
class HalfEdgeSet {
public:
    bool contains(std::uint32_t e) const noexcept {
        if (size_ == 0) return false;
        for (std::size_t i = slot(e);; i = (i + 1) & (table_.size() - 1)) {
            if (table_[i] == e) return true;
            if (table_[i] == empty) return false;
        }
    }
    void insert(std::uint32_t e) {
        if (2 * (size_ + 1) > table_.size()) grow();
        std::size_t i = slot(e);
        for (; table_[i] != empty; i = (i + 1) & (table_.size() - 1)) {
            if (table_[i] == e) return;
        }
        table_[i] = e;
        ++size_;
    }
    void clear() {
        if (size_ > 0) std::fill(table_.begin(), table_.end(), empty);
        size_ = 0;
    }

private:
    static constexpr std::uint32_t empty = 0xffffffffu;  // never a half-edge (< 2^31)
    std::size_t slot(std::uint32_t e) const noexcept {
        return static_cast<std::size_t>((e * 0x9e3779b97f4a7c15ull) >> 32) & (table_.size() - 1);
    }
    void grow() {
        std::vector<std::uint32_t> old(std::max<std::size_t>(64, 2 * table_.size()), empty);
        old.swap(table_);
        size_ = 0;
        for (const std::uint32_t e : old) {
            if (e != empty) insert(e);
        }
    }
    std::vector<std::uint32_t> table_;
    std::size_t size_ = 0;
};

/// The order a cut separates pieces by: vertical cuts (x, y), horizontal cuts (y, -x)
/// (the zipper's l0 is the largest point of L in it, r0 the smallest of R).
inline bool cut_less(Point2 a, Point2 b, bool horizontal) {
    if (horizontal) return a.y < b.y || (a.y == b.y && a.x > b.x);
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/// A triangulated piece of the sorted points: positions [first, end), triangle slots
/// [2 first, 2 end) of the shared Mesh, `free` the slots of that range not in use.
struct Piece {
    std::uint32_t first = 0, end = 0;
    std::vector<std::uint32_t> free;
};

template <PredicateKernel K, Instrumentation I>
class Merger : Counting<I> {
public:
    /// `points`: all sorted points; `mesh`: the shared arrays, over sorted positions.
    /// Merges of disjoint pieces touch disjoint parts of the arrays, so mergers of their
    /// own may run them in parallel.
    Merger(const K& kernel, std::span<const Point2> points, Mesh& mesh)
        : k_(kernel), pts_(points), m_(mesh) {}

    /// Merges R into L (L.end == R.first). `l0` and `r0`: L's largest and R's smallest
    /// point in the order that separates them (above). On failure the two pieces are
    /// meaningless.
    std::optional<Failure> merge(Piece& L, Piece& R) { return merge(L, R, L.end - 1, R.first); }
    std::optional<Failure> merge(Piece& L, Piece& R, std::uint32_t l0, std::uint32_t r0) {
        L_ = &L;
        R_ = &R;
        start_l_ = l0;
        start_r_ = r0;
        steps_.clear();
        deleted_.clear();
        gone_.clear();
        // A guard against an inexact kernel sending the walks round in circles, not a
        // cost model: every step of the walks spends one unit. Exact runs on the test
        // families spent at most about 9 units per point of the two pieces (the fans are
        // walked about twice, and each zipper step peeks once per side); 64 per point
        // leaves a wide margin and still stops a runaway walk after linear work.
        budget_ = 64 * (static_cast<std::size_t>(R.end) - L.first) + 1024;
        L.free.insert(L.free.end(), R.free.begin(), R.free.end());
        R.free.clear();
        auto failure = zip();
        if (!failure) failure = rebuild();
        L.end = R.end;
        return failure;
    }

    const Counters& counters() const noexcept { return this->counters_; }

private:
    // A neighbour c of vertex v in v's fan, with the half-edge v -> c of the triangle
    // counter-clockwise after c (`out`) and c -> v of the triangle clockwise before it
    // (`in`), -1 where that side of the edge is outside the triangulation.
    struct Fan {
        std::uint32_t v, c;
        std::int32_t in, out;
    };
    // One zipper step: the new triangle (l, r, apex), apex taken on the left or the right,
    // and the surviving half-edge across its side on the chain (-1: the hull).
    struct Step {
        std::uint32_t l, r, apex;
        bool right;
        std::int32_t twin;  // -2 once that triangle turns out destroyed
    };
    // A new triangle's chain side from -> to, half-edge `half`, with its step's twin.
    struct Chain {
        std::uint32_t lo, hi, from;
        std::int32_t half, twin;
    };

    std::optional<Failure> fail(std::string what) const {
        return Failure{FailureKind::merge_inconsistent, no_index, no_index,
                       "merge of sorted points [" + std::to_string(L_->first) + ", " +
                           std::to_string(L_->end) + ") and [" + std::to_string(R_->first) + ", " +
                           std::to_string(R_->end) + "), at the step '" + std::move(what) +
                           "', found no consistent merge"};
    }
    bool spend() { return budget_-- > 0; }

    Sign orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        this->count(&Counters::merge_orientations);
        return k_.orient2d(pts_[a], pts_[b], pts_[c]);
    }
    // d strictly inside the circle through a, b, c (counter-clockwise).
    bool inside(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        this->count(&Counters::merge_incircle_tests);
        return k_.incircle(pts_[a], pts_[b], pts_[c], pts_[d]) == Sign::positive;
    }

    bool is_gone(const Fan& f) const {
        return (f.out >= 0 && gone_.contains(static_cast<std::uint32_t>(f.out))) ||
               (f.in >= 0 && gone_.contains(static_cast<std::uint32_t>(f.in)));
    }
    void remove(const Fan& f) {
        this->count(&Counters::merge_deleted_edges);
        for (const std::int32_t e : {f.in, f.out}) {
            if (e >= 0) {
                gone_.insert(static_cast<std::uint32_t>(e));
                deleted_.push_back(static_cast<std::uint32_t>(e));
            }
        }
    }

    // Every index read from the arrays is checked before use: with an inexact kernel the
    // pieces may be inconsistent, and the merge must fail, not read out of bounds.
    bool vertex_ok(std::uint32_t v) const { return v >= L_->first && v < R_->end; }
    bool half_ok(std::int32_t e) const {
        return e >= 0 && static_cast<std::size_t>(e) >= 6 * std::size_t{L_->first} &&
               static_cast<std::size_t>(e) < 6 * std::size_t{R_->end} &&
               m_.triangles[static_cast<std::size_t>(e)] != dead;
    }
    std::optional<Fan> checked(Fan f) const {
        if (!vertex_ok(f.c) || (f.in >= 0 && !half_ok(f.in)) || (f.out >= 0 && !half_ok(f.out)) ||
            (f.in < 0 && f.out < 0)) {
            return std::nullopt;
        }
        return f;
    }

    // One step counter-clockwise (clockwise) around f.v, across the outside of the
    // triangulation when f.c is the last (first) neighbour of a hull vertex.
    std::optional<Fan> ccw(const Fan& f) const {
        if (f.out < 0) return checked({f.v, m_.hull_next[f.v], -1, m_.hull_edge[f.v]});
        const std::size_t p = prev_halfedge(static_cast<std::size_t>(f.out));
        return checked({f.v, m_.triangles[p], static_cast<std::int32_t>(p), m_.halfedges[p]});
    }
    std::optional<Fan> cw(const Fan& f) const {
        if (f.in < 0) {
            const std::uint32_t last = m_.hull_prev[f.v];
            if (!vertex_ok(last)) return std::nullopt;
            return checked({f.v, last, m_.hull_edge[last], -1});
        }
        const std::size_t n = next_halfedge(static_cast<std::size_t>(f.in));
        return checked({f.v, m_.triangles[prev_halfedge(static_cast<std::size_t>(f.in))],
                        m_.halfedges[n], static_cast<std::int32_t>(n)});
    }
    // The next neighbour (counter-clockwise, or clockwise) whose edge is not deleted.
    std::optional<Fan> live(Fan f, bool clockwise) {
        do {
            if (!spend()) return std::nullopt;
            const auto g = clockwise ? cw(f) : ccw(f);
            if (!g) return std::nullopt;
            f = *g;
        } while (is_gone(f));
        return f;
    }
    std::optional<Fan> live_ccw(const Fan& f) { return live(f, false); }
    std::optional<Fan> live_cw(const Fan& f) { return live(f, true); }

    std::optional<Failure> zip() {
        const auto& next = m_.hull_next;
        const auto& prev = m_.hull_prev;
        // 1. Lower common tangent, from the two extreme points (hull vertices of their
        // sides): move l clockwise and r counter-clockwise along the lower hulls while
        // the neighbour is strictly below the line, then inwards along the line.
        std::uint32_t l = start_l_, r = start_r_;
        auto hull_ok = [&](std::uint32_t v) {
            return vertex_ok(v) && vertex_ok(next[v]) && vertex_ok(prev[v]);
        };
        if (!hull_ok(l) || !hull_ok(r)) return fail("extreme point not on its hull");
        for (bool moved = true; moved;) {
            if (!spend()) return fail("lower tangent search");
            moved = false;
            if (orient(l, r, prev[l]) == Sign::negative) l = prev[l], moved = true;
            if (orient(l, r, next[r]) == Sign::negative) r = next[r], moved = true;
            if (!hull_ok(l) || !hull_ok(r)) return fail("broken hull");
        }
        while (orient(l, r, next[l]) == Sign::zero) {
            if (!spend()) return fail("lower tangent, collinear points");
            l = next[l];
            if (!hull_ok(l)) return fail("broken hull");
        }
        while (orient(l, r, prev[r]) == Sign::zero) {
            if (!spend()) return fail("lower tangent, collinear points");
            r = prev[r];
            if (!hull_ok(r)) return fail("broken hull");
        }
        lower_l_ = l;
        lower_r_ = r;
        // The first candidates: just past the outside of each hull vertex.
        const auto lc0 = checked({l, next[l], -1, m_.hull_edge[l]});
        const auto rc0 = checked({r, prev[r], m_.hull_edge[prev[r]], -1});
        if (!lc0 || !rc0) return fail("hull edge missing");
        Fan lc = *lc0, rc = *rc0;
        this->count(&Counters::merge_cross_edges);
        for (;;) {
            if (!spend()) return fail("zipper");
            if (orient(l, r, lc.c) == Sign::positive) {
                for (;;) {
                    const auto nx = live_ccw(lc);
                    if (!nx) return fail("left fan");
                    if (!inside(l, r, lc.c, nx->c)) break;
                    remove(lc);
                    lc = *nx;
                }
            }
            if (orient(l, r, rc.c) == Sign::positive) {
                for (;;) {
                    const auto nx = live_cw(rc);
                    if (!nx) return fail("right fan");
                    if (!inside(l, r, rc.c, nx->c)) break;
                    remove(rc);
                    rc = *nx;
                }
            }
            const bool left_ok = orient(l, r, lc.c) == Sign::positive;
            const bool right_ok = orient(l, r, rc.c) == Sign::positive;
            if (!left_ok && !right_ok) break;
            this->count(&Counters::merge_cross_edges);
            if (!left_ok || (right_ok && inside(lc.c, l, r, rc.c))) {
                steps_.push_back({l, r, rc.c, true, rc.in});
                const std::uint32_t y = rc.c;
                const auto nx = live_cw(Fan{y, r, rc.out, rc.in});
                if (!nx) return fail("right fan");
                rc = *nx;
                r = y;
            } else {
                steps_.push_back({l, r, lc.c, false, lc.out});
                const std::uint32_t x = lc.c;
                const auto nx = live_ccw(Fan{x, l, lc.out, lc.in});
                if (!nx) return fail("left fan");
                lc = *nx;
                l = x;
            }
        }
        if (steps_.empty()) return fail("no cross triangle");
        upper_l_ = l;
        upper_r_ = r;
        return std::nullopt;
    }

    std::optional<Failure> rebuild() {
        auto& tris = m_.triangles;
        auto& half = m_.halfedges;
        // Destroy every triangle with a deleted edge.
        std::vector<std::uint32_t>& free = L_->free;
        for (const std::uint32_t e : deleted_) {
            const std::size_t t = e / 3;
            if (tris[3 * t] == dead) continue;
            tris[3 * t] = tris[3 * t + 1] = tris[3 * t + 2] = dead;
            free.push_back(static_cast<std::uint32_t>(t));
            this->count(&Counters::triangles_destroyed);
        }
        for (Step& s : steps_) {
            if (s.twin >= 0 && tris[static_cast<std::size_t>(s.twin)] == dead) s.twin = -2;
        }
        if (free.size() < steps_.size()) return fail("more new triangles than free slots");
        // New triangles (l, r, apex): half-edge 0 is the base l -> r, 1 is r -> apex,
        // 2 is apex -> l. The chain side is 2 (left apex) or 1 (right apex); the other
        // of the two is the next base, reversed.
        chains_.clear();
        std::int32_t below = -1;  // the previous triangle's half-edge across the base
        for (const Step& s : steps_) {
            const std::uint32_t t = free.back();
            free.pop_back();
            if (below < 0) first_base_ = static_cast<std::int32_t>(3 * t);
            this->count(&Counters::triangles_created);
            const auto T = static_cast<std::int32_t>(3 * t);
            tris[3 * t] = s.l;
            tris[3 * t + 1] = s.r;
            tris[3 * t + 2] = s.apex;
            half[3 * t] = below;
            if (below >= 0) half[static_cast<std::size_t>(below)] = T;
            const std::int32_t chain = s.right ? T + 1 : T + 2;
            const std::uint32_t from = s.right ? s.r : s.apex, to = s.right ? s.apex : s.l;
            chains_.push_back({std::min(from, to), std::max(from, to), from, chain, s.twin});
            below = s.right ? T + 2 : T + 1;
            half[static_cast<std::size_t>(below)] = -1;
        }
        // Chain sides. The chain of a side usually has the surviving triangle of that side
        // across each edge (the half-edge the fan walk recorded). But the zipper may pass
        // the same edge twice, once up and once back down (the base can swing round a
        // vertex of one side): then that side's triangle across it was destroyed and the
        // twin is the other new triangle on the edge. Pair those first.
        std::sort(chains_.begin(), chains_.end(), [](const Chain& a, const Chain& b) {
            return a.lo != b.lo ? a.lo < b.lo : a.hi < b.hi;
        });
        for (std::size_t j = 0; j < chains_.size();) {
            const Chain& c = chains_[j];
            if (j + 1 < chains_.size() && chains_[j + 1].lo == c.lo && chains_[j + 1].hi == c.hi) {
                if (j + 2 < chains_.size() && chains_[j + 2].lo == c.lo &&
                    chains_[j + 2].hi == c.hi) {
                    return fail("three new triangles on one edge");
                }
                half[static_cast<std::size_t>(c.half)] = chains_[j + 1].half;
                half[static_cast<std::size_t>(chains_[j + 1].half)] = c.half;
                j += 2;
                continue;
            }
            if (c.twin == -2) return fail("a chain edge borders a destroyed triangle");
            half[static_cast<std::size_t>(c.half)] = c.twin;
            if (c.twin >= 0) {
                half[static_cast<std::size_t>(c.twin)] = c.half;
            } else {
                m_.hull_edge[c.from] = c.half;  // on the hull: its start vertex owns it
            }
            ++j;
        }
        // The hull: ... -> l0 -> r0 -> ... (lower tangent, the first base, half-edge 0 of
        // the first new triangle) and ... -> r_m -> l_m -> ... (upper tangent, the last
        // base, reversed). The vertices of either side between them left the hull.
        m_.hull_next[lower_l_] = lower_r_;
        m_.hull_prev[lower_r_] = lower_l_;
        m_.hull_edge[lower_l_] = first_base_;
        m_.hull_next[upper_r_] = upper_l_;
        m_.hull_prev[upper_l_] = upper_r_;
        m_.hull_edge[upper_r_] = below;
        return std::nullopt;
    }

    const K& k_;
    std::span<const Point2> pts_;
    Mesh& m_;
    HalfEdgeSet gone_;  // the deleted edges' half-edges
    Piece* L_ = nullptr;
    Piece* R_ = nullptr;
    std::vector<Step> steps_;
    std::vector<Chain> chains_;
    std::vector<std::uint32_t> deleted_;  // half-edges of deleted edges
    std::size_t budget_ = 0;
    std::uint32_t start_l_ = 0, start_r_ = 0;
    std::uint32_t lower_l_ = 0, lower_r_ = 0, upper_l_ = 0, upper_r_ = 0;
    std::int32_t first_base_ = -1;
};

}  // namespace exidel::delaunay::detail
