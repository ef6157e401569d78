// exidel I/O: writing a triangulation (exidel/delaunay/result.hpp), and reading back the
// JSON form (other producers' output, for the certifier: exidel/io/triangulation_input.hpp).
//
// Formats. Vertex indices are always input indices (0-based, the position of the point
// in the input; a duplicated point is represented by its first occurrence).
//
//   json  exactly {"triangles": [...], "halfedges": [...], "hull": [...], "duplicates": [...]}
//         one key per line: the arrays of delaunator's layout (triangles counter-clockwise,
//         halfedges -1 for a boundary half-edge, hull counter-clockwise from the
//         lexicographically smallest point; for collinear input no triangles and hull the
//         chain of distinct points) and the input indices that repeat an earlier point.
//   ele   Triangle's .ele: "ntriangles 3 0", then "t v0 v1 v2" per triangle, t and the
//         vertices (input indices) counted from WriteOptions::index_base, 0 or 1: the
//         base of the .node the points came from, so the pair stays consistent. Pair it
//         with a .node of the input in input order (write_points with PointFormat::node
//         and the same base writes one).
//   off   OFF: "OFF", "nvertices nfaces 0", every input point as "x y 0" (duplicates
//         included, so face indices are input indices), then "3 v0 v1 v2" per triangle.
//   svg   a picture: triangles, the hull drawn thicker, the points as dots; scaled into a
//         viewBox about 1000 units wide with y flipped so that up is up. For looking at,
//         not for reading back (coordinates are rounded to 0.001 of the viewBox). Paths
//         hold at most svg_path_items triangles (hull vertices, points) each: XML parsers
//         cap an attribute's length (libxml2, under librsvg, at 10 MB), which one path of
//         every triangle passes near 10^5 points, and librsvg refuses more than 10^6
//         elements, which one element per point passes at 10^6 points.
#pragma once

#include <cstddef>
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

struct WriteOptions {
    unsigned index_base = 0;  // ele: the number of the first vertex and triangle (0 or 1)
    /// json: threads that format parts of the arrays at once (the text is the same).
    unsigned threads = 1;
};

/// Triangles (or hull vertices) per SVG path element: about 40 kB of attribute each.
inline constexpr std::size_t svg_path_items = 1000;

/// Writes `tri`, the triangulation of `points`, in `format`. Only off and svg use the
/// coordinates.
void write_triangulation(std::ostream& out, std::span<const Point2> points,
                         const delaunay::Triangulation& tri, TriangulationFormat format,
                         const WriteOptions& options = {});

/// Parses the json format above (the keys in any order, each exactly once). Fills
/// triangles, halfedges, hull and duplicates; `collinear` is set iff there are no
/// triangles; vertex_of_input is left empty (the points are needed to rebuild it: see
/// fill_vertex_of_input). Throws ReadError ("line N: ...") on anything else.
delaunay::Triangulation parse_triangulation_json(std::string_view text);

/// Rebuilds tri.vertex_of_input (each input index -> its first occurrence) from the
/// points, so a triangulation read back from json can be certified.
void fill_vertex_of_input(std::span<const Point2> points, delaunay::Triangulation& tri);

}  // namespace exidel::io
