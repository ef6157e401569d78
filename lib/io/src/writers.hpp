// exidel I/O (internal): the writers of the GIS formats, called by write_triangulation
// and write_voronoi (formats: exidel/io/triangulation.hpp, exidel/io/voronoi.hpp).
#pragma once

#include <iosfwd>
#include <span>

#include "exidel/delaunay/result.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::io::detail {

/// `z` is empty (2D positions) or has one value per point. `threads` format parts of the
/// file at once (the text is the same for every count).
void write_triangulation_geojson(std::ostream& out, std::span<const Point2> points,
                                 const delaunay::Triangulation& tri, std::span<const double> z,
                                 unsigned threads = 1);
void write_triangulation_wkt(std::ostream& out, std::span<const Point2> points,
                             const delaunay::Triangulation& tri, std::span<const double> z,
                             unsigned threads = 1);
void write_triangulation_ply(std::ostream& out, std::span<const Point2> points,
                             const delaunay::Triangulation& tri, std::span<const double> z,
                             bool binary);

void write_voronoi_geojson(std::ostream& out, const delaunay::ClippedVoronoi& d,
                           const delaunay::Box& box);
void write_voronoi_wkt(std::ostream& out, const delaunay::ClippedVoronoi& d);

}  // namespace exidel::io::detail
