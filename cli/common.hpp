// exidel CLI (internal): what the commands that triangulate a point file share (exidel
// triangulate, exidel voronoi): their common options (PointCommand), the point input
// (-i/--input FILE or FILE, --input-format, --columns), the steps of a run (PointRun:
// read, triangulate and its failure message, write the output into its pending file,
// finish with --stats), the output format, and the --stats line's layout.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/io/constraints.hpp"
#include "exidel/io/points.hpp"
#include "exidel/predicates/registry.hpp"
#include "memory.hpp"
#include "options.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace exidel::cli {

/// -a/--algorithm NAME: a name of the registry (algorithms.hpp), else a usage error that
/// lists them.
void add_algorithm_option(CLI::App& app, delaunay::Algorithm& target);

/// A whole number from 1 to `limit`.
std::optional<std::size_t> whole_number(const std::string& text, std::size_t limit);

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start);

/// The help texts' paragraph on the input, from "Input (" to the line starting "Text
/// coordinates ..."; each command ends its sentence (what duplicates do).
extern const std::string_view point_input_help;

/// A point command's --help: `head`, point_input_help, `tail` (which ends with the line
/// "Algorithms:"), the algorithms, then "Kernels:" and the kernels.
std::string point_command_help(std::string_view head, std::string_view tail);

/// The points a command reads: -i/--input FILE or a positional FILE (standard input when
/// neither is given, or '-'), in --input-format, else the format of the file's extension,
/// else xy; --columns picks two fields of a wider xy file.
struct PointInput {
    std::optional<std::string> path;
    std::optional<io::PointFormat> format;
    std::optional<io::Columns> columns;
    std::optional<std::string> z_property;

    PointInput() = default;
    PointInput(const PointInput&) = delete;  // the options' callbacks hold its address
    PointInput& operator=(const PointInput&) = delete;

    /// Declares -i/--input and the positional FILE on `app`.
    void add_file_options(CLI::App& app);
    /// Declares --input-format and --columns on `app`.
    void add_format_options(CLI::App& app);
    /// Declares --z-property NAME on `app` (geojson input: z from that property).
    void add_z_property_option(CLI::App& app);
    /// After parsing: the usage error of more than one input file, if given.
    std::optional<std::string> take_files();

    bool from_stdin() const { return !path || *path == "-"; }
    /// --input-format, else from the extension, else xy.
    io::PointFormat resolved_format() const;
    /// The usage error of --columns with a format other than xy, or --z-property with
    /// one other than geojson, if given.
    std::optional<std::string> columns_error() const;
    /// Reads every point (showing the phase on `progress`). When the input cannot be read
    /// or is malformed: "exidel: <why>" on standard error, progress stopped, nothing.
    std::optional<io::PointFile> read(unsigned threads, Progress& progress) const;
    /// Reads points with segments and holes (poly, geojson or json input), as read() does.
    std::optional<io::ConstraintFile> read_constraints(Progress& progress) const;

private:
    const CLI::Option* input_option_ = nullptr;
    std::vector<std::string> files_;
};

/// The options exidel triangulate and exidel voronoi both take, declared by the add_*
/// functions in the order each command lists them: the point input, -o/--output,
/// -k/--kernel, -a/--algorithm, --threads, --stats and -q/--quiet.
struct PointCommand {
    PointInput input;
    std::optional<std::string> output;
    std::string kernel = "adaptive";
    delaunay::Algorithm algorithm = delaunay::Algorithm::external;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    bool stats = false;
    bool quiet = false;

    /// Declares -i/--input, FILE, -o/--output, -k/--kernel and -a/--algorithm.
    void add_input_output_options(CLI::App& app);
    /// Declares --threads.
    void add_threads_option(CLI::App& app);
    /// Declares --stats and -q/--quiet.
    void add_report_options(CLI::App& app);
    /// Parses `args` into the options declared on `cli`; more than one input or output
    /// file is a usage error. Nothing when the command runs, else its exit status.
    std::optional<int> parse(CommandLine& cli, std::span<const std::string_view> args);

    /// Whether the output goes to standard output (no -o, or '-').
    bool to_stdout() const { return !output || *output == "-"; }
    /// The checks made before any work: the kernel --kernel names, else nothing and
    /// `error` says why (an unknown kernel, or --columns with a format other than xy).
    std::optional<AnyKernel> checked_kernel(std::string& error) const;
    /// Creates -o's temporary file (nothing for standard output). When it cannot:
    /// "exidel: <why>" on standard error, and false.
    bool open_output(std::optional<PendingFile>& file) const;

private:
    const CLI::Option* output_option_ = nullptr;
};

/// A triangulation run: its result, the kernel's name and exactness, its time.
struct Triangulated {
    delaunay::Result result;
    std::string kernel_name;
    bool exact_kernel = false;
    double ms = 0;
};

/// make(k) (a delaunay::Result) for the kernel `kernel` holds, timed, with the kernel's
/// name and exactness.
template <class Make>
Triangulated timed_triangulation(const AnyKernel& kernel, Make make) {
    Triangulated t;
    std::visit(
        [&](const auto& k) {
            t.kernel_name = k.name();
            t.exact_kernel = std::decay_t<decltype(k)>::is_exact;
            const Clock::time_point start = Clock::now();
            t.result = make(k);
            t.ms = ms_since(start);
        },
        kernel);
    return t;
}

/// Triangulates `points` with `kernel`, instrumented (counters) iff `counters`.
Triangulated triangulate_points(const AnyKernel& kernel, std::span<const Point2> points,
                                const delaunay::Options& options, bool counters);

/// "exidel: triangulation failed: <where>: <what> (<kind>)." and, for an inexact kernel,
/// that an exact one triangulates every finite input; one line on `err`.
void print_triangulation_failure(std::ostream& err, const Triangulated& t);

/// Prints the certifier's findings on `err`, one per line ("exidel: certificate: KIND:
/// message"), and how many more there are.
void print_findings(std::ostream& err, const delaunay::Certificate& c);

/// The output format: `given`, else the one of -o's extension (`from_path`), else
/// `fallback`. An extension `from_path` does not know is an error: nothing, and `error`
/// says so (naming `extensions`, ".json .svg").
template <class Format, class FromPath>
std::optional<Format> output_format(const std::optional<Format>& given,
                                    const std::optional<std::string>& output, Format fallback,
                                    FromPath from_path, std::string_view extensions,
                                    std::string& error) {
    if (given) return *given;
    if (!output || *output == "-") return fallback;
    const std::string& out = *output;
    const std::size_t dot = out.rfind('.'), slash = out.rfind('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return fallback;
    const std::optional<Format> f = from_path(out);
    if (!f) {
        error = "cannot tell the output format from '" + out +
                "' (extensions: " + std::string(extensions) + "); give --format";
    }
    return f;
}

/// Runs `step`; a std::runtime_error it throws (an I/O error) is printed as "exidel:
/// <what>" on standard error, after stopping `progress` if given. Returns whether `step`
/// succeeded.
template <class Step>
bool reported(Step step, Progress* progress = nullptr) {
    try {
        step();
        return true;
    } catch (const std::runtime_error& e) {
        if (progress) progress->stop();
        std::cerr << "exidel: " << e.what() << '\n';
        return false;
    }
}

/// "what: <strerror(error)>", or "what" alone when error is 0.
std::string write_error(const std::string& what, int error);

/// Writes through `write(std::ostream&)` into `file`'s temporary; throws on I/O errors.
template <class Write>
void write_into(const PendingFile& file, Write write) {
    errno = 0;
    std::ofstream out = file.open();
    if (out) write(out);
    out.close();
    // The stream keeps no error code; errno holds the failed system call's (ENOSPC for a
    // full disk, EFBIG past a file size limit, ENOENT for a removed directory).
    if (!out) throw std::runtime_error(write_error("cannot write '" + file.path() + "'", errno));
}

/// Writes through `write(std::ostream&)` on standard output; throws on I/O errors.
template <class Write>
void write_stdout(Write write) {
    errno = 0;
    write(std::cout);
    std::cout.flush();
    if (!std::cout) throw std::runtime_error(write_error("cannot write the output", errno));
}

/// What the output step writes into one file: `write(std::ostream&)`.
using Writer = std::function<void(std::ostream&)>;

/// A file written beside the output (exidel triangulate's .node): its pending file and
/// what goes into it.
struct BesideFile {
    PendingFile& file;
    Writer write;
};

/// The times of the steps every run has, in milliseconds, as --stats prints them.
struct StepTimes {
    double read = 0, triangulate = 0, write = 0, total = 0;
};

/// One run of exidel triangulate or exidel voronoi once its output files exist: the
/// progress line, the steps both commands take (each saying on standard error why it
/// failed), and their times. A command that fails after reading returns finish().
class PointRun {
public:
    /// `start`: when the command started (the total time counts from there).
    PointRun(const PointCommand& command, Clock::time_point start);

    /// Reads the points (times.read). Nothing when they cannot be read.
    std::optional<io::PointFile> read();
    /// Triangulates `points` (times.triangulate), instrumented (counters) iff `counters`.
    /// A failed triangulation is said with print_triangulation_failure.
    Triangulated triangulate(const AnyKernel& kernel, std::span<const Point2> points,
                             const delaunay::Options& options, bool counters);
    /// The same step for another triangulation of the points: make(k) gives its
    /// delaunay::Result; `what` names it on the progress line.
    template <class Make>
    Triangulated triangulate_with(const AnyKernel& kernel, std::size_t points,
                                  std::string_view what, Make make) {
        start_triangulating(points, what);
        return recorded(timed_triangulation(kernel, make));
    }
    /// The output step (times.write): `write` on standard output when `output` holds no
    /// file, else into its temporary file, then each file `beside` into its own; then
    /// every file is renamed into place, the output first. An I/O error is said, and
    /// gives false; success stops the progress line.
    bool write(std::optional<PendingFile>& output, const Writer& write,
               std::span<const BesideFile> beside = {});
    /// The end of every run: stops the progress line, takes the total time, calls
    /// `print_stats()` when --stats was given, and returns `status`.
    template <class PrintStats>
    int finish(int status, PrintStats print_stats) {
        progress.stop();
        times.total = ms_since(start_);
        if (command_.stats) print_stats();
        return status;
    }

    Progress progress;
    StepTimes times;

private:
    /// The step's time into `times`; a failure said on standard error.
    Triangulated recorded(Triangulated t);
    /// The progress line and the memory need of triangulating `points` points; `what`
    /// follows "points" on the progress line.
    void start_triangulating(std::size_t points, std::string_view what);

    const PointCommand& command_;
    Clock::time_point start_;
};

/// `stats` with the times of a run appended, as --stats ends: "read_ms",
/// "triangulate_ms", "certify_ms", "write_ms", "total_ms".
nlohmann::ordered_json& with_times(nlohmann::ordered_json& stats, const StepTimes& times,
                                   double certify_ms);

/// Milliseconds as --stats prints them: six decimals.
double stats_ms(double ms);

/// `stats` on one line, with ", " and ": " between items: the layout of the hand-written
/// writer nlohmann-json replaced, which scripts may match. Ends with '\n'.
std::string stats_line(const nlohmann::ordered_json& stats);

}  // namespace exidel::cli
