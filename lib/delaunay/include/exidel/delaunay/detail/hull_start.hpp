// exidel: where the external insertion's tangent walks start, one type per insertion
// order. Builder (builder.hpp) asks its Start for a vertex of the current hull at which
// the new point p sees a hull edge, and tells it when the hull changed; it never branches
// on the order itself.
//
//   LastPointStart  the lexicographic order: the last point inserted is the largest so
//                   far, hence a hull vertex, and p, larger still, sees one of its two hull
//                   edges. Nothing to maintain.
//   RadialHullHash  the radial order: p lies on the boundary of a disc around the centre
//                   that holds every earlier point, so p sees some hull edge, but which one
//                   is not known in advance. An angular hash of hull vertices around the
//                   centre (as in delaunator) proposes a start, and a bounded walk along
//                   the hull tests edges with the kernel's orient2d until one is strictly
//                   visible (visible_edge).
//
// The interface (duck-typed, both below):
//   prepare(points)             once, before the seed
//   seeded(points, apex)        the seed fan of points 0..apex is built
//   start(p, i, last, mesh, sees) -> std::optional<Start>
//                               where the walks start for point i; `sees(e)` tests hull
//                               edge e -> hull_next[e] with the kernel (p strictly on its
//                               right). nullopt: no visible edge was found (only an
//                               inexact kernel can cause that)
//   inserted(mesh, i, lower, upper)
//                               called after point i was connected between the tangent
//                               points lower and upper, before the hull cycle is relinked:
//                               the vertices strictly between them are leaving the hull
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/detail/radial.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay::detail {

/// Where the tangent walks start: `lower` walks clockwise from `from`, `upper` walks
/// counter-clockwise from `upper`; `visible` edges between them are already known visible.
struct Start {
    std::uint32_t from, upper;
    std::size_t visible;
};

struct LastPointStart {
    void prepare(std::span<const Point2>) {}
    void seeded(std::span<const Point2>, std::uint32_t) {}
    template <class Sees>
    std::optional<Start> start(Point2, std::uint32_t, std::uint32_t last, const Mesh&, Sees&&) {
        return Start{last, last, 0};
    }
    void inserted(Mesh&, std::uint32_t, std::uint32_t, std::uint32_t) {}
};

class RadialHullHash {
public:
    /// `centre`: the centre the points were ordered about.
    explicit RadialHullHash(Point2 centre) : centre_(centre) {}

    void prepare(std::span<const Point2> pts) {
        hash_.assign(
            std::max<std::size_t>(16, static_cast<std::size_t>(std::sqrt(double(pts.size())))),
            dead);
        bucket_.assign(pts.size(), 0);
        const Point2 box = bounding_box_centre(pts);
        const double ax = box.x - centre_.x, ay = box.y - centre_.y;
        const double len = std::abs(ax) + std::abs(ay);
        if (len > 0 && std::isfinite(len)) axis_x_ = ax / len, axis_y_ = ay / len;
        angle_lo_ = 2;
        double hi = -2;
        for (const Point2& p : pts) {
            const double a = pseudo_angle(p);
            angle_lo_ = std::min(angle_lo_, a);
            hi = std::max(hi, a);
        }
        angle_scale_ = hi > angle_lo_ ? static_cast<double>(hash_.size()) / (hi - angle_lo_) : 0;
        if (!std::isfinite(angle_scale_)) angle_scale_ = 0;
        // Every point's bucket here, in a loop of independent divisions, rather than one
        // at each insertion, where the division waits on the walk before it.
        for (std::size_t v = 0; v < pts.size(); ++v) {
            bucket_[v] = static_cast<std::uint32_t>(hash_key(pts[v]));
        }
    }

    void seeded(std::span<const Point2>, std::uint32_t apex) {
        for (std::uint32_t v = 0; v <= apex; ++v) hash_[bucket_[v]] = v;
    }

    // A hull vertex e whose edge e -> next(e) p sees strictly. The hash gives a live hull
    // vertex near p's angle; from it the walk tests hull edges, alternately one more
    // forwards and one more backwards, and stops at the first with p strictly on its
    // right, so the edge returned is visible by the kernel's own answer and the walk costs
    // the hull distance from the start to the nearest visible edge (a one-way walk can go
    // round the whole hull: quadratic on a convex curve, where every point lands in the
    // same bucket). With an inexact kernel the walk may pass every edge without finding
    // one, and that is reported, not guessed.
    template <class Sees>
    std::optional<Start> start(Point2, std::uint32_t i, std::uint32_t, const Mesh& mesh,
                               Sees&& sees) {
        const auto e = visible_edge(bucket_[i], mesh, sees);
        if (!e) return std::nullopt;
        return Start{*e, mesh.hull_next[*e], 1};  // the edge e -> next(e): already tested
    }

    void inserted(Mesh& mesh, std::uint32_t i, std::uint32_t lower, std::uint32_t upper) {
        auto& next = mesh.hull_next;
        // Vertices strictly between the tangent points leave the hull: the hash must not
        // propose them again.
        for (std::uint32_t v = next[lower]; v != upper;) {
            const std::uint32_t w = next[v];
            next[v] = dead;
            v = w;
        }
        // The new point always takes its bucket; the tangent points only refill buckets
        // whose vertex left the hull. Overwriting a live entry with a tangent point can
        // move a bucket's start to the far end of a long chain (on a convex curve the
        // tangent is often the opposite end of the arc), and then every later point in
        // that bucket walks the whole chain.
        for (const std::uint32_t v : {lower, upper}) {
            std::uint32_t& slot = hash_[bucket_[v]];
            if (slot == dead || next[slot] == dead) slot = v;
        }
        hash_[bucket_[i]] = i;
    }

private:
    // A pseudo-angle of p - centre (monotone in the angle, no trigonometry), cut into
    // hash_.size() buckets. Only a starting guess: any bucket is correct, a good one makes
    // the walk in visible_edge short. The angle is measured from the direction of the
    // points' bounding-box centre and stretched over the range the points actually
    // cover: with a centre far outside the points (the osculating centre of a sampled
    // convex curve) they span a tiny angle, and unstretched buckets would put them all in
    // one, making the walk linear per point.
    double pseudo_angle(Point2 p) const {
        const double dx = p.x - centre_.x, dy = p.y - centre_.y;
        const double rx = dx * axis_x_ + dy * axis_y_, ry = dy * axis_x_ - dx * axis_y_;
        const double r = std::abs(rx) + std::abs(ry);
        if (!(r > 0) || !std::isfinite(r)) return 0;  // the centre itself, or overflow
        const double q = rx / r;                      // in [-1, 1]
        return ry >= 0 ? 1 - q : q - 1;               // in [-2, 2], 0 along the axis
    }
    std::size_t hash_key(Point2 p) const {
        const double k = (pseudo_angle(p) - angle_lo_) * angle_scale_;
        if (!(k > 0)) return 0;  // also NaN
        return std::min(static_cast<std::size_t>(std::min(k, 1e18)), hash_.size() - 1);
    }

    template <class Sees>
    std::optional<std::uint32_t> visible_edge(std::size_t key, const Mesh& mesh, Sees& sees) const {
        const auto& next = mesh.hull_next;
        const auto& prev = mesh.hull_prev;
        std::uint32_t start = dead;
        for (std::size_t j = 0; j < hash_.size(); ++j) {
            const std::uint32_t v = hash_[(key + j) % hash_.size()];
            if (v != dead && next[v] != dead) {
                start = v;
                break;
            }
        }
        if (start == dead) return std::nullopt;
        std::uint32_t forward = start, backward = prev[start];
        for (std::size_t tested = 0; tested < mesh.hull_size; tested += 2) {
            if (sees(forward)) return forward;
            if (sees(backward)) return backward;
            forward = next[forward];
            backward = prev[backward];
        }
        return std::nullopt;
    }

    Point2 centre_;
    std::vector<std::uint32_t> hash_;    // bucket -> a hull vertex (or dead)
    std::vector<std::uint32_t> bucket_;  // vertex -> its bucket
    double axis_x_ = 1, axis_y_ = 0;     // the direction the hash angle starts from
    double angle_lo_ = 0, angle_scale_ = 0;
};

}  // namespace exidel::delaunay::detail
