// exidel I/O: the triangulation writers and the json reader (formats:
// exidel/io/triangulation.hpp).
#include "exidel/io/triangulation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/delaunay/parallel.hpp"
#include "json.hpp"
#include "text.hpp"
#include "writers.hpp"

namespace exidel::io {

namespace {

using delaunay::Triangulation;
using detail::NumberWriter;

// Formats v[begin, end) as comma-separated integers (a comma before each but the first
// of the whole array) into `text`, which has room for 12 characters per number
// ("-2147483648," or "4294967295," at most); returns the length.
template <class T>
std::size_t format_integers(const std::vector<T>& v, std::size_t begin, std::size_t end,
                            char* text) {
    char* p = text;
    for (std::size_t i = begin; i < end; ++i) {
        if (i) *p++ = ',';
        p = std::to_chars(p, text + 12 * (end - begin), v[i]).ptr;
    }
    return static_cast<std::size_t>(p - text);
}

// "[v0,v1,...]": formatted in slices, `threads` slices at a time, written in order. The
// formatting is most of a large file's write time; the slices keep memory bounded. The
// buffers are not std::string: resizing one zero-fills it, a pass as long as the writing.
template <class T>
void json_array(std::ostream& out, const std::vector<T>& v, unsigned threads) {
    constexpr std::size_t slice = 1 << 17;  // numbers per slice: about 1 MB of text
    const std::size_t workers = std::max(threads, 1u);
    const std::size_t buffers = std::min(workers, (v.size() + slice - 1) / slice);
    std::vector<std::unique_ptr<char[]>> text(buffers);
    for (auto& t : text) t.reset(new char[12 * slice]);
    std::vector<std::size_t> length(buffers);
    out.put('[');
    for (std::size_t round = 0; round < v.size(); round += slice * workers) {
        const std::size_t slices = std::min(workers, (v.size() - round + slice - 1) / slice);
        exidel::parallel_for(slices, threads, [&](std::size_t s) {
            const std::size_t begin = round + s * slice;
            length[s] = format_integers(v, begin, std::min(v.size(), begin + slice), text[s].get());
        });
        for (std::size_t s = 0; s < slices; ++s) {
            out.write(text[s].get(), static_cast<std::streamsize>(length[s]));
        }
    }
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

void write_ele(std::ostream& out, const Triangulation& tri, std::uint64_t base) {
    NumberWriter w(out);
    const std::size_t n = tri.triangle_count();
    w.number(static_cast<std::uint64_t>(n)).text(" 3 0\n");
    for (std::size_t t = 0; t < n; ++t) {
        w.number(t + base);
        for (std::size_t k = 0; k < 3; ++k) {
            w.text(" ").number(tri.triangles[3 * t + k] + base);
        }
        w.text("\n");
    }
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
    double x0 = points[0].x, x1 = points[0].x, y0 = points[0].y, y1 = points[0].y;
    for (const Point2& p : points) {
        x0 = std::min(x0, p.x);
        x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y);
        y1 = std::max(y1, p.y);
    }
    return detail::svg_box(x0, y0, x1, y1);
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

void write_svg(std::ostream& out, std::span<const Point2> points, const Triangulation& tri) {
    NumberWriter w(out);
    const auto xy = [&](const char* command, std::uint32_t v) {
        w.text(command).number(points[v].x).text(" ").number(points[v].y);
    };
    const detail::SvgBox box = bounds(points);
    detail::svg_header(w, box);
    w.text("<!-- exidel triangulation: ")
        .number(static_cast<std::uint64_t>(points.size()))
        .text(" points, ")
        .number(static_cast<std::uint64_t>(tri.triangle_count()))
        .text(" triangles, ")
        .number(static_cast<std::uint64_t>(tri.hull.size()))
        .text(" hull vertices -->\n");
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

template <class T>
std::vector<T> integer_array(detail::JsonCursor& j, std::string_view key, std::int64_t lo,
                             std::int64_t hi) {
    std::vector<T> v;
    j.expect('[', "to open the array \"" + std::string(key) + "\"");
    if (j.accept(']')) return v;
    do {
        v.push_back(static_cast<T>(j.integer(key, lo, hi)));
    } while (j.accept(','));
    j.expect(']', "or ',' in the array \"" + std::string(key) + "\"");
    return v;
}

// Triangle's .ele: the triangles alone, as input indices.
Triangulation parse_ele(std::string_view text, std::size_t point_count) {
    Triangulation tri;
    std::size_t expected = 0, attributes = 0, base = 0, count = 0;
    bool have_header = false;
    const auto integer = [](std::size_t line, std::string_view field, const char* what,
                            std::uint64_t lo, std::uint64_t hi) {
        std::uint64_t v = 0;
        const auto r = std::from_chars(field.data(), field.data() + field.size(), v);
        if (r.ec != std::errc{} || r.ptr != field.data() + field.size() || v < lo || v > hi) {
            throw ReadError::at_line(line, std::string(what) + ": " + quoted(field) +
                                               " is not a whole number in [" + std::to_string(lo) +
                                               ", " + std::to_string(hi) + "]");
        }
        return static_cast<std::size_t>(v);
    };
    std::vector<std::string_view> fields;
    const std::size_t lines =
        detail::for_each_line(text, [&](std::size_t number, std::string_view line) {
            fields.clear();
            const std::string_view content = detail::strip_comment(line);
            for (std::size_t i = 0; i < content.size();) {
                while (i < content.size() && detail::is_blank(content[i])) ++i;
                const std::size_t start = i;
                while (i < content.size() && !detail::is_blank(content[i])) ++i;
                if (i > start) fields.push_back(content.substr(start, i - start));
            }
            if (fields.empty()) return;
            if (!have_header) {
                if (fields.size() < 2 || fields.size() > 3) {
                    throw ReadError::at_line(number, "the header is \"triangles 3 [attributes]\"");
                }
                expected = integer(number, fields[0], "number of triangles", 0, 0x7fffffff / 3);
                integer(number, fields[1], "nodes per triangle (only 3 is supported)", 3, 3);
                if (fields.size() == 3)
                    attributes = integer(number, fields[2], "attributes", 0, 1 << 20);
                have_header = true;
                tri.triangles.reserve(3 * std::min(expected, text.size() / 8));
                return;
            }
            if (count == expected) {
                throw ReadError::at_line(number, "more triangle lines than the " +
                                                     std::to_string(expected) +
                                                     " the header announces");
            }
            if (fields.size() != 4 + attributes) {
                throw ReadError::at_line(number, "expected " + std::to_string(4 + attributes) +
                                                     " fields (index v0 v1 v2" +
                                                     (attributes ? " attributes" : "") + "), got " +
                                                     std::to_string(fields.size()));
            }
            if (count == 0) {
                base = integer(number, fields[0], "first triangle index", 0, 1);
            } else {
                integer(number, fields[0], "triangle index", base + count, base + count);
            }
            for (std::size_t k = 1; k <= 3; ++k) {
                if (point_count == 0) throw ReadError::at_line(number, "a triangle, but no points");
                tri.triangles.push_back(static_cast<std::uint32_t>(
                    integer(number, fields[k], "vertex", base, base + point_count - 1) - base));
            }
            ++count;
        });
    if (!have_header) throw ReadError::at_line(1, "empty .ele file (no header)");
    if (count != expected) {
        throw ReadError::at_line(std::max<std::size_t>(lines, 1),
                                 "truncated: the file ends after " + std::to_string(count) +
                                     " of the " + std::to_string(expected) +
                                     " triangles the header announces");
    }
    return tri;
}

// halfedges from triangles: the twin of a -> b is the half-edge b -> a, when exactly one
// half-edge runs each way.
void link_halfedges(Triangulation& tri) {
    const std::size_t n = tri.triangles.size();
    const auto key = [&](std::size_t e) {
        const std::size_t next = e % 3 == 2 ? e - 2 : e + 1;
        return std::uint64_t{tri.triangles[e]} << 32 | tri.triangles[next];
    };
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return key(a) < key(b); });
    const auto unique = [&](std::uint64_t k) -> std::int64_t {
        const auto lo =
            std::lower_bound(order.begin(), order.end(), k,
                             [&](std::uint32_t e, std::uint64_t v) { return key(e) < v; });
        if (lo == order.end() || key(*lo) != k) return -1;
        if (lo + 1 != order.end() && key(*(lo + 1)) == k) return -1;
        return *lo;
    };
    tri.halfedges.assign(n, -1);
    for (std::size_t e = 0; e < n; ++e) {
        const std::uint64_t k = key(e);
        if (unique(k) < 0) continue;
        const std::int64_t twin = unique(k << 32 | k >> 32);
        if (twin >= 0) tri.halfedges[e] = static_cast<std::int32_t>(twin);
    }
}

// The boundary cycle (half-edges without twin) from its lexicographically smallest vertex;
// empty when the boundary half-edges do not form one cycle.
std::vector<std::uint32_t> boundary_hull(std::span<const Point2> points, const Triangulation& tri) {
    const std::size_t n = tri.triangles.size();
    std::vector<std::int64_t> out_edge(points.size(), -1);  // the boundary half-edge leaving v
    std::size_t boundary = 0;
    for (std::size_t e = 0; e < n; ++e) {
        if (tri.halfedges[e] >= 0) continue;
        std::int64_t& slot = out_edge[tri.triangles[e]];
        if (slot >= 0) return {};  // two boundary edges leave one vertex: not one cycle
        slot = static_cast<std::int64_t>(e);
        ++boundary;
    }
    std::int64_t start = -1;
    for (std::size_t v = 0; v < points.size(); ++v) {
        if (out_edge[v] < 0) continue;
        if (start < 0 || points[v].x < points[static_cast<std::size_t>(start)].x ||
            (points[v].x == points[static_cast<std::size_t>(start)].x &&
             points[v].y < points[static_cast<std::size_t>(start)].y)) {
            start = static_cast<std::int64_t>(v);
        }
    }
    std::vector<std::uint32_t> hull;
    if (start < 0) return hull;
    auto v = static_cast<std::uint32_t>(start);
    do {
        hull.push_back(v);
        const auto e = static_cast<std::size_t>(out_edge[v]);
        v = tri.triangles[e % 3 == 2 ? e - 2 : e + 1];
        if (out_edge[v] < 0 || hull.size() > boundary) return {};
    } while (v != static_cast<std::uint32_t>(start));
    if (hull.size() != boundary) return {};
    return hull;
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
    }
    return "?";
}

std::optional<TriangulationFormat> triangulation_format_from_name(std::string_view name) {
    for (TriangulationFormat f :
         {TriangulationFormat::json, TriangulationFormat::ele, TriangulationFormat::off,
          TriangulationFormat::svg, TriangulationFormat::geojson, TriangulationFormat::wkt,
          TriangulationFormat::ply, TriangulationFormat::ply_ascii}) {
        if (to_string(f) == name) return f;
    }
    return std::nullopt;
}

std::optional<TriangulationFormat> triangulation_format_from_path(std::string_view path) {
    const std::size_t dot = path.rfind('.');
    const std::size_t slash = path.rfind('/');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
        return std::nullopt;
    }
    const std::string_view extension = path.substr(dot + 1);
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
        case TriangulationFormat::ele: return write_ele(out, tri, options.index_base);
        case TriangulationFormat::off: return write_off(out, points, tri, z);
        case TriangulationFormat::svg: return write_svg(out, points, tri);
        case TriangulationFormat::geojson:
            return detail::write_triangulation_geojson(out, points, tri, z);
        case TriangulationFormat::wkt: return detail::write_triangulation_wkt(out, points, tri, z);
        case TriangulationFormat::ply:
            return detail::write_triangulation_ply(out, points, tri, z, true);
        case TriangulationFormat::ply_ascii:
            return detail::write_triangulation_ply(out, points, tri, z, false);
    }
}

// The json layout. With `has_duplicates` given, "duplicates" may be missing, and
// *has_duplicates says whether it was there; without, it is required.
static Triangulation parse_json(std::string_view text, bool* has_duplicates) {
    detail::JsonCursor j(text);
    Triangulation tri;
    constexpr std::int64_t max_u32 = 0xffffffff, max_i32 = 0x7fffffff;
    bool seen[4] = {false, false, false, false};
    constexpr std::string_view keys[4] = {"triangles", "halfedges", "hull", "duplicates"};
    j.expect('{', "to open the triangulation object");
    do {
        const std::string_view key = j.key();
        const auto k = static_cast<std::size_t>(std::find(keys, keys + 4, key) - keys);
        if (k == 4) j.fail("unknown key " + quoted(key));
        if (seen[k]) j.fail("key " + quoted(key) + " appears twice");
        seen[k] = true;
        j.expect(':', "after the key");
        switch (k) {
            case 0: tri.triangles = integer_array<std::uint32_t>(j, key, 0, max_u32); break;
            case 1: tri.halfedges = integer_array<std::int32_t>(j, key, -1, max_i32); break;
            case 2: tri.hull = integer_array<std::uint32_t>(j, key, 0, max_u32); break;
            default: tri.duplicates = integer_array<std::uint32_t>(j, key, 0, max_u32); break;
        }
    } while (j.accept(','));
    j.expect('}', "or ',' after an array");
    for (std::size_t k = 0; k < (has_duplicates ? 3 : 4); ++k) {
        if (!seen[k]) j.fail("key \"" + std::string(keys[k]) + "\" is missing");
    }
    if (!j.at_end()) j.fail("unexpected " + j.found() + " after the closing '}'");
    tri.collinear = tri.triangles.empty();
    if (has_duplicates) *has_duplicates = seen[3];
    return tri;
}

Triangulation parse_triangulation_json(std::string_view text) { return parse_json(text, nullptr); }

void fill_vertex_of_input(std::span<const Point2> points, Triangulation& tri) {
    std::vector<std::uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        if (points[a].x != points[b].x) return points[a].x < points[b].x;
        if (points[a].y != points[b].y) return points[a].y < points[b].y;
        return a < b;
    });
    tri.vertex_of_input.assign(points.size(), 0);
    for (std::size_t j = 0; j < order.size(); ++j) {
        const bool repeat = j > 0 && points[order[j]] == points[order[j - 1]];
        tri.vertex_of_input[order[j]] = repeat ? tri.vertex_of_input[order[j - 1]] : order[j];
    }
}

delaunay::Triangulation read_triangulation(std::string_view text, TriangulationFormat format,
                                           std::span<const Point2> points) {
    Triangulation tri;
    bool has_duplicates = false;  // json may list them; .ele cannot
    if (format == TriangulationFormat::json) {
        tri = parse_json(text, &has_duplicates);
    } else if (format == TriangulationFormat::ele) {
        tri = parse_ele(text, points.size());
        tri.collinear = tri.triangles.empty();
        link_halfedges(tri);
        tri.hull = boundary_hull(points, tri);
    } else {
        throw std::invalid_argument("cannot read a triangulation in the " +
                                    std::string(to_string(format)) + " format (json or ele)");
    }
    fill_vertex_of_input(points, tri);
    if (!has_duplicates) {
        tri.duplicates.clear();
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (tri.vertex_of_input[i] != i)
                tri.duplicates.push_back(static_cast<std::uint32_t>(i));
        }
    }
    if (tri.collinear && format == TriangulationFormat::ele) {
        // No triangles: the certifier then expects the chain of distinct points in
        // lexicographic order, which is all a triangle-less file can mean.
        std::vector<std::uint32_t> chain;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (tri.vertex_of_input[i] == i) chain.push_back(static_cast<std::uint32_t>(i));
        }
        std::sort(chain.begin(), chain.end(), [&](std::uint32_t a, std::uint32_t b) {
            return points[a].x != points[b].x ? points[a].x < points[b].x
                                              : points[a].y < points[b].y;
        });
        tri.hull = std::move(chain);
    }
    return tri;
}

}  // namespace exidel::io
