// exidel CLI: `exidel locate`, points and queries in, where each query lies out.
//
// As `exidel triangulate` (triangulate.cpp), one way: create the output's temporary file
// -> read the points and the queries -> triangulate -> locate every query exactly
// (lib/delaunay, locate.hpp) -> write a CSV or JSON table into the temporary file,
// renamed into place on success (or stdout). No failure leaves an output file behind.
#include <iostream>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "common.hpp"
#include "exidel/delaunay/locate.hpp"
#include "exidel/delaunay/triangulate.hpp"
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

struct Options : PointCommand {
    std::optional<std::string> queries;
    std::optional<io::PointFormat> queries_format;
    std::optional<TableFormat> format;
};

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
    std::visit(
        [&](const auto& k) {
            using K = std::decay_t<decltype(k)>;
            const delaunay::Locator<K> locator(points, tri, k);
            failure = locator.locate(*queries, where, {.threads = o.threads});
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
        if (*format == TableFormat::csv) {
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
