// exidel I/O: writing a triangulation (exidel/delaunay/result.hpp), and reading back the
// JSON form.
//
// Formats. Vertex indices are always input indices (0-based, the position of the point
// in the input; a duplicated point is represented by its first occurrence).
//
//   json  exactly {"triangles": [...], "halfedges": [...], "hull": [...], "duplicates": [...]}
//         one key per line: the arrays of delaunator's layout (triangles counter-clockwise,
//         halfedges -1 for a boundary half-edge, hull counter-clockwise from the
//         lexicographically smallest point; for collinear input no triangles and hull the
//         chain of distinct points) and the input indices that repeat an earlier point.
//   ele   Triangle's .ele: "ntriangles 3 0", then "t v0 v1 v2" per triangle, t from 0 and
//         the vertices 0-based input indices. Pair it with a 0-based .node of the input in
//         input order (write_points with PointFormat::node writes one).
//   off   OFF: "OFF", "nvertices nfaces 0", every input point as "x y 0" (duplicates
//         included, so face indices are input indices), then "3 v0 v1 v2" per triangle.
//   svg   a picture: triangles, the hull drawn thicker, the points as dots; scaled into a
//         viewBox about 1000 units wide with y flipped so that up is up. For looking at,
//         not for reading back (coordinates are rounded to 0.001 of the viewBox).
#pragma once

#include <iosfwd>
#include <optional>
#include <span>
#include <string_view>

#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::io {

enum class TriangulationFormat { json, ele, off, svg };

std::string_view to_string(TriangulationFormat f) noexcept;
/// "json", "ele", "off", "svg"; nullopt for anything else.
std::optional<TriangulationFormat> triangulation_format_from_name(std::string_view name);
/// From the extension of `path` (.json .ele .off .svg); nullopt for any other.
std::optional<TriangulationFormat> triangulation_format_from_path(std::string_view path);

/// Writes `tri`, the triangulation of `points`, in `format`. Only off and svg use the
/// coordinates.
void write_triangulation(std::ostream& out, std::span<const Point2> points,
                         const delaunay::Triangulation& tri, TriangulationFormat format);

/// Parses the json format above (the keys in any order, each exactly once). Fills
/// triangles, halfedges, hull and duplicates; `collinear` is set iff there are no
/// triangles; vertex_of_input is left empty (the points are needed to rebuild it: see
/// fill_vertex_of_input). Throws ReadError ("line N: ...") on anything else.
delaunay::Triangulation parse_triangulation_json(std::string_view text);

/// Rebuilds tri.vertex_of_input (each input index -> its first occurrence) from the
/// points, so a triangulation read back from json can be certified.
void fill_vertex_of_input(std::span<const Point2> points, delaunay::Triangulation& tri);

}  // namespace exidel::io
