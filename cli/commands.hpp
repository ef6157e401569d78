// exidel CLI (internal): the subcommands and their shared conventions.
//
// To add a subcommand: write `int NAME_command(std::span<const std::string_view> args)` in
// its own NAME.cpp (args are the words after the subcommand's name; it declares its
// options on a CommandLine of options.hpp and has its own --help text), declare it here,
// add one row to the table in main.cpp and the file to cli/CMakeLists.txt.
#pragma once

#include <iosfwd>
#include <span>
#include <string_view>

#include "exidel/predicates/registry.hpp"

namespace exidel::cli {

/// Exit statuses of every subcommand.
inline constexpr int exit_ok = 0;
inline constexpr int exit_failure = 1;  // bad input data, unreadable file, I/O error
inline constexpr int exit_usage = 2;    // bad options or arguments

/// `exidel predicate`: signs of predicate queries, one per line.
int predicate_command(std::span<const std::string_view> args);

/// `exidel triangulate`: Delaunay triangulation of points read from a file or stdin.
int triangulate_command(std::span<const std::string_view> args);

/// `exidel voronoi`: Voronoi diagram of points read from a file or stdin.
int voronoi_command(std::span<const std::string_view> args);

/// `exidel locate`: where query points lie in the triangulation of points, exactly.
int locate_command(std::span<const std::string_view> args);

/// `exidel interpolate`: values at points interpolated at query points (linear, nearest).
int interpolate_command(std::span<const std::string_view> args);

/// `exidel certify`: the exact certifier on a point file and a triangulation file.
int certify_command(std::span<const std::string_view> args);

/// `exidel study`: the research instruments of lib/research (study.cpp).
int study_command(std::span<const std::string_view> args);

/// `exidel fuzz`: fuzzing campaigns (predicates against a reference, certified
/// triangulations) on threads and MPI ranks.
int fuzz_command(std::span<const std::string_view> args);

/// The core of `exidel predicate`, without option parsing: reads queries from `in`, writes
/// one sign per query to `out` as it goes, and on the first bad line writes
/// "exidel: line N: ..." to `err` and stops. Returns an exit status.
int run_predicate_queries(std::istream& in, std::ostream& out, std::ostream& err,
                          const AnyKernel& kernel);

}  // namespace exidel::cli
