// exidel CLI: `exidel certify POINTS TRIANGULATION`, the exact certifier on files: is this
// the Delaunay triangulation of these points? For checking any triangulator's output
// (exidel's json, delaunator's arrays, Triangle's .ele) with exact predicates.
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"
#include "options.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view certify_help =
    R"(usage: exidel certify POINTS TRIANGULATION [--input-format xy|json|node|f64]
                      [--columns X,Y] [--format json|ele]

Checks, with exact predicates, whether TRIANGULATION is the Delaunay triangulation of
the points in POINTS, and says what is wrong and where when it is not. The checks, in
order: array shapes and index ranges; twins; every triangle strictly counter-clockwise;
the boundary is one convex cycle winding once, equal to the hull; every distinct point
is a vertex, duplicates listed; Euler's count; every interior edge locally Delaunay.

POINTS is read as by exidel triangulate (the format from --input-format, else the
extension; --columns for wider CSV). TRIANGULATION is, by --format or its extension:
  json  exidel triangulate's output: {"triangles", "halfedges", "hull", "duplicates"}
        with input indices (delaunator's arrays; "duplicates" may be absent and is
        then derived from the points)
  ele   Triangle's .ele, counted from the first triangle's number (0 or 1); the
        twins, the hull and the duplicates are derived from the triangles
Indices refer to the points in input order; a repeated point is represented by its
first occurrence.

Output: on standard output, one line per finding, "KIND: where and what" (at most 64,
then a count), and a last line with the verdict:
  certified: the Delaunay triangulation of N points (V distinct), T triangles
  not certified: F findings

Exit status: 0 certified, 1 a finding, or a file that cannot be read (the reason on
standard error), 2 bad options.

Options:
      --input-format FMT  xy|json|node|f64 (POINTS)
      --columns X,Y       xy POINTS: the fields holding x and y, by number or name
  -f, --format FMT        json|ele (TRIANGULATION)
  -h, --help              show this help
)";

int run(const std::string& points_path, const std::string& tri_path,
        std::optional<io::PointFormat> input_format, std::optional<io::TriangulationFormat> format,
        const std::optional<io::Columns>& columns, const CommandLine& cli) {
    const io::PointFormat pf = input_format.value_or(io::point_format_from_path(points_path));
    if (const std::optional<std::string> e = columns_error(columns, pf)) return cli.usage_error(*e);
    const std::optional<io::TriangulationFormat> tf =
        format ? format : io::triangulation_format_from_path(tri_path);
    if (!tf || (*tf != io::TriangulationFormat::json && *tf != io::TriangulationFormat::ele)) {
        return cli.usage_error("cannot read a triangulation from '" + tri_path +
                               "': json or ele (give --format)");
    }
    std::vector<Point2> points;
    delaunay::Triangulation tri;
    std::string reading = points_path;
    try {
        points =
            io::parse_point_file(io::FileBytes(points_path).view(), pf, io::ReadOptions{columns})
                .points;
        reading = tri_path;
        tri = io::read_triangulation(io::FileBytes(tri_path).view(), *tf, points);
    } catch (const io::ReadError& e) {
        std::cerr << "exidel: " << reading << ": " << e.what() << '\n';
        return exit_failure;
    } catch (const std::runtime_error& e) {
        std::cerr << "exidel: " << e.what() << '\n';
        return exit_failure;
    }
    const delaunay::Certificate c = delaunay::certify(points, tri);
    for (const delaunay::Finding& f : c.findings) {
        std::cout << delaunay::to_string(f.kind) << ": " << f.message << '\n';
    }
    if (c.total_findings > c.findings.size()) {
        std::cout << "... and " << c.total_findings - c.findings.size() << " more findings\n";
    }
    if (!c.ok()) {
        std::cout << "not certified: " << c.total_findings << " findings\n";
        return exit_failure;
    }
    std::cout << "certified: the Delaunay triangulation of " << points.size() << " points ("
              << points.size() - tri.duplicates.size() << " distinct), " << tri.triangle_count()
              << " triangles\n";
    return exit_ok;
}

}  // namespace

int certify_command(std::span<const std::string_view> args) {
    CommandLine cli("certify", std::string(certify_help));
    CLI::App& app = cli.app;
    std::vector<std::string> files;
    std::optional<io::PointFormat> input_format;
    std::optional<io::TriangulationFormat> format;
    std::optional<io::Columns> columns;
    app.add_option("FILES", files);
    add_point_format_option(app, input_format);
    add_parsed(app, "-f,--format", "json or ele", format, io::triangulation_format_from_name);
    add_columns_option(app, columns);
    if (const std::optional<int> status = cli.parse(args)) return *status;
    if (files.size() != 2) {
        return cli.usage_error("expected two files, POINTS and TRIANGULATION, got " +
                               std::to_string(files.size()));
    }
    return run(files[0], files[1], input_format, format, columns, cli);
}

}  // namespace exidel::cli
