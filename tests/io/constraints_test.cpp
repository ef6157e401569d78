// Triangle's .poly reader (exidel/io/constraints.hpp): every section, both index bases, markers,
// regions, and an error with its line for each way a file can be malformed or truncated.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/io/points.hpp"
#include "exidel/io/constraints.hpp"

namespace exidel::io {
namespace {

// A square with a square hole, numbered from 1, with markers and two regions.
constexpr const char* square_with_hole = R"(# outer square and a hole
8 2 1 1
1 0 0 0.5 1
2 4 0 0.5 1
3 4 4 0.5 1
4 0 4 0.5 1
5 1 1 0 2
6 3 1 0 2
7 3 3 0 2
8 1 3 0 2
8 1
1 1 2 1
2 2 3 1
3 3 4 1
4 4 1 1
5 5 6 2
6 6 7 2
7 7 8 2
8 8 5 2

1
1 2 2
2
1 0.5 0.5 10 -1
2 3.5 3.5 20 0x1p-2
)";

TEST(Poly, ReadsEverySection) {
    const ConstraintFile p = parse_poly(square_with_hole);
    ASSERT_EQ(p.points.size(), 8u);
    EXPECT_EQ(p.index_base, 1u);
    EXPECT_EQ(p.points[5], (Point2{3, 1}));
    ASSERT_EQ(p.segments.size(), 8u);
    EXPECT_EQ(p.segments[0], (std::array<std::uint32_t, 2>{0, 1}));
    EXPECT_EQ(p.segments[7], (std::array<std::uint32_t, 2>{7, 4}));
    EXPECT_EQ(p.segment_markers, (std::vector<std::int32_t>{1, 1, 1, 1, 2, 2, 2, 2}));
    EXPECT_EQ(p.holes, (std::vector<Point2>{{2, 2}}));
    ASSERT_EQ(p.regions.size(), 2u);
    EXPECT_EQ(p.regions[0].seed, (Point2{0.5, 0.5}));
    EXPECT_EQ(p.regions[0].attribute, 10);
    EXPECT_FALSE(p.regions[0].max_area.has_value());
    EXPECT_EQ(p.regions[1].max_area, 0.25);
}

TEST(Poly, ZeroBasedWithoutMarkersOrRegions) {
    const ConstraintFile p =
        parse_poly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n2 2 0\n0\n");
    EXPECT_EQ(p.index_base, 0u);
    EXPECT_EQ(p.segments.size(), 3u);
    EXPECT_TRUE(p.segment_markers.empty());
    EXPECT_TRUE(p.holes.empty());
    EXPECT_TRUE(p.regions.empty());
    // No segments at all is a point set.
    EXPECT_TRUE(parse_poly("2\n0 0 0\n1 1 1\n0\n0\n").segments.empty());
}

void expect_error(const std::string& text, std::size_t line, const std::string& reason) {
    try {
        parse_poly(text);
        ADD_FAILURE() << "no error for:\n" << text;
    } catch (const ReadError& e) {
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    }
}

TEST(Poly, MalformedFilesNameTheLine) {
    const std::string points = "3\n0 0 0\n1 1 0\n2 0 1\n";
    expect_error("", 1, "empty .poly file");
    expect_error("0 2 0 0\n", 1, "separate .node file");
    expect_error("3\n0 0 0\n1 1 0\n", 3, "truncated: the file ends after 2 of the 3 vertices");
    expect_error(points, 4, "no segments header");
    expect_error(points + "2\n0 0 1\n", 6, "after 1 of the 2 segments");
    expect_error(points + "1\n0 0 3\n0\n", 6, "segment endpoint 3 is outside [0, 2]");
    expect_error(points + "1\n0 0 1 5\n0\n", 6, "expected 3 fields");
    expect_error(points + "2\n0 0 1\n2 1 2\n0\n", 7, "segment index 2, expected 1");
    expect_error(points + "1 1\n0 0 1\n0\n", 6, "expected 4 fields");
    expect_error(points + "1\n0 0 1\n", 6, "no holes header");
    expect_error(points + "1\n0 0 1\n1\n0 nan 0\n", 8, "x:");
    expect_error(points + "1\n0 0 1\n1\n", 7, "after 0 of the 1 holes");
    expect_error(points + "0\n0\n1\n0 1 1\n", 8, "expected 4 or 5 fields");
    expect_error(points + "0\n0\n2\n0 1 1 3\n", 8, "after 1 of the 2 regions");
    expect_error(points + "0\n0\n0\n7\n", 8, "unexpected line after the regions");
    expect_error(points + "0 2\n", 5, "markers 2 is outside [0, 1]");
}

// ---- GeoJSON --------------------------------------------------------------------------------

TEST(GeoJsonConstraints, PolygonWithAHoleLineAndPoints) {
    const ConstraintFile f =
        parse_geojson_constraints(R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [
    [[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]],
    [[1, 1], [1, 3], [3, 3], [3, 1], [1, 1]]]}},
  {"type": "Feature", "properties": null, "geometry": {"type": "LineString",
    "coordinates": [[5, 0], [6, 1], [7, 0]]}},
  {"type": "Feature", "geometry": null, "properties": {}},
  {"type": "Feature", "properties": {}, "geometry": {"type": "GeometryCollection", "geometries": [
    {"type": "MultiPoint", "coordinates": [[9, 9], [8, 8]]},
    {"type": "MultiPolygon", "coordinates": [[[[10, 0], [11, 0], [10, 1], [10, 0]]]]}]}}
]})");
    ASSERT_EQ(f.points.size(), 4u + 4u + 3u + 2u + 3u);
    EXPECT_EQ(f.points[4], (Point2{1, 1}));
    const std::vector<std::array<std::uint32_t, 2>> want{
        {0, 1}, {1, 2}, {2, 3},  {3, 0},   {4, 5},   {5, 6},  {6, 7},
        {7, 4}, {8, 9}, {9, 10}, {13, 14}, {14, 15}, {15, 13}};
    EXPECT_EQ(f.segments, want);
    EXPECT_TRUE(f.z.empty());
}

TEST(GeoJsonConstraints, ZAndEmptyInput) {
    const ConstraintFile f = parse_geojson_constraints(
        R"({"type": "LineString", "coordinates": [[0, 0, 5], [1, 0, 6]]})");
    EXPECT_EQ(f.z, (std::vector<double>{5, 6}));
    EXPECT_EQ(f.segments.size(), 1u);
    EXPECT_TRUE(parse_geojson_constraints(" \n").points.empty());
}

void expect_geojson_error(const std::string& text, std::size_t line, const std::string& reason) {
    try {
        parse_geojson_constraints(text);
        ADD_FAILURE() << "no error for:\n" << text;
    } catch (const ReadError& e) {
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    }
}

TEST(GeoJsonConstraints, MalformedGeometriesNameTheLine) {
    expect_geojson_error(
        "{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0], [1, 0], [0, 1], [0, 2]]]}", 2,
        "must end where it starts");
    expect_geojson_error("{\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [0, 0]]]}", 1,
                         "at least 4 positions");
    expect_geojson_error("{\"type\": \"LineString\", \"coordinates\": [[0, 0]]}", 1,
                         "at least 2 positions");
    expect_geojson_error("{\"type\": \"LineString\"}", 1, "needs \"coordinates\"");
    expect_geojson_error("{\"type\": \"MultiLineString\", \"coordinates\": [7]}", 1,
                         "a LineString is an array of positions");
    expect_geojson_error("{\"type\": \"Polygon\", \"coordinates\": 3}", 1, "not an array");
    expect_geojson_error("{\"type\": \"Circle\", \"coordinates\": []}", 1,
                         "geometry type 'Circle' is not supported");
    expect_geojson_error("{\"type\": \"LineString\", \"coordinates\": [[0, 0], [1, 0, 2]]}", 1,
                         "with z");
    expect_geojson_error("{\"type\": \"LineString\",\n\"coordinates\": [[0, 0], [1e999, 0]]}", 2,
                         "x:");
}

TEST(JsonConstraints, ObjectArrayAndKeysInAnyOrder) {
    const ConstraintFile f = parse_json_constraints(
        "{\"segments\": [[0, 1], [1, 2]],\n \"holes\": [[0.25, 0.25]],\n"
        " \"points\": [[0, 0], [1, 0], [0, 1e-3]]}");
    ASSERT_EQ(f.points.size(), 3u);
    EXPECT_EQ(f.points[2].y, 1e-3);
    ASSERT_EQ(f.segments.size(), 2u);
    EXPECT_EQ(f.segments[1], (std::array<std::uint32_t, 2>{1, 2}));
    ASSERT_EQ(f.holes.size(), 1u);
    EXPECT_EQ(f.holes[0].x, 0.25);
    // A bare array is points without segments; empty input is nothing.
    EXPECT_EQ(parse_json_constraints("[[0, 0], [1, 1]]").points.size(), 2u);
    EXPECT_TRUE(parse_json_constraints(" \n").points.empty());
    EXPECT_TRUE(parse_json_constraints("{\"points\": []}").segments.empty());
}

TEST(JsonConstraints, MalformedInputNamesTheLine) {
    const auto reason = [](const std::string& text) {
        try {
            parse_json_constraints(text);
        } catch (const ReadError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(reason("{\"points\": [[0, 0]],\n \"segments\": [[0, 1]]}"),
              "line 2: segment 0 names point 1, but there are 1 points");
    EXPECT_EQ(reason("{\"points\": [], \"points\": []}"),
              "line 1: the key \"points\" appears twice");
    EXPECT_EQ(reason("{\"segments\": []}"), "line 1: the object has no \"points\"");
    EXPECT_NE(reason("{\"points\": [],\n\"edges\": []}").find("line 2: unknown key \"edges\""),
              std::string::npos);
    EXPECT_NE(reason("{\"points\": [[0, 0]], \"segments\": [[0, 0, 0]]}").find("third index"),
              std::string::npos);
    EXPECT_NE(reason("{\"points\": [[0, 0]], \"segments\": [[-1, 0]]}").find("out of range"),
              std::string::npos);
    EXPECT_NE(reason("{\"points\": [[0, NaN]]}").find("not a finite number"), std::string::npos);
    EXPECT_NE(reason("{\"points\": []} x").find("after the closing '}'"), std::string::npos);
    EXPECT_NE(reason("{\"points\": [[0, 0]").find("line 1:"), std::string::npos);
}

TEST(JsonConstraints, EveryFormatWithSegmentsAndPolyAsPoints) {
    const std::string poly = "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 1\n0\n";
    EXPECT_EQ(parse_constraint_file(poly, PointFormat::poly).segments.size(), 1u);
    EXPECT_EQ(parse_constraint_file("\xEF\xBB\xBF[[0, 0]]", PointFormat::json).points.size(), 1u);
    EXPECT_THROW(parse_constraint_file("0 0\n", PointFormat::xy), std::invalid_argument);
    EXPECT_EQ(point_format_from_path("a/b.poly"), PointFormat::poly);
    EXPECT_EQ(point_format_from_name("poly"), PointFormat::poly);
    const PointFile points = parse_point_file(poly, PointFormat::poly);
    EXPECT_EQ(points.points.size(), 3u);
    EXPECT_EQ(points.index_base, 0u);
}

}  // namespace
}  // namespace exidel::io
