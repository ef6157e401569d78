// exidel CLI: `exidel locate`, points and queries in, where each query lies out; and
// `exidel interpolate`, points with values and queries in, a value per query out.
//
// As `exidel triangulate` (triangulate.cpp), one way: create the output's temporary file
// -> read the points and the queries -> triangulate -> locate every query exactly
// (lib/delaunay, locate.hpp) -> interpolate (interpolate.hpp), for exidel interpolate ->
// write a CSV or JSON table into the temporary file,
// renamed into place on success (or stdout). No failure leaves an output file behind.
#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "common.hpp"
#include "exidel/delaunay/interpolate.hpp"
#include "exidel/delaunay/locate.hpp"
#include "exidel/delaunay/natural.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/io/number.hpp"
#include "exidel/io/points.hpp"
#include "options.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view locate_help_head =
    R"(usage: exidel locate -Q QUERIES [-i FILE] [-o FILE] [--kernel NAME]
                     [--algorithm NAME] [--format csv|json]
                     [--queries-format xy|json|node|f64|geojson]
                     [--input-format xy|json|node|f64|geojson] [--columns X,Y]
                     [--threads N] [--stats] [--quiet] [FILE]

Triangulates the points (as exidel triangulate does, with the same options, so that
triangle numbers are those of its output) and says where each query lies: strictly
inside a triangle, on an edge, on a vertex, or outside the convex hull. Decided by the
kernel's orient2d alone, with no tolerance: with an exact kernel (adaptive, the
default) a query on an edge or a vertex is found on it, however thin the triangles.

)";

constexpr std::string_view locate_help_tail =
    R"(a query equal to a duplicate point is on its first occurrence's vertex.

Queries (-Q/--queries FILE, or '-' for standard input when the points come from a
file): any point format above, by --queries-format, else the file's extension, else
xy. An empty file is no queries.

Output (-o FILE, or standard output). The format is --format, else the extension of
-o (.csv .json; another extension is an error), else csv. Indices are 0-based input
indices of the points; triangle numbers are those of exidel triangulate's output.
  csv   a header line, then one line per query, in order:
        query,kind,triangle,v0,v1,v2,edge_from,edge_to,vertex
          kind       inside | on_edge | on_vertex | outside
          triangle   a triangle holding the query (inside, on_edge, on_vertex), or,
                     outside, the triangle of a hull edge that sees it; v0 v1 v2 its
                     corners, counter-clockwise (empty when the points are collinear
                     and there are no triangles)
          edge_from, edge_to  on_edge: the edge; outside: a hull edge with the query
                     strictly on its outer side (empty otherwise); collinear points:
                     the segment of their chain holding an on_edge query
          vertex     on_vertex: the vertex (empty otherwise)
  json  {"kind": [...], "triangle": [...], "edge": [[from, to] | null, ...],
         "vertex": [v | null, ...]}, one key per line; triangle is null without
        triangles

Options:
  -Q, --queries FILE      the query points (required)
  -i, --input FILE        read the points from FILE ('-' for standard input)
  -o, --output FILE       write the table to FILE ('-' for standard output); written
                          to a temporary file and renamed on success
  -k, --kernel NAME       one of the kernels listed at the end (default: adaptive).
                          With an inexact kernel a walk whose answers contradict each
                          other stops with an error (never a loop)
  -a, --algorithm NAME    one of the algorithms listed at the end (default: external)
      --threads N         threads for reading, triangulating and locating (default:
                          the hardware's thread count); the output does not depend
                          on it
  -f, --format FORMAT     csv|json
      --queries-format FMT  xy|json|node|f64|geojson
      --input-format FMT  xy|json|node|f64|geojson (the points)
      --columns X,Y       xy input: the fields of the points holding x and y
      --stats             print one JSON object on standard error: "points",
                          "queries", "triangles", "kernel", "algorithm", the count of
                          each kind ("inside", "on_edge", "on_vertex", "outside"),
                          "failure" and the times "read_ms", "triangulate_ms",
                          "locate_ms", "write_ms", "total_ms"
  -q, --quiet             no progress line on standard error
  -h, --help              show this help

Errors: malformed points or queries stop with "exidel: line N: <reason>" (queries:
"exidel: queries: line N: <reason>"), a NaN or infinite query included; a failed
triangulation or walk says where; exit status 1, and no output is written.

Exit status: 0 success, 1 bad input, failed triangulation or location, or I/O error,
2 bad options.

Algorithms:
)";

enum class TableFormat { csv, json };

std::optional<TableFormat> table_format_from_name(std::string_view name) {
    if (name == "csv") return TableFormat::csv;
    if (name == "json") return TableFormat::json;
    return std::nullopt;
}

std::optional<TableFormat> table_format_from_path(std::string_view path) {
    const std::size_t dot = path.rfind('.');
    return dot == std::string_view::npos ? std::nullopt
                                         : table_format_from_name(path.substr(dot + 1));
}

enum class Method { linear, nearest, natural };

struct Options : PointCommand {
    std::optional<std::string> queries;
    std::optional<io::PointFormat> queries_format;
    std::optional<TableFormat> format;
    bool interpolate = false;  // exidel interpolate: values, not locations
    Method method = Method::linear;
    bool exact = false;  // natural: exact rationals
    double fill = std::numeric_limits<double>::quiet_NaN();
};

/// A value as the shortest decimal that reads back as the same double; NaN as `nan`.
void put_value(std::ostream& out, double v, std::string_view nan) {
    if (std::isnan(v)) {
        out << nan;
        return;
    }
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    out << std::string_view(buffer, static_cast<std::size_t>(r.ptr - buffer));
}

void write_values(std::ostream& out, std::span<const Point2> queries, std::span<const double> v,
                  TableFormat format) {
    if (format == TableFormat::csv) {
        out << "x,y,value\n";
        for (std::size_t i = 0; i < v.size(); ++i) {
            put_value(out, queries[i].x, "");
            out << ',';
            put_value(out, queries[i].y, "");
            out << ',';
            put_value(out, v[i], "");
            out << '\n';
        }
        return;
    }
    out << "{\"value\": [";
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (i) out << ", ";
        put_value(out, v[i], "null");
    }
    out << "]}\n";
}

/// The two ends of the edge a location names (none when it names no edge).
std::optional<std::pair<std::uint32_t, std::uint32_t>> edge_ends(const delaunay::Triangulation& t,
                                                                 const delaunay::Location& w) {
    if (w.edge < 0) return std::nullopt;
    const auto e = static_cast<std::size_t>(w.edge);
    if (t.collinear) return std::pair{t.hull[e], t.hull[e + 1]};
    return std::pair{t.triangles[e], t.triangles[delaunay::next_halfedge(e)]};
}

void write_csv(std::ostream& out, const delaunay::Triangulation& t,
               std::span<const delaunay::Location> where) {
    out << "query,kind,triangle,v0,v1,v2,edge_from,edge_to,vertex\n";
    for (std::size_t i = 0; i < where.size(); ++i) {
        const delaunay::Location& w = where[i];
        out << i << ',' << delaunay::to_string(w.kind) << ',';
        if (w.triangle >= 0) {
            const auto b = 3 * static_cast<std::size_t>(w.triangle);
            out << w.triangle << ',' << t.triangles[b] << ',' << t.triangles[b + 1] << ','
                << t.triangles[b + 2] << ',';
        } else {
            out << ",,,,";
        }
        if (const auto e = edge_ends(t, w)) {
            out << e->first << ',' << e->second << ',';
        } else {
            out << ",,";
        }
        if (w.vertex != delaunay::no_vertex) out << w.vertex;
        out << '\n';
    }
}

void write_json(std::ostream& out, const delaunay::Triangulation& t,
                std::span<const delaunay::Location> where) {
    const auto list = [&](const char* key, auto item, bool last) {
        out << '"' << key << "\": [";
        for (std::size_t i = 0; i < where.size(); ++i) {
            if (i) out << ", ";
            item(where[i]);
        }
        out << (last ? "]\n" : "],\n");
    };
    out << "{";
    list(
        "kind",
        [&](const delaunay::Location& w) { out << '"' << delaunay::to_string(w.kind) << '"'; },
        false);
    list(
        "triangle",
        [&](const delaunay::Location& w) {
            if (w.triangle >= 0) {
                out << w.triangle;
            } else {
                out << "null";
            }
        },
        false);
    list(
        "edge",
        [&](const delaunay::Location& w) {
            if (const auto e = edge_ends(t, w)) {
                out << '[' << e->first << ", " << e->second << ']';
            } else {
                out << "null";
            }
        },
        false);
    list(
        "vertex",
        [&](const delaunay::Location& w) {
            if (w.vertex != delaunay::no_vertex) {
                out << w.vertex;
            } else {
                out << "null";
            }
        },
        true);
    out << "}\n";
}

/// The queries, from their file (or standard input); "exidel: queries: ..." when they
/// cannot be read.
std::optional<std::vector<Point2>> read_queries(const Options& o, Progress& progress) {
    const std::string& path = *o.queries;
    const io::PointFormat format =
        o.queries_format ? *o.queries_format
                         : (path == "-" ? io::PointFormat::xy : io::point_format_from_path(path));
    progress.phase(path == "-" ? "reading queries from standard input"
                               : "reading queries '" + path + "'");
    try {
        if (path == "-") return io::read_points(std::cin, format);
        const io::FileBytes bytes(path);
        return io::parse_points(bytes.view(), format);
    } catch (const std::runtime_error& e) {
        progress.stop();
        std::cerr << "exidel: queries: " << e.what() << '\n';
        return std::nullopt;
    }
}

int run(const Options& o, const CommandLine& cli) {
    const Clock::time_point run_start = Clock::now();
    std::string error;
    const std::optional<AnyKernel> kernel = o.checked_kernel(error);
    if (!kernel) return cli.usage_error(error);
    if (!o.queries) return cli.usage_error("-Q/--queries FILE is required");
    if (*o.queries == "-" && o.input.from_stdin()) {
        return cli.usage_error("the points and the queries cannot both come from standard input");
    }
    const std::optional<TableFormat> format = output_format(
        o.format, o.output, TableFormat::csv, table_format_from_path, ".csv .json", error);
    if (!format) return cli.usage_error(error);

    std::optional<PendingFile> output;
    if (!o.open_output(output)) return exit_failure;
    PointRun steps(o, run_start);
    double locate_ms = 0;
    std::size_t counts[4] = {0, 0, 0, 0};
    std::optional<delaunay::Failure> failure;

    const std::optional<io::PointFile> input = steps.read();
    if (!input) return exit_failure;
    const Clock::time_point queries_start = Clock::now();
    const std::optional<std::vector<Point2>> queries = read_queries(o, steps.progress);
    if (!queries) return exit_failure;
    steps.times.read += ms_since(queries_start);
    const std::vector<Point2>& points = input->points;
    if (o.interpolate && input->z.size() != points.size()) {
        steps.progress.stop();
        std::cerr << "exidel: interpolate: the points have no values: give xy input a third "
                     "column (--columns X,Y,Z), or geojson z coordinates or --z-property NAME\n";
        return exit_failure;
    }

    const delaunay::Options options =
        delaunay::Options{}.with_algorithm(o.algorithm).with_threads(o.threads);
    const Triangulated triangulated = steps.triangulate(*kernel, points, options, false);
    const delaunay::Triangulation& tri = triangulated.result.triangulation;
    const auto finish = [&](int status) {
        return steps.finish(status, [&] {
            nlohmann::ordered_json failed;
            if (failure) {
                failed = {{"kind", delaunay::to_string(failure->kind)},
                          {"message", failure->message}};
            }
            const nlohmann::ordered_json stats{
                {"points", points.size()},
                {"queries", queries->size()},
                {"triangles", tri.triangle_count()},
                {"kernel", triangulated.kernel_name},
                {"algorithm", delaunay::to_string(triangulated.result.algorithm)},
                {"inside", counts[0]},
                {"on_edge", counts[1]},
                {"on_vertex", counts[2]},
                {"outside", counts[3]},
                {"failure", failed},
                {"read_ms", stats_ms(steps.times.read)},
                {"triangulate_ms", stats_ms(steps.times.triangulate)},
                {"locate_ms", stats_ms(locate_ms)},
                {"write_ms", stats_ms(steps.times.write)},
                {"total_ms", stats_ms(steps.times.total)},
            };
            std::cerr << stats_line(stats);
        });
    };
    if (!triangulated.result.ok()) {
        failure = triangulated.result.failure;
        return finish(exit_failure);
    }

    steps.progress.phase("locating " + std::to_string(queries->size()) + " queries");
    const Clock::time_point start = Clock::now();
    std::vector<delaunay::Location> where(queries->size());
    std::vector<double> values;
    std::visit(
        [&](const auto& k) {
            using K = std::decay_t<decltype(k)>;
            const delaunay::Locator<K> locator(points, tri, k);
            failure = locator.locate(*queries, where, {.threads = o.threads});
            if (failure || !o.interpolate) return;
            values.resize(queries->size());
            if (o.method == Method::linear) {
                delaunay::interpolate_linear(points, tri, input->z, *queries, where, values,
                                             o.fill);
                return;
            }
            if (o.method == Method::natural) {
                failure = delaunay::interpolate_natural(
                    locator, input->z, 1, *queries, values, o.fill,
                    {.locate = {.threads = o.threads},
                     .arithmetic = o.exact ? delaunay::NaturalArithmetic::exact
                                           : delaunay::NaturalArithmetic::rounded});
                return;
            }
            std::vector<std::uint32_t> nearest(queries->size());
            failure = locator.nearest(*queries, nearest, {.threads = o.threads});
            if (failure) return;
            for (std::size_t i = 0; i < nearest.size(); ++i) {
                values[i] = nearest[i] == delaunay::no_vertex ? o.fill : input->z[nearest[i]];
            }
        },
        *kernel);
    locate_ms = ms_since(start);
    if (failure) {
        steps.progress.stop();
        std::cerr << "exidel: ";
        if (failure->kind == delaunay::FailureKind::non_finite_input) {
            std::cerr << "queries: query " << failure->input_index
                      << " has a NaN or infinite coordinate\n";
        } else {
            std::cerr << "locate failed: " << failure->message << " ("
                      << delaunay::to_string(failure->kind) << ")";
            if (!triangulated.exact_kernel) {
                std::cerr << "; the " << triangulated.kernel_name
                          << " kernel is not exact, an exact one (adaptive) never fails";
            }
            std::cerr << '\n';
        }
        return finish(exit_failure);
    }
    for (const delaunay::Location& w : where) ++counts[static_cast<int>(w.kind)];

    const bool written = steps.write(output, [&](std::ostream& out) {
        if (o.interpolate) {
            write_values(out, *queries, values, *format);
        } else if (*format == TableFormat::csv) {
            write_csv(out, tri, where);
        } else {
            write_json(out, tri, where);
        }
    });
    return finish(written ? exit_ok : exit_failure);
}

}  // namespace

int locate_command(std::span<const std::string_view> args) {
    CommandLine cli("locate", point_command_help(locate_help_head, locate_help_tail));
    CLI::App& app = cli.app;
    Options o;
    o.add_input_output_options(app);
    app.add_option("-Q,--queries", o.queries);
    o.add_threads_option(app);
    add_parsed(app, "-f,--format", "csv or json", o.format, table_format_from_name);
    add_parsed(app, "--queries-format", "xy, json, node, f64 or geojson", o.queries_format,
               io::point_format_from_name);
    o.input.add_format_options(app);
    o.add_report_options(app);
    if (const std::optional<int> status = o.parse(cli, args)) return *status;
    return run(o, cli);
}

}  // namespace exidel::cli

namespace exidel::cli {

namespace {

constexpr std::string_view interpolate_help_head =
    R"(usage: exidel interpolate -Q QUERIES [-i FILE] [-o FILE]
                          [--method linear|nearest|natural] [--exact]
                          [--fill VALUE] [--kernel NAME] [--algorithm NAME]
                          [--format csv|json] [--queries-format FORMAT]
                          [--input-format xy|geojson] [--columns X,Y,Z]
                          [--z-property NAME] [--threads N] [--stats] [--quiet] [FILE]

Interpolates values given at points (their z: a third column of xy input through
--columns X,Y,Z, geojson z coordinates, or --z-property NAME) at query points, over the
Delaunay triangulation exidel triangulate computes. Where each query lies is decided
exactly (as exidel locate); then
  linear   (the default) on a vertex its value exactly; on an edge the interpolation
           between the edge's two ends (t = (q - a).(b - a) / |b - a|^2), the same from
           both of its triangles; inside a triangle the barycentric combination of its
           corners' values, the weights rounded to doubles (not exact: their error
           relative to the triangle grows as the triangle gets thinner); outside the
           convex hull --fill (default: none)
  nearest  the value of the exactly nearest point (the kernel's compare_distance; among
           equally near points one is chosen); --fill is used only without points
  natural  Sibson's natural neighbour interpolation: the share of each point's Voronoi
           cell the query would take, the neighbours decided exactly (the kernel's
           incircle), the areas in doubles relative to the query (no proven error bound;
           exact where a rounded determinant cannot decide), or with --exact in exact
           rationals, each value then the double nearest to the exact interpolant; on a
           vertex its value, on a hull edge linear along it, outside --fill
Collinear points interpolate along their chain.

)";

constexpr std::string_view interpolate_help_tail =
    R"(a repeated point's value is its first occurrence's.

Queries (-Q/--queries FILE, or '-' for standard input when the points come from a file):
any point format above, by --queries-format, else the extension, else xy.

Output (-o FILE, or standard output). The format is --format, else the extension of -o
(.csv .json), else csv.
  csv   "x,y,value", then one line per query in order: the query's coordinates and its
        value, each the shortest decimal that reads back as the same double; the value
        field is empty when there is none (outside the hull without --fill)
  json  {"value": [v | null, ...]}

Options:
  -Q, --queries FILE      the query points (required)
  -i, --input FILE        the points with their values ('-' for standard input)
  -o, --output FILE       write the values to FILE; written to a temporary file and
                          renamed on success
  -m, --method METHOD     linear (default), nearest or natural
      --exact             natural: the areas in exact rationals (slower)
      --fill VALUE        the value outside the convex hull (linear), a number
  -k, --kernel NAME       one of the kernels listed at the end (default: adaptive)
  -a, --algorithm NAME    one of the algorithms listed at the end (default: external)
      --threads N         threads (default: the hardware's); the output does not
                          depend on it
  -f, --format FORMAT     csv|json
      --queries-format FMT  xy|json|node|f64|geojson
      --input-format FMT  xy|json|node|f64|geojson (the points: xy or geojson hold values)
      --columns X,Y,Z     xy input: the fields of x, y and the value
      --z-property NAME   geojson input: the value is this property of each feature
      --stats             one JSON object on standard error, as exidel locate's
  -q, --quiet             no progress line on standard error
  -h, --help              show this help

Errors: points without values, malformed points or queries ("exidel: queries: line N:
..."), a failed triangulation or walk: exit status 1, no output written.

Exit status: 0 success, 1 bad input or failure, 2 bad options.

Algorithms:
)";

}  // namespace

int interpolate_command(std::span<const std::string_view> args) {
    CommandLine cli("interpolate",
                    point_command_help(interpolate_help_head, interpolate_help_tail));
    CLI::App& app = cli.app;
    Options o;
    o.interpolate = true;
    o.add_input_output_options(app);
    app.add_option("-Q,--queries", o.queries);
    add_parsed(app, "-m,--method", "linear, nearest or natural", o.method,
               [](const std::string& v) -> std::optional<Method> {
                   if (v == "linear") return Method::linear;
                   if (v == "nearest") return Method::nearest;
                   if (v == "natural") return Method::natural;
                   return std::nullopt;
               });
    app.add_flag("--exact", o.exact);
    add_parsed(app, "--fill", "a number", o.fill,
               [](const std::string& v) { return io::parse_double(v).value; });
    o.add_threads_option(app);
    add_parsed(app, "-f,--format", "csv or json", o.format, table_format_from_name);
    add_parsed(app, "--queries-format", "xy, json, node, f64 or geojson", o.queries_format,
               io::point_format_from_name);
    o.input.add_format_options(app);
    o.input.add_z_property_option(app);
    o.add_report_options(app);
    if (const std::optional<int> status = o.parse(cli, args)) return *status;
    return run(o, cli);
}

}  // namespace exidel::cli
