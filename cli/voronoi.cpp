// exidel CLI: `exidel voronoi`, points in, Voronoi diagram out.
//
// As `exidel triangulate` (triangulate.cpp), one way: create the output's temporary file
// -> read the input -> triangulate -> the Voronoi diagram (lib/delaunay, voronoi.hpp) ->
// optionally clip it to a box -> write (lib/io, voronoi.hpp) into the temporary file,
// renamed into place on success (or stdout). No failure leaves an output file behind.
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "common.hpp"
#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/delaunay/furthest.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/io/number.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/voronoi.hpp"
#include "options.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view voronoi_help_head =
    R"(usage: exidel voronoi [-i FILE] [-o FILE] [--kernel NAME] [--algorithm NAME]
                      [--format json|svg|geojson|wkt]
                      [--clip XMIN YMIN XMAX YMAX | --unclipped [--furthest-site]]
                      [--input-format xy|json|node|f64|geojson] [--columns X,Y]
                      [--threads N] [--stats] [--quiet] [FILE]

Computes the Voronoi diagram of a set of points from their Delaunay triangulation
(as exidel triangulate computes it). Every Voronoi vertex is the centre of a maximal
set of cocircular Delaunay triangles, decided by the kernel's in-circle test (exact
with an exact kernel, never a tolerance), so that four or more cocircular points
give one vertex, not several a rounding apart; its coordinates are the doubles
nearest to the exact centre. The diagram is clipped to a box (in exact rationals),
so that every cell is a polygon: by default the sites' bounding box widened by 10%
of its larger side on every side (1 unit for a single point), or --clip's box;
--unclipped writes the whole diagram instead (json and svg only). --furthest-site
(with --unclipped) computes the furthest-site diagram instead (scipy's and qhull's
furthest_site): the dual of the furthest-site triangulation, where the region of a point
is where it is the furthest; only the corners of the convex hull have regions, each
unbounded, its rays the inward normals of the hull edges at the corner.

)";

constexpr std::string_view voronoi_help_tail =
    R"(rounded to the nearest double. NaN and infinity are errors; a duplicate point has
its twin's cell. An empty input is 0 points.

Output (-o FILE, or standard output). The format is --format, else the extension of
-o (.json .svg .geojson .wkt; another extension is an error), else json. Sites are
input indices, 0-based. Coordinates are the shortest decimals that read back as the
same doubles. Longitude and latitude are taken as a plane (no antimeridian or pole
handling).
  json  {"vertices": [[x, y], ...], "vertex_sites": [[i, j, k, ...], ...],
         "cells": [[v, ...], ...], "unbounded": [bool, ...]}, one key per line:
          vertices      every coordinate the shortest decimal that reads back as
                        the same double (negative zero as -0.0)
          vertex_sites  the input indices exactly equidistant from each vertex
                        (three or more; duplicates after their twin),
                        counter-clockwise from the smallest
          cells         for every input index, the indices of its cell's vertices,
                        counter-clockwise (a duplicate repeats its twin's cell)
          unbounded     for every input index, whether its cell is unbounded
        Clipped (the default), every cell is its polygon inside the box, possibly
        empty (with --clip); the Voronoi vertices in the box come first, then the
        points the box adds (where an edge leaves the box, and its corners), their
        sites the one or two sites whose cells have them as a corner; "unbounded"
        is the unclipped cell's. With --unclipped, input on one line (or of fewer
        than three distinct points) has no vertices and empty cells: the cells are
        strips between parallel bisectors
  svg   a picture in the data's coordinates (the viewBox is the box in input
        units, y flipped by a scale(1,-1) group): the Voronoi edges, the box, the
        vertices (merged cocircular ones, of four or more sites, on orange discs)
        and the sites inside the box. With --unclipped it spans the sites and the
        vertices, and draws the rays of unbounded cells to its edge (the bisectors
        for input on one line)
  geojson  RFC 7946 FeatureCollection with the box as "bbox": feature i is site
        i, properties {"site": i}, geometry the Polygon of its clipped cell
        (counter-clockwise, closed), or null when the cell misses the box; a
        duplicate has its twin's polygon
  wkt   one GEOMETRYCOLLECTION of one POLYGON per site, in input order (POLYGON
        EMPTY when the cell misses the box)

Options:
  -i, --input FILE        read points from FILE ('-' for standard input)
  -o, --output FILE       write the diagram to FILE ('-' for standard output);
                          written to a temporary file in the same directory and
                          renamed on success, so a failed or interrupted run
                          (Ctrl-C, SIGTERM) leaves no FILE and no temporary
  -k, --kernel NAME       one of the kernels listed at the end (default: adaptive).
                          With adaptive, exact or exact-cpp the triangulation and the
                          merging of cocircular vertices are exact; the others may
                          fail or group vertices wrongly (the vertices' coordinates
                          are correctly rounded with any kernel)
  -a, --algorithm NAME    one of the algorithms listed at the end (default: external)
      --threads N         threads for reading and triangulating (default: the
                          hardware's thread count); the output does not depend on it
  -f, --format FORMAT     json|svg|geojson|wkt
      --clip XMIN YMIN XMAX YMAX
                          clip the diagram to this box instead of the default one:
                          four finite numbers with XMIN < XMAX and YMIN < YMAX
                          (decimal or hex floats)
      --unclipped         the whole diagram, unbounded cells included (json, svg)
      --furthest-site     the furthest-site diagram (with --unclipped)
      --input-format FMT  xy|json|node|f64|geojson
      --columns X,Y       xy input: the fields holding x and y, by number from 1
                          ("3,4") or by header name ("lon,lat")
      --stats             print one JSON object on standard error, also when the
                          run fails after reading: sizes ("points", "vertices" of
                          the diagram, "clipped_vertices"), "kernel", "algorithm",
                          "stage_counts" (the circumcentres each stage of the
                          correctly rounded construction decided: "floating",
                          "double_word", "exact"), "cocircular_tests" and
                          "cocircular_merges" (in-circle tests on triangles with
                          bit-identical centres, and those that shared a circle),
                          "failure" (null or its step, kind and message) and the
                          times "read_ms", "triangulate_ms", "voronoi_ms",
                          "clip_ms", "write_ms" and "total_ms"
  -q, --quiet             no progress line and no notes on standard error
  -h, --help              show this help

Progress: on a terminal, runs longer than a second show their step on standard
error. Notes: input that is all on one line, or has fewer than three distinct
points, has no Voronoi vertices; a one-line note on standard error says so.

Errors: malformed input stops with "exidel: line N: <reason>" (f64: "byte offset N")
and exit status 1; a file that cannot be read says why; a failed triangulation
stops with "exidel: triangulation failed: <where>: <what>"; a Voronoi vertex that
is not a finite point (a nearly flat triangle of huge coordinates, whose centre is
beyond the largest double) stops with "exidel: voronoi: <what>", exit status 1. No
output is written in any of these cases.

Exit status: 0 success, 1 bad input, failed triangulation or diagram, or I/O error,
2 bad options.

Algorithms:
)";

struct Options : PointCommand {
    std::optional<io::VoronoiFormat> format;
    std::optional<delaunay::Box> clip;
    bool unclipped = false;
    bool furthest = false;  // the furthest-site diagram
};

// --clip's four words as a box: finite numbers with xmin < xmax and ymin < ymax.
delaunay::Box parse_box(const std::vector<std::string>& words) {
    std::string given;
    for (const std::string& w : words) given += (given.empty() ? "" : " ") + w;
    const auto fail = [&](const std::string& why) {
        return std::invalid_argument("--clip XMIN YMIN XMAX YMAX: " + why + " (got '" + given +
                                     "')");
    };
    if (words.size() != 4) throw fail("four numbers are needed");
    double v[4];
    for (int k = 0; k < 4; ++k) {
        const io::ParsedNumber n = io::parse_double(words[static_cast<std::size_t>(k)]);
        if (!n.value) throw fail(n.error);
        v[k] = *n.value;
    }
    if (!(v[0] < v[2])) throw fail("XMIN must be below XMAX");
    if (!(v[1] < v[3])) throw fail("YMIN must be below YMAX");
    return {v[0], v[1], v[2], v[3]};
}

// The time spent in the steps of its own, in milliseconds.
struct Times {
    double voronoi = 0, clip = 0;
};

// What went wrong after reading, for --stats.
struct Failure {
    std::string step, kind, message;
};

// One JSON object on one line, keys in a fixed order.
void print_stats(std::ostream& err, std::size_t points, const Triangulated& t, bool furthest,
                 const delaunay::VoronoiDiagram& d, const delaunay::ClippedVoronoi* clipped,
                 const std::optional<Failure>& failure, const StepTimes& steps,
                 const Times& times) {
    const delaunay::Triangulation& tri = t.result.triangulation;
    nlohmann::ordered_json failed;  // null when the run succeeded
    if (failure) {
        failed = {{"step", failure->step}, {"kind", failure->kind}, {"message", failure->message}};
    }
    using exidel::CircumcenterStage;
    const auto stage = [&](CircumcenterStage s) { return d.stage_counts[static_cast<int>(s)]; };
    const nlohmann::ordered_json stats{
        {"points", points},
        {"duplicates", tri.duplicates.size()},
        {"triangles", tri.triangle_count()},
        {"collinear", tri.collinear},
        {"vertices", d.vertex_count()},
        {"clipped_vertices",
         clipped ? nlohmann::ordered_json(clipped->vertex_count()) : nlohmann::ordered_json()},
        {"kernel", t.kernel_name},
        {"algorithm",
         furthest ? std::string_view("furthest-site") : delaunay::to_string(t.result.algorithm)},
        {"stage_counts",
         {{"floating", stage(CircumcenterStage::floating)},
          {"double_word", stage(CircumcenterStage::double_word)},
          {"exact", stage(CircumcenterStage::exact)}}},
        {"cocircular_tests", d.cocircular_tests},
        {"cocircular_merges", d.cocircular_merges},
        {"failure", failed},
        {"read_ms", stats_ms(steps.read)},
        {"triangulate_ms", stats_ms(steps.triangulate)},
        {"voronoi_ms", stats_ms(times.voronoi)},
        {"clip_ms", stats_ms(times.clip)},
        {"write_ms", stats_ms(steps.write)},
        {"total_ms", stats_ms(steps.total)},
    };
    err << stats_line(stats);
}

int run(const Options& o, const CommandLine& cli) {
    const Clock::time_point run_start = Clock::now();
    std::string error;
    const std::optional<AnyKernel> kernel = o.checked_kernel(error);
    if (!kernel) return cli.usage_error(error);
    const std::optional<io::VoronoiFormat> format =
        output_format(o.format, o.output, io::VoronoiFormat::json, io::voronoi_format_from_path,
                      ".json .svg .geojson .wkt", error);
    if (!format) return cli.usage_error(error);
    if (o.unclipped && o.clip) return cli.usage_error("--clip and --unclipped exclude each other");
    if (o.furthest && !o.unclipped) {
        return cli.usage_error(
            "--furthest-site writes the whole diagram: give --unclipped (clipping is for the "
            "nearest-site diagram)");
    }
    if (o.unclipped && !io::holds_unbounded_cells(*format)) {
        return cli.usage_error("--unclipped: the " + std::string(io::to_string(*format)) +
                               " format holds polygons, not unbounded cells (json or svg)");
    }

    // The output file exists (as a temporary) from here on, removed again on any failure.
    std::optional<PendingFile> output;
    if (!o.open_output(output)) return exit_failure;
    PointRun steps(o, run_start);
    Times times;

    const std::optional<io::PointFile> input = steps.read();
    if (!input) return exit_failure;
    const std::vector<Point2>& points = input->points;

    const delaunay::Options options =
        delaunay::Options{}.with_algorithm(o.algorithm).with_threads(o.threads);
    // --furthest-site: the furthest-site triangulation (furthest.hpp) instead.
    const auto furthest = [&](const auto& k) {
        return delaunay::furthest_site_triangulation(points, k).to_result();
    };
    const Triangulated triangulated =
        o.furthest ? steps.triangulate_with(*kernel, points.size(), " (furthest site)", furthest)
                   : steps.triangulate(*kernel, points, options, false);
    const delaunay::Triangulation& tri = triangulated.result.triangulation;
    delaunay::VoronoiDiagram diagram;
    std::optional<delaunay::ClippedVoronoi> clipped;
    std::optional<Failure> failure;
    const auto finish = [&](int status) {
        return steps.finish(status, [&] {
            print_stats(std::cerr, points.size(), triangulated, o.furthest, diagram,
                        clipped ? &*clipped : nullptr, failure, steps.times, times);
        });
    };
    if (!triangulated.result.ok()) {
        const delaunay::Failure& f = *triangulated.result.failure;
        failure = Failure{"triangulate", std::string(delaunay::to_string(f.kind)), f.message};
        return finish(exit_failure);
    }

    // The diagram, with the kernel that triangulated (its in-circle test merges
    // cocircular triangles).
    steps.progress.phase("computing the Voronoi diagram");
    const Clock::time_point voronoi_start = Clock::now();
    try {
        std::visit(
            [&](const auto& k) {
                diagram = o.furthest ? delaunay::furthest_site_voronoi(points, tri, k)
                                     : delaunay::voronoi(points, tri, k);
            },
            *kernel);
    } catch (const delaunay::VoronoiError& e) {
        steps.progress.stop();
        failure = Failure{"voronoi", std::string(to_string(e.status())), e.what()};
        std::cerr << "exidel: voronoi: " << e.what();
        if (e.status() == CircumcenterStatus::collinear && !triangulated.exact_kernel) {
            std::cerr << ". The " << triangulated.kernel_name << " kernel is not exact; an exact "
                      << "kernel (adaptive, the default) never makes a flat triangle";
        }
        std::cerr << '\n';
        return finish(exit_failure);
    }
    times.voronoi = ms_since(voronoi_start);

    const delaunay::Box box = o.clip ? *o.clip : io::default_clip_box(points);
    if (!o.unclipped) {
        steps.progress.phase("clipping " + std::to_string(points.size()) + " cells");
        const Clock::time_point start = Clock::now();
        clipped = delaunay::clip(diagram, points, tri, box);
        times.clip = ms_since(start);
    }

    const bool written = steps.write(output, [&](std::ostream& out) {
        if (clipped) {
            io::write_voronoi(out, points, *clipped, box, *format);
        } else {
            io::write_voronoi(out, points, diagram, *format);
        }
    });
    if (!written) return finish(exit_failure);
    if (!o.quiet && diagram.collinear && o.furthest) {
        std::cerr << "exidel: note: no Voronoi vertices: fewer than three extreme points; the "
                     "ends of the line have the half-planes of their bisector\n";
    } else if (!o.quiet && diagram.collinear) {
        const std::size_t distinct = points.size() - tri.duplicates.size();
        std::cerr << "exidel: note: no Voronoi vertices: ";
        if (distinct == 0) {
            std::cerr << "no points\n";
        } else if (distinct == 1) {
            std::cerr << "one distinct point, whose cell is the whole plane\n";
        } else if (distinct == 2) {
            std::cerr << "two distinct points, whose cells are the half-planes of their bisector\n";
        } else {
            std::cerr << "the distinct points are all on one line (" << distinct
                      << "); the cells are bounded by parallel bisectors\n";
        }
    }
    return finish(exit_ok);
}

}  // namespace

int voronoi_command(std::span<const std::string_view> args) {
    CommandLine cli("voronoi", point_command_help(voronoi_help_head, voronoi_help_tail));
    CLI::App& app = cli.app;
    Options o;
    o.add_input_output_options(app);
    o.add_threads_option(app);
    add_parsed(app, "-f,--format", "json, svg, geojson or wkt", o.format,
               io::voronoi_format_from_name);
    app.add_option_function<std::vector<std::string>>(
           "--clip", [&](const std::vector<std::string>& words) { o.clip = parse_box(words); })
        ->expected(4);
    app.add_flag("--unclipped", o.unclipped);
    app.add_flag("--furthest-site", o.furthest);
    o.input.add_format_options(app);
    o.add_report_options(app);
    if (const std::optional<int> status = o.parse(cli, args)) return *status;
    return run(o, cli);
}

}  // namespace exidel::cli
