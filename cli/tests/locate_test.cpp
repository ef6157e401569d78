// End-to-end tests of `exidel locate`: the csv and json tables against the library's
// Locator on a lattice whose half-step queries are all on edges, vertices or outside,
// duplicates, collinear points, usage errors and malformed queries (no output written),
// --stats.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "exidel/delaunay/interpolate.hpp"
#include "exidel/delaunay/natural.hpp"
#include "exidel/delaunay/locate.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "run_binary.hpp"

namespace {

using exidel::AdaptiveKernel;
using exidel::Point2;
namespace delaunay = exidel::delaunay;
using namespace exidel::cli_test;

RunResult run(const std::string& args, const std::string& input = "") {
    return run_exidel("loc", "locate " + args, input);
}

std::string xy_text(const std::vector<Point2>& points) {
    std::ostringstream s;
    for (const Point2& p : points) s << std::hexfloat << p.x << ' ' << p.y << '\n';
    return s.str();
}

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream s(text);
    while (std::getline(s, part, sep)) parts.push_back(part);
    return parts;
}

TEST(LocateCommand, CsvMatchesTheLibraryOnALattice) {
    std::vector<Point2> points, queries;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) points.push_back({double(i), double(j)});
    for (int i = -1; i < 12; ++i)
        for (int j = -1; j < 12; ++j) queries.push_back({i * 0.5, j * 0.5});
    const std::string pts = write_file("loc_lattice.xy", xy_text(points));
    const std::string qs = write_file("loc_lattice_q.xy", xy_text(queries));
    const RunResult r = run("-q " + pts + " -Q " + qs);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto lines = split(r.out, '\n');
    ASSERT_EQ(lines.size(), queries.size() + 1);
    EXPECT_EQ(lines[0], "query,kind,triangle,v0,v1,v2,edge_from,edge_to,vertex");

    const auto tri = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    const delaunay::Locator<AdaptiveKernel> locator(points, tri);
    std::vector<delaunay::Location> where(queries.size());
    ASSERT_FALSE(locator.locate(queries, where, {.threads = 2}).has_value());
    std::size_t on_edge = 0, on_vertex = 0, outside = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const auto f = split(lines[i + 1], ',');
        ASSERT_GE(f.size(), 8u) << lines[i + 1];
        EXPECT_EQ(f[0], std::to_string(i));
        EXPECT_EQ(f[1], delaunay::to_string(where[i].kind)) << lines[i + 1];
        EXPECT_EQ(f[2], std::to_string(where[i].triangle));
        on_edge += f[1] == "on_edge";
        on_vertex += f[1] == "on_vertex";
        outside += f[1] == "outside";
        if (f[1] == "on_vertex") {
            ASSERT_EQ(f.size(), 9u);
            const Point2 v = points[std::stoul(f[8])];
            EXPECT_TRUE(v.x == queries[i].x && v.y == queries[i].y);
        }
        if (f[1] == "on_edge") {
            const Point2 a = points[std::stoul(f[6])], b = points[std::stoul(f[7])];
            EXPECT_EQ(AdaptiveKernel::orient2d(a, b, queries[i]), exidel::Sign::zero);
        }
    }
    EXPECT_EQ(on_vertex, 36u);
    EXPECT_EQ(on_edge, 2u * 5 * 6 + 5 * 5);  // axis edges' midpoints, cells' centres
    EXPECT_EQ(outside, 13u * 13 - 11 * 11);
}

TEST(LocateCommand, JsonDuplicatesAndStats) {
    const std::string pts = write_file("loc_dup.xy", "0 0\n1 0\n0 1\n1 1\n1 1\n");
    const std::string qs =
        write_file("loc_dup_q.json", "[[1, 1], [0.5, 0.5], [3, 3], [0.25, 0.25]]");
    const std::string out = work_path("loc_dup_out.json");
    std::remove(out.c_str());
    const RunResult r = run(pts + " -Q " + qs + " -o " + out + " --stats -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(slurp(out));
    EXPECT_EQ(j["kind"], (nlohmann::json{"on_vertex", "on_edge", "outside", "inside"}));
    EXPECT_EQ(j["vertex"][0], 3);  // the first of the two copies of (1, 1)
    EXPECT_TRUE(j["vertex"][1].is_null());
    EXPECT_TRUE(j["edge"][1].is_array());
    EXPECT_TRUE(j["edge"][2].is_array());  // the hull edge that sees (3, 3)
    const auto stats = nlohmann::json::parse(r.err);
    EXPECT_EQ(stats["queries"], 4);
    EXPECT_EQ(stats["on_vertex"], 1);
    EXPECT_EQ(stats["outside"], 1);
    EXPECT_TRUE(stats["failure"].is_null());
}

TEST(LocateCommand, CollinearPoints) {
    const std::string pts = write_file("loc_line.xy", "0 0\n1 1\n2 2\n");
    const RunResult r = run(pts + " -Q - -f json", "0.5 0.5\n1 1\n3 3\n0 1\n");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["kind"], (nlohmann::json{"on_edge", "on_vertex", "outside", "outside"}));
    EXPECT_EQ(j["edge"][0], (nlohmann::json{0, 1}));
    EXPECT_TRUE(j["triangle"][0].is_null());
}

TEST(LocateCommand, ErrorsWriteNothing) {
    const std::string pts = write_file("loc_err.xy", "0 0\n1 0\n0 1\n");
    const std::string out = work_path("loc_err_out.csv");
    std::remove(out.c_str());
    RunResult r = run(pts);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--queries"), std::string::npos);
    r = run("-Q - -", "0 0\n");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("standard input"), std::string::npos);
    const std::string bad = write_file("loc_err_q.xy", "0.1 0.1\n0.2 nan\n");
    r = run(pts + " -Q " + bad + " -o " + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("queries: line 2"), std::string::npos) << r.err;
    EXPECT_FALSE(exists(out));
    r = run(pts + " -Q " + work_path("loc_missing.xy") + " -o " + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("exidel: queries:"), std::string::npos) << r.err;
    EXPECT_FALSE(exists(out));
    r = run(pts + " -Q " + bad + " -o " + work_path("loc.txt"));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(files_containing("loc_err_out.csv.tmp").empty());
}

TEST(InterpolateCommand, LinearAndNearestMatchTheLibrary) {
    // A plane's values are reproduced by linear interpolation up to rounding; vertices
    // exactly; outside gets --fill; nearest gives a nearest point's value.
    std::vector<Point2> points, queries;
    std::ostringstream text;
    std::vector<double> z;
    for (int i = 0; i < 7; ++i) {
        for (int j = 0; j < 5; ++j) {
            const Point2 p{i * 1.5 + (j % 2) * 0.25, j * 0.75 + (i % 3) * 0.125};
            points.push_back(p);
            z.push_back(2 * p.x - 3 * p.y + 1);
            text << std::hexfloat << p.x << ',' << p.y << ',' << z.back() << '\n';
        }
    }
    for (int k = 0; k < 60; ++k) queries.push_back({k * 0.17 - 0.5, (k % 11) * 0.33 - 0.2});
    queries.push_back(points[7]);
    const std::string pts = write_file("interp_plane.csv", "x,y,z\n" + text.str());
    const std::string qs = write_file("interp_plane_q.xy", xy_text(queries));
    const RunResult r = run_exidel(
        "interp", "interpolate -q " + pts + " --columns x,y,z -Q " + qs + " -f json --fill -99",
        "");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto got = nlohmann::json::parse(r.out)["value"];
    ASSERT_EQ(got.size(), queries.size());
    const auto tri = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    const delaunay::Locator<AdaptiveKernel> locator(points, tri);
    std::vector<delaunay::Location> where(queries.size());
    ASSERT_FALSE(locator.locate(queries, where).has_value());
    std::vector<double> want(queries.size());
    delaunay::interpolate_linear(points, tri, z, queries, where, want, -99);
    std::size_t inside = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
        EXPECT_EQ(got[i].get<double>(), want[i]) << i;
        if (where[i].kind == delaunay::LocationKind::outside) {
            EXPECT_EQ(want[i], -99);
        } else {
            ++inside;
            EXPECT_NEAR(want[i], 2 * queries[i].x - 3 * queries[i].y + 1, 1e-12) << i;
        }
    }
    EXPECT_GT(inside, 20u);
    EXPECT_EQ(got.back().get<double>(), z[7]);  // a vertex: its value exactly

    const RunResult n = run_exidel(
        "interp", "interpolate -q " + pts + " --columns x,y,z -Q " + qs + " -m nearest", "");
    ASSERT_EQ(n.status, 0) << n.err;
    const auto lines = split(n.out, '\n');
    ASSERT_EQ(lines.size(), queries.size() + 1);
    EXPECT_EQ(lines[0], "x,y,value");
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const double value = std::stod(split(lines[i + 1], ',')[2]);
        double best = INFINITY, best_value = 0;
        bool tie_value = false;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const double d = std::hypot(points[k].x - queries[i].x, points[k].y - queries[i].y);
            if (d < best)
                best = d, best_value = z[k], tie_value = false;
            else if (d == best)
                tie_value = tie_value || z[k] == value;
        }
        EXPECT_TRUE(value == best_value || tie_value) << i;
    }
}

TEST(InterpolateCommand, NaturalMatchesTheLibrary) {
    // Sibson's interpolant reproduces a plane; --exact gives the library's exact values.
    std::vector<Point2> points, queries;
    std::ostringstream text;
    std::vector<double> z;
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 6; ++j) {
            const Point2 p{i * 1.5 + (j % 2) * 0.25, j * 0.75 + (i % 3) * 0.125};
            points.push_back(p);
            z.push_back(2 * p.x - 3 * p.y + 1);
            text << std::hexfloat << p.x << ',' << p.y << ',' << z.back() << '\n';
        }
    }
    for (int k = 0; k < 80; ++k) queries.push_back({k * 0.17 - 0.5, (k % 13) * 0.33 - 0.2});
    queries.push_back(points[9]);
    const std::string pts = write_file("interp_natural.csv", "x,y,z\n" + text.str());
    const std::string qs = write_file("interp_natural_q.xy", xy_text(queries));
    const auto tri = delaunay::triangulate(points, AdaptiveKernel{}).triangulation;
    const delaunay::Locator<AdaptiveKernel> locator(points, tri);
    for (const bool exact : {false, true}) {
        const RunResult r =
            run_exidel("interp",
                       "interpolate -q " + pts + " --columns x,y,z -Q " + qs +
                           " -f json --fill -99 -m natural" + (exact ? " --exact" : ""),
                       "");
        ASSERT_EQ(r.status, 0) << r.err;
        const auto got = nlohmann::json::parse(r.out)["value"];
        ASSERT_EQ(got.size(), queries.size());
        std::vector<double> want(queries.size());
        ASSERT_FALSE(delaunay::interpolate_natural(
            locator, z, 1, queries, want, -99,
            {.arithmetic = exact ? delaunay::NaturalArithmetic::exact
                                 : delaunay::NaturalArithmetic::rounded}));
        std::size_t inside = 0;
        for (std::size_t i = 0; i < queries.size(); ++i) {
            EXPECT_EQ(got[i].get<double>(), want[i]) << i;
            if (want[i] != -99) {
                ++inside;
                EXPECT_NEAR(want[i], 2 * queries[i].x - 3 * queries[i].y + 1, 1e-12) << i;
            }
        }
        EXPECT_GT(inside, 30u);
        EXPECT_EQ(got.back().get<double>(), z[9]);
    }
}

TEST(InterpolateCommand, PointsWithoutValuesAreAnError) {
    const std::string pts = write_file("interp_novalue.xy", "0 0\n1 0\n0 1\n");
    const std::string out = work_path("interp_novalue.csv");
    std::remove(out.c_str());
    const RunResult r = run_exidel("interp", "interpolate " + pts + " -Q - -o " + out, "0.1 0.1\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("no values"), std::string::npos) << r.err;
    EXPECT_FALSE(exists(out));
    EXPECT_EQ(run_exidel("interp", "interpolate " + pts + " -Q - -m cubic", "").status, 2);
}

}  // namespace
