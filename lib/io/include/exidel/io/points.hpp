// exidel I/O: reading (and writing) point sets.
//
// Formats (chosen explicitly, or from the file name's extension by format_from_path):
//
//   xy    (.txt .xy .csv, and the default) one point per line: two coordinates separated
//         by blanks (space, tab) and/or one comma: "1 2", "1,2", "1, 2". Everything from
//         '#' to the end of the line is a comment; lines blank after that are skipped.
//         A field may be quoted ("x","y"; "1.5"), as spreadsheets write CSV; a quoted
//         field may hold commas and blanks but no quote. Header: the FIRST non-blank
//         line may be a header of names, each starting with a letter and not a spelling
//         of nan/inf ("x,y", "lon lat"); it is skipped. Any later line of names is an
//         error. Wider files (an id, a label, then x and y): ReadOptions::columns picks
//         the two fields by number or by header name; every line then has the field
//         count of the first, and the fields not picked may be anything, empty included.
//         A third column (X,Y,Z) is read as z (PointFile::z): a finite number, as x and y.
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
//   geojson  (.geojson) RFC 7946: a FeatureCollection, a Feature, or a bare geometry, of
//         Point and MultiPoint geometries (also inside a GeometryCollection), in document
//         order. A feature whose geometry is null (unlocated) is skipped; any other
//         geometry type is an error naming the feature ("feature 3: geometry type
//         'Polygon' is not supported"). Positions are [x, y] or [x, y, z]; z
//         (PointFile::z) is the third coordinate when every position has one (some with
//         and some without is an error), or with ReadOptions::z_property that property of
//         each feature, which must be a number (missing or not a number: an error naming
//         the feature). Strict JSON (RFC 8259): malformed text is a ReadError with its
//         line; unknown members (bbox, crs, id, other properties) are ignored.
//   poly  (.poly) Triangle's planar straight-line graph (exidel/io/constraints.hpp): its
//         vertices, numbered like a .node; the segments, holes and regions are checked
//         and, as points, dropped (parse_constraint_file keeps them).
//
// Coordinates in the text formats are decimal or C99 hexadecimal floats (json: decimal
// only), rounded to the nearest double (exidel/io/number.hpp). Every format rejects NaN
// and infinity. Empty input (nothing, or only blanks and comments) is 0 points, not an
// error. A UTF-8 byte order mark at the start of a text file (spreadsheets on Windows
// write one) is skipped.
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

enum class PointFormat { xy, json, node, f64, geojson, poly };

std::string_view to_string(PointFormat f) noexcept;
/// "xy", "json", "node", "f64", "geojson", "poly"; nullopt for anything else.
std::optional<PointFormat> point_format_from_name(std::string_view name);
/// From the extension of `path` (case-sensitive: .txt .xy .csv .json .node .f64 .geojson
/// .poly); xy when the extension is none of these.
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

/// Which two fields of an xy line are x and y, and optionally which one is z: each a field
/// number counted from 1 (as `cut -f` counts) or a name of the header line.
struct Columns {
    std::string x, y;
    std::optional<std::string> z{};
};
/// "X,Y" or "X,Y,Z" (e.g. "2,3", "lon,lat" or "lon,lat,height") to Columns; nullopt with
/// `error` set when it is not two or three non-empty items, or a number is 0.
std::optional<Columns> parse_columns(std::string_view spec, std::string& error);

struct ReadOptions {
    std::optional<Columns> columns;  // xy only; nullopt: exactly two fields per line
    /// xy: threads that parse parts of a large input (above 1 MiB) at once. The points,
    /// and the line of the first error, do not depend on it.
    unsigned threads = 1;
    /// geojson only: z is this property of each feature (a number), not the positions'
    /// third coordinates.
    std::optional<std::string> z_property{};
};

/// A point file's contents: the points, the first vertex index of a .node file (0 or 1;
/// 0 for every other format), so that a .ele written for it counts the same way, and a z
/// value per point when the input has them (xy with a third column, geojson), else empty.
struct PointFile {
    std::vector<Point2> points;
    unsigned index_base = 0;
    std::vector<double> z{};
};

/// Parses the whole of `data` (a file's bytes) as points in `format`, in input order.
/// Throws ReadError on malformed input, std::invalid_argument when `options` do not apply
/// to `format` (columns for anything but xy, z_property for anything but geojson).
PointFile parse_point_file(std::string_view data, PointFormat format,
                           const ReadOptions& options = {});
/// The points alone.
std::vector<Point2> parse_points(std::string_view data, PointFormat format);

/// Reads `in` to its end and parses it. Throws ReadError on malformed input and
/// std::runtime_error if the stream fails.
std::vector<Point2> read_points(std::istream& in, PointFormat format);
PointFile read_point_file(std::istream& in, PointFormat format, const ReadOptions& options = {});

/// The bytes of the file at `path`, read into memory of their own (anonymous memory
/// asking for huge pages for a regular file; a growing string for a pipe or /proc file).
/// Not a mapping of the file: a mapped file that another process truncates kills the
/// reader with SIGBUS, and one it rewrites changes under the parser. The constructor
/// throws std::runtime_error "cannot read 'PATH': REASON" with the system's reason (no
/// such file, permission denied, is a directory), "the input 'PATH' changed while it was
/// read (...)" when the size or modification time of a regular file changed during the
/// read, and std::bad_alloc when there is no memory for the copy.
class FileBytes {
public:
    explicit FileBytes(const std::string& path);
    ~FileBytes();
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;

    std::string_view view() const noexcept { return view_; }

private:
    void* map_ = nullptr;
    std::size_t map_size_ = 0;
    std::string copy_;
    std::string_view view_;
};

/// Writes `points` in `format`, so that parse_points gives the same doubles back
/// (text coordinates are the shortest decimal that rounds back exactly; node has no
/// attributes or markers and numbers its vertices from `index_base`, 0 or 1). `threads`
/// format parts of a text file at once (the text is the same for every count).
void write_points(std::ostream& out, std::span<const Point2> points, PointFormat format,
                  unsigned index_base = 0, unsigned threads = 1);

}  // namespace exidel::io
