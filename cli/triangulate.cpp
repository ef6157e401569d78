// exidel CLI: `exidel triangulate`, points in, Delaunay triangulation out.
//
// Data flows one way: create the output's temporary file (so an unwritable directory
// fails at once) -> read the whole input (lib/io) -> triangulate (lib/delaunay, the one
// timed call) -> optionally certify -> write into the temporary file, renamed into place
// on success (or stdout). Nothing reaches the output's name until everything succeeded,
// so bad input, a failed run or an interrupt (output.hpp) leaves no output file behind.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "common.hpp"
#include "constrained.hpp"
#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"
#include "options.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view triangulate_help_head =
    R"(usage: exidel triangulate [-i FILE] [-o FILE] [--kernel NAME] [--algorithm NAME]
                          [--incircle determinant|cosine]
                          [--format json|ele|off|svg|geojson|wkt|ply|ply-ascii|poly]
                          [--input-format xy|json|node|f64|geojson|poly]
                          [--columns X,Y[,Z]] [--z-property NAME]
                          [--constraints] [--fill even-odd|non-zero|enclosed|all]
                          [--order auto|lexicographic|radial|strips] [--threads N]
                          [--strip-points N] [--strip-tiles N] [--certify] [--stats]
                          [--quiet] [FILE]

Computes the Delaunay triangulation of a set of points, by default with the external
incremental algorithm (Cai 2025): each point is added outside the hull of the previous
ones, so no point location is needed. Its order of insertion (--order):
  lexicographic  the paper's: by x then y. The reference; quadratic on a sampled convex
                 curve inserted towards its vertex
  radial         by exact distance from a centre (ties by x then y)
  strips         vertical strips of --strip-points points, each radial, merged by the
                 Guibas-Stolfi zipper, on --threads threads; from 2^22 points (or
                 with --strip-tiles) each strip cut across into tiles first
  auto           (default) radial below 32768 points and on points along a convex
                 curve (a sampled hull test: parabolas, ellipses, not circles),
                 strips otherwise; a radial run that erodes more than 14 edges
                 per point (curves crossing the sweep: GPS tracks) gives up and
                 its points are inserted by cavities in BRIO order instead
Every order gives a Delaunay triangulation with an exact kernel, and the same one when
no four points are cocircular; the thread count never changes the output.

Constraints (--constraints, or .poly input): the constrained Delaunay triangulation of
the points with segments as edges: from a .poly (segments, hole seeds, regions), from
GeoJSON (LineStrings are breaklines, Polygon rings are segments) or from json
{"points": [[x, y], ...], "segments": [[i, j], ...], "holes": [[x, y], ...]}. A point
exactly on a segment splits it; overlapping segments are merged; two segments that
cross get a new vertex, each coordinate the double nearest to the exact crossing
(numbered after the input points). Only the domain's triangles are written (--fill):
  even-odd  inside an odd number of rings (default for geojson and json: polygons
            with holes as rings)
  non-zero  winding number of the segments, directed, not zero
  enclosed  closed off from the outside by segments (default for .poly: Triangle's
            -p; holes come from the hole seeds)
  all       the whole convex hull
Hole seeds then remove the region around each. Output (--format as below) holds
every vertex (input, then added points): json {"triangles", "halfedges", "region",
"constraints", "chain_offsets", "chain_vertices", "added_points", "crossings",
"duplicates"}; geojson the triangles with their "region", then each segment's
chain as a LineString; poly the vertices, the split segments (markers kept), holes
and regions; ele with a .node of every vertex; svg with the segments in red.
--certify checks the result with exidel's exact constrained certifier.

)";

constexpr std::string_view triangulate_help_tail =
    R"(rounded to the nearest double. NaN and infinity are errors; duplicates are kept
out of the triangulation and listed. An empty input is 0 points.

Output (-o FILE, or standard output). The format is --format, else the extension of
-o (.json .ele .off .svg .geojson .wkt .ply .poly; another extension is an error), else
json. Indices are input indices, 0-based (ele: counted like the input .node, from 0
or 1). Coordinates are written as the shortest decimals that read back as the same
doubles. z (from --columns X,Y,Z or geojson input) goes into off, geojson, wkt and
ply. Longitude and latitude are triangulated as a plane (no antimeridian or pole
handling).
  json  {"triangles": [...], "halfedges": [...], "hull": [...], "duplicates": [...]}
        delaunator's arrays: triangles counter-clockwise, halfedges -1 on the
        boundary, hull counter-clockwise from the lexicographically smallest point
        (all distinct points in order when they are collinear)
  ele   Triangle's .ele: "ntriangles 3 0", then "t v0 v1 v2"; -o FILE.ele also
        writes the points as FILE.node beside it (Triangle's pair, same numbering)
        unless FILE.node is the input itself or FILE a device or pipe
  off   OFF with the input's z, else z = 0 (every input point is a vertex,
        duplicates included)
  svg   a picture: triangles, hull in red, points; in the data's coordinates (the
        viewBox is the points' bounding box, y flipped by a scale(1,-1) group) so
        that it overlays other data; strokes keep their pixel width at any scale;
        opens at 10^6 points
  geojson  RFC 7946 FeatureCollection: Feature t is triangle t, a Polygon
        (counter-clockwise, closed) with properties {"triangle": t, "vertices":
        [i, j, k]}; then one Feature {"hull": true, "vertices": [...]}: the hull's
        Polygon, or for input without triangles a LineString of the distinct points
        (a Point for one; none for no points). Positions [x, y] or [x, y, z]
  wkt   one MULTIPOLYGON (MULTIPOLYGON Z with z), polygon t being triangle t;
        MULTIPOLYGON EMPTY without triangles
  ply   binary little-endian PLY (ply-ascii: ASCII PLY): vertices double x, y, z
        (z = 0 without z; every input point, duplicates included), faces "list uchar
        int vertex_indices"
  poly  Triangle's .poly: the points as vertices, the hull's edges as segments

Options:
  -i, --input FILE        read points from FILE ('-' for standard input)
  -o, --output FILE       write the triangulation to FILE ('-' for standard output);
                          written to a temporary file in the same directory and
                          renamed on success, so a failed or interrupted run
                          (Ctrl-C, SIGTERM) leaves no FILE and no temporary
  -k, --kernel NAME       one of the kernels listed at the end (default: adaptive).
                          adaptive, exact and exact-cpp give the Delaunay
                          triangulation of every finite input; the others may give a
                          wrong one or fail
  -a, --algorithm NAME    one of the algorithms listed at the end (default: external)
      --incircle POLICY   determinant (default) or cosine (the paper's Section 5 test;
                          used by the insertions, the strips' merges always use the
                          determinant)
      --order ORDER       auto|lexicographic|radial|strips (default auto)
      --threads N         threads for --order strips/auto, for reading and for
                          formatting text output (default: the hardware's thread
                          count; the output does not depend on it)
      --strip-points N    points per strip (default: chosen by input size); strips
                          grow until their points are not all on one line
      --strip-tiles N     cut each strip across into N tiles of --strip-points
                          points (strips of N times as many); 1: plain strips;
                          default: chosen by input size
  -f, --format FORMAT     json|ele|off|svg|geojson|wkt|ply|ply-ascii
      --input-format FMT  xy|json|node|f64|geojson
      --columns X,Y[,Z]   xy input: the fields holding x and y, and z if a third is
                          given, by number from 1 ("3,4,5") or by header name
                          ("lon,lat,height")
      --z-property NAME   geojson input: z is the feature's property NAME (a
                          number) instead of the position's third coordinate
      --constraints       read segments (and holes) too: see Constraints above
      --fill RULE         which triangles of a constrained run are written: even-odd,
                          non-zero, enclosed or all (see Constraints above)
      --certify           check the result with exact predicates before writing it
                          (exidel certify's checks); a finding is an error: exit
                          status 1, findings on standard error, no output written
      --stats             print one JSON object on standard error, also when the
                          triangulation fails: sizes, kernel, "algorithm",
                          "strategy" (the order that ran; null for an algorithm
                          without orders), "strips", "threads" (the threads that
                          worked: 1 unless strips ran), the algorithm's
                          counters, "failure" (null or its kind and message) and the
                          times "read_ms", "triangulate_ms" (the triangulation
                          alone), "certify_ms", "write_ms" and "total_ms" (from
                          start to end, including the temporary file and the
                          rename). Counters are collected only with --stats
                          (otherwise the run is not instrumented)
  -q, --quiet             no progress line and no notes on standard error
  -h, --help              show this help

Progress: on a terminal, runs longer than a second show their step on standard
error. Notes: input that is all on one line, or has fewer than three distinct
points, has no triangles; a one-line note on standard error says so.

Errors: malformed input stops with "exidel: line N: <reason>" (f64: "byte offset N")
and exit status 1; a file that cannot be read says why ("No such file or
directory"); a triangulation that an inexact kernel made inconsistent stops with
"exidel: triangulation failed: <where>: <what>" and exit status 1. No output is
written in any of these cases.

Exit status: 0 success, 1 bad input, failed triangulation or I/O error, 2 bad options.

Algorithms:
)";

struct Options : PointCommand {
    delaunay::InCirclePolicy incircle = delaunay::InCirclePolicy::determinant;
    delaunay::Strategy strategy = delaunay::Strategy::automatic;
    std::size_t strip_points = 0;
    std::size_t strip_tiles = 0;
    std::optional<io::TriangulationFormat> format;
    bool certify = false;
    bool constraints = false;
    std::optional<delaunay::FillRule> fill;
};

std::string_view policy_name(delaunay::InCirclePolicy p) {
    return p == delaunay::InCirclePolicy::cosine ? "cosine" : "determinant";
}

bool takes_order(delaunay::Algorithm a) {
    for (const delaunay::AlgorithmInfo& info : delaunay::algorithms()) {
        if (info.id == a) return info.takes_order;
    }
    return false;
}

// One JSON object on one line, keys in a fixed order (nlohmann's ordered_json).
void print_stats(std::ostream& err, std::size_t points, const delaunay::Result& r,
                 const std::string& kernel, const Options& o, const StepTimes& times,
                 double certify_ms) {
    const delaunay::Triangulation& t = r.triangulation;
    nlohmann::ordered_json counters;
    r.counters.for_each([&](std::string_view name, std::uint64_t v) { counters[name] = v; });
    counters["flips"] = r.counters.flips();
    nlohmann::ordered_json failure;  // null when the run succeeded
    if (r.failure) {
        failure = {{"kind", delaunay::to_string(r.failure->kind)}, {"message", r.failure->message}};
    }
    // Only the strips strategy runs on several threads, one strip or merge per thread.
    const std::size_t threads =
        r.strategy == delaunay::Strategy::strips ? std::min<std::size_t>(o.threads, r.strips) : 1;
    const bool ok = r.ok();
    nlohmann::ordered_json stats{
        {"points", points},
        {"vertices", ok ? points - t.duplicates.size() : 0},
        {"duplicates", t.duplicates.size()},
        {"triangles", t.triangle_count()},
        {"hull_size", t.hull.size()},
        {"collinear", t.collinear},
        {"kernel", kernel},
        {"incircle", policy_name(o.incircle)},
        {"algorithm", delaunay::to_string(r.algorithm)},
        // null for an algorithm that takes no order (it runs as it runs).
        {"strategy", takes_order(r.algorithm)
                         ? nlohmann::ordered_json(delaunay::to_string(r.strategy))
                         : nlohmann::ordered_json()},
        {"strips", r.strips},
        {"cavity_pieces", r.cavity_pieces},
        {"threads", threads},
        {"instrumentation", "counters"},
        {"counters", counters},
        {"failure", failure},
    };
    err << stats_line(with_times(stats, times, certify_ms));
}

// Are `a` and `b` the same existing file?
bool same_file(const std::string& a, const std::string& b) {
    struct stat sa {};
    struct stat sb {};
    return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

int run(const Options& o, const CommandLine& cli) {
    const Clock::time_point run_start = Clock::now();
    std::string error;
    const std::optional<AnyKernel> kernel = o.checked_kernel(error);
    if (!kernel) return cli.usage_error(error);
    const std::optional<io::TriangulationFormat> format = output_format(
        o.format, o.output, io::TriangulationFormat::json, io::triangulation_format_from_path,
        ".json .ele .off .svg .geojson .wkt .ply .poly", error);
    if (!format) return cli.usage_error(error);
    // Constrained mode: asked for, or a .poly (Triangle's -p: a .poly is read for its segments).
    const io::PointFormat input_format = o.input.resolved_format();
    const bool constrained = o.constraints || input_format == io::PointFormat::poly;
    if (constrained && input_format != io::PointFormat::poly &&
        input_format != io::PointFormat::geojson && input_format != io::PointFormat::json) {
        return cli.usage_error(
            "--constraints reads segments from poly, geojson or json input, not " +
            std::string(io::to_string(input_format)));
    }
    if (constrained && o.input.z_property) {
        return cli.usage_error(
            "--z-property does not apply with --constraints (z is the "
            "positions' third coordinate)");
    }
    if (!constrained && o.fill) return cli.usage_error("--fill applies with --constraints only");

    // The output files exist (as temporaries) from here on, removed again on any failure.
    std::optional<PendingFile> output, node_output;
    if (!o.open_output(output)) return exit_failure;
    // A device or a pipe as the output (-o /dev/null --format ele) gets no .node beside it:
    // that would be a new regular file in /dev.
    if (output && *format == io::TriangulationFormat::ele && !output->in_place()) {
        const std::string& out = *o.output;
        const std::string node =
            (out.ends_with(".ele") ? out.substr(0, out.size() - 4) : out) + ".node";
        const bool opened = reported([&] {
            if (o.input.from_stdin() || !same_file(node, *o.input.path)) node_output.emplace(node);
        });
        if (!opened) return exit_failure;
    }
    // The triangulation (with constraints: its start). Counters only when asked for, so a
    // plain run is the uninstrumented algorithm.
    const delaunay::Options options = delaunay::Options{}
                                          .with_algorithm(o.algorithm)
                                          .with_incircle(o.incircle)
                                          .with_strategy(o.strategy)
                                          .with_threads(o.threads)
                                          .with_strip_points(o.strip_points)
                                          .with_strip_tiles(o.strip_tiles);
    if (constrained) {
        const ConstrainedSettings settings{o.fill, *format, options, o.certify};
        return run_constrained(o, settings, *kernel, run_start, output, node_output);
    }
    PointRun steps(o, run_start);
    double certify_ms = 0;

    const std::optional<io::PointFile> input = steps.read();
    if (!input) return exit_failure;
    const std::vector<Point2>& points = input->points;

    // Triangulate: the only timed step.
    const Triangulated triangulated = steps.triangulate(*kernel, points, options, o.stats);
    const delaunay::Result& result = triangulated.result;
    const auto finish = [&](int status) {
        return steps.finish(status, [&] {
            print_stats(std::cerr, points.size(), result, triangulated.kernel_name, o, steps.times,
                        certify_ms);
        });
    };
    if (!result.ok()) return finish(exit_failure);
    const delaunay::Triangulation& tri = result.triangulation;

    if (o.certify) {
        steps.progress.phase("certifying " + std::to_string(tri.triangle_count()) + " triangles");
        const Clock::time_point start = Clock::now();
        const delaunay::Certificate certificate = delaunay::certify(points, tri);
        certify_ms = ms_since(start);
        if (!certificate.ok()) {
            steps.progress.stop();
            std::cerr << "exidel: the result is not the Delaunay triangulation of the input ("
                      << certificate.total_findings << " findings; nothing written):\n";
            print_findings(std::cerr, certificate);
            return finish(exit_failure);
        }
    }

    const io::WriteOptions write_options{input->index_base, o.threads, input->z};
    std::vector<BesideFile> beside;
    if (node_output) {
        beside.push_back({*node_output, [&](std::ostream& out) {
                              io::write_points(out, points, io::PointFormat::node,
                                               input->index_base, o.threads);
                          }});
    }
    const bool written = steps.write(
        output,
        [&](std::ostream& out) {
            io::write_triangulation(out, points, tri, *format, write_options);
        },
        beside);
    if (!written) return finish(exit_failure);
    if (!o.quiet && tri.collinear) {
        const std::size_t distinct = points.size() - tri.duplicates.size();
        std::cerr << "exidel: note: no triangles: "
                  << (distinct < 3 ? "fewer than three distinct points ("
                                   : "the distinct points are all on one line (")
                  << distinct << "); the hull lists them in order\n";
    }
    if (!o.quiet && o.certify) {
        std::cerr << "exidel: certified: the Delaunay triangulation of the input (exact checks)\n";
    }
    return finish(exit_ok);
}

}  // namespace

int triangulate_command(std::span<const std::string_view> args) {
    using delaunay::InCirclePolicy, delaunay::Strategy;
    CommandLine cli("triangulate",
                    point_command_help(triangulate_help_head, triangulate_help_tail));
    CLI::App& app = cli.app;
    Options o;
    o.add_input_output_options(app);
    add_parsed(app, "--incircle", "determinant or cosine", o.incircle,
               [](const std::string& v) -> std::optional<InCirclePolicy> {
                   if (v == "determinant") return InCirclePolicy::determinant;
                   if (v == "cosine") return InCirclePolicy::cosine;
                   return {};
               });
    add_parsed(
        app, "--order", "auto, lexicographic, radial or strips", o.strategy,
        [](const std::string& v) -> std::optional<Strategy> {
            if (v == "auto") return Strategy::automatic;
            for (const Strategy s : {Strategy::lexicographic, Strategy::radial, Strategy::strips}) {
                if (v == delaunay::to_string(s)) return s;
            }
            return {};
        });
    o.add_threads_option(app);
    add_parsed(app, "--strip-points",
               "a whole number from 1 to " + std::to_string(delaunay::detail::max_points),
               o.strip_points,
               [](const std::string& v) { return whole_number(v, delaunay::detail::max_points); });
    add_parsed(app, "--strip-tiles",
               "a whole number from 1 to " + std::to_string(delaunay::detail::max_points),
               o.strip_tiles,
               [](const std::string& v) { return whole_number(v, delaunay::detail::max_points); });
    add_parsed(app, "-f,--format", "json, ele, off, svg, geojson, wkt, ply, ply-ascii or poly",
               o.format, io::triangulation_format_from_name);
    o.input.add_format_options(app);
    o.input.add_z_property_option(app);
    app.add_flag("--certify", o.certify);
    app.add_flag("--constraints", o.constraints);
    add_parsed(app, "--fill", "even-odd, non-zero, enclosed or all", o.fill, fill_rule_from_name);
    o.add_report_options(app);
    if (const std::optional<int> status = o.parse(cli, args)) return *status;
    return run(o, cli);
}

}  // namespace exidel::cli
