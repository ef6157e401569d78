// exidel: the external incremental Delaunay triangulation (Yifeng Cai 2025) of a sequence
// of points given in an external order, one in which every new point lies strictly
// outside the hull of the earlier ones, so that no point location is needed (Alg. 1):
//
//   1. seed      the first point off the line of the earlier ones, fanned to them;
//   2. tangents  from a hull vertex that sees the new point p, walk the hull clockwise to
//                the lower and counter-clockwise to the upper tangent point (Alg. 2 / 5).
//                An edge is visible only when p is strictly on its outer side: a point
//                collinear with a hull edge connects to the nearer endpoint, collinear
//                points stay hull vertices (the paper's hull appendix keeps the farther
//                one, which is right for hulls and wrong for triangulations);
//   3. erosion   pop border edges from a stack; an edge whose triangle's circumcircle
//                strictly contains p is deleted and the two edges behind it pushed
//                (Alg. 3). Points on the circle keep their edge;
//   4. connect   fan p to the surviving border.
//
// Two external orders, each a Starts type (hull_start.hpp) that says where the walks start:
//   lexicographic  the paper's (x, y) order. The last inserted point is the largest so
//                  far, hence a hull vertex, and p, larger still, sees one of its two hull
//                  edges: the walks start there (LastPointStart).
//   radial         ascending distance from a centre c, ties lexicographic. The earlier
//                  points lie in the closed disc of radius |p - c| around c, and p is on
//                  its boundary circle; a strictly convex disc has no boundary point in the
//                  convex hull of other points of the disc, so p (distinct from them) is
//                  strictly outside their hull and sees at least one hull edge. Which one
//                  is not known in advance: an angular hash of hull vertices around c (as
//                  in delaunator) proposes a start, and a bounded walk along the hull tests
//                  edges with orient2d until one is strictly visible (RadialHullHash).
//                  The first points may be collinear; the caller sorts that collinear
//                  prefix lexicographically, which keeps the order external (they are the
//                  nearest points) and lets the seed fan them in order along their line.
//
// Step 3 is one of three Repair modes, so that the same sweep serves three algorithms:
//   erode     the paper's erosion (the external algorithm);
//   legalize  no erosion: p is fanned to the whole visible chain, then the fan's outer
//             edges are legalized by Lawson flips (flips.hpp), as Sinclair's sweep-hull
//             and delaunator do;
//   none      no erosion and no flips: the fan of the visible chain only, which in
//             lexicographic order is the sorted fan that the `lawson` algorithm starts
//             from (a valid triangulation, not Delaunay).
//
// The in-circle test of step 3 is decided in exactly one place: Builder::in_circle.
// Every walk is bounded; an answer of an inexact kernel that contradicts the geometry
// stops the run with a Failure naming the step.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/bowyer_watson.hpp"
#include "exidel/delaunay/detail/brio.hpp"
#include "exidel/delaunay/detail/counting.hpp"
#include "exidel/delaunay/detail/flips.hpp"
#include "exidel/delaunay/detail/hull_start.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/detail/radial.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

/// How the sweep restores the Delaunay property after fanning a point (see above).
enum class Repair : std::uint8_t { erode, legalize, none };

template <PredicateKernel K, Instrumentation I, InCirclePolicy P, class Starts,
          Repair R = Repair::erode>
class Builder : Counting<I> {
public:
    /// `points` in an external order (see above); `input_of` maps a position to the input
    /// index named in failure messages; `starts` finds where the tangent walks start in
    /// that order (hull_start.hpp).
    Builder(const K& kernel, std::span<const Point2> points,
            std::span<const std::uint32_t> input_of, Starts starts = {})
        : k_(kernel), pts_(points), input_of_(input_of), starts_(std::move(starts)) {}

    /// Builds into `mesh` (its vectors are replaced). On failure the mesh is meaningless.
    std::optional<Failure> run(Mesh& mesh) {
        const std::size_t n = pts_.size();
        std::size_t first_off = n;
        // The paper's "try to create a triangle": P[j] against the line P[0] P[j-1].
        for (std::size_t j = 2; j < n; ++j) {
            this->count(&Counters::seed_orientations);
            if (k_.orient2d(pts_[0], pts_[j - 1], pts_[j]) != Sign::zero) {
                first_off = j;
                break;
            }
        }
        mesh.clear();
        if (first_off == n) {
            mesh.collinear = true;
            return std::nullopt;
        }
        m_ = &mesh;
        mesh.reset(n);
        starts_.prepare(pts_);
        seed(first_off);
        for (std::size_t i = first_off + 1; i < n; ++i) {
            if (auto failure = insert(static_cast<std::uint32_t>(i))) return failure;
            // Past half the points, finishing costs less than starting again.
            if (erosion_limit_ != 0 && 2 * i <= n &&
                eroded_total_ > erosion_limit_ * i + erosion_slack) {
                gave_up_ = true;
                return std::nullopt;
            }
        }
        return std::nullopt;
    }

    /// Makes run() give up, with no failure and gave_up() true, as soon as the edges
    /// eroded so far exceed `per_point` times the points inserted plus erosion_slack,
    /// while at most half the points are inserted. 0: never (the default). The mesh is then
    /// unfinished, and the caller triangulates the points another way (build_radial).
    void limit_erosion(std::size_t per_point) noexcept { erosion_limit_ = per_point; }
    bool gave_up() const noexcept { return gave_up_; }

    /// Eroded edges a run may spend beyond the per-point limit: room for a costly start
    /// (the first points' fans are re-eroded as the hull grows) before the rate counts.
    static constexpr std::size_t erosion_slack = 4096;

    const Counters& counters() const noexcept { return this->counters_; }

private:
    // One entry of the erosion stack: the half-edge of the triangle behind a border edge
    // (or -1: nothing behind it) and the border edge's end vertex. Its start vertex is the
    // end of the border built so far, because the stack is processed in border order.
    struct Pending {
        std::int32_t behind;
        std::uint32_t end;
    };

    /// The one place where the in-circle question is decided. abc is the triangle behind
    /// border edge a->b (counter-clockwise: c on the left of a->b), p the new point on
    /// the right. True: p strictly inside the circle through a, b, c.
    bool in_circle(Point2 a, Point2 b, Point2 c, Point2 p) {
        return this->template in_circle_by_policy<P>(k_, a, b, c, p);
    }

    std::uint32_t new_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        this->count(&Counters::triangles_created);
        return m_->add_triangle(a, b, c);
    }
    void link(std::int32_t a, std::int32_t b) { m_->link(a, b); }
    void set_next(std::uint32_t a, std::uint32_t b) { m_->set_hull_next(a, b); }

    // Fan of the collinear prefix P[0..k-1] (in order along its line) to P[k] (k >= 2).
    void seed(std::size_t k) {
        const auto apex = static_cast<std::uint32_t>(k);
        const bool left = k_.orient2d(pts_[0], pts_[k - 1], pts_[k]) == Sign::positive;
        auto& hull_edge = m_->hull_edge;
        std::int32_t prev_t = -1;
        for (std::uint32_t i = 0; i + 1 < apex; ++i) {
            // left: (P_i, P_i+1, apex); right: (P_i+1, P_i, apex). Half-edge 3t is the
            // chain edge, on the hull.
            const std::uint32_t t =
                left ? new_triangle(i, i + 1, apex) : new_triangle(i + 1, i, apex);
            const auto T = static_cast<std::int32_t>(3 * t);
            hull_edge[left ? i : i + 1] = T;
            if (prev_t >= 0) {
                // Shared edge apex-P_i: left: prev's P_i->apex (3p+1) with this apex->P_i
                // (3t+2); right: prev's apex->P_i (3p+2) with this P_i->apex (3t+1).
                link(left ? 3 * prev_t + 1 : 3 * prev_t + 2, left ? T + 2 : T + 1);
            }
            prev_t = static_cast<std::int32_t>(t);
        }
        const std::uint32_t last_chain = apex - 1;
        if (left) {
            // Hull: P_0, P_1, ..., P_k-1, apex.
            for (std::uint32_t i = 0; i + 1 < apex; ++i) set_next(i, i + 1);
            set_next(last_chain, apex);
            set_next(apex, 0);
            hull_edge[last_chain] = 3 * prev_t + 1;
            hull_edge[apex] = 2;  // apex->P_0 in triangle 0
        } else {
            // Hull: P_0, apex, P_k-1, ..., P_1.
            set_next(0, apex);
            set_next(apex, last_chain);
            for (std::uint32_t i = last_chain; i > 0; --i) set_next(i, i - 1);
            hull_edge[0] = 1;  // P_0->apex in triangle 0
            hull_edge[apex] = 3 * prev_t + 2;
        }
        m_->hull_size = k + 1;
        last_ = apex;
        starts_.seeded(pts_, apex);
    }

    std::optional<Failure> fail(FailureKind kind, std::uint32_t i, std::string what) const {
        return Failure{kind, input_of_[i], i,
                       "insertion of point " + std::to_string(i) + " of the order (input index " +
                           std::to_string(input_of_[i]) + "): " + std::move(what)};
    }

    // flatten: everything this calls is inlined into it. GCC otherwise keeps the stacks'
    // push_backs, the free list's and the hull hash's small functions as calls in this
    // loop (about 5% of a run in cpu-clock samples); inlined, the strips ran about 7%
    // faster on 10^6 uniform points (bench/ab.py; docs/measurements.md). Calls into other
    // translation units (the predicates' later stages) stay calls.
    [[gnu::flatten]] std::optional<Failure> insert(std::uint32_t i) {
        const Point2 p = pts_[i];
        auto& next = m_->hull_next;
        auto& prev = m_->hull_prev;
        auto& hull_edge = m_->hull_edge;
        auto& tris = m_->triangles;
        auto& half = m_->halfedges;

        // Where the tangent walks start: a vertex with a visible edge at it.
        const auto start = starts_.start(p, i, last_, *m_, [&](std::uint32_t e) {
            this->count(&Counters::visible_search_orientations);
            return k_.orient2d(pts_[e], pts_[next[e]], p) == Sign::negative;
        });
        if (!start) {
            return fail(FailureKind::point_inside_hull, i,
                        "no edge of the current hull is visible from the point");
        }
        const std::uint32_t from = start->from;
        std::uint32_t upper = start->upper;
        std::size_t visible = start->visible;

        // Tangent walks (Alg. 5 without its farther-point rule). Together they can pass
        // at most hull_size - 1 edges: a point outside the hull cannot see all of them.
        std::uint32_t lower = from;
        for (;;) {
            const std::uint32_t a = prev[lower];
            this->count(&Counters::tangent_orientations);
            if (k_.orient2d(pts_[a], pts_[lower], p) != Sign::negative) break;
            lower = a;
            if (++visible >= m_->hull_size) {
                return fail(FailureKind::hull_walk_exceeded, i,
                            "the lower tangent walk passed every hull edge");
            }
        }
        for (;;) {
            const std::uint32_t b = next[upper];
            this->count(&Counters::tangent_orientations);
            if (k_.orient2d(pts_[upper], pts_[b], p) != Sign::negative) break;
            upper = b;
            if (++visible >= m_->hull_size) {
                return fail(FailureKind::hull_walk_exceeded, i,
                            "the upper tangent walk passed every hull edge");
            }
        }
        if (visible == 0) {
            return fail(FailureKind::no_visible_edge, i,
                        "neither hull edge at the last point faces the new point, which lies "
                        "outside the hull");
        }

        // Erosion (Alg. 3 over half-edges). The visible chain lower -> ... -> upper is
        // pushed so that its first edge is on top: the border then comes out in order.
        stack_.clear();
        border_vertex_.clear();
        border_behind_.clear();
        for (std::uint32_t v = upper; v != lower;) {
            const std::uint32_t a = prev[v];
            stack_.push_back({hull_edge[a], v});
            v = a;
        }
        const std::size_t live = m_->live_triangles();
        std::size_t eroded = 0;
        std::uint32_t x = lower;
        border_vertex_.push_back(lower);
        while (!stack_.empty()) {
            const Pending top = stack_.back();
            if (top.behind >= 0) {
                const auto e = static_cast<std::size_t>(top.behind);
                const std::size_t en = next_halfedge(e), ep = prev_halfedge(e);
                if (tris[e] != x || tris[en] != top.end) {
                    return fail(FailureKind::erosion_inconsistent, i,
                                "half-edge " + std::to_string(e) +
                                    " is not the border edge it was pushed as");
                }
                const std::uint32_t c = tris[ep];
                if (R == Repair::erode && in_circle(pts_[x], pts_[top.end], pts_[c], p)) {
                    stack_.pop_back();
                    stack_.push_back({half[en], top.end});  // c -> end
                    stack_.push_back({half[ep], c});        // x -> c, processed first
                    m_->remove_triangle(e / 3);
                    this->count(&Counters::eroded_edges);
                    this->count(&Counters::triangles_destroyed);
                    if (++eroded > live) {
                        return fail(FailureKind::erosion_exceeded, i,
                                    "the erosion destroyed more triangles than there are");
                    }
                    continue;
                }
            }
            stack_.pop_back();
            border_vertex_.push_back(top.end);
            border_behind_.push_back(top.behind);
            x = top.end;
        }

        flip_stack_.clear();
        // Connect: border edge a -> b gets triangle (b, a, p). Its half-edge b->a faces
        // the triangle behind; with nothing behind, b->a is a hull edge outside the
        // visible chain (the eroded triangle had two hull edges) and keeps being one.
        std::int32_t prev_t = -1;
        for (std::size_t j = 0; j < border_behind_.size(); ++j) {
            const std::uint32_t a = border_vertex_[j], b = border_vertex_[j + 1];
            const auto t = static_cast<std::int32_t>(new_triangle(b, a, i));
            const std::int32_t behind = border_behind_[j];
            link(3 * t, behind);
            if constexpr (R == Repair::legalize) flip_stack_.push_back(3 * t);
            if (behind < 0) hull_edge[b] = 3 * t;
            if (prev_t < 0) {
                half[3 * static_cast<std::size_t>(t) + 1] = -1;
                hull_edge[lower] = 3 * t + 1;  // lower -> p
            } else {
                link(3 * t + 1, 3 * prev_t + 2);
            }
            prev_t = t;
        }
        half[3 * static_cast<std::size_t>(prev_t) + 2] = -1;
        hull_edge[i] = 3 * prev_t + 2;  // p -> upper
        if constexpr (R == Repair::legalize) {
            // The new triangles' edges opposite p (half-edge 0 of each, b -> a) are the
            // ones the fan may have made illegal. Each flip gives p one more neighbour
            // among the earlier points, so more than i flips means the kernel contradicted
            // itself.
            if (!legalize<P>(k_, pts_, *m_, static_cast<Counting<I>&>(*this), flip_stack_, i)) {
                return fail(FailureKind::flips_exceeded, i,
                            "more flips than the point can have neighbours");
            }
        }
        starts_.inserted(*m_, i, lower, upper);
        set_next(lower, i);
        set_next(i, upper);
        m_->hull_size = m_->hull_size + 2 - visible;
        last_ = i;
        eroded_total_ += eroded;
        return std::nullopt;
    }

    const K& k_;
    std::span<const Point2> pts_;
    std::span<const std::uint32_t> input_of_;
    Starts starts_;
    Mesh* m_ = nullptr;
    std::vector<Pending> stack_;  // reused by every insertion: no allocation
    std::vector<std::uint32_t> border_vertex_;
    std::vector<std::int32_t> border_behind_;
    std::vector<std::int32_t> flip_stack_;  // Repair::legalize
    std::uint32_t last_ = 0;
    std::size_t erosion_limit_ = 0;  // limit_erosion
    std::size_t eroded_total_ = 0;
    bool gave_up_ = false;
};

/// The vertex ids of a radial run: mesh vertex j is sorted position order[j], input index
/// input_of[j].
struct RadialIds {
    std::vector<std::uint32_t> order, input_of;
};

/// Working memory of build_radial, kept by callers that run it many times (the strips:
/// allocating a strip's arrays afresh each time costs a page fault per 4 KiB of them,
/// whenever malloc serves them from mappings of their own).
struct RadialWorkspace {
    RadialScratch sort;
    FreshVector<Point2> local;  // the points in radial order
    /// False: the sort's arrays are freed before the insertions start, as a one-off run
    /// wants (at 10^6 points they are 48 MB, which would otherwise stay live through the
    /// build and raise its peak).
    bool keep_sort_memory = true;
    /// Eroded edges per point beyond which the radial run gives up and its points are
    /// inserted by cavities in BRIO order instead (Builder::limit_erosion,
    /// build_by_cavities); 0: never. Only `automatic` sets it (external.hpp).
    std::size_t erosion_limit = 0;
    /// Whether the last build_radial gave its points to build_by_cavities.
    bool gave_up = false;
};

/// The fallback of a radial run that gave up: the Bowyer-Watson insertion (bowyer_watson.hpp)
/// of `points` (sorted, distinct, not all collinear) in BRIO order, written as build_radial
/// writes its run (ids.order[j]: the position in `points` of mesh vertex j). The mesh's
/// deleted slots (the ghosts') are in its free list; off-hull vertices have hull_next dead.
template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
std::optional<Failure> build_by_cavities(const K& kernel, std::span<const Point2> points,
                                         std::span<const std::uint32_t> input_of, RadialIds& ids,
                                         Mesh& mesh, Counters& counters) {
    ids.order = brio_order(points);
    std::vector<Point2> local(points.size());
    ids.input_of.resize(points.size());
    for (std::size_t j = 0; j < points.size(); ++j) {
        local[j] = points[ids.order[j]];
        ids.input_of[j] = input_of[ids.order[j]];
    }
    CavityInserter<K, I, P> inserter(kernel, local, ids.input_of, ids.order);
    auto failure = inserter.run(mesh);
    counters += inserter.counters();
    return failure;
}

/// One external incremental run in radial order over `points` (sorted, distinct, not
/// empty): about their radial centre, exact distance order, the collinear prefix sorted
/// back into position order. `input_of` maps positions to input indices. Counters are
/// added to `counters`. `ids`, `mesh` and `work` keep their memory for the next run.
template <PredicateKernel K, Instrumentation I, InCirclePolicy P, Repair R = Repair::erode>
std::optional<Failure> build_radial(const K& kernel, std::span<const Point2> points,
                                    std::span<const std::uint32_t> input_of, RadialIds& ids,
                                    Mesh& mesh, Counters& counters, RadialWorkspace& work) {
    const Point2 centre = radial_centre(points);
    radial_order(points, centre, kernel, work.sort, ids.order);
    if (!work.keep_sort_memory) work.sort = RadialScratch{};
    sort_collinear_prefix(points, std::span<std::uint32_t>(ids.order), kernel);
    FreshVector<Point2>& local = work.local;
    local.resize(ids.order.size());
    ids.input_of.resize(ids.order.size());
    for (std::size_t j = 0; j < ids.order.size(); ++j) {
        local[j] = points[ids.order[j]];
        ids.input_of[j] = input_of[ids.order[j]];
    }
    Builder<K, I, P, RadialHullHash, R> builder(kernel, local, ids.input_of,
                                                RadialHullHash(centre));
    builder.limit_erosion(work.erosion_limit);
    auto failure = builder.run(mesh);
    counters += builder.counters();
    work.gave_up = builder.gave_up();
    if (failure || !work.gave_up) return failure;
    return build_by_cavities<K, I, P>(kernel, points, input_of, ids, mesh, counters);
}

/// One radial run over the whole sorted input, written as an algorithm's output: the mesh
/// over radial positions, their input indices, and the id of sorted position 0.
/// `erosion_limit`: RadialWorkspace::erosion_limit (a fallback is counted in
/// result.cavity_pieces).
template <PredicateKernel K, Instrumentation I, InCirclePolicy P, Repair R = Repair::erode>
void build_radial_output(const K& kernel, const SortedInput& in, MeshOutput& out, Result& result,
                         std::size_t erosion_limit = 0) {
    RadialIds ids;
    RadialWorkspace work;
    work.keep_sort_memory = false;
    work.erosion_limit = erosion_limit;
    result.failure = build_radial<K, I, P, R>(kernel, in.points, in.input_of, ids, out.mesh,
                                              result.counters, work);
    result.cavity_pieces = work.gave_up ? 1 : 0;
    for (std::size_t j = 0; j < ids.order.size(); ++j) {
        if (ids.order[j] == 0) out.first = static_cast<std::uint32_t>(j);
    }
    out.input_of = std::move(ids.input_of);
}

}  // namespace exidel::delaunay::detail
