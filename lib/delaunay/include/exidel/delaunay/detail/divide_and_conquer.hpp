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
//     points (about half) and the rest, so that all leaves but one have three points.
//     Every cut is planned first, top down (dwyer partitions each range at its cut),
//     then the pieces are triangulated bottom up by the plan;
//   - a part whose points all lie on one line cannot be triangulated alone (the index
//     arrays of Mesh hold edges only as sides of triangles), so a range whose cut would
//     leave such a part is not cut: it is a leaf. Three points are one triangle; a larger
//     leaf (a line and a few points, or the one leaf of four or five) is sorted and
//     triangulated by the radial sweep (strips.hpp, build_piece);
//   - the two triangulated parts are merged by the zipper (merge.hpp). A vertical cut
//     separates them lexicographically, a horizontal one by (y, -x), the lexicographic
//     order of the plane turned clockwise by 90 degrees, which the zipper accepts: it
//     starts from the left part's largest and the right part's smallest point in that
//     order, which the plan finds when it partitions.
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
#include <type_traits>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/builder.hpp"
#include "exidel/delaunay/detail/merge.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/detail/strips.hpp"
#include "exidel/delaunay/external.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

template <PredicateKernel K, Instrumentation I, InCirclePolicy P, bool Alternate>
class DivideAndConquerBuilder {
public:
    /// `points` (sorted lexicographically, distinct) and the input index of each
    /// position; dwyer permutes both together. `mesh` receives the triangulation.
    DivideAndConquerBuilder(const K& kernel, std::vector<Point2>& points,
                            std::vector<std::uint32_t>& input_of, Mesh& mesh)
        : k_(kernel),
          pts_(points),
          input_of_(input_of),
          mesh_(mesh),
          merger_(kernel, points, mesh) {}

    std::optional<Failure> run(Counters& counters) {
        const std::size_t n = pts_.size();
        mesh_ = Mesh{};
        if (n < 3 || collinear(std::span<const Point2>(pts_))) {
            mesh_.collinear = true;
            return std::nullopt;
        }
        // 1. Plan: every cut, top down, on one array of points with their input indices
        // (dwyer's partitions move both); then the array is split into the two the
        // zipper and the result read.
        std::vector<Item> items(n);
        for (std::size_t j = 0; j < n; ++j) items[j] = {pts_[j], input_of_[j]};
        plan(items, 0, static_cast<std::uint32_t>(n), false);
        for (std::size_t j = 0; j < n; ++j) {
            pts_[j] = items[j].p;
            input_of_[j] = items[j].id;
        }
        items = {};
        if constexpr (Alternate) {
            std::uint32_t inputs = 0;
            for (const std::uint32_t i : input_of_) inputs = std::max(inputs, i + 1);
            position_of_.assign(inputs, 0);
            for (std::uint32_t j = 0; j < n; ++j) position_of_[input_of_[j]] = j;
        }
        // 2. Triangulate bottom up, replaying the plan.
        mesh_.triangles.assign(6 * n, dead);
        mesh_.halfedges.assign(6 * n, -1);
        mesh_.hull_next.assign(n, dead);
        mesh_.hull_prev.assign(n, dead);
        mesh_.hull_edge.assign(n, -1);
        Piece all;
        next_ = next_end_ = 0;
        auto failure = solve(0, static_cast<std::uint32_t>(n), false, all);
        counters += leaf_counters_;
        counters += merger_.counters();
        return failure;
    }

private:
    struct Item {
        Point2 p;
        std::uint32_t id;
    };

    // Whether `points` (distinct, at least two; points or Items) lie on one line.
    template <class Range>
    bool collinear(const Range& points) const {
        auto point = [](const auto& x) -> Point2 {
            if constexpr (std::is_same_v<std::decay_t<decltype(x)>, Item>) {
                return x.p;
            } else {
                return x;
            }
        };
        const Point2 a = point(points[0]), b = point(points[1]);
        for (std::size_t j = 2; j < points.size(); ++j) {
            if (k_.orient2d(a, b, point(points[j])) != Sign::zero) return false;
        }
        return true;
    }

    // Where a range of m >= 6 points is cut: a multiple of three points on the left.
    static std::uint32_t cut_at(std::uint32_t lo, std::uint32_t hi) {
        return lo + 3 * std::max<std::uint32_t>(1, (hi - lo) / 6);
    }

    // The plan of [lo, hi) (not all collinear), in pre-order into cuts_: 1 a cut, 0 a
    // leaf. dwyer partitions at the cut first (a median partition, std::nth_element: the
    // order inside each part is left arbitrary); a leaf of more than three points is
    // sorted, since the radial sweep fans its collinear first points in position order.
    void plan(std::vector<Item>& items, std::uint32_t lo, std::uint32_t hi, bool horizontal) {
        const auto first = items.begin() + lo, last = items.begin() + hi;
        if (hi - lo >= 6) {
            const std::uint32_t mid = cut_at(lo, hi);
            if constexpr (Alternate) {
                std::nth_element(first, items.begin() + mid, last,
                                 [horizontal](const Item& a, const Item& b) {
                                     return cut_less(a.p, b.p, horizontal);
                                 });
            }
            const std::span<const Item> all(items);
            if (!collinear(all.subspan(lo, mid - lo)) && !collinear(all.subspan(mid, hi - mid))) {
                cuts_.push_back(1);
                if constexpr (Alternate) {
                    // The zipper's start points, the left part's largest and the right
                    // part's smallest in the cut's order, named by input index: the
                    // partitions below still move them. nth_element put the smallest of
                    // the right part at mid.
                    const auto largest = std::max_element(
                        first, items.begin() + mid, [horizontal](const Item& a, const Item& b) {
                            return cut_less(a.p, b.p, horizontal);
                        });
                    ends_.push_back({largest->id, items[mid].id});
                }
                plan(items, lo, mid, Alternate && !horizontal);
                plan(items, mid, hi, Alternate && !horizontal);
                return;
            }
        }
        cuts_.push_back(0);
        if (Alternate && hi - lo > 3) {
            std::sort(first, last,
                      [](const Item& a, const Item& b) { return cut_less(a.p, b.p, false); });
        }
    }

    // Triangulates [lo, hi) by the plan into `piece`. `horizontal`: the cut of this
    // level (dwyer alternates it).
    std::optional<Failure> solve(std::uint32_t lo, std::uint32_t hi, bool horizontal,
                                 Piece& piece) {
        if (cuts_[next_++] == 0) {
            return build_piece<K, I, P>(k_, pts_, input_of_, lo, hi, mesh_, piece, leaf_counters_,
                                        leaf_work_);
        }
        const std::uint32_t mid = cut_at(lo, hi);
        std::uint32_t l0 = mid - 1, r0 = mid;  // vertical cuts: the array stays sorted
        if constexpr (Alternate) {
            const auto [l0_input, r0_input] = ends_[next_end_++];
            l0 = position_of_[l0_input];
            r0 = position_of_[r0_input];
        }
        Piece right;
        if (auto f = solve(lo, mid, Alternate && !horizontal, piece)) return f;
        if (auto f = solve(mid, hi, Alternate && !horizontal, right)) return f;
        return merger_.merge(piece, right, l0, r0);
    }

    const K& k_;
    std::vector<Point2>& pts_;
    std::vector<std::uint32_t>& input_of_;
    Mesh& mesh_;
    Merger<K, I> merger_;
    Counters leaf_counters_{};
    PieceWorkspace leaf_work_;                                   // reused by every leaf
    std::vector<std::uint8_t> cuts_;                             // the plan, pre-order
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends_;  // dwyer: start points
    std::vector<std::uint32_t> position_of_;                     // dwyer: input -> position
    std::size_t next_ = 0, next_end_ = 0;
};

template <bool Alternate>
struct DivideAndConquerAlgorithm {
    template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
    static void run(const K& kernel, const SortedInput& in, const Options&, MeshOutput& out,
                    Result& result) {
        // The recursion permutes its own copy (dwyer); the input_of of each position is
        // permuted along, and the copy's order is the sorted positions' at first.
        std::vector<Point2> points(in.points.begin(), in.points.end());
        std::vector<std::uint32_t> input_of(in.input_of.begin(), in.input_of.end());
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
