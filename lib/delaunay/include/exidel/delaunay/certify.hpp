// exidel: the certifier. Decides, with exact predicates, whether a Triangulation is the
// Delaunay triangulation of a point set, and says what is wrong and where when it is not.
//
// Checked, in order (later checks need the earlier ones and are skipped when they fail):
//   1. shape      array sizes, index ranges;
//   2. topology   twins are mutual and run the opposite way, no triangle repeats a vertex;
//   3. geometry   every triangle strictly counter-clockwise;
//   4. boundary   the twin-less half-edges form one cycle, equal to `hull`; it turns left
//                 or goes straight at every vertex and winds once, so with 2-3 it is the
//                 convex hull (a map with positive triangles and a boundary winding once
//                 covers its inside exactly once); collinear boundary points are vertices;
//   5. vertices   every distinct input point is a vertex, no two vertices coincide,
//                 vertex_of_input and duplicates agree with the points;
//   6. counting   triangles = 2V - 2 - H (Euler, with H boundary vertices);
//   7. Delaunay   every interior edge is locally Delaunay (the opposite vertex is not
//                 strictly inside the circumcircle), hence the whole triangulation is.
// A result marked `collinear` must have no triangles, all distinct points on one line and
// `hull` the lexicographic chain of them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay {

enum class FindingKind {
    bad_shape,             ///< array sizes do not match
    index_out_of_range,    ///< a vertex or twin index outside its array
    twin_mismatch,         ///< halfedges[halfedges[e]] != e, or the twin is not reversed
    degenerate_triangle,   ///< a triangle repeats a vertex
    not_ccw,               ///< a triangle is not strictly counter-clockwise
    boundary_broken,       ///< the boundary half-edges do not form one simple cycle
    hull_mismatch,         ///< `hull` differs from the boundary cycle
    boundary_not_convex,   ///< a right turn or a reversal on the boundary
    boundary_winding,      ///< the boundary winds more than once
    missing_point,         ///< a distinct input point is not a vertex
    duplicate_vertex,      ///< two vertices at the same coordinates
    bad_vertex_map,        ///< vertex_of_input / duplicates disagree with the points
    wrong_triangle_count,  ///< triangles != 2V - 2 - H
    not_delaunay,          ///< an interior edge is not locally Delaunay
    collinear_mismatch,    ///< the collinear flag disagrees with the points or arrays
    non_finite_input,      ///< the point set itself is not valid input
    // Constrained triangulations (certify_constrained):
    input_mismatch,        ///< the points do not start with the input, or a segment is invalid
    added_point_wrong,     ///< an added point is not the rounded crossing of its two segments
    chain_broken,          ///< a chain does not run end to end, or a piece is not an edge
    chain_off_segment,     ///< a chain vertex neither on its segment nor a crossing of it
    constraints_mismatch,  ///< `constraints` is not the set of the chains' pieces
};

std::string_view to_string(FindingKind kind) noexcept;

/// One defect, located. `message` names what it is about in words and indices
/// ("triangle 18 (4, 9, 2) is clockwise"); the same location is in the fields, for tools.
/// Vertices are input indices; a repeated point is named by its first occurrence.
struct Finding {
    FindingKind kind;
    std::int64_t index = -1;  ///< half-edge, triangle, hull position or input index (see message)
    std::int64_t other = -1;  ///< a second index where one helps (twin, opposite vertex, ...)
    std::string message;
    std::int64_t triangle = -1;        ///< the triangle (its position in `triangles` / 3), or -1
    std::vector<std::int64_t> points;  ///< the input points concerned, in the message's order
};

struct Certificate {
    std::vector<Finding> findings;  ///< the first CertifyOptions::max_findings of them
    std::size_t total_findings = 0;
    bool ok() const noexcept { return total_findings == 0; }
    bool has(FindingKind kind) const noexcept;
    std::string summary() const;  ///< one line per finding, for test output

    static constexpr std::size_t max_findings = 64;  ///< the default of CertifyOptions
};

struct CertifyOptions {
    /// Findings kept with their details (all are counted in total_findings).
    std::size_t max_findings = Certificate::max_findings;
};

/// Certifies `tri` as the Delaunay triangulation of `points` (the same input that was
/// triangulated) with the exact adaptive kernel.
Certificate certify(std::span<const Point2> points, const Triangulation& tri,
                    const CertifyOptions& options = {});

// ---------------------------------------------------------------------------------------
// Another producer's output. Triangulators agree on what a Delaunay triangulation is but
// not on how to write it down: delaunator lists triangles clockwise in y-up coordinates
// and starts its hull anywhere, scipy (qhull) orients each simplex as it comes and keeps
// whichever copy of a repeated point it met, Triangle and CGAL write triangles alone.
// normalize() turns any of these into the layout certify() judges, changing nothing a
// Delaunay triangulation's correctness depends on, and says what it changed.

/// What a producer wrote: the triangles (3 input indices each) and, when it wrote them,
/// twins in delaunator's layout (halfedges[e] the half-edge running opposite to e, -1 on
/// the boundary), the hull cycle, and the input indices that repeat an earlier point.
struct ProducedTriangulation {
    std::vector<std::uint32_t> triangles;
    std::optional<std::vector<std::int32_t>> halfedges;
    std::optional<std::vector<std::uint32_t>> hull;
    std::optional<std::vector<std::uint32_t>> duplicates;
};

/// What normalize() changed (all zero / false: the input was already in exidel's layout).
struct Normalization {
    std::size_t copies_renamed = 0;  ///< vertex entries that named a later copy of a point
    std::size_t reoriented = 0;      ///< clockwise triangles turned counter-clockwise
    bool twins_derived = false;      ///< halfedges were absent and derived from the triangles
    bool hull_derived = false;       ///< the hull was absent and derived from the boundary
    bool hull_reversed = false;      ///< the hull ran clockwise (or the chain backwards)
    bool hull_rotated = false;       ///< the hull started elsewhere than its smallest vertex
    /// One line per change, for a user ("412 clockwise triangles turned counter-clockwise").
    std::vector<std::string> notes() const;
};

/// `produced` in certify()'s layout:
///   - every vertex (triangles, hull) naming a repeated point names its first occurrence;
///   - a clockwise triangle (a, b, c) becomes (a, c, b), triangle by triangle (the
///     orientation of a row is a convention: qhull mixes both); its given twins follow
///     (half-edge k of the old triangle is half-edge 2 - k of the new one), so twins that
///     do not match the triangles are still found. Flat triangles (collinear vertices)
///     are left as they are, for the certifier to report;
///   - absent twins are matched from the triangles (an edge used twice in one direction
///     stays unmatched); an absent hull is the boundary cycle from the lexicographically
///     smallest boundary vertex;
///   - a given hull is reversed when it runs clockwise (at its lexicographically smallest
///     vertex) and rotated to start there; without triangles (collinear input), a chain
///     given backwards is reversed, and an absent one is the distinct points in
///     lexicographic order;
///   - vertex_of_input is derived from the points; duplicates too when not given.
/// Indices out of range are kept for certify() to report. Row t of the triangles stays
/// triangle t, so a finding's triangle is a row of the producer's file.
/// With `strict`, only what is absent is derived (twins, hull, duplicates, the collinear
/// chain) and nothing given is changed: the certifier then holds the file to exidel's
/// own layout.
Triangulation normalize(std::span<const Point2> points, ProducedTriangulation produced,
                        Normalization* what = nullptr, bool strict = false);

}  // namespace exidel::delaunay
