// exidel tests: CGAL's Delaunay triangulation as the oracle, the edge sets compared with
// it, and the point-set generator shared by the delaunay tests.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <ostream>
#include <random>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <rapidcheck.h>

#include "cgal_oracle.hpp"
#include "instances.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/testing/all.hpp"

namespace exidel::test {

using Edge = std::pair<std::uint32_t, std::uint32_t>;  // (smaller, larger) input index
using Tri = std::array<std::uint32_t, 3>;              // sorted vertex triple

// Recomputes every twin from the triangles (used after editing triangles by hand).
inline void rebuild_twins(delaunay::Triangulation& t) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::int32_t> by_edge;
    for (std::size_t e = 0; e < t.triangles.size(); ++e) {
        by_edge[{t.triangles[e], t.triangles[delaunay::next_halfedge(e)]}] =
            static_cast<std::int32_t>(e);
    }
    for (std::size_t e = 0; e < t.triangles.size(); ++e) {
        const auto it = by_edge.find({t.triangles[delaunay::next_halfedge(e)], t.triangles[e]});
        t.halfedges[e] = it == by_edge.end() ? -1 : it->second;
    }
}

inline Edge make_edge(std::uint32_t a, std::uint32_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }
inline Tri make_tri(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    Tri t{a, b, c};
    std::sort(t.begin(), t.end());
    return t;
}

/// The edges every Delaunay triangulation of the points contains: hull edges and interior
/// edges whose quadrilateral is not cocircular (decided by CGAL, exactly). Cocircular
/// quadrilaterals may be split either way; these edges may not differ.
struct EdgeSets {
    bool collinear = false;
    std::set<Edge> forced;
    std::set<Tri> triangles;
    std::size_t free_edges = 0;  ///< interior edges of cocircular quadrilaterals
};

/// For every input index, the smallest input index at the same coordinates (computed
/// here independently of the library).
inline std::vector<std::uint32_t> first_occurrence(std::span<const Point2> points) {
    std::map<std::pair<double, double>, std::uint32_t> seen;  // -0.0 and 0.0 compare equal
    std::vector<std::uint32_t> first(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        first[i] = seen.try_emplace({points[i].x, points[i].y}, i).first->second;
    }
    return first;
}

inline EdgeSets cgal_edge_sets(std::span<const Point2> points) {
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Epick>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb>;
    using DT = CGAL::Delaunay_triangulation_2<Epick, Tds>;
    const auto first = first_occurrence(points);
    std::vector<std::pair<Epick::Point_2, std::uint32_t>> input;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        input.emplace_back(to_cgal(points[i]), first[i]);
    DT dt(input.begin(), input.end());
    EdgeSets s;
    s.collinear = dt.dimension() < 2;
    if (s.collinear) return s;
    const auto P = [&](DT::Vertex_handle v) { return points[v->info()]; };
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
        const auto f = e->first;
        const int i = e->second;
        const auto a = f->vertex(f->cw(i)), b = f->vertex(f->ccw(i));
        const auto c = f->vertex(i), d = dt.mirror_vertex(f, i);
        const bool hull = dt.is_infinite(c) || dt.is_infinite(d);
        if (hull || cgal_incircle(P(a), P(b), P(c), P(d)) != Sign::zero) {
            s.forced.insert(make_edge(a->info(), b->info()));
        } else {
            ++s.free_edges;
        }
    }
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
        s.triangles.insert(
            make_tri(f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()));
    }
    return s;
}

inline EdgeSets edge_sets(std::span<const Point2> points, const delaunay::Triangulation& t) {
    EdgeSets s;
    s.collinear = t.collinear;
    const auto& T = t.triangles;
    const auto& H = t.halfedges;
    for (std::size_t e = 0; e < H.size(); ++e) {
        const std::uint32_t a = T[e], b = T[delaunay::next_halfedge(e)];
        if (H[e] < 0) {
            s.forced.insert(make_edge(a, b));
            continue;
        }
        const auto tw = static_cast<std::size_t>(H[e]);
        if (tw < e) continue;
        const std::uint32_t c = T[delaunay::prev_halfedge(e)], d = T[delaunay::prev_halfedge(tw)];
        if (cgal_incircle(points[a], points[b], points[c], points[d]) != Sign::zero) {
            s.forced.insert(make_edge(a, b));
        } else {
            ++s.free_edges;
        }
    }
    for (std::size_t e = 0; e < T.size(); e += 3)
        s.triangles.insert(make_tri(T[e], T[e + 1], T[e + 2]));
    return s;
}

/// A point set with the name of the family it came from (printed with counterexamples).
struct PointSet {
    std::string family;
    std::vector<Point2> points;
};

inline void showValue(const PointSet& s, std::ostream& os) {
    os << s.family << ", " << s.points.size() << " points:\n";
    for (const Point2& p : s.points) {
        exidel::showValue(p, os);
        os << "\n";
    }
}

/// n points from a standard normal distribution (seeded; the generator shrinks the seed).
/// n points uniform in the unit square, the same on every platform (the 53 high bits of
/// mt19937_64, whose sequence the standard fixes; uniform_real_distribution is not).
inline std::vector<Point2> uniform_points(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const auto unit = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
    std::vector<Point2> p(n);
    for (Point2& q : p) {
        q.x = unit();
        q.y = unit();
    }
    return p;
}

/// The queries that matter: every input point, the midpoints of the edges (on the edge when
/// the midpoint is exact), points beyond the ends of hull edges on their lines, the
/// points mirrored through others, and random points of the bounding box and far outside.
inline std::vector<Point2> degenerate_queries(std::span<const Point2> points,
                                              const delaunay::Triangulation& t,
                                              std::uint64_t seed) {
    std::vector<Point2> q(points.begin(), points.end());
    const auto& T = t.triangles;
    for (std::size_t e = 0; e < T.size(); e += 2) {
        const Point2 a = points[T[e]], b = points[T[delaunay::next_halfedge(e)]];
        q.push_back({a.x * 0.5 + b.x * 0.5, a.y * 0.5 + b.y * 0.5});
        if (t.halfedges[e] < 0) q.push_back({2 * b.x - a.x, 2 * b.y - a.y});
    }
    if (t.collinear && t.hull.size() >= 2) {
        const Point2 a = points[t.hull.front()], b = points[t.hull.back()];
        q.push_back({2 * b.x - a.x, 2 * b.y - a.y});
        q.push_back({2 * a.x - b.x, 2 * a.y - b.y});
        for (std::size_t i = 0; i + 1 < t.hull.size(); ++i) {
            const Point2 u = points[t.hull[i]], v = points[t.hull[i + 1]];
            q.push_back({u.x * 0.5 + v.x * 0.5, u.y * 0.5 + v.y * 0.5});
        }
    }
    double lo_x = 0, hi_x = 1, lo_y = 0, hi_y = 1;
    if (!points.empty()) {
        lo_x = hi_x = points[0].x;
        lo_y = hi_y = points[0].y;
        for (const Point2& p : points) {
            lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
            lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
        }
    }
    const auto random = uniform_points(16, seed);
    for (const Point2& r : random) {
        q.push_back({lo_x + (hi_x - lo_x) * r.x, lo_y + (hi_y - lo_y) * r.y});
    }
    q.push_back({hi_x + (hi_x - lo_x) + 1, hi_y});
    q.push_back({lo_x - 1e300, lo_y});
    for (std::size_t i = 0; i + 1 < points.size() && i < 8; ++i) {
        q.push_back({2 * points[i + 1].x - points[i].x, 2 * points[i + 1].y - points[i].y});
    }
    std::vector<Point2> finite;
    for (const Point2& p : q) {
        if (std::isfinite(p.x) && std::isfinite(p.y)) finite.push_back(p);
    }
    return finite;
}

inline std::vector<Point2> gaussian_points(std::uint64_t seed, std::size_t n) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> d(0.0, 1.0);
    std::vector<Point2> p(n);
    for (auto& q : p) q = {d(rng), d(rng)};
    return p;
}

/// The family names of gen_point_set beyond exidel::testing's predicate families:
/// "gaussian", "mixed" (points of two families together, e.g. a collinear run followed by
/// scattered points, which exercises the seed fan with k1 > 3), and the realistic families
/// of exidel/testing/point_sets.hpp (places, coastlines, quantized borders, a LiDAR
/// lattice, blue noise, GPS tracks), drawn from a random seed.
inline std::vector<std::string> point_set_family_names() {
    std::vector<std::string> names;
    for (const auto& f : testing::all_families()) names.emplace_back(f.name);
    names.emplace_back("gaussian");
    names.emplace_back("mixed");
    for (const auto& f : testing::realistic_families()) names.emplace_back(f.name);
    return names;
}

inline rc::Gen<std::vector<Point2>> gen_family_points(const std::string& family, std::size_t n) {
    for (const auto& f : testing::realistic_families()) {
        if (family == f.name) {
            return rc::gen::map(rc::gen::arbitrary<std::uint64_t>(),
                                [n, r = f.family](std::uint64_t seed) {
                                    return testing::realistic_points(r, n, seed);
                                });
        }
    }
    if (family == "gaussian") {
        return rc::gen::map(rc::gen::arbitrary<std::uint32_t>(),
                            [n](std::uint32_t seed) { return gaussian_points(seed, n); });
    }
    if (family == "mixed") {
        return rc::gen::exec([n] {
            constexpr auto fams = testing::all_families();
            const auto a = fams[*rc::gen::inRange<std::size_t>(0, fams.size())].family;
            const auto b = fams[*rc::gen::inRange<std::size_t>(0, fams.size())].family;
            const std::size_t na = *rc::gen::inRange<std::size_t>(0, n + 1);
            auto p = *testing::gen_points(a, na);
            const auto q = *testing::gen_points(b, n - na);
            p.insert(p.end(), q.begin(), q.end());
            return p;
        });
    }
    return testing::gen_points(testing::family_from_name(family), n);
}

/// A point set of a random family with 0..max_n points; tiny sizes (0..5) a quarter of
/// the time.
inline rc::Gen<PointSet> gen_point_set(std::size_t max_n) {
    return rc::gen::exec([max_n] {
        const auto names = point_set_family_names();
        PointSet s;
        s.family = *rc::gen::elementOf(names);
        const bool tiny = *rc::gen::inRange(0, 4) == 0;
        const std::size_t n = *rc::gen::inRange<std::size_t>(0, (tiny ? 5 : max_n) + 1);
        s.points = *gen_family_points(s.family, n);
        return s;
    });
}

}  // namespace exidel::test
