#include "options.hpp"

#include <iostream>
#include <stdexcept>
#include <vector>

#include "commands.hpp"

namespace exidel::cli {

CommandLine::CommandLine(std::string command, std::string help, bool help_on_error)
    : app("exidel " + command),
      command_(std::move(command)),
      help_(std::move(help)),
      help_on_error_(help_on_error) {
    // Flags take no value (--stats=1 is an error), options keep their last value.
    app.option_defaults()
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
        ->disable_flag_override();
    // Unknown options are collected and reported in parse(), in the words the user typed.
    app.allow_extras();
}

std::optional<int> CommandLine::parse(std::span<const std::string_view> args) {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11's order
    try {
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        std::cout << help_;
        return exit_ok;
    } catch (const CLI::ArgumentMismatch& e) {
        // CLI11 says "--input: 1 required TEXT missing"; the commands have always said
        // "--input needs a value".
        const std::string what = e.what();
        const std::size_t colon = what.find(':');
        if (colon != std::string::npos && what.ends_with(" missing")) {
            return usage_error(what.substr(0, colon) + " needs a value");
        }
        return usage_error(what);
    } catch (const CLI::ParseError& e) {
        return usage_error(e.what());
    } catch (const std::invalid_argument& e) {
        return usage_error(e.what());
    }
    const std::vector<std::string> unknown = app.remaining();
    if (!unknown.empty()) return usage_error("unknown option '" + unknown.front() + "'");
    return std::nullopt;
}

int CommandLine::usage_error(const std::string& message) const {
    std::cerr << "exidel " << command_ << ": " << message << '\n';
    if (help_on_error_) {
        // The synopsis (the help's first paragraph), not the whole help: the reason stays
        // the first thing one reads, not 70 lines above the prompt.
        std::cerr << '\n'
                  << help_.substr(0, help_.find("\n\n") + 1) << "(see exidel " << command_
                  << " --help)\n";
    } else {
        std::cerr << "(see exidel " << command_ << " --help)\n";
    }
    return exit_usage;
}

void add_point_format_option(CLI::App& app, std::optional<io::PointFormat>& target) {
    add_parsed(app, "--input-format", "xy, json, node, f64, geojson or poly", target,
               io::point_format_from_name);
}

void add_columns_option(CLI::App& app, std::optional<io::Columns>& target) {
    app.add_option_function<std::string>("--columns", [&target](const std::string& spec) {
        std::string error;
        target = io::parse_columns(spec, error);
        if (!target) throw std::invalid_argument("--columns: " + error);
    });
}

std::optional<std::string> columns_error(const std::optional<io::Columns>& columns,
                                         io::PointFormat format) {
    if (!columns || format == io::PointFormat::xy) return std::nullopt;
    return "--columns applies to xy input, not to " + std::string(io::to_string(format));
}

}  // namespace exidel::cli
