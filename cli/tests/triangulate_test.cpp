// End-to-end tests of `exidel triangulate`: every input format, output formats, error
// line numbers, no partial output, --stats, and the output certified in-process.
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
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
#include "exidel/io/triangulation_input.hpp"
#include "run_binary.hpp"

namespace {

using exidel::Point2;
namespace io = exidel::io;

using namespace exidel::cli_test;

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

// 100 points: random doubles, a cocircular lattice, and two exact duplicates. Includes
// the configurations where a wrong in-circle sign would show (cocircular 4-sets).
std::vector<Point2> hundred_points() {
    std::vector<Point2> p;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-10, 10);
    for (int i = 0; i < 86; ++i) p.push_back({u(rng), u(rng)});
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{{3, 4},
                                                               {-4, 3},
                                                               {-3, -4},
                                                               {4, -3},
                                                               {5, 0},
                                                               {0, -5},
                                                               {0, 5},
                                                               {-5, 0},
                                                               {4, 3},
                                                               {-3, 4},
                                                               {3, -4},
                                                               {-4, -3}}) {
        p.push_back({static_cast<double>(x), static_cast<double>(y)});
    }
    p.push_back(p[10]);
    p.push_back(p[90]);
    return p;
}

// A valid input file of three points.
std::string in_any() { return write_file("any.xy", "0 0\n1 0\n0 1\n"); }

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
    const std::string top =
        std::string("'") + EXIDEL_CLI_PATH + "' --help > " + work_path("top.out");
    ASSERT_EQ(std::system(top.c_str()), 0);
    EXPECT_NE(slurp(work_path("top.out")).find("triangulate"), std::string::npos);
}

TEST(ExidelTriangulate, BadOptionsExitTwoWithUsage) {
    for (const char* args : {"--kernel",
                             "--kernel fast",
                             "--kernel=mpfr:1",
                             "--incircle sine",
                             "--format png",
                             "--input-format csv",
                             "--frob",
                             "a b",
                             "-i a b",
                             "-o",
                             "-o a.json -o b.json",
                             "--order",
                             "--order spiral",
                             "--threads 0",
                             "--threads two",
                             "--threads=3x",
                             "--strip-points 0",
                             "--strip-points -5",
                             "--strip-tiles 0",
                             "--strip-tiles three"}) {
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
    for (io::PointFormat f : {io::PointFormat::xy, io::PointFormat::json, io::PointFormat::node,
                              io::PointFormat::f64}) {
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
            const RunResult r =
                run(std::string("-i ") + path + " --kernel " + kernel + " --incircle " + policy);
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
    EXPECT_EQ(slurp(work_path("fmt-out.off"))
                  .rfind("OFF\n100 " + std::to_string(tri.triangle_count()) + " 0\n", 0),
              0u);
    const std::string svg = slurp(work_path("fmt-out.svg"));
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_TRUE(svg.ends_with("</svg>\n"));
    std::size_t dots = 0;  // a dot per point: "M x y h0"
    for (std::size_t i = svg.find(" h0"); i != std::string::npos; i = svg.find(" h0", i + 1)) {
        ++dots;
    }
    EXPECT_EQ(dots, pts.size());
    // --format wins over the extension; no extension means json; an unknown extension
    // is a usage error (no JSON inside a .png), and nothing is written.
    EXPECT_EQ(run("-i " + in + " -o " + work_path("fmt2.svg") + " -f ele").status, 0);
    EXPECT_EQ(slurp(work_path("fmt2.svg")), ele);
    EXPECT_EQ(run("-i " + in + " -o " + work_path("fmt3")).status, 0);
    EXPECT_EQ(slurp(work_path("fmt3")), json);
    std::remove(work_path("fmt4.png").c_str());
    const RunResult png = run("-i " + in + " -o " + work_path("fmt4.png"));
    EXPECT_EQ(png.status, 2);
    EXPECT_NE(png.err.find("cannot tell the output format from"), std::string::npos) << png.err;
    EXPECT_FALSE(exists(work_path("fmt4.png")));
    EXPECT_EQ(run("-i " + in + " -o " + work_path("fmt4.png") + " -f json").status, 0);
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
    // A file that cannot be read says why, in the system's words.
    const RunResult missing = run("-i " + work_path("no-such-file.txt"));
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("no-such-file.txt': No such file or directory"), std::string::npos)
        << missing.err;
    const RunResult directory = run("-i " + work_path(""));
    EXPECT_EQ(directory.status, 1);
    EXPECT_NE(directory.err.find("Is a directory"), std::string::npos) << directory.err;
    const RunResult unwritable = run("-i " + in_any() + " -o /nonexistent-dir/out.json");
    EXPECT_EQ(unwritable.status, 1);
    EXPECT_NE(unwritable.err.find("No such file or directory"), std::string::npos)
        << unwritable.err;
}

TEST(ExidelTriangulate, EmptyInputIsZeroPoints) {
    const RunResult r = run("--stats", "# nothing here\n\n");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out,
              "{\"triangles\": [],\n \"halfedges\": [],\n \"hull\": [],\n \"duplicates\": []}\n");
    EXPECT_NE(r.err.find("\"points\": 0,"), std::string::npos);
}

// Kettner's configuration, p moved two ulps up: the double kernel contradicts itself
// (lib/delaunay fixture KettnerTwoUlpsAboveReportsNoVisibleEdge).
const std::string kettner = "0x1p-1 0x1.0000000000002p-1\n12 12\n24 24\n2 2\n6 6\n";

TEST(ExidelTriangulate, InexactKernelFailureExitsOneWithoutOutput) {
    const std::string in = write_file("kettner.txt", kettner);
    const std::string out = work_path("kettner.json");
    std::remove(out.c_str());
    // The paper's order: the last point sees no hull edge. The default (radial) order
    // meets the same wrong sign as a point that sees no edge of the hull at all.
    for (const auto& [order, kind] :
         {std::pair{"lexicographic", "no_visible_edge"}, std::pair{"auto", "point_inside_hull"}}) {
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
            } else if (s.compare(i, 4, "null") == 0) {
                values[key] = "null";
                i += 4;
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
    for (const char* key : {"points",
                            "vertices",
                            "duplicates",
                            "triangles",
                            "hull_size",
                            "collinear",
                            "kernel",
                            "incircle",
                            "instrumentation",
                            "counters.seed_orientations",
                            "counters.tangent_orientations",
                            "counters.incircle_tests",
                            "counters.eroded_edges",
                            "counters.triangles_created",
                            "counters.triangles_destroyed",
                            "counters.theorem1_checks",
                            "counters.theorem1_violations",
                            "counters.visible_search_orientations",
                            "counters.merge_orientations",
                            "counters.merge_incircle_tests",
                            "counters.merge_deleted_edges",
                            "counters.merge_cross_edges",
                            "counters.location_steps",
                            "counters.location_orientations",
                            "counters.cavity_orientations",
                            "counters.lawson_flips",
                            "counters.flips",
                            "algorithm",
                            "strategy",
                            "strips",
                            "cavity_pieces",
                            "threads",
                            "failure",
                            "read_ms",
                            "triangulate_ms",
                            "certify_ms",
                            "write_ms",
                            "total_ms"}) {
        EXPECT_TRUE(v.count(key)) << key << " missing in " << r.err;
    }
    EXPECT_EQ(v.size(), 38u) << r.err;
    EXPECT_EQ(v.at("failure"), "null");
    EXPECT_EQ(v.at("threads"), "1");  // radial runs on one thread whatever --threads says
    EXPECT_GE(std::stod(v.at("total_ms")), std::stod(v.at("triangulate_ms")));
    EXPECT_EQ(v.at("algorithm"), "external");  // the default
    EXPECT_EQ(v.at("strategy"), "radial");     // auto, below 32768 points
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
        for (const std::string& flag :
             {"--algorithm " + name, "--algorithm=" + name, "-a " + name}) {
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
    for (const char* args :
         {"--order lexicographic", "--order radial", "--order strips --strip-points 7 --threads 1",
          "--order strips --strip-points 7 --threads 2",
          "--order strips --strip-points 7 --strip-tiles 3 --threads 2", "--order auto"}) {
        const RunResult r = run("-i " + in + " --stats " + args);
        ASSERT_EQ(r.status, 0) << args << r.err;
        const FlatJson stats(r.err);
        const auto& v = stats.values;
        const std::string all = args;
        const std::size_t end = all.find(' ', 8);
        const std::string order =
            all.substr(8, end == std::string::npos ? std::string::npos : end - 8);
        EXPECT_EQ(v.at("strategy"), order == "auto" ? "radial" : order) << args;
        if (order == "strips") {
            EXPECT_GT(std::stoul(v.at("strips")), 1u) << args;
            EXPECT_EQ(v.at("threads"), all.ends_with("2") ? "2" : "1") << args;
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
            text += std::to_string(x[0]) + "," + std::to_string(x[1]) + "," + std::to_string(x[2]) +
                    ";";
        }
        if (reference.empty()) reference = text;
        EXPECT_EQ(text, reference) << args;
    }
}

// -o FILE.ele writes FILE.node beside it, numbered like the input .node (1-based here),
// unless FILE.node is the input itself; the pair reads back and certifies.
TEST(ExidelTriangulate, EleComesWithANodeFileOfTheSameBase) {
    const std::vector<Point2> pts = hundred_points();
    std::ostringstream node;
    io::write_points(node, pts, io::PointFormat::node, 1);
    const std::string in = write_file("based.node", node.str());
    const std::string ele = work_path("based-out.ele"), companion = work_path("based-out.node");
    std::remove(companion.c_str());
    ASSERT_EQ(run("-i " + in + " -o " + ele).status, 0);
    const std::string ele_text = slurp(ele);
    EXPECT_EQ(slurp(companion), node.str());  // the same numbering, the same doubles
    const auto read = io::parse_point_file(slurp(companion), io::PointFormat::node);
    EXPECT_EQ(read.index_base, 1u);
    auto tri = exidel::delaunay::normalize(
        read.points, io::read_produced(ele_text, io::ProducedFormat::ele, read.points));
    EXPECT_TRUE(exidel::delaunay::certify(read.points, tri).ok());
    EXPECT_EQ(ele_text.substr(ele_text.find('\n') + 1, 2), "1 ");  // triangles from 1 too
    // Reading based.node and writing based.ele leaves the input alone.
    const std::string beside = work_path("based.ele");
    ASSERT_EQ(run("-i " + in + " -o " + beside).status, 0);
    EXPECT_EQ(slurp(in), node.str());
    // From xy input: 0-based.
    const std::string xy = points_file("based.xy", pts, io::PointFormat::xy);
    ASSERT_EQ(run("-i " + xy + " -o " + work_path("based-xy.ele")).status, 0);
    EXPECT_EQ(
        io::parse_point_file(slurp(work_path("based-xy.node")), io::PointFormat::node).index_base,
        0u);
    // A device as the output: nothing beside it (there was a /dev/null.node).
    std::remove("/dev/null.node");
    ASSERT_EQ(run("-i " + xy + " -o /dev/null --format ele").status, 0);
    struct stat st {};
    EXPECT_NE(::stat("/dev/null.node", &st), 0);
}

TEST(ExidelTriangulate, ColumnsPickFieldsOfAWiderCsv) {
    const std::string csv =
        write_file("wide.csv",
                   "\xEF\xBB\xBF\"id\",\"city\",\"lon\",\"lat\"\n1,\"Paris, FR\",2.35,48.85\n"
                   "2,London,-0.12,51.5\n3,Berlin,13.4,52.52\n4,Rome,12.5,41.9\n");
    const RunResult by_name = run("-i " + csv + " --columns lon,lat --stats");
    ASSERT_EQ(by_name.status, 0) << by_name.err;
    EXPECT_NE(by_name.err.find("\"points\": 4,"), std::string::npos) << by_name.err;
    const RunResult by_number = run("-i " + csv + " --columns 3,4");
    EXPECT_EQ(by_number.out, by_name.out);
    const RunResult without = run("-i " + csv);
    EXPECT_EQ(without.status, 1);
    EXPECT_NE(without.err.find("line 1: "), std::string::npos) << without.err;
    EXPECT_EQ(run("-i " + csv + " --columns lon").status, 2);
    EXPECT_EQ(run("-i " + csv + " --columns 1,2 --input-format json").status, 2);
    const RunResult missing = run("-i " + csv + " --columns lon,height");
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("no column named 'height'"), std::string::npos) << missing.err;
}

TEST(ExidelTriangulate, StatsAndCompleteSentencesOnFailure) {
    const std::string in = write_file("kettner2.txt", kettner);
    const RunResult r = run("-i " + in + " --kernel double --order lexicographic --stats");
    EXPECT_EQ(r.status, 1);
    const std::string first = r.err.substr(0, r.err.find('\n'));
    EXPECT_NE(first.find("neither hull edge at the last point faces the new point"),
              std::string::npos)
        << first;
    EXPECT_NE(first.find("The double kernel is not exact"), std::string::npos) << first;
    EXPECT_TRUE(first.ends_with(".")) << first;
    const FlatJson stats(r.err.substr(r.err.find('\n') + 1));
    EXPECT_EQ(stats.values.at("failure.kind"), "no_visible_edge");
    EXPECT_EQ(stats.values.at("kernel"), "double");
}

TEST(ExidelTriangulate, NoteWhenThereAreNoTriangles) {
    const RunResult line = run("", "0 0\n1 1\n2 2\n1 1\n");
    EXPECT_EQ(line.status, 0);
    EXPECT_EQ(line.err,
              "exidel: note: no triangles: the distinct points are all on one line "
              "(3); the hull lists them in order\n");
    const RunResult two = run("", "0 0\n1 1\n");
    EXPECT_NE(two.err.find("fewer than three distinct points (2)"), std::string::npos) << two.err;
    EXPECT_TRUE(run("--quiet", "0 0\n1 1\n").err.empty());
    EXPECT_TRUE(run("", "0 0\n1 0\n0 1\n").err.empty());
}

TEST(ExidelTriangulate, CertifyOption) {
    const std::vector<Point2> pts = hundred_points();
    const std::string in = points_file("certify.xy", pts, io::PointFormat::xy);
    const RunResult ok = run("-i " + in + " --certify --stats");
    ASSERT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(ok.err.rfind("exidel: certified: ", 0), 0u) << ok.err;
    EXPECT_TRUE(certify_output(pts, ok.out).ok());
}

// SIGINT and SIGTERM while a run waits for its input: the temporary output file, created
// at the start, is removed and the process ends by the signal.
TEST(ExidelTriangulate, InterruptLeavesNoFile) {
    for (const int sig : {SIGTERM, SIGINT}) {
        const std::string dir = work_path("interrupt" + std::to_string(sig));
        ::mkdir(dir.c_str(), 0755);
        int feed[2];
        ASSERT_EQ(::pipe(feed), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            ::dup2(feed[0], 0);
            ::close(feed[1]);
            const std::string out = dir + "/out.json";
            ::execl(EXIDEL_CLI_PATH, "exidel", "triangulate", "-o", out.c_str(), "-q",
                    static_cast<char*>(nullptr));
            ::_exit(127);
        }
        ::close(feed[0]);
        // Wait (at most 20 s) for the temporary file, then interrupt.
        const auto listing = [&] {
            std::vector<std::string> names;
            if (DIR* d = ::opendir(dir.c_str())) {
                while (const dirent* e = ::readdir(d)) {
                    if (e->d_name[0] != '.') names.push_back(e->d_name);
                }
                ::closedir(d);
            }
            return names;
        };
        for (int i = 0; i < 2000 && listing().empty(); ++i) ::usleep(10000);
        ASSERT_EQ(listing().size(), 1u);
        EXPECT_EQ(listing()[0].rfind("out.json.tmp.", 0), 0u);
        ASSERT_EQ(::write(feed[1], "0 0\n1 0\n", 8), 8);  // partly read input, too
        ::usleep(20000);
        ::kill(child, sig);
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        ::close(feed[1]);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
        EXPECT_TRUE(listing().empty()) << listing().front();
    }
}

TEST(ExidelCertify, CertifiesJsonAndEleAndReportsFindings) {
    const std::vector<Point2> pts = hundred_points();
    const std::string in = points_file("cert.xy", pts, io::PointFormat::xy);
    ASSERT_EQ(run("-i " + in + " -o " + work_path("cert.json")).status, 0);
    ASSERT_EQ(run("-i " + in + " -o " + work_path("cert.ele")).status, 0);
    for (const char* file : {"cert.json", "cert.ele"}) {
        const RunResult r = run_exidel("cert", "certify " + in + " " + work_path(file), "");
        EXPECT_EQ(r.status, 0) << file << r.out << r.err;
        EXPECT_EQ(
            r.out.rfind("certified: the Delaunay triangulation of 100 points (98 distinct), ", 0),
            0u)
            << r.out;
    }
    // The kite's wrong diagonal: one typed finding, exit status 1.
    const std::string kite = write_file("kite.xy", "0 0\n1 0\n0.6 0.6\n0 1\n");
    const std::string wrong = write_file("kite.ele", "2 3 0\n0 0 1 3\n1 1 2 3\n");
    const RunResult bad = run_exidel("cert", "certify " + kite + " " + wrong, "");
    EXPECT_EQ(bad.status, 1);
    EXPECT_EQ(bad.out.rfind("not_delaunay: ", 0), 0u) << bad.out;
    EXPECT_NE(bad.out.find("\nnot certified: 1 findings\n"), std::string::npos) << bad.out;
    // Unreadable files and usage errors.
    const RunResult missing =
        run_exidel("cert", "certify " + kite + " " + work_path("none.json"), "");
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("No such file or directory"), std::string::npos) << missing.err;
    const RunResult malformed =
        run_exidel("cert", "certify " + kite + " " + write_file("bad.ele", "1 3 0\n0 0 1\n"), "");
    EXPECT_EQ(malformed.status, 1);
    EXPECT_NE(malformed.err.find("bad.ele: line 2: "), std::string::npos) << malformed.err;
    EXPECT_EQ(run_exidel("cert", "certify " + kite, "").status, 2);
    EXPECT_EQ(run_exidel("cert", "certify " + kite + " " + work_path("x.svg"), "").status, 2);
    EXPECT_EQ(run_exidel("cert", "certify --help", "").status, 0);
}

// A picture of 10^6 points opens in librsvg: XML parsers cap one attribute at 10 MB,
// which a single path of every triangle passed near 10^5 points, and librsvg refuses more
// than 10^6 elements, which a <circle> per point passed.
TEST(ExidelTriangulate, LargeSvgOpensInLibrsvg) {
#ifndef EXIDEL_RSVG_CONVERT
    GTEST_SKIP() << "rsvg-convert not found at configure time (Debian: librsvg2-bin)";
#else
    std::vector<Point2> pts;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 1000000; ++i) pts.push_back({u(rng), u(rng)});
    const std::string in = points_file("big.f64", pts, io::PointFormat::f64);
    const std::string svg = work_path("big.svg"), png = work_path("big.png");
    std::remove(png.c_str());
    ASSERT_EQ(run("-i " + in + " -o " + svg).status, 0);
    const std::string render = std::string("'") + EXIDEL_RSVG_CONVERT + "' -w 200 -o '" + png +
                               "' '" + svg + "' 2> '" + work_path("rsvg.err") + "'";
    EXPECT_EQ(std::system(render.c_str()), 0) << slurp(work_path("rsvg.err"));
    EXPECT_EQ(slurp(png).substr(1, 3), "PNG");
#endif
}

// A FIFO (like /dev/null or /dev/stdout, not a regular file) is written in place: the
// temporary-and-rename of regular files would replace it with a file.
TEST(ExidelTriangulate, DevicesAndPipesAreWrittenInPlace) {
    const std::string fifo = work_path("out-fifo"), captured = work_path("fifo.captured");
    std::remove(fifo.c_str());
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    const std::string in = in_any();
    // The reader gives up after 20 s, in case exidel never opens the pipe.
    const std::string command = "timeout 20 cat '" + fifo + "' > '" + captured + "' & '" +
                                EXIDEL_CLI_PATH + "' triangulate -i '" + in + "' -o '" + fifo +
                                "'; s=$?; wait; exit $s";
    EXPECT_EQ(std::system(command.c_str()), 0);
    struct stat st {};
    ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    EXPECT_EQ(slurp(captured), run("-i " + in).out);
    EXPECT_EQ(run("-i " + in + " -o " + work_path("")).status, 1);  // a directory: an error
}

// -o onto a symbolic link writes the file the link names and leaves the link a link (it
// used to be replaced by the output, found by issue 15's list of weak spots). Relative
// and absolute targets, a chain of two links, and a dangling link, which creates its
// target.
TEST(ExidelTriangulate, OutputIsWrittenThroughSymbolicLinks) {
    namespace fs = std::filesystem;
    const fs::path dir = work_path("links");
    fs::remove_all(dir);
    fs::create_directories(dir / "sub");
    const std::string in = in_any(), expected = run("-i " + in).out;
    write_file("links/sub/real.json", "old\n");
    fs::create_symlink("sub/real.json", dir / "relative.json");
    fs::create_symlink(dir / "relative.json", dir / "chain.json");
    fs::create_symlink("sub/new.json", dir / "dangling.json");
    for (const char* link : {"relative.json", "chain.json", "dangling.json"}) {
        const fs::path path = dir / link;
        ASSERT_EQ(run("-i " + in + " -o '" + path.string() + "'").status, 0) << link;
        EXPECT_TRUE(fs::is_symlink(path)) << link;
        EXPECT_EQ(slurp(path.string()), expected) << link;
    }
    EXPECT_EQ(slurp((dir / "sub/real.json").string()), expected);
    EXPECT_EQ(slurp((dir / "sub/new.json").string()), expected);
    // Nothing left over next to the links or their targets.
    for (const fs::path& d : {dir, dir / "sub"}) {
        for (const auto& e : fs::directory_iterator(d)) {
            EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
        }
    }
    // A loop of links is an error, not a hang.
    fs::create_symlink("loop-b.json", dir / "loop-a.json");
    fs::create_symlink("loop-a.json", dir / "loop-b.json");
    const auto looped = run("-i " + in + " -o '" + (dir / "loop-a.json").string() + "'");
    EXPECT_EQ(looped.status, 1);
    EXPECT_NE(looped.err.find("Too many levels of symbolic links"), std::string::npos)
        << looped.err;
}

}  // namespace
