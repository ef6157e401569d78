// exidel I/O: reading what a triangulator wrote, for the certifier. The result is a
// delaunay::ProducedTriangulation: the triangles as written (input indices), and the
// twins, hull and duplicates when the file holds them; delaunay::normalize then puts it
// in the certifier's layout (exidel/delaunay/certify.hpp).
//
// Formats (chosen explicitly, or from the extension: .json .ele .off; simplices has no
// extension of its own):
//   json       an object, delaunator's arrays as exidel triangulate writes them:
//              {"triangles": [...], "halfedges": [...], "hull": [...], "duplicates": [...]}
//              with only "triangles" required; "coords" (delaunator's flat
//              [x0, y0, x1, y1, ...]) may be present and must equal the points.
//              Or an array of rows [[i, j, k], ...]: scipy's simplices.tolist().
//   ele        Triangle's .ele: "ntriangles 3 [attributes]", then "t v0 v1 v2
//              [attributes]"; vertices counted from the first triangle's number (0 or 1,
//              as Triangle numbers its .node and .ele alike).
//   off        OFF as CGAL writes a triangulation (and as exidel triangulate does):
//              "OFF", "nvertices nfaces nedges", vertex lines "x y [z]", face lines
//              "3 a b c [colour...]". Vertices are matched to the points by their exact
//              coordinates (z is ignored), so vertices need not be in input order; a
//              vertex that is not an input point is an error naming its line (write the
//              OFF with 17 significant digits so coordinates read back exactly).
//   simplices  text, one triangle per line: three vertex indices separated by blanks
//              or a comma (numpy.savetxt of scipy's simplices; its default "%.18e"
//              floats are accepted when they are whole numbers); '#' comments.
// Every index must be a whole number in [0, 2^32); in json and simplices, whether it
// names a point is the certifier's to say (index_out_of_range); an .ele vertex must name
// a point and an OFF face one of the file's vertices. Malformed text: ReadError with its
// line.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "exidel/delaunay/certify.hpp"
#include "exidel/io/points.hpp"  // ReadError
#include "exidel/predicates/types.hpp"

namespace exidel::io {

enum class ProducedFormat { json, ele, off, simplices };

std::string_view to_string(ProducedFormat f) noexcept;
/// "json", "ele", "off", "simplices"; nullopt for anything else.
std::optional<ProducedFormat> produced_format_from_name(std::string_view name);
/// From the extension of `path` (.json .ele .off); nullopt for any other.
std::optional<ProducedFormat> produced_format_from_path(std::string_view path);

/// Parses `text` in `format`; `points` are the input the triangulation claims to be of.
delaunay::ProducedTriangulation read_produced(std::string_view text, ProducedFormat format,
                                              std::span<const Point2> points);

}  // namespace exidel::io
