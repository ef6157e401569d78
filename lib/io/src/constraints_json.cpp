// exidel I/O: the JSON form of points with segments and holes, and the one entry point
// that reads constraints in any format that has them (exidel/io/constraints.hpp).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "exidel/io/constraints.hpp"
#include "json.hpp"

namespace exidel::io {

ConstraintFile parse_json_constraints(std::string_view data) {
    ConstraintFile file;
    detail::JsonCursor j(data);
    if (j.at_end()) return file;
    if (j.peek() == '[') {  // a bare array of points
        detail::point_array(j, file.points, "points");
        if (!j.at_end()) j.fail("unexpected " + j.found() + " after the closing ']'");
        return file;
    }
    j.expect('{', "to open the object {\"points\": ..., \"segments\": ...}");
    bool seen_points = false, seen_segments = false, seen_holes = false;
    // Segments are checked against the point count at the end (the keys come in any
    // order); the line of each is kept for the message.
    std::vector<std::size_t> segment_lines;
    const auto once = [&](bool& seen, std::string_view key) {
        if (seen) j.fail("the key \"" + std::string(key) + "\" appears twice");
        seen = true;
    };
    if (!j.accept('}')) {
        do {
            const std::string_view key = j.key();
            j.expect(':', "after a key");
            if (key == "points") {
                once(seen_points, key);
                detail::point_array(j, file.points, "points");
            } else if (key == "holes") {
                once(seen_holes, key);
                detail::point_array(j, file.holes, "holes");
            } else if (key == "segments") {
                once(seen_segments, key);
                j.expect('[', "to open the array of segments");
                if (!j.accept(']')) {
                    do {
                        j.expect('[', "to open a segment [a, b]");
                        segment_lines.push_back(j.line());
                        const auto a = j.integer("a segment's first point", 0, UINT32_MAX);
                        j.expect(',', "between a segment's two point indices");
                        const auto b = j.integer("a segment's second point", 0, UINT32_MAX);
                        if (j.peek() == ',') j.fail("a segment is [a, b]: found a third index");
                        j.expect(']', "to close the segment");
                        file.segments.push_back(
                            {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
                    } while (j.accept(','));
                    j.expect(']', "or ',' after a segment");
                }
            } else {
                j.fail("unknown key \"" + std::string(key) +
                       "\" (expected \"points\", \"segments\" or \"holes\")");
            }
        } while (j.accept(','));
        j.expect('}', "or ',' after a member");
    }
    if (!j.at_end()) j.fail("unexpected " + j.found() + " after the closing '}'");
    if (!seen_points) j.fail("the object has no \"points\"");
    for (std::size_t s = 0; s < file.segments.size(); ++s) {
        const auto [a, b] = file.segments[s];
        if (a >= file.points.size() || b >= file.points.size()) {
            throw ReadError::at_line(segment_lines[s],
                                     "segment " + std::to_string(s) + " names point " +
                                         std::to_string(a >= file.points.size() ? a : b) +
                                         ", but there are " + std::to_string(file.points.size()) +
                                         " points");
        }
    }
    return file;
}

ConstraintFile parse_constraint_file(std::string_view data, PointFormat format) {
    constexpr std::string_view bom = "\xEF\xBB\xBF";
    if (data.starts_with(bom)) data.remove_prefix(bom.size());
    switch (format) {
        case PointFormat::poly: return parse_poly(data);
        case PointFormat::geojson: return parse_geojson_constraints(data);
        case PointFormat::json: return parse_json_constraints(data);
        case PointFormat::xy:
        case PointFormat::node:
        case PointFormat::f64: break;
    }
    throw std::invalid_argument("the " + std::string(to_string(format)) +
                                " format has no segments (poly, geojson and json have)");
}

}  // namespace exidel::io
