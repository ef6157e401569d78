// exidel I/O: writing a Voronoi diagram (exidel/delaunay/voronoi.hpp), whole or clipped to
// a box.
//
// Formats. Sites are input indices (0-based, duplicates included: a duplicate's cell is
// its twin's, and it is listed beside its twin among a vertex's sites).
//
//   json  exactly {"vertices": [[x, y], ...], "vertex_sites": [[i, j, k, ...], ...],
//                  "cells": [[v, ...], ...], "unbounded": [bool, ...]}
//         one key per line, in this order:
//           vertices[v]      the vertex's coordinates, each the shortest decimal that
//                            reads back as the same double (std::to_chars); negative
//                            zero is written "-0.0" (a JSON reader may take "-0" for the
//                            integer 0 and lose its sign)
//           vertex_sites[v]  diagram.vertex_sites(v)
//           cells[i]         diagram.cell(i), for every input index i
//           unbounded[i]     whether cell i is unbounded
//         Collinear input has no vertices and empty cells; clipped, the cells are the
//         clipped strips and every vertex the box added is listed after the Voronoi
//         vertices (delaunay::ClippedVoronoi).
//   svg   a picture in the data's coordinates (as the triangulation's svg,
//         exidel/io/triangulation.hpp: viewBox in input units, y flipped by a
//         scale(1,-1) group, shortest round-trip coordinates, pixel-sized strokes): the
//         Voronoi edges (each once), the rays of unbounded cells drawn to the picture's
//         edge (the whole diagram), the perpendicular bisectors of a collinear diagram's
//         chain, the vertices as small dots with merged cocircular vertices (four or more
//         distinct sites) on orange discs, and the sites as dots. The whole diagram's
//         picture is the bounding box of the sites and the vertices (padded only where a
//         side is zero); clipped, it is the box (drawn), and only the sites inside it are
//         drawn. For looking at, not for reading back.
//   geojson  (clipped only) RFC 7946: {"type": "FeatureCollection", "bbox": [box], ...},
//         one Feature per input index i, in order, one per line: properties {"site": i},
//         geometry the Polygon of its clipped cell (counter-clockwise, closed), or null
//         when the cell misses the box (so that feature i is always site i). A duplicate
//         has its twin's polygon.
//   wkt   (clipped only) one GEOMETRYCOLLECTION of one POLYGON per input index, in order,
//         one per line: "POLYGON ((x y, ..., x y))" (counter-clockwise, closed) or
//         "POLYGON EMPTY" when the cell misses the box; "GEOMETRYCOLLECTION EMPTY" for no
//         points. Not a MULTIPOLYGON: a duplicate's polygon repeats its twin's, and
//         overlapping members would make a MULTIPOLYGON invalid.
// geojson and wkt coordinates are the shortest decimals that read back as the same
// doubles, never rounded.
#pragma once

#include <iosfwd>
#include <optional>
#include <span>
#include <string_view>

#include "exidel/delaunay/voronoi.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::io {

enum class VoronoiFormat { json, svg, geojson, wkt };

std::string_view to_string(VoronoiFormat f) noexcept;
/// "json", "svg", "geojson", "wkt"; nullopt for anything else.
std::optional<VoronoiFormat> voronoi_format_from_name(std::string_view name);
/// From the extension of `path` (.json .svg .geojson .wkt); nullopt for any other.
std::optional<VoronoiFormat> voronoi_format_from_path(std::string_view path);
/// Whether `format` can hold the whole (unclipped) diagram: json and svg; geojson and wkt
/// hold polygons, which unbounded cells are not.
bool holds_unbounded_cells(VoronoiFormat format) noexcept;

/// The margin of default_clip_box, as a fraction of the larger side of the sites'
/// bounding box.
inline constexpr double default_clip_margin = 0.1;

/// The box `exidel voronoi` clips to by default: the bounding box of `sites`, widened on
/// every side by default_clip_margin times its larger side, or by 1 when that is zero (a
/// single distinct site, or none: then the box is [-1, 1]^2). Each side moves by at least
/// one representable step and stays finite, so the box always has an interior.
delaunay::Box default_clip_box(std::span<const Point2> sites);

/// Writes `diagram`, the Voronoi diagram of `points`, in `format`: json or svg (geojson
/// and wkt throw std::invalid_argument: an unbounded cell is no polygon).
void write_voronoi(std::ostream& out, std::span<const Point2> points,
                   const delaunay::VoronoiDiagram& diagram, VoronoiFormat format);

/// Writes `diagram`, the Voronoi diagram of `points` clipped to `box`, in `format`.
void write_voronoi(std::ostream& out, std::span<const Point2> points,
                   const delaunay::ClippedVoronoi& diagram, const delaunay::Box& box,
                   VoronoiFormat format);

}  // namespace exidel::io
