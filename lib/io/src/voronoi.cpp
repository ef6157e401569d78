// exidel I/O: the Voronoi diagram writers (formats: exidel/io/voronoi.hpp).
#include "exidel/io/voronoi.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <ostream>
#include <vector>

#include "exidel/io/triangulation.hpp"
#include "text.hpp"

namespace exidel::io {

namespace {

using delaunay::Box;
using delaunay::ClippedVoronoi;
using delaunay::VoronoiDiagram;
using detail::NumberWriter;

// ---- json -------------------------------------------------------------------------

// The shortest decimal that reads back as `v`; negative zero as "-0.0", which every JSON
// reader takes for a floating-point number (to_chars writes "-0", an integer to many).
void coordinate(NumberWriter& w, double v) {
    if (v == 0 && std::signbit(v)) {
        w.text("-0.0");
    } else {
        w.number(v);
    }
}

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

struct XY {
    double x, y;
};

// Maps a rectangle of the plane onto the picture: its larger side becomes `size` units, y
// is flipped so that up is up. Computed on quarters of the coordinates, so that neither
// a span nor its padding can overflow near +-DBL_MAX.
class Picture {
public:
    static constexpr double size = 1000;
    static constexpr double margin = 20;

    /// The rectangle [xmin, xmax] x [ymin, ymax] (finite, min <= max), padded by `pad`
    /// times its larger side on every side; a side shorter than `min_aspect` times the
    /// other is widened to that, about its middle. A point becomes a square around it.
    Picture(double xmin, double ymin, double xmax, double ymax, double pad, double min_aspect) {
        double x0 = xmin / 4, x1 = xmax / 4, y0 = ymin / 4, y1 = ymax / 4;
        double span = std::max(x1 - x0, y1 - y0);
        if (span == 0) {
            span = std::max({1.0, std::abs(x0), std::abs(y0)});
            pad = 0.5;
        }
        const double p = pad * span;
        x0 -= p, x1 += p, y0 -= p, y1 += p;
        const double wider = std::max(x1 - x0, y1 - y0) * min_aspect;
        if (x1 - x0 < wider) {
            const double e = (wider - (x1 - x0)) / 2;
            x0 -= e, x1 += e;
        }
        if (y1 - y0 < wider) {
            const double e = (wider - (y1 - y0)) / 2;
            y0 -= e, y1 += e;
        }
        x0_ = x0;
        y1_ = y1;
        span_ = std::max(x1 - x0, y1 - y0);
        width_ = (x1 - x0) / span_ * size;
        height_ = (y1 - y0) / span_ * size;
    }

    XY operator()(Point2 p) const {
        return {(p.x / 4 - x0_) / span_ * size, (y1_ - p.y / 4) / span_ * size};
    }
    double width() const { return width_; }
    double height() const { return height_; }

    /// The part of {from + t dir : t >= t0} inside the viewBox (dir in picture
    /// coordinates, not zero), as its two ends; false if it misses the viewBox.
    bool clip(XY from, XY dir, double t0, XY& a, XY& b) const {
        double lo = t0, hi = std::numeric_limits<double>::infinity();
        const double p[2] = {from.x, from.y}, d[2] = {dir.x, dir.y};
        const double edge[2][2] = {{-margin, width_ + margin}, {-margin, height_ + margin}};
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
        a = {from.x + lo * dir.x, from.y + lo * dir.y};
        b = {from.x + hi * dir.x, from.y + hi * dir.y};
        return true;
    }

private:
    double x0_ = 0, y1_ = 0, span_ = 1, width_ = 0, height_ = 0;
};

// One <g> of unfilled paths, each of at most svg_path_items items (io/triangulation.hpp
// says why), with round caps (a zero-length subpath draws a dot).
class PathGroup {
public:
    PathGroup(NumberWriter& w, std::string_view colour, double stroke_width) : w_(w) {
        w_.text("<g fill=\"none\" stroke-linecap=\"round\" stroke=\"")
            .text(colour)
            .text("\" stroke-width=\"")
            .fixed(stroke_width, 2)
            .text("\">\n");
    }
    ~PathGroup() { w_.text(items_ ? "\"/>\n</g>\n" : "</g>\n"); }
    PathGroup(const PathGroup&) = delete;
    PathGroup& operator=(const PathGroup&) = delete;

    /// Starts an item: a new path every svg_path_items items.
    NumberWriter& item() {
        if (items_ % svg_path_items == 0) {
            w_.text(items_ ? "\"/>\n<path d=\"" : "<path d=\"");
        } else {
            w_.text(" ");
        }
        ++items_;
        return w_;
    }
    NumberWriter& xy(XY p) { return w_.fixed(p.x, 3).text(" ").fixed(p.y, 3); }
    void segment(XY a, XY b) {
        item().text("M");
        xy(a).text(" L");
        xy(b);
    }
    void dot(XY p) {
        item().text("M");
        xy(p).text(" h0");
    }
    /// A circle of radius r: two half-circle arcs.
    void ring(XY p, double r) {
        item().text("M");
        xy({p.x - r, p.y}).text(" a").fixed(r, 2).text(" ").fixed(r, 2).text(" 0 1 0 ");
        w_.fixed(2 * r, 2).text(" 0 a").fixed(r, 2).text(" ").fixed(r, 2).text(" 0 1 0 ");
        w_.fixed(-2 * r, 2).text(" 0");
    }
    /// The outline of the rectangle with corners a and b.
    void rectangle(XY a, XY b) {
        item().text("M");
        xy(a).text(" H").fixed(b.x, 3).text(" V").fixed(b.y, 3).text(" H").fixed(a.x, 3).text(" Z");
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
    detail::svg_header(w, f.width(), f.height(), Picture::margin);
    w.text("<!-- exidel voronoi: ")
        .number(static_cast<std::uint64_t>(points.size()))
        .text(" sites, ")
        .number(static_cast<std::uint64_t>(voronoi_vertices))
        .text(" Voronoi vertices, ")
        .number(static_cast<std::uint64_t>(merged))
        .text(" of them of four or more cocircular sites (ringed) -->\n");
    const double r = detail::svg_dot_radius(Picture::size, points.size());
    {
        PathGroup g(w, "#3b5b92", std::clamp(r / 2, 0.25, 1.0));
        for (const std::uint64_t e : edges(d, closed)) {
            g.segment(f(d.vertices[e >> 32]), f(d.vertices[e & 0xffffffffu]));
        }
        extra(g);
    }
    if (merged > 0) {
        PathGroup g(w, "#e67e22", 1.5);
        for (std::size_t v = 0; v < voronoi_vertices; ++v) {
            if (distinct_sites(v) >= 4) g.ring(f(d.vertices[v]), 2 * r + 2);
        }
    }
    if (voronoi_vertices > 0) {
        PathGroup g(w, "#3b5b92", 1.25 * r);
        for (std::size_t v = 0; v < voronoi_vertices; ++v) g.dot(f(d.vertices[v]));
    }
    {
        PathGroup g(w, "#111", 2 * r);
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (!repeated[i] && (drawn_sites.empty() || drawn_sites[i])) g.dot(f(points[i]));
        }
    }
    w.text("</svg>\n");
}

// The picture's direction of a plane vector (y flipped), scaled to at most 1 per
// component so that huge and tiny vectors alike stay finite and nonzero.
XY direction(Point2 v) {
    const double m = std::max(std::abs(v.x), std::abs(v.y));
    return m > 0 ? XY{v.x / m, -v.y / m} : XY{0, 0};
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
    const Picture f(xmin, ymin, xmax, ymax, 0.08, 0.5);
    const std::vector<std::uint8_t> repeated = repeated_points(points);
    const auto bounded = [&](std::size_t i) { return !d.unbounded[i]; };
    const auto rays_and_bisectors = [&](PathGroup& g) {
        XY a{}, b{};
        // Each hull edge's ray is the exit ray of the cell it ends in (and the entry ray
        // of the next): the exit rays draw each once.
        for (std::size_t i = 0; i < d.site_count(); ++i) {
            const auto c = d.cell(i);
            const XY u = direction(d.exit_ray[i]);
            if (repeated[i] || !d.unbounded[i] || c.empty() || (u.x == 0 && u.y == 0)) continue;
            if (f.clip(f(d.vertices[c.back()]), u, 0, a, b)) g.segment(a, b);
        }
        // Collinear: the perpendicular bisector of each pair of neighbours on the line.
        for (std::size_t k = 1; k < d.chain.size(); ++k) {
            const XY p = f(points[d.chain[k - 1]]), q = f(points[d.chain[k]]);
            const XY u{p.y - q.y, q.x - p.x};
            if (u.x == 0 && u.y == 0) continue;  // too close to tell apart in the picture
            const XY m{p.x / 2 + q.x / 2, p.y / 2 + q.y / 2};
            if (f.clip(m, u, -std::numeric_limits<double>::infinity(), a, b)) g.segment(a, b);
        }
    };
    draw(out, points, d, d.vertex_count(), f, bounded, rays_and_bisectors, repeated, {});
}

void write_svg(std::ostream& out, std::span<const Point2> points, const ClippedVoronoi& d,
               const Box& box) {
    const Picture f(box.xmin, box.ymin, box.xmax, box.ymax, 0, 0);
    std::vector<std::uint8_t> inside(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Point2 p = points[i];
        inside[i] = p.x >= box.xmin && p.x <= box.xmax && p.y >= box.ymin && p.y <= box.ymax;
    }
    const auto frame = [&](PathGroup& g) {
        g.rectangle(f({box.xmin, box.ymax}), f({box.xmax, box.ymin}));
    };
    // A clipped cell is a closed polygon.
    draw(
        out, points, d, d.voronoi_vertex_count, f, [](std::size_t) { return true; }, frame,
        repeated_points(points), inside);
}

// ".json" -> "json"; empty when `path` has no extension.
std::string_view extension(std::string_view path) {
    const std::size_t dot = path.rfind('.'), slash = path.rfind('/');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash))
        return {};
    return path.substr(dot + 1);
}

}  // namespace

std::string_view to_string(VoronoiFormat f) noexcept {
    return f == VoronoiFormat::svg ? "svg" : "json";
}

std::optional<VoronoiFormat> voronoi_format_from_name(std::string_view name) {
    if (name == "json") return VoronoiFormat::json;
    if (name == "svg") return VoronoiFormat::svg;
    return std::nullopt;
}

std::optional<VoronoiFormat> voronoi_format_from_path(std::string_view path) {
    return voronoi_format_from_name(extension(path));
}

void write_voronoi(std::ostream& out, std::span<const Point2> points, const VoronoiDiagram& diagram,
                   VoronoiFormat format) {
    if (format == VoronoiFormat::svg) return write_svg(out, points, diagram);
    write_json(out, diagram);
}

void write_voronoi(std::ostream& out, std::span<const Point2> points, const ClippedVoronoi& diagram,
                   const Box& box, VoronoiFormat format) {
    if (format == VoronoiFormat::svg) return write_svg(out, points, diagram, box);
    write_json(out, diagram);
}

}  // namespace exidel::io
