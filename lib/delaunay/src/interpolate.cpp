// exidel: linear interpolation from exact locations (interpolate.hpp says the arithmetic).
#include "exidel/delaunay/interpolate.hpp"

#include <stdexcept>
#include <string>

namespace exidel::delaunay {

namespace {

double cross(Point2 u, Point2 v, Point2 q) {
    return (u.x - q.x) * (v.y - q.y) - (u.y - q.y) * (v.x - q.x);
}

double along(Point2 a, Point2 b, double va, double vb, Point2 q) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t = ((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy);
    return (1 - t) * va + t * vb;
}

}  // namespace

void interpolate_linear(std::span<const Point2> points, const Triangulation& t,
                        std::span<const double> values, std::span<const Point2> queries,
                        std::span<const Location> where, std::span<double> out, double fill) {
    if (values.size() != points.size()) {
        throw std::invalid_argument("interpolate_linear: " + std::to_string(values.size()) +
                                    " values for " + std::to_string(points.size()) + " points");
    }
    if (where.size() != queries.size() || out.size() != queries.size()) {
        throw std::invalid_argument(
            "interpolate_linear: queries, locations and out differ in size");
    }
    const auto& T = t.triangles;
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const Location& w = where[i];
        const Point2 q = queries[i];
        switch (w.kind) {
            case LocationKind::outside: out[i] = fill; break;
            case LocationKind::on_vertex: out[i] = values[w.vertex]; break;
            case LocationKind::on_edge: {
                const auto e = static_cast<std::size_t>(w.edge);
                const std::uint32_t a = t.collinear ? t.hull[e] : T[e];
                const std::uint32_t b = t.collinear ? t.hull[e + 1] : T[next_halfedge(e)];
                out[i] = along(points[a], points[b], values[a], values[b], q);
                break;
            }
            case LocationKind::inside: {
                const std::size_t base = 3 * static_cast<std::size_t>(w.triangle);
                const std::uint32_t a = T[base], b = T[base + 1], c = T[base + 2];
                const Point2 pa = points[a], pb = points[b], pc = points[c];
                const double A = cross(pb, pc, q), B = cross(pc, pa, q), C = cross(pa, pb, q);
                const double sum = A + B + C;
                // A triangle too thin for its rounded area: a segment, in doubles.
                out[i] = sum != 0 ? (A * values[a] + B * values[b] + C * values[c]) / sum
                                  : along(pa, pb, values[a], values[b], q);
                break;
            }
        }
    }
}

}  // namespace exidel::delaunay
