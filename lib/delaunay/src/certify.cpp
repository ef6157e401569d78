// exidel: the certifier (see certify.hpp for what is checked and why it suffices).
#include "exidel/delaunay/certify.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <numeric>
#include <string>

#include "certify_mesh.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::delaunay {

std::string_view to_string(FindingKind kind) noexcept {
    switch (kind) {
        case FindingKind::bad_shape: return "bad_shape";
        case FindingKind::index_out_of_range: return "index_out_of_range";
        case FindingKind::twin_mismatch: return "twin_mismatch";
        case FindingKind::degenerate_triangle: return "degenerate_triangle";
        case FindingKind::not_ccw: return "not_ccw";
        case FindingKind::boundary_broken: return "boundary_broken";
        case FindingKind::hull_mismatch: return "hull_mismatch";
        case FindingKind::boundary_not_convex: return "boundary_not_convex";
        case FindingKind::boundary_winding: return "boundary_winding";
        case FindingKind::missing_point: return "missing_point";
        case FindingKind::duplicate_vertex: return "duplicate_vertex";
        case FindingKind::bad_vertex_map: return "bad_vertex_map";
        case FindingKind::wrong_triangle_count: return "wrong_triangle_count";
        case FindingKind::not_delaunay: return "not_delaunay";
        case FindingKind::collinear_mismatch: return "collinear_mismatch";
        case FindingKind::input_mismatch: return "input_mismatch";
        case FindingKind::added_point_wrong: return "added_point_wrong";
        case FindingKind::chain_broken: return "chain_broken";
        case FindingKind::chain_off_segment: return "chain_off_segment";
        case FindingKind::constraints_mismatch: return "constraints_mismatch";
        case FindingKind::non_finite_input: return "non_finite_input";
    }
    return "unknown";
}

bool Certificate::has(FindingKind kind) const noexcept {
    return std::any_of(findings.begin(), findings.end(),
                       [kind](const Finding& f) { return f.kind == kind; });
}

std::string Certificate::summary() const {
    std::string s;
    for (const Finding& f : findings) s += std::string(to_string(f.kind)) + ": " + f.message + "\n";
    if (total_findings > findings.size()) {
        s += "... " + std::to_string(total_findings - findings.size()) + " more\n";
    }
    return s;
}

namespace {

using K = AdaptiveKernel;

bool lex_less(Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

bool finite(double v) {
    constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
    return (std::bit_cast<std::uint64_t>(v) & exponent) != exponent;
}

class Certifier {
public:
    Certifier(std::span<const Point2> points, const Triangulation& tri, std::size_t max_findings,
              std::span<const std::array<std::uint32_t, 2>> exempt = {})
        : pts_(points), tri_(tri), max_findings_(max_findings), exempt_(exempt) {}

    Certificate run() {
        for (std::size_t i = 0; i < pts_.size(); ++i) {
            if (!finite(pts_[i].x) || !finite(pts_[i].y)) {
                add(FindingKind::non_finite_input, i, -1, -1, {i},
                    "point " + str(i) + " has a non-finite coordinate");
                return std::move(cert_);
            }
        }
        group_points();
        check_vertex_map();
        if (tri_.collinear) {
            check_collinear();
        } else if (check_shape() && check_topology() && check_orientation()) {
            const bool boundary = check_boundary();
            check_vertices();
            if (boundary) check_count();
            check_delaunay();
        }
        return std::move(cert_);
    }

    /// After run(): the first occurrence of every point (empty if a point is not finite).
    std::vector<std::uint32_t> take_first() { return std::move(first_); }

private:
    using Ids = detail::FindingPoints;

    template <class I, class J>
    void add(FindingKind kind, I index, J other, std::int64_t triangle, Ids points,
             std::string message) {
        ++cert_.total_findings;
        if (cert_.findings.size() < max_findings_) {
            cert_.findings.push_back({kind, static_cast<std::int64_t>(index),
                                      static_cast<std::int64_t>(other), std::move(message),
                                      triangle, std::move(points.v)});
        }
    }

    template <class I>
    static std::string str(I i) {
        return std::to_string(i);
    }
    // "triangle 18 (4, 9, 2)": the triangle of half-edge or corner e, its vertices as listed.
    std::string triangle_name(std::size_t t) const {
        const auto& T = tri_.triangles;
        return "triangle " + str(t) + " (" + str(T[3 * t]) + ", " + str(T[3 * t + 1]) + ", " +
               str(T[3 * t + 2]) + ")";
    }
    // "edge (4, 9) of triangle 18 (4, 9, 2)": half-edge e from its vertex to the next.
    std::string edge_name(std::size_t e) const {
        const auto& T = tri_.triangles;
        return "edge (" + str(T[e]) + ", " + str(T[next_halfedge(e)]) + ") of " +
               triangle_name(e / 3);
    }
    std::int64_t vertex(std::size_t e) const { return tri_.triangles[e]; }

    // first_[i]: smallest input index with the coordinates of point i; order_: the
    // distinct first occurrences in lexicographic order.
    void group_points() {
        std::vector<std::uint32_t> idx(pts_.size());
        std::iota(idx.begin(), idx.end(), 0u);
        std::sort(idx.begin(), idx.end(), [&](std::uint32_t a, std::uint32_t b) {
            if (pts_[a] == pts_[b]) return a < b;
            return lex_less(pts_[a], pts_[b]);
        });
        first_.assign(pts_.size(), 0);
        for (std::size_t j = 0; j < idx.size(); ++j) {
            if (j > 0 && pts_[idx[j]] == pts_[idx[j - 1]]) {
                first_[idx[j]] = first_[idx[j - 1]];
            } else {
                first_[idx[j]] = idx[j];
                order_.push_back(idx[j]);
            }
        }
    }

    void check_vertex_map() {
        if (tri_.vertex_of_input.empty() && tri_.duplicates.empty()) return;  // not provided
        if (tri_.vertex_of_input.size() != pts_.size()) {
            add(FindingKind::bad_vertex_map, tri_.vertex_of_input.size(), pts_.size(), -1, {},
                "vertex_of_input has " + str(tri_.vertex_of_input.size()) + " entries for " +
                    str(pts_.size()) + " points");
            return;
        }
        std::vector<std::uint32_t> dups;
        for (std::size_t i = 0; i < pts_.size(); ++i) {
            if (tri_.vertex_of_input[i] != first_[i]) {
                add(FindingKind::bad_vertex_map, i, tri_.vertex_of_input[i], -1,
                    {static_cast<std::int64_t>(i), tri_.vertex_of_input[i], first_[i]},
                    "point " + str(i) + " maps to " + str(tri_.vertex_of_input[i]) + ", not to " +
                        str(first_[i]) + ", the first occurrence of its coordinates");
            }
            if (first_[i] != i) dups.push_back(static_cast<std::uint32_t>(i));
        }
        if (dups != tri_.duplicates) {
            const auto [mine, theirs] = std::mismatch(
                dups.begin(), dups.end(), tri_.duplicates.begin(), tri_.duplicates.end());
            const std::int64_t where = mine != dups.end()                ? *mine
                                       : theirs != tri_.duplicates.end() ? *theirs
                                                                         : -1;
            add(FindingKind::bad_vertex_map, dups.size(), tri_.duplicates.size(), -1, {where},
                "duplicates lists " + str(tri_.duplicates.size()) + " points where " +
                    str(dups.size()) + " repeat an earlier one; first difference at point " +
                    str(where));
        }
    }

    void check_collinear() {
        if (!tri_.triangles.empty() || !tri_.halfedges.empty()) {
            add(FindingKind::collinear_mismatch, tri_.triangles.size(), -1, -1, {},
                "marked collinear but has " + str(tri_.triangles.size()) + " triangle entries");
        }
        if (order_.size() >= 3) {
            const Point2 lo = pts_[order_.front()], hi = pts_[order_.back()];
            for (std::uint32_t v : order_) {
                if (K::orient2d(lo, hi, pts_[v]) != Sign::zero) {
                    add(FindingKind::collinear_mismatch, v, -1, -1, {v},
                        "marked collinear but point " + str(v) + " is off the line through " +
                            str(order_.front()) + " and " + str(order_.back()));
                    return;
                }
            }
        }
        if (tri_.hull != order_) {
            const std::size_t j = first_difference(tri_.hull, order_);
            add(FindingKind::hull_mismatch, j, -1, -1, {},
                "the collinear chain differs from the " + str(order_.size()) +
                    " distinct points in lexicographic order at position " + str(j));
        }
    }

    bool check_shape() {
        const std::size_t before = cert_.total_findings;
        if (order_.size() < 3) {
            add(FindingKind::collinear_mismatch, order_.size(), -1, -1, {},
                "only " + str(order_.size()) +
                    " distinct points, yet there are triangles (no triangles is right)");
        }
        if (tri_.triangles.size() % 3 != 0 || tri_.halfedges.size() != tri_.triangles.size()) {
            add(FindingKind::bad_shape, tri_.triangles.size(), tri_.halfedges.size(), -1, {},
                str(tri_.triangles.size()) + " triangle entries and " + str(tri_.halfedges.size()) +
                    " halfedges: triangles must hold 3 entries per triangle and halfedges as "
                    "many");
            return false;
        }
        const auto size = static_cast<std::int64_t>(tri_.halfedges.size());
        for (std::size_t e = 0; e < tri_.triangles.size(); ++e) {
            if (tri_.triangles[e] >= pts_.size()) {
                add(FindingKind::index_out_of_range, e, tri_.triangles[e],
                    static_cast<std::int64_t>(e / 3), {},
                    triangle_name(e / 3) + ": vertex " + str(tri_.triangles[e]) +
                        " is out of range (" + str(pts_.size()) + " points)");
            }
            if (tri_.halfedges[e] < -1 || tri_.halfedges[e] >= size) {
                add(FindingKind::index_out_of_range, e, tri_.halfedges[e],
                    static_cast<std::int64_t>(e / 3), {},
                    "half-edge " + str(e) + " of triangle " + str(e / 3) + ": twin " +
                        str(tri_.halfedges[e]) + " is out of range");
            }
        }
        for (std::size_t j = 0; j < tri_.hull.size(); ++j) {
            if (tri_.hull[j] >= pts_.size()) {
                add(FindingKind::index_out_of_range, j, tri_.hull[j], -1, {},
                    "hull position " + str(j) + ": point " + str(tri_.hull[j]) +
                        " is out of range (" + str(pts_.size()) + " points)");
            }
        }
        return cert_.total_findings == before;
    }

    bool check_topology() {
        const std::size_t before = cert_.total_findings;
        const auto& T = tri_.triangles;
        const auto& H = tri_.halfedges;
        for (std::size_t e = 0; e < H.size(); ++e) {
            if (e % 3 == 0 && (T[e] == T[e + 1] || T[e + 1] == T[e + 2] || T[e] == T[e + 2])) {
                add(FindingKind::degenerate_triangle, e / 3, -1, static_cast<std::int64_t>(e / 3),
                    {vertex(e), vertex(e + 1), vertex(e + 2)},
                    triangle_name(e / 3) + " repeats a vertex");
            }
            if (e % 3 == 0) {
                for (std::size_t k = 0; k < 3; ++k) {
                    if (first_[T[e + k]] != T[e + k]) {
                        add(FindingKind::duplicate_vertex, T[e + k], first_[T[e + k]],
                            static_cast<std::int64_t>(e / 3), {T[e + k], first_[T[e + k]]},
                            triangle_name(e / 3) + ": vertex " + str(T[e + k]) + " repeats point " +
                                str(first_[T[e + k]]) + " (a vertex must be the first occurrence)");
                    }
                }
            }
            if (H[e] < 0) continue;
            const auto t = static_cast<std::size_t>(H[e]);
            if (static_cast<std::size_t>(H[t]) != e || t / 3 == e / 3 ||
                T[t] != T[next_halfedge(e)] || T[next_halfedge(t)] != T[e]) {
                add(FindingKind::twin_mismatch, e, H[e], static_cast<std::int64_t>(e / 3),
                    {vertex(e), vertex(next_halfedge(e))},
                    edge_name(e) + ": its twin, the edge (" + str(T[t]) + ", " +
                        str(T[next_halfedge(t)]) + ") of triangle " + str(t / 3) +
                        ", is not mutual or does not run the opposite way");
            }
        }
        return cert_.total_findings == before;
    }

    bool check_orientation() {
        const std::size_t before = cert_.total_findings;
        const auto& T = tri_.triangles;
        for (std::size_t t = 0; 3 * t < T.size(); ++t) {
            const Sign s = K::orient2d(pts_[T[3 * t]], pts_[T[3 * t + 1]], pts_[T[3 * t + 2]]);
            if (s != Sign::positive) {
                add(FindingKind::not_ccw, t, -1, static_cast<std::int64_t>(t),
                    {T[3 * t], T[3 * t + 1], T[3 * t + 2]},
                    triangle_name(t) + (s == Sign::zero ? " is flat (its vertices are collinear)"
                                                        : " is clockwise"));
            }
        }
        return cert_.total_findings == before;
    }

    bool check_boundary() {
        const std::size_t before = cert_.total_findings;
        const auto& T = tri_.triangles;
        const auto& H = tri_.halfedges;
        std::vector<std::int64_t> out(pts_.size(), -1);  // boundary half-edge leaving v
        std::size_t boundary_edges = 0;
        std::int64_t start = -1;
        for (std::size_t e = 0; e < H.size(); ++e) {
            if (H[e] >= 0) continue;
            ++boundary_edges;
            if (out[T[e]] >= 0) {
                const auto other = static_cast<std::size_t>(out[T[e]]);
                add(FindingKind::boundary_broken, T[e], e, static_cast<std::int64_t>(e / 3), {T[e]},
                    "two boundary edges leave point " + str(T[e]) + ": " + edge_name(other) +
                        " and " + edge_name(e));
                return false;
            }
            out[T[e]] = static_cast<std::int64_t>(e);
            if (start < 0 || lex_less(pts_[T[e]], pts_[T[static_cast<std::size_t>(start)]])) {
                start = static_cast<std::int64_t>(e);
            }
        }
        if (boundary_edges == 0) {
            add(FindingKind::boundary_broken, -1, -1, -1, {}, "no boundary: every edge has a twin");
            return false;
        }
        // The cycle from the lexicographically smallest boundary vertex.
        std::vector<std::uint32_t> cycle;
        std::uint32_t v = T[static_cast<std::size_t>(start)];
        do {
            if (out[v] < 0 || cycle.size() > boundary_edges) {
                add(FindingKind::boundary_broken, v, -1, -1, {v},
                    "the boundary does not close into a cycle: it stops at point " + str(v));
                return false;
            }
            cycle.push_back(v);
            v = T[next_halfedge(static_cast<std::size_t>(out[v]))];
        } while (v != cycle.front());
        if (cycle.size() != boundary_edges) {
            add(FindingKind::boundary_broken, cycle.size(), boundary_edges, -1, {},
                "the boundary consists of more than one cycle: the one through point " +
                    str(cycle.front()) + " has " + str(cycle.size()) + " of the " +
                    str(boundary_edges) + " boundary edges");
            return false;
        }
        if (!connected()) return false;
        boundary_size_ = cycle.size();
        if (tri_.hull != cycle) {
            const std::size_t j = first_difference(tri_.hull, cycle);
            add(FindingKind::hull_mismatch, j, -1, -1, {},
                "hull (" + str(tri_.hull.size()) + " points) differs at position " + str(j) +
                    " from the boundary cycle (" + str(cycle.size()) +
                    " points from the lexicographically smallest vertex, counter-clockwise)");
        }
        std::size_t maxima = 0;
        for (std::size_t j = 0; j < cycle.size(); ++j) {
            const Point2 a = pts_[cycle[(j + cycle.size() - 1) % cycle.size()]];
            const Point2 b = pts_[cycle[j]];
            const Point2 c = pts_[cycle[(j + 1) % cycle.size()]];
            const Sign turn = K::orient2d(a, b, c);
            // Straight on only if b lies between a and c (the chain runs monotonically in
            // lexicographic order along its line); otherwise the boundary reverses.
            const bool straight_on = lex_less(a, b) == lex_less(b, c);
            if (turn == Sign::negative || (turn == Sign::zero && !straight_on)) {
                const std::uint32_t before_b = cycle[(j + cycle.size() - 1) % cycle.size()];
                const std::uint32_t after_b = cycle[(j + 1) % cycle.size()];
                add(FindingKind::boundary_not_convex, j, cycle[j], -1,
                    {before_b, cycle[j], after_b},
                    "the boundary " +
                        std::string(turn == Sign::negative ? "turns right" : "reverses") +
                        " at point " + str(cycle[j]) + " (from " + str(before_b) + " to " +
                        str(after_b) + "): it is not the convex hull");
            }
            if (lex_less(a, b) && lex_less(c, b)) ++maxima;
        }
        // A boundary that only turns left winds w times and has w lexicographic maxima.
        if (maxima != 1) {
            add(FindingKind::boundary_winding, maxima, -1, -1, {},
                "the boundary winds " + str(maxima) +
                    " times (it has that many lexicographic maxima)");
        }
        return cert_.total_findings == before;
    }

    bool connected() {
        const std::size_t nt = tri_.triangles.size() / 3;
        std::vector<std::uint8_t> seen(nt, 0);
        std::vector<std::size_t> stack{0};
        seen[0] = 1;
        std::size_t reached = 1;
        while (!stack.empty()) {
            const std::size_t t = stack.back();
            stack.pop_back();
            for (std::size_t k = 0; k < 3; ++k) {
                const std::int32_t tw = tri_.halfedges[3 * t + k];
                if (tw >= 0 && !seen[static_cast<std::size_t>(tw) / 3]) {
                    seen[static_cast<std::size_t>(tw) / 3] = 1;
                    ++reached;
                    stack.push_back(static_cast<std::size_t>(tw) / 3);
                }
            }
        }
        if (reached != nt) {
            add(FindingKind::boundary_broken, reached, nt, -1, {},
                "triangles form more than one component: " + str(reached) + " of " + str(nt) +
                    " reached from triangle 0 through twins");
            return false;
        }
        return true;
    }

    void check_vertices() {
        std::vector<std::uint8_t> used(pts_.size(), 0);
        for (std::uint32_t v : tri_.triangles) used[v] = 1;
        used_vertices_ = 0;
        for (std::uint32_t v = 0; v < pts_.size(); ++v) {
            if (!used[v]) continue;
            ++used_vertices_;
        }
        for (std::uint32_t v : order_) {
            if (!used[v])
                add(FindingKind::missing_point, v, -1, -1, {v},
                    "point " + str(v) + " is not a vertex");
        }
    }

    void check_count() {
        const auto V = static_cast<std::int64_t>(used_vertices_);
        const auto H = static_cast<std::int64_t>(boundary_size_);
        const auto F = static_cast<std::int64_t>(tri_.triangles.size() / 3);
        if (F != 2 * V - 2 - H) {
            add(FindingKind::wrong_triangle_count, F, 2 * V - 2 - H, -1, {},
                str(F) + " triangles, not 2V - 2 - H = " + str(2 * V - 2 - H) + " (V = " + str(V) +
                    " vertices, H = " + str(H) + " on the boundary)");
        }
    }

    void check_delaunay() {
        const auto& T = tri_.triangles;
        const auto& H = tri_.halfedges;
        for (std::size_t e = 0; e < H.size(); ++e) {
            if (H[e] < 0 || static_cast<std::size_t>(H[e]) < e) continue;
            if (exempt(T[e], T[next_halfedge(e)])) continue;
            const auto t = static_cast<std::size_t>(H[e]);
            const std::uint32_t d = T[prev_halfedge(t)];
            if (K::incircle(pts_[T[e]], pts_[T[next_halfedge(e)]], pts_[T[prev_halfedge(e)]],
                            pts_[d]) == Sign::positive) {
                add(FindingKind::not_delaunay, e, d, static_cast<std::int64_t>(e / 3),
                    {vertex(e), vertex(next_halfedge(e)), vertex(prev_halfedge(e)), d},
                    edge_name(e) + " is not locally Delaunay: point " + str(d) + " of triangle " +
                        str(t / 3) + " is strictly inside the circumcircle");
            }
        }
    }

    // Whether the edge (u, v) is exempt from the Delaunay check (a constraint).
    bool exempt(std::uint32_t u, std::uint32_t v) const {
        if (exempt_.empty()) return false;
        const std::array<std::uint32_t, 2> key{std::min(u, v), std::max(u, v)};
        return std::binary_search(exempt_.begin(), exempt_.end(), key);
    }

    static std::size_t first_difference(const std::vector<std::uint32_t>& a,
                                        const std::vector<std::uint32_t>& b) {
        const auto [i, j] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
        return static_cast<std::size_t>(i - a.begin());
    }

    std::span<const Point2> pts_;
    const Triangulation& tri_;
    std::size_t max_findings_;
    std::span<const std::array<std::uint32_t, 2>> exempt_;
    Certificate cert_;
    std::vector<std::uint32_t> first_;
    std::vector<std::uint32_t> order_;
    std::size_t used_vertices_ = 0;
    std::size_t boundary_size_ = 0;
};

}  // namespace

Certificate certify(std::span<const Point2> points, const Triangulation& tri,
                    const CertifyOptions& options) {
    return Certifier(points, tri, options.max_findings).run();
}

namespace detail {

MeshCertificate certify_mesh(std::span<const Point2> points, const Triangulation& tri,
                             std::span<const std::array<std::uint32_t, 2>> exempt,
                             std::size_t max_findings) {
    Certifier certifier(points, tri, max_findings, exempt);
    MeshCertificate out;
    out.certificate = certifier.run();
    out.first = certifier.take_first();
    return out;
}

}  // namespace detail

}  // namespace exidel::delaunay
