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
//   off   OFF: "OFF", "nvertices nfaces 0", every input point as "x y z" (z from
//         WriteOptions::z, else 0; duplicates included, so face indices are input
//         indices), then "3 v0 v1 v2" per triangle.
//   svg   a picture in the data's own coordinates: the viewBox is the points' bounding
//         box in input units (x = min x, y = -max y, width and height the box's sides;
//         padded only where a side is zero: that side as long as the other, or one unit
//         around a single point), and a <g transform="scale(1,-1)"> flips y so that up is
//         up and the coordinates are written as they are, each the shortest decimal that
//         reads back as the same double: a GIS or a browser can overlay the picture on
//         other data. width and height attributes put the larger side at 1000 pixels,
//         and stroke widths are pixels of that picture in data units (a 2-pixel line is
//         2/1000 of the larger side), so that lines and dots look the same at any scale
//         of the data (vector-effect="non-scaling-stroke" would do it for a zooming
//         viewer, but librsvg before 2.56 ignores it). The triangles as the hull's fill
//         and every edge once (in trails: about one vertex written per edge, half of what
//         writing each triangle's corners costs), the hull drawn thicker, the points as
//         dots (zero-length round-capped subpaths). Paths hold at most svg_path_items
//         edges (hull vertices, points) each, about 40 kB of attribute: XML parsers cap an
//         attribute's length (libxml2, under librsvg, at 10 MB), which one path of every
//         edge passes near 10^5 points; librsvg 2.54 also stopped reading ("Premature
//         end of data") some files of 120 kB attributes; and librsvg refuses more than
//         10^6 elements, which one element per point passes at 10^6 points.
//   geojson  RFC 7946: a FeatureCollection, one Feature per line. Feature t (t from 0) is
//         triangle t: a Polygon whose one ring is the triangle counter-clockwise and
//         closed (first position repeated last), properties {"triangle": t, "vertices":
//         [i, j, k]} (input indices). After the triangles, one Feature for the hull:
//         properties {"hull": true, "vertices": [hull indices]}, geometry the hull's
//         Polygon (counter-clockwise); for input without triangles the chain of its
//         distinct points as a LineString, or a Point for one distinct point, and no
//         hull Feature (an empty FeatureCollection) for no points. Positions are [x, y],
//         or [x, y, z] with WriteOptions::z; numbers are the shortest decimals that read
//         back as the same doubles (negative zero "-0.0").
//   wkt   one MULTIPOLYGON of every triangle, one per line, polygon t being triangle t
//         (counter-clockwise, closed): "MULTIPOLYGON (((x y, x y, x y, x y)),\n((...)))";
//         "MULTIPOLYGON Z" with "x y z" positions when WriteOptions::z is given;
//         "MULTIPOLYGON EMPTY" ("MULTIPOLYGON Z EMPTY") when there are no triangles.
//   ply   PLY, binary_little_endian 1.0 (ply) or ascii 1.0 (ply-ascii): "element vertex
//         n" with "property double x", "y", "z" (z from WriteOptions::z, else 0), every
//         input point in input order (duplicates included, so face indices are input
//         indices), then "element face" with "property list uchar int vertex_indices",
//         one face of three per triangle, counter-clockwise.
//   poly  Triangle's .poly: every input point as a vertex (as a .node, numbered from
//         WriteOptions::index_base), the hull's edges as segments (for collinear input the
//         chain of its distinct points), no holes and no regions: what Triangle writes for
//         a triangulation of points (exidel/io/constrained.hpp for constraints).
//
// Coordinates in json-like and text formats (off, geojson, wkt, ply-ascii) are the
// shortest decimals that read back as the same doubles (std::to_chars), never rounded.
// Longitude and latitude are triangulated as a plane: there is no handling of the
// antimeridian or the poles.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <span>
#include <string_view>

#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::io {

enum class TriangulationFormat { json, ele, off, svg, geojson, wkt, ply, ply_ascii, poly };

std::string_view to_string(TriangulationFormat f) noexcept;
/// "json", "ele", "off", "svg", "geojson", "wkt", "ply", "ply-ascii", "poly"; nullopt for
/// anything else.
std::optional<TriangulationFormat> triangulation_format_from_name(std::string_view name);
/// From the extension of `path` (.json .ele .off .svg .geojson .wkt .ply .poly, .ply being
/// binary PLY); nullopt for any other.
std::optional<TriangulationFormat> triangulation_format_from_path(std::string_view path);

struct WriteOptions {
    unsigned index_base = 0;  // ele: the number of the first vertex and triangle (0 or 1)
    /// json, ele, geojson, wkt: threads that format parts of the file at once (the text
    /// is the same for every count).
    unsigned threads = 1;
    /// off, geojson, wkt, ply: a z value per point (PointFile::z), or empty for none.
    std::span<const double> z{};
};

/// Edges (hull vertices, points) per SVG path element: about 40 kB of attribute each.
inline constexpr std::size_t svg_path_items = 1000;

/// Writes `tri`, the triangulation of `points`, in `format`. json and ele do not use the
/// coordinates. Throws std::invalid_argument when options.z is neither empty nor of
/// points.size() values.
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
