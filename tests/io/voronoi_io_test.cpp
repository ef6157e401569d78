// Tests of the Voronoi diagram writers (exidel/io/voronoi.hpp): the json layout read back
// by nlohmann-json (key order, every coordinate the same double bit for bit, negative
// zero, subnormals, the largest doubles), the clipped overload, the format names, and
// SVG pictures of every kind of diagram that are whole documents.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "exidel/delaunay/triangulate.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/io/voronoi.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "voronoi_json.hpp"

namespace {

using exidel::AdaptiveKernel;
using exidel::io_test::expect_voronoi_json;
using exidel::io_test::expect_whole_svg;
using exidel::io_test::lattice_circle;
using exidel::Point2;
namespace delaunay = exidel::delaunay;
namespace io = exidel::io;

std::string to_json(std::span<const Point2> points, const delaunay::VoronoiDiagram& d) {
    std::ostringstream s;
    io::write_voronoi(s, points, d, io::VoronoiFormat::json);
    return s.str();
}

std::string to_svg(std::span<const Point2> points, const delaunay::VoronoiDiagram& d) {
    std::ostringstream s;
    io::write_voronoi(s, points, d, io::VoronoiFormat::svg);
    return s.str();
}

delaunay::VoronoiDiagram diagram_of(const std::vector<Point2>& points) {
    const delaunay::Result r = delaunay::triangulate(points, AdaptiveKernel{});
    EXPECT_TRUE(r.ok());
    return delaunay::voronoi(points, r.triangulation, AdaptiveKernel{});
}

TEST(VoronoiWriter, JsonOfAHandMadeDiagramReadsBackBitForBit) {
    // Values a careless writer gets wrong: negative zero (to_chars says "-0", an integer
    // to JSON readers), the smallest subnormal, the largest doubles, a value printed
    // without exponent beyond 2^64, and one that needs 17 digits.
    delaunay::VoronoiDiagram d;
    const double max = std::numeric_limits<double>::max();
    const double tiny = std::numeric_limits<double>::denorm_min();
    d.vertices = {{-0.0, 0.0},
                  {tiny, -tiny},
                  {max, -max},
                  {1.2345678901234568e20, 0.1},
                  {1e-310, -2.2250738585072014e-308},
                  {0.30000000000000004, -1e22}};
    d.site_offsets = {0, 3, 7, 10, 13, 16, 19};
    d.sites = {0, 1, 2, 0, 2, 3, 4, 1, 2, 3, 0, 1, 4, 2, 3, 4, 0, 3, 4};
    d.cell_offsets = {0, 2, 2, 5, 6, 6};
    d.cell_vertices = {0, 1, 2, 3, 4, 5};
    d.unbounded = {1, 0, 0, 1, 1};
    d.entry_ray = d.exit_ray = std::vector<Point2>(5, Point2{0, 0});
    const std::vector<Point2> points(5, Point2{0, 0});
    const std::string text = to_json(points, d);
    EXPECT_EQ(text.rfind("{\"vertices\": [[-0.0, 0], [5e-324, -5e-324], ", 0), 0u) << text;
    EXPECT_NE(text.find("],\n \"vertex_sites\": [[0, 1, 2], "), std::string::npos) << text;
    EXPECT_NE(text.find("],\n \"cells\": [[0, 1], [], [2, 3, 4], [5], []],\n"), std::string::npos)
        << text;
    EXPECT_NE(text.find(",\n \"unbounded\": [true, false, false, true, true]}\n"),
              std::string::npos)
        << text;
    expect_voronoi_json(text, d);
    const nlohmann::json j = nlohmann::json::parse(text);
    EXPECT_TRUE(std::signbit(j["vertices"][0][0].get<double>()));
    EXPECT_FALSE(std::signbit(j["vertices"][0][1].get<double>()));
}

TEST(VoronoiWriter, JsonOfALatticeCircleHasOneVertexWithEverySite) {
    std::vector<Point2> points = lattice_circle();
    points.push_back(points[4]);  // a duplicate of (5, 0): index 12
    const delaunay::VoronoiDiagram d = diagram_of(points);
    const std::string text = to_json(points, d);
    expect_voronoi_json(text, d);
    const nlohmann::json j = nlohmann::json::parse(text);
    ASSERT_EQ(j["vertices"].size(), 1u);
    EXPECT_EQ(j["vertices"][0], nlohmann::json::parse("[0, 0]"));
    std::vector<std::uint32_t> sites = j["vertex_sites"][0].get<std::vector<std::uint32_t>>();
    EXPECT_EQ(sites.size(), 13u);
    EXPECT_EQ(sites.front(), 0u);
    std::sort(sites.begin(), sites.end());
    for (std::uint32_t i = 0; i < 13; ++i) EXPECT_EQ(sites[i], i);
    EXPECT_EQ(j["cells"].size(), 13u);
    EXPECT_EQ(j["cells"][12], j["cells"][4]);  // the duplicate repeats its twin's cell
}

TEST(VoronoiWriter, ClippedJsonHasTheSameLayout) {
    const std::vector<Point2> points = lattice_circle();
    const delaunay::Result r = delaunay::triangulate(points, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    const delaunay::VoronoiDiagram d = delaunay::voronoi(points, r.triangulation, AdaptiveKernel{});
    const delaunay::Box box{-6, -0x1p-1074, 6, 6.5};
    const delaunay::ClippedVoronoi c = delaunay::clip(d, points, r.triangulation, box);
    std::ostringstream json, svg;
    io::write_voronoi(json, points, c, box, io::VoronoiFormat::json);
    expect_voronoi_json(json.str(), c);
    io::write_voronoi(svg, points, c, box, io::VoronoiFormat::svg);
    expect_whole_svg(svg.str());
    EXPECT_NE(svg.str().find(" Z\""), std::string::npos);  // the box
}

TEST(VoronoiWriter, CollinearAndTinyDiagramsHaveEmptyCells) {
    for (const std::vector<Point2>& points :
         {std::vector<Point2>{}, std::vector<Point2>{{1, 2}}, std::vector<Point2>{{0, 0}, {1, 1}},
          std::vector<Point2>{{0, 0}, {1, 1}, {3, 3}, {1, 1}}}) {
        const delaunay::VoronoiDiagram d = diagram_of(points);
        const std::string text = to_json(points, d);
        expect_voronoi_json(text, d);
        const nlohmann::json j = nlohmann::json::parse(text);
        EXPECT_TRUE(j["vertices"].empty());
        EXPECT_EQ(j["cells"].size(), points.size());
        for (const auto& cell : j["cells"]) EXPECT_TRUE(cell.empty());
        const std::string svg = to_svg(points, d);
        expect_whole_svg(svg);
        // One bisector between each pair of chain neighbours.
        if (points.size() == 4) {
            EXPECT_EQ(std::count(svg.begin(), svg.end(), 'L'), 2);
        }
    }
}

TEST(VoronoiWriter, SvgShowsEdgesRaysAndRingsMergedVertices) {
    // The square's corners and centre: four vertices, four bounded edges, four rays.
    const std::vector<Point2> square = {{0, 0}, {4, 0}, {0, 4}, {4, 4}, {2, 2}};
    const std::string svg = to_svg(square, diagram_of(square));
    expect_whole_svg(svg);
    EXPECT_EQ(std::count(svg.begin(), svg.end(), 'L'), 8) << svg;
    EXPECT_EQ(svg.find("#e67e22"), std::string::npos);  // nothing merged
    // The lattice circle: one merged vertex, ringed; twelve rays.
    const std::vector<Point2> circle = lattice_circle();
    const std::string ringed = to_svg(circle, diagram_of(circle));
    expect_whole_svg(ringed);
    EXPECT_NE(ringed.find("#e67e22"), std::string::npos);
    EXPECT_EQ(std::count(ringed.begin(), ringed.end(), 'L'), 12) << ringed;
    // Huge and subnormal coordinates stay finite in the picture.
    const std::vector<Point2> extreme = {
        {0, 0}, {4e-310, 0}, {0, 4e-310}, {1e300, 1e300}, {-1e300, 1e300}};
    expect_whole_svg(to_svg(extreme, diagram_of(extreme)));
}

TEST(VoronoiWriter, FormatNames) {
    EXPECT_EQ(io::voronoi_format_from_name("json"), io::VoronoiFormat::json);
    EXPECT_EQ(io::voronoi_format_from_name("svg"), io::VoronoiFormat::svg);
    EXPECT_EQ(io::voronoi_format_from_name("ele"), std::nullopt);
    EXPECT_EQ(io::voronoi_format_from_path("out/d.svg"), io::VoronoiFormat::svg);
    EXPECT_EQ(io::voronoi_format_from_path("d.json"), io::VoronoiFormat::json);
    EXPECT_EQ(io::voronoi_format_from_path("d.svg/x"), std::nullopt);
    EXPECT_EQ(io::voronoi_format_from_path("d"), std::nullopt);
    EXPECT_EQ(io::to_string(io::VoronoiFormat::svg), "svg");
    EXPECT_EQ(io::to_string(io::VoronoiFormat::json), "json");
}

}  // namespace
