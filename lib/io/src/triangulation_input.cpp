// exidel I/O: reading another triangulator's output (formats: exidel/io/triangulation_input.hpp).
#include "exidel/io/triangulation_input.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "exidel/io/constrained_input.hpp"
#include "exidel/io/number.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"
#include "json.hpp"
#include "text.hpp"

namespace exidel::io {

namespace {

using delaunay::ProducedTriangulation;
constexpr std::int64_t max_u32 = 0xffffffff, max_i32 = 0x7fffffff;

// The blank- (or one comma-) separated fields of a line without its comment.
void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    const std::string_view content = detail::strip_comment(line);
    for (std::size_t i = 0; i < content.size();) {
        while (i < content.size() && (detail::is_blank(content[i]) || content[i] == ',')) ++i;
        const std::size_t start = i;
        while (i < content.size() && !detail::is_blank(content[i]) && content[i] != ',') ++i;
        if (i > start) fields.push_back(content.substr(start, i - start));
    }
}

// A whole number in [lo, hi]: digits, or a number text that is exactly a whole number
// ("4.000000000000000000e+00", numpy.savetxt's default).
std::uint64_t whole(std::size_t line, std::string_view field, const std::string& what,
                    std::uint64_t lo, std::uint64_t hi) {
    std::uint64_t v = 0;
    const auto r = std::from_chars(field.data(), field.data() + field.size(), v);
    bool ok = r.ec == std::errc{} && r.ptr == field.data() + field.size();
    if (!ok) {
        const ParsedNumber d = parse_double(field);
        ok = d.value && *d.value >= 0 && *d.value <= static_cast<double>(hi) &&
             std::floor(*d.value) == *d.value;
        if (ok) v = static_cast<std::uint64_t>(*d.value);
    }
    if (!ok || v < lo || v > hi) {
        throw ReadError::at_line(line, what + ": " + quoted(field) + " is not a whole number in [" +
                                           std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return v;
}

// The json format; `exact` (parse_triangulation_json): exidel's own layout, the four
// keys required and nothing else.
ProducedTriangulation parse_json(std::string_view text, std::span<const Point2> points,
                                 bool exact) {
    detail::JsonCursor j(text);
    ProducedTriangulation p;
    if (!exact && j.accept('[')) {  // rows [i, j, k]: scipy's simplices.tolist()
        if (!j.accept(']')) {
            do {
                j.expect('[', "to open a triangle [i, j, k]");
                for (int k = 0; k < 3; ++k) {
                    if (k) j.expect(',', "between a triangle's vertices (three of them)");
                    p.triangles.push_back(
                        static_cast<std::uint32_t>(j.integer("vertex", 0, max_u32)));
                }
                j.expect(']', "after a triangle's three vertices");
            } while (j.accept(','));
            j.expect(']', "or ',' after a triangle");
        }
        if (!j.at_end()) j.fail("unexpected " + j.found() + " after the closing ']'");
        return p;
    }
    constexpr std::string_view keys[] = {"triangles", "halfedges", "hull", "duplicates", "coords"};
    bool seen[5] = {};
    j.expect('{', "to open the triangulation object (or '[' for rows of triangles)");
    do {
        const std::string_view key = j.key();
        const std::size_t known = exact ? 4 : 5;
        const auto k = static_cast<std::size_t>(std::find(keys, keys + known, key) - keys);
        if (k == known) {
            if (exact) j.fail("unknown key " + quoted(key));
            j.fail("unknown key " + quoted(key) +
                   " (expected triangles, halfedges, hull, duplicates, coords)");
        }
        if (seen[k]) j.fail("key " + quoted(key) + " appears twice");
        seen[k] = true;
        j.expect(':', "after the key");
        switch (k) {
            case 0: p.triangles = detail::integer_array<std::uint32_t>(j, key, 0, max_u32); break;
            case 1: p.halfedges = detail::integer_array<std::int32_t>(j, key, -1, max_i32); break;
            case 2: p.hull = detail::integer_array<std::uint32_t>(j, key, 0, max_u32); break;
            case 3: p.duplicates = detail::integer_array<std::uint32_t>(j, key, 0, max_u32); break;
            default: {
                // delaunator's coords: must be the points the certifier is given.
                j.expect('[', "to open the array \"coords\"");
                std::size_t n = 0;
                if (!j.accept(']')) {
                    do {
                        const double v = j.number("coords");
                        const bool same = n / 2 < points.size() &&
                                          v == (n % 2 ? points[n / 2].y : points[n / 2].x);
                        if (!same) {
                            j.fail("coords[" + std::to_string(n) + "] is not coordinate " +
                                   (n % 2 ? "y" : "x") + " of point " + std::to_string(n / 2) +
                                   ": this triangulation is of other points");
                        }
                        ++n;
                    } while (j.accept(','));
                    j.expect(']', "or ',' in the array \"coords\"");
                }
                if (n != 2 * points.size()) {
                    j.fail("coords holds " + std::to_string(n) + " numbers for " +
                           std::to_string(points.size()) + " points");
                }
            }
        }
    } while (j.accept(','));
    j.expect('}', "or ',' after an array");
    for (std::size_t k = 0; k < (exact ? 4 : 1); ++k) {
        if (!seen[k]) j.fail("key \"" + std::string(keys[k]) + "\" is missing");
    }
    if (!j.at_end()) j.fail("unexpected " + j.found() + " after the closing '}'");
    return p;
}

// Triangle's .ele: the triangles alone, as input indices.
ProducedTriangulation parse_ele(std::string_view text, std::size_t point_count) {
    ProducedTriangulation p;
    std::size_t expected = 0, attributes = 0, base = 0, count = 0;
    bool have_header = false;
    std::vector<std::string_view> fields;
    const std::size_t lines =
        detail::for_each_line(text, [&](std::size_t number, std::string_view line) {
            split_fields(line, fields);
            if (fields.empty()) return;
            if (!have_header) {
                if (fields.size() < 2 || fields.size() > 3) {
                    throw ReadError::at_line(number, "the header is \"triangles 3 [attributes]\"");
                }
                expected = whole(number, fields[0], "number of triangles", 0, max_i32 / 3);
                whole(number, fields[1], "nodes per triangle (only 3 is supported)", 3, 3);
                if (fields.size() == 3)
                    attributes = whole(number, fields[2], "attributes", 0, 1 << 20);
                have_header = true;
                p.triangles.reserve(3 * std::min(expected, text.size() / 8));
                return;
            }
            if (count == expected) {
                throw ReadError::at_line(number, "more triangle lines than the " +
                                                     std::to_string(expected) +
                                                     " the header announces");
            }
            if (fields.size() != 4 + attributes) {
                throw ReadError::at_line(number, "expected " + std::to_string(4 + attributes) +
                                                     " fields (index v0 v1 v2" +
                                                     (attributes ? " attributes" : "") + "), got " +
                                                     std::to_string(fields.size()));
            }
            if (count == 0) {
                base = whole(number, fields[0], "first triangle index", 0, 1);
            } else {
                whole(number, fields[0], "triangle index", base + count, base + count);
            }
            if (point_count == 0) throw ReadError::at_line(number, "a triangle, but no points");
            for (std::size_t k = 1; k <= 3; ++k) {
                p.triangles.push_back(static_cast<std::uint32_t>(
                    whole(number, fields[k], "vertex", base, base + point_count - 1) - base));
            }
            ++count;
        });
    if (!have_header) throw ReadError::at_line(1, "empty .ele file (no header)");
    if (count != expected) {
        throw ReadError::at_line(std::max<std::size_t>(lines, 1),
                                 "truncated: the file ends after " + std::to_string(count) +
                                     " of the " + std::to_string(expected) +
                                     " triangles the header announces");
    }
    return p;
}

// Exact coordinates -> the first input index with them (-0.0 and 0.0 are one key, as
// they are one point).
class PointIndex {
public:
    explicit PointIndex(std::span<const Point2> points) {
        index_.reserve(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            index_.emplace(key(points[i]), static_cast<std::uint32_t>(i));
        }
    }
    void add(Point2 p, std::uint32_t i) { index_.emplace(key(p), i); }
    std::optional<std::uint32_t> find(Point2 p) const {
        const auto it = index_.find(key(p));
        return it == index_.end() ? std::nullopt : std::optional(it->second);
    }

private:
    struct Key {
        std::uint64_t x, y;
        bool operator==(const Key&) const = default;
    };
    struct Hash {
        std::size_t operator()(const Key& k) const noexcept {
            return std::hash<std::uint64_t>{}(k.x * 0x9e3779b97f4a7c15ull ^ k.y);
        }
    };
    static Key key(Point2 p) {
        return {std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0)};
    }
    std::unordered_map<Key, std::uint32_t, Hash> index_;
};

// OFF; `vertex(line, v, point, fields)` gives the index vertex v (at `point`, on line
// `line`) stands for in the triangles.
template <class Vertex>
ProducedTriangulation parse_off(std::string_view text, Vertex&& vertex) {
    ProducedTriangulation p;
    enum { magic, counts, vertices, faces, done } state = magic;
    std::size_t nv = 0, nf = 0, v = 0, f = 0;
    std::vector<std::uint32_t> input_of;  // OFF vertex -> input index
    std::vector<std::string_view> fields;
    const std::size_t lines = detail::for_each_line(text, [&](std::size_t number,
                                                              std::string_view line) {
        split_fields(line, fields);
        if (fields.empty()) return;
        if (state == magic) {
            if (fields[0] != "OFF") {
                throw ReadError::at_line(
                    number, "an OFF file starts with \"OFF\", found " + quoted(fields[0]));
            }
            fields.erase(fields.begin());
            state = counts;
            if (fields.empty()) return;  // the counts on the next line
        }
        if (state == counts) {
            if (fields.size() != 3 && fields.size() != 2) {
                throw ReadError::at_line(number, "expected \"nvertices nfaces nedges\"");
            }
            nv = whole(number, fields[0], "number of vertices", 0, max_u32);
            nf = whole(number, fields[1], "number of faces", 0, max_i32 / 3);
            input_of.reserve(std::min(nv, text.size() / 4));
            p.triangles.reserve(3 * std::min(nf, text.size() / 8));
            state = nv ? vertices : nf ? faces : done;
            return;
        }
        if (state == vertices) {
            if (fields.size() != 2 && fields.size() != 3) {
                throw ReadError::at_line(number, "a vertex line is \"x y [z]\", got " +
                                                     std::to_string(fields.size()) + " fields");
            }
            double c[3] = {0, 0, 0};
            for (std::size_t k = 0; k < fields.size(); ++k) {
                const ParsedNumber d = parse_double(fields[k]);
                if (!d.value) throw ReadError::at_line(number, "vertex coordinate: " + d.error);
                c[k] = *d.value;
            }
            input_of.push_back(vertex(number, v, Point2{c[0], c[1]}, fields));
            if (++v == nv) state = nf ? faces : done;
            return;
        }
        if (state == faces) {
            const std::size_t k = whole(number, fields[0], "vertices of a face", 3, max_u32);
            if (k != 3) {
                throw ReadError::at_line(number, "face " + std::to_string(f) + " has " +
                                                     std::to_string(k) +
                                                     " vertices: a triangulation has 3");
            }
            if (fields.size() < 4) throw ReadError::at_line(number, "a face line is \"3 a b c\"");
            if (nv == 0) throw ReadError::at_line(number, "a face, but no vertices");
            for (std::size_t j = 1; j <= 3; ++j) {
                p.triangles.push_back(input_of[whole(number, fields[j], "face vertex", 0, nv - 1)]);
            }
            if (++f == nf) state = done;
            return;
        }
        throw ReadError::at_line(number, "more lines than the " + std::to_string(nv) +
                                             " vertices and " + std::to_string(nf) +
                                             " faces the header announces");
    });
    if (state == magic) throw ReadError::at_line(1, "empty OFF file");
    if (state != done) {
        throw ReadError::at_line(std::max<std::size_t>(lines, 1),
                                 "truncated: the file ends after " + std::to_string(v) + " of " +
                                     std::to_string(nv) + " vertices and " + std::to_string(f) +
                                     " of " + std::to_string(nf) + " faces");
    }
    return p;
}

ProducedTriangulation parse_simplices(std::string_view text) {
    ProducedTriangulation p;
    std::vector<std::string_view> fields;
    detail::for_each_line(text, [&](std::size_t number, std::string_view line) {
        split_fields(line, fields);
        if (fields.empty()) return;
        if (fields.size() != 3) {
            throw ReadError::at_line(number, "expected three vertex indices, got " +
                                                 std::to_string(fields.size()) + " fields");
        }
        for (const std::string_view field : fields) {
            p.triangles.push_back(
                static_cast<std::uint32_t>(whole(number, field, "vertex", 0, max_u32)));
        }
    });
    return p;
}

}  // namespace

std::string_view to_string(ProducedFormat f) noexcept {
    switch (f) {
        case ProducedFormat::json: return "json";
        case ProducedFormat::ele: return "ele";
        case ProducedFormat::off: return "off";
        case ProducedFormat::simplices: return "simplices";
    }
    return "?";
}

std::optional<ProducedFormat> produced_format_from_name(std::string_view name) {
    for (ProducedFormat f : {ProducedFormat::json, ProducedFormat::ele, ProducedFormat::off,
                             ProducedFormat::simplices}) {
        if (to_string(f) == name) return f;
    }
    return std::nullopt;
}

std::optional<ProducedFormat> produced_format_from_path(std::string_view path) {
    const std::optional<ProducedFormat> f = produced_format_from_name(detail::extension_of(path));
    return f == ProducedFormat::simplices ? std::nullopt : f;
}

delaunay::ProducedTriangulation read_produced(std::string_view text, ProducedFormat format,
                                              std::span<const Point2> points) {
    switch (format) {
        case ProducedFormat::json: return parse_json(text, points, false);
        case ProducedFormat::ele: return parse_ele(text, points.size());
        case ProducedFormat::off: {
            const PointIndex index(points);
            return parse_off(text, [&](std::size_t number, std::size_t v, Point2 point,
                                       const std::vector<std::string_view>& fields) {
                const std::optional<std::uint32_t> i = index.find(point);
                if (!i) {
                    throw ReadError::at_line(
                        number, "vertex " + std::to_string(v) + " (" + std::string(fields[0]) +
                                    " " + std::string(fields[1]) +
                                    ") is not one of the input points (coordinates must "
                                    "read back exactly: write 17 significant digits)");
                }
                return *i;
            });
        }
        case ProducedFormat::simplices: return parse_simplices(text);
    }
    throw std::invalid_argument("unknown triangulation format");
}

delaunay::Triangulation parse_triangulation_json(std::string_view text) {
    ProducedTriangulation p = parse_json(text, {}, true);
    delaunay::Triangulation tri;
    tri.triangles = std::move(p.triangles);
    tri.halfedges = std::move(*p.halfedges);
    tri.hull = std::move(*p.hull);
    tri.duplicates = std::move(*p.duplicates);
    tri.collinear = tri.triangles.empty();
    return tri;
}

ProducedConstrained read_constrained_off(std::string_view text, std::span<const Point2> input) {
    ProducedConstrained c;
    c.points.assign(input.begin(), input.end());
    // The added points so far, by coordinates (an input point is found first).
    PointIndex index(input);
    c.mesh = parse_off(
        text, [&](std::size_t, std::size_t, Point2 point, const std::vector<std::string_view>&) {
            if (const std::optional<std::uint32_t> i = index.find(point)) return *i;
            const auto i = static_cast<std::uint32_t>(c.points.size());
            c.points.push_back(point);
            index.add(point, i);
            return i;
        });
    return c;
}

void fill_vertex_of_input(std::span<const Point2> points, delaunay::Triangulation& tri) {
    tri.vertex_of_input = delaunay::normalize(points, {}).vertex_of_input;
}

}  // namespace exidel::io
