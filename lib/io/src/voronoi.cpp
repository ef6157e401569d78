// exidel I/O: the Voronoi diagram writers (formats: exidel/io/voronoi.hpp).
#include "exidel/io/voronoi.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/io/triangulation.hpp"
#include "text.hpp"
#include "writers.hpp"

namespace exidel::io {

namespace {

using delaunay::Box;
using delaunay::ClippedVoronoi;
using delaunay::VoronoiDiagram;
using detail::NumberWriter;

// ---- json -------------------------------------------------------------------------

void coordinate(NumberWriter& w, double v) { detail::json_number(w, v); }

// "[[a, b], [c], []]": list(k) for k < count, each a span of indices.
template <class List>
void index_lists(NumberWriter& w, std::size_t count, List list) {
    w.text("[");
    for (std::size_t k = 0; k < count; ++k) {
        w.text(k ? ", [" : "[");
        bool first = true;
        for (const std::uint32_t i : list(k)) {
            w.text(first ? "" : ", ").number(static_cast<std::uint64_t>(i));
            first = false;
        }
        w.text("]");
    }
    w.text("]");
}

// Both diagram types have the same accessors.
template <class Diagram>
void write_json(std::ostream& out, const Diagram& d) {
    NumberWriter w(out);
    w.text("{\"vertices\": [");
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        w.text(v ? ", [" : "[");
        coordinate(w, d.vertices[v].x);
        w.text(", ");
        coordinate(w, d.vertices[v].y);
        w.text("]");
    }
    w.text("],\n \"vertex_sites\": ");
    index_lists(w, d.vertex_count(), [&](std::size_t v) { return d.vertex_sites(v); });
    w.text(",\n \"cells\": ");
    index_lists(w, d.site_count(), [&](std::size_t i) { return d.cell(i); });
    w.text(",\n \"unbounded\": [");
    for (std::size_t i = 0; i < d.unbounded.size(); ++i) {
        w.text(i ? ", " : "").text(d.unbounded[i] ? "true" : "false");
    }
    w.text("]}\n");
}

// ---- svg --------------------------------------------------------------------------

// The box a picture shows, in data coordinates (the SVG is written in them: text.hpp's
// svg_header), and lines clipped to it.
class Picture {
public:
    explicit Picture(const detail::SvgBox& box) : box_(box) {}
    const detail::SvgBox& box() const { return box_; }

    /// The part of {from + t dir : t >= t0} inside the box (dir not zero, its larger
    /// component of size 1), as its two ends; false if it misses the box.
    bool clip(Point2 from, Point2 dir, double t0, Point2& a, Point2& b) const {
        double lo = t0, hi = std::numeric_limits<double>::infinity();
        const double p[2] = {from.x, from.y}, d[2] = {dir.x, dir.y};
        const double edge[2][2] = {{box_.x0, box_.x1}, {box_.y0, box_.y1}};
        for (int k = 0; k < 2; ++k) {
            if (d[k] == 0) {
                if (p[k] < edge[k][0] || p[k] > edge[k][1]) return false;
                continue;
            }
            const double s = (edge[k][0] - p[k]) / d[k], u = (edge[k][1] - p[k]) / d[k];
            lo = std::max(lo, std::min(s, u));
            hi = std::min(hi, std::max(s, u));
        }
        if (!(lo <= hi)) return false;
        // Rounding (or an overflow near the largest doubles) may step past the box.
        const auto inside = [&](double t) {
            return Point2{std::clamp(from.x + t * dir.x, box_.x0, box_.x1),
                          std::clamp(from.y + t * dir.y, box_.y0, box_.y1)};
        };
        a = inside(lo);
        b = inside(hi);
        return true;
    }

private:
    detail::SvgBox box_;
};

// One <g> of unfilled paths, each of at most svg_path_items / 2 items (io/triangulation.hpp
// says why), with round caps (a zero-length subpath draws a dot) and strokes of
// `pixels` screen pixels in a picture of `box`.
class PathGroup {
public:
    PathGroup(NumberWriter& w, const detail::SvgBox& box, std::string_view colour, double pixels)
        : w_(w) {
        w_.text("<g fill=\"none\" stroke-linecap=\"round\" stroke=\"").text(colour).text("\" ");
        detail::svg_stroke_width(w_, box, pixels).text(">\n");
    }
    ~PathGroup() {
        if (items_) w_.text(detail::svg_path_end);
        w_.text("</g>\n");
    }
    PathGroup(const PathGroup&) = delete;
    PathGroup& operator=(const PathGroup&) = delete;

    /// Starts an item: a new path every svg_path_items / 2 items (a segment writes two
    /// points: about 40 kB of attribute per path, as io/triangulation.hpp says).
    NumberWriter& item() {
        if (items_ % (svg_path_items / 2) == 0) {
            if (items_) w_.text(detail::svg_path_end);
            w_.text("<path d=\"");
        } else {
            w_.text(" ");
        }
        ++items_;
        return w_;
    }
    NumberWriter& xy(Point2 p) { return w_.number(p.x).text(" ").number(p.y); }
    void segment(Point2 a, Point2 b) {
        item().text("M");
        xy(a).text(" L");
        xy(b);
    }
    void dot(Point2 p) {
        item().text("M");
        xy(p).text(" h0");
    }
    /// The outline of the box.
    void rectangle(const detail::SvgBox& b) {
        item().text("M");
        xy({b.x0, b.y0}).text(" H").number(b.x1).text(" V").number(b.y1).text(" H");
        w_.number(b.x0).text(" Z");
    }

private:
    NumberWriter& w_;
    std::size_t items_ = 0;
};

// repeated[i]: point i equals an earlier one (a duplicate, drawn and counted once).
std::vector<std::uint8_t> repeated_points(std::span<const Point2> points) {
    std::vector<std::uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto less = [&](std::uint32_t a, std::uint32_t b) {
        return points[a].x < points[b].x ||
               (points[a].x == points[b].x && points[a].y < points[b].y);
    };
    std::stable_sort(order.begin(), order.end(), less);
    std::vector<std::uint8_t> repeated(points.size(), 0);
    for (std::size_t k = 1; k < order.size(); ++k) {
        if (!less(order[k - 1], order[k])) repeated[order[k]] = 1;
    }
    return repeated;
}

// Every edge between consecutive vertices of a cell (closing the cell when `closed(i)`),
// each once, as (smaller, larger) vertex pairs packed in 64 bits, sorted.
template <class Diagram, class Closed>
std::vector<std::uint64_t> edges(const Diagram& d, Closed closed) {
    std::vector<std::uint64_t> keys;
    const auto add = [&](std::uint64_t u, std::uint64_t v) {
        if (u != v) keys.push_back(std::min(u, v) << 32 | std::max(u, v));
    };
    for (std::size_t i = 0; i < d.site_count(); ++i) {
        const auto c = d.cell(i);
        for (std::size_t k = 1; k < c.size(); ++k) add(c[k - 1], c[k]);
        if (c.size() > 2 && closed(i)) add(c.back(), c.front());
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    return keys;
}

// What the pictures of both diagrams have: the edges, the Voronoi vertices (the first
// `voronoi_vertices`; merged ones ringed) and the sites but the repeated ones (and those
// without drawn_sites[i], unless it is empty). `extra(group)` adds lines drawn like the
// edges: rays and bisectors, or the box.
template <class Diagram, class Closed, class Extra>
void draw(std::ostream& out, std::span<const Point2> points, const Diagram& d,
          std::size_t voronoi_vertices, const Picture& f, Closed closed, Extra extra,
          std::span<const std::uint8_t> repeated, std::span<const std::uint8_t> drawn_sites) {
    const auto distinct_sites = [&](std::size_t v) {
        std::size_t n = 0;
        for (const std::uint32_t s : d.vertex_sites(v)) n += repeated[s] ? 0 : 1;
        return n;
    };
    std::size_t merged = 0;
    for (std::size_t v = 0; v < voronoi_vertices; ++v) merged += distinct_sites(v) >= 4 ? 1 : 0;
    NumberWriter w(out);
    detail::svg_header(w, f.box());
    w.text("<!-- exidel voronoi: ")
        .number(static_cast<std::uint64_t>(points.size()))
        .text(" sites, ")
        .number(static_cast<std::uint64_t>(voronoi_vertices))
        .text(" Voronoi vertices, ")
        .number(static_cast<std::uint64_t>(merged))
        .text(" of them of four or more cocircular sites (on orange discs) -->\n");
    const double r = detail::svg_dot_radius(points.size());
    {
        PathGroup g(w, f.box(), "#3b5b92", std::clamp(r / 2, 0.25, 1.0));
        for (const std::uint64_t e : edges(d, closed)) {
            g.segment(d.vertices[e >> 32], d.vertices[e & 0xffffffffu]);
        }
        extra(g);
    }
    if (merged > 0) {
        // An orange disc under the vertex's dot (a ring's radius would be in data units).
        PathGroup g(w, f.box(), "#e67e22", 4 * r + 4);
        for (std::size_t v = 0; v < voronoi_vertices; ++v) {
            if (distinct_sites(v) >= 4) g.dot(d.vertices[v]);
        }
    }
    if (voronoi_vertices > 0) {
        PathGroup g(w, f.box(), "#3b5b92", 1.25 * r);
        for (std::size_t v = 0; v < voronoi_vertices; ++v) g.dot(d.vertices[v]);
    }
    {
        PathGroup g(w, f.box(), "#111", 2 * r);
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (!repeated[i] && (drawn_sites.empty() || drawn_sites[i])) g.dot(points[i]);
        }
    }
    detail::svg_footer(w);
}

// `v` scaled so that its larger component has size 1 (huge and tiny vectors alike stay
// finite and nonzero); (0, 0) stays.
Point2 direction(Point2 v) {
    const double m = std::max(std::abs(v.x), std::abs(v.y));
    return m > 0 ? Point2{v.x / m, v.y / m} : Point2{0, 0};
}

void write_svg(std::ostream& out, std::span<const Point2> points, const VoronoiDiagram& d) {
    double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
    bool any = false;
    const auto extend = [&](Point2 p) {
        xmin = any ? std::min(xmin, p.x) : p.x;
        xmax = any ? std::max(xmax, p.x) : p.x;
        ymin = any ? std::min(ymin, p.y) : p.y;
        ymax = any ? std::max(ymax, p.y) : p.y;
        any = true;
    };
    for (const Point2& p : points) extend(p);
    for (const Point2& v : d.vertices) extend(v);
    const Picture f(detail::svg_box(xmin, ymin, xmax, ymax));
    const std::vector<std::uint8_t> repeated = repeated_points(points);
    const auto bounded = [&](std::size_t i) { return !d.unbounded[i]; };
    const auto rays_and_bisectors = [&](PathGroup& g) {
        Point2 a{}, b{};
        // Each hull edge's ray is the exit ray of the cell it ends in (and the entry ray
        // of the next): the exit rays draw each once, to the picture's edge.
        for (std::size_t i = 0; i < d.site_count(); ++i) {
            const auto c = d.cell(i);
            const Point2 u = direction(d.exit_ray[i]);
            if (repeated[i] || !d.unbounded[i] || c.empty() || (u.x == 0 && u.y == 0)) continue;
            if (f.clip(d.vertices[c.back()], u, 0, a, b)) g.segment(a, b);
        }
        // Collinear: the perpendicular bisector of each pair of neighbours on the line
        // (halves: no difference or sum can overflow).
        for (std::size_t k = 1; k < d.chain.size(); ++k) {
            const Point2 p = points[d.chain[k - 1]], q = points[d.chain[k]];
            const Point2 u = direction({p.y / 2 - q.y / 2, q.x / 2 - p.x / 2});
            if (u.x == 0 && u.y == 0) continue;
            const Point2 m{p.x / 2 + q.x / 2, p.y / 2 + q.y / 2};
            if (f.clip(m, u, -std::numeric_limits<double>::infinity(), a, b)) g.segment(a, b);
        }
    };
    draw(out, points, d, d.vertex_count(), f, bounded, rays_and_bisectors, repeated, {});
}

void write_svg(std::ostream& out, std::span<const Point2> points, const ClippedVoronoi& d,
               const Box& box) {
    const Picture f(detail::SvgBox{box.xmin, box.ymin, box.xmax, box.ymax});
    std::vector<std::uint8_t> inside(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Point2 p = points[i];
        inside[i] = p.x >= box.xmin && p.x <= box.xmax && p.y >= box.ymin && p.y <= box.ymax;
    }
    const auto frame = [&](PathGroup& g) { g.rectangle(f.box()); };
    // A clipped cell is a closed polygon.
    draw(
        out, points, d, d.voronoi_vertex_count, f, [](std::size_t) { return true; }, frame,
        repeated_points(points), inside);
}

}  // namespace

std::string_view to_string(VoronoiFormat f) noexcept {
    switch (f) {
        case VoronoiFormat::json: return "json";
        case VoronoiFormat::svg: return "svg";
        case VoronoiFormat::geojson: return "geojson";
        case VoronoiFormat::wkt: return "wkt";
    }
    return "?";
}

std::optional<VoronoiFormat> voronoi_format_from_name(std::string_view name) {
    for (VoronoiFormat f :
         {VoronoiFormat::json, VoronoiFormat::svg, VoronoiFormat::geojson, VoronoiFormat::wkt}) {
        if (to_string(f) == name) return f;
    }
    return std::nullopt;
}

std::optional<VoronoiFormat> voronoi_format_from_path(std::string_view path) {
    return voronoi_format_from_name(detail::extension_of(path));
}

bool holds_unbounded_cells(VoronoiFormat format) noexcept {
    return format == VoronoiFormat::json || format == VoronoiFormat::svg;
}

Box default_clip_box(std::span<const Point2> sites) {
    if (sites.empty()) return {-1, -1, 1, 1};
    auto [x0, y0, x1, y1] = detail::bounding_box(sites);
    const double side = std::max(detail::finite_span(x1 - x0), detail::finite_span(y1 - y0));
    const double margin = side > 0 ? default_clip_margin * side : 1;
    detail::widen(x0, x1, margin);
    detail::widen(y0, y1, margin);
    return {x0, y0, x1, y1};
}

void write_voronoi(std::ostream& out, std::span<const Point2> points, const VoronoiDiagram& diagram,
                   VoronoiFormat format) {
    if (!holds_unbounded_cells(format)) {
        throw std::invalid_argument("write_voronoi: the " + std::string(to_string(format)) +
                                    " format needs a clipped diagram (polygons)");
    }
    if (format == VoronoiFormat::svg) return write_svg(out, points, diagram);
    write_json(out, diagram);
}

void write_voronoi(std::ostream& out, std::span<const Point2> points, const ClippedVoronoi& diagram,
                   const Box& box, VoronoiFormat format) {
    switch (format) {
        case VoronoiFormat::json: return write_json(out, diagram);
        case VoronoiFormat::svg: return write_svg(out, points, diagram, box);
        case VoronoiFormat::geojson: return detail::write_voronoi_geojson(out, diagram, box);
        case VoronoiFormat::wkt: return detail::write_voronoi_wkt(out, diagram);
    }
}

}  // namespace exidel::io
