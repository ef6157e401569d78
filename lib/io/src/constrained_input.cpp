// exidel I/O: exidel's constrained json read back (exidel/io/constrained_input.hpp).
#include "exidel/io/constrained_input.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "json.hpp"

namespace exidel::io {

namespace {

constexpr std::int64_t max_u32 = 0xffffffff, max_i32 = 0x7fffffff;

// A flat array of pairs [a0, b0, a1, b1, ...].
std::vector<std::array<std::uint32_t, 2>> pairs(detail::JsonCursor& j, std::string_view key) {
    const std::size_t line = j.line();
    const std::vector<std::uint32_t> flat =
        detail::integer_array<std::uint32_t>(j, key, 0, max_u32);
    if (flat.size() % 2 != 0) {
        throw ReadError::at_line(line, "\"" + std::string(key) + "\" holds " +
                                           std::to_string(flat.size()) +
                                           " numbers: flat pairs need an even count");
    }
    std::vector<std::array<std::uint32_t, 2>> v(flat.size() / 2);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = {flat[2 * i], flat[2 * i + 1]};
    return v;
}

std::vector<Point2> points(detail::JsonCursor& j) {
    std::vector<Point2> v;
    j.expect('[', "to open the array \"added_points\"");
    if (j.accept(']')) return v;
    do {
        j.expect('[', "to open an added point [x, y]");
        const double x = j.number("x");
        j.expect(',', "between an added point's x and y");
        const double y = j.number("y");
        j.expect(']', "after an added point's x and y");
        v.push_back({x, y});
    } while (j.accept(','));
    j.expect(']', "or ',' in the array \"added_points\"");
    return v;
}

}  // namespace

bool is_constrained_json(std::string_view text) {
    return text.find("\"added_points\"") != std::string_view::npos ||
           text.find("\"chain_offsets\"") != std::string_view::npos;
}

ProducedConstrained read_constrained_json(std::string_view text, std::span<const Point2> input) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    detail::JsonCursor j(text);
    ProducedConstrained p;
    constexpr std::string_view keys[] = {"triangles",    "chain_offsets", "chain_vertices",
                                         "added_points", "crossings",     "halfedges",
                                         "region",       "constraints",   "duplicates"};
    constexpr std::size_t required = 5, known = std::size(keys);
    bool seen[known] = {};
    std::vector<Point2> added;
    j.expect('{', "to open exidel's constrained json object");
    do {
        const std::string_view key = j.key();
        const auto k = static_cast<std::size_t>(std::find(keys, keys + known, key) - keys);
        if (k == known) {
            j.fail("unknown key \"" + std::string(key) +
                   "\" (exidel's constrained json has triangles, halfedges, region, constraints, "
                   "chain_offsets, chain_vertices, added_points, crossings, duplicates)");
        }
        if (seen[k]) j.fail("key \"" + std::string(key) + "\" appears twice");
        seen[k] = true;
        j.expect(':', "after the key");
        switch (k) {
            case 0:
                p.mesh.triangles = detail::integer_array<std::uint32_t>(j, key, 0, max_u32);
                break;
            case 1:
                p.chain_offsets = detail::integer_array<std::uint32_t>(j, key, 0, max_u32);
                break;
            case 2:
                p.chain_vertices = detail::integer_array<std::uint32_t>(j, key, 0, max_u32);
                break;
            case 3: added = points(j); break;
            case 4: p.crossings = pairs(j, key); break;
            case 5:
                p.mesh.halfedges = detail::integer_array<std::int32_t>(j, key, -1, max_i32);
                break;
            case 6: p.region = detail::integer_array<std::uint32_t>(j, key, 0, max_u32); break;
            case 7: p.constraints = pairs(j, key); break;
            default:
                p.mesh.duplicates = detail::integer_array<std::uint32_t>(j, key, 0, max_u32);
                break;
        }
    } while (j.accept(','));
    j.expect('}', "or ',' after an array");
    for (std::size_t k = 0; k < required; ++k) {
        if (!seen[k]) j.fail("key \"" + std::string(keys[k]) + "\" is missing");
    }
    if (!j.at_end()) j.fail("unexpected " + j.found() + " after the closing '}'");
    p.points.reserve(input.size() + added.size());
    p.points.assign(input.begin(), input.end());
    p.points.insert(p.points.end(), added.begin(), added.end());
    return p;
}

}  // namespace exidel::io
