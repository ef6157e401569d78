// exidel: the k points nearest a query, and the points within a distance of it, by
// walking the Delaunay triangulation from the nearest point.
//
// Why a walk finds them, in order. Let p be a point that is not nearest to q, at distance
// d. Slide the disk centred at q through p toward p, keeping p on its boundary: the disks
// shrink inside the first one and touch it only at p. At the last moment one of them
// still holds another point s (on its boundary, none strictly inside), ps is an edge of an
// empty circle, so p and s are joined by Delaunay edges through the points on that circle
// (consecutive points on an empty circle are joined by an edge of every Delaunay
// triangulation), every one of them strictly nearer to q than p. So p has a strictly
// nearer Delaunay neighbour. Popping the points from a priority queue in order of their
// distance to q, starting with a nearest point and pushing the neighbours of each popped
// point, therefore pops every point in order of distance: when p is the nearest point not
// yet popped, its strictly nearer neighbour has been popped and has pushed p. (Points tied
// for nearest lie on one empty circle and are reached along it.) The k nearest are the
// first k popped; the points within r are those popped before the first one beyond r.
//
// Exactness. The order is the kernel's compare_distance (exact with an exact kernel; ties
// by input index); "within r" is |p - q| <= r decided exactly, whatever the kernel:
// compare_distance's filter with the second distance r^2 (the filter's proof in
// proofs/bounds.md#compare-distance covers differences that happen to be exact, here r
// and 0), then exact rationals. Points are vertices: a repeated point counts once, by its
// first occurrence. Every search visits each point at most once, so an inexact kernel
// gives some answer (not necessarily sorted) and never loops.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

#include "exidel/delaunay/locate.hpp"

namespace exidel::delaunay {

/// Rows of points: those of query i are vertices[offsets[i]] ... vertices[offsets[i + 1]
/// - 1] (input indices, first occurrences), nearest first.
struct NeighborRows {
    std::vector<std::size_t> offsets;
    std::vector<std::uint32_t> vertices;
};

/// The min(k, number of distinct points) points nearest each query, nearest first (ties
/// by input index). Failures as Locator::nearest's (a non-finite query first).
template <PredicateKernel K>
std::optional<Failure> nearest_k(const Locator<K>& locator, std::span<const Point2> queries,
                                 std::size_t k, NeighborRows& out,
                                 const LocateOptions& options = {});

/// Every point p with |p - q| <= radius (exactly) for each query q, nearest first (ties by
/// input index). std::invalid_argument for a radius that is negative or not finite;
/// failures as above.
template <PredicateKernel K>
std::optional<Failure> within_radius(const Locator<K>& locator, std::span<const Point2> queries,
                                     double radius, NeighborRows& out,
                                     const LocateOptions& options = {});

namespace detail {

/// sign(|p - q|^2 - r^2), exactly, for finite coordinates and r >= 0 (src/neighbors.cpp).
Sign compare_to_radius(Point2 q, Point2 p, double r);

/// A set of local vertices: a short list, a hash set once it grows.
class VisitedSet {
public:
    void clear() {
        list_.clear();
        set_.clear();
    }
    /// Inserts v; false when it was there.
    bool insert(std::uint32_t v) {
        if (list_.size() < small) {
            if (std::find(list_.begin(), list_.end(), v) != list_.end()) return false;
            list_.push_back(v);
            return true;
        }
        if (set_.empty()) set_.insert(list_.begin(), list_.end());
        return set_.insert(v).second;
    }

private:
    static constexpr std::size_t small = 64;
    std::vector<std::uint32_t> list_;
    std::unordered_set<std::uint32_t> set_;
};

/// The best-first search (the top of the file) from input vertex `seed`: calls
/// take(input index) for each point in order of distance to q (ties by input index) while
/// it returns true. The search runs on the Locator's local vertices (their coordinates
/// in its Hilbert layout: neighbours are near in memory, where input indices would be
/// anywhere); for collinear points, on input indices along the chain (`position`: input
/// index -> place in Triangulation::hull).
template <PredicateKernel K, class Take>
void best_first(const Locator<K>& locator, const LocalMesh& m,
                std::span<const std::uint32_t> position, Point2 q, std::uint32_t seed,
                std::vector<std::uint32_t>& heap, std::vector<std::uint32_t>& group,
                VisitedSet& visited, Take&& take) {
    const Triangulation& t = locator.triangulation();
    const bool chain = t.collinear;
    const std::span<const Point2> points = chain ? locator.points() : m.points;
    const auto input = [&](std::uint32_t v) { return chain ? v : m.input_of_local[v]; };
    // Vertices in a heap whose top is the nearest (ties by vertex number: a group of
    // equally near points is sorted by input index below anyway).
    const auto farther = [&](std::uint32_t a, std::uint32_t b) {
        const Sign s = locator.kernel().compare_distance(q, points[a], points[b]);
        return s == Sign::positive || (s == Sign::zero && a > b);
    };
    heap.clear();
    visited.clear();
    group.clear();
    const std::uint32_t start = chain ? seed : m.local_of_input[seed];
    heap.push_back(start);
    visited.insert(start);
    const auto push = [&](std::uint32_t v) {
        if (!visited.insert(v)) return;
        heap.push_back(v);
        std::push_heap(heap.begin(), heap.end(), farther);
    };
    // Points at one distance are popped together (each is reached before any farther one
    // is popped) but in the order they were reached: each such group is given to `take`
    // sorted by input index once it is complete.
    const auto flush = [&] {
        for (std::uint32_t& v : group) v = input(v);
        std::sort(group.begin(), group.end());
        for (const std::uint32_t v : group)
            if (!take(v)) return false;
        group.clear();
        return true;
    };
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), farther);
        const std::uint32_t v = heap.back();
        heap.pop_back();
        if (!group.empty() &&
            locator.kernel().compare_distance(q, points[v], points[group.front()]) != Sign::zero &&
            !flush())
            return;
        group.push_back(v);
        if (chain) {
            const std::size_t i = position[v];
            if (i > 0) push(t.hull[i - 1]);
            if (i + 1 < t.hull.size()) push(t.hull[i + 1]);
            continue;
        }
        const auto first = static_cast<std::size_t>(m.vertex_edge[v]);
        std::size_t e = first;
        do {  // every triangle around v, counter-clockwise
            push(m.triangles[next_halfedge(e)]);
            push(m.triangles[prev_halfedge(e)]);
            const std::int32_t twin = m.halfedges[prev_halfedge(e)];
            if (twin < 0) break;
            e = static_cast<std::size_t>(twin);
        } while (e != first);
    }
    flush();
}

/// Seeds every query with its nearest point, then runs the search with take(i, v) per
/// popped point v of query i, in chunks of 4096 queries on the options' threads; rows
/// are assembled in query order.
template <PredicateKernel K, class Take>
std::optional<Failure> neighbor_rows(const Locator<K>& locator, std::span<const Point2> queries,
                                     NeighborRows& out, const LocateOptions& options, Take&& take) {
    const std::size_t n = queries.size();
    std::vector<std::uint32_t> seed(n);
    if (auto failure = locator.nearest(queries, seed, options)) return failure;
    const Triangulation& t = locator.triangulation();
    std::vector<std::uint32_t> position;
    if (t.collinear) {
        position.assign(locator.points().size(), 0);
        for (std::size_t i = 0; i < t.hull.size(); ++i)
            position[t.hull[i]] = static_cast<std::uint32_t>(i);
    }
    const LocalMesh m = locator.local_mesh();
    constexpr std::size_t chunk = 4096;
    const std::size_t chunks = (n + chunk - 1) / chunk;
    std::vector<std::vector<std::uint32_t>> found(chunks);
    std::vector<std::size_t> counts(n, 0);
    parallel_for(chunks, options.threads, [&](std::size_t c) {
        std::vector<std::uint32_t> heap, group;
        VisitedSet visited;
        for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i) {
            if (seed[i] == no_vertex) continue;
            const std::size_t before = found[c].size();
            best_first(locator, m, position, queries[i], seed[i], heap, group, visited,
                       [&](std::uint32_t v) {
                           if (!take(i, v, found[c].size() - before)) return false;
                           found[c].push_back(v);
                           return true;
                       });
            counts[i] = found[c].size() - before;
        }
    });
    out.offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) out.offsets[i + 1] = out.offsets[i] + counts[i];
    out.vertices.clear();
    out.vertices.reserve(out.offsets[n]);
    for (auto& rows : found) out.vertices.insert(out.vertices.end(), rows.begin(), rows.end());
    return std::nullopt;
}

}  // namespace detail

template <PredicateKernel K>
std::optional<Failure> nearest_k(const Locator<K>& locator, std::span<const Point2> queries,
                                 std::size_t k, NeighborRows& out, const LocateOptions& options) {
    return detail::neighbor_rows(
        locator, queries, out, options,
        [k](std::size_t, std::uint32_t, std::size_t taken) { return taken < k; });
}

template <PredicateKernel K>
std::optional<Failure> within_radius(const Locator<K>& locator, std::span<const Point2> queries,
                                     double radius, NeighborRows& out,
                                     const LocateOptions& options) {
    if (!(radius >= 0) || !std::isfinite(radius)) {
        throw std::invalid_argument(
            "within_radius: the radius must be finite and not negative, "
            "got " +
            std::to_string(radius));
    }
    const auto points = locator.points();
    return detail::neighbor_rows(
        locator, queries, out, options, [&](std::size_t i, std::uint32_t v, std::size_t) {
            return detail::compare_to_radius(queries[i], points[v], radius) != Sign::positive;
        });
}

}  // namespace exidel::delaunay
