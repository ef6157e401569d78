// exidel I/O (internal): the writers of the GIS formats, called by write_triangulation
// and write_voronoi (formats: exidel/io/triangulation.hpp, exidel/io/voronoi.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <span>

#include "exidel/delaunay/constrained.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/io/constraints.hpp"
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

/// The triangles of `domain` (over `points`, all vertices of `cdt`), each with its
/// "region" and "attribute" when given, then one Feature per input segment of `cdt`: its chain
/// as a LineString (a Point for a segment whose ends are equal), properties {"segment": s,
/// "vertices": [chain], "marker": m (when `markers` is given)}.
void write_constrained_geojson(std::ostream& out, std::span<const Point2> points,
                               const delaunay::Triangulation& domain, std::span<const double> z,
                               unsigned threads, std::span<const std::uint32_t> region,
                               std::span<const double> attribute,
                               const delaunay::ConstrainedTriangulation& cdt,
                               std::span<const std::int32_t> markers);

/// Triangle's .poly: `points` as vertices (numbered from `base`, no attributes or
/// markers), `segments` (with `markers` when not empty), `holes`, `regions`.
void write_poly(std::ostream& out, std::span<const Point2> points,
                std::span<const std::array<std::uint32_t, 2>> segments,
                std::span<const std::int32_t> markers, std::span<const Point2> holes,
                std::span<const ConstraintFile::Region> regions, unsigned base, unsigned threads);

void write_voronoi_geojson(std::ostream& out, const delaunay::ClippedVoronoi& d,
                           const delaunay::Box& box);
void write_voronoi_wkt(std::ostream& out, const delaunay::ClippedVoronoi& d);

}  // namespace exidel::io::detail
