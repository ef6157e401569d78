// End-to-end tests of `exidel triangulate`: every input format, output formats, error
// line numbers, no partial output, --stats, and the output certified in-process.
#include <dirent.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/predicates/registry.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"
#include "run_binary.hpp"

namespace {

using exidel::Point2;
namespace io = exidel::io;

using namespace exidel::cli_test;

bool exists(const std::string& path) { return std::ifstream(path).good(); }

std::string points_file(const std::string& name, const std::vector<Point2>& pts,
                        io::PointFormat f) {
    std::ostringstream s;
    io::write_points(s, pts, f);
    return write_file(name, s.str());
}

// Runs `exidel triangulate ARGS` with stdin from `input`.
RunResult run(const std::string& args, const std::string& input = "") {
    return run_exidel("tri", "triangulate " + args, input);
}

// Files in the work directory whose name contains `part` (leftover temporaries).
std::vector<std::string> files_containing(const std::string& part) {
    std::vector<std::string> found;
    DIR* d = opendir(EXIDEL_CLI_TEST_DIR);
    if (!d) return found;
    while (const dirent* e = readdir(d)) {
        const std::string name = e->d_name;
        if (name.find(part) != std::string::npos) found.push_back(name);
    }
    closedir(d);
    return found;
}

// 100 points: random doubles, a cocircular lattice, and two exact duplicates. Includes
// the configurations where a wrong in-circle sign would show (cocircular 4-sets).
std::vector<Point2> hundred_points() {
    std::vector<Point2> p;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-10, 10);
    for (int i = 0; i < 86; ++i) p.push_back({u(rng), u(rng)});
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{
             {3, 4}, {-4, 3}, {-3, -4}, {4, -3}, {5, 0}, {0, -5}, {0, 5}, {-5, 0}, {4, 3},
             {-3, 4}, {3, -4}, {-4, -3}}) {
        p.push_back({static_cast<double>(x), static_cast<double>(y)});
    }
    p.push_back(p[10]);
    p.push_back(p[90]);
    return p;
}

exidel::delaunay::Certificate certify_output(const std::vector<Point2>& pts,
                                             const std::string& json) {
    exidel::delaunay::Triangulation t = io::parse_triangulation_json(json);
    io::fill_vertex_of_input(pts, t);
    return exidel::delaunay::certify(pts, t);
}

TEST(ExidelTriangulate, HelpAndListing) {
    const RunResult help = run("--help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("usage: exidel triangulate"), std::string::npos);
    EXPECT_NE(help.out.find("--input-format"), std::string::npos);
    const std::string top = std::string("'") + EXIDEL_CLI_PATH + "' --help > " +
                            work_path("top.out");
    ASSERT_EQ(std::system(top.c_str()), 0);
    EXPECT_NE(slurp(work_path("top.out")).find("triangulate"), std::string::npos);
}

TEST(ExidelTriangulate, BadOptionsExitTwoWithUsage) {
    for (const char* args : {"--kernel", "--kernel fast", "--kernel=mpfr:1", "--incircle sine",
                             "--format png", "--input-format csv", "--frob", "a b", "-i a b",
                             "-o", "-o a.json -o b.json", "--order", "--order spiral",
                             "--threads 0", "--threads two", "--threads=3x", "--strip-points 0",
                             "--strip-points -5"}) {
        const RunResult r = run(args, "0 0\n1 0\n0 1\n");
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_NE(r.err.find("usage: exidel triangulate"), std::string::npos) << args;
        EXPECT_TRUE(r.out.empty()) << args;
    }
}

TEST(ExidelTriangulate, EveryInputFormatGivesTheSameTriangulation) {
    const std::vector<Point2> pts = hundred_points();
    const RunResult reference = run("", [&] {
        std::ostringstream s;
        io::write_points(s, pts, io::PointFormat::xy);
        return s.str();
    }());
    ASSERT_EQ(reference.status, 0) << reference.err;
    EXPECT_TRUE(certify_output(pts, reference.out).ok());
    for (io::PointFormat f :
         {io::PointFormat::xy, io::PointFormat::json, io::PointFormat::node, io::PointFormat::f64}) {
        const std::string name = std::string(io::to_string(f));
        const std::string ext = f == io::PointFormat::xy ? "txt" : name;
        const std::string path = points_file("pts." + ext, pts, f);
        // By extension, named explicitly, and from stdin with --input-format.
        EXPECT_EQ(run("-i " + path).out, reference.out) << name;
        EXPECT_EQ(run("--input " + path + " --input-format=" + name).out, reference.out) << name;
        EXPECT_EQ(run(path).out, reference.out) << name;
        EXPECT_EQ(run("--input-format " + name, slurp(path)).out, reference.out) << name;
    }
    // A CSV with a header, 1-based .node with attributes and markers.
    std::string csv = "x,y\n", node = std::to_string(pts.size()) + " 2 1 1\n";
    char buf[128];
    for (std::size_t i = 0; i < pts.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%a,%a\n", pts[i].x, pts[i].y);
        csv += buf;
        std::snprintf(buf, sizeof buf, "%zu %a %a 0.5 %d\n", i + 1, pts[i].x, pts[i].y,
                      static_cast<int>(i % 2));
        node += buf;
    }
    EXPECT_EQ(run("-i " + write_file("pts.csv", csv)).out, reference.out);
    EXPECT_EQ(run("-i " + write_file("pts1.node", node)).out, reference.out);
}

TEST(ExidelTriangulate, HundredPointsCertifyForEveryExactKernelAndPolicy) {
    const std::vector<Point2> pts = hundred_points();
    const std::string path = points_file("hundred.json", pts, io::PointFormat::json);
    for (const char* kernel : {"adaptive", "exact", "exact-cpp"}) {
        for (const char* policy : {"determinant", "cosine"}) {
            const RunResult r = run(std::string("-i ") + path + " --kernel " + kernel +
                                    " --incircle " + policy);
            ASSERT_EQ(r.status, 0) << kernel << " " << policy << ": " << r.err;
            const exidel::delaunay::Certificate c = certify_output(pts, r.out);
            EXPECT_TRUE(c.ok()) << kernel << " " << policy << "\n" << c.summary();
            EXPECT_EQ(io::parse_triangulation_json(r.out).duplicates,
                      (std::vector<std::uint32_t>{98, 99}));
        }
    }
    // The inexact kernels run too (this input is far from degenerate).
    for (const char* kernel : {"double", "long-double", "mpfr:200"}) {
        const RunResult r = run(std::string("-i ") + path + " -k " + kernel);
        ASSERT_EQ(r.status, 0) << kernel << ": " << r.err;
        EXPECT_TRUE(certify_output(pts, r.out).ok()) << kernel;
    }
}

TEST(ExidelTriangulate, OutputFormatFromExtensionAndOption) {
    const std::vector<Point2> pts = hundred_points();
    const std::string in = points_file("fmt.xy", pts, io::PointFormat::xy);
    for (const char* ext : {"json", "ele", "off", "svg"}) {
        const std::string out = work_path(std::string("fmt-out.") + ext);
        std::remove(out.c_str());
        const RunResult r = run("-i " + in + " -o " + out);
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_TRUE(r.out.empty());
        const RunResult same = run("-i " + in + " --format " + ext);
        EXPECT_EQ(slurp(out), same.out) << ext;
    }
    const std::string ele = slurp(work_path("fmt-out.ele"));
    const std::string json = slurp(work_path("fmt-out.json"));
    const auto tri = io::parse_triangulation_json(json);
    EXPECT_EQ(ele.substr(0, ele.find('\n')), std::to_string(tri.triangle_count()) + " 3 0");
    EXPECT_EQ(slurp(work_path("fmt-out.off")).rfind("OFF\n100 " +
                                                        std::to_string(tri.triangle_count()) +
                                                        " 0\n",
                                                    0),
              0u);
    const std::string svg = slurp(work_path("fmt-out.svg"));
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_TRUE(svg.ends_with("</svg>\n"));
    std::size_t circles = 0;
    for (std::size_t i = svg.find("<circle"); i != std::string::npos; i = svg.find("<circle", i + 1)) {
        ++circles;
    }
    EXPECT_EQ(circles, pts.size());
    // --format wins over the extension; an unknown extension means json.
    EXPECT_EQ(run("-i " + in + " -o " + work_path("fmt2.svg") + " -f ele").status, 0);
    EXPECT_EQ(slurp(work_path("fmt2.svg")), ele);
    EXPECT_EQ(run("-i " + in + " -o " + work_path("fmt3.result")).status, 0);
    EXPECT_EQ(slurp(work_path("fmt3.result")), json);
}

TEST(ExidelTriangulate, MalformedInputNamesTheLineAndWritesNothing) {
    struct Case {
        std::string file;
        std::string content;
        std::string position;  // "line N" or "byte offset N"
        std::string reason;
    };
    std::string f64(40, '\0');  // 2.5 points
    const std::vector<Case> cases = {
        {"bad1.txt", "0 0\n1 0\n# c\n\n0 1\n1 nan\n", "line 6", "not a finite number"},
        {"bad2.csv", "x,y\n0,0\n1,0,2\n", "line 3", "expected 2 coordinates"},
        {"bad3.json", "[[0, 0],\n [1, 0],\n [0, 1e999]]", "line 3", "outside the range"},
        {"bad4.node", "4 2 0 0\n0 0 0\n1 1 0\n2 0 1\n", "line 4", "truncated"},
        {"bad5.f64", f64, "byte offset 32", "not a multiple of 16"},
        {"bad6.xy", "0 0\n1 0\n0 1\n1 1\n0.5 0x1q\n", "line 5", "not a number"},
    };
    for (const Case& c : cases) {
        const std::string in = write_file(c.file, c.content);
        const std::string out = work_path(c.file + ".json");
        std::remove(out.c_str());
        const RunResult r = run("-i " + in + " -o " + out);
        EXPECT_EQ(r.status, 1) << c.file;
        EXPECT_EQ(r.err.rfind("exidel: " + c.position + ": ", 0), 0u) << c.file << ": " << r.err;
        EXPECT_NE(r.err.find(c.reason), std::string::npos) << r.err;
        EXPECT_FALSE(exists(out)) << c.file;
        // An existing output file is left as it was.
        write_file(c.file + ".json", "previous");
        EXPECT_EQ(run("-i " + in + " -o " + out).status, 1);
        EXPECT_EQ(slurp(out), "previous") << c.file;
        // Standard output gets nothing either.
        EXPECT_TRUE(run("-i " + in).out.empty()) << c.file;
    }
    EXPECT_TRUE(files_containing(".tmp.").empty());
    const RunResult missing = run("-i " + work_path("no-such-file.txt"));
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("cannot open"), std::string::npos);
}

TEST(ExidelTriangulate, EmptyInputIsZeroPoints) {
    const RunResult r = run("--stats", "# nothing here\n\n");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "{\"triangles\": [],\n \"halfedges\": [],\n \"hull\": [],\n \"duplicates\": []}\n");
    EXPECT_NE(r.err.find("\"points\": 0,"), std::string::npos);
}

// Kettner's configuration, p moved two ulps up: the double kernel contradicts itself
// (lib/delaunay fixture KettnerTwoUlpsAboveReportsNoVisibleEdge).
const std::string kettner =
    "0x1p-1 0x1.0000000000002p-1\n12 12\n24 24\n2 2\n6 6\n";

TEST(ExidelTriangulate, InexactKernelFailureExitsOneWithoutOutput) {
    const std::string in = write_file("kettner.txt", kettner);
    const std::string out = work_path("kettner.json");
    std::remove(out.c_str());
    // The paper's order: the last point sees no hull edge. The default (radial) order
    // meets the same wrong sign as a point that sees no edge of the hull at all.
    for (const auto& [order, kind] : {std::pair{"lexicographic", "no_visible_edge"},
                                      std::pair{"auto", "point_inside_hull"}}) {
        const RunResult r =
            run("-i " + in + " -o " + out + " --kernel double --order " + std::string(order));
        EXPECT_EQ(r.status, 1);
        EXPECT_EQ(r.err.rfind("exidel: triangulation failed: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(kind), std::string::npos) << r.err;
        EXPECT_FALSE(exists(out));
        EXPECT_TRUE(files_containing(".tmp.").empty());
    }
    // The exact kernel triangulates it.
    const RunResult exact = run("-i " + in + " -o " + out);
    EXPECT_EQ(exact.status, 0) << exact.err;
    const std::vector<Point2> pts = io::parse_points(kettner, io::PointFormat::xy);
    EXPECT_TRUE(certify_output(pts, slurp(out)).ok());
}

// A minimal JSON reader for the stats line: objects, strings without escapes, numbers,
// true/false. Flattens to "key" / "outer.inner" -> raw value text; throws on bad syntax.
struct FlatJson {
    std::map<std::string, std::string> values;
    std::string s;
    std::size_t i = 0;

    explicit FlatJson(std::string text) : s(std::move(text)) {
        object("");
        space();
        if (i != s.size()) throw std::runtime_error("trailing text");
    }
    void space() {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    }
    void expect(char c) {
        space();
        if (i >= s.size() || s[i] != c) throw std::runtime_error(std::string("expected ") + c);
        ++i;
    }
    std::string string() {
        expect('"');
        const std::size_t end = s.find('"', i);
        if (end == std::string::npos) throw std::runtime_error("unterminated string");
        std::string v = s.substr(i, end - i);
        i = end + 1;
        return v;
    }
    void object(const std::string& prefix) {
        expect('{');
        space();
        if (s[i] == '}') {
            ++i;
            return;
        }
        for (;;) {
            const std::string key = prefix + string();
            expect(':');
            space();
            if (s[i] == '{') {
                object(key + ".");
            } else if (s[i] == '"') {
                values[key] = string();
            } else {
                std::size_t end = i;
                while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) ||
                                          s[end] == '.' || s[end] == '-' || s[end] == '+')) {
                    ++end;
                }
                const std::string v = s.substr(i, end - i);
                if (v != "true" && v != "false") {
                    std::size_t used = 0;
                    std::stod(v, &used);
                    if (used != v.size()) throw std::runtime_error("bad number " + v);
                }
                values[key] = v;
                i = end;
            }
            space();
            if (s[i] == ',') {
                ++i;
                continue;
            }
            expect('}');
            return;
        }
    }
};

TEST(ExidelTriangulate, StatsIsOneJsonObjectWithEveryKey) {
    const std::vector<Point2> pts = hundred_points();
    const std::string in = points_file("stats.txt", pts, io::PointFormat::xy);
    const RunResult r = run("-i " + in + " --stats --kernel exact --incircle cosine");
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    const FlatJson stats(r.err);
    const auto& v = stats.values;
    for (const char* key :
         {"points", "vertices", "duplicates", "triangles", "hull_size", "collinear", "kernel",
          "incircle", "instrumentation", "counters.seed_orientations",
          "counters.tangent_orientations", "counters.incircle_tests", "counters.eroded_edges",
          "counters.triangles_created", "counters.triangles_destroyed",
          "counters.theorem1_checks", "counters.theorem1_violations",
          "counters.visible_search_orientations", "counters.merge_orientations",
          "counters.merge_incircle_tests", "counters.merge_deleted_edges",
          "counters.merge_cross_edges", "counters.flips", "algorithm", "strategy", "strips",
          "threads", "read_ms", "triangulate_ms", "write_ms"}) {
        EXPECT_TRUE(v.count(key)) << key << " missing in " << r.err;
    }
    EXPECT_EQ(v.size(), 30u) << r.err;
    EXPECT_EQ(v.at("algorithm"), "external");  // the default
    EXPECT_EQ(v.at("strategy"), "radial");  // auto, below 32768 points
    const auto tri = io::parse_triangulation_json(r.out);
    EXPECT_EQ(v.at("points"), "100");
    EXPECT_EQ(v.at("vertices"), "98");
    EXPECT_EQ(v.at("duplicates"), "2");
    EXPECT_EQ(v.at("triangles"), std::to_string(tri.triangle_count()));
    EXPECT_EQ(v.at("hull_size"), std::to_string(tri.hull.size()));
    EXPECT_EQ(v.at("collinear"), "false");
    EXPECT_EQ(v.at("kernel"), "exact");
    EXPECT_EQ(v.at("incircle"), "cosine");
    // Every triangle ever created is either in the result or was destroyed.
    EXPECT_EQ(std::stoull(v.at("counters.triangles_created")) -
                  std::stoull(v.at("counters.triangles_destroyed")),
              tri.triangle_count());
    EXPECT_GT(std::stoull(v.at("counters.incircle_tests")), 0u);
    EXPECT_GE(std::stod(v.at("triangulate_ms")), 0.0);
    // Without --stats nothing is printed on stderr.
    EXPECT_TRUE(run("-i " + in).err.empty());
}

// --algorithm takes every name of the registry, says in --stats which one ran, and
// rejects anything else as a usage error (exit 2) that lists the known names. --help
// lists the algorithms and the kernels from their registries.
TEST(ExidelTriangulate, AlgorithmOptionTakesTheRegistryNames) {
    const std::vector<Point2> pts = hundred_points();
    const std::string in = points_file("algorithms.txt", pts, io::PointFormat::xy);
    for (const exidel::delaunay::AlgorithmInfo& a : exidel::delaunay::algorithms()) {
        const std::string name(a.name);
        for (const std::string& flag : {"--algorithm " + name, "--algorithm=" + name, "-a " + name}) {
            const RunResult r = run("-i " + in + " --stats " + flag);
            ASSERT_EQ(r.status, 0) << flag << r.err;
            EXPECT_EQ(FlatJson(r.err).values.at("algorithm"), name) << flag;
            EXPECT_TRUE(certify_output(pts, r.out).ok()) << flag;
        }
    }
    const RunResult bad = run("-i " + in + " --algorithm sideways");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("unknown algorithm 'sideways'"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find(exidel::delaunay::algorithm_spellings()), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(run("-i " + in + " --algorithm").status, 2);
    const RunResult help = run("--help");
    EXPECT_NE(help.out.find(exidel::delaunay::algorithm_help()), std::string::npos);
    EXPECT_NE(help.out.find(exidel::kernel_help()), std::string::npos);
}

// Every order gives the same triangulation of points in general position, and says in
// --stats which one ran; the thread count never changes the output.
TEST(ExidelTriangulate, OrdersAndThreadsGiveTheSameTriangles) {
    const std::vector<Point2> pts = hundred_points();
    const std::string in = points_file("orders.txt", pts, io::PointFormat::xy);
    std::string reference;
    for (const char* args : {"--order lexicographic", "--order radial",
                             "--order strips --strip-points 7 --threads 1",
                             "--order strips --strip-points 7 --threads 2", "--order auto"}) {
        const RunResult r = run("-i " + in + " --stats " + args);
        ASSERT_EQ(r.status, 0) << args << r.err;
        const FlatJson stats(r.err);
        const auto& v = stats.values;
        const std::string all = args;
        const std::size_t end = all.find(' ', 8);
        const std::string order = all.substr(8, end == std::string::npos ? std::string::npos : end - 8);
        EXPECT_EQ(v.at("strategy"), order == "auto" ? "radial" : order) << args;
        if (order == "strips") {
            EXPECT_GT(std::stoul(v.at("strips")), 1u) << args;
        }
        EXPECT_TRUE(certify_output(pts, r.out).ok()) << args;
        const auto tri = io::parse_triangulation_json(r.out);
        // Compare triangle sets: the arrays are in each order's own sequence.
        std::vector<std::array<std::uint32_t, 3>> tris;
        for (std::size_t t = 0; t < tri.triangle_count(); ++t) {
            std::array<std::uint32_t, 3> x{tri.triangles[3 * t], tri.triangles[3 * t + 1],
                                           tri.triangles[3 * t + 2]};
            std::sort(x.begin(), x.end());
            tris.push_back(x);
        }
        std::sort(tris.begin(), tris.end());
        std::string text;
        for (const auto& x : tris) {
            text += std::to_string(x[0]) + "," + std::to_string(x[1]) + "," + std::to_string(x[2]) + ";";
        }
        if (reference.empty()) reference = text;
        EXPECT_EQ(text, reference) << args;
    }
}

}  // namespace
