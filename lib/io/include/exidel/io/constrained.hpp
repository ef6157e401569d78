// exidel I/O: writing a constrained triangulation (exidel/delaunay/constrained.hpp) with its
// regions (exidel/delaunay/regions.hpp): the triangles of the domain (Regions::inside), the
// added crossing points, the constraint pieces.
//
// Vertex indices are indices into cdt.points: the input points (input order, a repeated
// point represented by its first occurrence), then the added crossing points from
// cdt.input_count on. Regional attributes (Regions::attribute, from a .poly's regions) go
// into json, geojson and ele. The formats (TriangulationFormat, triangulation.hpp):
//
//   json  {"triangles": [...], "halfedges": [...], "region": [...], "attribute": [...] (with
//         attributes only), "constraints": [...], "chain_offsets": [...],
//         "chain_vertices": [...], "added_points": [[x, y], ...],
//         "crossings": [...], "duplicates": [...]}, one key per line: the domain's
//         triangles (counter-clockwise, flat), halfedges in delaunator's layout (-1 where the
//         neighbour across is outside the domain or the hull), each triangle's region, the
//         pieces (u, v) flat, each input segment's chain (cdt.chain), the added points (the
//         vertices from cdt.input_count on), for each added point the two input segments it
//         is the rounded crossing of (flat), and the input indices that repeat a point.
//   ele   Triangle's .ele of the domain's triangles, counted from WriteOptions::index_base
//         (with regional attributes, "ntriangles 3 1" and each triangle's attribute);
//         pair it with a .node of every vertex (write_points(cdt.points, node)).
//   poly  Triangle's .poly: every vertex (as in .node, no attributes or markers), the
//         pieces as segments (each once, with the marker of the first input segment whose
//         chain holds it when markers are given), the hole seeds, and the regions (seed,
//         attribute, maximum area or -1). A plain triangulation's .poly (write_triangulation)
//         has its hull edges as segments, as Triangle writes one.
//   off, ply, ply-ascii, wkt  the domain's triangles over every vertex, z as given.
//   geojson  the domain's triangles as Features with properties {"triangle", "vertices",
//         "region", "attribute" (with attributes)}, then one LineString Feature per input
//         segment: its chain, properties
//         {"segment": s, "vertices": [chain], "marker": m (when markers are given)}.
//   svg   the domain's triangles (filled, every edge once), the pieces drawn thicker in
//         red, the vertices as dots; in the data's coordinates as for a triangulation.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <span>
#include <vector>

#include "exidel/delaunay/constrained.hpp"
#include "exidel/delaunay/regions.hpp"
#include "exidel/io/constraints.hpp"
#include "exidel/io/triangulation.hpp"

namespace exidel::io {

struct ConstrainedWriteOptions {
    unsigned index_base = 0;  ///< ele, poly: the number of the first vertex (0 or 1)
    unsigned threads = 1;     ///< text formats: threads formatting parts of the file
    /// off, ply, geojson, wkt: one z per vertex of cdt.points (constrained_z), or empty.
    std::span<const double> z{};
    /// poly, geojson: one marker per input segment, or empty for none.
    std::span<const std::int32_t> segment_markers{};
    /// poly: the hole seeds and regions to write back.
    std::span<const Point2> holes{};
    std::span<const ConstraintFile::Region> regions{};
};

/// The domain of `regions` as a Triangulation over cdt.points: the inside triangles in
/// order, halfedges paired among them (-1 across the domain's boundary), no hull.
delaunay::Triangulation domain_triangulation(const delaunay::ConstrainedTriangulation& cdt,
                                             const delaunay::Regions& regions);

/// One z per vertex of `cdt` from `input_z` (one per input point): the input's values, and
/// for an added point the mean of the linear interpolations of z along its two segments
/// at the point's projection on each (z is carried, not part of the geometry).
std::vector<double> constrained_z(const delaunay::ConstrainedTriangulation& cdt,
                                  std::span<const double> input_z);

/// Writes the constrained triangulation `cdt` restricted to `regions`' domain in `format`.
/// Throws std::invalid_argument when options.z or options.segment_markers have the wrong
/// size.
void write_constrained(std::ostream& out, const delaunay::ConstrainedTriangulation& cdt,
                       const delaunay::Regions& regions, TriangulationFormat format,
                       const ConstrainedWriteOptions& options = {});

}  // namespace exidel::io
