// exidel: the constrained certifier (constrained.hpp says what is checked). The mesh is
// judged by certify()'s own checks (certify_mesh.hpp), with the constraint pieces exempt
// from the Delaunay check; what is added here concerns the input, the added crossing
// points, the chains and the list of constraints. Every check sorts or scans once:
// O(n log n) in the points, triangles and chain vertices.
#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "certify_mesh.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/construct.hpp"

namespace exidel::delaunay {

namespace {

using K = AdaptiveKernel;
using Pair = std::array<std::uint32_t, 2>;

bool finite(double v) {
    constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
    return (std::bit_cast<std::uint64_t>(v) & exponent) != exponent;
}
bool finite(Point2 p) { return finite(p.x) && finite(p.y); }

// Bit for bit: -0.0 differs from 0.0, and a NaN equals the same NaN.
bool same_bits(Point2 a, Point2 b) { return std::memcmp(&a, &b, sizeof(Point2)) == 0; }

Pair undirected(std::uint32_t u, std::uint32_t v) { return {std::min(u, v), std::max(u, v)}; }

class ConstrainedCertifier {
public:
    ConstrainedCertifier(std::span<const Point2> points, std::span<const Segment> segments,
                         const ConstrainedTriangulation& cdt, std::size_t max_findings)
        : input_(points), segments_(segments), cdt_(cdt), max_findings_(max_findings) {}

    Certificate run() {
        // Everything after this check indexes by the input's numbers: it must hold first.
        if (!check_input()) return std::move(cert_);
        collect_pieces();
        // Non-finite input points are certify()'s non_finite_input; the crossings of such
        // points cannot be decided, so only the mesh check below runs and reports them.
        const bool inputs_finite =
            std::all_of(input_.begin(), input_.end(), [](Point2 p) { return finite(p); });
        if (inputs_finite) check_added_points();
        const Triangulation& tri = cdt_.triangulation;
        if (tri.vertex_of_input.empty() && tri.duplicates.empty() && !cdt_.points.empty()) {
            // certify() accepts an absent map (other producers do not write one), but a
            // constrained triangulation always has one entry per point.
            add(FindingKind::bad_vertex_map, 0, cdt_.points.size(), {},
                "vertex_of_input is empty: a constrained triangulation has one entry per point (" +
                    str(cdt_.points.size()) + " points)");
        }
        detail::MeshCertificate mesh =
            detail::certify_mesh(cdt_.points, tri, pieces_, max_findings_);
        merge(std::move(mesh.certificate));
        // Without the first occurrences (a point is not finite) the chains' ends and
        // geometry cannot be judged; their pieces can still be compared with the list.
        if (!mesh.first.empty()) check_chains(mesh.first);
        check_constraints();
        return std::move(cert_);
    }

private:
    using Ids = detail::FindingPoints;

    template <class I, class J>
    void add(FindingKind kind, I index, J other, Ids points, std::string message) {
        ++cert_.total_findings;
        if (cert_.findings.size() < max_findings_) {
            cert_.findings.push_back({kind, static_cast<std::int64_t>(index),
                                      static_cast<std::int64_t>(other), std::move(message), -1,
                                      std::move(points.v)});
        }
    }

    // The mesh checks' findings, after those found so far, within the same limit.
    void merge(Certificate mesh) {
        cert_.total_findings += mesh.total_findings;
        for (Finding& f : mesh.findings) {
            if (cert_.findings.size() >= max_findings_) break;
            cert_.findings.push_back(std::move(f));
        }
    }

    template <class I>
    static std::string str(I i) {
        return std::to_string(i);
    }
    // The shortest decimal that reads back as the same double.
    static std::string str(double v) {
        char buf[32];
        const auto r = std::to_chars(buf, buf + sizeof buf, v);
        return std::string(buf, r.ptr);
    }
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "(" + a temporary.
    static std::string str(Point2 p) {
        std::string s = "(";
        s += str(p.x);
        s += ", ";
        s += str(p.y);
        s += ")";
        return s;
    }
    // "segment 4 (12, 7)": a segment by its position and its ends' input indices.
    std::string segment_name(std::size_t s) const {
        return "segment " + str(s) + " (" + str(segments_[s].a) + ", " + str(segments_[s].b) + ")";
    }
    // "added point 3 (point 40)": the fourth crossing point, at index 40 of cdt.points.
    std::string added_name(std::size_t p) const {
        return "added point " + str(p - cdt_.input_count) + " (point " + str(p) + ")";
    }

    bool check_input() {
        const std::size_t before = cert_.total_findings;
        const std::size_t n = input_.size();
        if (cdt_.input_count != n || cdt_.points.size() < n) {
            add(FindingKind::input_mismatch, cdt_.input_count, cdt_.points.size(), {},
                "input_count is " + str(cdt_.input_count) + " and there are " +
                    str(cdt_.points.size()) + " points, for an input of " + str(n) +
                    " points (input_count must equal it, the points at least)");
            // The remaining checks of this step index the points by input_count.
            return false;
        }
        std::size_t changed = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (same_bits(cdt_.points[i], input_[i])) continue;
            if (changed++ == 0) {
                add(FindingKind::input_mismatch, i, -1, {i},
                    "point " + str(i) + " is " + str(cdt_.points[i]) + ", not the input's " +
                        str(input_[i]));
            } else {
                ++cert_.total_findings;  // counted; the first one says what is wrong
            }
        }
        for (std::size_t s = 0; s < segments_.size(); ++s) {
            if (segments_[s].a >= n || segments_[s].b >= n) {
                add(FindingKind::input_mismatch, s, -1, {},
                    segment_name(s) + " names a point past the input (" + str(n) + " points)");
            }
        }
        if (cdt_.crossings.size() != cdt_.added_count() ||
            cdt_.crossing_lines.size() != cdt_.added_count()) {
            add(FindingKind::input_mismatch, cdt_.crossings.size(), cdt_.added_count(), {},
                str(cdt_.crossings.size()) + " crossings and " + str(cdt_.crossing_lines.size()) +
                    " crossing lines listed for " + str(cdt_.added_count()) + " added points");
        }
        const auto& off = cdt_.chain_offsets;
        if (off.size() != segments_.size() + 1 || off.front() != 0 ||
            off.back() != cdt_.chain_vertices.size() || !std::is_sorted(off.begin(), off.end())) {
            add(FindingKind::input_mismatch, off.size(), cdt_.chain_vertices.size(), {},
                "chain_offsets (" + str(off.size()) + " entries) does not divide the " +
                    str(cdt_.chain_vertices.size()) + " chain vertices among " +
                    str(segments_.size()) +
                    " segments: it needs one entry more than the segments, from 0, "
                    "non-decreasing, to the number of chain vertices");
        }
        for (std::size_t j = 0; j < cdt_.chain_vertices.size(); ++j) {
            if (cdt_.chain_vertices[j] >= cdt_.points.size()) {
                add(FindingKind::input_mismatch, j, cdt_.chain_vertices[j], {},
                    "chain vertex " + str(j) + " (of all chains) is point " +
                        str(cdt_.chain_vertices[j]) + ", out of range (" + str(cdt_.points.size()) +
                        " points)");
            }
        }
        return cert_.total_findings == before;
    }

    // Whether segments ab and cd cross at a point interior to both: the ends of each are
    // strictly on opposite sides of the other's line.
    static bool cross_properly(Point2 a, Point2 b, Point2 c, Point2 d) {
        const auto opposite = [](Sign p, Sign q) { return to_int(p) * to_int(q) < 0; };
        return opposite(K::orient2d(a, b, c), K::orient2d(a, b, d)) &&
               opposite(K::orient2d(c, d, a), K::orient2d(c, d, b));
    }
    bool cross_properly(std::size_t s, std::size_t t) const {
        return cross_properly(input_[segments_[s].a], input_[segments_[s].b],
                              input_[segments_[t].a], input_[segments_[t].b]);
    }

    Intersection crossing(std::size_t s, std::size_t t) const {
        return intersection(input_[segments_[s].a], input_[segments_[s].b], input_[segments_[t].a],
                            input_[segments_[t].b]);
    }

    void check_added_points() {
        for (std::size_t i = 0; i < cdt_.crossings.size(); ++i) {
            const std::size_t p = cdt_.input_count + i;
            const Point2 q = cdt_.points[p];
            const auto [s, t] = cdt_.crossings[i];
            if (!finite(q)) {
                add(FindingKind::added_point_wrong, p, -1, {p},
                    added_name(p) + " has a non-finite coordinate");
                continue;
            }
            if (s >= segments_.size() || t >= segments_.size()) {
                add(FindingKind::added_point_wrong, p, -1, {p},
                    added_name(p) + " is the crossing of segments " + str(s) + " and " + str(t) +
                        ", but there are " + str(segments_.size()) + " segments");
                continue;
            }
            // The lines it is the crossing of: ab and cd, by point: the two segments' ends, or
            // the ends of the two pieces that crossed (which later splits and cut loops may
            // have taken off the chains). They were there before it, which rules out points
            // defined through each other in a circle.
            const std::array<std::uint32_t, 4> v = cdt_.crossing_lines[i];
            if (*std::max_element(v.begin(), v.end()) >= p) {
                add(FindingKind::added_point_wrong, p, -1, {p},
                    added_name(p) + " is the crossing of lines through (" + str(v[0]) + ", " +
                        str(v[1]) + ") and (" + str(v[2]) + ", " + str(v[3]) +
                        "), not all points before it");
                continue;
            }
            const Point2 a = cdt_.points[v[0]], b = cdt_.points[v[1]], c = cdt_.points[v[2]],
                         d = cdt_.points[v[3]];
            // A non-finite one is an earlier added point, found wrong above.
            if (!finite(a) || !finite(b) || !finite(c) || !finite(d)) continue;
            if (!cross_properly(a, b, c, d)) {
                add(FindingKind::added_point_wrong, p, -1, {p, v[0], v[1], v[2], v[3]},
                    added_name(p) + " is the crossing of (" + str(v[0]) + ", " + str(v[1]) +
                        ") and (" + str(v[2]) + ", " + str(v[3]) +
                        "), which do not cross at a point interior to both");
                continue;
            }
            const Intersection x = intersection(a, b, c, d);
            if (!x.ok() || !same_bits(x.point, q)) {
                add(FindingKind::added_point_wrong, p, -1, {p, v[0], v[1], v[2], v[3]},
                    added_name(p) + " is " + str(q) + ", not " + str(x.point) +
                        ", the rounded crossing of (" + str(v[0]) + ", " + str(v[1]) + ") and (" +
                        str(v[2]) + ", " + str(v[3]) + ")" +
                        (x.ok() ? "" : " (" + std::string(to_string(x.status)) + ")"));
            }
        }
    }

    // The pieces of all chains, undirected, sorted, once each. Repeated consecutive vertices
    // are not pieces (check_chains reports them). And the chains through every vertex.
    void collect_pieces() {
        const auto& c = cdt_.chain_vertices;
        for (std::size_t s = 0; s < segments_.size(); ++s) {
            for (std::size_t j = cdt_.chain_offsets[s]; j < cdt_.chain_offsets[s + 1]; ++j) {
                on_chains_.push_back({c[j], static_cast<std::uint32_t>(s)});
            }
            for (std::size_t j = cdt_.chain_offsets[s] + 1; j < cdt_.chain_offsets[s + 1]; ++j) {
                if (c[j - 1] != c[j]) pieces_.push_back(undirected(c[j - 1], c[j]));
            }
        }
        std::sort(on_chains_.begin(), on_chains_.end());
        std::sort(pieces_.begin(), pieces_.end());
        pieces_.erase(std::unique(pieces_.begin(), pieces_.end()), pieces_.end());
    }

    // The triangulation's edges, undirected, sorted: those of the triangles, or of the chain
    // of a collinear result (which has no triangles).
    std::vector<Pair> mesh_edges() const {
        const Triangulation& tri = cdt_.triangulation;
        std::vector<Pair> edges;
        if (tri.collinear) {
            for (std::size_t j = 1; j < tri.hull.size(); ++j) {
                edges.push_back(undirected(tri.hull[j - 1], tri.hull[j]));
            }
        } else {
            // Only whole triangles: a ragged array is bad_shape, found by the mesh check.
            const std::size_t n = tri.triangles.size() / 3 * 3;
            for (std::size_t e = 0; e < n; ++e) {
                edges.push_back(undirected(tri.triangles[e], tri.triangles[next_halfedge(e)]));
            }
        }
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
        return edges;
    }

    // Whether point x lies exactly on the open segment from a to b: on its line, and
    // strictly between the ends along an axis where they differ (collinear points are
    // ordered alike along both axes, so one axis decides).
    static bool on_open_segment(Point2 a, Point2 b, Point2 x) {
        if (K::orient2d(a, b, x) != Sign::zero) return false;
        if (a.x != b.x) return std::min(a.x, b.x) < x.x && x.x < std::max(a.x, b.x);
        return std::min(a.y, b.y) < x.y && x.y < std::max(a.y, b.y);
    }

    // Whether chain vertex x of segment s is one of its anchors: a point exactly on the open
    // segment, or where rounding put a crossing of s:
    //   - an added point whose listed pair of segments includes s (its own crossing);
    //   - the rounded crossing of s with a segment t whose chain passes through x: where
    //     several segments cross at one point only the first pair found is listed, and a
    //     rounded crossing may fall on an existing vertex (even an end of t). Only vertices
    //     off the segment, rare, try these candidates.
    bool is_anchor(std::size_t s, std::uint32_t x) const {
        const Point2 a = input_[segments_[s].a], b = input_[segments_[s].b];
        const Point2 px = cdt_.points[x];
        if (on_open_segment(a, b, px)) return true;
        if (x >= cdt_.input_count) {
            const auto [t0, t1] = cdt_.crossings[x - cdt_.input_count];
            if (t0 == s || t1 == s) return true;
        }
        const auto from = std::lower_bound(on_chains_.begin(), on_chains_.end(), Pair{x, 0});
        for (auto it = from; it != on_chains_.end() && (*it)[0] == x; ++it) {
            const std::uint32_t t = (*it)[1];
            if (t == s || !cross_properly(s, t)) continue;
            const Intersection i = crossing(s, t);
            if (i.ok() && same_bits(i.point, px)) return true;
        }
        return false;
    }

    void check_chains(const std::vector<std::uint32_t>& first) {
        const std::vector<Pair> edges = mesh_edges();
        const auto& c = cdt_.chain_vertices;
        // The segment whose chain last visited each point: a chain visiting a point twice
        // doubles back on itself, which no straight segment does.
        constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
        std::vector<std::uint32_t> visited_by(cdt_.points.size(), none);
        std::vector<std::size_t> loose;  // the current chain's vertices that are not anchors
        for (std::size_t s = 0; s < segments_.size(); ++s) {
            const std::size_t begin = cdt_.chain_offsets[s], end = cdt_.chain_offsets[s + 1];
            const std::uint32_t va = first[segments_[s].a], vb = first[segments_[s].b];
            if (begin == end) {
                add(FindingKind::chain_broken, s, -1, {segments_[s].a, segments_[s].b},
                    segment_name(s) + ": the chain is empty");
                continue;
            }
            if (c[begin] != va) {
                add(FindingKind::chain_broken, s, c[begin], {c[begin], va},
                    segment_name(s) + ": the chain starts at point " + str(c[begin]) +
                        ", not at point " + str(va) + ", the vertex of its first end");
            }
            if (c[end - 1] != vb) {
                add(FindingKind::chain_broken, s, c[end - 1], {c[end - 1], vb},
                    segment_name(s) + ": the chain ends at point " + str(c[end - 1]) +
                        ", not at point " + str(vb) + ", the vertex of its second end");
            }
            if (va == vb) {
                if (end - begin != 1) {
                    add(FindingKind::chain_broken, s, end - begin, {va},
                        segment_name(s) + ": both ends are point " + str(va) +
                            ", so the chain is that one vertex, not " + str(end - begin) +
                            " vertices");
                }
                continue;
            }
            loose.clear();
            for (std::size_t j = begin; j < end; ++j) {
                const std::uint32_t w = c[j];
                const std::size_t k = j - begin;  // its position in the chain
                if (j > begin) {
                    const std::uint32_t u = c[j - 1];
                    if (u == w) {
                        add(FindingKind::chain_broken, s, k, {w},
                            segment_name(s) + ": chain vertices " + str(k - 1) + " and " + str(k) +
                                " are both point " + str(w));
                        continue;
                    }
                    if (!std::binary_search(edges.begin(), edges.end(), undirected(u, w))) {
                        add(FindingKind::chain_broken, s, k, {u, w},
                            segment_name(s) + ": the piece (" + str(u) + ", " + str(w) +
                                ") from chain vertex " + str(k - 1) + " to " + str(k) +
                                " is not an edge of the triangulation");
                    }
                }
                if (visited_by[w] == s) {
                    add(FindingKind::chain_broken, s, k, {w},
                        segment_name(s) + ": chain vertex " + str(k) + " (point " + str(w) +
                            ") was visited before: the chain doubles back");
                }
                visited_by[w] = static_cast<std::uint32_t>(s);
                if (j > begin && j + 1 < end) {
                    if (!is_anchor(s, w)) loose.push_back(j);
                }
            }
            // A vertex that is neither is where a piece bent by rounding met a vertex or
            // another bent piece: it must lie within the segment's tolerance of it.
            if (!loose.empty()) {
                const Point2 a = input_[segments_[s].a], b = input_[segments_[s].b];
                const double tolerance = chain_tolerance(a, b);
                for (const std::size_t j : loose) {
                    if (compare_segment_distance(cdt_.points[c[j]], a, b, tolerance) !=
                        Sign::positive)
                        continue;
                    add(FindingKind::chain_off_segment, s, c[j], {c[j]},
                        segment_name(s) + ": chain vertex " + str(j - begin) + " (point " +
                            str(c[j]) +
                            ") is neither on the segment nor a crossing of it, and lies farther "
                            "from it than the tolerance " +
                            str(tolerance));
                }
            }
        }
    }

    void check_constraints() {
        const auto& given = cdt_.constraints;
        for (std::size_t j = 0; j < given.size(); ++j) {
            if (given[j][0] >= given[j][1] || (j > 0 && given[j - 1] >= given[j])) {
                add(FindingKind::constraints_mismatch, j, -1, {given[j][0], given[j][1]},
                    "constraint " + str(j) + " (" + str(given[j][0]) + ", " + str(given[j][1]) +
                        ") is out of order: the list holds (u, v) with u < v, sorted, once each");
                break;
            }
        }
        std::vector<Pair> listed;
        listed.reserve(given.size());
        for (const Pair& p : given) listed.push_back(undirected(p[0], p[1]));
        std::sort(listed.begin(), listed.end());
        listed.erase(std::unique(listed.begin(), listed.end()), listed.end());
        std::vector<Pair> missing, extra;
        std::set_difference(pieces_.begin(), pieces_.end(), listed.begin(), listed.end(),
                            std::back_inserter(missing));
        std::set_difference(listed.begin(), listed.end(), pieces_.begin(), pieces_.end(),
                            std::back_inserter(extra));
        // The first of each kind in detail; the rest counted.
        if (!missing.empty()) {
            add(FindingKind::constraints_mismatch, missing.size(), extra.size(),
                {missing[0][0], missing[0][1]},
                "the piece (" + str(missing[0][0]) + ", " + str(missing[0][1]) +
                    ") of a chain is not in constraints (" + str(missing.size()) +
                    " pieces missing)");
            cert_.total_findings += missing.size() - 1;
        }
        if (!extra.empty()) {
            add(FindingKind::constraints_mismatch, extra.size(), missing.size(),
                {extra[0][0], extra[0][1]},
                "constraints lists (" + str(extra[0][0]) + ", " + str(extra[0][1]) +
                    "), which is no chain's piece (" + str(extra.size()) + " such entries)");
            cert_.total_findings += extra.size() - 1;
        }
    }

    std::span<const Point2> input_;
    std::span<const Segment> segments_;
    const ConstrainedTriangulation& cdt_;
    std::size_t max_findings_;
    Certificate cert_;
    std::vector<Pair> pieces_;
    std::vector<Pair> on_chains_;  // (vertex, segment) for every chain vertex, sorted
};

}  // namespace

Certificate certify_constrained(std::span<const Point2> points, std::span<const Segment> segments,
                                const ConstrainedTriangulation& cdt,
                                const CertifyOptions& options) {
    return ConstrainedCertifier(points, segments, cdt, options.max_findings).run();
}

}  // namespace exidel::delaunay
