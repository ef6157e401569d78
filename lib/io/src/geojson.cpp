// exidel I/O: the GeoJSON (RFC 7946) and WKT writers of triangulations and clipped Voronoi
// diagrams (formats: exidel/io/triangulation.hpp, exidel/io/voronoi.hpp).
#include <cstdint>
#include <ostream>
#include <span>
#include <string_view>

#include "text.hpp"
#include "writers.hpp"

namespace exidel::io::detail {

namespace {

using delaunay::ClippedVoronoi;
using delaunay::Triangulation;

// [x, y] or [x, y, z] of point i.
void position(NumberWriter& w, std::span<const Point2> points, std::span<const double> z,
              std::uint32_t i) {
    w.text("[");
    json_number(w, points[i].x);
    w.text(", ");
    json_number(w, points[i].y);
    if (!z.empty()) {
        w.text(", ");
        json_number(w, z[i]);
    }
    w.text("]");
}

// "[[p, q, ..., p]]": the closed ring through `ring` (at least three vertices).
template <class Ring, class Position>
void polygon_coordinates(NumberWriter& w, const Ring& ring, Position pos) {
    w.text("[[");
    for (const std::uint32_t v : ring) {
        pos(v);
        w.text(", ");
    }
    pos(ring[0]);
    w.text("]]");
}

void index_array(NumberWriter& w, std::span<const std::uint32_t> v) {
    w.text("[");
    for (std::size_t k = 0; k < v.size(); ++k) {
        w.text(k ? ", " : "").number(static_cast<std::uint64_t>(v[k]));
    }
    w.text("]");
}

// "x y" or "x y z" of point i, as WKT writes a position.
void wkt_position(NumberWriter& w, std::span<const Point2> points, std::span<const double> z,
                  std::uint32_t i) {
    w.number(points[i].x).text(" ").number(points[i].y);
    if (!z.empty()) w.text(" ").number(z[i]);
}

}  // namespace

// The triangles of `tri` as Features, each on its own line after a ",\n" (the first after
// "\n"), properties {"triangle": t, "vertices": [i, j, k]} and, when given, "region":
// region[t] and "attribute": attribute[t]. Returns whether any was written.
bool triangle_features(std::ostream& out, std::span<const Point2> points, const Triangulation& tri,
                       std::span<const double> z, unsigned threads,
                       std::span<const std::uint32_t> region, std::span<const double> attribute) {
    const std::size_t n = tri.triangle_count();
    if (n == 0) return false;
    // Each position formatted once ("[x, y]" or "[x, y, z]"), then copied into the
    // features of the triangles around it.
    const FormattedPoints positions(points.size(), threads, [&](std::size_t i, TextBuffer& b) {
        b.append(96, [&](char* p) {
            p = put_json(put(p, "["), points[i].x);
            p = put_json(put(p, ", "), points[i].y);
            if (!z.empty()) p = put_json(put(p, ", "), z[i]);
            return put(p, "]");
        });
    });
    write_items(out, n, threads, [&](std::size_t t, TextBuffer& b) {
        const std::uint32_t* c = tri.triangles.data() + 3 * t;
        const std::string_view p0 = positions[c[0]], p1 = positions[c[1]], p2 = positions[c[2]];
        b.append(288 + 2 * p0.size() + p1.size() + p2.size(), [&](char* p) {
            p = put(p, t ? ",\n" : "\n");
            p = put(p, "{\"type\": \"Feature\", \"properties\": {\"triangle\": ");
            p = put(p, static_cast<std::uint64_t>(t));
            p = put(put(p, ", \"vertices\": ["), static_cast<std::uint64_t>(c[0]));
            p = put(put(p, ", "), static_cast<std::uint64_t>(c[1]));
            p = put(put(p, ", "), static_cast<std::uint64_t>(c[2]));
            p = put(p, "]");
            if (!region.empty()) p = put(put(p, ", \"region\": "), std::uint64_t{region[t]});
            if (!attribute.empty()) p = put_json(put(p, ", \"attribute\": "), attribute[t]);
            p = put(p, "}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[");
            p = put(put(put(put(p, p0), ", "), p1), ", ");
            p = put(put(put(put(p, p2), ", "), p0), "]]}}");
            return p;
        });
    });
    return true;
}

void write_triangulation_geojson(std::ostream& out, std::span<const Point2> points,
                                 const Triangulation& tri, std::span<const double> z,
                                 unsigned threads) {
    out << "{\"type\": \"FeatureCollection\", \"features\": [";
    const std::size_t n = tri.triangle_count();
    triangle_features(out, points, tri, z, threads, {}, {});
    NumberWriter w(out);
    const auto pos = [&](std::uint32_t v) { position(w, points, z, v); };
    // The hull: the boundary polygon, or for input without triangles the chain of its
    // distinct points (a LineString), or its one point.
    const std::span<const std::uint32_t> hull(tri.hull);
    if (!hull.empty()) {
        w.text(n ? ",\n" : "\n")
            .text("{\"type\": \"Feature\", \"properties\": {\"hull\": true, \"vertices\": ");
        index_array(w, hull);
        w.text("}, \"geometry\": {\"type\": ");
        if (!tri.collinear) {
            w.text("\"Polygon\", \"coordinates\": ");
            polygon_coordinates(w, hull, pos);
        } else if (hull.size() == 1) {
            w.text("\"Point\", \"coordinates\": ");
            pos(hull[0]);
        } else {
            w.text("\"LineString\", \"coordinates\": [");
            for (std::size_t k = 0; k < hull.size(); ++k) {
                w.text(k ? ", " : "");
                pos(hull[k]);
            }
            w.text("]");
        }
        w.text("}}");
    }
    w.text(n || !hull.empty() ? "\n]}\n" : "]}\n");
}

void write_constrained_geojson(std::ostream& out, std::span<const Point2> points,
                               const Triangulation& domain, std::span<const double> z,
                               unsigned threads, std::span<const std::uint32_t> region,
                               std::span<const double> attribute,
                               const delaunay::ConstrainedTriangulation& cdt,
                               std::span<const std::int32_t> markers) {
    out << "{\"type\": \"FeatureCollection\", \"features\": [";
    bool any = triangle_features(out, points, domain, z, threads, region, attribute);
    NumberWriter w(out);
    const auto pos = [&](std::uint32_t v) { position(w, points, z, v); };
    const std::size_t segments = cdt.chain_offsets.empty() ? 0 : cdt.chain_offsets.size() - 1;
    for (std::size_t s = 0; s < segments; ++s) {
        const std::span<const std::uint32_t> chain = cdt.chain(s);
        w.text(any ? ",\n" : "\n")
            .text("{\"type\": \"Feature\", \"properties\": {\"segment\": ")
            .number(static_cast<std::uint64_t>(s))
            .text(", \"vertices\": ");
        index_array(w, chain);
        if (!markers.empty()) {
            w.text(", \"marker\": ");
            const std::int32_t m = markers[s];
            if (m < 0) w.text("-");
            w.number(static_cast<std::uint64_t>(m < 0 ? -static_cast<std::int64_t>(m) : m));
        }
        if (chain.size() == 1) {
            w.text("}, \"geometry\": {\"type\": \"Point\", \"coordinates\": ");
            pos(chain[0]);
        } else {
            w.text("}, \"geometry\": {\"type\": \"LineString\", \"coordinates\": [");
            for (std::size_t k = 0; k < chain.size(); ++k) {
                w.text(k ? ", " : "");
                pos(chain[k]);
            }
            w.text("]");
        }
        w.text("}}");
        any = true;
    }
    w.text(any ? "\n]}\n" : "]}\n");
}

void write_triangulation_wkt(std::ostream& out, std::span<const Point2> points,
                             const Triangulation& tri, std::span<const double> z,
                             unsigned threads) {
    out << (z.empty() ? "MULTIPOLYGON" : "MULTIPOLYGON Z");
    const std::size_t n = tri.triangle_count();
    if (n == 0) {
        out << " EMPTY\n";
        return;
    }
    out << " (";
    // Each position ("x y" or "x y z") formatted once, then copied into its triangles.
    const FormattedPoints positions(points.size(), threads, [&](std::size_t i, TextBuffer& b) {
        b.append(96, [&](char* p) {
            p = put(put(put(p, points[i].x), " "), points[i].y);
            if (!z.empty()) p = put(put(p, " "), z[i]);
            return p;
        });
    });
    write_items(out, n, threads, [&](std::size_t t, TextBuffer& b) {
        const std::uint32_t* c = tri.triangles.data() + 3 * t;
        const std::string_view p0 = positions[c[0]], p1 = positions[c[1]], p2 = positions[c[2]];
        b.append(32 + 2 * p0.size() + p1.size() + p2.size(), [&](char* p) {
            p = put(p, t ? ",\n((" : "((");
            p = put(put(put(put(p, p0), ", "), p1), ", ");
            return put(put(put(put(p, p2), ", "), p0), "))");
        });
    });
    out << ")\n";
}

void write_voronoi_geojson(std::ostream& out, const ClippedVoronoi& d, const delaunay::Box& box) {
    NumberWriter w(out);
    const std::span<const Point2> vertices(d.vertices);
    const auto pos = [&](std::uint32_t v) { position(w, vertices, {}, v); };
    w.text("{\"type\": \"FeatureCollection\", \"bbox\": [");
    json_number(w, box.xmin);
    w.text(", ");
    json_number(w, box.ymin);
    w.text(", ");
    json_number(w, box.xmax);
    w.text(", ");
    json_number(w, box.ymax);
    w.text("], \"features\": [");
    for (std::size_t i = 0; i < d.site_count(); ++i) {
        const auto cell = d.cell(i);
        w.text(i ? ",\n" : "\n")
            .text("{\"type\": \"Feature\", \"properties\": {\"site\": ")
            .number(static_cast<std::uint64_t>(i))
            .text("}, \"geometry\": ");
        if (cell.size() < 3) {
            w.text("null}");  // the cell misses the box
            continue;
        }
        w.text("{\"type\": \"Polygon\", \"coordinates\": ");
        polygon_coordinates(w, cell, pos);
        w.text("}}");
    }
    w.text(d.site_count() ? "\n]}\n" : "]}\n");
}

void write_voronoi_wkt(std::ostream& out, const ClippedVoronoi& d) {
    NumberWriter w(out);
    if (d.site_count() == 0) {
        w.text("GEOMETRYCOLLECTION EMPTY\n");
        return;
    }
    const std::span<const Point2> vertices(d.vertices);
    w.text("GEOMETRYCOLLECTION (");
    for (std::size_t i = 0; i < d.site_count(); ++i) {
        const auto cell = d.cell(i);
        w.text(i ? ",\nPOLYGON " : "POLYGON ");
        if (cell.size() < 3) {
            w.text("EMPTY");
            continue;
        }
        w.text("((");
        for (std::size_t k = 0; k <= cell.size(); ++k) {
            if (k) w.text(", ");
            wkt_position(w, vertices, {}, cell[k % cell.size()]);
        }
        w.text("))");
    }
    w.text(")\n");
}

}  // namespace exidel::io::detail
