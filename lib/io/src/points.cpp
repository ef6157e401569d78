// exidel I/O: the point readers and writers (formats: exidel/io/points.hpp).
#include "exidel/io/points.hpp"
#include "exidel/io/constraints.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <new>
#include <ostream>

#include "exidel/delaunay/parallel.hpp"
#include "exidel/io/number.hpp"
#include "geojson_points.hpp"
#include "json.hpp"
#include "text.hpp"

namespace exidel::io {

namespace {

using detail::for_each_line;
using detail::is_blank;
using detail::strip_comment;

// Splits a comment-free line into fields separated by blanks and/or one comma (only
// blanks when `commas` is false). With commas a field may be quoted ("x", "1, 2"): the
// quotes are dropped. An empty field ("1,,2", ",1", "1,") is an error unless
// `allow_empty`: returns false and sets `error`.
bool split_fields(std::string_view line, std::vector<std::string_view>& fields, std::string& error,
                  bool commas, bool allow_empty = false) {
    fields.clear();
    std::size_t i = 0;
    const std::size_t n = line.size();
    const auto skip = [&] {
        while (i < n && is_blank(line[i])) ++i;
    };
    skip();
    if (i == n) return true;
    for (;;) {
        if (i == n || (commas && line[i] == ',')) {
            if (!allow_empty) {
                error = "empty field (two separators in a row, or a comma at the start or end)";
                return false;
            }
            fields.push_back({});
        } else if (commas && line[i] == '"') {
            const std::size_t close = line.find('"', i + 1);
            if (close == std::string_view::npos) {
                error = "unterminated quoted field " + quoted(line.substr(i));
                return false;
            }
            fields.push_back(line.substr(i + 1, close - i - 1));
            i = close + 1;
            if (i < n && !is_blank(line[i]) && line[i] != ',') {
                error = "a quoted field is followed by " + quoted(line.substr(i, 1)) +
                        " (a quote inside a field is not supported)";
                return false;
            }
        } else {
            const std::size_t start = i;
            while (i < n && !is_blank(line[i]) && !(commas && line[i] == ',')) ++i;
            fields.push_back(line.substr(start, i - start));
        }
        skip();
        if (i == n) {
            if (allow_empty && commas && !line.empty() && line[n - 1] == ',') fields.push_back({});
            return true;
        }
        if (commas && line[i] == ',') {
            ++i;
            skip();
        }
    }
}

bool starts_with_ci(std::string_view s, std::string_view prefix) {
    return s.size() >= prefix.size() &&
           std::equal(prefix.begin(), prefix.end(), s.begin(), [](char p, char c) {
               return p == std::tolower(static_cast<unsigned char>(c));
           });
}

// A header field: starts with a letter and is not a spelling of nan or inf (which must
// be reported as a non-finite coordinate, not skipped).
bool is_name(std::string_view f) {
    return !f.empty() && std::isalpha(static_cast<unsigned char>(f.front())) &&
           !starts_with_ci(f, "nan") && !starts_with_ci(f, "inf");
}

double coordinate(std::size_t line, std::string_view field, const char* what) {
    const ParsedNumber n = parse_double(field);
    if (!n.value) throw ReadError::at_line(line, std::string(what) + ": " + n.error);
    return *n.value;
}

// The field index (from 0) that `column` names: a number from 1, or a name of `header`.
std::size_t column_index(const std::string& column, std::span<const std::string_view> header,
                         std::size_t line) {
    if (!column.empty() && std::isdigit(static_cast<unsigned char>(column.front()))) {
        return static_cast<std::size_t>(std::stoull(column)) - 1;  // checked by parse_columns
    }
    const auto found = std::find(header.begin(), header.end(), column);
    if (found == header.end()) {
        std::string names;
        for (const std::string_view h : header) names += (names.empty() ? "" : ", ") + quoted(h);
        throw ReadError::at_line(
            line, "no column named " + quoted(column) + " in the first line (" + names + ")");
    }
    if (std::find(found + 1, header.end(), column) != header.end()) {
        throw ReadError::at_line(line, "the header names " + quoted(column) + " twice");
    }
    return static_cast<std::size_t>(found - header.begin());
}

// Where x and y are on an xy line, decided by its first line with content.
struct XyLayout {
    std::size_t width = 2, ix = 0, iy = 1;  // fields per line, and which are x and y
    std::size_t iz = 0;                     // which is z, when has_z
    bool has_z = false;
    bool columns = false;  // chosen by ReadOptions::columns
};

// The common line "x y" or "x,y" (blanks around, plain decimals) read without splitting
// it into fields: true with `p` set, or false for anything else (a sign '+', hex, a
// comment, quotes, a third field, an error), which the general path then reads or
// reports. Where it answers, it answers as the general path does: a field starting with a
// digit, '.', or '-' and one of those is exactly what parse_double hands to
// std::from_chars (its sign taken off and put back, which changes no bit), and a value
// from_chars reports in range is finite.
bool simple_xy(std::string_view line, Point2& p) {
    const char* c = line.data();
    const char* const end = c + line.size();
    const auto skip = [&] {
        while (c != end && is_blank(*c)) ++c;
    };
    const auto starts_number = [&] {
        const auto digit_or_point = [](char d) { return (d >= '0' && d <= '9') || d == '.'; };
        return c != end &&
               (digit_or_point(*c) || (*c == '-' && c + 1 != end && digit_or_point(c[1])));
    };
    skip();
    if (!starts_number()) return false;
    auto r = std::from_chars(c, end, p.x);
    if (r.ec != std::errc{}) return false;
    c = r.ptr;
    const char* const after_x = c;
    skip();
    if (c != end && *c == ',') {
        ++c;
        skip();
    } else if (c == after_x) {
        return false;  // no separator: "1.5e" or "0x1"
    }
    if (!starts_number()) return false;
    r = std::from_chars(c, end, p.y);
    if (r.ec != std::errc{}) return false;
    c = r.ptr;
    skip();
    return c == end;
}

// Parses the data lines of `data` (line numbers counted from 1) into out[0, ...) (and their
// z into z_out[0, ...) when the layout has z); returns how many points it wrote (at most
// one per line).
std::size_t parse_xy_lines(std::string_view data, const XyLayout& layout, Point2* out,
                           double* z_out) {
    std::vector<std::string_view> fields;
    std::string error;
    std::size_t written = 0;
    const bool plain = !layout.columns && !layout.has_z && layout.width == 2;
    for_each_line(data, [&](std::size_t number, std::string_view line) {
        if (plain && simple_xy(line, out[written])) {
            ++written;
            return;
        }
        if (!split_fields(strip_comment(line), fields, error, true, layout.columns)) {
            throw ReadError::at_line(number, error);
        }
        if (fields.empty()) return;
        if (fields.size() != layout.width) {
            throw ReadError::at_line(
                number,
                layout.columns
                    ? "expected " + std::to_string(layout.width) +
                          " fields, as on the first line, got " + std::to_string(fields.size())
                    : "expected 2 coordinates (x y), got " + std::to_string(fields.size()) +
                          (fields.size() > 2 ? " fields (pick two with --columns X,Y)" : ""));
        }
        if (layout.has_z) z_out[written] = coordinate(number, fields[layout.iz], "z");
        out[written++] = {coordinate(number, fields[layout.ix], "x"),
                          coordinate(number, fields[layout.iy], "y")};
    });
    return written;
}

PointFile parse_xy(std::string_view data, const std::optional<Columns>& columns, unsigned threads) {
    // The first line with content: a header or not, and the layout of every line.
    XyLayout layout;
    layout.columns = columns.has_value();
    std::size_t first = 0, lines_before = 0;  // where the data lines start, and their line
    {
        std::vector<std::string_view> fields;
        std::string error;
        while (first < data.size()) {
            std::size_t end = data.find('\n', first);
            if (end == std::string_view::npos) end = data.size();
            std::string_view line = data.substr(first, end - first);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            const std::size_t number = lines_before + 1;
            if (!split_fields(strip_comment(line), fields, error, true, layout.columns)) {
                throw ReadError::at_line(number, error);
            }
            if (fields.empty()) {
                first = end + 1;
                ++lines_before;
                continue;
            }
            bool header = false;
            if (columns) {
                // A header when a column is picked by name, or when the picked fields are
                // names (by number).
                layout.width = fields.size();
                const auto named = [](const std::string& c) {
                    return !std::isdigit(static_cast<unsigned char>(c[0]));
                };
                const bool by_name =
                    named(columns->x) || named(columns->y) || (columns->z && named(*columns->z));
                layout.ix = column_index(columns->x, fields, number);
                layout.iy = column_index(columns->y, fields, number);
                layout.has_z = columns->z.has_value();
                if (layout.has_z) layout.iz = column_index(*columns->z, fields, number);
                const std::size_t widest = std::max({layout.ix, layout.iy, layout.iz});
                if (widest >= layout.width) {
                    throw ReadError::at_line(number, "column " + std::to_string(widest + 1) +
                                                         " asked for, the line has " +
                                                         std::to_string(layout.width) + " fields");
                }
                header = by_name || (is_name(fields[layout.ix]) && is_name(fields[layout.iy]) &&
                                     (!layout.has_z || is_name(fields[layout.iz])));
            } else {
                header = fields.size() == 2 && is_name(fields[0]) && is_name(fields[1]);
            }
            if (header) {
                first = std::min(end + 1, data.size());
                ++lines_before;
            }
            break;
        }
    }
    const std::string_view rest = data.substr(std::min(first, data.size()));

    // The rest in parts cut at line ends, parsed at once into one array with room for a
    // point per line (one allocation, touched once: on some machines a fresh page costs
    // more than parsing the 80 characters that fill it; docs/measurements.md), then the
    // parts' points moved together.
    constexpr std::size_t min_part = 1 << 20;
    const std::size_t parts =
        std::clamp<std::size_t>(rest.size() / min_part, 1, std::max(threads, 1u));
    std::vector<std::size_t> cut(parts + 1, rest.size());
    cut[0] = 0;
    for (std::size_t p = 1; p < parts; ++p) {
        const std::size_t nl = rest.find('\n', std::max(cut[p - 1], p * (rest.size() / parts)));
        cut[p] = nl == std::string_view::npos ? rest.size() : nl + 1;
    }
    std::vector<std::size_t> lines(parts), start(parts + 1, 0), written(parts, 0);
    exidel::parallel_for(parts, threads, [&](std::size_t p) {
        const std::string_view part = rest.substr(cut[p], cut[p + 1] - cut[p]);
        lines[p] = static_cast<std::size_t>(std::count(part.begin(), part.end(), '\n')) +
                   (part.empty() || part.back() == '\n' ? 0 : 1);
    });
    for (std::size_t p = 0; p < parts; ++p) start[p + 1] = start[p] + lines[p];
    PointFile file;
    std::vector<Point2>& points = file.points;
    points.resize(start[parts]);
    if (layout.has_z) file.z.resize(start[parts]);
    std::vector<std::optional<ReadError>> part_error(parts);
    exidel::parallel_for(parts, threads, [&](std::size_t p) {
        try {
            written[p] = parse_xy_lines(rest.substr(cut[p], cut[p + 1] - cut[p]), layout,
                                        points.data() + start[p],
                                        layout.has_z ? file.z.data() + start[p] : nullptr);
        } catch (const ReadError& e) {
            part_error[p] = e;
        }
    });
    // The first error in input order, at its line in the whole input.
    for (std::size_t p = 0; p < parts; ++p) {
        if (!part_error[p]) continue;
        std::size_t before = lines_before;
        for (std::size_t q = 0; q < p; ++q) before += lines[q];
        throw ReadError::at_line(before + part_error[p]->line(), part_error[p]->reason());
    }
    std::size_t total = written[0];
    for (std::size_t p = 1; p < parts; ++p) {
        std::copy_n(points.begin() + static_cast<std::ptrdiff_t>(start[p]), written[p],
                    points.begin() + static_cast<std::ptrdiff_t>(total));
        if (layout.has_z) {
            std::copy_n(file.z.begin() + static_cast<std::ptrdiff_t>(start[p]), written[p],
                        file.z.begin() + static_cast<std::ptrdiff_t>(total));
        }
        total += written[p];
    }
    points.resize(total);
    if (layout.has_z) file.z.resize(total);
    return file;
}

std::vector<Point2> parse_json(std::string_view data) {
    detail::JsonCursor j(data);
    std::vector<Point2> points;
    if (j.at_end()) return points;
    detail::point_array(j, points, "points");
    if (!j.at_end()) j.fail("unexpected " + j.found() + " after the closing ']'");
    return points;
}

// A whole-field integer in [lo, hi].
long long node_integer(std::size_t line, std::string_view field, const std::string& what,
                       long long lo, long long hi) {
    long long v = 0;
    const auto r = std::from_chars(field.data(), field.data() + field.size(), v);
    if (r.ec != std::errc{} || r.ptr != field.data() + field.size()) {
        throw ReadError::at_line(line, what + ": " + quoted(field) + " is not an integer");
    }
    if (v < lo || v > hi) {
        throw ReadError::at_line(line, what + " " + std::to_string(v) +
                                           (lo == hi ? ", expected " + std::to_string(lo)
                                                     : " is outside [" + std::to_string(lo) + ", " +
                                                           std::to_string(hi) + "]"));
    }
    return v;
}

// Triangle's vertex section (a .node file, or the start of a .poly): the header
// "n [dim [attributes [markers]]]" then n lines "index x y [attribute...] [marker]".
// feed() takes every non-blank line until the section is complete.
class VertexSection {
public:
    VertexSection(PointFile& file, std::size_t bytes) : file_(file), bytes_(bytes) {}

    bool complete() const noexcept {
        return have_header_ && static_cast<long long>(file_.points.size()) == expected_;
    }
    bool have_header() const noexcept { return have_header_; }
    long long expected() const noexcept { return expected_; }

    void feed(std::size_t number, const std::vector<std::string_view>& fields) {
        if (!have_header_) {
            if (fields.size() > 4) {
                throw ReadError::at_line(number,
                                         "the header is \"vertices [dimension "
                                         "[attributes [markers]]]\", got " +
                                             std::to_string(fields.size()) + " fields");
            }
            expected_ = node_integer(number, fields[0], "number of vertices", 0, max_count);
            if (fields.size() > 1) node_integer(number, fields[1], "dimension", 2, 2);
            if (fields.size() > 2) {
                attributes_ = node_integer(number, fields[2], "number of attributes", 0, 1 << 20);
            }
            if (fields.size() > 3) markers_ = node_integer(number, fields[3], "markers", 0, 1);
            have_header_ = true;
            // The header's count is not trusted for memory: at most one point per 4 bytes.
            file_.points.reserve(static_cast<std::size_t>(
                std::min<long long>(expected_, static_cast<long long>(bytes_ / 4))));
            return;
        }
        const auto k = static_cast<long long>(file_.points.size());
        const auto want = static_cast<std::size_t>(3 + attributes_ + markers_);
        if (fields.size() != want) {
            throw ReadError::at_line(
                number,
                "expected " + std::to_string(want) + " fields (index x y" +
                    (attributes_ ? " + " + std::to_string(attributes_) + " attributes" : "") +
                    (markers_ ? " + marker" : "") + "), got " + std::to_string(fields.size()));
        }
        if (k == 0) {
            first_index_ = node_integer(number, fields[0], "first vertex index", 0, 1);
            file_.index_base = static_cast<unsigned>(first_index_);
        } else {
            node_integer(number, fields[0], "vertex index", first_index_ + k, first_index_ + k);
        }
        file_.points.push_back(
            {coordinate(number, fields[1], "x"), coordinate(number, fields[2], "y")});
        for (std::size_t a = 0; a < static_cast<std::size_t>(attributes_); ++a) {
            coordinate(number, fields[3 + a], "attribute");
        }
        if (markers_) node_integer(number, fields.back(), "boundary marker", INT32_MIN, INT32_MAX);
    }

    static constexpr long long max_count = 0x7fffffff;

private:
    PointFile& file_;
    std::size_t bytes_;
    bool have_header_ = false;
    long long expected_ = 0, attributes_ = 0, markers_ = 0, first_index_ = 0;
};

PointFile parse_node(std::string_view data) {
    PointFile file;
    VertexSection vertices(file, data.size());
    std::vector<std::string_view> fields;
    std::string error;
    const std::size_t lines = for_each_line(data, [&](std::size_t number, std::string_view line) {
        split_fields(strip_comment(line), fields, error, false);  // no commas: cannot fail
        if (fields.empty()) return;
        if (vertices.complete()) {
            throw ReadError::at_line(number, "more vertex lines than the " +
                                                 std::to_string(vertices.expected()) +
                                                 " the header announces");
        }
        vertices.feed(number, fields);
    });
    if (vertices.have_header() && !vertices.complete()) {
        throw ReadError::at_line(
            std::max<std::size_t>(lines, 1),
            "truncated: the file ends after " + std::to_string(file.points.size()) + " of the " +
                std::to_string(vertices.expected()) + " vertices the header announces");
    }
    return file;
}

std::uint64_t little_endian(std::uint64_t v) {
    if constexpr (std::endian::native == std::endian::big) {
        std::uint64_t r = 0;
        for (int b = 0; b < 8; ++b) r |= ((v >> (8 * b)) & 0xffu) << (8 * (7 - b));
        return r;
    }
    return v;
}

std::vector<Point2> parse_f64(std::string_view data) {
    if (data.size() % 16 != 0) {
        throw ReadError::at_byte(data.size() - data.size() % 16,
                                 "truncated: " + std::to_string(data.size()) +
                                     " bytes is not a multiple of 16 (one x y pair of float64); " +
                                     std::to_string(data.size() % 16) + " bytes left over");
    }
    std::vector<Point2> points(data.size() / 16);
    for (std::size_t offset = 0; offset < data.size(); offset += 8) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, data.data() + offset, 8);
        const double v = std::bit_cast<double>(little_endian(bits));
        if (!std::isfinite(v)) {
            throw ReadError::at_byte(offset, std::string(offset % 16 ? "y" : "x") + " of point " +
                                                 std::to_string(offset / 16) + " is " +
                                                 (std::isnan(v) ? "NaN" : "infinite"));
        }
        Point2& p = points[offset / 16];
        (offset % 16 ? p.y : p.x) = v;
    }
    return points;
}

void require_finite(std::span<const Point2> points) {
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) {
            throw std::invalid_argument("write_points: point " + std::to_string(i) +
                                        " is not finite");
        }
    }
}

}  // namespace

ConstraintFile parse_poly(std::string_view data) {
    ConstraintFile poly;
    PointFile vertices_file;
    VertexSection vertices(vertices_file, data.size());
    enum class Part { vertices, segments, holes, regions, done } part = Part::vertices;
    long long count = -1, markers = 0, first = 0;  // of the current section; -1: header next
    std::size_t in_part = 0;
    std::vector<std::string_view> fields;
    std::string error;
    const auto index_in = [&](std::size_t number, std::string_view field, const char* what) {
        // A section's first line numbers from 0 or 1, the others follow.
        if (in_part == 0) {
            first = node_integer(number, field, (std::string("first ") + what + " index").c_str(),
                                 0, 1);
        } else {
            const auto k = static_cast<long long>(in_part);
            node_integer(number, field, std::string(what) + " index", first + k, first + k);
        }
    };
    const auto header = [&](std::size_t number, const char* what, std::size_t max_fields) {
        if (fields.size() > max_fields) {
            throw ReadError::at_line(number, std::string("the ") + what + " header has " +
                                                 std::to_string(fields.size()) +
                                                 " fields, expected at most " +
                                                 std::to_string(max_fields));
        }
        count = node_integer(number, fields[0], std::string("number of ") + what, 0,
                             VertexSection::max_count);
        in_part = 0;
    };
    // After a section's last line (or a header announcing none), the next section's header.
    const auto end_section = [&](Part next) {
        if (static_cast<long long>(in_part) != count) return;
        part = next;
        count = -1;
    };
    const std::size_t lines = for_each_line(data, [&](std::size_t number, std::string_view line) {
        split_fields(strip_comment(line), fields, error, false);  // no commas: cannot fail
        if (fields.empty()) return;
        switch (part) {
            case Part::vertices:
                vertices.feed(number, fields);
                if (vertices.have_header() && vertices.expected() == 0) {
                    throw ReadError::at_line(
                        number,
                        "0 vertices: the vertices are in a separate .node file, which exidel "
                        "does not read; put them in the .poly");
                }
                if (vertices.complete()) part = Part::segments;
                return;
            case Part::segments:
                if (count < 0) {
                    header(number, "segments", 2);
                    if (fields.size() > 1)
                        markers = node_integer(number, fields[1], "markers", 0, 1);
                    poly.segments.reserve(static_cast<std::size_t>(
                        std::min<long long>(count, static_cast<long long>(data.size() / 4))));
                } else {
                    const auto want = static_cast<std::size_t>(3 + markers);
                    if (fields.size() != want) {
                        throw ReadError::at_line(number, "expected " + std::to_string(want) +
                                                             " fields (index endpoint endpoint" +
                                                             (markers ? " marker" : "") +
                                                             "), got " +
                                                             std::to_string(fields.size()));
                    }
                    index_in(number, fields[0], "segment");
                    const long long base = vertices_file.index_base;
                    const long long last =
                        base + static_cast<long long>(vertices_file.points.size()) - 1;
                    const auto a = node_integer(number, fields[1], "segment endpoint", base, last);
                    const auto b = node_integer(number, fields[2], "segment endpoint", base, last);
                    poly.segments.push_back({static_cast<std::uint32_t>(a - base),
                                             static_cast<std::uint32_t>(b - base)});
                    if (markers) {
                        poly.segment_markers.push_back(static_cast<std::int32_t>(node_integer(
                            number, fields[3], "boundary marker", INT32_MIN, INT32_MAX)));
                    }
                    ++in_part;
                }
                end_section(Part::holes);
                return;
            case Part::holes:
                if (count < 0) {
                    header(number, "holes", 1);
                } else {
                    if (fields.size() != 3) {
                        throw ReadError::at_line(number, "expected 3 fields (index x y), got " +
                                                             std::to_string(fields.size()));
                    }
                    index_in(number, fields[0], "hole");
                    poly.holes.push_back(
                        {coordinate(number, fields[1], "x"), coordinate(number, fields[2], "y")});
                    ++in_part;
                }
                end_section(Part::regions);
                return;
            case Part::regions:
                if (count < 0) {
                    header(number, "regions", 1);
                } else {
                    if (fields.size() != 4 && fields.size() != 5) {
                        throw ReadError::at_line(
                            number,
                            "expected 4 or 5 fields (index x y attribute [maximum area]), got " +
                                std::to_string(fields.size()));
                    }
                    index_in(number, fields[0], "region");
                    ConstraintFile::Region r;
                    r.seed = {coordinate(number, fields[1], "x"),
                              coordinate(number, fields[2], "y")};
                    r.attribute = coordinate(number, fields[3], "attribute");
                    if (fields.size() == 5) {
                        const double area = coordinate(number, fields[4], "maximum area");
                        if (area > 0) r.max_area = area;  // Triangle: negative means none
                    }
                    poly.regions.push_back(r);
                    ++in_part;
                }
                end_section(Part::done);
                return;
            case Part::done: throw ReadError::at_line(number, "unexpected line after the regions");
        }
    });
    const auto end_line = std::max<std::size_t>(lines, 1);
    if (part == Part::vertices) {
        if (!vertices.have_header()) throw ReadError::at_line(end_line, "empty .poly file");
        throw ReadError::at_line(end_line, "truncated: the file ends after " +
                                               std::to_string(vertices_file.points.size()) +
                                               " of the " + std::to_string(vertices.expected()) +
                                               " vertices the header announces");
    }
    if (part == Part::segments || (part == Part::holes && count >= 0)) {
        const char* what = part == Part::segments ? "segments" : "holes";
        if (count < 0)
            throw ReadError::at_line(end_line, std::string("truncated: no ") + what + " header");
        throw ReadError::at_line(end_line, "truncated: the file ends after " +
                                               std::to_string(in_part) + " of the " +
                                               std::to_string(count) + " " + what);
    }
    if (part == Part::holes) {  // the holes header is required
        throw ReadError::at_line(end_line, "truncated: no holes header");
    }
    if (part == Part::regions && count >= 0) {
        throw ReadError::at_line(end_line, "truncated: the file ends after " +
                                               std::to_string(in_part) + " of the " +
                                               std::to_string(count) + " regions");
    }
    poly.points = std::move(vertices_file.points);
    poly.index_base = vertices_file.index_base;
    return poly;
}

ReadError ReadError::at_line(std::size_t line, const std::string& reason) {
    return ReadError("line " + std::to_string(line) + ": " + reason, line, 0, reason);
}

ReadError ReadError::at_byte(std::size_t offset, const std::string& reason) {
    return ReadError("byte offset " + std::to_string(offset) + ": " + reason, 0, offset, reason);
}

std::string_view to_string(PointFormat f) noexcept {
    switch (f) {
        case PointFormat::xy: return "xy";
        case PointFormat::json: return "json";
        case PointFormat::node: return "node";
        case PointFormat::f64: return "f64";
        case PointFormat::geojson: return "geojson";
        case PointFormat::poly: return "poly";
    }
    return "?";
}

std::optional<PointFormat> point_format_from_name(std::string_view name) {
    for (PointFormat f : {PointFormat::xy, PointFormat::json, PointFormat::node, PointFormat::f64,
                          PointFormat::geojson, PointFormat::poly}) {
        if (to_string(f) == name) return f;
    }
    return std::nullopt;
}

PointFormat point_format_from_path(std::string_view path) {
    if (path.ends_with(".geojson")) return PointFormat::geojson;
    if (path.ends_with(".json")) return PointFormat::json;
    if (path.ends_with(".node")) return PointFormat::node;
    if (path.ends_with(".f64")) return PointFormat::f64;
    if (path.ends_with(".poly")) return PointFormat::poly;
    return PointFormat::xy;  // .txt, .xy, .csv and anything else
}

std::optional<Columns> parse_columns(std::string_view spec, std::string& error) {
    std::vector<std::string> items;
    for (std::size_t start = 0;;) {
        const std::size_t comma = spec.find(',', start);
        items.emplace_back(spec.substr(start, comma - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    if (items.size() < 2 || items.size() > 3) {
        error =
            "columns are two or three items X,Y[,Z] (field numbers from 1, or header "
            "names), got " +
            quoted(spec);
        return std::nullopt;
    }
    Columns c{items[0], items[1], std::nullopt};
    if (items.size() == 3) c.z = items[2];
    for (const std::string& item : items) {
        if (item.empty()) {
            error = "an empty column in " + quoted(spec);
            return std::nullopt;
        }
        if (std::isdigit(static_cast<unsigned char>(item.front()))) {
            unsigned long long v = 0;
            const auto r = std::from_chars(item.data(), item.data() + item.size(), v);
            if (r.ec != std::errc{} || r.ptr != item.data() + item.size() || v == 0 ||
                v > (1u << 20)) {
                error = "column " + quoted(item) + " is neither a field number from 1 nor a name";
                return std::nullopt;
            }
        }
    }
    return c;
}

PointFile parse_point_file(std::string_view data, PointFormat format, const ReadOptions& options) {
    if (options.columns && format != PointFormat::xy) {
        throw std::invalid_argument("columns apply to the xy format only, not to " +
                                    std::string(to_string(format)));
    }
    if (options.z_property && format != PointFormat::geojson) {
        throw std::invalid_argument("a z property applies to the geojson format only, not to " +
                                    std::string(to_string(format)));
    }
    // A UTF-8 byte order mark is not part of the text (spreadsheet CSV exports start with one).
    constexpr std::string_view bom = "\xEF\xBB\xBF";
    if (format != PointFormat::f64 && data.starts_with(bom)) data.remove_prefix(bom.size());
    switch (format) {
        case PointFormat::xy: return parse_xy(data, options.columns, options.threads);
        case PointFormat::json: return {parse_json(data), 0, {}};
        case PointFormat::node: return parse_node(data);
        case PointFormat::f64: return {parse_f64(data), 0, {}};
        case PointFormat::geojson: return detail::parse_geojson_points(data, options.z_property);
        case PointFormat::poly: {
            ConstraintFile poly = parse_poly(data);
            return {std::move(poly.points), poly.index_base, {}};
        }
    }
    return {};
}

std::vector<Point2> parse_points(std::string_view data, PointFormat format) {
    return parse_point_file(data, format).points;
}

PointFile read_point_file(std::istream& in, PointFormat format, const ReadOptions& options) {
    std::string data;
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        data.append(chunk, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) throw std::runtime_error("error while reading the input");
    return parse_point_file(data, format, options);
}

std::vector<Point2> read_points(std::istream& in, PointFormat format) {
    return read_point_file(in, format).points;
}

FileBytes::FileBytes(const std::string& path) {
    const auto fail = [&](int error) {
        throw std::runtime_error("cannot read '" + path + "': " + std::strerror(error));
    };
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail(errno);
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat before {};
    if (::fstat(fd, &before) != 0) fail(errno);
    if (S_ISDIR(before.st_mode)) fail(EISDIR);
    // read() until the end, into bytes of our own. (Not on a read error: EINTR is retried.)
    const auto read_some = [&](char* into, std::size_t room) {
        for (;;) {
            const ::ssize_t got = ::read(fd, into, room);
            if (got >= 0) return static_cast<std::size_t>(got);
            if (errno != EINTR) fail(errno);
        }
    };
    if (S_ISREG(before.st_mode) && before.st_size > 0) {
        // A private copy, not a mapping of the file: another process that truncates a
        // mapped file makes the next access to the lost pages raise SIGBUS, and one that
        // rewrites it changes the bytes between the parsers' passes (an xy file is cut
        // into parts by counting lines, then parsed into room for that many points). The
        // copy goes into anonymous memory asking for huge pages: fresh 4 kB pages cost
        // more than the copy on some machines (docs/measurements.md, "Text input").
        const auto size = static_cast<std::size_t>(before.st_size);
        void* map =
            ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (map == MAP_FAILED) throw std::bad_alloc();
        map_ = map;
        map_size_ = size;
#ifdef MADV_HUGEPAGE
        ::madvise(map_, map_size_, MADV_HUGEPAGE);
#endif
        char* bytes = static_cast<char*>(map_);
        std::size_t used = 0;
        for (std::size_t got; used < size && (got = read_some(bytes + used, size - used)) > 0;) {
            used += got;
        }
        char extra;
        const bool longer = used == size && read_some(&extra, 1) > 0;
        struct stat after {};
        if (::fstat(fd, &after) != 0) fail(errno);
        if (used != size || longer || after.st_size != before.st_size ||
            after.st_mtim.tv_sec != before.st_mtim.tv_sec ||
            after.st_mtim.tv_nsec != before.st_mtim.tv_nsec) {
            throw std::runtime_error("the input '" + path + "' changed while it was read (" +
                                     std::to_string(size) + " bytes when opened, " +
                                     std::to_string(after.st_size) +
                                     " now): read it once it is complete");
        }
        view_ = std::string_view(bytes, size);
        return;
    }
    // Read until the end: the size is at most a hint (a pipe or /proc file says 0).
    copy_.resize(1 << 16);
    std::size_t used = 0;
    for (;;) {
        if (used == copy_.size()) copy_.resize(2 * copy_.size());
        const std::size_t got = read_some(copy_.data() + used, copy_.size() - used);
        if (got == 0) break;
        used += got;
    }
    copy_.resize(used);
    view_ = copy_;
}

FileBytes::~FileBytes() {
    if (map_) ::munmap(map_, map_size_);
}

void write_points(std::ostream& out, std::span<const Point2> points, PointFormat format,
                  unsigned index_base, unsigned threads) {
    if (format == PointFormat::f64) {
        for (const Point2& p : points) {
            for (double v : {p.x, p.y}) {
                const std::uint64_t bits = little_endian(std::bit_cast<std::uint64_t>(v));
                char bytes[8];
                std::memcpy(bytes, &bits, 8);
                out.write(bytes, 8);
            }
        }
        return;
    }
    require_finite(points);
    if (format == PointFormat::json) {
        out << "[";
        detail::write_items(out, points.size(), threads, [&](std::size_t i, detail::TextBuffer& b) {
            b.append(64, [&](char* p) {
                p = detail::put(detail::put(p, i ? ",\n [" : "["), points[i].x);
                return detail::put(detail::put(detail::put(p, ", "), points[i].y), "]");
            });
        });
        out << "]\n";
        return;
    }
    if (format == PointFormat::node) out << points.size() << " 2 0 0\n";
    const bool node = format == PointFormat::node;
    detail::write_items(out, points.size(), threads, [&](std::size_t i, detail::TextBuffer& b) {
        b.append(96, [&](char* p) {
            if (node)
                p = detail::put(detail::put(p, static_cast<std::uint64_t>(i) + index_base), " ");
            p = detail::put(detail::put(detail::put(p, points[i].x), " "), points[i].y);
            return detail::put(p, "\n");
        });
    });
}

}  // namespace exidel::io
