// exidel I/O: the triangulation writers and the json reader (formats:
// exidel/io/triangulation.hpp).
#include "exidel/io/triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <ostream>
#include <string>

#include "json.hpp"
#include "text.hpp"

namespace exidel::io {

namespace {

using delaunay::Triangulation;
using detail::NumberWriter;

template <class T>
void json_array(NumberWriter& w, const std::vector<T>& v) {
    w.text("[");
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (i) w.text(",");
        if constexpr (std::is_signed_v<T>) {
            w.number(static_cast<std::int64_t>(v[i]));
        } else {
            w.number(static_cast<std::uint64_t>(v[i]));
        }
    }
    w.text("]");
}

void write_json(std::ostream& out, const Triangulation& tri) {
    NumberWriter w(out);
    w.text("{\"triangles\": ");
    json_array(w, tri.triangles);
    w.text(",\n \"halfedges\": ");
    json_array(w, tri.halfedges);
    w.text(",\n \"hull\": ");
    json_array(w, tri.hull);
    w.text(",\n \"duplicates\": ");
    json_array(w, tri.duplicates);
    w.text("}\n");
}

void write_ele(std::ostream& out, const Triangulation& tri) {
    NumberWriter w(out);
    const std::size_t n = tri.triangle_count();
    w.number(static_cast<std::uint64_t>(n)).text(" 3 0\n");
    for (std::size_t t = 0; t < n; ++t) {
        w.number(static_cast<std::uint64_t>(t));
        for (std::size_t k = 0; k < 3; ++k) {
            w.text(" ").number(static_cast<std::uint64_t>(tri.triangles[3 * t + k]));
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
    w.text("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"")
        .fixed(-Frame::margin, 0)
        .text(" ")
        .fixed(-Frame::margin, 0)
        .text(" ")
        .fixed(f.width + 2 * Frame::margin, 3)
        .text(" ")
        .fixed(f.height + 2 * Frame::margin, 3)
        .text("\">\n");
    w.text("<!-- exidel triangulation: ")
        .number(static_cast<std::uint64_t>(points.size()))
        .text(" points, ")
        .number(static_cast<std::uint64_t>(tri.triangle_count()))
        .text(" triangles, ")
        .number(static_cast<std::uint64_t>(tri.hull.size()))
        .text(" hull vertices -->\n");
    if (tri.triangle_count() > 0) {
        w.text("<path fill=\"#dde6f3\" stroke=\"#3b5b92\" stroke-width=\"0.5\" "
               "stroke-linejoin=\"round\" d=\"");
        for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
            xy(t ? " M" : "M", tri.triangles[3 * t]);
            xy(" L", tri.triangles[3 * t + 1]);
            xy(" L", tri.triangles[3 * t + 2]);
            w.text(" Z");
        }
        w.text("\"/>\n");
    }
    if (!tri.hull.empty()) {
        // A triangulated hull is a closed cycle; a collinear "hull" is an open chain.
        w.text("<path fill=\"none\" stroke=\"#c0392b\" stroke-width=\"2\" "
               "stroke-linejoin=\"round\" d=\"");
        for (std::size_t i = 0; i < tri.hull.size(); ++i) xy(i ? " L" : "M", tri.hull[i]);
        if (!tri.collinear) w.text(" Z");
        w.text("\"/>\n");
    }
    const double r = std::clamp(Frame::size / (4 * std::sqrt(static_cast<double>(points.size()) + 1)),
                                0.5, 4.0);
    w.text("<g fill=\"#111\">\n");
    for (const Point2& p : points) {
        w.text("<circle cx=\"").fixed(f.x(p), 3).text("\" cy=\"").fixed(f.y(p), 3);
        w.text("\" r=\"").fixed(r, 2).text("\"/>\n");
    }
    w.text("</g>\n</svg>\n");
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
                         const Triangulation& tri, TriangulationFormat format) {
    switch (format) {
        case TriangulationFormat::json: return write_json(out, tri);
        case TriangulationFormat::ele: return write_ele(out, tri);
        case TriangulationFormat::off: return write_off(out, points, tri);
        case TriangulationFormat::svg: return write_svg(out, points, tri);
    }
}

Triangulation parse_triangulation_json(std::string_view text) {
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
    for (std::size_t k = 0; k < 4; ++k) {
        if (!seen[k]) j.fail("key \"" + std::string(keys[k]) + "\" is missing");
    }
    if (!j.at_end()) j.fail("unexpected " + j.found() + " after the closing '}'");
    tri.collinear = tri.triangles.empty();
    return tri;
}

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

}  // namespace exidel::io
