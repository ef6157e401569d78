// End-to-end tests of `exidel voronoi`: the json read back with nlohmann-json and compared
// bit for bit with the library's diagram (merged cocircular vertices, negative zero,
// subnormal and huge coordinates, --clip), usage errors, malformed input and a centre
// beyond the largest double (no output written), SVG pictures, tiny and collinear input,
// --stats.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "exidel/delaunay/triangulate.hpp"
#include "exidel/delaunay/furthest.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/voronoi.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "run_binary.hpp"
#include "voronoi_json.hpp"

namespace {

using exidel::AdaptiveKernel;
using exidel::Point2;
namespace delaunay = exidel::delaunay;
namespace io = exidel::io;

using namespace exidel::cli_test;
using exidel::io_test::expect_voronoi_json;
using exidel::io_test::expect_whole_svg;

// Runs `exidel voronoi ARGS` with stdin from `input`.
RunResult run(const std::string& args, const std::string& input = "") {
    return run_exidel("vor", "voronoi " + args, input);
}

// The points as an xy file (hex floats: exactly these doubles).
std::string xy_text(const std::vector<Point2>& points) {
    std::ostringstream s;
    for (const Point2& p : points) s << std::hexfloat << p.x << ' ' << p.y << '\n';
    return s.str();
}

// The 12 lattice points of x^2 + y^2 = 25, and a duplicate of (5, 0) as index 12.
std::vector<Point2> lattice_circle() {
    std::vector<Point2> points = exidel::io_test::lattice_circle();
    points.push_back(points[4]);
    return points;
}

struct Library {
    delaunay::Result triangulation;
    delaunay::VoronoiDiagram diagram;
};

// What the library computes for `points` with the default kernel.
Library library(const std::vector<Point2>& points) {
    Library l;
    l.triangulation = delaunay::triangulate(points, AdaptiveKernel{});
    EXPECT_TRUE(l.triangulation.ok());
    l.diagram = delaunay::voronoi(points, l.triangulation.triangulation, AdaptiveKernel{});
    return l;
}

TEST(ExidelVoronoi, HelpAndListing) {
    const RunResult help = run("--help");
    EXPECT_EQ(help.status, 0);
    EXPECT_EQ(help.out.rfind("usage: exidel voronoi", 0), 0u) << help.out;
    for (const char* text : {"--clip XMIN YMIN XMAX YMAX", "--input-format", "--columns",
                             "\"vertex_sites\"", "Kernels:", "Algorithms:", "adaptive"}) {
        EXPECT_NE(help.out.find(text), std::string::npos) << text;
    }
    const std::string top =
        std::string("'") + EXIDEL_CLI_PATH + "' --help > " + work_path("vtop.out");
    ASSERT_EQ(std::system(top.c_str()), 0);
    EXPECT_NE(slurp(work_path("vtop.out")).find("  voronoi "), std::string::npos);
}

// The lattice circle: one vertex with all thirteen sites (the duplicate beside its twin),
// every cell that one vertex, the duplicate's cell its twin's.
TEST(ExidelVoronoi, CocircularLatticeIsOneVertexWithEverySite) {
    const std::vector<Point2> points = lattice_circle();
    const RunResult r = run("--unclipped", xy_text(points));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    const Library l = library(points);
    expect_voronoi_json(r.out, l.diagram);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["vertices"].size(), 1u);
    EXPECT_EQ(j["vertices"][0], nlohmann::json::parse("[0, 0]"));
    std::vector<std::uint32_t> sites = j["vertex_sites"][0].get<std::vector<std::uint32_t>>();
    ASSERT_EQ(sites.size(), 13u);
    EXPECT_EQ(sites.front(), 0u);
    const auto twin = std::find(sites.begin(), sites.end(), 4u);
    ASSERT_NE(twin, sites.end());
    ASSERT_NE(twin + 1, sites.end());
    EXPECT_EQ(*(twin + 1), 12u);  // the duplicate follows its twin
    std::sort(sites.begin(), sites.end());
    for (std::uint32_t i = 0; i < 13; ++i) EXPECT_EQ(sites[i], i);
    for (std::uint32_t i = 0; i < 13; ++i) {
        EXPECT_EQ(j["cells"][i], nlohmann::json::parse("[0]")) << i;
        EXPECT_TRUE(j["unbounded"][i].get<bool>()) << i;
    }
    // The square's corners and centre: four vertices, the centre's cell bounded.
    const std::vector<Point2> square = {{0, 0}, {4, 0}, {0, 4}, {4, 4}, {2, 2}};
    const RunResult s = run("-q --unclipped", xy_text(square));
    ASSERT_EQ(s.status, 0) << s.err;
    expect_voronoi_json(s.out, library(square).diagram);
    EXPECT_FALSE(nlohmann::json::parse(s.out)["unbounded"][4].get<bool>());
}

// --furthest-site: the library's furthest-site diagram, written unclipped; clipping is an
// error.
TEST(ExidelVoronoi, FurthestSiteIsTheLibrarysDiagram) {
    std::vector<Point2> points;
    for (int i = 0; i < 40; ++i)
        points.push_back(
            {std::ldexp(double((i * 37) % 41), -3), std::ldexp(double((i * 11) % 29), -2)});
    points.push_back(points[3]);  // a duplicate of a point
    const auto t = delaunay::furthest_site_triangulation(points, AdaptiveKernel{});
    ASSERT_TRUE(t.ok());
    const auto d = delaunay::furthest_site_voronoi(points, t.triangulation, AdaptiveKernel{});
    const RunResult r = run("-q --unclipped --furthest-site", xy_text(points));
    ASSERT_EQ(r.status, 0) << r.err;
    expect_voronoi_json(r.out, d);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    std::size_t regions = 0;
    for (std::size_t i = 0; i < points.size(); ++i) regions += !j["cells"][i].empty();
    EXPECT_EQ(regions, t.triangulation.hull.size() + (j["cells"][3].empty() ? 0 : 1));
    const nlohmann::json stats =
        nlohmann::json::parse(run("--stats --unclipped --furthest-site", xy_text(points)).err);
    EXPECT_EQ(stats["algorithm"], "furthest-site");
    EXPECT_EQ(stats["triangles"], t.triangulation.triangle_count());
    const RunResult clipped = run("-q --furthest-site", xy_text(points));
    EXPECT_EQ(clipped.status, 2);
    EXPECT_NE(clipped.err.find("--unclipped"), std::string::npos) << clipped.err;
}

// Negative zero (the centre of (-3, 0), (2, 0) in units of the smallest subnormal and
// (0, 1) has x = -2^-1075, a tie that rounds to -0), subnormal and huge vertices: every
// coordinate reads back as the same double, unclipped and clipped.
TEST(ExidelVoronoi, CoordinatesReadBackBitForBit) {
    const double tiny = std::numeric_limits<double>::denorm_min();
    const std::vector<std::vector<Point2>> inputs = {
        {{-3 * tiny, 0}, {2 * tiny, 0}, {0, 1}},
        {{0, 0}, {4e-310, 0}, {0, 4e-310}, {1e300, 1e300}},
        {{0, 0}, {1e-310, 3e-310}, {-2e-310, 1e-310}, {4e-310, -1e-310}, {tiny, 0}, {0, -6 * tiny}},
        {{0, 0},
         {3e307, 1e307},
         {1e307, 4e307},
         {-2e307, 2e307},
         {-1e307, -3e307},
         {2e307, -2e307},
         {0.5e307, 0.7e307},
         {8e307, 1e306}},
    };
    for (const std::vector<Point2>& points : inputs) {
        const std::string in = write_file("bits.xy", xy_text(points));
        const RunResult r = run("-i " + in + " -q --unclipped");
        ASSERT_EQ(r.status, 0) << r.err;
        const Library l = library(points);
        expect_voronoi_json(r.out, l.diagram);
        const delaunay::Box box{-1e308, -1e308, 1e308, 1.7976931348623157e308};
        const RunResult c =
            run("-i " + in + " -q --clip -1e308 -1e308 1e308 1.7976931348623157e308");
        ASSERT_EQ(c.status, 0) << c.err;
        expect_voronoi_json(c.out,
                            delaunay::clip(l.diagram, points, l.triangulation.triangulation, box));
    }
    const RunResult zero = run("-q --unclipped", xy_text(inputs[0]));
    EXPECT_EQ(zero.out.rfind("{\"vertices\": [[-0.0, 0.5]],", 0), 0u) << zero.out;
    EXPECT_TRUE(std::signbit(nlohmann::json::parse(zero.out)["vertices"][0][0].get<double>()));
    // The subnormal vertex of the second input, exactly.
    const nlohmann::json sub = nlohmann::json::parse(run("-q --unclipped", xy_text(inputs[1])).out);
    EXPECT_EQ(sub["vertices"][0][0].get<double>(), 2e-310);
    EXPECT_EQ(sub["vertices"][1][0].get<double>(), 5e299);
}

TEST(ExidelVoronoi, ClipMatchesTheLibraryAndKeepsUnbounded) {
    const std::vector<Point2> points = lattice_circle();
    const Library l = library(points);
    const RunResult r = run("--clip -6 -0x1p-3 6.5 6", xy_text(points));
    ASSERT_EQ(r.status, 0) << r.err;
    const delaunay::ClippedVoronoi c =
        delaunay::clip(l.diagram, points, l.triangulation.triangulation, {-6, -0.125, 6.5, 6});
    expect_voronoi_json(r.out, c);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_GT(j["vertices"].size(), 1u);
    EXPECT_TRUE(j["unbounded"][0].get<bool>());  // the unclipped cell's
    // The last --clip counts, as with every option.
    const RunResult twice = run("--clip 0 0 1 1 --clip -6 -0x1p-3 6.5 6", xy_text(points));
    EXPECT_EQ(twice.status, 0) << twice.err;
    EXPECT_EQ(twice.out, r.out);
}

TEST(ExidelVoronoi, BadClipIsAUsageError) {
    const std::string out = work_path("badclip.json");
    for (const char* clip :
         {"--clip", "--clip 0 0 1", "--clip 1 0 0 1", "--clip 0 1 1 0", "--clip 0 0 0 1",
          "--clip 0 0 1 1e-400", "--clip nan 0 1 1", "--clip 0 -inf 1 1", "--clip 0 0 inf 1",
          "--clip 0 0 1e309 1", "--clip a 0 1 1", "--clip 0 0 1 1x", "--clip=1"}) {
        std::remove(out.c_str());
        const RunResult r = run(std::string(clip) + " -o " + out, "0 0\n1 0\n0 1\n");
        EXPECT_EQ(r.status, 2) << clip << ": " << r.err;
        EXPECT_EQ(r.err.rfind("exidel voronoi: ", 0), 0u) << clip << ": " << r.err;
        EXPECT_NE(r.err.find("usage: exidel voronoi"), std::string::npos) << clip;
        EXPECT_TRUE(r.out.empty()) << clip;
        EXPECT_FALSE(exists(out)) << clip;
    }
    // Other bad options too.
    for (const char* args :
         {"--kernel fast", "--format ele", "--threads 0", "-a nothing", "--input-format csv", "a b",
          "-o a.json -o b.json", "--frob", "--input-format json --columns 1,2"}) {
        EXPECT_EQ(run(args, "0 0\n").status, 2) << args;
    }
    const RunResult png = run("-o " + work_path("vor.png"), "0 0\n");
    EXPECT_EQ(png.status, 2);
    EXPECT_NE(png.err.find("cannot tell the output format from"), std::string::npos) << png.err;
}

TEST(ExidelVoronoi, MalformedInputNamesTheLineAndWritesNothing) {
    const std::string in = write_file("vbad.xy", "0 0\n1 0\n# c\n0 1\n1 nan\n");
    const std::string out = work_path("vbad.json");
    std::remove(out.c_str());
    const RunResult r = run("-i " + in + " -o " + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err.rfind("exidel: line 5: ", 0), 0u) << r.err;
    EXPECT_FALSE(exists(out));
    write_file("vbad.json", "previous");
    EXPECT_EQ(run(in + " -o " + out).status, 1);  // the positional FILE
    EXPECT_EQ(slurp(out), "previous");
    const RunResult json = run("--input-format json", "[[0, 0],\n [1, 0],\n [0, 1e999]]");
    EXPECT_EQ(json.status, 1);
    EXPECT_EQ(json.err.rfind("exidel: line 3: ", 0), 0u) << json.err;
    EXPECT_TRUE(json.out.empty());
    EXPECT_TRUE(files_containing(".tmp.").empty());
    const RunResult missing = run("-i " + work_path("no-such-file.xy"));
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("No such file or directory"), std::string::npos) << missing.err;
}

// The exact centre of (-DBL_MAX, 0), (DBL_MAX, 0), (0, 1) is near (0, -DBL_MAX^2 / 2):
// not a double. The run fails with the library's reason and writes nothing.
TEST(ExidelVoronoi, CentreBeyondTheLargestDoubleExitsOne) {
    const std::string in =
        write_file("voverflow.xy", "-1.7976931348623157e308 0\n1.7976931348623157e308 0\n0 1\n");
    const std::string out = work_path("voverflow.json");
    std::remove(out.c_str());
    const RunResult r = run("-i " + in + " -o " + out + " --stats");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err.rfind("exidel: voronoi: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("beyond the largest double"), std::string::npos) << r.err;
    EXPECT_FALSE(exists(out));
    EXPECT_TRUE(files_containing(".tmp.").empty());
    // --stats: the last line, with the failure.
    const std::string stats = r.err.substr(r.err.find('\n') + 1);
    const nlohmann::json j = nlohmann::json::parse(stats);
    EXPECT_EQ(j["failure"]["step"], "voronoi");
    EXPECT_EQ(j["failure"]["kind"], "overflow");
    const RunResult plain = run("-i " + in);
    EXPECT_EQ(plain.status, 1);
    EXPECT_TRUE(plain.out.empty());
}

TEST(ExidelVoronoi, SvgIsAWholeDocument) {
    std::vector<Point2> points = lattice_circle();
    // Outside the circle, which stays empty: its centre stays one vertex of 12 sites.
    for (int i = 0; i < 20; ++i) {
        points.push_back({(6 + i % 3) * std::sin(i * 1.3), (6 + i % 4) * std::cos(i * 1.3)});
    }
    const std::string in = write_file("vsvg.xy", xy_text(points));
    for (const std::string& args :
         {std::string("-o ") + work_path("v.svg"), std::string("-f svg -o ") + work_path("v2.out"),
          std::string("--clip -4 -4 4 4 -o ") + work_path("v3.svg")}) {
        const RunResult r = run("-i " + in + " " + args);
        ASSERT_EQ(r.status, 0) << args << ": " << r.err;
        const std::string svg = slurp(args.substr(args.rfind(' ') + 1));
        expect_whole_svg(svg);
        EXPECT_NE(svg.find("#e67e22"), std::string::npos) << args;  // the merged vertex's ring
#ifdef EXIDEL_RSVG_CONVERT
        const std::string render = std::string("'") + EXIDEL_RSVG_CONVERT + "' -w 100 -o '" +
                                   work_path("v.png") + "' '" + args.substr(args.rfind(' ') + 1) +
                                   "' 2> '" + work_path("vrsvg.err") + "'";
        EXPECT_EQ(std::system(render.c_str()), 0) << slurp(work_path("vrsvg.err"));
#endif
    }
}

// No, one and two points, collinear points: no vertices, every cell empty (the whole
// plane, half-planes, strips); clipped, the strips' polygons. A note says why, unless -q.
TEST(ExidelVoronoi, TinyAndCollinearInputSucceed) {
    for (const std::string input : {"", "1 2\n", "0 0\n1 0\n", "0 0\n1 1\n3 3\n1 1\n-2 -2\n"}) {
        const std::vector<Point2> points = io::parse_points(input, io::PointFormat::xy);
        const RunResult r = run("--unclipped", input);
        ASSERT_EQ(r.status, 0) << input << r.err;
        EXPECT_NE(r.err.find("exidel: note: no Voronoi vertices"), std::string::npos) << r.err;
        expect_voronoi_json(r.out, library(points).diagram);
        const nlohmann::json j = nlohmann::json::parse(r.out);
        EXPECT_TRUE(j["vertices"].empty());
        EXPECT_EQ(j["cells"].size(), points.size());
        for (const auto& cell : j["cells"]) EXPECT_TRUE(cell.empty());
        EXPECT_TRUE(run("-q", input).err.empty());
        const RunResult svg = run("-q -f svg", input);
        EXPECT_EQ(svg.status, 0) << svg.err;
        expect_whole_svg(svg.out);
        const RunResult clipped = run("-q --clip -5 -5 5 5", input);
        ASSERT_EQ(clipped.status, 0) << clipped.err;
        const nlohmann::json c = nlohmann::json::parse(clipped.out);
        EXPECT_EQ(c["cells"].size(), points.size());
        for (const auto& cell : c["cells"]) EXPECT_GE(cell.size(), 3u) << clipped.out;
        EXPECT_EQ(run("-q -f svg --clip -5 -5 5 5", input).status, 0);
    }
}

TEST(ExidelVoronoi, StatsIsOneJsonObjectWithEveryKey) {
    const std::vector<Point2> points = lattice_circle();
    const RunResult r = run("--stats --kernel exact -a dwyer --clip -6 -6 6 6", xy_text(points));
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    const nlohmann::ordered_json j = nlohmann::ordered_json::parse(r.err);
    std::vector<std::string> keys;
    for (const auto& item : j.items()) keys.push_back(item.key());
    EXPECT_EQ(keys, (std::vector<std::string>{
                        "points", "duplicates", "triangles", "collinear", "vertices",
                        "clipped_vertices", "kernel", "algorithm", "stage_counts",
                        "cocircular_tests", "cocircular_merges", "failure", "read_ms",
                        "triangulate_ms", "voronoi_ms", "clip_ms", "write_ms", "total_ms"}));
    EXPECT_EQ(j["points"], 13);
    EXPECT_EQ(j["duplicates"], 1);
    EXPECT_EQ(j["vertices"], 1);
    EXPECT_EQ(j["clipped_vertices"], nlohmann::json::parse(r.out)["vertices"].size());
    EXPECT_EQ(j["kernel"], "exact");
    EXPECT_EQ(j["algorithm"], "dwyer");
    const auto& stages = j["stage_counts"];
    EXPECT_EQ(stages["floating"].get<std::uint64_t>() + stages["double_word"].get<std::uint64_t>() +
                  stages["exact"].get<std::uint64_t>(),
              j["triangles"].get<std::uint64_t>());
    EXPECT_EQ(j["cocircular_merges"], 9);  // ten triangles, one vertex
    EXPECT_GE(j["cocircular_tests"].get<std::uint64_t>(), 9u);
    EXPECT_TRUE(j["failure"].is_null());
    EXPECT_GE(j["total_ms"].get<double>(), j["voronoi_ms"].get<double>());
    const nlohmann::json plain =
        nlohmann::json::parse(run("--stats --unclipped", xy_text(points)).err);
    EXPECT_TRUE(plain["clipped_vertices"].is_null());
    EXPECT_EQ(plain["algorithm"], "external");
    EXPECT_EQ(plain["kernel"], "adaptive");
}

// The viewBox of an SVG as four doubles (x, y, width, height).
std::vector<double> view_box(const std::string& svg) {
    const std::size_t at = svg.find("viewBox=\"");
    EXPECT_NE(at, std::string::npos) << svg.substr(0, 300);
    std::istringstream in(svg.substr(at + 9, svg.find('"', at + 9) - at - 9));
    std::vector<double> v(4);
    for (double& x : v) in >> x;
    return v;
}

// The default: clipped to the sites' bounding box widened by 10% of its larger side, for
// every format; --unclipped gives the whole diagram, --clip its own box.
TEST(ExidelVoronoi, ClippedByDefaultToTheSitesBoxWithAMargin) {
    std::vector<Point2> points;
    for (int i = 0; i < 40; ++i) {
        points.push_back({500000 + 37.0 * ((i * 7919) % 41), 4000000 + 23.0 * ((i * 104729) % 37)});
    }
    const Library l = library(points);
    const delaunay::Box box = io::default_clip_box(points);
    double x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
    for (const Point2& p : points) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    const double margin = io::default_clip_margin * std::max(x1 - x0, y1 - y0);
    EXPECT_EQ(box.xmin, x0 - margin);
    EXPECT_EQ(box.xmax, x1 + margin);
    EXPECT_EQ(box.ymin, y0 - margin);
    EXPECT_EQ(box.ymax, y1 + margin);
    const RunResult r = run("-q", xy_text(points));
    ASSERT_EQ(r.status, 0) << r.err;
    expect_voronoi_json(r.out,
                        delaunay::clip(l.diagram, points, l.triangulation.triangulation, box));
    const RunResult whole = run("-q --unclipped", xy_text(points));
    ASSERT_EQ(whole.status, 0) << whole.err;
    expect_voronoi_json(whole.out, l.diagram);
    // The SVG's viewBox is the box, in input units (y flipped).
    const RunResult svg = run("-q -f svg", xy_text(points));
    ASSERT_EQ(svg.status, 0) << svg.err;
    expect_whole_svg(svg.out);
    EXPECT_EQ(view_box(svg.out),
              (std::vector<double>{box.xmin, -box.ymax, box.xmax - box.xmin, box.ymax - box.ymin}));
    const RunResult clipped =
        run("-q -f svg --clip 500100 4000100 500900 4000300", xy_text(points));
    ASSERT_EQ(clipped.status, 0) << clipped.err;
    EXPECT_EQ(view_box(clipped.out), (std::vector<double>{500100, -4000300, 800, 200}));
    // One point: a unit margin.
    const RunResult one = run("-q", "5e5 4e6\n");
    ASSERT_EQ(one.status, 0) << one.err;
    const std::vector<Point2> lone = {{5e5, 4e6}};
    const Library ll = library(lone);
    expect_voronoi_json(one.out, delaunay::clip(ll.diagram, lone, ll.triangulation.triangulation,
                                                {499999, 3999999, 500001, 4000001}));
    // Usage errors: both, and polygon formats without a box.
    for (const char* args : {"--unclipped --clip 0 0 1 1", "--unclipped -f geojson",
                             "--unclipped -f wkt", "--unclipped=1"}) {
        const RunResult bad = run(args, "0 0\n1 0\n0 1\n");
        EXPECT_EQ(bad.status, 2) << args;
        EXPECT_EQ(bad.err.rfind("exidel voronoi: ", 0), 0u) << bad.err;
    }
}

TEST(ExidelVoronoi, GeojsonAndWktHoldTheClippedCells) {
    std::vector<Point2> points = lattice_circle();  // with a duplicate of site 4 as 12
    const Library l = library(points);
    const delaunay::Box box{-6, -6, 6, 6.5};
    const delaunay::ClippedVoronoi c =
        delaunay::clip(l.diagram, points, l.triangulation.triangulation, box);
    const std::string in = write_file("vgis.xy", xy_text(points));
    for (const char* ext : {"geojson", "wkt"}) {
        const std::string out = work_path(std::string("vgis.") + ext);
        const RunResult r = run("-q -i " + in + " --clip -6 -6 6 6.5 -o " + out);
        ASSERT_EQ(r.status, 0) << r.err;
        std::ostringstream expected;
        io::write_voronoi(expected, points, c, box, *io::voronoi_format_from_name(ext));
        EXPECT_EQ(slurp(out), expected.str()) << ext;
    }
    const nlohmann::json j = nlohmann::json::parse(slurp(work_path("vgis.geojson")));
    ASSERT_EQ(j["features"].size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(j["features"][i]["properties"]["site"], i);
        const auto cell = c.cell(i);
        const auto& ring = j["features"][i]["geometry"]["coordinates"][0];
        ASSERT_EQ(ring.size(), cell.size() + 1) << i;
        for (std::size_t k = 0; k <= cell.size(); ++k) {
            const Point2 v = c.vertices[cell[k % cell.size()]];
            EXPECT_EQ(ring[k][0].get<double>(), v.x);
            EXPECT_EQ(ring[k][1].get<double>(), v.y);
        }
    }
    EXPECT_EQ(j["features"][12]["geometry"], j["features"][4]["geometry"]);
    const std::string wkt = slurp(work_path("vgis.wkt"));
    EXPECT_EQ(wkt.rfind("GEOMETRYCOLLECTION (POLYGON ((", 0), 0u) << wkt;
    EXPECT_EQ(std::count(wkt.begin(), wkt.end(), '\n'), static_cast<long>(points.size()));
}

}  // namespace
