// exidel CLI: `exidel certify POINTS TRIANGULATION`, the exact certifier on files: is this
// the Delaunay triangulation of these points? For checking any triangulator's output
// (exidel's json, delaunator's arrays, scipy's simplices, Triangle's .ele, CGAL's OFF)
// with exact predicates: read (lib/io, triangulation_input.hpp) -> normalise the
// producer's conventions (delaunay::normalize) -> certify -> report.
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "constrained.hpp"
#include "constrained_certify.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation_input.hpp"
#include "options.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view certify_help =
    R"(usage: exidel certify POINTS TRIANGULATION [--input-format xy|json|node|f64]
                      [--columns X,Y] [--format json|ele|off|simplices] [--all]
                      [--json] [--strict] [--quiet]
       exidel certify --constraints CONSTRAINTS TRIANGULATION
                      [--input-format poly|geojson|json] [--format json|ele|off]
                      [--fill even-odd|non-zero|enclosed|all|any]
                      [--tolerate-crossings] [--all] [--json] [--strict] [--quiet]

Checks, with exact predicates, whether TRIANGULATION is the Delaunay triangulation of
the points in POINTS, and says what is wrong and where when it is not. The checks, in
order: array shapes and index ranges; twins; every triangle strictly counter-clockwise;
the boundary is one convex cycle winding once, equal to the hull; every distinct point
is a vertex, duplicates listed; Euler's count; every interior edge locally Delaunay.

POINTS is read as by exidel triangulate (the format from --input-format, else the
extension; --columns for wider CSV). TRIANGULATION is, by --format or its extension:
  json       delaunator's arrays as exidel triangulate writes them: {"triangles",
             "halfedges", "hull", "duplicates"} with input indices; only "triangles"
             is required, and delaunator's "coords" may be there (it must equal the
             points). Or rows [[i, j, k], ...]: scipy's simplices.tolist()
  ele        Triangle's .ele, counted from the first triangle's number (0 or 1)
  off        OFF, as CGAL or exidel triangulate write it: vertices are matched to
             the points by their exact coordinates, in any order
  simplices  text, three vertex indices per line (numpy.savetxt of scipy's
             simplices, any number format that holds whole numbers)
What a file does not hold is derived: twins from shared edges, the hull from the
boundary, duplicates from the points. Producers differ in conventions that do not
decide whether a triangulation is Delaunay, and these are normalised first (unless
--strict), each with a note on standard error: a later copy of a repeated point
stands for its first occurrence; clockwise triangles (delaunator in y-up
coordinates, qhull) are turned counter-clockwise, and their twins with them; a hull
running clockwise or starting anywhere is reversed and rotated to start at its
lexicographically smallest point.

Output: on standard output, one line per finding, "KIND: where and what", naming the
triangle (its row in the file, 0-based), the edge and the points (input indices; a
repeated point by its first occurrence):
  not_ccw: triangle 18 (4, 9, 2) is clockwise
  not_delaunay: edge (4, 9) of triangle 18 (4, 9, 2) is not locally Delaunay: point
  31 of triangle 40 is strictly inside the circumcircle
at most 64 of them unless --all, then a last line with the verdict:
  certified: the Delaunay triangulation of N points (V distinct), T triangles
  not certified: F findings
With --json, one JSON object instead: {"certified", "points", "distinct",
"triangles", "total_findings", "notes": [...], "findings": [{"kind", "message",
"triangle", "points", "index", "other"}, ...]} with every finding ("triangle" -1 when
a finding concerns none; "index" and "other" as in the C++ Finding).

With --constraints: whether TRIANGULATION is the constrained Delaunay triangulation of
the points and segments of CONSTRAINTS (the input of exidel triangulate --constraints or
Triangle's -p: .poly, .geojson, .json), or the domain of it such a run writes.
TRIANGULATION is exidel's constrained json (its vertices: the input points, then
"added_points"; its chains and crossings as written), an .ele with the .node beside it
(same stem; every vertex, the input's first, then the added points: Triangle's -p
output or exidel's -o X.ele), or an OFF of every vertex (an input point recognised by
its exact coordinates, the others added points). A peer's chains are derived: segment
(a, b) runs through the input points exactly on it and the added points within
chain_tolerance of it, in order along it; an added point is the crossing of the first
two segments through it. The file's triangles are completed to the convex hull with
the constrained Delaunay triangulation of the same vertices and pieces outside the
domain, and the whole is certified exactly (every triangle counter-clockwise, one
convex boundary winding once, every vertex used, Euler's count, every chain's pieces
edges, every non-piece edge locally Delaunay, every added point the correctly rounded
crossing of its segments); then the file's triangles must be exactly the domain that
--fill (default as for triangulate: enclosed for .poly, even-odd otherwise) and the
hole seeds define, or with --fill any be bounded by pieces and the hull. Findings in
triangles numbered from the file's count on concern the completion.
exidel's added points are the correctly rounded crossings (each coordinate the double
nearest to the exact crossing): a peer that computes crossings otherwise gets
added_point_wrong findings, or with --tolerate-crossings a note for each added point
within chain_tolerance of both its segments. Other findings: twin_mismatch (json
halfedges), domain_mismatch (the file's triangles are not the domain), and those of
certify_constrained (chain_broken: a piece is not an edge, constraints_mismatch, ...).
Verdict: "certified: the constrained Delaunay triangulation of N points and S segments
(A added points), T triangles, the whole convex hull | of the domain (...), fill F";
--json adds "segments", "added_points", "completion_triangles", "fill".

Exit status: 0 certified, 1 a finding, or a file that cannot be read (the reason on
standard error, with its line), 2 bad options.

Options:
      --constraints FILE  certify a constrained triangulation of FILE's points and
                          segments (.poly, .geojson, .json)
      --input-format FMT  xy|json|node|f64 (POINTS); poly|geojson|json (CONSTRAINTS)
      --fill RULE         --constraints: the domain the file must be: even-odd,
                          non-zero, enclosed, all (then the hole seeds), or any
                          union of regions bounded by pieces and the hull
      --tolerate-crossings  --constraints: an added point within chain_tolerance of
                          both its segments is a note, not a finding
      --columns X,Y       xy POINTS: the fields holding x and y, by number or name
  -f, --format FMT        json|ele|off|simplices (TRIANGULATION)
      --all               print every finding, not the first 64
      --json              write the verdict and every finding as one JSON object
      --strict            normalise nothing: hold the file to exidel's own layout
                          (counter-clockwise triangles, the hull from its smallest
                          point, repeated points by their first occurrence)
  -q, --quiet             no notes on standard error
  -h, --help              show this help
)";

struct Settings {
    std::optional<io::PointFormat> input_format;
    std::optional<io::ProducedFormat> format;
    std::optional<io::Columns> columns;
    bool all = false, json = false, strict = false, quiet = false;
};

nlohmann::ordered_json to_json(const delaunay::Certificate& c, std::size_t points,
                               std::size_t distinct, std::size_t triangles,
                               const std::vector<std::string>& notes) {
    nlohmann::ordered_json findings = nlohmann::ordered_json::array();
    for (const delaunay::Finding& f : c.findings) {
        findings.push_back({{"kind", delaunay::to_string(f.kind)},
                            {"message", f.message},
                            {"triangle", f.triangle},
                            {"points", f.points},
                            {"index", f.index},
                            {"other", f.other}});
    }
    return {{"certified", c.ok()},
            {"points", points},
            {"distinct", distinct},
            {"triangles", triangles},
            {"total_findings", c.total_findings},
            {"notes", notes},
            {"findings", std::move(findings)}};
}

int run(const std::string& points_path, const std::string& tri_path, const Settings& s,
        const CommandLine& cli) {
    const io::PointFormat pf = s.input_format.value_or(io::point_format_from_path(points_path));
    if (const std::optional<std::string> e = columns_error(s.columns, pf)) {
        return cli.usage_error(*e);
    }
    const std::optional<io::ProducedFormat> tf =
        s.format ? s.format : io::produced_format_from_path(tri_path);
    if (!tf) {
        return cli.usage_error("cannot tell the format of '" + tri_path +
                               "' from its extension: give --format json|ele|off|simplices");
    }
    std::vector<Point2> points;
    delaunay::ProducedTriangulation produced;
    std::string reading = points_path;
    try {
        points =
            io::parse_point_file(io::FileBytes(points_path).view(), pf, io::ReadOptions{s.columns})
                .points;
        reading = tri_path;
        produced = io::read_produced(io::FileBytes(tri_path).view(), *tf, points);
    } catch (const io::ReadError& e) {
        std::cerr << "exidel: " << reading << ": " << e.what() << '\n';
        return exit_failure;
    } catch (const std::runtime_error& e) {
        std::cerr << "exidel: " << e.what() << '\n';
        return exit_failure;
    }
    delaunay::Normalization normalization;
    const delaunay::Triangulation tri =
        delaunay::normalize(points, std::move(produced), &normalization, s.strict);
    const std::vector<std::string> notes = normalization.notes();
    if (!s.quiet) {
        for (const std::string& n : notes) std::cerr << "exidel: note: " << n << '\n';
    }
    delaunay::CertifyOptions options;
    if (s.all || s.json) options.max_findings = std::numeric_limits<std::size_t>::max();
    const delaunay::Certificate c = delaunay::certify(points, tri, options);
    const std::size_t distinct = points.size() - tri.duplicates.size();
    if (s.json) {
        std::cout << to_json(c, points.size(), distinct, tri.triangle_count(), notes).dump(1)
                  << '\n';
        return c.ok() ? exit_ok : exit_failure;
    }
    for (const delaunay::Finding& f : c.findings) {
        std::cout << delaunay::to_string(f.kind) << ": " << f.message << '\n';
    }
    if (c.total_findings > c.findings.size()) {
        std::cout << "... and " << c.total_findings - c.findings.size()
                  << " more findings (--all prints every one)\n";
    }
    if (!c.ok()) {
        std::cout << "not certified: " << c.total_findings << " findings\n";
        return exit_failure;
    }
    std::cout << "certified: the Delaunay triangulation of " << points.size() << " points ("
              << distinct << " distinct), " << tri.triangle_count() << " triangles\n";
    return exit_ok;
}

}  // namespace

int certify_command(std::span<const std::string_view> args) {
    CommandLine cli("certify", std::string(certify_help));
    CLI::App& app = cli.app;
    std::vector<std::string> files;
    Settings s;
    app.add_option("FILES", files);
    add_point_format_option(app, s.input_format);
    add_parsed(app, "-f,--format", "json, ele, off or simplices", s.format,
               io::produced_format_from_name);
    add_columns_option(app, s.columns);
    app.add_flag("--all", s.all);
    app.add_flag("--json", s.json);
    app.add_flag("--strict", s.strict);
    app.add_flag("-q,--quiet", s.quiet);
    std::optional<std::string> constraints;
    ConstrainedCertifySettings c;
    app.add_option("--constraints", constraints);
    add_parsed(app, "--fill", "even-odd, non-zero, enclosed, all or any", c.fill,
               [&c](const std::string& v) -> std::optional<std::optional<delaunay::FillRule>> {
                   if (v == "any") {
                       c.any_domain = true;
                       return std::optional<delaunay::FillRule>{};
                   }
                   const std::optional<delaunay::FillRule> r = fill_rule_from_name(v);
                   if (!r) return std::nullopt;
                   c.any_domain = false;
                   return r;
               });
    app.add_flag("--tolerate-crossings", c.tolerate_crossings);
    if (const std::optional<int> status = cli.parse(args)) return *status;
    if (constraints) {
        if (files.size() != 1) {
            return cli.usage_error("with --constraints, expected one file, TRIANGULATION, got " +
                                   std::to_string(files.size()));
        }
        if (s.columns) return cli.usage_error("--columns does not apply to --constraints");
        c.input_format = s.input_format;
        c.format = s.format;
        c.all = s.all;
        c.json = s.json;
        c.strict = s.strict;
        c.quiet = s.quiet;
        return run_constrained_certify(*constraints, files[0], c, cli);
    }
    if (c.fill || c.any_domain || c.tolerate_crossings) {
        return cli.usage_error("--fill and --tolerate-crossings need --constraints");
    }
    if (files.size() != 2) {
        return cli.usage_error("expected two files, POINTS and TRIANGULATION, got " +
                               std::to_string(files.size()));
    }
    return run(files[0], files[1], s, cli);
}

}  // namespace exidel::cli
