// exidel I/O: what write_constrained needs besides the writers of triangulations: the
// domain as a Triangulation, z at the added points, and Triangle's .poly writer
// (exidel/io/constrained.hpp).
#include "exidel/io/constrained.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <ostream>
#include <vector>

#include "exidel/io/points.hpp"
#include "text.hpp"
#include "writers.hpp"

namespace exidel::io {

delaunay::Triangulation domain_triangulation(const delaunay::ConstrainedTriangulation& cdt,
                                             const delaunay::Regions& regions) {
    const delaunay::Triangulation& all = cdt.triangulation;
    const std::size_t n = all.triangle_count();
    // Each inside triangle's new number.
    std::vector<std::int64_t> renumber(n, -1);
    std::size_t kept = 0;
    for (std::size_t t = 0; t < n && t < regions.inside.size(); ++t) {
        if (regions.inside[t]) renumber[t] = static_cast<std::int64_t>(kept++);
    }
    delaunay::Triangulation domain;
    domain.triangles.reserve(3 * kept);
    domain.halfedges.reserve(3 * kept);
    for (std::size_t t = 0; t < n; ++t) {
        if (renumber[t] < 0) continue;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t e = 3 * t + k;
            domain.triangles.push_back(all.triangles[e]);
            const std::int64_t twin = all.halfedges[e];
            const std::int64_t across =
                twin < 0 ? -1 : renumber[static_cast<std::size_t>(twin) / 3];
            domain.halfedges.push_back(
                across < 0
                    ? -1
                    : static_cast<std::int32_t>(3 * across + static_cast<std::int64_t>(twin) % 3));
        }
    }
    domain.vertex_of_input = all.vertex_of_input;
    domain.duplicates = all.duplicates;
    domain.collinear = kept == 0;
    return domain;
}

std::vector<double> constrained_z(const delaunay::ConstrainedTriangulation& cdt,
                                  std::span<const double> input_z) {
    if (input_z.empty()) return {};
    std::vector<double> z(input_z.begin(), input_z.end());
    z.resize(cdt.points.size(), 0.0);
    // z along segment s at the projection of p on it (clamped to the segment).
    const auto along = [&](std::size_t s, Point2 p) {
        const std::span<const std::uint32_t> chain = cdt.chain(s);
        const std::uint32_t a = chain.front(), b = chain.back();
        const Point2 pa = cdt.points[a], pb = cdt.points[b];
        const double dx = pb.x - pa.x, dy = pb.y - pa.y;
        const double length2 = dx * dx + dy * dy;
        double t = length2 > 0 ? ((p.x - pa.x) * dx + (p.y - pa.y) * dy) / length2 : 0.0;
        t = std::clamp(t, 0.0, 1.0);
        return z[a] + t * (z[b] - z[a]);
    };
    for (std::size_t i = 0; i < cdt.added_count(); ++i) {
        const Point2 p = cdt.points[cdt.input_count + i];
        const auto [s, t] = cdt.crossings[i];
        z[cdt.input_count + i] = 0.5 * (along(s, p) + along(t, p));
    }
    return z;
}

namespace detail {

void write_poly(std::ostream& out, std::span<const Point2> points,
                std::span<const std::array<std::uint32_t, 2>> segments,
                std::span<const std::int32_t> markers, std::span<const Point2> holes,
                std::span<const ConstraintFile::Region> regions, unsigned base, unsigned threads) {
    write_points(out, points, PointFormat::node, base, threads);
    out << segments.size() << (markers.empty() ? " 0\n" : " 1\n");
    write_items(out, segments.size(), threads, [&](std::size_t s, TextBuffer& b) {
        b.append(96, [&](char* p) {
            p = put(put(p, std::uint64_t{s} + base), " ");
            p = put(put(p, std::uint64_t{segments[s][0]} + base), " ");
            p = put(p, std::uint64_t{segments[s][1]} + base);
            if (!markers.empty()) {
                const std::int32_t m = markers[s];
                p = put(put(p, m < 0 ? " -" : " "),
                        static_cast<std::uint64_t>(m < 0 ? -static_cast<std::int64_t>(m) : m));
            }
            return put(p, "\n");
        });
    });
    NumberWriter w(out);
    w.number(std::uint64_t{holes.size()}).text("\n");
    for (std::size_t h = 0; h < holes.size(); ++h) {
        w.number(std::uint64_t{h} + base).text(" ").number(holes[h].x).text(" ");
        w.number(holes[h].y).text("\n");
    }
    if (!regions.empty()) {
        w.number(std::uint64_t{regions.size()}).text("\n");
        for (std::size_t r = 0; r < regions.size(); ++r) {
            const ConstraintFile::Region& g = regions[r];
            w.number(std::uint64_t{r} + base).text(" ").number(g.seed.x).text(" ");
            w.number(g.seed.y).text(" ").number(g.attribute).text(" ");
            w.number(g.max_area ? *g.max_area : -1.0).text("\n");
        }
    }
}

}  // namespace detail

}  // namespace exidel::io
