// End-to-end tests of `exidel certify --constraints`: exidel's own constrained outputs
// (json, .ele + .node, OFF, --fill all) certify; tampered ones give the typed findings
// (a moved added point, a missing triangle, a flipped piece, a segment that is not an
// edge, the wrong fill rule); a Triangle-style .node/.ele of a square with a hole and two
// crossing segments certifies, and with its Steiner point off by an ulp is a finding (a
// note under --tolerate-crossings); malformed files are errors with their lines.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "run_binary.hpp"

namespace {

using namespace exidel::cli_test;
using nlohmann::json;

RunResult exidel(const std::string& args) { return run_exidel("ccert", args, ""); }

RunResult certify(const std::string& args) { return exidel("certify " + args); }

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A 4x4 square (1-4) with a square hole (5-8, seed (2, 2)), two segments crossing in the
// band below the hole (9-10 and 11-12) and a point outside the square (13): Triangle's -p
// keeps the square minus the hole (fill enclosed), -c (fill all) the hull minus the hole.
const std::string square_poly = R"(# square, hole, crossing segments, a point outside
13 2 0 0
1 0 0
2 4 0
3 4 4
4 0 4
5 1 1
6 3 1
7 3 3
8 1 3
9 0.1 0.2
10 3.9 0.7
11 0.3 0.8
12 3.7 0.1
13 6 2
10 0
1 1 2
2 2 3
3 3 4
4 4 1
5 5 6
6 6 7
7 7 8
8 8 5
9 9 10
10 11 12
1
1 2 2
)";

struct Outputs {
    std::string poly, json, ele, off, all;
};

// exidel's outputs of square_poly, made once.
const Outputs& outputs() {
    static const Outputs o = [] {
        Outputs r;
        r.poly = write_file("ccert_square.poly", square_poly);
        r.json = work_path("ccert_square.json");
        r.ele = work_path("ccert_square.ele");
        r.off = work_path("ccert_square.off");
        r.all = work_path("ccert_square_all.json");
        for (const std::string& out : {r.json, r.ele, r.off}) {
            EXPECT_EQ(exidel("triangulate '" + r.poly + "' -q -o '" + out + "'").status, 0);
        }
        EXPECT_EQ(exidel("triangulate '" + r.poly + "' -q --fill all -o '" + r.all + "'").status,
                  0);
        return r;
    }();
    return o;
}

json read_json(const std::string& path) { return json::parse(slurp(path)); }

std::string write_json(const std::string& name, const json& j) {
    return write_file(name, j.dump());
}

TEST(ExidelCertifyConstrained, ExidelsOwnOutputsCertify) {
    const Outputs& o = outputs();
    for (const std::string& file : {o.json, o.ele, o.off}) {
        const RunResult r = certify("--constraints '" + o.poly + "' '" + file + "'");
        EXPECT_EQ(r.status, 0) << file << "\n" << r.out << r.err;
        EXPECT_TRUE(has(r.out,
                        "certified: the constrained Delaunay triangulation of 13 points "
                        "and 10 segments (1 added points), 18 triangles of the domain "
                        "(the hull completed with 3 triangles), fill enclosed"))
            << r.out;
    }
    const RunResult all = certify("--constraints '" + o.poly + "' '" + o.all + "' --fill all");
    EXPECT_EQ(all.status, 0) << all.out << all.err;
    EXPECT_TRUE(has(all.out, "19 triangles of the domain (the hull completed with 2 triangles)"))
        << all.out;
    // --json: the verdict as an object.
    const RunResult j = certify("--constraints '" + o.poly + "' '" + o.json + "' --json");
    ASSERT_EQ(j.status, 0) << j.out << j.err;
    const json v = json::parse(j.out);
    EXPECT_EQ(v["certified"], true);
    EXPECT_EQ(v["added_points"], 1);
    EXPECT_EQ(v["triangles"], 18);
    EXPECT_EQ(v["completion_triangles"], 3);
    EXPECT_EQ(v["fill"], "enclosed");
    EXPECT_EQ(v["findings"].size(), 0u);
}

TEST(ExidelCertifyConstrained, WholeHullWithoutHoles) {
    // json input without holes, --fill all: the file is the whole hull, nothing completed.
    const std::string in = write_file(
        "ccert_hull.json",
        R"({"points": [[0,0],[4,0],[4,4],[0,4],[0.1,0.6],[3.9,0.2],[0.3,0.1],[3.7,0.8],[6,2]],
            "segments": [[0,1],[1,2],[2,3],[3,0],[4,5],[6,7]]})");
    const std::string out = work_path("ccert_hull_out.json");
    ASSERT_EQ(
        exidel("triangulate --constraints '" + in + "' --fill all -q -o '" + out + "'").status, 0);
    const RunResult r = certify("--constraints '" + in + "' '" + out + "' --fill all");
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "(1 added points)")) << r.out;
    EXPECT_TRUE(has(r.out, "the whole convex hull, fill all")) << r.out;
    // The same file is not the even-odd domain (json's default): the outside triangles.
    const RunResult wrong = certify("--constraints '" + in + "' '" + out + "'");
    EXPECT_EQ(wrong.status, 1);
    EXPECT_TRUE(has(wrong.out, "domain_mismatch: triangle ")) << wrong.out;
    EXPECT_TRUE(has(wrong.out, "outside the domain under fill rule even-odd")) << wrong.out;
    // --fill any accepts any union of regions.
    EXPECT_EQ(certify("--constraints '" + in + "' '" + out + "' --fill any").status, 0);
}

// A peer's chains are derived from the geometry (a grid of the vertices walked along each
// segment): every lattice point exactly on a long row, column or diagonal, and every
// crossing of the slanted segments with them, must be found, or the OFF (which has no
// chains) would not certify. Also lattices one cell wide, where the grid has one column
// or one row.
TEST(ExidelCertifyConstrained, ChainsThroughManyVerticesAreDerivedForAPeersOff) {
    const auto lattice = [](int nx, int ny) {
        json in;
        in["points"] = json::array();
        for (int y = 0; y <= ny; ++y) {
            for (int x = 0; x <= nx; ++x) in["points"].push_back({x, y});
        }
        const auto id = [&](int x, int y) { return y * (nx + 1) + x; };
        in["segments"] = json::array();
        for (int y = 0; y <= ny; y += 3) in["segments"].push_back({id(0, y), id(nx, y)});
        for (int x = 0; x <= nx; x += 4) in["segments"].push_back({id(x, 0), id(x, ny)});
        in["segments"].push_back({id(0, 0), id(nx, ny)});
        if (nx > 1 && ny > 1) {
            // Slanted ends off the lattice: they cross rows, columns and the diagonal.
            const std::size_t k = in["points"].size();
            in["points"].push_back({0.5, 0.25});
            in["points"].push_back({nx - 0.5, ny - 1.25});
            in["points"].push_back({0.25, ny - 0.5});
            in["points"].push_back({nx - 0.75, 0.5});
            in["segments"].push_back({k, k + 1});
            in["segments"].push_back({k + 2, k + 3});
        }
        return in;
    };
    for (const auto& [nx, ny] : {std::pair{30, 24}, std::pair{1, 40}, std::pair{40, 1}}) {
        const std::string name = "ccert_lattice_" + std::to_string(nx) + "x" + std::to_string(ny);
        const std::string in = write_json(name + ".json", lattice(nx, ny));
        const std::string off = work_path(name + ".off");
        ASSERT_EQ(
            exidel("triangulate --constraints '" + in + "' --fill all -q -o '" + off + "'").status,
            0);
        const RunResult r = certify("--constraints '" + in + "' '" + off + "' --fill all");
        EXPECT_EQ(r.status, 0) << name << "\n" << r.out << r.err;
        EXPECT_TRUE(has(r.out, "certified: the constrained Delaunay triangulation of")) << r.out;
        if (nx > 1 && ny > 1) {
            EXPECT_FALSE(has(r.out, "(0 added points)")) << r.out;
        }
    }
}

// A segment only a subnormal wide and 20 high: its slope is no double. Its crossing with
// a horizontal segment at y = 15 is an added point its chain must hold; the far points
// make the grid several rows high, so a walk that lost the steep segment's rows would
// miss it.
TEST(ExidelCertifyConstrained, ChainOfASegmentTooSteepForItsSlopeIsDerived) {
    json in;
    in["points"] = json::array({{0.0, 0.0}, {5e-324, 20.0}, {-1.0, 15.0}, {1.0, 15.0}});
    for (int k = 0; k <= 20; ++k) in["points"].push_back({10.0, static_cast<double>(k)});
    in["segments"] = json::array({{0, 1}, {2, 3}});
    const std::string file = write_json("ccert_steep.json", in);
    const std::string off = work_path("ccert_steep.off");
    ASSERT_EQ(
        exidel("triangulate --constraints '" + file + "' --fill all -q -o '" + off + "'").status,
        0);
    const RunResult r = certify("--constraints '" + file + "' '" + off + "' --fill all");
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "(1 added points)")) << r.out;
}

TEST(ExidelCertifyConstrained, WrongFillRuleIsADomainMismatch) {
    const Outputs& o = outputs();
    // The enclosed output lacks the triangle between the square and the outside point.
    const RunResult fewer = certify("--constraints '" + o.poly + "' '" + o.json + "' --fill all");
    EXPECT_EQ(fewer.status, 1);
    // The triangle (1, 12, 2), whichever vertex the finding names first.
    const std::string missing =
        "domain_mismatch: 1 triangle of the domain under fill rule all is not in the file, "
        "such as ";
    EXPECT_TRUE(has(fewer.out, missing + "(1, 12, 2)") || has(fewer.out, missing + "(12, 2, 1)") ||
                has(fewer.out, missing + "(2, 1, 12)"))
        << fewer.out;
    // The --fill all output has it, outside the enclosed domain.
    const RunResult more = certify("--constraints '" + o.poly + "' '" + o.all + "'");
    EXPECT_EQ(more.status, 1);
    EXPECT_TRUE(has(more.out, "lies outside the domain under fill rule enclosed (region "))
        << more.out;
    EXPECT_TRUE(has(more.out, "not certified: 1 findings")) << more.out;
}

TEST(ExidelCertifyConstrained, AddedPointMovedByAnUlp) {
    const Outputs& o = outputs();
    json j = read_json(o.json);
    const double x = j["added_points"][0][0];
    j["added_points"][0][0] = std::nextafter(x, std::numeric_limits<double>::infinity());
    const std::string moved = write_json("ccert_moved.json", j);
    const RunResult r = certify("--constraints '" + o.poly + "' '" + moved + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(has(r.out,
                    "added_point_wrong: added point 0 (point 13) is (2.0000000000000004, "
                    "0.45), not (2, 0.45), the rounded crossing"))
        << r.out;
    EXPECT_TRUE(has(r.out, "not certified: 1 findings")) << r.out;
    // Within chain_tolerance of both segments: a note under --tolerate-crossings.
    const RunResult t =
        certify("--constraints '" + o.poly + "' '" + moved + "' --tolerate-crossings");
    EXPECT_EQ(t.status, 0) << t.out << t.err;
    EXPECT_TRUE(has(t.err, "note: tolerated (within chain_tolerance of both segments)")) << t.err;
    // Moved far (0.01): not tolerated, and no longer on its segments' chains' geometry.
    j["added_points"][0][1] = 0.46;
    const std::string far = write_json("ccert_far.json", j);
    const RunResult f =
        certify("--constraints '" + o.poly + "' '" + far + "' --tolerate-crossings");
    EXPECT_EQ(f.status, 1);
    EXPECT_TRUE(has(f.out, "added_point_wrong: added point 0 (point 13)")) << f.out;
}

TEST(ExidelCertifyConstrained, MissingTriangle) {
    const Outputs& o = outputs();
    json j = read_json(o.json);
    std::vector<std::uint32_t> t = j["triangles"];
    t.erase(t.begin(), t.begin() + 3);
    j["triangles"] = t;
    j.erase("halfedges");
    const RunResult r =
        certify("--constraints '" + o.poly + "' '" + write_json("ccert_missing.json", j) + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(has(r.out,
                    "domain_mismatch: 1 triangle of the domain under fill rule enclosed is "
                    "not in the file, such as "))
        << r.out;
    EXPECT_TRUE(has(r.out, "not certified: 1 findings")) << r.out;
}

TEST(ExidelCertifyConstrained, FlippedPieceAndGivenTwins) {
    const Outputs& o = outputs();
    json j = read_json(o.json);
    std::vector<std::uint32_t> t = j["triangles"];
    const std::vector<std::int32_t> h = j["halfedges"];
    const std::vector<std::uint32_t> c = j["constraints"];
    const auto next = [](std::size_t e) { return e % 3 == 2 ? e - 2 : e + 1; };
    bool flipped = false;
    std::uint32_t piece_a = 0, piece_b = 0;  // the piece flipped away
    for (std::size_t e = 0; e < t.size() && !flipped; ++e) {
        const std::uint32_t a = t[e], b = t[next(e)];
        bool piece = false;
        for (std::size_t k = 0; k < c.size(); k += 2) {
            piece |= c[k] == std::min(a, b) && c[k + 1] == std::max(a, b);
        }
        if (h[e] < 0 || !piece) continue;
        const std::size_t f = static_cast<std::size_t>(h[e]);
        const std::uint32_t x = t[next(next(e))], y = t[next(next(f))];
        const std::size_t t1 = e / 3, t2 = f / 3;
        t[3 * t1] = a, t[3 * t1 + 1] = y, t[3 * t1 + 2] = x;
        t[3 * t2] = y, t[3 * t2 + 1] = b, t[3 * t2 + 2] = x;
        piece_a = a, piece_b = b;
        flipped = true;
    }
    ASSERT_TRUE(flipped);
    j["triangles"] = t;
    // With the file's halfedges kept, they no longer match the triangles.
    const RunResult twins =
        certify("--constraints '" + o.poly + "' '" + write_json("ccert_twins.json", j) + "'");
    EXPECT_EQ(twins.status, 1);
    EXPECT_TRUE(has(twins.out, "twin_mismatch: halfedges[")) << twins.out;
    j.erase("halfedges");
    const RunResult r =
        certify("--constraints '" + o.poly + "' '" + write_json("ccert_flipped.json", j) + "'");
    EXPECT_EQ(r.status, 1);
    // Which segment's chain breaks depends on which piece came first in the file.
    const std::string ab = std::to_string(piece_a) + ", " + std::to_string(piece_b);
    const std::string ba = std::to_string(piece_b) + ", " + std::to_string(piece_a);
    EXPECT_TRUE(has(r.out, "chain_broken: segment ")) << r.out;
    EXPECT_TRUE(has(r.out, ": the piece (" + ab + ")") || has(r.out, ": the piece (" + ba + ")"))
        << r.out;
    EXPECT_TRUE(has(r.out, "is not an edge of the triangulation")) << r.out;
}

TEST(ExidelCertifyConstrained, SegmentThatIsNotAnEdge) {
    // The .ele of square_poly against the same input with one more segment, (4, 0)-(0, 3):
    // its chain is derived from the geometry, and its piece is no edge.
    const Outputs& o = outputs();
    std::string extra = square_poly;
    extra.replace(extra.find("10 0\n"), 5, "11 0\n");
    extra.replace(extra.find("10 11 12\n"), 9, "10 11 12\n11 5 4\n");
    const std::string poly = write_file("ccert_extra.poly", extra);
    const RunResult r = certify("--constraints '" + poly + "' '" + o.ele + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(has(r.out,
                    "chain_broken: segment 10 (4, 3): the piece (4, 3) from chain vertex 0 "
                    "to 1 is not an edge of the triangulation"))
        << r.out;
}

// Triangle's output of `triangle -p` for this input, as Triangle writes it (1-based, vertex
// markers, its own order of triangles and of their vertices): the Steiner point 13 is the
// crossing of segments 9 and 10, here correctly rounded.
const std::string peer_poly = R"(# a square with a square hole and two crossing segments
12 2 0 1
1 0 0 1
2 4 0 1
3 4 4 1
4 0 4 1
5 1 1 2
6 3 1 2
7 3 3 2
8 1 3 2
9 0.1 0.6 0
10 3.9 0.2 0
11 0.3 0.1 0
12 3.7 0.8 0
10 1
1 1 2 1
2 2 3 1
3 3 4 1
4 4 1 1
5 5 6 2
6 6 7 2
7 7 8 2
8 8 5 2
9 9 10 0
10 11 12 0
1
1 2 2
)";

std::string peer_node(const std::string& steiner_x) {
    return "13 2 0 1\n"
           "   1    0  0    1\n   2    4  0    1\n   3    4  4    1\n   4    0  4    1\n"
           "   5    1  1    2\n   6    3  1    2\n   7    3  3    2\n   8    1  3    2\n"
           "   9    0.10000000000000001  0.59999999999999998    0\n"
           "  10    3.8999999999999999  0.20000000000000001    0\n"
           "  11    0.29999999999999999  0.10000000000000001    0\n"
           "  12    3.7000000000000002  0.80000000000000004    0\n"
           "  13    " +
           steiner_x + "  0.41691542288557215    0\n# Generated by triangle -p\n";
}

const std::string peer_ele = R"(18  3  0
   1      10     12     13
   2       9     11     13
   3       7      3      4
   4      12      3      7
   5       9      4      1
   6       8      4      9
   7       7      4      8
   8      12      7      6
   9      10      2     12
  10       5     13      6
  11       6     13     12
  12       2      3     12
  13      11      2     13
  14       5      8      9
  15       9     13      5
  16       1      2     11
  17       9      1     11
  18      10     13      2
# Generated by triangle -p
)";

TEST(ExidelCertifyConstrained, TriangleStyleOutput) {
    const std::string poly = write_file("ccert_peer.poly", peer_poly);
    write_file("ccert_peer.node", peer_node("1.8393034825870647"));
    const std::string ele = write_file("ccert_peer.ele", peer_ele);
    const RunResult r = certify("--constraints '" + poly + "' '" + ele + "'");
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_TRUE(has(r.out,
                    "of 12 points and 10 segments (1 added points), 18 triangles of the "
                    "domain (the hull completed with 2 triangles), fill enclosed"))
        << r.out;

    // The crossing as a + t (b - a) in doubles: one ulp off in x.
    write_file("ccert_peer_ulp.node", peer_node("1.8393034825870649"));
    const std::string ulp = write_file("ccert_peer_ulp.ele", peer_ele);
    const RunResult off = certify("--constraints '" + poly + "' '" + ulp + "'");
    EXPECT_EQ(off.status, 1);
    EXPECT_TRUE(has(off.out,
                    "added_point_wrong: added point 0 (point 12) is (1.8393034825870649, "
                    "0.41691542288557215), not (1.8393034825870647, 0.41691542288557215)"))
        << off.out;
    EXPECT_TRUE(has(off.out, "not certified: 1 findings")) << off.out;
    const RunResult tolerated =
        certify("--constraints '" + poly + "' '" + ulp + "' --tolerate-crossings --json");
    EXPECT_EQ(tolerated.status, 0) << tolerated.out << tolerated.err;
    const json v = json::parse(tolerated.out);
    EXPECT_EQ(v["certified"], true);
    ASSERT_EQ(v["notes"].size(), 1u) << tolerated.out;
    EXPECT_TRUE(has(v["notes"][0], "tolerated")) << tolerated.out;

    // A Steiner point off the segments (a quality point, Triangle's -q): on no chain.
    std::string node = peer_node("1.8393034825870647");
    node.replace(0, 2, "14");
    node.replace(node.find("# Generated"), 0, "  14    2  3.5    0\n");
    write_file("ccert_peer_q.node", node);
    const RunResult q = certify("--constraints '" + poly + "' '" +
                                write_file("ccert_peer_q.ele", peer_ele) + "' --fill any");
    EXPECT_EQ(q.status, 1);
    EXPECT_TRUE(has(q.out,
                    "added_point_wrong: added point 1 (point 13) (2, 3.5) is on the chains "
                    "of 0 segments"))
        << q.out;
}

TEST(ExidelCertifyConstrained, MalformedFilesAndUsage) {
    const Outputs& o = outputs();
    write_file("ccert_bad.node", peer_node("1.8393034825870647"));
    const std::string bad_ele = write_file("ccert_bad.ele", "2 3 0\n1 1 2 3\n2 1 2\n");
    const RunResult ele = certify("--constraints '" + o.poly + "' '" + bad_ele + "'");
    EXPECT_EQ(ele.status, 1);
    EXPECT_TRUE(has(ele.err, "ccert_bad.ele: line 3: expected 4 fields")) << ele.err;

    write_file("ccert_badnode.node", "3 2 0 0\n1 0 0\n2 1 x\n3 0 1\n");
    const std::string ele2 = write_file("ccert_badnode.ele", "1 3 0\n1 1 2 3\n");
    const RunResult node = certify("--constraints '" + o.poly + "' '" + ele2 + "'");
    EXPECT_EQ(node.status, 1);
    EXPECT_TRUE(has(node.err, "ccert_badnode.node: line 3")) << node.err;

    const std::string lonely = write_file("ccert_lonely.ele", "1 3 0\n1 1 2 3\n");
    const RunResult missing = certify("--constraints '" + o.poly + "' '" + lonely + "'");
    EXPECT_EQ(missing.status, 1);
    EXPECT_TRUE(has(missing.err, "ccert_lonely.node")) << missing.err;

    const std::string bad_json = write_file(
        "ccert_bad.json", "{\"triangles\": [],\n \"added_points\": [[1, 2]],\n \"chains\": []}");
    const RunResult j = certify("--constraints '" + o.poly + "' '" + bad_json + "'");
    EXPECT_EQ(j.status, 1);
    EXPECT_TRUE(has(j.err, "ccert_bad.json: line 3: unknown key \"chains\"")) << j.err;

    const std::string plain = write_file("ccert_plain.json", "{\"triangles\": [0, 1, 2]}");
    const RunResult p = certify("--constraints '" + o.poly + "' '" + plain + "'");
    EXPECT_EQ(p.status, 1);
    EXPECT_TRUE(has(p.err, "not exidel's constrained json")) << p.err;

    // Chains that do not divide the vertices: a finding, not a crash.
    json c = read_json(o.json);
    c["chain_offsets"] = json::array({0, 1});
    const RunResult chains =
        certify("--constraints '" + o.poly + "' '" + write_json("ccert_chains.json", c) + "'");
    EXPECT_EQ(chains.status, 1);
    EXPECT_TRUE(has(chains.out, "input_mismatch: chain_offsets")) << chains.out;

    EXPECT_EQ(certify("--constraints '" + o.poly + "' a.json b.json").status, 2);
    EXPECT_EQ(certify("--tolerate-crossings a.xy b.json").status, 2);
    EXPECT_EQ(certify("--constraints '" + o.poly + "' '" + o.json + "' --fill most").status, 2);
    EXPECT_EQ(certify("--constraints '" + o.poly + "' x.txt --format simplices").status, 2);
}

}  // namespace
