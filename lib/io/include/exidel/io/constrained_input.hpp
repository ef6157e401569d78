// exidel I/O: reading a constrained triangulation that a triangulator wrote, for the
// constrained certifier (exidel certify --constraints). The result holds every vertex (the
// input points, then the points the triangulator added) and what the file says about the
// triangles over them; the CLI rebuilds a delaunay::ConstrainedTriangulation from it.
//
//   json  exidel's constrained json (exidel/io/constrained.hpp): {"triangles", "halfedges",
//         "region", "constraints", "chain_offsets", "chain_vertices", "added_points",
//         "crossings", "duplicates"}, keys in any order, nothing else; "triangles",
//         "chain_offsets", "chain_vertices", "added_points" and "crossings" required. The
//         vertices are the input points followed by "added_points". Recognised by its
//         "added_points" or "chain_offsets" key (is_constrained_json).
//   off   OFF ("OFF", counts, vertex lines "x y [z]", faces "3 a b c"): every vertex of the
//         triangulation. A vertex with the exact coordinates of an input point is that
//         point (its first occurrence); the others are the added points, numbered after
//         the input in the order of their first vertex line.
// Triangle's .ele is read by read_produced (triangulation_input.hpp) over the points of
// the .node beside it. Malformed text: ReadError with its line.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "exidel/delaunay/certify.hpp"
#include "exidel/io/points.hpp"  // ReadError
#include "exidel/predicates/types.hpp"

namespace exidel::io {

struct ProducedConstrained {
    /// Every vertex: the input points, then the added points.
    std::vector<Point2> points;
    /// The triangles over `points` (and, from json, halfedges and duplicates).
    delaunay::ProducedTriangulation mesh;
    /// json only: each triangle's region, the pieces, the chains, each added point's two
    /// segments (pairs from the flat arrays).
    std::optional<std::vector<std::uint32_t>> region;
    std::optional<std::vector<std::array<std::uint32_t, 2>>> constraints;
    std::optional<std::vector<std::uint32_t>> chain_offsets;
    std::optional<std::vector<std::uint32_t>> chain_vertices;
    std::optional<std::vector<std::array<std::uint32_t, 2>>> crossings;
};

/// Whether `text` looks like exidel's constrained json: it holds the key "added_points" or
/// "chain_offsets".
bool is_constrained_json(std::string_view text);

/// Parses exidel's constrained json; `input` are the input points of the run.
ProducedConstrained read_constrained_json(std::string_view text, std::span<const Point2> input);

/// Parses an OFF of every vertex (above); `input` are the input points of the run.
/// Defined in triangulation_input.cpp, next to the OFF reader it shares.
ProducedConstrained read_constrained_off(std::string_view text, std::span<const Point2> input);

}  // namespace exidel::io
