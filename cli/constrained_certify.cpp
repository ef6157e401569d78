// exidel CLI: `exidel certify --constraints CONSTRAINTS TRIANGULATION`. Is this file the
// constrained Delaunay triangulation of that input (exidel/delaunay/constrained.hpp), or
// the domain of it that `exidel triangulate --constraints` or Triangle's `-p` writes?
//
// The steps: read the input and the file (exidel's constrained json, an .ele with its
// .node, an OFF of every vertex; exidel/io/constrained_input.hpp) -> rebuild a
// delaunay::ConstrainedTriangulation (the chains and crossings from the json, or derived
// from the geometry for a peer) -> complete the file's domain to the convex hull with the
// constrained Delaunay triangulation of the same vertices and pieces outside the domain
// (untrusted: it only has to make the check below pass) -> certify_constrained on the
// whole -> compare the file's triangles with the domain that --fill and the hole seeds
// define on the certified whole -> report as `exidel certify` does.
//
// Why that proves what it says: certify_constrained checks exactly that the whole (the
// file's triangles followed by the completion's) is the constrained Delaunay triangulation
// of the hull; the file's triangles are rows of it, and the domain check says they are
// exactly the triangles of its domain. How the completion was built does not matter.
#include "constrained_certify.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "constrained.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/io/constrained_input.hpp"
#include "exidel/io/constraints.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/construct.hpp"

namespace exidel::cli {

namespace {

using delaunay::FillRule;
using delaunay::FindingKind;
using Pair = std::array<std::uint32_t, 2>;
using K = AdaptiveKernel;

Pair undirected(std::uint32_t u, std::uint32_t v) { return {std::min(u, v), std::max(u, v)}; }

std::string str(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}
std::string str(Point2 p) {
    std::string s = "(";
    s += str(p.x);
    s += ", ";
    s += str(p.y);
    s += ")";
    return s;
}
template <class I>
std::string num(I i) {
    return std::to_string(i);
}

// One finding as reported: certify_constrained's, or the file-level ones made here
// (domain_mismatch, and twin_mismatch / added_point_wrong with the certifier's meaning).
struct Report {
    std::string kind;
    std::string message;
    std::int64_t triangle = -1;
    std::vector<std::int64_t> points;
    std::int64_t index = -1;
    std::int64_t other = -1;
};

bool on_open_segment(Point2 a, Point2 b, Point2 x) {
    if (K::orient2d(a, b, x) != Sign::zero) return false;
    if (a.x != b.x) return std::min(a.x, b.x) < x.x && x.x < std::max(a.x, b.x);
    return std::min(a.y, b.y) < x.y && x.y < std::max(a.y, b.y);
}

bool cross_properly(Point2 a, Point2 b, Point2 c, Point2 d) {
    const auto opposite = [](Sign p, Sign q) { return to_int(p) * to_int(q) < 0; };
    return opposite(K::orient2d(a, b, c), K::orient2d(a, b, d)) &&
           opposite(K::orient2d(c, d, a), K::orient2d(c, d, b));
}

bool within(Point2 p, Point2 a, Point2 b) {
    return compare_segment_distance(p, a, b, delaunay::chain_tolerance(a, b)) != Sign::positive;
}

// The vertices that may lie on a segment, for deriving a peer's chains: a uniform grid of
// about one vertex per cell over the vertices' bounding box, walked column by column
// along the segment, so a segment costs the cells it passes through rather than every
// vertex in its x-range (quadratic for long segments). A candidate list only: the exact
// tests decide. It misses no vertex within `tol` of the segment (in each coordinate:
// chain_tolerance() bounds the Euclidean distance): each column is widened by a whole
// column on either side and then by 2 tol, the segment's y over that x-range is widened
// by 2 tol and a whole row, and the rounding of those few operations (a few ulps of the
// largest coordinate) is far below tol (2^-44 of it, or 256 subnormal ulps). An input
// whose extent overflows gets one cell (every vertex a candidate, as a scan).
class VertexGrid {
public:
    VertexGrid(const std::vector<Point2>& points, const std::vector<std::uint32_t>& vertices) {
        for (const std::uint32_t v : vertices) {
            const Point2 p = points[v];
            x0_ = std::min(x0_, p.x), x1_ = std::max(x1_, p.x);
            y0_ = std::min(y0_, p.y), y1_ = std::max(y1_, p.y);
        }
        const double wx = x1_ - x0_, wy = y1_ - y0_;
        if (!vertices.empty() && std::isfinite(wx) && std::isfinite(wy)) {
            // side x side cells, or a single row or column of one per vertex when the
            // vertices lie on a horizontal or vertical line.
            const std::size_t side = static_cast<std::size_t>(
                std::ceil(std::sqrt(static_cast<double>(vertices.size()))));
            nx_ = wx > 0 ? (wy > 0 ? side : vertices.size()) : 1;
            ny_ = wy > 0 ? (wx > 0 ? side : vertices.size()) : 1;
            cw_ = wx / static_cast<double>(nx_);
            ch_ = wy / static_cast<double>(ny_);
        }
        start_.assign(nx_ * ny_ + 1, 0);
        for (const std::uint32_t v : vertices) ++start_[cell(points[v]) + 1];
        for (std::size_t c = 0; c < nx_ * ny_; ++c) start_[c + 1] += start_[c];
        items_.resize(vertices.size());
        std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
        for (const std::uint32_t v : vertices) items_[fill[cell(points[v])]++] = v;
    }

    /// Calls f(v) once for every vertex v that may lie within `tol` of segment a-b.
    template <class F>
    void near_segment(Point2 a, Point2 b, double tol, F&& f) const {
        const double xmin = std::min(a.x, b.x), xmax = std::max(a.x, b.x);
        const double xlo = xmin - 2 * tol, xhi = xmax + 2 * tol;
        const double slope = a.x != b.x ? (b.y - a.y) / (b.x - a.x) : 0;
        const auto y_at = [&](double x) { return a.y + (std::clamp(x, xmin, xmax) - a.x) * slope; };
        const std::size_t c0 = column(xlo), c1 = column(xhi);
        for (std::size_t c = c0 > 0 ? c0 - 1 : 0; c <= std::min(c1 + 1, nx_ - 1); ++c) {
            std::size_t r0 = 0, r1 = ny_ - 1;
            if (ny_ > 1) {
                // The segment's y over the column (widened), a whole row more either side;
                // its whole y-range when it is vertical, or so steep that its slope or a
                // y is no finite double (a width of a few subnormals).
                double ymin = std::min(a.y, b.y), ymax = std::max(a.y, b.y);
                if (a.x != b.x) {
                    const double cl = static_cast<double>(c);
                    const double lo = std::max(xlo, x0_ + (cl - 1) * cw_ - 2 * tol);
                    const double hi = std::min(xhi, x0_ + (cl + 2) * cw_ + 2 * tol);
                    const double ya = y_at(lo), yb = y_at(hi);
                    if (std::isfinite(ya) && std::isfinite(yb)) {
                        ymin = std::min(ya, yb);
                        ymax = std::max(ya, yb);
                    }
                }
                r0 = row(ymin - 2 * tol);
                r0 = r0 > 0 ? r0 - 1 : 0;
                r1 = std::min(row(ymax + 2 * tol) + 1, ny_ - 1);
            }
            for (std::size_t r = r0; r <= r1; ++r) {
                const std::size_t k = r * nx_ + c;
                for (std::uint32_t i = start_[k]; i < start_[k + 1]; ++i) f(items_[i]);
            }
        }
    }

private:
    static std::size_t index(double t, double origin, double width, std::size_t count) {
        if (count == 1 || !(t > origin)) return 0;  // also NaN, which no finite input makes
        const double i = (t - origin) / width;
        return i >= static_cast<double>(count - 1) ? count - 1 : static_cast<std::size_t>(i);
    }
    std::size_t column(double x) const { return index(x, x0_, cw_, nx_); }
    std::size_t row(double y) const { return index(y, y0_, ch_, ny_); }
    std::size_t cell(Point2 p) const { return row(p.y) * nx_ + column(p.x); }

    double x0_ = std::numeric_limits<double>::infinity(), x1_ = -x0_, y0_ = x0_, y1_ = -x0_;
    double cw_ = 0, ch_ = 0;
    std::size_t nx_ = 1, ny_ = 1;
    std::vector<std::uint32_t> start_, items_;
};

// Everything the certification needs, rebuilt from the two files.
class Rebuild {
public:
    Rebuild(const io::ConstraintFile& input, std::span<const delaunay::Segment> segments,
            io::ProducedConstrained file, const ConstrainedCertifySettings& s)
        : input_(input), segments_(segments), file_(std::move(file)), settings_(s) {}

    // The verdict's numbers.
    std::size_t file_triangles = 0, completion_triangles = 0;
    std::vector<Report> reports;
    std::size_t total = 0;
    std::vector<std::string> notes;
    delaunay::ConstrainedTriangulation cdt;

    void run() {
        const std::size_t n = input_.points.size();
        cdt.points = file_.points;
        cdt.input_count = n;
        delaunay::Normalization normalization;
        // The file's triangles, normalised as `exidel certify` does (twins derived when
        // absent); their own twins, derived, for the domain's boundary.
        domain_ = delaunay::normalize(cdt.points, file_.mesh, &normalization, settings_.strict);
        // What a domain file leaves out (its hull, maybe its twins) is expected: no note.
        for (const std::string& note : normalization.notes()) {
            if (!note.starts_with("no ")) notes.push_back(note);
        }
        file_triangles = domain_.triangle_count();
        own_twins_ = delaunay::normalize(cdt.points, {domain_.triangles, {}, {}, {}}, nullptr, true)
                         .halfedges;
        if (file_.mesh.halfedges) check_given_twins();
        const bool indexed = cdt.points.size() >= n;
        if (indexed) {
            if (file_.chain_offsets) {
                cdt.chain_offsets = *file_.chain_offsets;
                cdt.chain_vertices = *file_.chain_vertices;
                cdt.crossings = *file_.crossings;
            } else {
                build_chains();
                build_crossings();
            }
        }
        chains_ok_ = indexed && chains_valid();
        if (chains_ok_) {
            collect_pieces();
            build_crossing_lines();
        } else {
            // Not in any file: one entry per added point, so that the certifier's findings
            // are about what the file holds.
            cdt.crossing_lines.assign(cdt.added_count(), {0, 0, 0, 0});
        }
        if (file_.constraints) {
            cdt.constraints = *file_.constraints;
        } else {
            cdt.constraints = pieces_;
        }
        const bool completed = chains_ok_ && complete();
        delaunay::ProducedTriangulation whole{domain_.triangles, {}, {}, file_.mesh.duplicates};
        whole.triangles.insert(whole.triangles.end(), completion_.begin(), completion_.end());
        cdt.triangulation = completed && collinear_whole_
                                ? std::move(collinear_)
                                : delaunay::normalize(cdt.points, std::move(whole), nullptr, true);
        if (!completed && chains_ok_) {
            notes.push_back(
                "the domain cannot be completed to the convex hull (the pieces cross, or the "
                "triangulation of the vertices and pieces failed): certifying the file's "
                "triangles alone as a triangulation of the whole hull");
        }
        delaunay::CertifyOptions options;
        options.max_findings = std::numeric_limits<std::size_t>::max();
        const delaunay::Certificate c =
            delaunay::certify_constrained(input_.points, segments_, cdt, options);
        take(c);
        // The domain is decided on a certified whole; wrong added points do not change it.
        const bool sound = std::all_of(c.findings.begin(), c.findings.end(), [](const auto& f) {
            return f.kind == FindingKind::added_point_wrong;
        });
        if (completed && sound && !collinear_whole_) check_domain();
    }

private:
    void add(Report r) {
        ++total;
        reports.push_back(std::move(r));
    }

    std::string triangle_name(std::size_t t) const {
        const auto& tr = cdt.triangulation.triangles;
        return "(" + num(tr[3 * t]) + ", " + num(tr[3 * t + 1]) + ", " + num(tr[3 * t + 2]) + ")";
    }

    // exidel's json gives the domain's twins: they must be those of its triangles.
    void check_given_twins() {
        const std::vector<std::int32_t>& given = domain_.halfedges;
        if (given.size() != own_twins_.size()) {
            add({"twin_mismatch",
                 "halfedges has " + num(given.size()) + " entries for " + num(own_twins_.size()) +
                     " half-edges",
                 -1,
                 {},
                 static_cast<std::int64_t>(given.size()),
                 static_cast<std::int64_t>(own_twins_.size())});
            return;
        }
        for (std::size_t e = 0; e < given.size(); ++e) {
            if (given[e] == own_twins_[e]) continue;
            const std::size_t t = e / 3;
            add({"twin_mismatch",
                 "halfedges[" + num(e) + "] is " + num(given[e]) +
                     ", but the half-edge across "
                     "edge " +
                     num(e % 3) + " of triangle " + num(t) + " is " + num(own_twins_[e]) +
                     " (-1: none in the domain)",
                 static_cast<std::int64_t>(t),
                 {},
                 static_cast<std::int64_t>(e),
                 given[e]});
        }
    }

    // A peer's chains: for segment (a, b), a, then the input points exactly on the open
    // segment and the added points within chain_tolerance of it, ordered along it, then b.
    void build_chains() {
        const std::size_t n = input_.points.size();
        const std::vector<std::uint32_t>& first = domain_.vertex_of_input;
        std::vector<std::uint32_t> distinct;
        for (std::size_t i = 0; i < cdt.points.size(); ++i) {
            if (first[i] == i) distinct.push_back(static_cast<std::uint32_t>(i));
        }
        const VertexGrid grid(cdt.points, distinct);
        cdt.chain_offsets.assign(1, 0);
        std::vector<std::uint32_t> inner;
        for (const delaunay::Segment& seg : segments_) {
            if (seg.a >= n || seg.b >= n) {  // input_mismatch, from the certifier
                cdt.chain_offsets.push_back(static_cast<std::uint32_t>(cdt.chain_vertices.size()));
                continue;
            }
            const std::uint32_t fa = first[seg.a], fb = first[seg.b];
            cdt.chain_vertices.push_back(fa);
            if (fa != fb) {
                const Point2 a = cdt.points[fa], b = cdt.points[fb];
                const double tol = delaunay::chain_tolerance(a, b);
                const double xlo = std::min(a.x, b.x) - 2 * tol, xhi = std::max(a.x, b.x) + 2 * tol;
                const double ylo = std::min(a.y, b.y) - 2 * tol, yhi = std::max(a.y, b.y) + 2 * tol;
                inner.clear();
                grid.near_segment(a, b, tol, [&](std::uint32_t v) {
                    const Point2 p = cdt.points[v];
                    if (v == fa || v == fb || p.x < xlo || p.x > xhi || p.y < ylo || p.y > yhi)
                        return;
                    if (v < n ? on_open_segment(a, b, p) : within(p, a, b)) inner.push_back(v);
                });
                // Along the segment: by the coordinate that changes most, then the other.
                const bool by_x_axis = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
                const double sx = b.x >= a.x ? 1 : -1, sy = b.y >= a.y ? 1 : -1;
                std::sort(inner.begin(), inner.end(), [&](std::uint32_t i, std::uint32_t j) {
                    const Point2 p = cdt.points[i], q = cdt.points[j];
                    const std::pair<double, double> kp =
                        by_x_axis ? std::pair(sx * p.x, sy * p.y) : std::pair(sy * p.y, sx * p.x);
                    const std::pair<double, double> kq =
                        by_x_axis ? std::pair(sx * q.x, sy * q.y) : std::pair(sy * q.y, sx * q.x);
                    return kp < kq;
                });
                cdt.chain_vertices.insert(cdt.chain_vertices.end(), inner.begin(), inner.end());
                cdt.chain_vertices.push_back(fb);
            }
            cdt.chain_offsets.push_back(static_cast<std::uint32_t>(cdt.chain_vertices.size()));
        }
    }

    // A peer's crossings: each added point is the crossing of the first two segments whose
    // chains hold it. One on fewer than two chains is no crossing: reported here.
    void build_crossings() {
        const std::size_t n = input_.points.size();
        std::vector<std::vector<std::uint32_t>> on(cdt.added_count());
        for (std::size_t s = 0; s + 1 < cdt.chain_offsets.size(); ++s) {
            for (const std::uint32_t v : cdt.chain(s)) {
                if (v >= n && on[v - n].size() < 2)
                    on[v - n].push_back(static_cast<std::uint32_t>(s));
            }
        }
        cdt.crossings.assign(cdt.added_count(), {0, 0});
        for (std::size_t i = 0; i < on.size(); ++i) {
            const std::size_t p = n + i;
            if (on[i].size() == 2) {
                cdt.crossings[i] = {on[i][0], on[i][1]};
                continue;
            }
            const std::uint32_t f = domain_.vertex_of_input[p];
            std::string why = f != p          ? " (it repeats point " + num(f) + ")"
                              : on[i].empty() ? ""
                                              : " (segment " + num(on[i][0]) + ")";
            add({"added_point_wrong",
                 "added point " + num(i) + " (point " + num(p) + ") " + str(cdt.points[p]) +
                     " is on the chains of " + num(on[i].size()) + " segments" + why +
                     ": exidel adds points only where two segments cross",
                 -1,
                 {static_cast<std::int64_t>(p)},
                 static_cast<std::int64_t>(p),
                 -1});
            reported_.insert(p);
        }
    }

    // chain_offsets divides chain_vertices among the segments, every vertex a point.
    bool chains_valid() const {
        const auto& off = cdt.chain_offsets;
        if (off.size() != segments_.size() + 1 || off.front() != 0 ||
            off.back() != cdt.chain_vertices.size() || !std::is_sorted(off.begin(), off.end()))
            return false;
        for (const std::uint32_t v : cdt.chain_vertices) {
            if (v >= cdt.points.size()) return false;
        }
        return cdt.crossings.size() == cdt.added_count();
    }

    void collect_pieces() {
        for (std::size_t s = 0; s < segments_.size(); ++s) {
            const auto c = cdt.chain(s);
            for (std::size_t j = 1; j < c.size(); ++j) {
                if (c[j - 1] != c[j]) pieces_.push_back(undirected(c[j - 1], c[j]));
            }
        }
        std::sort(pieces_.begin(), pieces_.end());
        pieces_.erase(std::unique(pieces_.begin(), pieces_.end()), pieces_.end());
    }

    // The lines each added point is the rounded crossing of. The files do not record them:
    // the segments' ends, or where rounding bent pieces (cascades), the ends of the pieces
    // through it on the two chains; the first that gives the point exactly, else the
    // segments' ends (and the certifier says the point is not their crossing).
    void build_crossing_lines() {
        const std::size_t n = input_.points.size();
        cdt.crossing_lines.assign(cdt.added_count(), {0, 0, 0, 0});
        for (std::size_t i = 0; i < cdt.added_count(); ++i) {
            const std::uint32_t p = static_cast<std::uint32_t>(n + i);
            const auto [s, t] = cdt.crossings[i];
            if (s >= segments_.size() || t >= segments_.size()) continue;
            if (segments_[s].a >= n || segments_[s].b >= n || segments_[t].a >= n ||
                segments_[t].b >= n)
                continue;
            const auto lines = [&](std::size_t seg) {
                std::vector<Pair> v{{domain_.vertex_of_input[segments_[seg].a],
                                     domain_.vertex_of_input[segments_[seg].b]}};
                const auto c = cdt.chain(seg);
                for (std::size_t j = 1; j + 1 < c.size(); ++j) {
                    if (c[j] == p && c[j - 1] < p && c[j + 1] < p)
                        v.push_back({c[j - 1], c[j + 1]});
                }
                return v;
            };
            const std::vector<Pair> ls = lines(s), lt = lines(t);
            cdt.crossing_lines[i] = {ls[0][0], ls[0][1], lt[0][0], lt[0][1]};
            const Point2 q = cdt.points[p];
            bool found = false;
            for (const Pair& u : ls) {
                for (const Pair& v : lt) {
                    if (found) break;
                    const Point2 a = cdt.points[u[0]], b = cdt.points[u[1]], c = cdt.points[v[0]],
                                 d = cdt.points[v[1]];
                    if (!cross_properly(a, b, c, d)) continue;
                    const Intersection x = intersection(a, b, c, d);
                    if (x.ok() && x.point.x == q.x && x.point.y == q.y) {
                        cdt.crossing_lines[i] = {u[0], u[1], v[0], v[1]};
                        found = true;
                    }
                }
            }
        }
    }

    // The constrained Delaunay triangulation of the vertices with the pieces as constraints,
    // outside the file's domain: every triangle reachable from the domain's side of its
    // boundary without crossing that boundary is the domain's; the others complete it.
    bool complete() {
        std::vector<delaunay::Segment> pieces;
        pieces.reserve(pieces_.size());
        for (const Pair& p : pieces_) pieces.push_back({p[0], p[1]});
        delaunay::ConstrainedResult r = delaunay::constrained_delaunay<K>(cdt.points, pieces, K{});
        if (!r.ok() || r.cdt.added_count() != 0) return false;
        const delaunay::Triangulation& full = r.cdt.triangulation;
        if (full.collinear) {
            if (file_triangles != 0) return false;
            collinear_whole_ = true;
            collinear_ = std::move(r.cdt.triangulation);
            return true;
        }
        std::vector<Pair> directed, edges;
        for (std::size_t e = 0; e < own_twins_.size(); ++e) {
            if (own_twins_[e] >= 0) continue;
            const std::uint32_t u = domain_.triangles[e],
                                v = domain_.triangles[delaunay::next_halfedge(e)];
            directed.push_back({u, v});
            edges.push_back(undirected(u, v));
        }
        std::sort(directed.begin(), directed.end());
        std::sort(edges.begin(), edges.end());
        std::vector<std::uint8_t> inside(full.triangle_count(), 0);
        std::vector<std::size_t> stack;
        for (std::size_t e = 0; e < full.triangles.size(); ++e) {
            const Pair uv{full.triangles[e], full.triangles[delaunay::next_halfedge(e)]};
            if (!inside[e / 3] && std::binary_search(directed.begin(), directed.end(), uv)) {
                inside[e / 3] = 1;
                stack.push_back(e / 3);
            }
        }
        while (!stack.empty()) {
            const std::size_t t = stack.back();
            stack.pop_back();
            for (std::size_t e = 3 * t; e < 3 * t + 3; ++e) {
                const std::int32_t twin = full.halfedges[e];
                if (twin < 0 || inside[static_cast<std::size_t>(twin) / 3]) continue;
                const Pair uv =
                    undirected(full.triangles[e], full.triangles[delaunay::next_halfedge(e)]);
                if (std::binary_search(edges.begin(), edges.end(), uv)) continue;
                inside[static_cast<std::size_t>(twin) / 3] = 1;
                stack.push_back(static_cast<std::size_t>(twin) / 3);
            }
        }
        for (std::size_t t = 0; t < inside.size(); ++t) {
            if (inside[t]) continue;
            completion_.insert(completion_.end(), full.triangles.begin() + 3 * t,
                               full.triangles.begin() + 3 * t + 3);
        }
        completion_triangles = completion_.size() / 3;
        return true;
    }

    // Whether added point p is within chain_tolerance of both its segments.
    bool tolerable(std::int64_t index) const {
        const std::size_t n = input_.points.size();
        if (index < 0 || static_cast<std::size_t>(index) < n ||
            static_cast<std::size_t>(index) >= cdt.points.size() || reported_.count(index))
            return false;
        const auto [s, t] = cdt.crossings[static_cast<std::size_t>(index) - n];
        if (s >= segments_.size() || t >= segments_.size() || s == t) return false;
        const Point2 q = cdt.points[static_cast<std::size_t>(index)];
        const auto ends = [&](std::size_t seg) {
            return std::pair(input_.points[segments_[seg].a], input_.points[segments_[seg].b]);
        };
        const auto [a, b] = ends(s);
        const auto [c, d] = ends(t);
        return within(q, a, b) && within(q, c, d);
    }

    // The certifier's findings: those about added points reported here dropped, tolerated
    // ones turned into notes, the completion's triangles said to be its.
    void take(const delaunay::Certificate& c) {
        std::size_t dropped = 0;
        for (const delaunay::Finding& f : c.findings) {
            if (f.kind == FindingKind::added_point_wrong) {
                if (reported_.count(f.index)) {
                    ++dropped;
                    continue;
                }
                if (settings_.tolerate_crossings && tolerable(f.index)) {
                    ++dropped;
                    notes.push_back("tolerated (within chain_tolerance of both segments): " +
                                    f.message);
                    continue;
                }
            }
            Report r{std::string(delaunay::to_string(f.kind)),
                     f.message,
                     f.triangle,
                     f.points,
                     f.index,
                     f.other};
            if (f.triangle >= static_cast<std::int64_t>(file_triangles)) {
                r.message += " (triangles from " + num(file_triangles) +
                             " on are the completion's, outside the file's domain)";
                r.triangle = -1;
            }
            reports.push_back(std::move(r));
        }
        total += c.total_findings - dropped;
    }

    // The file's triangles must be exactly the domain: --fill's rule and the hole seeds on
    // the certified whole (rows 0 .. file_triangles - 1), or with --fill any, bounded by
    // pieces and the hull.
    void check_domain() {
        const delaunay::Triangulation& whole = cdt.triangulation;
        if (settings_.any_domain) {
            for (std::size_t e = 0; e < own_twins_.size(); ++e) {
                if (own_twins_[e] >= 0 || whole.halfedges[e] < 0) continue;
                const std::uint32_t u = whole.triangles[e],
                                    v = whole.triangles[delaunay::next_halfedge(e)];
                if (std::binary_search(pieces_.begin(), pieces_.end(), undirected(u, v))) continue;
                add({"domain_mismatch",
                     "edge (" + num(u) + ", " + num(v) + ") of triangle " + num(e / 3) + " " +
                         triangle_name(e / 3) +
                         " bounds the file's domain but is neither a constraint piece nor on "
                         "the hull",
                     static_cast<std::int64_t>(e / 3),
                     {u, v},
                     static_cast<std::int64_t>(e),
                     -1});
            }
            return;
        }
        const FillRule rule = *settings_.fill;
        const delaunay::Regions regions = delaunay::classify_regions(cdt, {rule, input_.holes});
        for (const std::size_t h : regions.unplaced_holes) {
            notes.push_back("hole " + num(h + input_.index_base) +
                            " is outside the triangulation or exactly on a segment or point; it "
                            "removes nothing");
        }
        if (!regions.closed && rule == FillRule::non_zero) {
            notes.push_back(
                "the segments do not form closed rings, so winding numbers depend on "
                "the path");
        }
        const auto kept_by_rule = [&](std::size_t t) {
            switch (rule) {
                case FillRule::even_odd: return regions.depth[t] % 2 == 1;
                case FillRule::non_zero: return regions.winding[t] != 0;
                case FillRule::enclosed: return regions.depth[t] > 0;
                case FillRule::all: return true;
            }
            return true;
        };
        // By region: the first triangle and how many.
        std::map<std::uint32_t, std::pair<std::size_t, std::size_t>> extra, missing;
        for (std::size_t t = 0; t < whole.triangle_count(); ++t) {
            const bool in_file = t < file_triangles;
            if (in_file == (regions.inside[t] != 0)) continue;
            auto& m = in_file ? extra : missing;
            const auto [it, fresh] = m.try_emplace(regions.region[t], t, 0);
            ++it->second.second;
            (void)fresh;
        }
        const auto where = [&](std::size_t t) {
            return "region " + num(regions.region[t]) + ": depth " + num(regions.depth[t]) +
                   ", winding " + num(regions.winding[t]) +
                   (kept_by_rule(t) && !regions.inside[t] ? ", removed by a hole seed" : "");
        };
        const std::string rule_name(fill_rule_name(rule));
        for (const auto& [region, tc] : extra) {
            const auto [t, count] = tc;
            const auto& tr = whole.triangles;
            add({"domain_mismatch",
                 "triangle " + num(t) + " " + triangle_name(t) +
                     (count > 1 ? " and " + num(count - 1) + " more triangles of its region lie"
                                : std::string(" lies")) +
                     " outside the domain under fill rule " + rule_name + " (" + where(t) + ")",
                 static_cast<std::int64_t>(t),
                 {tr[3 * t], tr[3 * t + 1], tr[3 * t + 2]},
                 static_cast<std::int64_t>(region),
                 static_cast<std::int64_t>(count)});
            total += count - 1;
        }
        for (const auto& [region, tc] : missing) {
            const auto [t, count] = tc;
            const auto& tr = whole.triangles;
            add({"domain_mismatch",
                 num(count) + (count > 1 ? " triangles" : " triangle") +
                     " of the domain under fill rule " + rule_name + (count > 1 ? " are" : " is") +
                     " not in the file, such as " + triangle_name(t) + " (" + where(t) + ")",
                 -1,
                 {tr[3 * t], tr[3 * t + 1], tr[3 * t + 2]},
                 static_cast<std::int64_t>(region),
                 static_cast<std::int64_t>(count)});
            total += count - 1;
        }
    }

    const io::ConstraintFile& input_;
    std::span<const delaunay::Segment> segments_;
    io::ProducedConstrained file_;
    const ConstrainedCertifySettings& settings_;
    delaunay::Triangulation domain_;       // the file's triangles, normalised
    std::vector<std::int32_t> own_twins_;  // their twins among themselves
    std::vector<Pair> pieces_;             // every chain's pieces, undirected, sorted
    std::vector<std::uint32_t> completion_;
    bool chains_ok_ = false;
    bool collinear_whole_ = false;
    delaunay::Triangulation collinear_;
    std::set<std::int64_t> reported_;  // added points reported here, not by the certifier
};

std::string node_path_of(const std::string& ele_path) {
    const std::size_t slash = ele_path.find_last_of('/');
    const std::size_t dot = ele_path.find_last_of('.');
    const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (has_ext ? ele_path.substr(0, dot) : ele_path) + ".node";
}

}  // namespace

int run_constrained_certify(const std::string& constraints_path, const std::string& tri_path,
                            const ConstrainedCertifySettings& s, const CommandLine& cli) {
    const io::PointFormat pf =
        s.input_format.value_or(io::point_format_from_path(constraints_path));
    if (pf != io::PointFormat::poly && pf != io::PointFormat::geojson &&
        pf != io::PointFormat::json) {
        return cli.usage_error(
            "--constraints reads .poly, .geojson or .json (or give "
            "--input-format poly|geojson|json), not '" +
            constraints_path + "'");
    }
    const std::optional<io::ProducedFormat> tf =
        s.format ? s.format : io::produced_format_from_path(tri_path);
    if (!tf || *tf == io::ProducedFormat::simplices) {
        return cli.usage_error(
            "a constrained triangulation is exidel's json, an .ele (with its "
            ".node) or an OFF: give --format json|ele|off for '" +
            tri_path + "'");
    }
    ConstrainedCertifySettings settings = s;
    if (!settings.fill && !settings.any_domain) {
        settings.fill = pf == io::PointFormat::poly ? FillRule::enclosed : FillRule::even_odd;
    }
    io::ConstraintFile input;
    io::ProducedConstrained file;
    std::string reading = constraints_path;
    try {
        input = io::parse_constraint_file(io::FileBytes(constraints_path).view(), pf);
        reading = tri_path;
        if (*tf == io::ProducedFormat::json) {
            const io::FileBytes bytes(tri_path);
            if (!io::is_constrained_json(bytes.view())) {
                std::cerr << "exidel: " << tri_path
                          << ": not exidel's constrained json (it has no \"added_points\" or "
                             "\"chain_offsets\"): a constrained triangulation is certified from "
                             "that json, an .ele with its .node, or an OFF of every vertex\n";
                return exit_failure;
            }
            file = io::read_constrained_json(bytes.view(), input.points);
        } else if (*tf == io::ProducedFormat::ele) {
            reading = node_path_of(tri_path);
            file.points =
                io::parse_point_file(io::FileBytes(reading).view(), io::PointFormat::node).points;
            reading = tri_path;
            file.mesh = io::read_produced(io::FileBytes(tri_path).view(), *tf, file.points);
        } else {
            file = io::read_constrained_off(io::FileBytes(tri_path).view(), input.points);
        }
    } catch (const io::ReadError& e) {
        std::cerr << "exidel: " << reading << ": " << e.what() << '\n';
        return exit_failure;
    } catch (const std::runtime_error& e) {
        std::cerr << "exidel: " << e.what() << '\n';
        return exit_failure;
    }
    std::vector<delaunay::Segment> segments;
    segments.reserve(input.segments.size());
    for (const auto& [a, b] : input.segments) segments.push_back({a, b});

    Rebuild r(input, segments, std::move(file), settings);
    r.run();
    if (!s.quiet) {
        for (const std::string& n : r.notes) std::cerr << "exidel: note: " << n << '\n';
    }
    const bool ok = r.total == 0;
    const std::string domain =
        settings.any_domain ? "any" : std::string(fill_rule_name(*settings.fill));
    if (s.json) {
        nlohmann::ordered_json findings = nlohmann::ordered_json::array();
        for (const Report& f : r.reports) {
            findings.push_back({{"kind", f.kind},
                                {"message", f.message},
                                {"triangle", f.triangle},
                                {"points", f.points},
                                {"index", f.index},
                                {"other", f.other}});
        }
        const nlohmann::ordered_json out{{"certified", ok},
                                         {"points", input.points.size()},
                                         {"segments", segments.size()},
                                         {"added_points", r.cdt.added_count()},
                                         {"triangles", r.file_triangles},
                                         {"completion_triangles", r.completion_triangles},
                                         {"fill", domain},
                                         {"total_findings", r.total},
                                         {"notes", r.notes},
                                         {"findings", std::move(findings)}};
        std::cout << out.dump(1) << '\n';
        return ok ? exit_ok : exit_failure;
    }
    const std::size_t shown =
        s.all ? r.reports.size() : std::min<std::size_t>(r.reports.size(), 64);
    for (std::size_t i = 0; i < shown; ++i) {
        std::cout << r.reports[i].kind << ": " << r.reports[i].message << '\n';
    }
    if (r.total > shown) {
        std::cout << "... and " << r.total - shown << " more findings (--all prints every one)\n";
    }
    if (!ok) {
        std::cout << "not certified: " << r.total << " findings\n";
        return exit_failure;
    }
    std::cout << "certified: the constrained Delaunay triangulation of " << input.points.size()
              << " points and " << segments.size() << " segments (" << r.cdt.added_count()
              << " added points), " << r.file_triangles << " triangles";
    if (r.completion_triangles == 0) {
        std::cout << ", the whole convex hull";
    } else {
        std::cout << " of the domain (the hull completed with " << r.completion_triangles
                  << " triangles)";
    }
    std::cout << ", fill " << domain << '\n';
    return exit_ok;
}

}  // namespace exidel::cli
