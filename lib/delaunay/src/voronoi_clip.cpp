// exidel: the Voronoi diagram clipped to a box, in exact rationals (voronoi.hpp, clip()).
//
// A cell whose vertices are all strictly inside the box and which is bounded lies inside
// it (it is convex), and keeps its vertices. (A correctly rounded coordinate strictly
// inside the box's bounds has its exact value strictly inside too: rounding is monotone
// and the bounds are doubles.) Every other cell is computed as the box cut by the
// half-planes of its neighbours (Sutherland-Hodgman), every corner an exact rational point
// with the set of lines it lies on: a corner on two bisectors is a Voronoi vertex (the
// centre of the site and both neighbours), any other corner is a point the box adds.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "exidel/delaunay/voronoi.hpp"
#include "rational.hpp"

namespace exidel::delaunay {

namespace {

using detail::Rational;
using detail::round_rational;

/// A line's tag: a neighbour's input index (the bisector of the site and that neighbour)
/// or one of the box's sides.
using Line = std::int64_t;
constexpr Line box_side(int k) { return -1 - k; }  // k = 0 bottom, 1 right, 2 top, 3 left

struct Corner {
    Rational x, y;
    std::vector<Line> on;  // every line the corner lies on
};

bool same_point(const Corner& a, const Corner& b) { return a.x == b.x && a.y == b.y; }

/// The half-plane a x + b y <= c.
struct HalfPlane {
    Rational a, b, c;
    Line line;
    Rational value(const Corner& p) const { return a * p.x + b * p.y - c; }
};

/// Points at least as close to s as to q: 2 (q - s) . x <= |q|^2 - |s|^2.
HalfPlane closer_to(Point2 s, Point2 q, Line line) {
    const Rational sx(s.x), sy(s.y), qx(q.x), qy(q.y);
    return {2 * (qx - sx), 2 * (qy - sy), qx * qx + qy * qy - sx * sx - sy * sy, line};
}

/// The line shared by two consecutive corners (the edge between them lies on it).
Line shared_line(const Corner& p, const Corner& q) {
    for (const Line l : p.on)
        if (std::find(q.on.begin(), q.on.end(), l) != q.on.end()) return l;
    return box_side(0);  // unreachable for a polygon built by cut() (every edge has a line)
}

/// Sutherland-Hodgman: the part of convex polygon `poly` in half-plane h.
std::vector<Corner> cut(const std::vector<Corner>& poly, const HalfPlane& h) {
    std::vector<Corner> out;
    const std::size_t m = poly.size();
    std::vector<Rational> f(m);
    for (std::size_t k = 0; k < m; ++k) f[k] = h.value(poly[k]);
    for (std::size_t k = 0; k < m; ++k) {
        const Corner& p = poly[k];
        const Corner& q = poly[(k + 1) % m];
        const Rational& fp = f[k];
        const Rational& fq = f[(k + 1) % m];
        if (fp <= 0) {
            out.push_back(p);
            if (fp == 0) out.back().on.push_back(h.line);
        }
        if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
            const Rational t = fp / (fp - fq);
            out.push_back(
                {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), {shared_line(p, q), h.line}});
        }
    }
    // Merge repeated points (a cut through a corner); fewer than three corners is empty.
    std::vector<Corner> merged;
    for (Corner& c : out) {
        if (!merged.empty() && same_point(merged.back(), c)) {
            merged.back().on.insert(merged.back().on.end(), c.on.begin(), c.on.end());
        } else {
            merged.push_back(std::move(c));
        }
    }
    while (merged.size() > 1 && same_point(merged.front(), merged.back())) {
        merged.front().on.insert(merged.front().on.end(), merged.back().on.begin(),
                                 merged.back().on.end());
        merged.pop_back();
    }
    if (merged.size() < 3) merged.clear();
    return merged;
}

}  // namespace

ClippedVoronoi clip(const VoronoiDiagram& d, std::span<const Point2> points, const Triangulation& t,
                    const Box& box) {
    if (!(std::isfinite(box.xmin) && std::isfinite(box.ymin) && std::isfinite(box.xmax) &&
          std::isfinite(box.ymax) && box.xmin < box.xmax && box.ymin < box.ymax))
        throw std::invalid_argument(
            "clip: the box must be finite with xmin < xmax and ymin < ymax");
    const std::size_t n = points.size();
    const auto inside = [&](Point2 p) {
        return box.xmin < p.x && p.x < box.xmax && box.ymin < p.y && p.y < box.ymax;
    };
    const std::vector<Corner> frame = {
        {Rational(box.xmin), Rational(box.ymin), {box_side(3), box_side(0)}},
        {Rational(box.xmax), Rational(box.ymin), {box_side(0), box_side(1)}},
        {Rational(box.xmax), Rational(box.ymax), {box_side(1), box_side(2)}},
        {Rational(box.xmin), Rational(box.ymax), {box_side(2), box_side(3)}},
    };

    // A corner of an output cell: Voronoi vertex v (ref = v) or added point a
    // (ref = voronoi_count + a), renumbered at the end.
    const std::size_t voronoi_count = d.vertex_count();
    std::map<std::pair<Rational, Rational>, std::uint32_t> added_index;
    std::vector<Point2> added_points;
    std::vector<std::vector<std::uint32_t>> added_sites;
    std::vector<std::vector<std::uint32_t>> cell_of_site(n);  // first occurrences only

    // The chain neighbours of a collinear diagram.
    std::vector<std::uint32_t> chain_position(n, 0);
    for (std::size_t k = 0; k < d.chain.size(); ++k)
        chain_position[d.chain[k]] = static_cast<std::uint32_t>(k);

    std::vector<std::uint32_t> neighbours;
    for (std::size_t s = 0; s < n; ++s) {
        if (t.vertex_of_input[s] != s) continue;
        const auto cell = d.cell(s);
        std::vector<std::uint32_t>& out = cell_of_site[s];
        if (!d.collinear && d.unbounded[s] == 0 &&
            std::all_of(cell.begin(), cell.end(),
                        [&](std::uint32_t v) { return inside(d.vertices[v]); })) {
            out.assign(cell.begin(), cell.end());
            continue;
        }
        neighbours.clear();
        if (d.collinear) {
            const std::size_t k = chain_position[s];
            if (k > 0) neighbours.push_back(d.chain[k - 1]);
            if (k + 1 < d.chain.size()) neighbours.push_back(d.chain[k + 1]);
        } else {
            for (const std::uint32_t v : cell)
                for (const std::uint32_t q : d.vertex_sites(v))
                    if (t.vertex_of_input[q] == q && q != s) neighbours.push_back(q);
            std::sort(neighbours.begin(), neighbours.end());
            neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
        }
        std::vector<Corner> poly = frame;
        for (const std::uint32_t q : neighbours) {
            poly = cut(poly, closer_to(points[s], points[q], static_cast<Line>(q)));
            if (poly.empty()) break;
        }
        for (const Corner& c : poly) {
            // On two bisectors (s, j) and (s, k): the Voronoi vertex of s, j and k.
            std::vector<std::uint32_t> bisectors;
            for (const Line l : c.on)
                if (l >= 0) bisectors.push_back(static_cast<std::uint32_t>(l));
            std::sort(bisectors.begin(), bisectors.end());
            bisectors.erase(std::unique(bisectors.begin(), bisectors.end()), bisectors.end());
            std::uint32_t ref = 0xffffffffu;
            if (bisectors.size() >= 2) {
                for (const std::uint32_t v : cell) {
                    const auto sites = d.vertex_sites(v);
                    const auto has = [&](std::uint32_t q) {
                        return std::find(sites.begin(), sites.end(), q) != sites.end();
                    };
                    if (has(bisectors[0]) && has(bisectors[1])) {
                        ref = v;
                        break;
                    }
                }
            }
            if (ref == 0xffffffffu) {
                const auto [it, fresh] = added_index.emplace(
                    std::pair{c.x, c.y}, static_cast<std::uint32_t>(added_points.size()));
                if (fresh) {
                    added_points.push_back({round_rational(c.x), round_rational(c.y)});
                    added_sites.emplace_back();
                }
                added_sites[it->second].push_back(static_cast<std::uint32_t>(s));
                ref = static_cast<std::uint32_t>(voronoi_count + it->second);
            }
            out.push_back(ref);
        }
    }

    // Number the Voronoi vertices that appear, in their order, then the added points.
    ClippedVoronoi r;
    std::vector<std::uint32_t> new_index(voronoi_count + added_points.size(), 0xffffffffu);
    for (std::size_t s = 0; s < n; ++s)
        for (const std::uint32_t ref : cell_of_site[s])
            if (ref < voronoi_count) new_index[ref] = 0;
    // Duplicates of each first occurrence, to list them beside it.
    std::vector<std::vector<std::uint32_t>> copies(n);
    for (const std::uint32_t dup : t.duplicates) copies[t.vertex_of_input[dup]].push_back(dup);
    for (std::size_t v = 0; v < voronoi_count; ++v) {
        if (new_index[v] == 0xffffffffu) continue;
        new_index[v] = static_cast<std::uint32_t>(r.vertices.size());
        r.vertices.push_back(d.vertices[v]);
        const auto sites = d.vertex_sites(v);
        r.sites.insert(r.sites.end(), sites.begin(), sites.end());
        r.site_offsets.push_back(static_cast<std::uint32_t>(r.sites.size()));
    }
    r.voronoi_vertex_count = r.vertices.size();
    for (std::size_t a = 0; a < added_points.size(); ++a) {
        new_index[voronoi_count + a] = static_cast<std::uint32_t>(r.vertices.size());
        r.vertices.push_back(added_points[a]);
        std::vector<std::uint32_t> sites;
        for (const std::uint32_t s : added_sites[a]) {
            sites.push_back(s);
            sites.insert(sites.end(), copies[s].begin(), copies[s].end());
        }
        std::sort(sites.begin(), sites.end());
        r.sites.insert(r.sites.end(), sites.begin(), sites.end());
        r.site_offsets.push_back(static_cast<std::uint32_t>(r.sites.size()));
    }
    r.unbounded = d.unbounded;
    for (std::size_t i = 0; i < n; ++i) {
        for (const std::uint32_t ref : cell_of_site[t.vertex_of_input[i]])
            r.cell_vertices.push_back(new_index[ref]);
        r.cell_offsets.push_back(static_cast<std::uint32_t>(r.cell_vertices.size()));
    }
    return r;
}

}  // namespace exidel::delaunay
