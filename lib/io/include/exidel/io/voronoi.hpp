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
//   svg   a picture, y up, scaled into a viewBox about 1000 units wide: the Voronoi edges
//         (each once), the rays of unbounded cells drawn to the picture's edge (the
//         whole diagram), the perpendicular bisectors of a collinear diagram's chain,
//         the vertices as small dots with merged cocircular vertices (four or more
//         distinct sites) ringed in orange, and the sites as dots. The picture spans the
//         sites and the vertices, padded; clipped, it is the box (drawn), and only the
//         sites inside it are drawn. For looking at, not for reading back.
#pragma once

#include <iosfwd>
#include <optional>
#include <span>
#include <string_view>

#include "exidel/delaunay/voronoi.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::io {

enum class VoronoiFormat { json, svg };

std::string_view to_string(VoronoiFormat f) noexcept;
/// "json", "svg"; nullopt for anything else.
std::optional<VoronoiFormat> voronoi_format_from_name(std::string_view name);
/// From the extension of `path` (.json .svg); nullopt for any other.
std::optional<VoronoiFormat> voronoi_format_from_path(std::string_view path);

/// Writes `diagram`, the Voronoi diagram of `points`, in `format`.
void write_voronoi(std::ostream& out, std::span<const Point2> points,
                   const delaunay::VoronoiDiagram& diagram, VoronoiFormat format);

/// Writes `diagram`, the Voronoi diagram of `points` clipped to `box`, in `format`.
void write_voronoi(std::ostream& out, std::span<const Point2> points,
                   const delaunay::ClippedVoronoi& diagram, const delaunay::Box& box,
                   VoronoiFormat format);

}  // namespace exidel::io
