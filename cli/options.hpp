// exidel CLI (internal): what the subcommands' option parsers share. Each subcommand
// declares its options on a CLI11 app; CommandLine adds the conventions of every
// subcommand:
//   - -h/--help prints the subcommand's own help text on standard output (status 0);
//   - a usage error prints "exidel CMD: MESSAGE" and then, after a blank line, the
//     synopsis (the help text's first paragraph) and a pointer to --help on standard
//     error, with exit status 2. CLI11's errors,
//     unknown options and values that an option's callback rejects by throwing
//     std::invalid_argument are all usage errors;
//   - an option given twice keeps its last value (a command counts what must not repeat).
// And the options several subcommands declare alike: add_parsed (a value parsed by a
// function, with one form of error), and a point file's --input-format and --columns.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "exidel/io/points.hpp"

namespace exidel::cli {

class CommandLine {
public:
    /// `command` is the subcommand's name, `help` its --help text. With `help_on_error`
    /// false a usage error ends with "(see exidel CMD --help)" alone, without the synopsis.
    CommandLine(std::string command, std::string help, bool help_on_error = true);

    /// Parses `args` (the words after the subcommand's name) into the options declared on
    /// `app`. Returns nothing when the subcommand should run, else its exit status: 0
    /// after --help, 2 after a usage error (already printed).
    std::optional<int> parse(std::span<const std::string_view> args);

    /// Prints the usage error `message`; returns exit_usage.
    int usage_error(const std::string& message) const;

    CLI::App app;

private:
    std::string command_;
    std::string help_;
    bool help_on_error_;
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

/// --input-format xy|json|node|f64|geojson: the format of a point file.
void add_point_format_option(CLI::App& app, std::optional<io::PointFormat>& target);
/// --columns X,Y[,Z]: the fields of a wider xy file that hold x and y (and z).
void add_columns_option(CLI::App& app, std::optional<io::Columns>& target);
/// The usage error of --columns with a point format other than xy, if given.
std::optional<std::string> columns_error(const std::optional<io::Columns>& columns,
                                         io::PointFormat format);

}  // namespace exidel::cli
