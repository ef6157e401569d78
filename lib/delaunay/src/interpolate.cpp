// exidel: linear interpolation from exact locations (interpolate.hpp says the arithmetic).
#include "exidel/delaunay/interpolate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace exidel::delaunay {

namespace {

double cross(Point2 u, Point2 v, Point2 q) {
    return (u.x - q.x) * (v.y - q.y) - (u.y - q.y) * (v.x - q.x);
}

/// The points scaled by one power of two when the largest coordinate is beyond 2^500 or,
/// not zero, below 2^-400: then differences stay below 1 and their products can neither
/// overflow nor, for differences near the largest, underflow. Exact, but for coordinates
/// far below the largest, which may lose low bits when scaling down. The weights are
/// ratios, the same for any common scale.
template <std::size_t N>
void fit(std::array<Point2, N>& p) {
    double m = 0;
    for (const Point2& v : p) m = std::max({m, std::fabs(v.x), std::fabs(v.y)});
    if (!(m > 0x1p500) && !(m < 0x1p-400 && m > 0)) return;
    const int e = -(std::ilogb(m) + 2);
    for (Point2& v : p) v = {std::ldexp(v.x, e), std::ldexp(v.y, e)};
}

double along(Point2 a, Point2 b, double va, double vb, Point2 q) {
    std::array<Point2, 3> p{a, b, q};
    fit(p);
    const double dx = p[1].x - p[0].x, dy = p[1].y - p[0].y;
    const double t = ((p[2].x - p[0].x) * dx + (p[2].y - p[0].y) * dy) / (dx * dx + dy * dy);
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
                std::array<Point2, 4> p{points[a], points[b], points[c], q};
                fit(p);
                const auto [pa, pb, pc, s] = p;
                const double A = cross(pb, pc, s), B = cross(pc, pa, s), C = cross(pa, pb, s);
                const double sum = A + B + C;
                // A triangle too thin for its rounded area: a segment, in doubles.
                out[i] = sum != 0 ? (A * values[a] + B * values[b] + C * values[c]) / sum
                                  : along(pa, pb, values[a], values[b], s);
                break;
            }
        }
    }
}

}  // namespace exidel::delaunay
