// `exidel certify` end to end: one triangulation written as delaunator, scipy, numpy and
// CGAL write it is certified from each, and a corrupted copy gets the same located
// findings from each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "exidel/delaunay/result.hpp"
#include "exidel/io/number.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "run_binary.hpp"

namespace {

using exidel::AdaptiveKernel;
using exidel::Point2;
using exidel::Sign;
using exidel::delaunay::next_halfedge;
using exidel::delaunay::prev_halfedge;
using exidel::delaunay::Triangulation;
namespace io = exidel::io;
using namespace exidel::cli_test;

RunResult certify(const std::string& args) { return run_exidel("cert2", "certify " + args, ""); }

// 400 random points, 30 of them repeated (the repeats later in the input).
std::vector<Point2> points() {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(-50, 50);
    std::vector<Point2> p(400);
    for (auto& q : p) q = {u(rng), u(rng)};
    for (int i = 0; i < 30; ++i) p.push_back(p[static_cast<std::size_t>(i * 13)]);
    return p;
}

// Appends each piece: "x" + std::string(...) trips GCC 12's -Wrestrict (a false positive).
template <class... P>
void append(std::string& s, const P&... pieces) {
    (s.append(pieces), ...);
}

std::string shortest(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

std::string json_array(const auto& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (i) s += ',';
        s += std::to_string(v[i]);
    }
    return s + "]";
}

// Twins of a triangle list, matched by reversed edges.
std::vector<std::int32_t> twins(const std::vector<std::uint32_t>& T) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::int32_t> edge;
    for (std::size_t e = 0; e < T.size(); ++e) edge[{T[e], T[next_halfedge(e)]}] = std::int32_t(e);
    std::vector<std::int32_t> h(T.size(), -1);
    for (std::size_t e = 0; e < T.size(); ++e) {
        const auto it = edge.find({T[next_halfedge(e)], T[e]});
        if (it != edge.end()) h[e] = it->second;
    }
    return h;
}

// The four layouts of `t`, each a file: delaunator's object (clockwise triangles, the
// hull clockwise from elsewhere, later copies, coords), scipy's rows as JSON (every
// other row clockwise), numpy.savetxt's text of them, and CGAL's OFF (the distinct
// points in a shuffled order, 17 digits).
std::vector<std::string> layouts(const std::string& name, const std::vector<Point2>& pts,
                                 const Triangulation& t) {
    std::vector<std::uint32_t> last(pts.size());
    for (std::uint32_t i = 0; i < pts.size(); ++i) last[t.vertex_of_input[i]] = i;
    // delaunator
    std::vector<std::uint32_t> T = t.triangles;
    for (std::size_t i = 0; i < T.size(); i += 3) std::swap(T[i + 1], T[i + 2]);
    for (auto& v : T) v = last[v];
    std::vector<std::uint32_t> hull(t.hull.rbegin(), t.hull.rend());
    std::rotate(hull.begin(), hull.begin() + 3, hull.end());
    std::string coords = "[";
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (i) coords += ',';
        append(coords, shortest(pts[i].x), ",", shortest(pts[i].y));
    }
    coords += "]";
    std::vector<std::string> files;
    std::string object;
    append(object, "{\"coords\": ", coords, ", \"triangles\": ", json_array(T),
           ", \"halfedges\": ", json_array(twins(T)), ", \"hull\": ", json_array(hull), "}");
    files.push_back(write_file(name + "-delaunator.json", object));
    // scipy rows, JSON and text
    std::string rows = "[", text;
    for (std::size_t i = 0; i < t.triangles.size(); i += 3) {
        std::uint32_t a = last[t.triangles[i]], b = t.triangles[i + 1], c = t.triangles[i + 2];
        if (i % 2) std::swap(b, c);
        if (i) rows += ',';
        append(rows, "[", std::to_string(a), ",", std::to_string(b), ",", std::to_string(c), "]");
        char line[128];
        std::snprintf(line, sizeof line, "%.18e %.18e %.18e\n", double(a), double(b), double(c));
        text += line;
    }
    files.push_back(write_file(name + "-scipy.json", rows + "]"));
    files.push_back(write_file(name + "-savetxt.txt", text));
    // CGAL's OFF
    std::vector<std::uint32_t> distinct;
    for (std::uint32_t i = 0; i < pts.size(); ++i) {
        if (t.vertex_of_input[i] == i) distinct.push_back(i);
    }
    std::shuffle(distinct.begin(), distinct.end(), std::mt19937_64(5));
    std::map<std::uint32_t, std::size_t> at;
    std::string off;
    append(off, "OFF\n", std::to_string(distinct.size()), " ", std::to_string(t.triangle_count()),
           " 0\n");
    for (std::size_t k = 0; k < distinct.size(); ++k) {
        at[distinct[k]] = k;
        append(off, shortest(pts[distinct[k]].x), " ", shortest(pts[distinct[k]].y), " 0\n");
    }
    for (std::size_t i = 0; i < t.triangles.size(); i += 3) {
        append(off, "3 ", std::to_string(at[t.triangles[i]]), " ",
               std::to_string(at[t.triangles[i + 1]]), " ", std::to_string(at[t.triangles[i + 2]]),
               "\n");
    }
    files.push_back(write_file(name + "-cgal.off", off));
    return files;
}

std::string format_of(const std::string& file) {
    return file.ends_with(".txt") ? " --format simplices" : "";
}

// (kind, the points sorted): what a finding says independently of triangle order.
using Located = std::multiset<std::pair<std::string, std::vector<std::int64_t>>>;

Located findings(const nlohmann::json& report) {
    Located out;
    for (const auto& f : report.at("findings")) {
        auto p = f.at("points").get<std::vector<std::int64_t>>();
        std::sort(p.begin(), p.end());
        out.insert({f.at("kind").get<std::string>(), p});
    }
    return out;
}

TEST(ExidelCertify, EveryProducersLayoutOfOneTriangulationCertifies) {
    const std::vector<Point2> pts = points();
    std::ostringstream xy;
    io::write_points(xy, pts, io::PointFormat::xy);
    const std::string in = write_file("producers.xy", xy.str());
    const RunResult made = run_exidel("cert2", "triangulate -q -i " + in, "");
    ASSERT_EQ(made.status, 0) << made.err;
    Triangulation t = io::parse_triangulation_json(made.out);
    io::fill_vertex_of_input(pts, t);
    for (const std::string& file : layouts("good", pts, t)) {
        const RunResult r = certify(in + " " + file + format_of(file));
        EXPECT_EQ(r.status, 0) << file << "\n" << r.out << r.err;
        EXPECT_EQ(r.out, "certified: the Delaunay triangulation of 430 points (400 distinct), " +
                             std::to_string(t.triangle_count()) + " triangles\n")
            << file;
        // Each convention shows as a note, and --quiet silences them.
        if (file.ends_with("delaunator.json")) {
            EXPECT_NE(r.err.find("clockwise triangles turned counter-clockwise"),
                      std::string::npos);
            EXPECT_NE(r.err.find("later copy"), std::string::npos) << r.err;
            EXPECT_NE(r.err.find("hull ran clockwise"), std::string::npos) << r.err;
            EXPECT_EQ(certify("-q " + in + " " + file).err, "");
            // --strict holds it to exidel's layout: a vertex at each later copy.
            const RunResult strict = certify("--strict " + in + " " + file);
            EXPECT_EQ(strict.status, 1);
            EXPECT_NE(strict.out.find("duplicate_vertex: triangle "), std::string::npos);
            EXPECT_NE(strict.out.find("... and "), std::string::npos);  // more than 64
            const RunResult all = certify("--strict --all " + in + " " + file);
            const std::size_t verdict = all.out.rfind("not certified: ");
            ASSERT_NE(verdict, std::string::npos) << all.out;
            const long total = std::stol(all.out.substr(verdict + 15));
            EXPECT_GT(total, 64);
            EXPECT_EQ(std::count(all.out.begin(), all.out.end(), '\n'), total + 1);
            EXPECT_EQ(all.out.find("... and "), std::string::npos);
        }
    }
    // delaunator's coords of other points: an error naming the point, not a verdict.
    std::vector<Point2> moved = pts;
    moved[3].x += 1;
    std::ostringstream other;
    io::write_points(other, moved, io::PointFormat::xy);
    const RunResult wrong =
        certify(write_file("moved.xy", other.str()) + " " + work_path("good-delaunator.json"));
    EXPECT_EQ(wrong.status, 1);
    EXPECT_NE(wrong.err.find("coords[6] is not coordinate x of point 3"), std::string::npos)
        << wrong.err;
}

TEST(ExidelCertify, ACorruptedCopyGetsTheSameLocatedFindingsFromEveryLayout) {
    const std::vector<Point2> pts = points();
    std::ostringstream xy;
    io::write_points(xy, pts, io::PointFormat::xy);
    const std::string in = write_file("corrupt.xy", xy.str());
    const RunResult made = run_exidel("cert2", "triangulate -q -i " + in, "");
    ASSERT_EQ(made.status, 0) << made.err;
    Triangulation t = io::parse_triangulation_json(made.out);
    io::fill_vertex_of_input(pts, t);
    // Flip one interior edge whose quadrilateral is strictly convex and not cocircular.
    std::uint32_t c = 0, d = 0;
    for (std::size_t e = 0; e < t.halfedges.size(); ++e) {
        if (t.halfedges[e] < 0) continue;
        const auto tw = static_cast<std::size_t>(t.halfedges[e]);
        const std::uint32_t a = t.triangles[e], b = t.triangles[next_halfedge(e)];
        c = t.triangles[prev_halfedge(e)];
        d = t.triangles[prev_halfedge(tw)];
        using K = AdaptiveKernel;
        if (K::orient2d(pts[c], pts[d], pts[a]) == Sign::zero ||
            K::orient2d(pts[c], pts[d], pts[a]) == K::orient2d(pts[c], pts[d], pts[b]) ||
            K::orient2d(pts[c], pts[d], pts[b]) == Sign::zero ||
            K::incircle(pts[a], pts[b], pts[c], pts[d]) == Sign::zero)
            continue;
        const std::size_t t0 = 3 * (e / 3), t1 = 3 * (tw / 3);
        t.triangles[t0] = c, t.triangles[t0 + 1] = a, t.triangles[t0 + 2] = d;
        t.triangles[t1] = d, t.triangles[t1 + 1] = b, t.triangles[t1 + 2] = c;
        break;
    }
    t.halfedges = twins(t.triangles);
    std::vector<Located> seen;
    for (const std::string& file : layouts("bad", pts, t)) {
        const RunResult r = certify("--json " + in + " " + file + format_of(file));
        EXPECT_EQ(r.status, 1) << file << r.out << r.err;
        const nlohmann::json report = nlohmann::json::parse(r.out);
        EXPECT_FALSE(report.at("certified").get<bool>());
        EXPECT_EQ(report.at("total_findings"), report.at("findings").size());
        const auto& f = report.at("findings").at(0);
        EXPECT_EQ(f.at("kind"), "not_delaunay") << r.out;
        EXPECT_GE(f.at("triangle").get<std::int64_t>(), 0);
        const auto p = f.at("points").get<std::vector<std::int64_t>>();
        ASSERT_EQ(p.size(), 4u);
        EXPECT_EQ(std::set<std::int64_t>(p.begin(), p.begin() + 2),
                  (std::set<std::int64_t>{c, d}));  // the flipped diagonal
        seen.push_back(findings(report));
        // The text form names the edge, its triangle and the point.
        const RunResult text = certify(in + " " + file + format_of(file));
        EXPECT_EQ(text.out.rfind("not_delaunay: edge (", 0), 0u) << text.out;
        EXPECT_NE(
            text.out.find(") of triangle " + std::to_string(f.at("triangle").get<int>()) + " ("),
            std::string::npos)
            << text.out;
    }
    ASSERT_EQ(seen.size(), 4u);
    for (const Located& s : seen) EXPECT_EQ(s, seen.front());
}

TEST(ExidelCertify, ReadErrorsNameTheLine) {
    const std::string tri = write_file("three.xy", "0 0\n1 0\n0 1\n");
    const auto err = [&](const std::string& name, const std::string& text, const char* format) {
        const RunResult r = certify(tri + " " + write_file(name, text) + format);
        EXPECT_EQ(r.status, 1) << name;
        return r.err;
    };
    EXPECT_NE(err("a.txt", "0 1 2\n0 1\n", " -f simplices").find("line 2: expected three"),
              std::string::npos);
    EXPECT_NE(err("b.txt", "0 1 2.5\n", " -f simplices").find("line 1: vertex"), std::string::npos);
    EXPECT_NE(err("c.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 2 0\n3 0 1 2\n", "")
                  .find("line 5: vertex 2 (0 2) is not one of the input points"),
              std::string::npos);
    EXPECT_NE(err("d.off", "OFF\n3 1 0\n0 0\n1 0\n0 1\n4 0 1 2 0\n", "")
                  .find("line 6: face 0 has 4 vertices"),
              std::string::npos);
    EXPECT_NE(err("e.off", "OFF\n3 2 0\n0 0\n1 0\n0 1\n3 0 1 2\n", "").find("truncated"),
              std::string::npos);
    EXPECT_NE(err("f.json", "[[0, 1, 2], [0, 1]]", "").find("line 1: expected ','"),
              std::string::npos);
    EXPECT_NE(err("g.json", "{\"hull\": [0, 1, 2]}", "").find("\"triangles\" is missing"),
              std::string::npos);
    // A certified OFF with its vertices in another order, and 2D vertex lines.
    const RunResult ok =
        certify(tri + " " + write_file("h.off", "OFF 3 1 0\n0 1\n0 0\n1 0\n3 1 2 0\n"));
    EXPECT_EQ(ok.status, 0) << ok.out << ok.err;
}

}  // namespace
