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
};

std::string_view to_string(FindingKind kind) noexcept;

struct Finding {
    FindingKind kind;
    std::int64_t index = -1;  ///< half-edge, triangle, hull position or input index (see message)
    std::int64_t other = -1;  ///< a second index where one helps (twin, opposite vertex, ...)
    std::string message;
};

struct Certificate {
    std::vector<Finding> findings;  ///< at most max_findings of them
    std::size_t total_findings = 0;
    bool ok() const noexcept { return total_findings == 0; }
    bool has(FindingKind kind) const noexcept;
    std::string summary() const;  ///< one line per finding, for test output

    static constexpr std::size_t max_findings = 64;
};

/// Certifies `tri` as the Delaunay triangulation of `points` (the same input that was
/// triangulated) with the exact adaptive kernel.
Certificate certify(std::span<const Point2> points, const Triangulation& tri);

}  // namespace exidel::delaunay
