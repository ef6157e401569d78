// exidel I/O: points and segments for the constrained triangulation, from Triangle's .poly
// format (parse_poly), GeoJSON (parse_geojson_constraints) or JSON (parse_json_constraints).
//
// .poly, a planar straight-line graph: points, segments, holes, regional attributes.
//   vertices    "n [dim [attributes [markers]]]" then n lines "index x y [attribute...]
//               [marker]", exactly as a .node file (points.hpp); dim must be 2. n = 0
//               (vertices in a separate .node file) is an error: exidel reads one file.
//   segments    "m [markers]" then m lines "index a b [marker]"; a and b are vertex
//               numbers, counted like the vertices (from 0 or 1).
//   holes       "h" then h lines "index x y": hole seeds (RegionOptions::holes).
//   regions     optional: "r" then r lines "index x y attribute [maximum area]" (a
//               negative or zero maximum area means none, as in Triangle).
// Each section's indices start at 0 or 1 and follow consecutively. '#' starts a comment,
// blank lines are skipped, numbers are decimal or C99 hexadecimal floats rounded to the
// nearest double; NaN and infinity are errors. Attributes of vertices are checked and
// dropped, markers kept for segments only. Errors are ReadError with the line number
// (points.hpp); a file that ends inside a section says which.
//
// GeoJSON (RFC 7946): a FeatureCollection, a Feature or a bare geometry, read in document
// order (also inside GeometryCollections). Point and MultiPoint give points; LineString and
// MultiLineString give their positions as points joined in order by segments (breaklines);
// Polygon and MultiPolygon give every ring's positions but the closing one, joined around
// the ring (a ring has at least 4 positions and ends where it starts, else an error). The
// rings' orientations are kept, so FillRule::even_odd (regions.hpp) gives the polygons'
// interiors whatever they are, and FillRule::non_zero does for RFC 7946's orientations
// (exterior rings counter-clockwise, holes clockwise). z: positions are all [x, y] or all
// [x, y, z] (ConstraintFile::z). A feature whose geometry is null is skipped; strict JSON,
// errors are ReadError with their line. Points repeated between features (shared borders)
// are kept as given: the triangulation merges equal points.
//
// JSON: an object {"points": [[x, y], ...], "segments": [[a, b], ...], "holes": [[x, y],
// ...]}, the keys in any order, "segments" and "holes" optional, nothing else; a and b are
// point indices from 0. A bare array of points (the json point format, points.hpp) is
// points without segments. Numbers as in the json point format; errors with their line.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "exidel/io/points.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::io {

struct ConstraintFile {
    std::vector<Point2> points;
    unsigned index_base = 0;  ///< the first vertex number of the file (0 or 1)
    std::vector<std::array<std::uint32_t, 2>> segments;  ///< by point index, from 0
    std::vector<std::int32_t> segment_markers;           ///< one per segment when the file has them
    std::vector<Point2> holes;
    struct Region {
        Point2 seed;
        double attribute = 0;
        std::optional<double> max_area{};
    };
    std::vector<Region> regions;
    std::vector<double> z{};  ///< GeoJSON with z: one per point; else empty
};

/// Parses the whole of `data` (a .poly file's bytes). Throws ReadError on malformed input.
ConstraintFile parse_poly(std::string_view data);

/// Parses the whole of `data` as GeoJSON points, lines and polygons (above). Empty input (or
/// only whitespace) is an empty file. Throws ReadError on malformed input.
ConstraintFile parse_geojson_constraints(std::string_view data);
/// Parses the whole of `data` as the JSON object above. Throws ReadError on malformed input.
ConstraintFile parse_json_constraints(std::string_view data);
/// The reader of `format`: poly, geojson or json (a UTF-8 byte order mark skipped). Throws
/// std::invalid_argument for the formats that have no segments (xy, node, f64).
ConstraintFile parse_constraint_file(std::string_view data, PointFormat format);

}  // namespace exidel::io
