// exidel CLI: `exidel triangulate`, points in, Delaunay triangulation out.
//
// Data flows one way: read the whole input (lib/io) -> triangulate (lib/delaunay, the one
// timed call) -> write to a temporary file renamed into place (or stdout). Nothing is
// written to the output until the triangulation exists, so bad input or a failed run
// leaves no output file behind.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/io/points.hpp"
#include "exidel/io/triangulation.hpp"
#include "options.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view triangulate_help_head =
    R"(usage: exidel triangulate [-i FILE] [-o FILE] [--kernel NAME] [--algorithm NAME]
                          [--incircle determinant|cosine] [--format json|ele|off|svg]
                          [--input-format xy|json|node|f64] [--stats]
                          [--order auto|lexicographic|radial|strips] [--threads N]
                          [--strip-points N]

Computes the Delaunay triangulation of a set of points, by default with the external
incremental algorithm (Cai 2025): each point is added outside the hull of the previous
ones, so no point location is needed. Its order of insertion (--order):
  lexicographic  the paper's: by x then y. The reference; quadratic on a sampled convex
                 curve inserted towards its vertex
  radial         by exact distance from a centre (ties by x then y)
  strips         vertical strips of --strip-points points, each radial, merged by the
                 Guibas-Stolfi zipper, on --threads threads
  auto           (default) radial below 32768 points, strips from there
Every order gives a Delaunay triangulation with an exact kernel, and the same one when
no four points are cocircular; the thread count never changes the output.

Input (-i FILE, or standard input when no file or '-' is given). The format is
--input-format, else the file's extension (.json json, .node node, .f64 f64),
else xy:
  xy    one point per line, "x y" or "x,y" (.txt .xy .csv); '#' starts a comment;
        the first line may be a header of two names ("x,y"), which is skipped
  json  [[x, y], [x, y], ...]
  node  Triangle's .node: "n 2 attributes markers", then "index x y [...]" lines
        (0- or 1-based); attributes and markers are checked and ignored
  f64   raw little-endian float64 pairs x0 y0 x1 y1 ...
Text coordinates are decimal or C99 hex floats (0x1.8p-3; json: decimal only),
rounded to the nearest double. NaN and infinity are errors; duplicates are kept
out of the triangulation and listed. An empty input is 0 points.

Output (-o FILE, or standard output). The format is --format, else the extension of
-o (.json .ele .off .svg), else json. Indices are 0-based input indices.
  json  {"triangles": [...], "halfedges": [...], "hull": [...], "duplicates": [...]}
        delaunator's arrays: triangles counter-clockwise, halfedges -1 on the
        boundary, hull counter-clockwise from the lexicographically smallest point
        (all distinct points in order when they are collinear)
  ele   Triangle's .ele: "ntriangles 3 0", then "t v0 v1 v2", 0-based
  off   OFF with z = 0 (every input point is a vertex, duplicates included)
  svg   a picture: triangles, hull in red, points; y up

Options:
  -i, --input FILE        read points from FILE ('-' for standard input)
  -o, --output FILE       write the triangulation to FILE ('-' for standard output);
                          written to a temporary file in the same directory and
                          renamed on success, so a failed run leaves no FILE
  -k, --kernel NAME       one of the kernels listed at the end (default: adaptive).
                          adaptive, exact and exact-cpp give the Delaunay
                          triangulation of every finite input; the others may give a
                          wrong one or fail
  -a, --algorithm NAME    one of the algorithms listed at the end (default: external)
      --incircle POLICY   determinant (default) or cosine (the paper's Section 5 test;
                          used by the insertions, the strips' merges always use the
                          determinant)
      --order ORDER       auto|lexicographic|radial|strips (default auto)
      --threads N         threads for --order strips/auto (default: the hardware's
                          thread count)
      --strip-points N    points per strip (default: chosen by input size); strips
                          grow until their points are not all on one line
  -f, --format FORMAT     json|ele|off|svg
      --input-format FMT  xy|json|node|f64
      --stats             print one JSON object on standard error: sizes, kernel,
                          "algorithm", "strategy" (the order that ran), "strips",
                          "threads",
                          the algorithm's counters and "triangulate_ms" (the time of
                          the triangulation alone; reading and writing are in
                          "read_ms" and "write_ms"). Counters are collected only with
                          --stats (otherwise the run is not instrumented)
  -h, --help              show this help

Errors: malformed input stops with "exidel: line N: <reason>" (f64: "byte offset N")
and exit status 1; a triangulation that an inexact kernel made inconsistent stops
with "exidel: triangulation failed: <reason>" and exit status 1. No output is
written in either case.

Exit status: 0 success, 1 bad input, failed triangulation or I/O error, 2 bad options.

Algorithms:
)";

std::string triangulate_help() {
    return std::string(triangulate_help_head) + delaunay::algorithm_help() + "\nKernels:\n" +
           kernel_help();
}

struct Options {
    std::optional<std::string> input;
    std::optional<std::string> output;
    std::string kernel = "adaptive";
    delaunay::InCirclePolicy incircle = delaunay::InCirclePolicy::determinant;
    delaunay::Algorithm algorithm = delaunay::Algorithm::external;
    delaunay::Strategy strategy = delaunay::Strategy::automatic;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::size_t strip_points = 0;
    std::optional<io::TriangulationFormat> format;
    std::optional<io::PointFormat> input_format;
    bool stats = false;
};

// Adds an option whose value `parse` turns into `target`; a value it rejects (returns
// nothing for) is a usage error "--NAME takes EXPECTED, got 'VALUE'".
template <class T, class Parse>
void add_parsed(CLI::App& app, const std::string& names, const std::string& expected, T& target,
                Parse parse) {
    const std::string name = names.substr(names.rfind(',') + 1);
    app.add_option_function<std::string>(names, [=, &target](const std::string& value) {
        const auto parsed = parse(value);
        if (!parsed) {
            throw std::invalid_argument(name + " takes " + expected + ", got '" + value + "'");
        }
        target = static_cast<T>(*parsed);
    });
}

// A whole number from 1 to `limit`.
std::optional<std::size_t> whole_number(const std::string& text, std::size_t limit) {
    std::size_t n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc{} || end != text.data() + text.size() || n == 0 || n > limit) return {};
    return n;
}

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string_view policy_name(delaunay::InCirclePolicy p) {
    return p == delaunay::InCirclePolicy::cosine ? "cosine" : "determinant";
}

// One JSON object on one line, keys in a fixed order (nlohmann's ordered_json).
void print_stats(std::ostream& err, std::size_t points, const delaunay::Result& r,
                 const std::string& kernel, const Options& o, double read_ms,
                 double triangulate_ms, double write_ms) {
    const delaunay::Triangulation& t = r.triangulation;
    // Six decimals, as the hand-written writer printed them.
    const auto ms = [](double v) { return std::round(v * 1e6) / 1e6; };
    nlohmann::ordered_json counters;
    r.counters.for_each([&](std::string_view name, std::uint64_t v) { counters[name] = v; });
    counters["flips"] = r.counters.flips();
    const nlohmann::ordered_json stats{
        {"points", points},
        {"vertices", points - t.duplicates.size()},
        {"duplicates", t.duplicates.size()},
        {"triangles", t.triangle_count()},
        {"hull_size", t.hull.size()},
        {"collinear", t.collinear},
        {"kernel", kernel},
        {"incircle", policy_name(o.incircle)},
        {"algorithm", delaunay::to_string(r.algorithm)},
        {"strategy", delaunay::to_string(r.strategy)},
        {"strips", r.strips},
        {"threads", o.threads},
        {"instrumentation", "counters"},
        {"counters", counters},
        {"read_ms", ms(read_ms)},
        {"triangulate_ms", ms(triangulate_ms)},
        {"write_ms", ms(write_ms)},
    };
    // The layout of the hand-written writer this replaced, which scripts may match:
    // ", " and ": " between items, all on one line. dump(0) puts each item on its own
    // line with ": " (a string's own newlines are escaped, so every '\n' is layout).
    std::string line;
    for (const char c : stats.dump(0)) {
        if (c != '\n') {
            line += c;
        } else if (!line.empty() && line.back() == ',') {
            line += ' ';
        }
    }
    err << line << '\n';
}

// Removes the temporary file unless it was renamed into place.
struct TempFile {
    std::string path;
    bool keep = false;
    ~TempFile() {
        if (!path.empty() && !keep) std::remove(path.c_str());
    }
};

// Writes through `write` into a new file next to `path` and renames it over `path` when
// everything succeeded. On failure returns false with `error` set and leaves `path`
// untouched (the previous file, if any, survives).
template <class Write>
bool write_atomically(const std::string& path, Write write, std::string& error) {
    TempFile tmp{path + ".tmp.XXXXXX"};
    const int fd = ::mkstemp(tmp.path.data());
    if (fd < 0) {
        tmp.path.clear();
        error = "cannot create a temporary file next to '" + path + "'";
        return false;
    }
    // mkstemp creates the file 0600; give the result the permissions a plain open would.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
    {
        std::ofstream out(tmp.path, std::ios::binary | std::ios::trunc);
        if (out) write(out);
        out.close();
        if (!out) {
            error = "error while writing '" + path + "'";
            return false;
        }
    }
    if (std::rename(tmp.path.c_str(), path.c_str()) != 0) {
        error = "cannot rename the temporary file to '" + path + "'";
        return false;
    }
    tmp.keep = true;
    return true;
}

int run(const Options& o, const CommandLine& cli) {
    std::string error;
    const std::optional<AnyKernel> kernel = parse_kernel(o.kernel, error);
    if (!kernel) return cli.usage_error(error);
    const bool from_stdin = !o.input || *o.input == "-";
    const bool to_stdout = !o.output || *o.output == "-";
    const io::PointFormat input_format =
        o.input_format ? *o.input_format
                       : (from_stdin ? io::PointFormat::xy : io::point_format_from_path(*o.input));
    const io::TriangulationFormat format =
        o.format ? *o.format
                 : (to_stdout ? io::TriangulationFormat::json
                              : io::triangulation_format_from_path(*o.output)
                                    .value_or(io::TriangulationFormat::json));

    // Read.
    const Clock::time_point read_start = Clock::now();
    std::vector<Point2> points;
    try {
        if (from_stdin) {
            points = io::read_points(std::cin, input_format);
        } else {
            std::ifstream file(*o.input, std::ios::binary);
            if (!file) {
                std::cerr << "exidel: cannot open '" << *o.input << "'\n";
                return exit_failure;
            }
            points = io::read_points(file, input_format);
        }
    } catch (const io::ReadError& e) {
        std::cerr << "exidel: " << e.what() << '\n';
        return exit_failure;
    } catch (const std::runtime_error& e) {
        std::cerr << "exidel: " << e.what() << '\n';
        return exit_failure;
    }
    const double read_ms = ms_since(read_start);

    // Triangulate: the only timed step. Counters only when asked for, so a plain run is
    // the uninstrumented algorithm.
    delaunay::Options options{o.incircle, o.strategy, o.threads, o.strip_points};
    options.algorithm = o.algorithm;
    delaunay::Result result;
    std::string kernel_name;
    double triangulate_ms = 0;
    std::visit(
        [&](const auto& k) {
            kernel_name = k.name();
            const Clock::time_point start = Clock::now();
            if (o.stats) {
                result = delaunay::triangulate<delaunay::Instrumentation::counters>(
                    std::span<const Point2>(points), k, options);
            } else {
                result = delaunay::triangulate<delaunay::Instrumentation::off>(
                    std::span<const Point2>(points), k, options);
            }
            triangulate_ms = ms_since(start);
        },
        *kernel);
    if (!result.ok()) {
        std::cerr << "exidel: triangulation failed: " << result.failure->message << " ("
                  << delaunay::to_string(result.failure->kind) << ")\n";
        return exit_failure;
    }

    // Write.
    const Clock::time_point write_start = Clock::now();
    const auto write = [&](std::ostream& out) {
        io::write_triangulation(out, points, result.triangulation, format);
    };
    if (to_stdout) {
        write(std::cout);
        std::cout.flush();
        if (!std::cout) {
            std::cerr << "exidel: error while writing the output\n";
            return exit_failure;
        }
    } else if (!write_atomically(*o.output, write, error)) {
        std::cerr << "exidel: " << error << '\n';
        return exit_failure;
    }
    if (o.stats) {
        print_stats(std::cerr, points.size(), result, kernel_name, o, read_ms, triangulate_ms,
                    ms_since(write_start));
    }
    return exit_ok;
}

}  // namespace

int triangulate_command(std::span<const std::string_view> args) {
    using delaunay::InCirclePolicy, delaunay::Strategy;
    CommandLine cli("triangulate", triangulate_help());
    CLI::App& app = cli.app;
    Options o;
    std::vector<std::string> files;  // the positional FILE, counted with -i
    const CLI::Option* input = app.add_option("-i,--input", o.input);
    app.add_option("FILE", files);
    const CLI::Option* output = app.add_option("-o,--output", o.output);
    app.add_option("-k,--kernel", o.kernel);
    app.add_option_function<std::string>("-a,--algorithm", [&](const std::string& name) {
        const std::optional<delaunay::Algorithm> a = delaunay::algorithm_from_name(name);
        if (!a) {
            throw std::invalid_argument("unknown algorithm '" + name + "' (expected " +
                                        delaunay::algorithm_spellings() + ")");
        }
        o.algorithm = *a;
    });
    add_parsed(app, "--incircle", "determinant or cosine", o.incircle,
               [](const std::string& v) -> std::optional<InCirclePolicy> {
                   if (v == "determinant") return InCirclePolicy::determinant;
                   if (v == "cosine") return InCirclePolicy::cosine;
                   return {};
               });
    add_parsed(app, "--order", "auto, lexicographic, radial or strips", o.strategy,
               [](const std::string& v) -> std::optional<Strategy> {
                   if (v == "auto") return Strategy::automatic;
                   for (const Strategy s :
                        {Strategy::lexicographic, Strategy::radial, Strategy::strips}) {
                       if (v == delaunay::to_string(s)) return s;
                   }
                   return {};
               });
    add_parsed(app, "--threads", "a whole number from 1 to 1024", o.threads,
               [](const std::string& v) { return whole_number(v, 1024); });
    add_parsed(app, "--strip-points",
               "a whole number from 1 to " + std::to_string(delaunay::detail::max_points),
               o.strip_points,
               [](const std::string& v) { return whole_number(v, delaunay::detail::max_points); });
    add_parsed(app, "-f,--format", "json, ele, off or svg", o.format,
               io::triangulation_format_from_name);
    add_parsed(app, "--input-format", "xy, json, node or f64", o.input_format,
               io::point_format_from_name);
    app.add_flag("--stats", o.stats);
    if (const std::optional<int> status = cli.parse(args)) return *status;
    if (input->count() + files.size() > 1) {
        return cli.usage_error("more than one input file given");
    }
    if (output->count() > 1) return cli.usage_error("more than one output file given");
    if (!files.empty()) o.input = files.front();
    return run(o, cli);
}

}  // namespace exidel::cli
