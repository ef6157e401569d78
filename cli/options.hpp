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
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <span>
#include <string>
#include <string_view>

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

}  // namespace exidel::cli
