// exidel CLI: `exidel predicate`, the text interface to the kernels.
//
// Its input and output format is a contract: outside checks talk to the kernels through
// it. Keep it exactly as the help text below says.
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "options.hpp"
#include "query.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view predicate_help_head =
    R"(usage: exidel predicate [--kernel NAME] [-i FILE | FILE]

Evaluates geometric predicates and prints one sign (-1, 0 or 1) per query, one per line,
in input order.

Input (FILE, or standard input when no file or '-' is given), one query per line:
  orient2d        ax ay bx by cx cy
      sign of (b - a) x (c - a): 1 iff a, b, c turn counter-clockwise.
  incircle        ax ay bx by cx cy dx dy
      1 iff d is strictly inside the circle through a, b, c when abc turns
      counter-clockwise; the sign flips when abc turns clockwise.
  incircle_cosine ax ay bx by cx cy dx dy
      the cosine form of the in-circle test (Cai 2025): the sign of
      -(|a-c||b-c| (a-d).(b-d) + |a-d||b-d| (a-c).(b-c)). When c and d are strictly on
      opposite sides of line ab it equals orient2d(a,b,c) * incircle(a,b,c,d); otherwise
      it is still printed but is not an in-circle answer.
  compare_distance cx cy px py qx qy
      sign of |p - c|^2 - |q - c|^2: 1 iff p is strictly farther from c than q
      (the radial insertion order's comparison).
  orient3d        ax ay az bx by bz cx cy cz dx dy dz
      sign of det(a - d, b - d, c - d) (Shewchuk's convention): 1 iff d lies below
      the plane through a, b, c, "below" being the side from which a, b, c appear
      clockwise. The opposite of CGAL's orientation(a, b, c, d).
  insphere        ax ay az bx by bz cx cy cz dx dy dz ex ey ez
      1 iff e is strictly inside the sphere through a, b, c, d when orient3d(a, b, c, d)
      is 1; the sign flips with orient3d(a, b, c, d).
Coordinates: decimal (0.1, -2.5e-300) or C99 hexadecimal floats (0x1.8p-3,
-0X1P+4), each rounded to the nearest double (a value below the smallest subnormal
rounds to zero). Tokens are separated by spaces or tabs. Everything from a '#' to the
end of the line is a comment; lines that are blank after that are skipped.

Errors: an unknown predicate, a wrong number of coordinates, text that is not a number,
nan, inf, or a value too large for a finite double stops the run with
  exidel: line N: <reason>
on standard error and exit status 1. Output is streamed: the signs of the lines before
line N have already been printed; nothing is printed for line N or after it.

Options:
  -k, --kernel NAME  one of the kernels below (default: adaptive). adaptive, exact
                     and exact-cpp are exact for every finite input; the others
                     evaluate the plain formulas in their arithmetic and can be
                     wrong near degeneracy
  -i, --input FILE   read queries from FILE ('-' for standard input)
  -h, --help         show this help

Exit status: 0 success, 1 bad input line or I/O error, 2 bad options.

Kernels:
)";

std::string predicate_help() { return std::string(predicate_help_head) + kernel_help(); }

}  // namespace

int run_predicate_queries(std::istream& in, std::ostream& out, std::ostream& err,
                          const AnyKernel& kernel) {
    return std::visit(
        [&](const auto& k) {
            std::string line;
            for (long long number = 1; std::getline(in, line); ++number) {
                const ParsedLine parsed = parse_query_line(line);
                if (parsed.kind == ParsedLine::Kind::blank) continue;
                if (parsed.kind == ParsedLine::Kind::error) {
                    out.flush();
                    err << "exidel: line " << number << ": " << parsed.error << '\n';
                    return exit_failure;
                }
                out << to_int(evaluate(k, parsed.query)) << '\n';
            }
            if (in.bad()) {
                out.flush();
                err << "exidel: error while reading the input\n";
                return exit_failure;
            }
            out.flush();
            if (!out) {
                err << "exidel: error while writing the output\n";
                return exit_failure;
            }
            return exit_ok;
        },
        kernel);
}

int predicate_command(std::span<const std::string_view> args) {
    CommandLine cli("predicate", predicate_help());
    std::string kernel_name = "adaptive";
    std::optional<std::string> input;
    std::vector<std::string> files;  // the positional FILE, counted with -i
    cli.app.add_option("-k,--kernel", kernel_name);
    const CLI::Option* input_option = cli.app.add_option("-i,--input", input);
    cli.app.add_option("FILE", files);
    if (const std::optional<int> status = cli.parse(args)) return *status;
    if (input_option->count() + files.size() > 1) {
        return cli.usage_error("more than one input file given");
    }
    if (!files.empty()) input = files.front();

    std::string error;
    const std::optional<AnyKernel> kernel = parse_kernel(kernel_name, error);
    if (!kernel) return cli.usage_error(error);

    if (!input || *input == "-") {
        return run_predicate_queries(std::cin, std::cout, std::cerr, *kernel);
    }
    std::ifstream file(*input);
    if (!file) {
        std::cerr << "exidel: cannot open '" << *input << "'\n";
        return exit_failure;
    }
    return run_predicate_queries(file, std::cout, std::cerr, *kernel);
}

}  // namespace exidel::cli
