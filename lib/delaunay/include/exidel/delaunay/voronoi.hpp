// exidel: the Voronoi diagram, the dual of a Delaunay triangulation, with exact topology
// and correctly rounded vertices.
//
// Every Voronoi vertex is the centre of a maximal set of cocircular Delaunay triangles,
// decided by the kernel's exact in-circle test (never by a tolerance), and its coordinates
// are the nearest doubles to the exact centre (exidel::circumcenter). Triangles of one
// circle have one exact centre, hence one vertex; and since a correctly rounded value is a
// function of the exact one, only triangles whose rounded centres are bit-identical can
// share a circle: the in-circle test runs on those pairs only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/delaunay/result.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/construct.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay {

/// The arrays of both forms of the diagram (VoronoiDiagram, ClippedVoronoi): vertices,
/// the sites of each vertex and the vertices of each cell as offsets into flat arrays.
struct VoronoiCells {
    std::vector<Point2> vertices;
    std::vector<std::uint32_t> site_offsets{0};  ///< vertices.size() + 1 entries
    std::vector<std::uint32_t> sites;
    std::vector<std::uint32_t> cell_offsets{0};  ///< input size + 1 entries
    std::vector<std::uint32_t> cell_vertices;
    std::vector<std::uint8_t> unbounded;  ///< per input index

    std::size_t vertex_count() const noexcept { return vertices.size(); }
    std::size_t site_count() const noexcept { return cell_offsets.size() - 1; }
    std::span<const std::uint32_t> vertex_sites(std::size_t v) const noexcept {
        return std::span(sites).subspan(site_offsets[v], site_offsets[v + 1] - site_offsets[v]);
    }
    std::span<const std::uint32_t> cell(std::size_t i) const noexcept {
        return std::span(cell_vertices)
            .subspan(cell_offsets[i], cell_offsets[i + 1] - cell_offsets[i]);
    }
};

/// The diagram in compact arrays. "Site i" is input index i; a duplicate input point has
/// its twin's cell (the same vertex list) and is listed beside it among a vertex's sites.
///
///   vertices[v]               correctly rounded centre of vertex v
///   vertex_sites(v)           every input index exactly equidistant from v's exact centre
///                             (three or more distinct points), counter-clockwise around
///                             it, starting at the smallest index; duplicates follow their
///                             twin
///   cell(i)                   vertex indices of site i's cell, counter-clockwise
///   unbounded[i]              whether the cell is unbounded. Then it is closed by two
///                             rays: it is entered from infinity along `entry_ray[i]`
///                             (reversed) into cell(i).front(), and left along
///                             `exit_ray[i]` from cell(i).back(). Each ray is the outward
///                             normal of a hull edge: its direction is the edge's rounded
///                             difference vector turned by 90 degrees, exact in sign (a
///                             difference rounds to a value of its exact sign).
///   collinear                 no triangle: fewer than three distinct sites or all on one
///                             line. No vertices; `chain` lists the distinct sites along
///                             the line, and the cell of chain[k] is the strip (a
///                             half-plane at either end, the whole plane for one site)
///                             between the perpendicular bisectors of chain[k-1], chain[k]
///                             and of chain[k], chain[k+1].
struct VoronoiDiagram : VoronoiCells {
    std::vector<Point2> entry_ray, exit_ray;  ///< per input index; (0, 0) when bounded
    /// The Voronoi vertex of every Delaunay triangle (the dual map).
    std::vector<std::uint32_t> vertex_of_triangle;
    bool collinear = false;
    std::vector<std::uint32_t> chain;

    /// How many circumcentres each stage of exidel::circumcenter decided (indexed by
    /// CircumcenterStage), and how many in-circle tests confirmed a shared circle.
    std::uint64_t stage_counts[3] = {0, 0, 0};
    std::uint64_t cocircular_tests = 0;
    std::uint64_t cocircular_merges = 0;
};

/// A Delaunay triangle whose centre cannot be a vertex: its exact centre is beyond the
/// largest double (a nearly flat triangle of huge coordinates; the diagram cannot be
/// written in doubles), or it is degenerate (only an inexact kernel's triangulation can
/// contain a collinear triangle).
class VoronoiError : public std::runtime_error {
public:
    VoronoiError(std::size_t triangle, CircumcenterStatus status, const std::string& what)
        : std::runtime_error(what), triangle_(triangle), status_(status) {}
    std::size_t triangle() const noexcept { return triangle_; }
    CircumcenterStatus status() const noexcept { return status_; }

private:
    std::size_t triangle_;
    CircumcenterStatus status_;
};

/// An axis-parallel box, xmin < xmax and ymin < ymax, finite.
struct Box {
    double xmin, ymin, xmax, ymax;
};

/// The diagram intersected with a box: every cell a convex polygon (possibly empty).
/// Its vertices are the Voronoi vertices inside the box or on its boundary, in the order
/// of VoronoiDiagram::vertices, followed by the points the box adds (where a Voronoi edge
/// crosses the boundary, and the box's corners), in order of first appearance. Every
/// vertex is the correctly rounded value of an exact point (the clipping is done in
/// exact rationals). A Voronoi vertex lists its sites as in the diagram (every site
/// exactly equidistant, also one whose cell only touches the box at that vertex and is
/// therefore empty after clipping); a point the box adds lists the sites whose clipped
/// cells have it as a corner (with their duplicates), by input index.
/// `unbounded` is as in the unclipped diagram: whether the cell itself is unbounded.
struct ClippedVoronoi : VoronoiCells {
    /// How many of the vertices are Voronoi vertices (the rest the box added).
    std::size_t voronoi_vertex_count = 0;
};

/// `d` (the diagram of `points`, triangulated by `t`) clipped to `box`. Throws
/// std::invalid_argument for a box that is not finite or has no interior.
ClippedVoronoi clip(const VoronoiDiagram& d, std::span<const Point2> points, const Triangulation& t,
                    const Box& box);

namespace detail {

/// The kernel-independent work: circumcentres, the candidate pairs, the groups and the
/// cells. voronoi() below runs the kernel's in-circle test on the candidates between
/// construction and finish().
class VoronoiBuilder {
public:
    /// Computes every circumcentre (on `threads` threads); throws VoronoiError if one is
    /// not a finite point.
    VoronoiBuilder(std::span<const Point2> points, const Triangulation& t, unsigned threads);

    /// Interior half-edges whose two triangles have bit-identical rounded centres (each
    /// pair once): the only ones that can share a circle.
    const std::vector<std::uint32_t>& candidates() const noexcept { return candidates_; }
    /// The four points of the in-circle test for candidate half-edge e: its triangle
    /// (counter-clockwise) and the far vertex of its twin.
    void incircle_query(std::uint32_t e, Point2 q[4]) const noexcept;
    /// Records the answer for half-edge e: the two triangles share their circle.
    void merge(std::uint32_t e) noexcept;

    VoronoiDiagram finish(std::uint64_t tests) &&;

private:
    std::uint32_t find(std::uint32_t t) noexcept;

    std::span<const Point2> points_;
    const Triangulation& t_;
    unsigned threads_;
    std::vector<Circumcenter> centres_;
    std::vector<std::uint32_t> candidates_;
    std::vector<std::uint32_t> parent_;  // union-find over triangles
    std::uint64_t stage_counts_[3] = {0, 0, 0};
    std::uint64_t merges_ = 0;
};

VoronoiDiagram collinear_voronoi(std::span<const Point2> points, const Triangulation& t);

/// Turns the dual of a furthest-site triangulation `t`, built as voronoi() builds the
/// Delaunay one, into the furthest-site diagram (furthest_site_voronoi below).
void to_furthest(VoronoiDiagram& d, std::span<const Point2> points, const Triangulation& t);

}  // namespace detail

/// The Voronoi diagram of `points` from their Delaunay triangulation `t` (a successful
/// triangulate() of the same points). Cocircular triangles are merged by
/// kernel.incircle(...) == 0: exact with an exact kernel; with an inexact one the
/// grouping is that kernel's opinion (the vertices are correctly rounded regardless).
/// The circumcentres and the cells are computed on `threads` threads (the caller's
/// included); the result does not depend on it.
template <PredicateKernel K>
VoronoiDiagram voronoi(std::span<const Point2> points, const Triangulation& t, const K& kernel,
                       unsigned threads = 1) {
    if (t.collinear) return detail::collinear_voronoi(points, t);
    detail::VoronoiBuilder builder(points, t, threads);
    std::uint64_t tests = 0;
    for (const std::uint32_t e : builder.candidates()) {
        Point2 q[4];
        builder.incircle_query(e, q);
        ++tests;
        if (kernel.incircle(q[0], q[1], q[2], q[3]) == Sign::zero) builder.merge(e);
    }
    return std::move(builder).finish(tests);
}

/// The furthest-site Voronoi diagram of `points` from their furthest-site triangulation
/// `t` (furthest_site_triangulation of the same points): the region of a site is where
/// it is the furthest site. Its vertices are the correctly rounded centres of the
/// triangles of `t`, merged where cocircular (kernel.incircle(...) == 0), as voronoi()'s;
/// the sites of a vertex are every site exactly at the largest distance. Only the extreme
/// points (the corners of the convex hull) have regions, each unbounded: cell(i) lists
/// its vertices counter-clockwise, entered from infinity along -entry_ray[i] and left
/// along exit_ray[i], the inward normals of the hull edges at the site (the region lies
/// across the hull from its site). Every other site, a point inside a hull edge
/// included, has an empty region (cell(i) empty, unbounded[i] false). With fewer than
/// three extreme points (collinear): `chain` holds the one or two extreme points (the
/// lexicographically first and last), and the region of each is the half-plane on the
/// other's side of their bisector (the whole plane for one point).
template <PredicateKernel K>
VoronoiDiagram furthest_site_voronoi(std::span<const Point2> points, const Triangulation& t,
                                     const K& kernel, unsigned threads = 1) {
    VoronoiDiagram d = voronoi(points, t, kernel, threads);
    detail::to_furthest(d, points, t);
    return d;
}

}  // namespace exidel::delaunay
