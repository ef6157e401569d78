// Unit tests of the triangulation writers and the json reader
// (exidel/io/triangulation.hpp). The triangulations are built by hand: these tests are
// about the formats, not about which triangulation is right.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"

namespace exidel::io {
namespace {

using delaunay::Triangulation;

// The unit square split along 0-2, plus a duplicate of point 0 at index 4.
//   3 --- 2
//   |   / |
//   | /   |
//   0 --- 1
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

std::string written(const Triangulation& t, TriangulationFormat f,
                    const std::vector<Point2>& pts = square) {
    std::ostringstream out;
    write_triangulation(out, pts, t, f);
    return out.str();
}

TEST(TriangulationFormats, NamesAndExtensions) {
    EXPECT_EQ(triangulation_format_from_path("out/a.svg"), TriangulationFormat::svg);
    EXPECT_EQ(triangulation_format_from_path("a.b.ele"), TriangulationFormat::ele);
    EXPECT_EQ(triangulation_format_from_path("a.off"), TriangulationFormat::off);
    EXPECT_EQ(triangulation_format_from_path("a.json"), TriangulationFormat::json);
    EXPECT_FALSE(triangulation_format_from_path("a.txt"));
    EXPECT_FALSE(triangulation_format_from_path("dir.svg/a"));
    EXPECT_FALSE(triangulation_format_from_name("png"));
}

TEST(WriteTriangulation, HandTriangulationCertifies) {
    // Guards the fixture itself: the other tests rely on it being a valid answer.
    EXPECT_TRUE(delaunay::certify(square, square_triangulation()).ok());
}

TEST(WriteTriangulation, Json) {
    EXPECT_EQ(written(square_triangulation(), TriangulationFormat::json),
              "{\"triangles\": [0,1,2,0,2,3],\n"
              " \"halfedges\": [-1,-1,3,2,-1,-1],\n"
              " \"hull\": [0,1,2,3],\n"
              " \"duplicates\": [4]}\n");
    EXPECT_EQ(written(Triangulation{}, TriangulationFormat::json, {}),
              "{\"triangles\": [],\n \"halfedges\": [],\n \"hull\": [],\n \"duplicates\": []}\n");
}

TEST(WriteTriangulation, EleAndOff) {
    EXPECT_EQ(written(square_triangulation(), TriangulationFormat::ele),
              "2 3 0\n0 0 1 2\n1 0 2 3\n");
    EXPECT_EQ(written(square_triangulation(), TriangulationFormat::off),
              "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0\n3 0 1 2\n3 0 2 3\n");
}

// Well-formed enough for a browser: one root, every element closed in order.
bool balanced_tags(const std::string& svg, std::string& why) {
    std::vector<std::string> open;
    for (std::size_t i = svg.find('<'); i != std::string::npos; i = svg.find('<', i + 1)) {
        const std::size_t end = svg.find('>', i);
        if (end == std::string::npos) return why = "unterminated tag", false;
        const std::string tag = svg.substr(i + 1, end - i - 1);
        if (tag.starts_with("?") || tag.starts_with("!--")) continue;
        if (tag.starts_with("/")) {
            if (open.empty() || open.back() != tag.substr(1)) return why = "bad </" + tag, false;
            open.pop_back();
            if (open.empty() && svg.find('<', end) != std::string::npos) {
                return why = "content after the root", false;
            }
        } else if (!tag.ends_with("/")) {
            open.push_back(tag.substr(0, tag.find(' ')));
        }
    }
    return why = "unclosed", open.empty();
}

TEST(WriteTriangulation, SvgIsWellFormedWithYUp) {
    const std::string svg = written(square_triangulation(), TriangulationFormat::svg);
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    std::string why;
    EXPECT_TRUE(balanced_tags(svg, why)) << why << "\n" << svg;
    EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-20 -20 1040.000 "
                       "1040.000\">"),
              std::string::npos)
        << svg;
    // (0, 0) is at the bottom of the picture, (0, 1) at the top.
    EXPECT_NE(svg.find("<circle cx=\"0.000\" cy=\"1000.000\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("<circle cx=\"0.000\" cy=\"0.000\""), std::string::npos) << svg;
    // Two triangles, one closed hull.
    EXPECT_NE(svg.find("d=\"M0.000 1000.000 L1000.000 1000.000 L1000.000 0.000 Z M"),
              std::string::npos);
    EXPECT_NE(svg.find("L0.000 0.000 Z\"/>"), std::string::npos);
    // Degenerate pictures are still well-formed: nothing, one point, huge coordinates.
    for (const std::vector<Point2>& pts :
         {std::vector<Point2>{}, std::vector<Point2>{{3, 4}},
          std::vector<Point2>{{-1.7e308, 0}, {1.7e308, 1e308}, {0, -1e308}}}) {
        const delaunay::Result r = delaunay::triangulate(pts, GmpExactKernel{});
        ASSERT_TRUE(r.ok());
        const std::string s = written(r.triangulation, TriangulationFormat::svg, pts);
        EXPECT_TRUE(balanced_tags(s, why)) << why << "\n" << s;
        EXPECT_EQ(s.find("nan"), std::string::npos) << s;
        EXPECT_EQ(s.find("inf"), std::string::npos) << s;
    }
}

TEST(ParseTriangulationJson, RoundTripAndCertify) {
    const std::string json = written(square_triangulation(), TriangulationFormat::json);
    Triangulation t = parse_triangulation_json(json);
    EXPECT_EQ(t.triangles, square_triangulation().triangles);
    EXPECT_EQ(t.halfedges, square_triangulation().halfedges);
    EXPECT_EQ(t.hull, square_triangulation().hull);
    EXPECT_EQ(t.duplicates, square_triangulation().duplicates);
    EXPECT_FALSE(t.collinear);
    EXPECT_TRUE(t.vertex_of_input.empty());
    fill_vertex_of_input(square, t);
    EXPECT_EQ(t.vertex_of_input, square_triangulation().vertex_of_input);
    EXPECT_TRUE(delaunay::certify(square, t).ok());
    // Keys in another order, other spacing.
    t = parse_triangulation_json(
        "{ \"hull\":[0,1],\"duplicates\":[ ],\"halfedges\":[],\"triangles\":[] }");
    EXPECT_TRUE(t.collinear);
    EXPECT_EQ(t.hull, (std::vector<std::uint32_t>{0, 1}));
}

TEST(ParseTriangulationJson, ErrorsNameTheLine) {
    const auto line_of = [](const std::string& text, const std::string& reason) {
        try {
            parse_triangulation_json(text);
        } catch (const ReadError& e) {
            EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
            return e.line();
        }
        ADD_FAILURE() << "accepted: " << text;
        return std::size_t{0};
    };
    const std::string ok_tail = ",\n \"hull\": [],\n \"duplicates\": []}";
    EXPECT_EQ(line_of("{\"triangles\": [],\n \"halfedges\": [-2]" + ok_tail, "out of range"), 2u);
    EXPECT_EQ(line_of("{\"triangles\": [],\n \"halfedges\": [1.5]" + ok_tail, "or ','"), 2u);
    EXPECT_EQ(line_of("{\"triangles\": [],\n \"halfedges\": []" + ok_tail + "x", "after the"), 4u);
    EXPECT_EQ(line_of("{\"triangles\": [],\n \"hull\": [],\n \"duplicates\": []}", "missing"), 3u);
    EXPECT_EQ(line_of("{\"triangles\": [],\n\"triangles\": []}", "appears twice"), 2u);
    EXPECT_EQ(line_of("{\"points\": []}", "unknown key"), 1u);
    EXPECT_EQ(line_of("{\"triangles\": [0,\n", "the end of the input"), 2u);
}

}  // namespace
}  // namespace exidel::io
