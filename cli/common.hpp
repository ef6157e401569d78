// exidel CLI (internal): what the commands that triangulate a point file share (exidel
// triangulate, exidel voronoi): their value options, the point input (-i/--input FILE or
// FILE, --input-format, --columns), the triangulation step and its failure message, the
// output format and file, and the --stats line's layout.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/io/points.hpp"
#include "exidel/predicates/registry.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace exidel::cli {

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

/// The points a command reads: -i/--input FILE or a positional FILE (standard input when
/// neither is given, or '-'), in --input-format, else the format of the file's extension,
/// else xy; --columns picks two fields of a wider xy file.
struct PointInput {
    std::optional<std::string> path;
    std::optional<io::PointFormat> format;
    std::optional<io::Columns> columns;

    PointInput() = default;
    PointInput(const PointInput&) = delete;  // the options' callbacks hold its address
    PointInput& operator=(const PointInput&) = delete;

    /// Declares -i/--input and the positional FILE on `app`.
    void add_file_options(CLI::App& app);
    /// Declares --input-format and --columns on `app`.
    void add_format_options(CLI::App& app);
    /// After parsing: the usage error of more than one input file, if given.
    std::optional<std::string> take_files();

    bool from_stdin() const { return !path || *path == "-"; }
    /// --input-format, else from the extension, else xy.
    io::PointFormat resolved_format() const;
    /// The usage error of --columns with a format other than xy, if given.
    std::optional<std::string> columns_error() const;
    /// Reads every point (showing the phase on `progress`). When the input cannot be read
    /// or is malformed: "exidel: <why>" on standard error, progress stopped, nothing.
    std::optional<io::PointFile> read(unsigned threads, Progress& progress) const;

private:
    const CLI::Option* input_option_ = nullptr;
    std::vector<std::string> files_;
};

/// A triangulation run: its result, the kernel's name and exactness, its time.
struct Triangulated {
    delaunay::Result result;
    std::string kernel_name;
    bool exact_kernel = false;
    double ms = 0;
};

/// Triangulates `points` with `kernel`, instrumented (counters) iff `counters`.
Triangulated triangulate_points(const AnyKernel& kernel, std::span<const Point2> points,
                                const delaunay::Options& options, bool counters);

/// "exidel: triangulation failed: <where>: <what> (<kind>)." and, for an inexact kernel,
/// that an exact one triangulates every finite input; one line on `err`.
void print_triangulation_failure(std::ostream& err, const Triangulated& t);

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

/// Writes through `write(std::ostream&)` into `file`'s temporary; throws on I/O errors.
template <class Write>
void write_into(const PendingFile& file, Write write) {
    std::ofstream out = file.open();
    if (out) write(out);
    out.close();
    if (!out) throw std::runtime_error("error while writing '" + file.path() + "'");
}

/// Writes through `write(std::ostream&)` on standard output; throws on I/O errors.
template <class Write>
void write_stdout(Write write) {
    write(std::cout);
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("error while writing the output");
}

/// Runs `write` (the output step); an I/O error it throws (std::runtime_error) stops
/// `progress` and is printed as "exidel: <what>". Returns whether `write` succeeded.
template <class Write>
bool written(Progress& progress, Write write) {
    try {
        write();
        return true;
    } catch (const std::runtime_error& e) {
        progress.stop();
        std::cerr << "exidel: " << e.what() << '\n';
        return false;
    }
}

/// Milliseconds as --stats prints them: six decimals.
double stats_ms(double ms);

/// `stats` on one line, with ", " and ": " between items: the layout of the hand-written
/// writer nlohmann-json replaced, which scripts may match. Ends with '\n'.
std::string stats_line(const nlohmann::ordered_json& stats);

}  // namespace exidel::cli
