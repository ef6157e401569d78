// End-to-end tests of the GIS side of `exidel triangulate`: z from a third column into
// OFF, PLY, GeoJSON and WKT; GeoJSON point input (a round trip against xy input, every
// error with its line and feature); the output formats by extension and by name.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "exidel/io/points.hpp"
#include "run_binary.hpp"

namespace {

using exidel::Point2;
namespace io = exidel::io;

using namespace exidel::cli_test;

RunResult run(const std::string& args, const std::string& input = "") {
    return run_exidel("gis", "triangulate " + args, input);
}

struct Sample {
    std::vector<Point2> points;
    std::vector<double> z;
};

// Seeded UTM-like points with heights, and a duplicate (index 40 repeats 5).
Sample sample() {
    Sample s;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0, 500);
    for (int i = 0; i < 40; ++i) {
        s.points.push_back({500000 + u(rng), 4000000 + u(rng)});
        s.z.push_back(u(rng) / 7 - 20);
    }
    s.points.push_back(s.points[5]);
    s.z.push_back(s.z[5]);
    return s;
}

// A CSV with a header and x, y, z as its first three columns (and a label after).
std::string csv(const Sample& s) {
    std::ostringstream out;
    out.precision(17);
    out << "x,y,height,label\n";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        out << s.points[i].x << ',' << s.points[i].y << ',' << s.z[i] << ",p" << i << '\n';
    }
    return out.str();
}

std::vector<double> read_doubles(std::istream& in, std::size_t n) {
    std::vector<double> v(n);
    for (double& x : v) {
        std::string word;
        in >> word;
        x = std::stod(word);
    }
    return v;
}

TEST(ExidelGis, ThirdColumnIsZInOffPlyGeojsonAndWkt) {
    const Sample s = sample();
    // The values as the reader rounds them from the CSV's 17 digits: exactly s.z.
    const std::string in = write_file("gis-z.csv", csv(s));
    const std::string json = run("-q -i " + in + " --columns 1,2").out;
    const std::vector<std::uint32_t> triangles =
        nlohmann::json::parse(json)["triangles"].get<std::vector<std::uint32_t>>();
    ASSERT_FALSE(triangles.empty());
    // OFF: "x y z" per input point.
    const RunResult off = run("-q -i " + in + " --columns 1,2,3 -f off");
    ASSERT_EQ(off.status, 0) << off.err;
    std::istringstream o(off.out);
    std::string magic;
    std::size_t nv = 0, nf = 0, ne = 0;
    o >> magic >> nv >> nf >> ne;
    ASSERT_EQ(nv, s.points.size());
    EXPECT_EQ(nf, triangles.size() / 3);
    for (std::size_t i = 0; i < nv; ++i) {
        const std::vector<double> xyz = read_doubles(o, 3);
        EXPECT_EQ(xyz[0], s.points[i].x);
        EXPECT_EQ(xyz[1], s.points[i].y);
        EXPECT_EQ(xyz[2], s.z[i]) << i;
    }
    // Binary PLY: the vertex block after the header.
    const std::string ply_path = work_path("gis-z.ply");
    std::remove(ply_path.c_str());
    ASSERT_EQ(run("-q -i " + in + " --columns x,y,height -o " + ply_path).status, 0);
    const std::string ply = slurp(ply_path);
    ASSERT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
    const std::size_t body = ply.find("end_header\n") + 11;
    ASSERT_EQ(ply.size() - body, 24 * nv + 13 * nf);
    for (std::size_t i = 0; i < nv; ++i) {
        std::uint64_t bits = 0;
        for (int b = 7; b >= 0; --b) {
            bits = bits << 8 | static_cast<unsigned char>(ply[body + 24 * i + 16 + b]);
        }
        EXPECT_EQ(std::bit_cast<double>(bits), s.z[i]) << i;
    }
    // GeoJSON: [x, y, z] positions, z of the vertex the property names.
    const RunResult geo = run("-q -i " + in + " --columns 1,2,3 -f geojson");
    ASSERT_EQ(geo.status, 0) << geo.err;
    const nlohmann::json g = nlohmann::json::parse(geo.out);
    ASSERT_EQ(g["features"].size(), nf + 1);
    for (std::size_t t = 0; t < nf; ++t) {
        const auto& f = g["features"][t];
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t v = f["properties"]["vertices"][k];
            EXPECT_EQ(v, triangles[3 * t + k]);
            EXPECT_EQ(f["geometry"]["coordinates"][0][k][2].get<double>(), s.z[v]);
        }
    }
    // WKT: MULTIPOLYGON Z.
    const RunResult wkt = run("-q -i " + in + " --columns 1,2,3 -f wkt");
    EXPECT_EQ(wkt.out.rfind("MULTIPOLYGON Z (((", 0), 0u) << wkt.out.substr(0, 100);
    // Without z: z = 0 in OFF, 2D positions in GeoJSON.
    EXPECT_NE(run("-q -i " + in + " --columns 1,2 -f off").out.find(" 0\n"), std::string::npos);
    EXPECT_EQ(run("-q -i " + in + " --columns 1,2 -f wkt").out.rfind("MULTIPOLYGON (((", 0), 0u);
}

TEST(ExidelGis, NonFiniteZIsAnErrorWithItsLine) {
    for (const char* bad : {"nan", "inf", "-inf", "", "high"}) {
        const std::string in =
            write_file("gis-nan.csv", std::string("x,y,z\n0,0,1\n1,0,2\n0,1,") + bad + "\n");
        const std::string out = work_path("gis-nan.off");
        std::remove(out.c_str());
        const RunResult r = run("-i " + in + " --columns 1,2,3 -o " + out);
        EXPECT_EQ(r.status, 1) << bad;
        EXPECT_EQ(r.err.rfind("exidel: line 4: ", 0), 0u) << bad << ": " << r.err;
        EXPECT_FALSE(exists(out)) << bad;
    }
    EXPECT_EQ(run("--columns 1,2,3,4", "0 0 0 0\n").status, 2);
}

// The points as a GeoJSON FeatureCollection: a Point feature each, in order, with the z
// both as a third coordinate and as a property; a null-geometry feature in between.
std::string geojson(const Sample& s) {
    std::ostringstream out;
    out.precision(17);
    out << "{\"type\": \"FeatureCollection\",\n \"features\": [\n";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        out << (i ? ",\n" : "") << "  {\"type\": \"Feature\", \"properties\": {\"elev\": " << s.z[i]
            << ", \"name\": \"p\\u00e9" << i << "\"},\n   \"geometry\": {\"coordinates\": ["
            << s.points[i].x << ", " << s.points[i].y << ", " << s.z[i]
            << "], \"type\": \"Point\"}}";
        if (i == 3) out << ",\n  {\"type\": \"Feature\", \"properties\": null, \"geometry\": null}";
    }
    out << "\n]}\n";
    return out.str();
}

TEST(ExidelGis, GeojsonPointsGiveTheTrianglesOfTheXyInput) {
    const Sample s = sample();
    std::ostringstream xy;
    io::write_points(xy, s.points, io::PointFormat::xy);
    const RunResult from_xy = run("-q", xy.str());
    ASSERT_EQ(from_xy.status, 0) << from_xy.err;
    const std::string in = write_file("gis-points.geojson", geojson(s));
    const RunResult from_geojson = run("-q -i " + in);  // the extension says geojson
    ASSERT_EQ(from_geojson.status, 0) << from_geojson.err;
    EXPECT_EQ(from_geojson.out, from_xy.out);
    EXPECT_EQ(run("-q --input-format geojson", geojson(s)).out, from_xy.out);
    // z from the positions, or from a property: the same OFF.
    const RunResult off = run("-q -i " + in + " -f off");
    const RunResult by_property = run("-q -i " + in + " -f off --z-property elev");
    ASSERT_EQ(off.status, 0) << off.err;
    EXPECT_EQ(by_property.out, off.out);
    std::ostringstream with_z;
    with_z.precision(17);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        with_z << s.points[i].x << ' ' << s.points[i].y << ' ' << s.z[i] << '\n';
    }
    EXPECT_EQ(run("-q -f off --columns 1,2,3", with_z.str()).out, off.out);
}

TEST(ExidelGis, GeojsonErrorsExitOneWithTheLineAndTheFeature) {
    const Sample s = sample();
    const std::string good = geojson(s);
    struct Case {
        std::string text, args, says;
    };
    std::string polygon = good;
    polygon.replace(polygon.find("\"Point\"", polygon.find("\"elev\"", 200)), 7, "\"Polygon\"");
    for (const Case& c : std::vector<Case>{
             {"{\"type\": \"FeatureCollection\",\n \"features\": [\n  {\"type\": \"Feature\"\n]}",
              "", "line 4: expected ',' or '}'"},
             {polygon, "", "line 6: feature 1: geometry type 'Polygon' is not supported"},
             {good, "--z-property height", "line 3: feature 0: no property 'height'"},
             {good, "--z-property name", "line 3: feature 0: property 'name' is a string"},
             {"{\"type\": \"LineString\", \"coordinates\": [[0, 0], [1, 1]]}", "",
              "line 1: the geometry: geometry type 'LineString' is not supported"},
         }) {
        const std::string in = write_file("gis-bad.geojson", c.text);
        const std::string out = work_path("gis-bad.json");
        std::remove(out.c_str());
        const RunResult r = run("-i " + in + " -o " + out + " " + c.args);
        EXPECT_EQ(r.status, 1) << c.says << ": " << r.err;
        EXPECT_EQ(r.err.rfind("exidel: " + c.says, 0), 0u) << r.err;
        EXPECT_FALSE(exists(out));
    }
    // --z-property is for geojson input only.
    const RunResult xy = run("--z-property h", "0 0\n1 0\n0 1\n");
    EXPECT_EQ(xy.status, 2);
    EXPECT_NE(xy.err.find("--z-property applies to geojson input"), std::string::npos) << xy.err;
}

TEST(ExidelGis, FormatsByExtensionAndName) {
    const std::string in = write_file("gis-fmt.xy", "0 0\n4 0\n0 3\n4 3\n2 1\n");
    const RunResult help = run("--help");
    for (const char* text :
         {"geojson", "wkt", "ply-ascii", "--z-property", "X,Y[,Z]", "as a plane"}) {
        EXPECT_NE(help.out.find(text), std::string::npos) << text;
    }
    for (const char* ext : {"geojson", "wkt", "ply"}) {
        const std::string out = work_path(std::string("gis-fmt.") + ext);
        ASSERT_EQ(run("-q -i " + in + " -o " + out).status, 0) << ext;
        EXPECT_EQ(slurp(out), run("-q -i " + in + " -f " + ext).out) << ext;
    }
    const RunResult ascii = run("-q -i " + in + " -f ply-ascii");
    EXPECT_EQ(ascii.out.rfind("ply\nformat ascii 1.0\n", 0), 0u) << ascii.out;
    EXPECT_NE(ascii.out.find("end_header\n0 0 0\n4 0 0\n"), std::string::npos) << ascii.out;
    EXPECT_EQ(run("-i " + in + " -f shp").status, 2);
}

}  // namespace
