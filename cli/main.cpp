// exidel: the command-line entry point. Dispatches `exidel <command> [options]` to one
// function per subcommand, each in its own file (see commands.hpp).
#include <malloc.h>

#include <csignal>
#include <new>

#include <array>
#include <exception>
#include <iostream>
#include <string_view>
#include <vector>

#include "commands.hpp"
#include "memory.hpp"
#include "exidel/delaunay/algorithms.hpp"
#include "exidel/predicates/build_info.hpp"

namespace {

using exidel::cli::exit_failure;
using exidel::cli::exit_ok;
using exidel::cli::exit_usage;

struct Command {
    std::string_view name;
    std::string_view summary;
    int (*run)(std::span<const std::string_view> args);
};

// One row per subcommand, in the order `exidel --help` lists them.
constexpr std::array commands{
    Command{"predicate", "evaluate predicates on queries read from a file or stdin",
            &exidel::cli::predicate_command},
    Command{"triangulate", "Delaunay triangulation of points read from a file or stdin",
            &exidel::cli::triangulate_command},
    Command{"voronoi", "Voronoi diagram (exact cocircular vertices) of points, json or svg",
            &exidel::cli::voronoi_command},
    Command{"locate", "where queries lie (inside, on an edge or vertex, outside), exactly",
            &exidel::cli::locate_command},
    Command{"interpolate", "values at points interpolated at queries (linear, nearest)",
            &exidel::cli::interpolate_command},
    Command{"certify", "is a triangulation (json, .ele) the Delaunay triangulation of points?",
            &exidel::cli::certify_command},
    Command{"study", "failure maps, precision sweeps, triangulation outcomes, adaptive stages",
            &exidel::cli::study_command},
    Command{"fuzz", "fuzzing campaigns (predicates, triangulations) on threads and MPI ranks",
            &exidel::cli::fuzz_command},
};

void print_usage(std::ostream& os) {
    os << "usage: exidel <command> [options]\n"
          "       exidel <command> --help\n"
          "       exidel --version\n\n"
          "commands:\n";
    for (const Command& c : commands) {
        os << "  " << c.name << std::string(c.name.size() < 12 ? 12 - c.name.size() : 1, ' ')
           << c.summary << '\n';
    }
    os << "\nExit status: 0 success, 1 failure (bad input data, I/O), 2 bad usage.\n";
}

// What a bug report needs: which exidel, built how, with which number libraries.
void print_version(std::ostream& os) {
    const exidel::BuildInfo& b = exidel::build_info();
    os << "exidel " << b.version << " (commit " << b.commit << ")\n"
       << "compiler: " << b.compiler << ", " << (b.build_type.empty() ? "no" : b.build_type)
       << " build\nlibrary flags: " << b.cxx_flags << "\nGMP " << b.gmp << ", MPFR " << b.mpfr
       << ", Boost " << b.boost << "\nlong double: " << b.long_double << "\nkernels:";
    for (const std::string_view k : b.kernels) os << ' ' << k;
    os << "\nalgorithms:";
    for (const exidel::delaunay::AlgorithmInfo& a : exidel::delaunay::algorithms())
        os << ' ' << a.name;
    os << '\n';
}

}  // namespace

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);  // output is one short line per query: keep it buffered
    // Blocks up to 32 MB from the heap, kept when freed (glibc would raise its threshold
    // to this by itself after the first large free): each phase of a triangulation
    // allocates and frees arrays of that size, and a fresh page costs microseconds on
    // some machines (docs/measurements.md, "Text input and output").
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    // A write past the file size limit (ulimit -f) raises SIGXFSZ, which would end the
    // process on the spot and leave the temporary output behind. Ignored, the write fails
    // with EFBIG like a full disk's ENOSPC: the error is said and the temporary removed.
    std::signal(SIGXFSZ, SIG_IGN);
    const std::vector<std::string_view> args(argv + (argc > 0 ? 1 : 0), argv + argc);
    if (args.empty()) {
        print_usage(std::cerr);
        return exit_usage;
    }
    const std::string_view first = args.front();
    if (first == "-h" || first == "--help" || first == "help") {
        print_usage(std::cout);
        return exit_ok;
    }
    if (first == "--version") {
        print_version(std::cout);
        return exit_ok;
    }
    for (const Command& c : commands) {
        if (c.name != first) continue;
        try {
            return c.run(std::span(args).subspan(1));
        } catch (const std::bad_alloc&) {
            // The stack is unwound: the pending output files are gone, and so is most of
            // what was allocated, so the message can be built.
            std::cout.flush();
            std::cerr << "exidel: " << exidel::cli::out_of_memory_message() << '\n';
            return exit_failure;
        } catch (const std::exception& e) {
            // Only resource exhaustion gets here (an exact kernel out of memory): report it
            // instead of terminating.
            std::cout.flush();
            std::cerr << "exidel: " << e.what() << '\n';
            return exit_failure;
        }
    }
    std::cerr << "exidel: unknown command '" << first << "'\n\n";
    print_usage(std::cerr);
    return exit_usage;
}
