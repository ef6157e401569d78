// exidel: the external incremental Delaunay triangulation (Yifeng Cai 2025).
//
// Points are inserted in lexicographic order, so every new point p lies strictly outside
// the hull of the earlier ones and no point location is needed (paper Alg. 1):
//
//   1. seed      the first point off the line of the earlier ones, fanned to them;
//   2. tangents  walk the hull from the last inserted point clockwise to the lower and
//                counter-clockwise to the upper tangent point (Alg. 2 / 5). An edge is
//                visible only when p is strictly on its outer side: a point collinear
//                with a hull edge connects to the nearer endpoint, collinear points stay
//                hull vertices (the paper's hull appendix keeps the farther one, which is
//                right for hulls and wrong for triangulations);
//   3. erosion   pop border edges from a stack; an edge whose triangle's circumcircle
//                strictly contains p is deleted and the two edges behind it pushed
//                (Alg. 3). Points on the circle keep their edge;
//   4. connect   fan p to the surviving border.
//
// The in-circle test of step 3 is decided in exactly one place: Builder::in_circle.
//
// Header template: any exidel::PredicateKernel works. The library compiles explicit
// instantiations for the shipped kernels (see the extern declarations at the end).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/floating.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/mpfr.hpp"

namespace exidel::delaunay {

namespace detail {

template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
class Builder {
public:
    Builder(const K& kernel, SortedInput& input) : k_(kernel), in_(input) {}

    Result run() {
        Result result;
        const std::size_t n = in_.points.size();
        Triangulation& tri = result.triangulation;
        std::size_t first_off = n;
        // The paper's "try to create a triangle": P[j] against the line P[0] P[j-1].
        for (std::size_t j = 2; j < n; ++j) {
            count(&Counters::seed_orientations);
            if (k_.orient2d(in_.points[0], in_.points[j - 1], in_.points[j]) != Sign::zero) {
                first_off = j;
                break;
            }
        }
        if (first_off == n) {
            tri.collinear = true;
            tri.hull = in_.input_of;  // the chain, lexicographically
        } else {
            hull_next_.assign(n, 0);
            hull_prev_.assign(n, 0);
            hull_edge_.assign(n, -1);
            triangles_.reserve(6 * n);
            halfedges_.reserve(6 * n);
            seed(first_off);
            for (std::size_t i = first_off + 1; i < n && !result.failure; ++i) {
                result.failure = insert(static_cast<std::uint32_t>(i));
            }
            if (!result.failure) finish(tri);
        }
        tri.vertex_of_input = std::move(in_.vertex_of_input);
        tri.duplicates = std::move(in_.duplicates);
        result.counters = counters_;
        return result;
    }

private:
    static constexpr std::uint32_t dead = 0xffffffffu;  // vertex slot of a deleted triangle

    // One entry of the erosion stack: the half-edge of the triangle behind a border edge
    // (or -1: nothing behind it) and the border edge's end vertex. Its start vertex is the
    // end of the border built so far, because the stack is processed in border order.
    struct Pending {
        std::int32_t behind;
        std::uint32_t end;
    };

    void count(std::uint64_t Counters::*field) {
        if constexpr (I != Instrumentation::off) ++(counters_.*field);
    }

    /// The one place where the in-circle question is decided. abc is the triangle behind
    /// border edge a->b (counter-clockwise: c on the left of a->b), p the new point on
    /// the right. True: p strictly inside the circle through a, b, c.
    bool in_circle(Point2 a, Point2 b, Point2 c, Point2 p) {
        count(&Counters::incircle_tests);
        if constexpr (I == Instrumentation::theorem1) {
            // Theorem 1, decided exactly whatever kernel runs the algorithm.
            ++counters_.theorem1_checks;
            if (!(AdaptiveKernel::orient2d(a, b, c) == Sign::positive &&
                  AdaptiveKernel::orient2d(a, b, p) == Sign::negative)) {
                ++counters_.theorem1_violations;
            }
        }
        if constexpr (P == InCirclePolicy::determinant) {
            return k_.incircle(a, b, c, p) == Sign::positive;
        } else {
            // Paper roles: B = a, C = b, D = c (opposite vertex), A = p (new point).
            return k_.incircle_cosine(a, b, c, p) == Sign::positive;
        }
    }

    std::uint32_t new_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        count(&Counters::triangles_created);
        std::uint32_t t;
        if (!free_.empty()) {
            t = free_.back();
            free_.pop_back();
            triangles_[3 * t] = a;
            triangles_[3 * t + 1] = b;
            triangles_[3 * t + 2] = c;
        } else {
            t = static_cast<std::uint32_t>(triangles_.size() / 3);
            triangles_.insert(triangles_.end(), {a, b, c});
            halfedges_.insert(halfedges_.end(), {-1, -1, -1});
        }
        return t;
    }

    void link(std::int32_t a, std::int32_t b) {
        halfedges_[static_cast<std::size_t>(a)] = b;
        if (b >= 0) halfedges_[static_cast<std::size_t>(b)] = a;
    }

    // Fan of the collinear prefix P[0..k-1] to P[k] (k >= 2).
    void seed(std::size_t k) {
        const auto& pts = in_.points;
        const auto apex = static_cast<std::uint32_t>(k);
        const bool left = k_.orient2d(pts[0], pts[k - 1], pts[k]) == Sign::positive;
        std::int32_t prev_t = -1;
        for (std::uint32_t i = 0; i + 1 < apex; ++i) {
            // left: (P_i, P_i+1, apex); right: (P_i+1, P_i, apex). Half-edge 3t is the
            // chain edge, on the hull.
            const std::uint32_t t = left ? new_triangle(i, i + 1, apex) : new_triangle(i + 1, i, apex);
            const auto T = static_cast<std::int32_t>(3 * t);
            hull_edge_[left ? i : i + 1] = T;
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
            hull_edge_[last_chain] = 3 * prev_t + 1;
            hull_edge_[apex] = 2;  // apex->P_0 in triangle 0
        } else {
            // Hull: P_0, apex, P_k-1, ..., P_1.
            set_next(0, apex);
            set_next(apex, last_chain);
            for (std::uint32_t i = last_chain; i > 0; --i) set_next(i, i - 1);
            hull_edge_[0] = 1;  // P_0->apex in triangle 0
            hull_edge_[apex] = 3 * prev_t + 2;
        }
        hull_size_ = k + 1;
        last_ = apex;
    }

    void set_next(std::uint32_t a, std::uint32_t b) {
        hull_next_[a] = b;
        hull_prev_[b] = a;
    }

    std::optional<Failure> fail(FailureKind kind, std::uint32_t i, std::string what) const {
        return Failure{kind, in_.input_of[i], i,
                       "insertion of sorted point " + std::to_string(i) + " (input index " +
                           std::to_string(in_.input_of[i]) + "): " + std::move(what)};
    }

    std::optional<Failure> insert(std::uint32_t i) {
        const auto& pts = in_.points;
        const Point2 p = pts[i];

        // Tangent walks (Alg. 5 without its farther-point rule). Together they can pass
        // at most hull_size - 1 edges: a point outside the hull cannot see all of them.
        std::size_t visible = 0;
        std::uint32_t lower = last_;
        for (;;) {
            const std::uint32_t a = hull_prev_[lower];
            count(&Counters::tangent_orientations);
            if (k_.orient2d(pts[a], pts[lower], p) != Sign::negative) break;
            lower = a;
            if (++visible >= hull_size_) {
                return fail(FailureKind::hull_walk_exceeded, i, "lower tangent walk");
            }
        }
        std::uint32_t upper = last_;
        for (;;) {
            const std::uint32_t b = hull_next_[upper];
            count(&Counters::tangent_orientations);
            if (k_.orient2d(pts[upper], pts[b], p) != Sign::negative) break;
            upper = b;
            if (++visible >= hull_size_) {
                return fail(FailureKind::hull_walk_exceeded, i, "upper tangent walk");
            }
        }
        if (visible == 0) {
            return fail(FailureKind::no_visible_edge, i, "both hull edges at the last point");
        }

        // Erosion (Alg. 3 over half-edges). The visible chain lower -> ... -> upper is
        // pushed so that its first edge is on top: the border then comes out in order.
        stack_.clear();
        border_vertex_.clear();
        border_behind_.clear();
        for (std::uint32_t v = upper; v != lower;) {
            const std::uint32_t a = hull_prev_[v];
            stack_.push_back({hull_edge_[a], v});
            v = a;
        }
        const std::size_t live = triangles_.size() / 3 - free_.size();
        std::size_t eroded = 0;
        std::uint32_t x = lower;
        border_vertex_.push_back(lower);
        while (!stack_.empty()) {
            const Pending top = stack_.back();
            if (top.behind >= 0) {
                const auto e = static_cast<std::size_t>(top.behind);
                const std::size_t en = next_halfedge(e), ep = prev_halfedge(e);
                if (triangles_[e] != x || triangles_[en] != top.end) {
                    return fail(FailureKind::erosion_inconsistent, i,
                                "half-edge " + std::to_string(e) +
                                    " is not the border edge it was pushed as");
                }
                const std::uint32_t c = triangles_[ep];
                if (in_circle(pts[x], pts[top.end], pts[c], p)) {
                    stack_.pop_back();
                    stack_.push_back({halfedges_[en], top.end});  // c -> end
                    stack_.push_back({halfedges_[ep], c});        // x -> c, processed first
                    const std::size_t t = e / 3;
                    triangles_[3 * t] = triangles_[3 * t + 1] = triangles_[3 * t + 2] = dead;
                    free_.push_back(static_cast<std::uint32_t>(t));
                    count(&Counters::eroded_edges);
                    count(&Counters::triangles_destroyed);
                    if (++eroded > live) {
                        return fail(FailureKind::erosion_exceeded, i, "erosion stack");
                    }
                    continue;
                }
            }
            stack_.pop_back();
            border_vertex_.push_back(top.end);
            border_behind_.push_back(top.behind);
            x = top.end;
        }

        // Connect: border edge a -> b gets triangle (b, a, p). Its half-edge b->a faces
        // the triangle behind; with nothing behind, b->a is a hull edge outside the
        // visible chain (the eroded triangle had two hull edges) and keeps being one.
        std::int32_t prev_t = -1;
        for (std::size_t j = 0; j < border_behind_.size(); ++j) {
            const std::uint32_t a = border_vertex_[j], b = border_vertex_[j + 1];
            const auto t = static_cast<std::int32_t>(new_triangle(b, a, i));
            const std::int32_t behind = border_behind_[j];
            link(3 * t, behind);
            if (behind < 0) hull_edge_[b] = 3 * t;
            if (prev_t < 0) {
                halfedges_[3 * static_cast<std::size_t>(t) + 1] = -1;
                hull_edge_[lower] = 3 * t + 1;  // lower -> p
            } else {
                link(3 * t + 1, 3 * prev_t + 2);
            }
            prev_t = t;
        }
        halfedges_[3 * static_cast<std::size_t>(prev_t) + 2] = -1;
        hull_edge_[i] = 3 * prev_t + 2;  // p -> upper
        set_next(lower, i);
        set_next(i, upper);
        hull_size_ = hull_size_ + 2 - visible;
        last_ = i;
        return std::nullopt;
    }

    // Sorted positions -> input indices; the hull from the lexicographically smallest
    // point, which is always a hull vertex.
    void finish(Triangulation& tri) {
        tri.triangles.resize(triangles_.size());
        for (std::size_t e = 0; e < triangles_.size(); ++e) {
            tri.triangles[e] = in_.input_of[triangles_[e]];
        }
        tri.halfedges = std::move(halfedges_);
        tri.hull.reserve(hull_size_);
        std::uint32_t v = 0;
        for (std::size_t s = 0; s < hull_size_; ++s) {
            tri.hull.push_back(in_.input_of[v]);
            v = hull_next_[v];
        }
    }

    const K& k_;
    SortedInput& in_;
    Counters counters_{};
    std::vector<std::uint32_t> triangles_;  // sorted positions during construction
    std::vector<std::int32_t> halfedges_;
    std::vector<std::uint32_t> hull_next_, hull_prev_;  // the hull as a linked cycle
    std::vector<std::int32_t> hull_edge_;  // v -> the half-edge v -> hull_next_[v]
    std::vector<std::uint32_t> free_;      // slots of eroded triangles, reused by connect
    std::vector<Pending> stack_;           // reused by every insertion: no allocation
    std::vector<std::uint32_t> border_vertex_;
    std::vector<std::int32_t> border_behind_;
    std::size_t hull_size_ = 0;
    std::uint32_t last_ = 0;
};

}  // namespace detail

/// Delaunay triangulation of `points` with the predicates of `kernel`.
///
/// Every finite input is accepted, including none, one or two points and duplicates;
/// a non-finite coordinate fails before any work. With an exact kernel (AdaptiveKernel,
/// GmpExactKernel) the result is a Delaunay triangulation, the same one for both
/// in-circle policies. With an inexact kernel the result may be wrong, or the run may
/// stop with a Failure saying where the kernel contradicted itself; it never loops or
/// reads out of bounds.
template <Instrumentation I = Instrumentation::off, PredicateKernel K>
Result triangulate(std::span<const Point2> points, const K& kernel, const Options& options = {}) {
    detail::SortedInput input;
    if (auto failure = detail::sort_and_dedupe(points, input)) {
        Result r;
        r.failure = std::move(failure);
        return r;
    }
    if (options.incircle == InCirclePolicy::cosine) {
        return detail::Builder<K, I, InCirclePolicy::cosine>(kernel, input).run();
    }
    return detail::Builder<K, I, InCirclePolicy::determinant>(kernel, input).run();
}

#define EXIDEL_DELAUNAY_EXTERN(K)                                                        \
    extern template Result triangulate<Instrumentation::off, K>(std::span<const Point2>,  \
                                                                 const K&, const Options&); \
    extern template Result triangulate<Instrumentation::counters, K>(                     \
        std::span<const Point2>, const K&, const Options&);                               \
    extern template Result triangulate<Instrumentation::theorem1, K>(                     \
        std::span<const Point2>, const K&, const Options&);

EXIDEL_DELAUNAY_EXTERN(AdaptiveKernel)
EXIDEL_DELAUNAY_EXTERN(DoubleKernel)
EXIDEL_DELAUNAY_EXTERN(LongDoubleKernel)
EXIDEL_DELAUNAY_EXTERN(GmpExactKernel)
EXIDEL_DELAUNAY_EXTERN(MpfrKernel)
#undef EXIDEL_DELAUNAY_EXTERN

}  // namespace exidel::delaunay
