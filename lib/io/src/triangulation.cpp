// exidel I/O: the triangulation writers and the json reader (formats:
// exidel/io/triangulation.hpp).
#include "exidel/io/triangulation.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/delaunay/parallel.hpp"
#include "exidel/io/constrained.hpp"
#include "json.hpp"
#include "text.hpp"
#include "writers.hpp"

namespace exidel::io {

namespace {

using delaunay::Triangulation;
using detail::NumberWriter;

// "[v0,v1,...]", formatted in slices of 2^17 numbers (about 1 MB of text) on `threads`
// threads (detail::write_slices), each slice in one tight loop.
template <class T>
void json_array(std::ostream& out, const std::vector<T>& v, unsigned threads) {
    out.put('[');
    detail::write_slices(out, v.size(), threads, std::size_t{1} << 17,
                         [&](std::size_t begin, std::size_t end, detail::TextBuffer& b) {
                             b.append(12 * (end - begin), [&](char* p) {
                                 char* const last = p + 12 * (end - begin);
                                 for (std::size_t i = begin; i < end; ++i) {
                                     if (i) *p++ = ',';
                                     p = std::to_chars(p, last, v[i]).ptr;
                                 }
                                 return p;
                             });
                         });
    out.put(']');
}

void write_json(std::ostream& out, const Triangulation& tri, unsigned threads) {
    out << "{\"triangles\": ";
    json_array(out, tri.triangles, threads);
    out << ",\n \"halfedges\": ";
    json_array(out, tri.halfedges, threads);
    out << ",\n \"hull\": ";
    json_array(out, tri.hull, threads);
    out << ",\n \"duplicates\": ";
    json_array(out, tri.duplicates, threads);
    out << "}\n";
}

// write_constrained's json (exidel/io/constrained.hpp).
void write_constrained_json(std::ostream& out, const delaunay::ConstrainedTriangulation& cdt,
                            const Triangulation& domain, const std::vector<std::uint32_t>& region,
                            std::span<const double> attribute, unsigned threads) {
    const auto flat = [](const auto& pairs) {
        std::vector<std::uint32_t> v;
        v.reserve(2 * pairs.size());
        for (const auto& p : pairs) v.insert(v.end(), {p[0], p[1]});
        return v;
    };
    out << "{\"triangles\": ";
    json_array(out, domain.triangles, threads);
    out << ",\n \"halfedges\": ";
    json_array(out, domain.halfedges, threads);
    out << ",\n \"region\": ";
    json_array(out, region, threads);
    if (!attribute.empty()) {
        out << ",\n \"attribute\": [";
        detail::write_items(
            out, attribute.size(), threads, [&](std::size_t i, detail::TextBuffer& b) {
                b.append(40, [&](char* p) {
                    return detail::put_json(detail::put(p, i ? ", " : ""), attribute[i]);
                });
            });
        out << "]";
    }
    out << ",\n \"constraints\": ";
    json_array(out, flat(cdt.constraints), threads);
    out << ",\n \"chain_offsets\": ";
    json_array(out, cdt.chain_offsets, threads);
    out << ",\n \"chain_vertices\": ";
    json_array(out, cdt.chain_vertices, threads);
    out << ",\n \"added_points\": [";
    const std::span<const Point2> added(cdt.points.data() + cdt.input_count, cdt.added_count());
    detail::write_items(out, added.size(), threads, [&](std::size_t i, detail::TextBuffer& b) {
        b.append(64, [&](char* p) {
            p = detail::put_json(detail::put(p, i ? ", [" : "["), added[i].x);
            return detail::put(detail::put_json(detail::put(p, ", "), added[i].y), "]");
        });
    });
    out << "],\n \"crossings\": ";
    json_array(out, flat(cdt.crossings), threads);
    out << ",\n \"duplicates\": ";
    json_array(out, cdt.triangulation.duplicates, threads);
    out << "}\n";
}

// With `attributes` (one per triangle: Triangle's regional attributes), one attribute
// column.
void write_ele(std::ostream& out, const Triangulation& tri, std::uint64_t base, unsigned threads,
               std::span<const double> attributes = {}) {
    const std::size_t n = tri.triangle_count();
    out << n << (attributes.empty() ? " 3 0\n" : " 3 1\n");
    detail::write_items(out, n, threads, [&](std::size_t t, detail::TextBuffer& b) {
        b.append(128, [&](char* p) {
            p = detail::put(p, static_cast<std::uint64_t>(t + base));
            for (std::size_t k = 0; k < 3; ++k) {
                p = detail::put(detail::put(p, " "),
                                static_cast<std::uint64_t>(tri.triangles[3 * t + k] + base));
            }
            if (!attributes.empty()) p = detail::put(detail::put(p, " "), attributes[t]);
            return detail::put(p, "\n");
        });
    });
}

void write_off(std::ostream& out, std::span<const Point2> points, const Triangulation& tri,
               std::span<const double> z) {
    NumberWriter w(out);
    w.text("OFF\n")
        .number(static_cast<std::uint64_t>(points.size()))
        .text(" ")
        .number(static_cast<std::uint64_t>(tri.triangle_count()))
        .text(" 0\n");
    for (std::size_t i = 0; i < points.size(); ++i) {
        w.number(points[i].x).text(" ").number(points[i].y);
        if (z.empty()) {
            w.text(" 0\n");
        } else {
            w.text(" ").number(z[i]).text("\n");
        }
    }
    for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
        w.text("3");
        for (std::size_t k = 0; k < 3; ++k) {
            w.text(" ").number(static_cast<std::uint64_t>(tri.triangles[3 * t + k]));
        }
        w.text("\n");
    }
}

// The points' bounding box, padded where a side is zero (text.hpp's svg_box).
detail::SvgBox bounds(std::span<const Point2> points) {
    if (points.empty()) return {};
    const detail::Bounds b = detail::bounding_box(points);
    return detail::svg_box(b.x0, b.y0, b.x1, b.y1);
}

// Every edge of the triangulation once, as trails (walks along unused edges: one vertex
// written per edge, plus one per trail), in paths of at most svg_path_items edges.
// `xy(command, v)` writes a path command and vertex v.
template <class XY>
void draw_edges(NumberWriter& w, std::size_t vertex_count, const Triangulation& tri, XY xy) {
    const std::size_t n = tri.triangles.size();
    const auto next = [](std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    // The edges (a half-edge without twin, or the smaller of a pair), and each vertex's.
    std::vector<std::uint32_t> offset(vertex_count + 1, 0), incident;
    const auto is_edge = [&](std::size_t e) {
        return tri.halfedges[e] < 0 || e < static_cast<std::size_t>(tri.halfedges[e]);
    };
    for (std::size_t e = 0; e < n; ++e) {
        if (!is_edge(e)) continue;
        ++offset[tri.triangles[e] + 1];
        ++offset[tri.triangles[next(e)] + 1];
    }
    for (std::size_t v = 0; v < vertex_count; ++v) offset[v + 1] += offset[v];
    incident.resize(offset[vertex_count]);
    std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    for (std::size_t e = 0; e < n; ++e) {
        if (!is_edge(e)) continue;
        incident[fill[tri.triangles[e]]++] = static_cast<std::uint32_t>(e);
        incident[fill[tri.triangles[next(e)]]++] = static_cast<std::uint32_t>(e);
    }
    std::vector<std::uint8_t> used(n, 0);
    std::vector<std::uint32_t> cursor(offset.begin(), offset.end() - 1), left(vertex_count);
    for (std::size_t v = 0; v < vertex_count; ++v) left[v] = offset[v + 1] - offset[v];
    const auto unused_edge = [&](std::uint32_t v) -> std::int64_t {
        while (cursor[v] < offset[v + 1] && used[incident[cursor[v]]]) ++cursor[v];
        return cursor[v] < offset[v + 1] ? static_cast<std::int64_t>(incident[cursor[v]]) : -1;
    };
    std::size_t in_path = 0;  // edges in the open path element
    bool open = false;
    const auto walk = [&](std::uint32_t v) {
        bool started = false;
        for (std::int64_t e; (e = unused_edge(v)) >= 0;) {
            used[static_cast<std::size_t>(e)] = 1;
            const std::uint32_t a = tri.triangles[static_cast<std::size_t>(e)];
            const std::uint32_t b = tri.triangles[next(static_cast<std::size_t>(e))];
            const std::uint32_t u = a == v ? b : a;
            --left[a];
            --left[b];
            if (in_path == svg_path_items) {
                w.text(detail::svg_path_end);
                open = false;
                in_path = 0;
            }
            if (!open) {
                xy("<path d=\"M", v);
                open = true;
            } else if (!started) {
                xy(" M", v);
            }
            started = true;
            xy(" L", u);
            ++in_path;
            v = u;
        }
    };
    // Trails from odd vertices first: each ends at another odd vertex, so there are about
    // half as many trails as odd vertices; then the closed trails that remain.
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        if (left[v] % 2 == 1) walk(v);
    }
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        while (left[v] > 0) walk(v);
    }
    if (open) w.text(detail::svg_path_end);
}

// With `pieces` (a constrained triangulation's domain: no hull), the triangles are filled
// one by one (the domain need not be convex) and the pieces drawn where the hull would be.
void write_svg(std::ostream& out, std::span<const Point2> points, const Triangulation& tri,
               std::span<const std::array<std::uint32_t, 2>> pieces = {},
               bool constrained = false) {
    NumberWriter w(out);
    const auto xy = [&](const char* command, std::uint32_t v) {
        w.text(command).number(points[v].x).text(" ").number(points[v].y);
    };
    const detail::SvgBox box = bounds(points);
    detail::svg_header(w, box);
    w.text(constrained ? "<!-- exidel constrained triangulation: " : "<!-- exidel triangulation: ")
        .number(static_cast<std::uint64_t>(points.size()))
        .text(" points, ")
        .number(static_cast<std::uint64_t>(tri.triangle_count()))
        .text(" triangles, ")
        .number(static_cast<std::uint64_t>(constrained ? pieces.size() : tri.hull.size()))
        .text(constrained ? " constraint pieces -->\n" : " hull vertices -->\n");
    // Each group's style is set once; its paths carry only their data. Stroke widths are
    // screen pixels in data units (svg_stroke_width).
    if (tri.triangle_count() > 0) {
        // The triangles are drawn as their union's fill and their edges, each edge once:
        // writing every triangle's three corners would write every vertex six times on
        // average and half again the bytes (librsvg refuses a file above about 200 MB,
        // which 10^6 points of shortest round-trip coordinates pass that way).
        // The fill: the hull (convex) as a fan of pieces from its first vertex, each of at
        // most svg_path_items vertices.
        w.text("<g fill=\"#dde6f3\" stroke=\"none\">\n");
        for (std::size_t t = 0; constrained && t < tri.triangle_count(); ++t) {
            xy(t % svg_path_items ? " M" : "<path d=\"M", tri.triangles[3 * t]);
            xy(" L", tri.triangles[3 * t + 1]);
            xy(" L", tri.triangles[3 * t + 2]);
            w.text(" Z");
            if (t % svg_path_items == svg_path_items - 1 || t + 1 == tri.triangle_count()) {
                w.text(detail::svg_path_end);
            }
        }
        const std::size_t h = tri.hull.size();
        for (std::size_t k = 1; k + 1 < h; k += svg_path_items - 2) {
            xy("<path d=\"M", tri.hull[0]);
            for (std::size_t j = k; j < std::min(h, k + svg_path_items - 1); ++j) {
                xy(" L", tri.hull[j]);
            }
            w.text(" Z").text(detail::svg_path_end);
        }
        w.text("</g>\n<g fill=\"none\" stroke=\"#3b5b92\" ");
        detail::svg_stroke_width(w, box, 0.5)
            .text(" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n");
        draw_edges(w, points.size(), tri, xy);
        w.text("</g>\n");
    }
    if (!tri.hull.empty()) {
        // A triangulated hull is a closed cycle; a collinear "hull" is an open chain. In
        // pieces of svg_path_items edges, each starting where the previous one ended.
        w.text("<g fill=\"none\" stroke=\"#c0392b\" ");
        detail::svg_stroke_width(w, box, 2).text(
            " stroke-linejoin=\"round\" stroke-linecap=\"round\">\n<path d=\"");
        const std::size_t h = tri.hull.size();
        const std::size_t vertices = tri.collinear ? h : h + 1;  // the cycle returns to the start
        const bool one_cycle = !tri.collinear && h <= svg_path_items;  // closed by Z instead
        for (std::size_t i = 0; i < (one_cycle ? h : vertices); ++i) {
            const bool restart = i > 0 && i % svg_path_items == 0 && i + 1 < vertices;
            if (restart) {
                xy(" L", tri.hull[i % h]);
                w.text(detail::svg_path_end).text("<path d=\"");
            }
            xy(i == 0 || restart ? "M" : " L", tri.hull[i % h]);
        }
        w.text(one_cycle ? " Z" : "").text(detail::svg_path_end).text("</g>\n");
    }
    if (!pieces.empty()) {
        w.text("<g fill=\"none\" stroke=\"#c0392b\" ");
        detail::svg_stroke_width(w, box, 2).text(" stroke-linecap=\"round\">\n");
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            xy(k % svg_path_items ? " M" : "<path d=\"M", pieces[k][0]);
            xy(" L", pieces[k][1]);
            if (k % svg_path_items == svg_path_items - 1 || k + 1 == pieces.size()) {
                w.text(detail::svg_path_end);
            }
        }
        w.text("</g>\n");
    }
    const double r = detail::svg_dot_radius(points.size());
    // The points as dots: zero-length subpaths with round caps of diameter 2r, in paths of
    // svg_path_items points. Not one <circle> each: librsvg refuses a file of more than
    // 10^6 elements.
    w.text("<g fill=\"none\" stroke=\"#111\" stroke-linecap=\"round\" ");
    detail::svg_stroke_width(w, box, 2 * r).text(">\n");
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i % svg_path_items == 0) {
            if (i) w.text(detail::svg_path_end);
            w.text("<path d=\"");
        }
        xy(i % svg_path_items ? " M" : "M", static_cast<std::uint32_t>(i));
        w.text(" h0");
    }
    if (!points.empty()) w.text(detail::svg_path_end);
    w.text("</g>\n");
    detail::svg_footer(w);
}

}  // namespace

std::string_view to_string(TriangulationFormat f) noexcept {
    switch (f) {
        case TriangulationFormat::json: return "json";
        case TriangulationFormat::ele: return "ele";
        case TriangulationFormat::off: return "off";
        case TriangulationFormat::svg: return "svg";
        case TriangulationFormat::geojson: return "geojson";
        case TriangulationFormat::wkt: return "wkt";
        case TriangulationFormat::ply: return "ply";
        case TriangulationFormat::ply_ascii: return "ply-ascii";
        case TriangulationFormat::poly: return "poly";
    }
    return "?";
}

std::optional<TriangulationFormat> triangulation_format_from_name(std::string_view name) {
    for (TriangulationFormat f :
         {TriangulationFormat::json, TriangulationFormat::ele, TriangulationFormat::off,
          TriangulationFormat::svg, TriangulationFormat::geojson, TriangulationFormat::wkt,
          TriangulationFormat::ply, TriangulationFormat::ply_ascii, TriangulationFormat::poly}) {
        if (to_string(f) == name) return f;
    }
    return std::nullopt;
}

std::optional<TriangulationFormat> triangulation_format_from_path(std::string_view path) {
    const std::string_view extension = detail::extension_of(path);
    if (extension == "ply-ascii") return std::nullopt;  // a format name, not an extension
    return triangulation_format_from_name(extension);
}

void write_triangulation(std::ostream& out, std::span<const Point2> points,
                         const Triangulation& tri, TriangulationFormat format,
                         const WriteOptions& options) {
    const std::span<const double> z = options.z;
    if (!z.empty() && z.size() != points.size()) {
        throw std::invalid_argument("write_triangulation: " + std::to_string(z.size()) +
                                    " z values for " + std::to_string(points.size()) + " points");
    }
    switch (format) {
        case TriangulationFormat::json: return write_json(out, tri, options.threads);
        case TriangulationFormat::ele:
            return write_ele(out, tri, options.index_base, options.threads);
        case TriangulationFormat::off: return write_off(out, points, tri, z);
        case TriangulationFormat::svg: return write_svg(out, points, tri);
        case TriangulationFormat::geojson:
            return detail::write_triangulation_geojson(out, points, tri, z, options.threads);
        case TriangulationFormat::wkt:
            return detail::write_triangulation_wkt(out, points, tri, z, options.threads);
        case TriangulationFormat::ply:
            return detail::write_triangulation_ply(out, points, tri, z, true);
        case TriangulationFormat::ply_ascii:
            return detail::write_triangulation_ply(out, points, tri, z, false);
        case TriangulationFormat::poly: {
            // The hull's edges as segments (for collinear input, the chain of its points).
            std::vector<std::array<std::uint32_t, 2>> hull_edges;
            const std::size_t h = tri.hull.size();
            const std::size_t edges = tri.collinear ? (h > 0 ? h - 1 : 0) : h;
            for (std::size_t k = 0; k < edges; ++k) {
                hull_edges.push_back({tri.hull[k], tri.hull[(k + 1) % h]});
            }
            return detail::write_poly(out, points, hull_edges, {}, {}, {}, options.index_base,
                                      options.threads);
        }
    }
}

void write_constrained(std::ostream& out, const delaunay::ConstrainedTriangulation& cdt,
                       const delaunay::Regions& regions, TriangulationFormat format,
                       const ConstrainedWriteOptions& options) {
    const std::span<const Point2> points(cdt.points);
    const std::size_t segments = cdt.chain_offsets.empty() ? 0 : cdt.chain_offsets.size() - 1;
    if (!options.z.empty() && options.z.size() != points.size()) {
        throw std::invalid_argument("write_constrained: " + std::to_string(options.z.size()) +
                                    " z values for " + std::to_string(points.size()) + " vertices");
    }
    if (!options.segment_markers.empty() && options.segment_markers.size() != segments) {
        throw std::invalid_argument(
            "write_constrained: " + std::to_string(options.segment_markers.size()) +
            " markers for " + std::to_string(segments) + " segments");
    }
    const Triangulation domain = domain_triangulation(cdt, regions);
    std::vector<std::uint32_t> region;
    std::vector<double> attribute;  // per domain triangle, when the regions have attributes
    region.reserve(domain.triangle_count());
    for (std::size_t t = 0; t < regions.inside.size(); ++t) {
        if (!regions.inside[t]) continue;
        region.push_back(regions.region[t]);
        if (!regions.attribute.empty()) attribute.push_back(regions.attribute[t]);
    }
    switch (format) {
        case TriangulationFormat::json:
            return write_constrained_json(out, cdt, domain, region, attribute, options.threads);
        case TriangulationFormat::svg: return write_svg(out, points, domain, cdt.constraints, true);
        case TriangulationFormat::geojson:
            return detail::write_constrained_geojson(out, points, domain, options.z,
                                                     options.threads, region, attribute, cdt,
                                                     options.segment_markers);
        case TriangulationFormat::poly: {
            // Each piece once, with the marker of the first segment whose chain holds it.
            std::vector<std::int32_t> markers;
            if (!options.segment_markers.empty()) {
                markers.assign(cdt.constraints.size(), 0);
                std::vector<std::uint8_t> marked(cdt.constraints.size(), 0);
                for (std::size_t s = 0; s < segments; ++s) {
                    const std::span<const std::uint32_t> chain = cdt.chain(s);
                    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
                        const std::array<std::uint32_t, 2> piece{std::min(chain[k], chain[k + 1]),
                                                                 std::max(chain[k], chain[k + 1])};
                        const auto at =
                            std::lower_bound(cdt.constraints.begin(), cdt.constraints.end(), piece);
                        const auto i = static_cast<std::size_t>(at - cdt.constraints.begin());
                        if (at != cdt.constraints.end() && *at == piece && !marked[i]) {
                            marked[i] = 1;
                            markers[i] = options.segment_markers[s];
                        }
                    }
                }
            }
            return detail::write_poly(out, points, cdt.constraints, markers, options.holes,
                                      options.regions, options.index_base, options.threads);
        }
        case TriangulationFormat::ele:
            return write_ele(out, domain, options.index_base, options.threads, attribute);
        case TriangulationFormat::off:
        case TriangulationFormat::wkt:
        case TriangulationFormat::ply:
        case TriangulationFormat::ply_ascii:
            return write_triangulation(
                out, points, domain, format,
                WriteOptions{options.index_base, options.threads, options.z});
    }
}

}  // namespace exidel::io
