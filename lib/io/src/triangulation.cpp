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

void write_off(std::ostream& out, std::span<const Point2> points, const Triangulation& tri) {
    NumberWriter w(out);
    w.text("OFF\n")
        .number(static_cast<std::uint64_t>(points.size()))
        .text(" ")
        .number(static_cast<std::uint64_t>(tri.triangle_count()))
        .text(" 0\n");
    for (const Point2& p : points) w.number(p.x).text(" ").number(p.y).text(" 0\n");
    for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
        w.text("3");
        for (std::size_t k = 0; k < 3; ++k) {
            w.text(" ").number(static_cast<std::uint64_t>(tri.triangles[3 * t + k]));
        }
        w.text("\n");
    }
}

// Maps input coordinates into the picture: the larger side of the bounding box becomes
// `size` units, y grows downwards in SVG so it is flipped. Halves are subtracted
// (x/2 - min/2) so that coordinates near +-DBL_MAX cannot overflow the span.
struct Frame {
    double min_x = 0, max_y = 0, scale = 1, width = 0, height = 0;
    static constexpr double size = 1000;
    static constexpr double margin = 20;

    explicit Frame(std::span<const Point2> points) {
        if (points.empty()) return;
        double min_y = points[0].y, max_x = points[0].x;
        min_x = points[0].x;
        max_y = points[0].y;
        for (const Point2& p : points) {
            min_x = std::min(min_x, p.x);
            max_x = std::max(max_x, p.x);
            min_y = std::min(min_y, p.y);
            max_y = std::max(max_y, p.y);
        }
        const double hx = max_x / 2 - min_x / 2, hy = max_y / 2 - min_y / 2;
        const double half = std::max(hx, hy);
        // A single point, or a span so small its half rounds to zero: draw at the origin.
        scale = half > 0 ? size / half : 1;
        width = hx * scale;
        height = hy * scale;
    }
    double x(const Point2& p) const { return (p.x / 2 - min_x / 2) * scale; }
    double y(const Point2& p) const { return (max_y / 2 - p.y / 2) * scale; }
};

void write_svg(std::ostream& out, std::span<const Point2> points, const Triangulation& tri) {
    const Frame f(points);
    NumberWriter w(out);
    const auto xy = [&](const char* command, std::uint32_t v) {
        w.text(command).fixed(f.x(points[v]), 3).text(" ").fixed(f.y(points[v]), 3);
    };
    detail::svg_header(w, f.width, f.height, Frame::margin);
    w.text("<!-- exidel triangulation: ")
        .number(static_cast<std::uint64_t>(points.size()))
        .text(" points, ")
        .number(static_cast<std::uint64_t>(tri.triangle_count()))
        .text(" triangles, ")
        .number(static_cast<std::uint64_t>(tri.hull.size()))
        .text(" hull vertices -->\n");
    // Each group's style is set once; its paths carry only their data.
    if (tri.triangle_count() > 0) {
        w.text(
            "<g fill=\"#dde6f3\" stroke=\"#3b5b92\" stroke-width=\"0.5\" "
            "stroke-linejoin=\"round\">\n");
        for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
            const bool first = t % svg_path_items == 0;
            if (first) w.text(t ? "\"/>\n<path d=\"" : "<path d=\"");
            xy(first ? "M" : " M", tri.triangles[3 * t]);
            xy(" L", tri.triangles[3 * t + 1]);
            xy(" L", tri.triangles[3 * t + 2]);
            w.text(" Z");
        }
        w.text("\"/>\n</g>\n");
    }
    if (!tri.hull.empty()) {
        // A triangulated hull is a closed cycle; a collinear "hull" is an open chain. In
        // pieces of svg_path_items edges, each starting where the previous one ended.
        w.text(
            "<g fill=\"none\" stroke=\"#c0392b\" stroke-width=\"2\" "
            "stroke-linejoin=\"round\" stroke-linecap=\"round\">\n<path d=\"");
        const std::size_t h = tri.hull.size();
        const std::size_t vertices = tri.collinear ? h : h + 1;  // the cycle returns to the start
        const bool one_cycle = !tri.collinear && h <= svg_path_items;  // closed by Z instead
        for (std::size_t i = 0; i < (one_cycle ? h : vertices); ++i) {
            const bool restart = i > 0 && i % svg_path_items == 0 && i + 1 < vertices;
            if (restart) {
                xy(" L", tri.hull[i % h]);
                w.text("\"/>\n<path d=\"");
            }
            xy(i == 0 || restart ? "M" : " L", tri.hull[i % h]);
        }
        w.text(one_cycle ? " Z\"/>\n</g>\n" : "\"/>\n</g>\n");
    }
    const double r = detail::svg_dot_radius(Frame::size, points.size());
    // The points as dots: zero-length subpaths with round caps of diameter 2r, in paths of
    // svg_path_items points. Not one <circle> each: librsvg refuses a file of more than
    // 10^6 elements.
    w.text("<g fill=\"none\" stroke=\"#111\" stroke-linecap=\"round\" stroke-width=\"")
        .fixed(2 * r, 2)
        .text("\">\n");
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i % svg_path_items == 0) w.text(i ? "\"/>\n<path d=\"" : "<path d=\"");
        w.text(i % svg_path_items ? " M" : "M").fixed(f.x(points[i]), 3).text(" ");
        w.fixed(f.y(points[i]), 3).text(" h0");
    }
    w.text(points.empty() ? "</g>\n</svg>\n" : "\"/>\n</g>\n</svg>\n");
}

}  // namespace

std::string_view to_string(TriangulationFormat f) noexcept {
    switch (f) {
        case TriangulationFormat::json: return "json";
        case TriangulationFormat::ele: return "ele";
        case TriangulationFormat::off: return "off";
        case TriangulationFormat::svg: return "svg";
    }
    return "?";
}

std::optional<TriangulationFormat> triangulation_format_from_name(std::string_view name) {
    for (TriangulationFormat f : {TriangulationFormat::json, TriangulationFormat::ele,
                                  TriangulationFormat::off, TriangulationFormat::svg}) {
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
    return triangulation_format_from_name(path.substr(dot + 1));
}

void write_triangulation(std::ostream& out, std::span<const Point2> points,
                         const Triangulation& tri, TriangulationFormat format,
                         const WriteOptions& options) {
    switch (format) {
        case TriangulationFormat::json: return write_json(out, tri, options.threads);
        case TriangulationFormat::ele: return write_ele(out, tri, options.index_base);
        case TriangulationFormat::off: return write_off(out, points, tri);
        case TriangulationFormat::svg: return write_svg(out, points, tri);
    }
}

}  // namespace exidel::io
