// Tests of what GIS tools read and write: SVG in data coordinates (the viewBox parsed
// back), GeoJSON and WKT of triangulations and clipped Voronoi diagrams, PLY (binary and
// ASCII, parsed back), z carried from the input (--columns X,Y,Z, GeoJSON) into OFF,
// GeoJSON, WKT and PLY, the default clip box, and the GeoJSON point reader.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/delaunay/triangulate.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"
#include "exidel/io/voronoi.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "voronoi_json.hpp"

namespace exidel::io {
namespace {

using delaunay::Triangulation;

// The unit square split along 0-2, plus a duplicate of point 0 at index 4.
const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};

Triangulation square_triangulation() {
    Triangulation t;
    t.triangles = {0, 1, 2, 0, 2, 3};
    t.halfedges = {-1, -1, 3, 2, -1, -1};
    t.hull = {0, 1, 2, 3};
    t.duplicates = {4};
    t.vertex_of_input = {0, 1, 2, 3, 0};
    return t;
}

std::string written(std::span<const Point2> pts, const Triangulation& t, TriangulationFormat f,
                    std::span<const double> z = {}) {
    std::ostringstream out;
    WriteOptions options;
    options.z = z;
    write_triangulation(out, pts, t, f, options);
    return out.str();
}

Triangulation triangulated(const std::vector<Point2>& pts) {
    const delaunay::Result r = delaunay::triangulate(pts, AdaptiveKernel{});
    EXPECT_TRUE(r.ok());
    return r.triangulation;
}

// The viewBox of an SVG as four doubles (x, y, width, height).
std::vector<double> view_box(const std::string& svg) {
    const std::size_t at = svg.find("viewBox=\"");
    if (at == std::string::npos) return {};
    std::istringstream in(svg.substr(at + 9, svg.find('"', at + 9) - at - 9));
    std::vector<double> v(4, std::nan(""));
    for (double& x : v) in >> x;
    return v;
}

std::vector<double> bounds_box(std::span<const Point2> pts) {
    double x0 = pts[0].x, x1 = x0, y0 = pts[0].y, y1 = y0;
    for (const Point2& p : pts) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    return {x0, -y1, x1 - x0, y1 - y0};
}

// UTM-like: eastings near 5e5, northings near 4e6, over a few hundred metres.
std::vector<Point2> utm_points(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 700);
    std::vector<Point2> pts;
    for (std::size_t i = 0; i < n; ++i) pts.push_back({500000 + u(rng), 4000000 + u(rng) / 2});
    return pts;
}

TEST(GisSvg, ViewBoxIsTheDataBoundsInInputUnits) {
    const std::vector<Point2> pts = utm_points(300, 5);
    const std::string svg = written(pts, triangulated(pts), TriangulationFormat::svg);
    io_test::expect_whole_svg(svg);
    EXPECT_EQ(view_box(svg), bounds_box(pts));
    EXPECT_NE(svg.find("<g transform=\"scale(1,-1)\">"), std::string::npos);
    // Width and height keep the aspect, the larger side 1000 pixels.
    const std::vector<double> b = bounds_box(pts);
    std::ostringstream size;
    size << "width=\"1000.0\" height=\"" << std::fixed;
    size.precision(1);
    size << std::round(b[3] / b[2] * 10000) / 10 << "\"";
    EXPECT_NE(svg.find(size.str()), std::string::npos) << size.str() << "\n" << svg.substr(0, 200);
    // The first dot is the first point, written so that it reads back exactly.
    const std::size_t dots = svg.find("stroke=\"#111\"");
    const std::size_t m = svg.find("<path d=\"M", dots);
    std::istringstream first(svg.substr(m + 10, 60));
    double x = 0, y = 0;
    first >> x >> y;
    EXPECT_EQ(x, pts[0].x);
    EXPECT_EQ(y, pts[0].y);
}

TEST(GisSvg, DegenerateBoundsArePaddedWhereASideIsZero) {
    struct Case {
        std::vector<Point2> pts;
        std::vector<double> box;
    };
    const double big_pad = 4e6 * 0x1p-20;  // 2^-20 of the largest coordinate, above 1
    for (const Case& c : std::vector<Case>{
             {{}, {-1, -1, 2, 2}},
             {{{3, 4}}, {2, -5, 2, 2}},
             {{{3, 4}, {3, 4}}, {2, -5, 2, 2}},
             {{{0, 0}, {4, 0}, {2, 0}}, {0, -2, 4, 4}},  // horizontal: square, centred
             {{{1, 0}, {1, 6}}, {-2, -6, 6, 6}},         // vertical
             {{{5e5, 4e6}}, {5e5 - big_pad, -(4e6 + big_pad), 2 * big_pad, 2 * big_pad}},
         }) {
        const std::string svg = written(c.pts, triangulated(c.pts), TriangulationFormat::svg);
        io_test::expect_whole_svg(svg);
        EXPECT_EQ(view_box(svg), c.box) << svg.substr(0, 200);
    }
    // Coordinates of both signs near the largest double: the span is kept finite.
    const std::vector<Point2> huge{{-1.7e308, 0}, {1.7e308, 1e308}, {0, -1e308}};
    const std::string svg = written(huge, triangulated(huge), TriangulationFormat::svg);
    io_test::expect_whole_svg(svg);
    const std::vector<double> b = view_box(svg);
    ASSERT_EQ(b.size(), 4u);
    EXPECT_EQ(b[0], -1.7e308);
    EXPECT_EQ(b[1], -1e308);
    EXPECT_EQ(b[2], std::numeric_limits<double>::max());
    EXPECT_EQ(b[3], std::numeric_limits<double>::max());
    // A span too small for a large coordinate still gives the picture an interior.
    const std::vector<Point2> thin{{1e300, 0}, {1e300, 1e-300}};
    const std::vector<double> t =
        view_box(written(thin, triangulated(thin), TriangulationFormat::svg));
    ASSERT_EQ(t.size(), 4u);
    EXPECT_GT(t[2], 0);
    EXPECT_GT(t[3], 0);
}

TEST(GisSvg, VoronoiViewBoxIsTheClipBoxOrTheWholeDiagramsBounds) {
    const std::vector<Point2> pts = utm_points(100, 9);
    const delaunay::Result r = delaunay::triangulate(pts, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    const delaunay::VoronoiDiagram d = delaunay::voronoi(pts, r.triangulation, AdaptiveKernel{});
    const delaunay::Box box = default_clip_box(pts);
    std::ostringstream clipped, whole;
    write_voronoi(clipped, pts, delaunay::clip(d, pts, r.triangulation, box), box,
                  VoronoiFormat::svg);
    io_test::expect_whole_svg(clipped.str());
    EXPECT_EQ(view_box(clipped.str()),
              (std::vector<double>{box.xmin, -box.ymax, box.xmax - box.xmin, box.ymax - box.ymin}));
    write_voronoi(whole, pts, d, VoronoiFormat::svg);
    io_test::expect_whole_svg(whole.str());
    std::vector<Point2> all = pts;
    all.insert(all.end(), d.vertices.begin(), d.vertices.end());
    EXPECT_EQ(view_box(whole.str()), bounds_box(all));
}

TEST(GisGeojson, TriangulationFeaturesAndHull) {
    const std::string text = written(square, square_triangulation(), TriangulationFormat::geojson);
    EXPECT_EQ(text,
              "{\"type\": \"FeatureCollection\", \"features\": [\n"
              "{\"type\": \"Feature\", \"properties\": {\"triangle\": 0, \"vertices\": [0, 1, 2]}, "
              "\"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [1, 1], "
              "[0, 0]]]}},\n"
              "{\"type\": \"Feature\", \"properties\": {\"triangle\": 1, \"vertices\": [0, 2, 3]}, "
              "\"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 1], [0, 1], "
              "[0, 0]]]}},\n"
              "{\"type\": \"Feature\", \"properties\": {\"hull\": true, \"vertices\": [0, 1, 2, "
              "3]}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [1, "
              "1], [0, 1], [0, 0]]]}}\n]}\n");
    const std::vector<double> z{0.1, -0.0, 0.30000000000000004, 1e22, 7};
    const nlohmann::json j = nlohmann::json::parse(
        written(square, square_triangulation(), TriangulationFormat::geojson, z));
    const auto& ring = j["features"][1]["geometry"]["coordinates"][0];
    ASSERT_EQ(ring.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        const std::uint32_t v = square_triangulation().triangles[3 + k % 3];
        ASSERT_EQ(ring[k].size(), 3u);
        EXPECT_EQ(ring[k][2].get<double>(), z[v]);
    }
    EXPECT_TRUE(std::signbit(j["features"][2]["geometry"]["coordinates"][0][1][2].get<double>()));
    // Coordinates are never rounded: every one reads back as the same double.
    const std::vector<Point2> pts = utm_points(50, 3);
    const nlohmann::json u =
        nlohmann::json::parse(written(pts, triangulated(pts), TriangulationFormat::geojson));
    for (const auto& f : u["features"]) {
        if (f["properties"].contains("hull")) continue;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t v = f["properties"]["vertices"][k];
            EXPECT_EQ(f["geometry"]["coordinates"][0][k][0].get<double>(), pts[v].x);
            EXPECT_EQ(f["geometry"]["coordinates"][0][k][1].get<double>(), pts[v].y);
        }
    }
}

TEST(GisGeojson, CollinearOnePointAndNoPoints) {
    const std::vector<Point2> line{{0, 0}, {2, 2}, {1, 1}, {1, 1}};
    EXPECT_EQ(written(line, triangulated(line), TriangulationFormat::geojson),
              "{\"type\": \"FeatureCollection\", \"features\": [\n{\"type\": \"Feature\", "
              "\"properties\": {\"hull\": true, \"vertices\": [0, 2, 1]}, \"geometry\": "
              "{\"type\": \"LineString\", \"coordinates\": [[0, 0], [1, 1], [2, 2]]}}\n]}\n");
    const std::vector<Point2> one{{-0.0, 2.5}, {-0.0, 2.5}};
    EXPECT_EQ(written(one, triangulated(one), TriangulationFormat::geojson),
              "{\"type\": \"FeatureCollection\", \"features\": [\n{\"type\": \"Feature\", "
              "\"properties\": {\"hull\": true, \"vertices\": [0]}, \"geometry\": {\"type\": "
              "\"Point\", \"coordinates\": [-0.0, 2.5]}}\n]}\n");
    EXPECT_EQ(written({}, Triangulation{}, TriangulationFormat::geojson),
              "{\"type\": \"FeatureCollection\", \"features\": []}\n");
}

TEST(GisWkt, MultipolygonInTriangleOrder) {
    EXPECT_EQ(written(square, square_triangulation(), TriangulationFormat::wkt),
              "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)),\n((0 0, 1 1, 0 1, 0 0)))\n");
    const std::vector<double> z{1, 2, 3.5, 4, 5};
    EXPECT_EQ(written(square, square_triangulation(), TriangulationFormat::wkt, z),
              "MULTIPOLYGON Z (((0 0 1, 1 0 2, 1 1 3.5, 0 0 1)),\n((0 0 1, 1 1 3.5, 0 1 4, 0 0 "
              "1)))\n");
    const std::vector<Point2> line{{0, 0}, {1, 1}};
    EXPECT_EQ(written(line, triangulated(line), TriangulationFormat::wkt), "MULTIPOLYGON EMPTY\n");
    EXPECT_EQ(
        written(line, triangulated(line), TriangulationFormat::wkt, std::vector<double>{1, 2}),
        "MULTIPOLYGON Z EMPTY\n");
}

TEST(GisOff, WritesZInsteadOfZero) {
    const std::vector<double> z{0.5, -1, 2e-300, 3, 0.5};
    EXPECT_EQ(written(square, square_triangulation(), TriangulationFormat::off, z),
              "OFF\n5 2 0\n0 0 0.5\n1 0 -1\n1 1 2e-300\n0 1 3\n0 0 0.5\n3 0 1 2\n3 0 2 3\n");
    EXPECT_THROW(written(square, square_triangulation(), TriangulationFormat::off,
                         std::vector<double>{1, 2}),
                 std::invalid_argument);
}

// A PLY file read back: the header's elements and properties checked, then the vertices
// and faces of either encoding.
struct Ply {
    std::vector<double> x, y, z;
    std::vector<std::uint32_t> faces;
};

Ply read_ply(const std::string& data, bool binary) {
    Ply ply;
    std::size_t at = 0;
    std::vector<std::string> header;
    for (;;) {
        const std::size_t nl = data.find('\n', at);
        EXPECT_NE(nl, std::string::npos);
        if (nl == std::string::npos) return ply;
        header.push_back(data.substr(at, nl - at));
        at = nl + 1;
        if (header.back() == "end_header") break;
    }
    EXPECT_EQ(header[0], "ply");
    EXPECT_EQ(header[1], binary ? "format binary_little_endian 1.0" : "format ascii 1.0");
    std::size_t vertices = 0, faces = 0;
    std::vector<std::string> properties;
    for (const std::string& line : header) {
        std::istringstream in(line);
        std::string word, name;
        in >> word;
        if (word == "element") {
            std::size_t count = 0;
            in >> name >> count;
            (name == "vertex" ? vertices : faces) = count;
        } else if (word == "property") {
            properties.push_back(line);
        }
    }
    EXPECT_EQ(properties, (std::vector<std::string>{"property double x", "property double y",
                                                    "property double z",
                                                    "property list uchar int vertex_indices"}));
    if (binary) {
        EXPECT_EQ(data.size() - at, 24 * vertices + 13 * faces);
        const auto f64 = [&](std::size_t offset) {
            std::uint64_t bits = 0;
            for (int b = 7; b >= 0; --b)
                bits = bits << 8 | static_cast<unsigned char>(data[offset + b]);
            return std::bit_cast<double>(bits);
        };
        for (std::size_t i = 0; i < vertices; ++i, at += 24) {
            ply.x.push_back(f64(at));
            ply.y.push_back(f64(at + 8));
            ply.z.push_back(f64(at + 16));
        }
        for (std::size_t t = 0; t < faces; ++t, at += 13) {
            EXPECT_EQ(data[at], 3);
            for (std::size_t k = 0; k < 3; ++k) {
                std::uint32_t v = 0;
                for (int b = 3; b >= 0; --b)
                    v = v << 8 | static_cast<unsigned char>(data[at + 1 + 4 * k + b]);
                ply.faces.push_back(v);
            }
        }
        return ply;
    }
    std::istringstream in(data.substr(at));
    for (std::size_t i = 0; i < vertices; ++i) {
        std::string x, y, z;  // read as text: operator>> on doubles is not exact everywhere
        in >> x >> y >> z;
        ply.x.push_back(std::stod(x));
        ply.y.push_back(std::stod(y));
        ply.z.push_back(std::stod(z));
    }
    for (std::size_t t = 0; t < faces; ++t) {
        unsigned count = 0;
        in >> count;
        EXPECT_EQ(count, 3u);
        for (std::size_t k = 0; k < 3; ++k) {
            std::uint32_t v = 0;
            in >> v;
            ply.faces.push_back(v);
        }
    }
    std::string rest;
    EXPECT_FALSE(in >> rest) << rest;
    return ply;
}

TEST(GisPly, BinaryAndAsciiReadBackAsThePointsTrianglesAndZ) {
    std::vector<Point2> pts = utm_points(200, 17);
    pts.push_back(pts[3]);  // a duplicate stays a vertex
    std::vector<double> z;
    for (const Point2& p : pts) z.push_back(std::sin(p.x) * 100 + 0.1);
    const Triangulation t = triangulated(pts);
    for (const bool binary : {true, false}) {
        for (const bool with_z : {true, false}) {
            const Ply ply = read_ply(
                written(pts, t, binary ? TriangulationFormat::ply : TriangulationFormat::ply_ascii,
                        with_z ? std::span<const double>(z) : std::span<const double>()),
                binary);
            ASSERT_EQ(ply.x.size(), pts.size());
            for (std::size_t i = 0; i < pts.size(); ++i) {
                EXPECT_EQ(ply.x[i], pts[i].x);
                EXPECT_EQ(ply.y[i], pts[i].y);
                EXPECT_EQ(ply.z[i], with_z ? z[i] : 0.0);
            }
            EXPECT_EQ(ply.faces, t.triangles);
        }
    }
}

TEST(GisVoronoi, GeojsonAndWktOfClippedCells) {
    // Four corners and a centre; a box around the lower-left corner only: the cells of the
    // far sites miss it.
    const std::vector<Point2> pts{{0, 0}, {10, 0}, {0, 10}, {10, 10}, {5, 5}, {0, 0}};
    const delaunay::Result r = delaunay::triangulate(pts, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    const delaunay::VoronoiDiagram d = delaunay::voronoi(pts, r.triangulation, AdaptiveKernel{});
    const delaunay::Box box{-1, -1, 1, 2};
    const delaunay::ClippedVoronoi c = delaunay::clip(d, pts, r.triangulation, box);
    std::ostringstream geo, wkt;
    write_voronoi(geo, pts, c, box, VoronoiFormat::geojson);
    write_voronoi(wkt, pts, c, box, VoronoiFormat::wkt);
    EXPECT_EQ(geo.str(),
              "{\"type\": \"FeatureCollection\", \"bbox\": [-1, -1, 1, 2], \"features\": [\n"
              "{\"type\": \"Feature\", \"properties\": {\"site\": 0}, \"geometry\": {\"type\": "
              "\"Polygon\", \"coordinates\": [[[-1, -1], [1, -1], [1, 2], [-1, 2], [-1, -1]]]}},\n"
              "{\"type\": \"Feature\", \"properties\": {\"site\": 1}, \"geometry\": null},\n"
              "{\"type\": \"Feature\", \"properties\": {\"site\": 2}, \"geometry\": null},\n"
              "{\"type\": \"Feature\", \"properties\": {\"site\": 3}, \"geometry\": null},\n"
              "{\"type\": \"Feature\", \"properties\": {\"site\": 4}, \"geometry\": null},\n"
              "{\"type\": \"Feature\", \"properties\": {\"site\": 5}, \"geometry\": {\"type\": "
              "\"Polygon\", \"coordinates\": [[[-1, -1], [1, -1], [1, 2], [-1, 2], [-1, -1]]]}}\n"
              "]}\n")
        << geo.str();
    EXPECT_EQ(wkt.str(),
              "GEOMETRYCOLLECTION (POLYGON ((-1 -1, 1 -1, 1 2, -1 2, -1 -1)),\nPOLYGON EMPTY,\n"
              "POLYGON EMPTY,\nPOLYGON EMPTY,\nPOLYGON EMPTY,\nPOLYGON ((-1 -1, 1 -1, 1 2, -1 2, "
              "-1 -1)))\n")
        << wkt.str();
    // The whole diagram has unbounded cells: no polygons.
    std::ostringstream whole;
    EXPECT_THROW(write_voronoi(whole, pts, d, VoronoiFormat::geojson), std::invalid_argument);
    EXPECT_THROW(write_voronoi(whole, pts, d, VoronoiFormat::wkt), std::invalid_argument);
    EXPECT_EQ(voronoi_format_from_path("a.geojson"), VoronoiFormat::geojson);
    EXPECT_EQ(voronoi_format_from_path("a.wkt"), VoronoiFormat::wkt);
    EXPECT_EQ(to_string(VoronoiFormat::wkt), "wkt");
    EXPECT_TRUE(holds_unbounded_cells(VoronoiFormat::json));
    EXPECT_FALSE(holds_unbounded_cells(VoronoiFormat::geojson));
}

TEST(GisVoronoi, DefaultClipBox) {
    const auto same = [](const delaunay::Box& a, const delaunay::Box& b) {
        return a.xmin == b.xmin && a.ymin == b.ymin && a.xmax == b.xmax && a.ymax == b.ymax;
    };
    EXPECT_TRUE(same(default_clip_box({}), {-1, -1, 1, 1}));
    EXPECT_TRUE(same(default_clip_box(std::vector<Point2>{{3, 4}, {3, 4}}), {2, 3, 4, 5}));
    EXPECT_TRUE(same(default_clip_box(std::vector<Point2>{{0, 0}, {10, 0}}), {-1, -1, 11, 1}));
    EXPECT_TRUE(
        same(default_clip_box(std::vector<Point2>{{0, 0}, {10, 5}, {4, -5}}), {-1, -6, 11, 6}));
    // A margin that vanishes next to a large coordinate still opens the box by one step.
    for (const std::vector<Point2>& pts :
         {std::vector<Point2>{{1e300, -1e300}},
          std::vector<Point2>{{1.7976931348623157e308, 1.7976931348623157e308}},
          std::vector<Point2>{{-1.7e308, 0}, {1.7e308, 1e-300}}}) {
        const delaunay::Box b = default_clip_box(pts);
        EXPECT_LT(b.xmin, b.xmax);
        EXPECT_LT(b.ymin, b.ymax);
        for (const double v : {b.xmin, b.ymin, b.xmax, b.ymax}) EXPECT_TRUE(std::isfinite(v));
        for (const Point2& p : pts) {
            EXPECT_TRUE(p.x >= b.xmin && p.x <= b.xmax && p.y >= b.ymin && p.y <= b.ymax);
        }
    }
}

// ---- z in, GeoJSON in ---------------------------------------------------------------

TEST(GisPoints, ThirdColumnIsZ) {
    std::string error;
    const std::optional<Columns> c = parse_columns("lon,lat,height", error);
    ASSERT_TRUE(c) << error;
    EXPECT_EQ(c->z, "height");
    EXPECT_FALSE(parse_columns("1,2,3,4", error));
    EXPECT_NE(error.find("two or three items"), std::string::npos) << error;
    EXPECT_FALSE(parse_columns("1,2,", error));
    EXPECT_FALSE(parse_columns("1,2,0", error));
    EXPECT_FALSE(parse_columns("1", error));
    EXPECT_FALSE(parse_columns("1,2", error)->z);
    const std::string csv =
        "id,lon,lat,height\na,2.5,48.5,35\nb,-0.125,51.5,-2e-3\nc,13,52,0x1p-2\n";
    ReadOptions options;
    options.columns = parse_columns("lon,lat,height", error);
    const PointFile f = parse_point_file(csv, PointFormat::xy, options);
    EXPECT_EQ(f.points, (std::vector<Point2>{{2.5, 48.5}, {-0.125, 51.5}, {13, 52}}));
    EXPECT_EQ(f.z, (std::vector<double>{35, -2e-3, 0.25}));
    options.columns = parse_columns("2,3,4", error);
    EXPECT_EQ(parse_point_file(csv, PointFormat::xy, options).z, f.z);
    options.columns = parse_columns("2,3", error);
    EXPECT_TRUE(parse_point_file(csv, PointFormat::xy, options).z.empty());
    // z must be a finite number, reported with its line, with any number of threads.
    options.columns = parse_columns("2,3,4", error);
    for (const char* bad : {"nan", "inf", "-Infinity", "x", "1e999"}) {
        const std::string text = csv + "d,1,2," + bad + "\n";
        for (const unsigned threads : {1u, 4u}) {
            options.threads = threads;
            try {
                parse_point_file(text, PointFormat::xy, options);
                ADD_FAILURE() << bad;
            } catch (const ReadError& e) {
                EXPECT_EQ(e.line(), 5u) << bad;
                EXPECT_EQ(e.reason().rfind("z: ", 0), 0u) << e.what();
            }
        }
    }
    options.columns = parse_columns("2,3,9", error);
    EXPECT_THROW(parse_point_file(csv, PointFormat::xy, options), ReadError);
}

PointFile geojson(std::string_view text, std::optional<std::string> z_property = std::nullopt) {
    ReadOptions options;
    options.z_property = std::move(z_property);
    return parse_point_file(text, PointFormat::geojson, options);
}

// The ReadError's line and what it says, or "" when there is none.
std::string geojson_error(std::string_view text, std::size_t& line,
                          std::optional<std::string> z_property = std::nullopt) {
    try {
        geojson(text, std::move(z_property));
    } catch (const ReadError& e) {
        line = e.line();
        return e.what();
    }
    line = 0;
    return "";
}

TEST(GisPoints, GeojsonShapes) {
    EXPECT_EQ(point_format_from_path("a/b.geojson"), PointFormat::geojson);
    EXPECT_EQ(point_format_from_name("geojson"), PointFormat::geojson);
    const std::string fc = R"({"features": [
  {"type": "Feature", "geometry": {"coordinates": [1.5, 2], "type": "Point"}, "properties": {"h": 7}},
  {"type": "Feature", "id": "x\"\u00e9", "properties": null, "geometry": null},
  {"type": "Feature", "properties": {"h": -1e-3, "name": "a \\ b"},
   "geometry": {"type": "MultiPoint", "coordinates": [[3, 4], [-0.0, 1e-310]]}},
  {"type": "Feature", "properties": {"h": 2},
   "geometry": {"type": "GeometryCollection", "geometries": [
     {"type": "Point", "coordinates": [5, 6]}, {"type": "MultiPoint", "coordinates": []}]}}
 ], "type": "FeatureCollection", "bbox": [0, 0, 1, 1]})";
    const PointFile f = geojson(fc);
    EXPECT_EQ(f.points, (std::vector<Point2>{{1.5, 2}, {3, 4}, {-0.0, 1e-310}, {5, 6}}));
    EXPECT_TRUE(std::signbit(f.points[2].x));
    EXPECT_TRUE(f.z.empty());
    EXPECT_EQ(geojson(fc, "h").z, (std::vector<double>{7, -1e-3, -1e-3, 2}));
    // z from the positions, when every one has it.
    EXPECT_EQ(geojson(R"({"type": "MultiPoint", "coordinates": [[1, 2, 3], [4, 5, -6.5]]})").z,
              (std::vector<double>{3, -6.5}));
    EXPECT_EQ(geojson(R"({"type": "Feature", "properties": {},
                          "geometry": {"type": "Point", "coordinates": [1, 2]}})")
                  .points,
              (std::vector<Point2>{{1, 2}}));
    EXPECT_TRUE(geojson("").points.empty());
    EXPECT_TRUE(geojson(R"({"type": "FeatureCollection", "features": []})").points.empty());
}

TEST(GisPoints, GeojsonErrorsNameTheLineAndTheFeature) {
    struct Case {
        std::string text;
        std::size_t line;
        std::string says;
        std::optional<std::string> z_property = std::nullopt;
    };
    const std::string two = R"({"type": "FeatureCollection", "features": [
{"type": "Feature", "properties": {"h": 1}, "geometry": {"type": "Point", "coordinates": [0, 0]}},
{"type": "Feature", "properties": {"h": "tall"},
 "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1], [0, 0]]]}}]})";
    for (const Case& c : std::vector<Case>{
             {"{\"type\": \"Point\",\n \"coordinates\": [1, 2,]}", 2, "expected a JSON value"},
             {"{\"type\": \"Point\", \"coordinates\": [1, 2]}\n\nx", 3, "after the JSON value"},
             {"[[0, 0]]", 1, "not a GeoJSON object"},
             {"{\"type\": \"Point\",\n\"coordinates\": [NaN, 2]}", 2, "NaN and Infinity"},
             {"{\"type\": \"Point\", \"coordinates\": [1e999, 2]}", 1, "x: "},
             {"{\"type\": \"Point\", \"coordinates\": [1]}", 1, "a position is [x, y]"},
             {"{\"type\": \"Point\", \"coordinates\": [1, 2, 3, 4]}", 1, "a position is [x, y]"},
             {"{\"type\": \"Point\", \"coordinates\": [1, \"2\"]}", 1, "y is a string"},
             {"{\"type\": \"MultiPoint\", \"coordinates\": [[1, 2, 3],\n[4, 5]]}", 2,
              "without z, where the earlier ones are with z"},
             {"{\"type\": \"Point\", \"coordinates\": [1, 2]", 1, "expected ',' or '}'"},
             {"{\"type\": \"Point\", \"coordinates\": [1, 2], \"x\": \"a\\qb\"}", 1,
              "unknown escape"},
             {two, 4, "feature 1: geometry type 'Polygon' is not supported"},
             {two, 3, "feature 1: property 'h' is a string, not a number", "h"},
             {two, 2, "feature 0: no property 'height'", "height"},
             {"{\"type\": \"Point\", \"coordinates\": [1, 2]}", 1, "a bare geometry", "h"},
             {"{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Point\", "
              "\"coordinates\": [1, 2]}]}",
              1, "feature 0: type 'Point', expected \"Feature\""},
             {"{\"type\": \"FeatureCollection\"}", 1, "needs a \"features\" array"},
             {std::string(300, '[') + std::string(300, ']'), 1, "nested more than"},
         }) {
        std::size_t line = 0;
        const std::string what = geojson_error(c.text, line, c.z_property);
        EXPECT_EQ(line, c.line) << c.text << "\n" << what;
        EXPECT_NE(what.find(c.says), std::string::npos) << c.text << "\n" << what;
        EXPECT_EQ(what.rfind("line " + std::to_string(c.line) + ": ", 0), 0u) << what;
    }
    ReadOptions options;
    options.z_property = "h";
    EXPECT_THROW(parse_point_file("1 2\n", PointFormat::xy, options), std::invalid_argument);
}

}  // namespace
}  // namespace exidel::io
