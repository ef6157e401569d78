// exidel: Guibas and Stolfi's divide and conquer (1985) all the way down, as two
// registered algorithms (algorithms.hpp):
//
//   divide-and-conquer  vertical cuts: the lexicographically sorted points are halved
//                       recursively, each half sorted already;
//   dwyer               alternating cuts (Dwyer 1987 as Shewchuk's Triangle implements it,
//                       its default): the cut alternates between vertical and horizontal
//                       at each level, each by a median partition (std::nth_element), so
//                       that pieces stay roughly square. On uniform points a merge then
//                       costs about the square root of its piece's size, and the merges of
//                       all levels together about n, where vertical cuts cost n per level
//                       (thin strips are triangulated into long slivers that the merges
//                       above delete again).
//
// Both share one recursion over ranges [lo, hi) of a point array (vertex ids are
// positions in it):
//   - a range of at least six points is cut into a left part of a multiple of three
//     points (about half) and the rest, so that all leaves but one have three points;
//     dwyer partitions the range first, and positions no longer move once their subtree
//     is triangulated;
//   - a part whose points all lie on one line cannot be triangulated alone (the index
//     arrays of Mesh hold edges only as sides of triangles), so a range whose cut would
//     leave such a part is not cut: it is a leaf. Three points are one triangle; a larger
//     leaf (a line and a few points, or the one leaf of four or five) is sorted and
//     triangulated by the radial sweep (strips.hpp, build_piece);
//   - the two triangulated parts are merged by the zipper (merge.hpp). A vertical cut
//     separates them lexicographically, a horizontal one by (y, -x), the lexicographic
//     order of the plane turned clockwise by 90 degrees, which the zipper accepts: it
//     starts from the left part's largest and the right part's smallest point in that
//     order, found by a scan.
//
// The zipper asks its in-circle questions with the determinant whatever the policy, as
// for the strips (merge.hpp): its candidate circles are not circles of triangles across
// an edge from the tested point, the setting of Theorem 1. The cosine policy therefore
// reaches only the leaves the radial sweep triangulates.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exidel/delaunay/detail/builder.hpp"
#include "exidel/delaunay/detail/merge.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/detail/strips.hpp"
#include "exidel/delaunay/external.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

/// The order a cut separates by: vertical cuts (x, y), horizontal cuts (y, -x).
inline bool cut_less(Point2 a, Point2 b, bool horizontal) {
    if (horizontal) return a.y < b.y || (a.y == b.y && a.x > b.x);
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

template <PredicateKernel K, Instrumentation I, InCirclePolicy P, bool Alternate>
class DivideAndConquerBuilder {
public:
    /// `points` (sorted lexicographically, distinct) and the input index of each
    /// position; dwyer permutes both together. `mesh` receives the triangulation.
    DivideAndConquerBuilder(const K& kernel, std::vector<Point2>& points,
                            std::vector<std::uint32_t>& input_of, Mesh& mesh)
        : k_(kernel), pts_(points), input_of_(input_of), mesh_(mesh),
          gone_(6 * points.size(), 0), merger_(kernel, points, mesh, gone_) {}

    std::optional<Failure> run(Counters& counters) {
        const std::size_t n = pts_.size();
        mesh_ = Mesh{};
        if (n < 3 || collinear(0, static_cast<std::uint32_t>(n))) {
            mesh_.collinear = true;
            return std::nullopt;
        }
        mesh_.triangles.assign(6 * n, dead);
        mesh_.halfedges.assign(6 * n, -1);
        mesh_.hull_next.assign(n, dead);
        mesh_.hull_prev.assign(n, dead);
        mesh_.hull_edge.assign(n, -1);
        Piece all;
        auto failure = solve(0, static_cast<std::uint32_t>(n), false, all);
        counters += leaf_counters_;
        counters += merger_.counters();
        return failure;
    }

private:
    // Whether the points at positions [lo, hi) (distinct, at least two) lie on one line.
    bool collinear(std::uint32_t lo, std::uint32_t hi) const {
        for (std::uint32_t j = lo + 2; j < hi; ++j) {
            if (k_.orient2d(pts_[lo], pts_[lo + 1], pts_[j]) != Sign::zero) return false;
        }
        return true;
    }

    // Moves the points of [lo, hi) so that [lo, mid) holds the mid - lo smallest in the
    // cut's order (a median partition; the order inside each part is left arbitrary), or,
    // with mid == hi, sorts them lexicographically.
    void partition(std::uint32_t lo, std::uint32_t mid, std::uint32_t hi, bool horizontal) {
        scratch_.clear();
        for (std::uint32_t j = lo; j < hi; ++j) scratch_.push_back({pts_[j], input_of_[j]});
        const auto less = [horizontal](const Item& a, const Item& b) {
            return cut_less(a.p, b.p, horizontal);
        };
        if (mid == hi) {
            std::sort(scratch_.begin(), scratch_.end(), less);
        } else {
            std::nth_element(scratch_.begin(), scratch_.begin() + (mid - lo), scratch_.end(), less);
        }
        for (std::uint32_t j = lo; j < hi; ++j) {
            pts_[j] = scratch_[j - lo].p;
            input_of_[j] = scratch_[j - lo].id;
        }
    }

    // Triangulates [lo, hi) (not all collinear) into `piece`; `horizontal`: the cut of
    // this level (dwyer alternates it, vertical cuts never set it).
    std::optional<Failure> solve(std::uint32_t lo, std::uint32_t hi, bool horizontal,
                                 Piece& piece) {
        const std::uint32_t m = hi - lo;
        if (m >= 6) {
            const std::uint32_t mid = lo + 3 * std::max<std::uint32_t>(1, m / 6);
            if constexpr (Alternate) partition(lo, mid, hi, horizontal);
            if (!collinear(lo, mid) && !collinear(mid, hi)) {
                Piece right;
                if (auto f = solve(lo, mid, Alternate && !horizontal, piece)) return f;
                if (auto f = solve(mid, hi, Alternate && !horizontal, right)) return f;
                std::uint32_t l0 = mid - 1, r0 = mid;
                if constexpr (Alternate) {
                    // The parts' extreme points in the cut's order.
                    for (std::uint32_t j = lo; j < mid; ++j) {
                        if (cut_less(pts_[l0], pts_[j], horizontal)) l0 = j;
                    }
                    for (std::uint32_t j = mid; j < hi; ++j) {
                        if (cut_less(pts_[j], pts_[r0], horizontal)) r0 = j;
                    }
                }
                return merger_.merge(piece, right, l0, r0);
            }
        }
        // The radial sweep of a larger leaf wants its points sorted (its collinear first
        // points are fanned in position order); partitions left them in any order.
        if constexpr (Alternate) {
            if (m > 3) partition(lo, hi, hi, false);
        }
        return build_piece<K, I, P>(k_, pts_, input_of_, lo, hi, mesh_, piece, leaf_counters_);
    }

    struct Item {
        Point2 p;
        std::uint32_t id;
    };

    const K& k_;
    std::vector<Point2>& pts_;
    std::vector<std::uint32_t>& input_of_;
    Mesh& mesh_;
    std::vector<std::uint8_t> gone_;
    Merger<K, I> merger_;
    Counters leaf_counters_{};
    std::vector<Item> scratch_;
};

template <bool Alternate>
struct DivideAndConquerAlgorithm {
    template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
    static void run(const K& kernel, const SortedInput& in, const Options&, MeshOutput& out,
                    Result& result) {
        // The recursion permutes its own copy (dwyer); the input_of of each position is
        // permuted along, and the copy's order is the sorted positions' at first.
        std::vector<Point2> points = in.points;
        std::vector<std::uint32_t> input_of = in.input_of;
        if constexpr (Alternate) {
            // Track where sorted position 0 (the smallest point) ends up through its
            // input index, which no other position shares.
            DivideAndConquerBuilder<K, I, P, true> builder(kernel, points, input_of, out.mesh);
            result.failure = builder.run(result.counters);
            if (!points.empty()) {
                for (std::size_t j = 0; j < input_of.size(); ++j) {
                    if (input_of[j] == in.input_of[0]) out.first = static_cast<std::uint32_t>(j);
                }
            }
            out.input_of = std::move(input_of);
        } else {
            DivideAndConquerBuilder<K, I, P, false> builder(kernel, points, input_of, out.mesh);
            result.failure = builder.run(result.counters);
        }
    }
};

using DivideAndConquer = DivideAndConquerAlgorithm<false>;
using Dwyer = DivideAndConquerAlgorithm<true>;

}  // namespace exidel::delaunay::detail
