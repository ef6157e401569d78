// exidel::research: fuzzing campaigns. A kernel is checked against a reference kernel on
// queries drawn from the exidel::testing families, in amounts (10^9 and more) that the
// property tests cannot reach, on threads of one process or on the ranks of an MPI job.
//
// How the queries are defined (a function of --seed and --queries only):
//   - The campaign's queries are numbered 0 .. N-1 and cut into blocks of block_queries.
//     Block b draws one set of set_points points of family families[b % F] with
//     testing::gen_points, from the seed derive_seed(seed, {fuzz id, b}); query j of the
//     block asks predicates[j % P] of set_points distinct points of that set, chosen by a
//     SplitMix64 stream of derive_seed(seed, {fuzz id, b, j}). One RapidCheck draw thus
//     serves block_queries queries: a draw costs about 6 us per point here, more than a
//     query's evaluation, and every subset of a family's set has the family's structure
//     (cocircular points of a lattice circle stay cocircular).
//   - An incircle_cosine query orders its four points so that c and d are on opposite
//     sides of ab when any order allows it (the paper's precondition), decided by the
//     adaptive kernel's orient2d; the comparison is of the cosine formula's sign either way.
//   - Blocks are grouped into stripes, the unit of checkpointing and of the split over MPI
//     ranks (stripe s goes to rank s mod R); threads share a stripe's blocks. Counts are
//     sums over blocks and the reported disagreements are the first ones in query order,
//     so the result does not depend on how the work was split.
//
// A disagreement is shrunk with RapidCheck's shrinks of the block's point set: the query
// keeps its predicate and its point indices while the set moves toward the family's exact
// degenerate configuration, as long as kernel and reference still disagree.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/predicates/predicate.hpp"
#include "exidel/predicates/types.hpp"
#include "exidel/research/studies.hpp"
#include "exidel/testing/families.hpp"

namespace exidel::research {

// ---------------------------------------------------------------------------------
// The processes a campaign runs on.

/// One process (Team::solo()) or the ranks of an MPI job (the CLI's MPI team). Every rank
/// calls the collective operations in the same order.
class Team {
public:
    virtual ~Team() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    /// Each rank's `mine`, on rank 0 in rank order; an empty vector on the other ranks.
    virtual std::vector<std::string> gather(const std::string& mine) = 0;
    /// The largest `value` over the ranks, on every rank.
    virtual double max(double value) = 0;
    /// Ends the whole job after an error that this rank alone met (the other ranks would
    /// otherwise wait for it forever); returns for a team of one process.
    virtual void fail() {}

    /// The team of this process alone.
    static Team& solo();
};

// ---------------------------------------------------------------------------------
// exidel fuzz predicates.

inline constexpr std::size_t fuzz_block_queries = 256;  ///< queries per drawn point set
inline constexpr std::size_t fuzz_set_points = 16;      ///< points per drawn set

struct PredicateFuzzOptions {
    std::string kernel = "adaptive";        ///< the kernel checked (a registry spelling)
    std::string reference = "exact";        ///< the kernel it is checked against
    std::vector<testing::Family> families;  ///< empty: every family
    std::vector<Predicate> predicates;      ///< empty: every predicate
    std::uint64_t queries = 1'000'000;
    std::uint64_t seed = 20250704;
    std::size_t max_reports = 100;  ///< disagreements shrunk and reported (all are counted)
    /// A directory holding one file per finished stripe; empty: no checkpoint.
    std::filesystem::path checkpoint;
    /// Continue the campaign whose checkpoint is in `checkpoint` (same options) instead
    /// of refusing to overwrite it.
    bool resume = false;
    unsigned jobs = 1;     ///< threads of this process
    bool progress = true;  ///< a progress bar on a terminal (rank 0 only)
};

struct FuzzCount {
    std::uint64_t queries = 0, disagreements = 0;
};

/// A query on which the kernel and the reference disagree.
struct Disagreement {
    std::uint64_t index = 0;  ///< its number in the campaign
    testing::Family family{};
    Predicate predicate{};
    std::array<Point2, 4> query{};         ///< as drawn (point_count(predicate) points used)
    std::array<Point2, 4> shrunk{};        ///< the simplest query found that still disagrees
    Sign kernel_sign{}, reference_sign{};  ///< on the query as drawn
    Sign shrunk_kernel_sign{}, shrunk_reference_sign{};  ///< on the shrunk query
    std::size_t shrink_steps = 0;
};

struct PredicateFuzzResult {
    PredicateFuzzOptions options;  ///< with families and predicates filled in
    /// counts[f * predicates + p]: family options.families[f], predicate options.predicates[p].
    std::vector<FuzzCount> counts;
    FuzzCount total;
    std::vector<Disagreement> reported;  ///< the first max_reports, in query order
    double seconds = 0;                  ///< wall time of this run (the slowest rank)
    std::uint64_t resumed_queries = 0;   ///< queries taken from the checkpoint
    int ranks = 1;
    std::string commit;  ///< the exidel build that ran it
};

/// Runs the campaign on `team` (every rank calls it with the same options). The full
/// result is on rank 0; the other ranks return their options only. Throws
/// std::invalid_argument for bad options (unknown kernel, a checkpoint of another
/// campaign) and std::runtime_error for I/O errors.
PredicateFuzzResult fuzz_predicates(const PredicateFuzzOptions& options, Team& team = Team::solo());

/// The summary as JSON: the options, "queries", "disagreements", per family and
/// predicate the counts, the reported disagreements, and (the only members that differ
/// between runs of the same campaign) "seconds" and "run".
std::string summary_json(const PredicateFuzzResult& result);

// ---------------------------------------------------------------------------------
// exidel fuzz triangulations.
//
// Point set s (of N) has family families[s % F], a size drawn from [min_points,
// max_points] by the stream derive_seed(seed, {fuzz id, s, 1}), and its points from
// testing::gen_points at derive_seed(seed, {fuzz id, s}). Each set is triangulated by
// every method (an algorithm of the registry, the external one in each order asked for)
// under each in-circle policy, with the kernel asked for, and every result is certified
// exactly (classify_triangulation: the exact certifier, and a budget of predicate calls
// that turns a hang into the outcome "guard"). Unit k of the campaign is run
// k mod (methods x policies) of set k / (methods x policies).

struct TriangulationFuzzOptions {
    std::string kernel = "adaptive";
    std::vector<testing::Family> families;        ///< empty: every family
    std::vector<delaunay::Algorithm> algorithms;  ///< empty: every algorithm
    std::vector<delaunay::Strategy> orders;       ///< the external algorithm's; empty: all_orders
    std::vector<delaunay::InCirclePolicy> policies;  ///< empty: determinant and cosine
    std::size_t min_points = 3, max_points = 100;
    std::uint64_t sets = 10'000;
    std::uint64_t seed = 20250704;
    std::size_t max_reports = 20;  ///< wrong outcomes shrunk into fixtures (all are counted)
    std::filesystem::path out;     ///< where the fixtures go; empty: not written
    std::filesystem::path checkpoint;
    bool resume = false;
    unsigned jobs = 1;
    bool progress = true;
};

/// A triangulation that did not certify (or, with any kernel, exceeded its call budget),
/// shrunk by delta debugging to a set from which no single point can be removed.
struct TriangulationFinding {
    std::uint64_t index = 0;  ///< its unit number
    testing::Family family{};
    Method method;
    delaunay::InCirclePolicy policy{};
    Classification outcome;  ///< of the set as drawn
    std::size_t points = 0;  ///< size of the set as drawn
    std::vector<Point2> shrunk;
    Classification shrunk_outcome;
    std::string file;  ///< the fixture, relative to options.out (empty: not written)
};

struct TriangulationFuzzResult {
    TriangulationFuzzOptions options;  ///< with every list filled in
    std::vector<Method> methods;
    /// counts[((f * methods + m) * policies + p) * outcomes + o]: runs of family f, method
    /// m, policy options.policies[p] that ended in all_outcomes[o].
    std::vector<std::uint64_t> counts;
    std::uint64_t triangulations = 0;
    std::uint64_t wrong = 0;     ///< runs with any outcome but delaunay
    std::uint64_t problems = 0;  ///< what must not happen: wrong with an exact kernel; guard always
    std::vector<TriangulationFinding> reported;
    double seconds = 0;
    std::uint64_t resumed = 0;
    int ranks = 1;
    std::string commit;
};

/// A method's name in summaries and fixture names: "lawson", "external-strips", ...
std::string method_label(const Method& m);

/// Runs the campaign on `team`; the result (and the fixture files) on rank 0, as
/// fuzz_predicates.
TriangulationFuzzResult fuzz_triangulations(const TriangulationFuzzOptions& options,
                                            Team& team = Team::solo());

/// The summary as JSON: "triangulations", "wrong", "problems", the outcomes per family,
/// per method and per policy, the fixtures, and "seconds" and "run".
std::string summary_json(const TriangulationFuzzResult& result);

/// One line of `exidel predicate`'s input format, coordinates as C99 hex floats (exact).
std::string query_line(Predicate p, std::span<const Point2> points);

}  // namespace exidel::research
