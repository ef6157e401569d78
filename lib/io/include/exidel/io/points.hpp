// exidel I/O: reading (and writing) point sets.
//
// Formats (chosen explicitly, or from the file name's extension by format_from_path):
//
//   xy    (.txt .xy .csv, and the default) one point per line: two coordinates separated
//         by blanks (space, tab) and/or one comma: "1 2", "1,2", "1, 2". Everything from
//         '#' to the end of the line is a comment; lines blank after that are skipped.
//         Header: the FIRST non-blank line may be a header of exactly two names, each
//         starting with a letter and not a spelling of nan/inf ("x,y", "lon lat"); it
//         is skipped. Any later line of names is an error.
//   json  (.json) exactly a JSON array of [x, y] pairs: [[0, 0], [1, 0.5]]. Numbers use
//         JSON's grammar (no hex, no NaN/Infinity, no leading '+' or zeros); nothing but
//         whitespace may follow the closing bracket. An empty file is 0 points.
//   node  (.node) Triangle's format: a header "n [dim [attributes [markers]]]" (defaults
//         2, 0, 0; dim must be 2, markers 0 or 1), then n lines
//         "index x y [attribute...] [marker]". The first index is 0 or 1 and the others
//         follow consecutively. '#' starts a comment; blank lines are skipped. Attributes
//         must be finite numbers and markers integers; they are checked and dropped.
//   f64   (.f64) raw little-endian IEEE binary64 pairs x0 y0 x1 y1 ...; the byte count
//         must be a multiple of 16.
//
// Coordinates in the text formats are decimal or C99 hexadecimal floats (json: decimal
// only), rounded to the nearest double (exidel/io/number.hpp). Every format rejects NaN
// and infinity. Empty input (nothing, or only blanks and comments) is 0 points, not an
// error.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "exidel/predicates/types.hpp"

namespace exidel::io {

enum class PointFormat { xy, json, node, f64 };

std::string_view to_string(PointFormat f) noexcept;
/// "xy", "json", "node", "f64"; nullopt for anything else.
std::optional<PointFormat> point_format_from_name(std::string_view name);
/// From the extension of `path` (case-sensitive: .txt .xy .csv .json .node .f64);
/// xy when the extension is none of these.
PointFormat point_format_from_path(std::string_view path);

/// Malformed input. what() is "line N: reason" (text formats) or "byte offset N: reason"
/// (f64); line() and byte_offset() give the position alone (0 when not applicable;
/// lines count from 1).
class ReadError : public std::runtime_error {
public:
    static ReadError at_line(std::size_t line, const std::string& reason);
    static ReadError at_byte(std::size_t offset, const std::string& reason);

    std::size_t line() const noexcept { return line_; }
    std::size_t byte_offset() const noexcept { return byte_offset_; }
    const std::string& reason() const noexcept { return reason_; }

private:
    ReadError(const std::string& what, std::size_t line, std::size_t offset, std::string reason)
        : std::runtime_error(what), line_(line), byte_offset_(offset), reason_(std::move(reason)) {}
    std::size_t line_ = 0;
    std::size_t byte_offset_ = 0;
    std::string reason_;
};

/// Parses the whole of `data` (a file's bytes) as points in `format`, in input order.
/// Throws ReadError on malformed input.
std::vector<Point2> parse_points(std::string_view data, PointFormat format);

/// Reads `in` to its end and parses it. Throws ReadError on malformed input and
/// std::runtime_error if the stream fails.
std::vector<Point2> read_points(std::istream& in, PointFormat format);

/// Writes `points` in `format`, so that parse_points gives the same doubles back
/// (text coordinates are the shortest decimal that rounds back exactly; node is 0-based
/// with no attributes or markers).
void write_points(std::ostream& out, std::span<const Point2> points, PointFormat format);

}  // namespace exidel::io
