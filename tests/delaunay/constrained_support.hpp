// exidel tests: the constrained triangulation's oracle, shared by constrained_test.cpp and
// constrained_peers_test.cpp. CGAL's Constrained_Delaunay_triangulation_2 over exact
// constructions (Epeck, Exact_intersections_tag), its vertices and constraint pieces rounded
// to doubles (Shape), exidel's the same way, and whether rounding the exact arrangement
// cascades (then exidel's pieces need not be CGAL's; constrained.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "circumcenter_oracle.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::test {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<Epeck>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Epeck>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Epeck, Tds, CGAL::Exact_intersections_tag>;

/// A point of CGAL's exact triangulation rounded to nearest, coordinate by coordinate.
inline Point2 rounded(const Epeck::Point_2& p) {
    return {round_to_double(CGAL::exact(p.x()).get_mpq_t()),
            round_to_double(CGAL::exact(p.y()).get_mpq_t())};
}

using Pair = std::pair<std::pair<double, double>, std::pair<double, double>>;

inline Pair edge_key(Point2 a, Point2 b) {
    std::pair<double, double> p{a.x, a.y}, q{b.x, b.y};
    if (q < p) std::swap(p, q);
    return {p, q};
}

/// What is compared: the vertices and the constraint pieces, in coordinates.
struct Shape {
    std::set<std::pair<double, double>> vertices;
    std::set<Pair> pieces;
    /// CGAL's only: no rounded crossing point lies exactly on an input segment that its
    /// exact point is not on (exidel would split that segment there).
    bool plain = true;
    bool operator==(const Shape& o) const { return vertices == o.vertices && pieces == o.pieces; }
};

inline Shape cgal_shape(const std::vector<Point2>& points,
                        const std::vector<delaunay::Segment>& segments) {
    Cdt cdt;
    for (const Point2& p : points) cdt.insert(Epeck::Point_2(p.x, p.y));
    for (const delaunay::Segment& s : segments) {
        const Point2 a = points[s.a], b = points[s.b];
        if (a == b) continue;
        cdt.insert_constraint(Epeck::Point_2(a.x, a.y), Epeck::Point_2(b.x, b.y));
    }
    Shape shape;
    const AdaptiveKernel k;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        const Point2 p = rounded(v->point());
        shape.vertices.insert({p.x, p.y});
        for (const delaunay::Segment& s : segments) {
            const Point2 a = points[s.a], b = points[s.b];
            if (a == b || k.orient2d(a, b, p) != Sign::zero) continue;
            const bool inside = a.x != b.x ? std::min(a.x, b.x) < p.x && p.x < std::max(a.x, b.x)
                                           : std::min(a.y, b.y) < p.y && p.y < std::max(a.y, b.y);
            if (inside && CGAL::orientation(Epeck::Point_2(a.x, a.y), Epeck::Point_2(b.x, b.y),
                                            v->point()) != CGAL::COLLINEAR)
                shape.plain = false;
        }
    }
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
        if (!cdt.is_constrained(*e)) continue;
        const auto f = e->first;
        const int i = e->second;
        const Point2 a = rounded(f->vertex(Cdt::cw(i))->point());
        const Point2 b = rounded(f->vertex(Cdt::ccw(i))->point());
        // Two exact crossing points that round to the same double make a piece of length 0.
        if (!(a == b)) shape.pieces.insert(edge_key(a, b));
    }
    return shape;
}

inline Shape our_shape(const delaunay::ConstrainedTriangulation& cdt) {
    Shape shape;
    const auto& t = cdt.triangulation;
    for (std::size_t i = 0; i < cdt.points.size(); ++i)
        if (t.vertex_of_input[i] == i) shape.vertices.insert({cdt.points[i].x, cdt.points[i].y});
    for (const auto& [u, v] : cdt.constraints)
        shape.pieces.insert(edge_key(cdt.points[u], cdt.points[v]));
    return shape;
}

template <class K = AdaptiveKernel>
delaunay::ConstrainedResult run(const std::vector<Point2>& points,
                                const std::vector<delaunay::Segment>& segments,
                                const K& kernel = K{},
                                const delaunay::ConstrainedOptions& options = {}) {
    return delaunay::constrained_delaunay(std::span<const Point2>(points),
                                          std::span<const delaunay::Segment>(segments), kernel,
                                          options);
}

/// Whether rounding CGAL's exact arrangement leaves it an arrangement: no two rounded
/// pieces meet except at a shared end, and no rounded vertex lies on a piece it does not
/// end. Then nothing cascades and exidel's pieces must be exactly these; otherwise a
/// rounded crossing has bent a piece across another or onto a vertex, which exidel
/// resolves by further crossings the exact arrangement does not have (constrained.hpp).
inline bool rounding_keeps_an_arrangement(const Shape& cgal) {
    if (!cgal.plain) return false;
    const AdaptiveKernel k;
    const auto on = [&](Point2 p, Point2 a, Point2 b) {
        return k.orient2d(a, b, p) == Sign::zero && std::min(a.x, b.x) <= p.x &&
               p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
    };
    std::vector<std::pair<Point2, Point2>> pieces;
    for (const auto& [p, q] : cgal.pieces)
        pieces.push_back({{p.first, p.second}, {q.first, q.second}});
    for (const auto& [x, y] : cgal.vertices) {
        const Point2 v{x, y};
        for (const auto& [a, b] : pieces)
            if (!(v == a) && !(v == b) && on(v, a, b)) return false;
    }
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        for (std::size_t j = i + 1; j < pieces.size(); ++j) {
            const auto [a, b] = pieces[i];
            const auto [c, d] = pieces[j];
            if (a == c || a == d || b == c || b == d) continue;
            const int abc = to_int(k.orient2d(a, b, c)), abd = to_int(k.orient2d(a, b, d));
            const int cda = to_int(k.orient2d(c, d, a)), cdb = to_int(k.orient2d(c, d, b));
            if (abc * abd < 0 && cda * cdb < 0) return false;
        }
    }
    return true;
}

/// Whether exidel's output shows no cascade either: every added point is the crossing of
/// two input segments (not of bent pieces), and every inner chain vertex is an input point
/// exactly on its segment or an added point of a crossing of it.
inline bool no_cascade_in(const delaunay::ConstrainedTriangulation& cdt,
                          const std::vector<Point2>& points,
                          const std::vector<delaunay::Segment>& segments) {
    const AdaptiveKernel k;
    for (std::size_t i = 0; i < cdt.crossings.size(); ++i) {
        const auto [s, t] = cdt.crossings[i];
        const auto& l = cdt.crossing_lines[i];
        const auto& v = cdt.triangulation.vertex_of_input;
        const std::array<std::uint32_t, 4> ends{v[segments[s].a], v[segments[s].b],
                                                v[segments[t].a], v[segments[t].b]};
        if (l != ends && l != std::array<std::uint32_t, 4>{ends[2], ends[3], ends[0], ends[1]})
            return false;
    }
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const auto chain = cdt.chain(s);
        for (std::size_t j = 1; j + 1 < chain.size(); ++j) {
            const std::uint32_t x = chain[j];
            if (x < cdt.input_count) {
                if (k.orient2d(points[segments[s].a], points[segments[s].b], points[x]) !=
                    Sign::zero)
                    return false;
            } else {
                const auto [a, b] = cdt.crossings[x - cdt.input_count];
                if (a != s && b != s) return false;
            }
        }
    }
    return true;
}

}  // namespace exidel::test
