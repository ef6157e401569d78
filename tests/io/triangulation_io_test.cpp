// Unit tests of the triangulation writers and the json reader
// (exidel/io/triangulation.hpp). The triangulations are built by hand: these tests are
// about the formats, not about which triangulation is right.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"
#include "exidel/io/triangulation_input.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace exidel::io {
namespace {

using delaunay::Triangulation;

// The unit square split along 0-2, plus a duplicate of point 0 at index 4.
//   3 --- 2
//   |   / |
//   | /   |
//   0 --- 1
const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};

// What `exidel certify` does with a file: read it, then normalise it.
Triangulation read_triangulation(std::string_view text, ProducedFormat format,
                                 std::span<const Point2> points) {
    return delaunay::normalize(points, read_produced(text, format, points));
}

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
    EXPECT_EQ(triangulation_format_from_path("a.geojson"), TriangulationFormat::geojson);
    EXPECT_EQ(triangulation_format_from_path("a.wkt"), TriangulationFormat::wkt);
    EXPECT_EQ(triangulation_format_from_path("a.ply"), TriangulationFormat::ply);
    EXPECT_FALSE(triangulation_format_from_path("a.ply-ascii"));
    EXPECT_EQ(triangulation_format_from_name("ply-ascii"), TriangulationFormat::ply_ascii);
    EXPECT_EQ(to_string(TriangulationFormat::ply_ascii), "ply-ascii");
    for (const char* name : {"json", "ele", "off", "svg", "geojson", "wkt", "ply", "ply-ascii"}) {
        ASSERT_TRUE(triangulation_format_from_name(name)) << name;
        EXPECT_EQ(to_string(*triangulation_format_from_name(name)), name);
    }
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
    // Counted from 1, for a .node counted from 1: triangles and vertices alike.
    std::ostringstream one;
    write_triangulation(one, square, square_triangulation(), TriangulationFormat::ele,
                        WriteOptions{1});
    EXPECT_EQ(one.str(), "2 3 0\n1 1 2 3\n2 1 3 4\n");
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
    // The data's bounding box in input units, y flipped by the group, not rescaled.
    EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1000.0\" "
                       "height=\"1000.0\" viewBox=\"0 -1 1 1\">\n<g transform=\"scale(1,-1)\">"),
              std::string::npos)
        << svg;
    // The points in their own coordinates, in input order.
    EXPECT_NE(svg.find("<path d=\"M0 0 h0 M1 0 h0 M1 1 h0 M0 1 h0 M0 0 h0\"/>"), std::string::npos)
        << svg;
    // The two triangles: their union filled, their five edges in one trail; one closed hull.
    EXPECT_NE(svg.find("<g fill=\"#dde6f3\" stroke=\"none\">\n<path d=\"M0 0 L1 0 L1 1 L0 1 Z\"/>"),
              std::string::npos)
        << svg;
    EXPECT_NE(svg.find("d=\"M0 0 L1 0 L1 1 L0 0 L0 1 L1 1\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("stroke=\"#c0392b\" stroke-width=\"0.002\" stroke-linejoin=\"round\" "
                       "stroke-linecap=\"round\">\n<path d=\"M0 0 L1 0 L1 1 L0 1 Z\""),
              std::string::npos)
        << svg;
    // Stroke widths are pixels of the 1000-pixel picture in data units: 1 unit is 1000
    // pixels here.
    EXPECT_NE(svg.find("stroke=\"#3b5b92\" stroke-width=\"5e-04\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("stroke=\"#c0392b\" stroke-width=\"0.002\""), std::string::npos) << svg;
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

TEST(WriteTriangulation, SvgPathsStayShortForXmlParsers) {
    // A 60 x 60 grid: 6962 triangles and a hull of 236 vertices, drawn as the hull's fill and
    // every edge once, in trails, with paths of at most svg_path_items edges each, as
    // XML parsers limit an attribute's length.
    std::vector<Point2> grid;
    for (int i = 0; i < 60; ++i) {
        for (int j = 0; j < 60; ++j)
            grid.push_back({static_cast<double>(i), static_cast<double>(j)});
    }
    const delaunay::Result r = delaunay::triangulate(grid, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    const std::string svg = written(r.triangulation, TriangulationFormat::svg, grid);
    std::string why;
    EXPECT_TRUE(balanced_tags(svg, why)) << why;
    // The edge group's paths, read back as segments between coordinate pairs.
    const std::size_t group = svg.find("<g fill=\"none\" stroke=\"#3b5b92\"");
    ASSERT_NE(group, std::string::npos);
    const std::size_t group_end = svg.find("</g>", group);
    std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> drawn;
    std::size_t segments = 0, longest = 0;
    for (std::size_t at = svg.find("<path d=\"", group); at < group_end;
         at = svg.find("<path d=\"", at + 1)) {
        const std::size_t end = svg.find('"', at + 9);
        const std::string d = svg.substr(at + 9, end - at - 9);
        longest = std::max(longest, d.size());
        EXPECT_LE(std::count(d.begin(), d.end(), 'L'), static_cast<long>(svg_path_items));
        std::istringstream in(d);
        std::string x;  // "M0.5" or "L2": the command, glued to x
        std::pair<double, double> last{};
        while (in >> x) {
            std::pair<double, double> p;
            p.first = std::stod(x.substr(1));
            in >> p.second;
            if (x[0] == 'L') {
                drawn.insert(std::minmax(last, p));
                ++segments;
            }
            last = p;
        }
    }
    const Triangulation& t = r.triangulation;
    std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> edges;
    for (std::size_t e = 0; e < t.triangles.size(); ++e) {
        const Point2 a = grid[t.triangles[e]], b = grid[t.triangles[e % 3 == 2 ? e - 2 : e + 1]];
        edges.insert(std::minmax(std::pair{a.x, a.y}, std::pair{b.x, b.y}));
    }
    EXPECT_EQ(drawn, edges);
    EXPECT_EQ(segments, edges.size());  // each edge once
    EXPECT_LT(longest, 60 * svg_path_items);
    // The fill is the hull.
    EXPECT_NE(svg.find("<g fill=\"#dde6f3\" stroke=\"none\">\n<path d=\"M0 0 L1 0 L2 0"),
              std::string::npos);
    const std::size_t point_paths = (grid.size() + svg_path_items - 1) / svg_path_items;
    // A hull longer than one path: pieces that join end to start, covering every edge.
    Triangulation big;
    big.collinear = true;
    for (std::uint32_t i = 0; i < 2500; ++i) big.hull.push_back(i % 60);
    const std::string chain = written(big, TriangulationFormat::svg, grid);
    EXPECT_TRUE(balanced_tags(chain, why)) << why;
    std::size_t pieces = 0;
    for (std::size_t at = chain.find("<path d=\"M"); at != std::string::npos;
         at = chain.find("<path d=\"M", at + 1)) {
        ++pieces;
    }
    EXPECT_EQ(pieces, 3u + point_paths);  // 2500 hull edges in pieces of 1000, and the dots
}

TEST(WriteTriangulation, JsonIsTheSameWithThreads) {
    // More numbers than one slice of the parallel writer (2^14) in triangles and halfedges.
    std::vector<Point2> pts;
    for (int i = 0; i < 30000; ++i) pts.push_back({std::sin(i * 1.3) * i, std::cos(i * 0.7) * i});
    const delaunay::Result r = delaunay::triangulate(pts, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    ASSERT_GT(r.triangulation.triangles.size(), 1u << 17);
    std::ostringstream one;
    write_triangulation(one, pts, r.triangulation, TriangulationFormat::json);
    for (const unsigned threads : {2u, 5u}) {
        std::ostringstream many;
        write_triangulation(many, pts, r.triangulation, TriangulationFormat::json,
                            WriteOptions{0, threads});
        EXPECT_EQ(many.str(), one.str()) << threads;
    }
    const Triangulation back = parse_triangulation_json(one.str());
    EXPECT_EQ(back.triangles, r.triangulation.triangles);
    EXPECT_EQ(back.halfedges, r.triangulation.halfedges);
}

// The text formats formatted in slices on threads (json above; ele, geojson, wkt, and the
// points' xy, node and json): the same text for every thread count, across more than one
// slice of items (2^14) and of formatted positions (2^16 points), with z, negative zero
// and a point that repeats another.
TEST(WriteTriangulation, TextFormatsAreTheSameWithThreads) {
    std::vector<Point2> pts{{-0.0, 0.5}, {-0.0, 0.5}};
    std::vector<double> z{-0.0, -0.0};
    for (int i = 0; i < 70000; ++i) {
        pts.push_back({std::sin(i * 1.3) * i, std::cos(i * 0.7) * i});
        z.push_back(i * 0.25 - 3);
    }
    const delaunay::Result r = delaunay::triangulate(pts, AdaptiveKernel{});
    ASSERT_TRUE(r.ok());
    ASSERT_GT(r.triangulation.triangle_count(), 1u << 14);
    for (const TriangulationFormat f :
         {TriangulationFormat::ele, TriangulationFormat::geojson, TriangulationFormat::wkt}) {
        for (const bool with_z : {false, true}) {
            if (f == TriangulationFormat::ele && with_z) continue;
            const std::span<const double> zs =
                with_z ? std::span<const double>(z) : std::span<const double>();
            std::ostringstream one;
            write_triangulation(one, pts, r.triangulation, f, WriteOptions{1, 1, zs});
            for (const unsigned threads : {2u, 3u}) {
                std::ostringstream many;
                write_triangulation(many, pts, r.triangulation, f, WriteOptions{1, threads, zs});
                EXPECT_EQ(many.str(), one.str()) << to_string(f) << " threads " << threads;
            }
        }
    }
    // Spot checks of the text against the arrays: the last triangle's feature and polygon.
    std::ostringstream geojson, wkt;
    write_triangulation(geojson, pts, r.triangulation, TriangulationFormat::geojson,
                        WriteOptions{0, 2});
    write_triangulation(wkt, pts, r.triangulation, TriangulationFormat::wkt, WriteOptions{0, 2});
    const std::size_t last = r.triangulation.triangle_count() - 1;
    const std::uint32_t* c = r.triangulation.triangles.data() + 3 * last;
    EXPECT_NE(geojson.str().find("{\"triangle\": " + std::to_string(last) + ", \"vertices\": [" +
                                 std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " +
                                 std::to_string(c[2]) + "]}"),
              std::string::npos);
    EXPECT_NE(geojson.str().find("[-0.0, 0.5]"), std::string::npos);
    EXPECT_EQ(wkt.str().rfind("MULTIPOLYGON (((", 0), 0u);
    EXPECT_EQ(wkt.str().substr(wkt.str().size() - 4), ")))\n");
    for (const PointFormat f : {PointFormat::xy, PointFormat::node, PointFormat::json}) {
        std::ostringstream one, many;
        write_points(one, pts, f, 1, 1);
        write_points(many, pts, f, 1, 3);
        EXPECT_EQ(many.str(), one.str());
        const std::vector<Point2> back = parse_points(one.str(), f);
        ASSERT_EQ(back.size(), pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i) {
            EXPECT_EQ(back[i].x, pts[i].x) << i;
            EXPECT_EQ(std::signbit(back[i].x), std::signbit(pts[i].x)) << i;
            EXPECT_EQ(back[i].y, pts[i].y) << i;
        }
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

TEST(ReadTriangulation, EleAndJsonWithoutDuplicatesCertify) {
    // .ele counted from 1, read back: halfedges, hull and duplicates derived.
    std::ostringstream ele;
    write_triangulation(ele, square, square_triangulation(), TriangulationFormat::ele,
                        WriteOptions{1});
    Triangulation t = read_triangulation(ele.str(), ProducedFormat::ele, square);
    EXPECT_EQ(t.triangles, square_triangulation().triangles);
    EXPECT_EQ(t.halfedges, square_triangulation().halfedges);
    EXPECT_EQ(t.hull, square_triangulation().hull);
    EXPECT_EQ(t.duplicates, square_triangulation().duplicates);
    EXPECT_TRUE(delaunay::certify(square, t).ok());
    // delaunator's layout has no "duplicates": derived.
    t = read_triangulation(
        "{\"triangles\": [0,1,2,0,2,3], \"halfedges\": [-1,-1,3,2,-1,-1], \"hull\": [0,1,2,3]}",
        ProducedFormat::json, square);
    EXPECT_EQ(t.duplicates, square_triangulation().duplicates);
    EXPECT_TRUE(delaunay::certify(square, t).ok());
    // A wrong triangulation is read as it is and the certifier finds what is wrong: the
    // other diagonal of a square is Delaunay too, so move point 2 inward first.
    const std::vector<Point2> kite{{0, 0}, {1, 0}, {0.6, 0.6}, {0, 1}};
    t = read_triangulation("2 3 0\n0 0 1 3\n1 1 2 3\n", ProducedFormat::ele, kite);
    EXPECT_TRUE(delaunay::certify(kite, t).has(delaunay::FindingKind::not_delaunay));
    // Two triangles on top of each other: no edge has a twin, the triangles are two
    // components.
    t = read_triangulation("2 3 0\n0 0 1 2\n1 0 1 2\n", ProducedFormat::ele, square);
    EXPECT_EQ(t.halfedges, (std::vector<std::int32_t>(6, -1)));
    EXPECT_TRUE(delaunay::certify(square, t).has(delaunay::FindingKind::boundary_broken));
    // Collinear points: no triangles, the hull is their chain.
    const std::vector<Point2> line{{2, 2}, {0, 0}, {1, 1}};
    t = read_triangulation("0 3 0\n", ProducedFormat::ele, line);
    EXPECT_EQ(t.hull, (std::vector<std::uint32_t>{1, 2, 0}));
    EXPECT_TRUE(delaunay::certify(line, t).ok());

    const auto error_line = [](const std::string& text, const std::string& reason) {
        try {
            read_triangulation(text, ProducedFormat::ele, square);
        } catch (const ReadError& e) {
            EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
            return e.line();
        }
        ADD_FAILURE() << "accepted: " << text;
        return std::size_t{0};
    };
    EXPECT_EQ(error_line("2 3 0\n0 0 1 2\n", "truncated"), 2u);
    EXPECT_EQ(error_line("1 3 0\n0 0 1 5\n", "vertex"), 2u);
    EXPECT_EQ(error_line("1 4 0\n", "nodes per triangle"), 1u);
    EXPECT_EQ(error_line("# c\n1 3\n1 1 2 3\n2 1 2 3\n", "more triangle lines"), 4u);
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
