// exidel: Sibson's natural neighbour coordinates and interpolation over a Delaunay
// triangulation.
//
// The natural neighbour coordinates of a query q (Sibson, "A brief description of natural
// neighbour interpolation", 1981) are the shares of q's Voronoi cell, were q inserted,
// taken from each site's old cell. Inserting q into the Delaunay triangulation removes
// the triangles whose circumcircles hold q strictly (Bowyer and Watson's cavity: a
// connected union of triangles, star-shaped from q, with no vertex inside) and joins q to
// the cavity's boundary v_0 ... v_{k-1} (counter-clockwise). The area taken from v_j's cell
// is the convex polygon bounded by the bisector of q and v_j and by v_j's old cell: its
// corners are the new Voronoi vertices c(q, v_{j-1}, v_j) and c(q, v_j, v_{j+1}) (the
// circumcentres of the new triangles) and between them the old Voronoi vertices, the
// circumcentres of the cavity triangles around v_j in turn. The weight of v_j is its area
// over the sum of the areas.
//
// What is exact. The cavity is decided by the kernel's incircle (strictly inside: a
// triangle whose circle passes through q gives up nothing, its circumcentre is q's new
// Voronoi vertex), the location by its orient2d, so with an exact kernel the set of
// natural neighbours is exact. Where q is on a vertex, that vertex has weight 1; on a
// hull edge (or a segment of collinear points), the limit of the coordinates from inside
// is the linear interpolation between the edge's two ends, which is what is given;
// outside the hull there are no coordinates.
//
// The arithmetic of the areas (NaturalArithmetic):
//   rounded  doubles, every coordinate taken relative to q (so that the areas, small
//            beside the coordinates, are not differences of large numbers); weights are
//            area / sum, and a value is sum_j w_j f_j. No error bound is proven: a
//            circumcentre of a thin triangle is far away and its rounding error large.
//            The arithmetic falls back to `exact` for a query where a rounded
//            determinant is not positive, an area is negative, or a result is not finite,
//            so rounded weights are never negative and never NaN.
//   exact    exact rationals (Boost.Multiprecision over GMP): each weight is the double
//            nearest to the exact weight, and each interpolated value the double nearest
//            to the exact sum_j w_j f_j of the given values (not a sum of rounded terms).
//            About 200 times slower (docs/benchmarks.md#natural-neighbour-interpolation).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "exidel/delaunay/locate.hpp"

namespace exidel::delaunay {

enum class NaturalArithmetic : std::uint8_t {
    rounded,  ///< doubles relative to the query, exact where they cannot decide
    exact,    ///< exact rationals: weights and values correctly rounded
};

struct NaturalOptions {
    LocateOptions locate{};  ///< how the queries are located (order, threads, step bound)
    NaturalArithmetic arithmetic = NaturalArithmetic::rounded;
};

/// The coordinates of a batch of queries, row by row: those of query i are
/// vertices[offsets[i]] ... vertices[offsets[i + 1] - 1] (input indices, first
/// occurrences of repeated points), with weights alike; none outside the hull.
struct NaturalCoordinates {
    std::vector<std::size_t> offsets;
    std::vector<std::uint32_t> vertices;
    std::vector<double> weights;
};

/// The natural neighbour coordinates of every query, located by `locator` (with its
/// kernel; exact kernels give the exact neighbours). Returns the first failure: a
/// non-finite query (checked first), or an inexact kernel contradicting itself (a walk
/// that does not end, a cavity that is not a disk); `out` is then unspecified.
template <PredicateKernel K>
std::optional<Failure> natural_coordinates(const Locator<K>& locator,
                                           std::span<const Point2> queries, NaturalCoordinates& out,
                                           const NaturalOptions& options = {});

/// Sibson's interpolant of `values` at every query: values has `columns` doubles per input
/// point (point i's at values[i * columns + c]; a repeated point's are its first
/// occurrence's), out gets `columns` per query, `fill` outside the hull. Failures as above;
/// std::invalid_argument when the sizes do not match.
template <PredicateKernel K>
std::optional<Failure> interpolate_natural(const Locator<K>& locator,
                                           std::span<const double> values, std::size_t columns,
                                           std::span<const Point2> queries, std::span<double> out,
                                           double fill, const NaturalOptions& options = {});

namespace detail {

/// One query's cavity in a Locator's local mesh, and the space to find it (reused).
struct NaturalCavity {
    std::vector<std::uint32_t> triangles;  // local triangles whose circles hold q strictly
    std::vector<std::uint32_t> stack;
    std::unordered_map<std::uint32_t, std::uint32_t> slot_of;  // when the cavity is large
    // The boundary, counter-clockwise: boundary[j] is the local half-edge v_j -> v_{j+1}
    // of a cavity triangle; fan[fan_start[j]] ... fan[fan_start[j + 1] - 1] are the
    // positions in `triangles` of the cavity triangles around v_{j+1}, clockwise from the
    // one holding boundary[j] to the one holding boundary[j + 1].
    std::vector<std::uint32_t> boundary;
    std::vector<std::uint32_t> fan;
    std::vector<std::uint32_t> fan_start;
    // The rounded arithmetic's work space (src/natural.cpp).
    std::vector<Point2> rounded_fresh, rounded_old;
    std::vector<double> rounded_areas;

    static constexpr std::size_t small = 48;  // linear search below this many triangles

    /// Position of local triangle t in `triangles`, or -1.
    std::int64_t slot(std::uint32_t t) const {
        if (triangles.size() <= small) {
            for (std::size_t i = 0; i < triangles.size(); ++i)
                if (triangles[i] == t) return static_cast<std::int64_t>(i);
            return -1;
        }
        const auto it = slot_of.find(t);
        return it == slot_of.end() ? -1 : static_cast<std::int64_t>(it->second);
    }
    void add(std::uint32_t t) {
        triangles.push_back(t);
        if (triangles.size() == small + 1) {
            slot_of.clear();
            for (std::size_t i = 0; i < triangles.size(); ++i)
                slot_of.emplace(triangles[i], static_cast<std::uint32_t>(i));
        } else if (triangles.size() > small + 1) {
            slot_of.emplace(t, static_cast<std::uint32_t>(triangles.size() - 1));
        }
    }
};

/// Finds the cavity of q from local triangle `start` (one holding q, neither on a vertex nor
/// on a hull edge): false when the kernel contradicts itself (start not in conflict, or a
/// cavity that is not a disk), which an exact kernel never does.
template <PredicateKernel K>
bool natural_cavity(const K& k, const LocalMesh& mesh, Point2 q, std::uint32_t start,
                    NaturalCavity& c) {
    const auto& T = mesh.triangles;
    const auto& H = mesh.halfedges;
    const auto& P = mesh.points;
    const auto conflict = [&](std::uint32_t t) {
        return k.incircle(P[T[3 * t]], P[T[3 * t + 1]], P[T[3 * t + 2]], q) == Sign::positive;
    };
    c.triangles.clear();
    c.stack.clear();
    c.boundary.clear();
    c.fan.clear();
    c.fan_start.clear();
    if (!conflict(start)) return false;
    c.add(start);
    c.stack.push_back(start);
    while (!c.stack.empty()) {
        const std::uint32_t t = c.stack.back();
        c.stack.pop_back();
        for (std::uint32_t j = 0; j < 3; ++j) {
            const std::int32_t twin = H[3 * t + j];
            if (twin < 0) continue;
            const auto u = static_cast<std::uint32_t>(twin) / 3;
            if (c.slot(u) >= 0 || !conflict(u)) continue;
            c.add(u);
            c.stack.push_back(u);
        }
    }
    // The boundary cycle. A cavity with m triangles and no vertex inside (none can be:
    // its circles would hold it) is a disk bounded by m + 2 edges; anything else is a
    // kernel contradicting itself.
    const auto on_boundary = [&](std::size_t e) {
        return H[e] < 0 || c.slot(static_cast<std::uint32_t>(H[e]) / 3) < 0;
    };
    std::size_t first = SIZE_MAX;
    for (std::size_t i = 0; i < c.triangles.size() && first == SIZE_MAX; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
            if (on_boundary(3 * std::size_t{c.triangles[i]} + j)) {
                first = 3 * std::size_t{c.triangles[i]} + j;
                break;
            }
        }
    }
    if (first == SIZE_MAX) return false;
    const std::size_t edges = c.triangles.size() + 2;
    std::size_t e = first;
    do {
        if (c.boundary.size() == edges) return false;
        c.boundary.push_back(static_cast<std::uint32_t>(e));
        c.fan_start.push_back(static_cast<std::uint32_t>(c.fan.size()));
        c.fan.push_back(static_cast<std::uint32_t>(c.slot(static_cast<std::uint32_t>(e / 3))));
        std::size_t g = next_halfedge(e);  // out of v_{j+1}; turn clockwise round it
        for (std::size_t steps = 0; !on_boundary(g); ++steps) {
            if (steps > c.triangles.size()) return false;
            g = next_halfedge(static_cast<std::size_t>(H[g]));
            c.fan.push_back(static_cast<std::uint32_t>(c.slot(static_cast<std::uint32_t>(g / 3))));
        }
        e = g;
    } while (e != first);
    c.fan_start.push_back(static_cast<std::uint32_t>(c.fan.size()));
    return c.boundary.size() == edges;
}

/// Sibson's weights of the cavity's boundary vertices v_1, v_2, ..., v_0 (the ends of
/// boundary[0], boundary[1], ...), and, with `columns` > 0, the interpolated values
/// (values by input index, `columns` per point) into out. Rounded arithmetic falls back to
/// exact where it cannot decide (natural.hpp's top). False when even the exact arithmetic
/// finds the cavity not star-shaped from q (a kernel contradicting itself). In
/// src/natural.cpp.
bool sibson(const LocalMesh& mesh, Point2 q, NaturalCavity& c, NaturalArithmetic arithmetic,
            std::vector<double>& weights, std::span<const double> values, std::size_t columns,
            double* out);

/// The two weights of q on the segment a b (the limit of Sibson's coordinates on a hull
/// edge: linear along it), and the values likewise, in the given arithmetic.
void along_segment(Point2 a, Point2 b, Point2 q, NaturalArithmetic arithmetic, double weights[2],
                   const double* va, const double* vb, std::size_t columns, double* out);

/// One query at `where`: its coordinates appended to vertices and weights, its values (when
/// columns > 0) into out. False when the kernel contradicts itself.
template <PredicateKernel K>
bool natural_at(const Locator<K>& locator, const LocalMesh& mesh, Point2 q, const Location& where,
                NaturalArithmetic arithmetic, NaturalCavity& c,
                std::vector<std::uint32_t>& vertices, std::vector<double>& weights,
                std::span<const double> values, std::size_t columns, double* out, double fill) {
    const Triangulation& t = locator.triangulation();
    const auto segment = [&](std::uint32_t a, std::uint32_t b) {
        double w[2];
        const auto points = locator.points();
        const double* va = columns ? values.data() + std::size_t{a} * columns : nullptr;
        const double* vb = columns ? values.data() + std::size_t{b} * columns : nullptr;
        along_segment(points[a], points[b], q, arithmetic, w, va, vb, columns, out);
        vertices.push_back(a), weights.push_back(w[0]);
        vertices.push_back(b), weights.push_back(w[1]);
    };
    switch (where.kind) {
        case LocationKind::outside:
            for (std::size_t j = 0; j < columns; ++j) out[j] = fill;
            return true;
        case LocationKind::on_vertex:
            vertices.push_back(where.vertex), weights.push_back(1.0);
            for (std::size_t j = 0; j < columns; ++j)
                out[j] = values[std::size_t{where.vertex} * columns + j];
            return true;
        case LocationKind::on_edge: {
            const auto e = static_cast<std::size_t>(where.edge);
            if (t.collinear) {
                segment(t.hull[e], t.hull[e + 1]);
                return true;
            }
            if (t.halfedges[e] < 0) {
                segment(t.triangles[e], t.triangles[next_halfedge(e)]);
                return true;
            }
            break;
        }
        case LocationKind::inside: break;
    }
    const std::uint32_t start = mesh.local_of_triangle[static_cast<std::uint32_t>(where.triangle)];
    if (!natural_cavity(locator.kernel(), mesh, q, start, c)) return false;
    if (!sibson(mesh, q, c, arithmetic, weights, values, columns, out)) return false;
    for (const std::uint32_t e : c.boundary)
        vertices.push_back(mesh.input_of_local[mesh.triangles[next_halfedge(e)]]);
    return true;
}

/// Locates the queries, then runs job(i, k, where_i, cavity, vertices, weights) for each
/// query i, k its chunk, in
/// chunks of 4096 on the options' threads (`done(chunk, vertices, weights)` after a
/// chunk). With LocateOrder::hilbert the queries are taken along a Hilbert curve (the
/// cavities of consecutive queries then share the mesh's cache lines): chunk k holds the
/// k-th 4096 queries of that order, and job is called with each one's own index.
template <PredicateKernel K, class Job, class Done>
std::optional<Failure> natural_batch(const Locator<K>& locator, std::span<const Point2> queries,
                                     const NaturalOptions& options, Job&& job, Done&& done) {
    const std::size_t n = queries.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (!finite(queries[i])) return non_finite_query(i);
    }
    std::vector<std::uint32_t> order;
    std::vector<Point2> gathered;
    LocateOptions locate = options.locate;
    if (locate.order == LocateOrder::hilbert) {
        const FreshVector<KeyIndex> sorted = hilbert_sorted(queries);
        order.resize(n);
        gathered.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            order[i] = sorted[i].index;
            gathered[i] = queries[order[i]];
        }
        locate.order = LocateOrder::given;
    }
    std::vector<Location> where(n);
    const std::span<const Point2> walked = order.empty() ? queries : gathered;
    if (auto failure = locator.locate(walked, where, locate)) {
        if (!order.empty() && failure->input_index < n) {  // the walk's number -> the query's
            const std::string walked_name = "query " + std::to_string(failure->input_index);
            failure->input_index = order[failure->input_index];
            const auto at = failure->message.find(walked_name);
            if (at != std::string::npos) {
                failure->message.replace(at, walked_name.size(),
                                         "query " + std::to_string(failure->input_index));
            }
        }
        return failure;
    }
    constexpr std::size_t chunk = 4096;
    const std::size_t chunks = (n + chunk - 1) / chunk;
    try {
        parallel_for(chunks, options.locate.threads, [&](std::size_t k) {
            NaturalCavity cavity;
            std::vector<std::uint32_t> vertices;
            std::vector<double> weights;
            for (std::size_t s = k * chunk; s < std::min(n, (k + 1) * chunk); ++s) {
                const std::size_t i = order.empty() ? s : order[s];
                if (!job(i, k, where[s], cavity, vertices, weights)) {
                    throw FailureError(
                        Failure{FailureKind::location_inconsistent, i, no_index,
                                "the natural neighbour cavity of query " + std::to_string(i) +
                                    " is not a disk: the kernel contradicts itself"});
                }
            }
            done(k, vertices, weights);
        });
    } catch (FailureError& e) {
        return std::move(e.failure);
    }
    return std::nullopt;
}

}  // namespace detail

template <PredicateKernel K>
std::optional<Failure> natural_coordinates(const Locator<K>& locator,
                                           std::span<const Point2> queries, NaturalCoordinates& out,
                                           const NaturalOptions& options) {
    const detail::LocalMesh mesh = locator.local_mesh();
    const std::size_t n = queries.size();
    constexpr std::size_t chunk = 4096;
    // Where each query's coordinates are in its chunk's lists (chunks follow the walk
    // order, not the queries').
    std::vector<std::size_t> counts(n, 0), begin(n, 0);
    std::vector<std::uint32_t> chunk_of(n, 0);
    std::vector<std::vector<std::uint32_t>> chunk_vertices((n + chunk - 1) / chunk);
    std::vector<std::vector<double>> chunk_weights(chunk_vertices.size());
    auto failure = detail::natural_batch(
        locator, queries, options,
        [&](std::size_t i, std::size_t k, const Location& where, detail::NaturalCavity& c,
            std::vector<std::uint32_t>& vertices, std::vector<double>& weights) {
            chunk_of[i] = static_cast<std::uint32_t>(k);
            begin[i] = vertices.size();
            const bool ok = detail::natural_at(locator, mesh, queries[i], where, options.arithmetic,
                                               c, vertices, weights, {}, 0, nullptr, 0.0);
            counts[i] = vertices.size() - begin[i];
            return ok;
        },
        [&](std::size_t k, std::vector<std::uint32_t>& vertices, std::vector<double>& weights) {
            chunk_vertices[k] = std::move(vertices);
            chunk_weights[k] = std::move(weights);
        });
    if (failure) return failure;
    out.offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) out.offsets[i + 1] = out.offsets[i] + counts[i];
    out.vertices.resize(out.offsets[n]);
    out.weights.resize(out.offsets[n]);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = chunk_of[i];
        std::copy_n(chunk_vertices[k].begin() + static_cast<std::ptrdiff_t>(begin[i]), counts[i],
                    out.vertices.begin() + static_cast<std::ptrdiff_t>(out.offsets[i]));
        std::copy_n(chunk_weights[k].begin() + static_cast<std::ptrdiff_t>(begin[i]), counts[i],
                    out.weights.begin() + static_cast<std::ptrdiff_t>(out.offsets[i]));
    }
    return std::nullopt;
}

template <PredicateKernel K>
std::optional<Failure> interpolate_natural(const Locator<K>& locator,
                                           std::span<const double> values, std::size_t columns,
                                           std::span<const Point2> queries, std::span<double> out,
                                           double fill, const NaturalOptions& options) {
    if (columns == 0 || values.size() != locator.points().size() * columns ||
        out.size() != queries.size() * columns) {
        throw std::invalid_argument("interpolate_natural: " + std::to_string(values.size()) +
                                    " values for " + std::to_string(locator.points().size()) +
                                    " points and " + std::to_string(columns) +
                                    " columns, room for " + std::to_string(out.size()) + " for " +
                                    std::to_string(queries.size()) + " queries");
    }
    const detail::LocalMesh mesh = locator.local_mesh();
    return detail::natural_batch(
        locator, queries, options,
        [&](std::size_t i, std::size_t, const Location& where, detail::NaturalCavity& c,
            std::vector<std::uint32_t>& vertices, std::vector<double>& weights) {
            vertices.clear();
            weights.clear();
            return detail::natural_at(locator, mesh, queries[i], where, options.arithmetic, c,
                                      vertices, weights, values, columns, out.data() + i * columns,
                                      fill);
        },
        [](std::size_t, std::vector<std::uint32_t>&, std::vector<double>&) {});
}

}  // namespace exidel::delaunay
