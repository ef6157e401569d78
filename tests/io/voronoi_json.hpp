// Checks shared by the Voronoi writer's tests (tests/io/voronoi_io_test.cpp) and the
// exidel voronoi command's (cli/tests/voronoi_test.cpp): the json read back with
// nlohmann-json against the diagram, and SVG documents that are whole.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "exidel/predicates/types.hpp"

namespace exidel::io_test {

inline bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Reads the json back and checks it against the diagram (a VoronoiDiagram or a
// ClippedVoronoi), array by array: the keys in their order, every coordinate bit for bit.
template <class Diagram>
void expect_voronoi_json(const std::string& text, const Diagram& d) {
    ASSERT_EQ(text.rfind("{\"vertices\": [", 0), 0u) << text;
    const nlohmann::ordered_json j = nlohmann::ordered_json::parse(text);
    ASSERT_TRUE(j.is_object());
    std::vector<std::string> keys;
    for (const auto& item : j.items()) keys.push_back(item.key());
    EXPECT_EQ(keys, (std::vector<std::string>{"vertices", "vertex_sites", "cells", "unbounded"}));
    ASSERT_EQ(j["vertices"].size(), d.vertex_count());
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        ASSERT_EQ(j["vertices"][v].size(), 2u);
        const double x = j["vertices"][v][0].template get<double>();
        const double y = j["vertices"][v][1].template get<double>();
        EXPECT_TRUE(same_bits(x, d.vertices[v].x)) << v << ": " << x << " vs " << d.vertices[v].x;
        EXPECT_TRUE(same_bits(y, d.vertices[v].y)) << v << ": " << y << " vs " << d.vertices[v].y;
        const auto sites = d.vertex_sites(v);
        EXPECT_EQ(j["vertex_sites"][v].template get<std::vector<std::uint32_t>>(),
                  std::vector<std::uint32_t>(sites.begin(), sites.end()));
    }
    ASSERT_EQ(j["vertex_sites"].size(), d.vertex_count());
    ASSERT_EQ(j["cells"].size(), d.site_count());
    ASSERT_EQ(j["unbounded"].size(), d.site_count());
    for (std::size_t i = 0; i < d.site_count(); ++i) {
        const auto c = d.cell(i);
        EXPECT_EQ(j["cells"][i].template get<std::vector<std::uint32_t>>(),
                  std::vector<std::uint32_t>(c.begin(), c.end()));
        EXPECT_EQ(j["unbounded"][i].template get<bool>(), d.unbounded[i] != 0);
    }
}

// A whole SVG document: the XML declaration, one svg element, balanced groups, only
// finite numbers.
inline void expect_whole_svg(const std::string& svg) {
    ASSERT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0), 0u) << svg;
    ASSERT_GE(svg.size(), 7u);
    EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
    std::size_t open = 0, close = 0;
    for (std::size_t p = 0; (p = svg.find("<g ", p)) != std::string::npos; ++p) ++open;
    for (std::size_t p = 0; (p = svg.find("</g>", p)) != std::string::npos; ++p) ++close;
    EXPECT_EQ(open, close);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_EQ(svg.find("inf"), std::string::npos);
    // Paths' quotes are balanced (every attribute closed).
    EXPECT_EQ(std::count(svg.begin(), svg.end(), '"') % 2, 0);
}

// The 12 lattice points of x^2 + y^2 = 25.
inline std::vector<Point2> lattice_circle() {
    return {{3, 4}, {-4, 3}, {-3, -4}, {4, -3}, {5, 0},  {0, -5},
            {0, 5}, {-5, 0}, {4, 3},   {-3, 4}, {3, -4}, {-4, -3}};
}

}  // namespace exidel::io_test
