// End-to-end tests of `exidel triangulate`'s constrained mode (--constraints, .poly input):
// the fill rules and hole seeds measured by the domain's exact area, the added crossing
// points, every output format, .poly round trips, z carried to added points, errors with
// their lines and nothing written on failure.
#include <gtest/gtest.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_binary.hpp"

namespace {

using namespace exidel::cli_test;
using nlohmann::json;

RunResult run(const std::string& args, const std::string& input = "") {
    return run_exidel("cdt", "triangulate " + args, input);
}

// A 4x4 square (0-3) with a 2x2 square ring inside (4-7), and a breakline at y = 2 across
// both (8-9): it crosses the inner ring at (1, 2) and (3, 2).
const std::string square_json = R"({"points": [[0,0],[4,0],[4,4],[0,4],[1,1],[1,3],[3,3],[3,1],
  [0,2],[4,2]],
 "segments": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,7],[7,4],[8,9]]})";

// The same two squares as a 1-based .poly with a hole seed in the inner one.
const std::string square_poly = R"(# square with a hole
8 2 0 1
1 0 0 1
2 4 0 1
3 4 4 1
4 0 4 1
5 1 1 2
6 3 1 2
7 3 3 2
8 1 3 2
8 1
1 1 2 5
2 2 3 5
3 3 4 5
4 4 1 5
5 5 6 7
6 6 7 7
7 7 8 7
8 8 5 7
1
1 2 2
)";

// Twice the area of the triangles (flat, 0-based) over `xy`, exact for small integers.
std::int64_t twice_area(const std::vector<double>& xy, const std::vector<std::uint32_t>& t) {
    std::int64_t sum = 0;
    for (std::size_t k = 0; k + 2 < t.size(); k += 3) {
        const double ax = xy[2 * t[k]], ay = xy[2 * t[k] + 1], bx = xy[2 * t[k + 1]],
                     by = xy[2 * t[k + 1] + 1], cx = xy[2 * t[k + 2]], cy = xy[2 * t[k + 2] + 1];
        sum += static_cast<std::int64_t>((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
    }
    return sum;
}

// The vertices of a json output: the input points of square_json, then "added_points".
std::vector<double> vertices(const json& out) {
    std::vector<double> xy;
    const json input = json::parse(square_json);
    for (const auto& p : input["points"]) {
        xy.push_back(p[0]);
        xy.push_back(p[1]);
    }
    for (const auto& p : out["added_points"]) {
        xy.push_back(p[0]);
        xy.push_back(p[1]);
    }
    return xy;
}

TEST(ExidelConstrained, JsonInputFillRulesAndCrossings) {
    const std::string in = write_file("square.json", square_json);
    // even-odd (the default for json): the ring between the squares, area 16 - 4.
    const RunResult r = run("--constraints --certify '" + in + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("certified"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("2 crossing points added"), std::string::npos) << r.err;
    const json out = json::parse(r.out);
    EXPECT_EQ(out["added_points"], json::parse("[[1, 2], [3, 2]]"));
    EXPECT_EQ(out["crossings"].size(), 4u);
    const auto tri = out["triangles"].get<std::vector<std::uint32_t>>();
    EXPECT_EQ(twice_area(vertices(out), tri), 2 * 12);
    EXPECT_EQ(out["region"].size(), tri.size() / 3);
    EXPECT_EQ(out["halfedges"].size(), tri.size());
    // Every piece of a chain is listed once in "constraints" (no two chains share one here).
    const auto offsets = out["chain_offsets"].get<std::vector<std::uint32_t>>();
    ASSERT_EQ(offsets.size(), 10u);
    EXPECT_EQ(offsets.back() - 9, out["constraints"].size() / 2);
    for (const auto& [rule, area] : std::vector<std::pair<std::string, int>>{
             {"even-odd", 12}, {"non-zero", 12}, {"enclosed", 16}, {"all", 16}}) {
        const RunResult f = run("--constraints --fill " + rule + " '" + in + "'");
        ASSERT_EQ(f.status, 0) << rule << ": " << f.err;
        const json o = json::parse(f.out);
        EXPECT_EQ(twice_area(vertices(o), o["triangles"].get<std::vector<std::uint32_t>>()),
                  2 * area)
            << rule;
    }
}

TEST(ExidelConstrained, PolyInputIsConstrainedWithHoleSeeds) {
    const std::string in = write_file("square.poly", square_poly);
    // enclosed (the default for .poly, as Triangle) less the hole seed's square.
    const std::string out = work_path("square_out.poly");
    const RunResult r = run("'" + in + "' --certify --stats -o '" + out + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("\"fill\": \"enclosed\""), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\"triangles\": 8,"), std::string::npos) << r.err;
    const std::string written = slurp(out);
    // 1-based as the input, segment markers kept, the hole written back.
    EXPECT_EQ(written.substr(0, 17), "8 2 0 0\n1 0 0\n2 4") << written;
    EXPECT_NE(written.find("\n8 1\n1 "), std::string::npos) << written;
    EXPECT_NE(written.find(" 5\n"), std::string::npos) << written;
    EXPECT_NE(written.find("\n1\n1 2 2\n"), std::string::npos) << written;
    // The .poly written reads back to the same domain.
    const RunResult again = run("'" + out + "' --stats -f wkt");
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_NE(again.err.find("\"triangles\": 8,"), std::string::npos) << again.err;
    // --fill all keeps the hull, less the seed's region: 16 - 4 by area, 8 triangles too.
    const RunResult all = run("'" + in + "' --fill all --stats -f json");
    ASSERT_EQ(all.status, 0) << all.err;
    EXPECT_NE(all.err.find("\"hull_triangles\": 10,"), std::string::npos) << all.err;
}

TEST(ExidelConstrained, RegionalAttributesLabelTriangles) {
    // Triangle's -A: the two squares without a hole, the inner one labelled 10 and the ring
    // around it 20; a third seed outside labels nothing and says so.
    std::string poly = square_poly;
    poly.replace(poly.find("1\n1 2 2\n"), 8, "0\n3\n1 2 2 10 -1\n2 0.5 0.5 20 0.1\n3 9 9 30\n");
    const std::string in = write_file("attributes.poly", poly);
    const RunResult r = run("'" + in + "' --certify -f json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("note: region 3 is outside"), std::string::npos) << r.err;
    const json out = json::parse(r.out);
    const auto tri = out["triangles"].get<std::vector<std::uint32_t>>();
    const auto attribute = out["attribute"].get<std::vector<double>>();
    ASSERT_EQ(attribute.size(), tri.size() / 3);
    const std::vector<double> xy{0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3};
    for (std::size_t t = 0; t < attribute.size(); ++t) {
        double cx = 0, cy = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            cx += xy[2 * tri[3 * t + k]] / 3;
            cy += xy[2 * tri[3 * t + k] + 1] / 3;
        }
        EXPECT_EQ(attribute[t], cx > 1 && cx < 3 && cy > 1 && cy < 3 ? 10 : 20) << t;
    }
    // .ele: one attribute column.
    const RunResult ele = run("'" + in + "' -q -f ele");
    ASSERT_EQ(ele.status, 0) << ele.err;
    EXPECT_EQ(ele.out.substr(0, 8), "10 3 1\n1") << ele.out;
}

TEST(ExidelConstrained, EveryOutputFormat) {
    const std::string in = write_file("square_f.json", square_json);
    for (const std::string f :
         {"json", "geojson", "wkt", "off", "ply", "ply-ascii", "poly", "svg"}) {
        const RunResult r = run("--constraints -q -f " + f + " '" + in + "'");
        ASSERT_EQ(r.status, 0) << f << ": " << r.err;
        EXPECT_FALSE(r.out.empty()) << f;
        EXPECT_TRUE(r.err.empty()) << f << ": " << r.err;
    }
    // OFF and PLY hold every vertex, added points included: 10 + 2.
    EXPECT_EQ(run("--constraints -q -f off '" + in + "'").out.substr(0, 11), "OFF\n12 12 0");
    // ele writes a .node of every vertex beside it.
    const std::string ele = work_path("square_out.ele");
    ASSERT_EQ(run("--constraints -q -o '" + ele + "' '" + in + "'").status, 0);
    EXPECT_EQ(slurp(ele).substr(0, 7), "12 3 0\n");
    const std::string node = slurp(work_path("square_out.node"));
    EXPECT_EQ(node.substr(0, 9), "12 2 0 0\n") << node;
    EXPECT_NE(node.find("\n10 1 2\n11 3 2\n"), std::string::npos) << node;
    // GeoJSON: the triangles with their region, then each segment's chain.
    const json g = json::parse(run("--constraints -q -f geojson '" + in + "'").out);
    const auto& features = g["features"];
    ASSERT_EQ(features.size(), 12u + 9u);
    EXPECT_TRUE(features[0]["properties"].contains("region"));
    EXPECT_EQ(features[12 + 8]["properties"]["segment"], 8);
    EXPECT_EQ(features[12 + 8]["geometry"]["coordinates"],
              json::parse("[[0, 2], [1, 2], [3, 2], [4, 2]]"));
#ifdef EXIDEL_RSVG_CONVERT
    const std::string svg = work_path("square_out.svg");
    ASSERT_EQ(run("--constraints -q -o '" + svg + "' '" + in + "'").status, 0);
    const std::string png = work_path("square_out.png");
    EXPECT_EQ(std::system((std::string("'") + EXIDEL_RSVG_CONVERT + "' '" + svg + "' -o '" + png +
                           "' 2>/dev/null")
                              .c_str()),
              0);
#endif
}

TEST(ExidelConstrained, GeojsonZIsCarriedToAddedPoints) {
    // A square ring at z = 0 and a breakline from z = 10 to z = 20 crossing it at x = 0
    // and x = 10: each added point gets the mean of the two segments' z there.
    const std::string in = write_file("z.geojson", R"({"type": "FeatureCollection", "features": [
{"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates":
  [[[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0], [0, 0, 0]]]}},
{"type": "Feature", "properties": {}, "geometry": {"type": "LineString", "coordinates":
  [[-10, 5, 10], [20, 5, 20]]}}]})");
    const RunResult r = run("--constraints -q --certify -f geojson '" + in + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const json g = json::parse(r.out);
    const json& line = g["features"].back()["geometry"]["coordinates"];
    ASSERT_EQ(line.size(), 4u);
    // At x = 0 the breakline is at 10 + 10/3; the ring's side at 0; the mean.
    EXPECT_DOUBLE_EQ(line[1][2].get<double>(), (10.0 + 10.0 / 3) / 2);
    EXPECT_DOUBLE_EQ(line[2][2].get<double>(), (10.0 + 20.0 / 3) / 2);
}

TEST(ExidelConstrained, ErrorsSayWhereAndWriteNothing) {
    const std::string xy = write_file("cdt.xy", "0 0\n1 0\n0 1\n");
    RunResult r = run("--constraints '" + xy + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("poly, geojson or json input, not xy"), std::string::npos) << r.err;
    r = run("--fill even-odd '" + xy + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--fill applies with --constraints only"), std::string::npos) << r.err;
    r = run("--constraints --fill sideways -f json", "[]");
    EXPECT_EQ(r.status, 2) << r.err;

    const std::string out = work_path("cdt_never.json");
    const std::string bad = write_file("bad.json",
                                       "{\"points\": [[0, 0], [1, 0]],\n"
                                       " \"segments\": [[0, 1],\n [1, 2]]}");
    r = run("--constraints -o '" + out + "' '" + bad + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("line 3: segment 1 names point 2, but there are 2 points"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(exists(out));
    EXPECT_TRUE(files_containing("cdt_never").empty());

    const std::string poly = write_file("bad.poly", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 7\n");
    r = run("'" + poly + "' -o '" + out + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("line 6:"), std::string::npos) << r.err;
    EXPECT_FALSE(exists(out));
    // A hole seed outside everything removes nothing and says so.
    const std::string seed = write_file("seed.json", R"({"points": [[0,0],[1,0],[0,1]],
        "segments": [[0,1],[1,2],[2,0]], "holes": [[5, 5]]})");
    r = run("--constraints '" + seed + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("note: hole 0 is outside"), std::string::npos) << r.err;
}

TEST(ExidelConstrained, PlainRunsWritePolyWithTheHull) {
    const RunResult r =
        run("-f poly --input-format json", "[[0, 0], [2, 0], [2, 2], [0, 2], [1, 1]]");
    ASSERT_EQ(r.status, 0) << r.err;
    // Five vertices, the four hull edges as segments, no holes.
    EXPECT_NE(r.out.find("5 2 0 0\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n4 0\n0 "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.substr(r.out.size() - 2), "0\n") << r.out;
}

}  // namespace
