// exidel::research: the studies of `exidel study`. Each takes its own options and
// the common RunOptions, writes report.md, CSVs and pictures into run.out, and returns
// what it measured (for the tests and for `study all`).
//
//   failure-map    one predicate evaluated while one input point moves over a W x H grid
//                  of ulp steps (Kettner, Mehlhorn, Pion, Schirra, Yap, CGTA 2008)
//   precision      wrong-sign rate of the MPFR kernel against the exact kernel, per
//                  formulation, near-degenerate family and precision
//   triangulation  every kernel x in-circle policy x family (x insertion order): how the
//                  triangulation ends (Delaunay, valid but not Delaunay, invalid,
//                  failure), with minimal failing inputs written as fixtures; and the work
//                  (flips, predicate calls) of each insertion order with the adaptive kernel
//   stages         which stage of the adaptive kernel decides, on predicate streams and
//                  inside triangulations
//   constrained    every kernel x family of constrained inputs (crossings, segments
//                  through points, nearly parallel segments, polygons with holes): how
//                  constrained_delaunay ends (certified, wrong, failure detected)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/staged.hpp"
#include "exidel/predicates/wrapper.hpp"
#include "exidel/research/common.hpp"
#include "exidel/research/graphics.hpp"
#include "exidel/testing/families.hpp"

namespace exidel::research {

// =================================================================================
// failure-map

/// One failure-map configuration: the points of one query, the point that moves, and
/// the order in which the points are passed to the predicate. A map of a predicate of
/// the plane uses `formulation` and `points`; a map of a predicate of space sets `space`
/// and uses `points3`, and its moving point moves in the plane of its two coordinates
/// `axes` (0: x, 1: y, 2: z), the third one keeping its value.
struct FailureMapSpec {
    std::string name;  ///< preset name, or "custom"
    std::string description;
    Formulation formulation = Formulation::orient2d;
    std::vector<Point2> points;           ///< point_count(formulation) points (plane maps)
    std::optional<SpacePredicate> space;  ///< set: a map of orient3d or insphere
    std::vector<Point3> points3;          ///< point_count(*space) points (space maps)
    std::array<int, 2> axes{
        0, 1};              ///< the moving point's coordinates on the map's x and y (space maps)
    std::size_t pivot = 0;  ///< index into the points of the point that moves
    std::vector<std::size_t> order;  ///< argument i of the predicate is points[order[i]]
    int width = 256, height = 256;
    std::int64_t step = 1;  ///< ulps per cell
    /// The window's offsets: [-W/2, W/2) x [-H/2, H/2), the moving point at the centre cell
    /// (the default); false: [0, W) x [0, H), the moving point at the bottom-left corner.
    bool centered = true;

    std::string_view predicate() const {
        return space ? predicate_name(*space) : predicate_name(formulation);
    }
    std::size_t arity() const { return space ? point_count(*space) : point_count(formulation); }
};

/// The built-in configurations: kettner1..3 (docs/background.md section 4, the paper's p moved, the
/// formula pivoting on p), kettner1-pivot-q and -r (the same points with q or r first),
/// and circle/cosine configurations of four exactly cocircular points (a lattice circle
/// of radius 5 scaled by 2^-s around (2, 2), s = 2, 12, 24), d moved around its place.
/// In space: orient3d of four exactly coplanar points (on the plane x = y, Kettner's first
/// line lifted, and on the tilted plane x + y + z = 3/2), the point the formula subtracts
/// moved in x and y, or the first one; insphere of five exactly cospherical points (a
/// lattice sphere of radius 3 scaled by 2^-s around (2, 2, 2), s = 2, 12, 24), e moved
/// around its place in x and y, or a.
std::vector<FailureMapSpec> failure_map_presets();
/// Throws std::invalid_argument naming the presets when `name` is not one.
FailureMapSpec failure_map_preset(std::string_view name);
/// Checks sizes, arity, pivot and order; throws std::invalid_argument on bad specs.
void validate(const FailureMapSpec& spec);

struct SignCounts {
    std::uint64_t negative = 0, zero = 0, positive = 0;
    void add(Sign s) { (s == Sign::negative ? negative : s == Sign::zero ? zero : positive) += 1; }
};

struct FailureMap {
    FailureMapSpec spec;
    std::string kernel;
    std::vector<Sign> signs, exact;  ///< height rows of width cells, row j = offset j in y
    SignCounts counts, exact_counts;
    std::uint64_t wrong = 0;
    double wrong_rate() const { return signs.empty() ? 0 : double(wrong) / double(signs.size()); }
};

/// Evaluates the map (jobs threads; the result does not depend on jobs).
FailureMap compute_failure_map(const FailureMapSpec& spec, const Kernel& kernel, unsigned jobs,
                               Progress* progress = nullptr);

/// Where render_failure_map puts things, a function of the map's size only.
struct FailureMapLayout {
    int width = 0, height = 0;  ///< the whole picture
    int cell = 1;               ///< pixels per cell side
    int panel_x[3] = {};        ///< left edge of each panel
    int panel_y = 0;            ///< top edge of the panels
    int panel_width = 0, panel_height = 0;
};
FailureMapLayout failure_map_layout(int width, int height);

/// Three panels side by side, 2 px per cell when the map is at most 256 x 256: the
/// kernel's signs, the exact signs, and the exact signs faded with every wrong cell in
/// red. Colours: positive blue, zero white, negative amber; y grows upward. Around them:
/// a title (preset, predicate, moving point, kernel, wrong count), a caption per panel,
/// the offsets in ulps on both axes, and a legend of the colours.
Image render_failure_map(const FailureMap& map);

struct FailureMapOptions {
    std::vector<FailureMapSpec> specs;  ///< empty: the default preset list
    std::vector<std::string> kernels;   ///< empty: double, long-double, mpfr:64, adaptive, exact
    std::optional<int> width, height;   ///< override every spec's window
};

struct FailureMapRow {
    std::string preset, kernel, png;  ///< png: file name inside run.out
    SignCounts counts, exact_counts;
    std::uint64_t wrong = 0, cells = 0;
};

struct StudyResult {
    Report report{""};
    Table table;  ///< the main table (also written as CSV)
};

struct FailureMapStudy : StudyResult {
    std::vector<FailureMapRow> rows;
};

FailureMapStudy run_failure_map_study(const FailureMapOptions& options, const RunOptions& run);

// =================================================================================
// precision

struct PrecisionOptions {
    std::vector<unsigned> bits;             ///< empty: 24..128 by 8 (with 53, 64), then 160..512
    std::vector<testing::Family> families;  ///< empty: the near-degenerate families
    std::size_t samples = 0;                ///< queries per family and formulation; 0: default
};

struct PrecisionCell {
    Formulation formulation;
    testing::Family family;
    unsigned bits;
    std::uint64_t wrong = 0, total = 0;
};

struct PrecisionStudy : StudyResult {
    std::vector<PrecisionCell> cells;
};

PrecisionStudy run_precision_study(const PrecisionOptions& options, const RunOptions& run);

// =================================================================================
// triangulation

enum class Outcome {
    delaunay,      ///< certified Delaunay triangulation
    not_delaunay,  ///< a valid triangulation of the points, some edge not locally Delaunay
    invalid,       ///< not a valid triangulation (detail: the certifier's first finding)
    failure,       ///< the algorithm stopped itself (detail: its FailureKind)
    guard,         ///< the predicate-call budget ran out (never expected)
};
inline constexpr std::array all_outcomes{Outcome::delaunay, Outcome::not_delaunay, Outcome::invalid,
                                         Outcome::failure, Outcome::guard};
std::string_view to_string(Outcome o) noexcept;

struct Classification {
    Outcome outcome = Outcome::delaunay;
    std::string detail;  ///< FindingKind or FailureKind name; empty for delaunay
};

/// The insertion orders a study runs: every delaunay::Strategy but `automatic` (which
/// only picks one of them by input size). lexicographic is the paper's algorithm and the
/// default subject of the triangulation study.
inline constexpr std::array all_orders{delaunay::Strategy::lexicographic,
                                       delaunay::Strategy::radial, delaunay::Strategy::strips};

/// Points per strip whenever a study runs the strips order: small, so that the study's
/// point sets (tens to hundreds of points) are cut into several strips and the merges,
/// the part of strips that the other orders lack, actually run.
inline constexpr std::size_t study_strip_points = 64;

/// How a study triangulates: an algorithm of the registry (delaunay/algorithms.hpp) and,
/// for the external algorithm, its insertion order (ignored by the others). Converts from
/// an order alone: the external algorithm in that order, the subject of every study.
struct Method {
    Method(delaunay::Strategy order = delaunay::Strategy::lexicographic)
        : order(order) {}  // NOLINT
    Method(delaunay::Algorithm algorithm, delaunay::Strategy order)
        : algorithm(algorithm), order(order) {}
    delaunay::Algorithm algorithm = delaunay::Algorithm::external;
    delaunay::Strategy order = delaunay::Strategy::lexicographic;
    bool operator==(const Method&) const = default;
};

/// The methods of `algorithms`, in registry order: for an algorithm with insertion
/// orders (the external one) one method per order of `orders`, for any other one.
std::vector<Method> methods_of(std::span<const delaunay::Algorithm> algorithms,
                               std::span<const delaunay::Strategy> orders);

/// The delaunay::Options every study uses for `policy` and `method`: one thread (the
/// output does not depend on it, and the studies parallelise over inputs) and strips of
/// study_strip_points points.
delaunay::Options study_options(delaunay::InCirclePolicy policy, Method method);

/// Algorithms from a comma-separated list of registry names and "all", in the order
/// given, repeats dropped. Throws std::invalid_argument naming the spellings.
std::vector<delaunay::Algorithm> parse_algorithms(std::string_view list);

/// Orders from a comma-separated list of lexicographic, radial, strips and "all", in the
/// order given, repeats dropped. Throws std::invalid_argument naming the spellings.
std::vector<delaunay::Strategy> parse_orders(std::string_view list);

/// "determinant" or "cosine", as --incircle spells them.
std::string_view policy_name(delaunay::InCirclePolicy p);

/// The options of `exidel triangulate` that run `method` as the studies do (" --order
/// strips --strip-points 64", " --algorithm lawson", ...), each after a space.
std::string triangulate_order_flags(const Method& m);

/// Triangulates `points` with `kernel`, `policy` and `method` (study_options; at most
/// call_budget predicate calls, 0 meaning 64 n^2 + 10^6) and certifies the result
/// exactly.
Classification classify_triangulation(std::span<const Point2> points, const Kernel& kernel,
                                      delaunay::InCirclePolicy policy, Method method = {},
                                      std::uint64_t call_budget = 0);

/// Delta debugging: a smallest subset of `points` (no single point removable) whose
/// outcome under `method` is still `target`.outcome (and, for failures, the same
/// FailureKind).
std::vector<Point2> shrink_failing_input(std::vector<Point2> points, const Kernel& kernel,
                                         delaunay::InCirclePolicy policy,
                                         const Classification& target, Method method = {});

/// Fixture text: '#' comment lines (header), then "x y" with C99 hex floats, which
/// `exidel triangulate -i FILE` reads back exactly.
std::string fixture_text(std::span<const Point2> points, std::span<const std::string> header);

struct TriangulationOptions {
    std::vector<std::string>
        kernels;  ///< empty: double, long-double, mpfr:53, mpfr:106, adaptive, exact
    std::vector<testing::Family> families;  ///< empty: every family
    std::size_t seeds = 0;                  ///< point sets per family; 0: default
    std::vector<std::size_t> sizes;         ///< empty: 50, 100, 200, 500 (cycled over seeds)
    std::size_t shrink_per_class = 2;       ///< fixtures per (order, kernel, policy, outcome)
    /// Insertion orders for the outcome tables and fixtures; empty: lexicographic only
    /// (the paper's algorithm). The work table always runs all_orders.
    std::vector<delaunay::Strategy> orders;
    /// Algorithms of the registry; empty: every one. Each runs in the orders
    /// above if it takes an order (methods_of), and in the work table. With more than one,
    /// every table gets an "algorithm" column.
    std::vector<delaunay::Algorithm> algorithms;
    /// Precisions (significand bits) of the MPFR kernel for the failure-rate plot, each
    /// method with the determinant policy on every point set; empty: 12, 16, 20, 24, 32,
    /// 40, 48, 53, 64, 80, 106.
    std::vector<unsigned> precision_bits;
};

struct TriangulationRun {
    testing::Family family;
    std::size_t seed_index = 0, size = 0;
    std::string kernel;
    delaunay::InCirclePolicy policy;
    Classification result;
    delaunay::Strategy order = delaunay::Strategy::lexicographic;
    delaunay::Algorithm algorithm = delaunay::Algorithm::external;
};

struct Fixture {
    std::string file;  ///< path relative to run.out
    std::string kernel;
    delaunay::InCirclePolicy policy;
    Classification result;
    std::size_t original_size = 0, size = 0;
    delaunay::Strategy order = delaunay::Strategy::lexicographic;
    delaunay::Algorithm algorithm = delaunay::Algorithm::external;
};

/// The work of one insertion order on one family's point sets (every seed of the study),
/// with the adaptive kernel and the determinant policy: the algorithm's counters summed
/// over the sets, and how many results the certifier accepted.
struct OrderWork {
    testing::Family family;
    delaunay::Strategy order;
    delaunay::Algorithm algorithm = delaunay::Algorithm::external;
    std::size_t sets = 0, points = 0;  ///< points: input points, duplicates included
    delaunay::Counters counters;
    std::uint64_t distance_comparisons = 0;  ///< compare_distance calls (the radial sort)
    std::uint64_t merges = 0;                ///< strips merged: sum of (strips - 1)
    std::size_t certified = 0;               ///< sets whose result is certified Delaunay
};

/// One method at one MPFR precision: point sets whose triangulation came out wrong (any
/// outcome but certified Delaunay), out of `runs`.
struct PrecisionRate {
    Method method;
    unsigned bits = 0;
    std::uint64_t wrong = 0, runs = 0;
};

struct TriangulationStudy : StudyResult {
    std::vector<TriangulationRun> runs;
    std::vector<PrecisionRate> precision;  ///< per method (outcome-table order), then bits
    std::vector<Fixture> fixtures;
    std::vector<OrderWork> work;  ///< per family (study order), then per work method (all_orders
                                  ///< for the external algorithm)
};

TriangulationStudy run_triangulation_study(const TriangulationOptions& options,
                                           const RunOptions& run);

/// Reads a fixture (or any xy point file), classifies it as the study would, and says
/// so: the `exidel study replay` command.
Classification replay_fixture(const std::filesystem::path& file, const Kernel& kernel,
                              delaunay::InCirclePolicy policy, Method method = {});

// =================================================================================
// stages

/// The predicates whose stages are counted, in the order of StageCounts' rows: every
/// predicate of the list (the three formulations, then compare_distance, the radial
/// insertion order's sort key).
inline constexpr auto stage_predicates = all_predicates;
inline constexpr std::size_t compare_distance_row = std::size_t(Predicate::compare_distance);

/// Counts per predicate (stage_predicates) and AdaptiveStage.
using StageCounts =
    std::array<std::array<std::uint64_t, adaptive_stage_count>, stage_predicates.size()>;

/// The adaptive kernel, counting which stage decided each call: a PredicateKernel, so
/// the triangulation template runs with it unchanged.
struct StageCountingKernel : KernelWrapper<StageCountingKernel> {
    static constexpr bool is_exact = true;
    static std::string name() { return "adaptive-counting"; }
    /// Every predicate of the list (KernelWrapper): exidel::staged, counted in its row.
    template <class Points>
    Sign answer(Predicate which, const Points& points) const {
        return count(which, points);
    }
    Sign count(Predicate which, std::span<const Point2> points) const;
    mutable StageCounts counts{};  // mutable: the kernel interface is const
};
static_assert(PredicateKernel<StageCountingKernel>);

struct StagesOptions {
    std::vector<testing::Family> families;  ///< empty: every family
    std::size_t samples = 0;                ///< queries per family and predicate; 0: default
    std::size_t seeds = 0;                  ///< triangulations per family and context; 0: default
    std::size_t size = 0;                   ///< points per triangulation; 0: default
};

struct StagesRow {
    testing::Family family;
    /// "stream"; "triangulation/determinant" and "triangulation/cosine" (the paper's
    /// lexicographic order with each policy); "triangulation/radial" (determinant).
    std::string context;
    StageCounts counts{};
};

struct StagesStudy : StudyResult {
    std::vector<StagesRow> rows;
};

StagesStudy run_stages_study(const StagesOptions& options, const RunOptions& run);

// =================================================================================

/// All four studies with the quick (or default) presets, each in its own subfolder of
/// run.out, and run.out/report.md embedding the four reports. Every report starts with the
/// command that writes its files again (run.command is not used: `study all` takes only
/// the common options, so the command follows from them) and what built and ran it.
void run_all_studies(const RunOptions& run);

/// One sentence defining a family: its configuration, ulp offsets and exponent range, as
/// the generators of lib/testing build it.
std::string_view family_definition(testing::Family f);
/// A Markdown list defining each family, for a report (standalone: only when the report
/// is rendered on its own, as `study all` defines every family once at its top).
Report family_definitions(std::span<const testing::Family> families, bool standalone = true);

/// Families by name from a comma-separated list; "all", "near" (the near_degenerate
/// families) and "degenerate" (the degenerate ones) stand for several.
std::vector<testing::Family> parse_families(std::string_view list);

}  // namespace exidel::research

// =================================================================================
// constrained

namespace exidel::research {

/// The families of constrained inputs (points and segments) of the constrained study,
/// each drawn deterministically from a seed (src/constrained.cpp says how).
enum class ConstrainedFamily {
    crossing_grid,       ///< k x k segments of a rotated grid, ends and crossing points ulps off
    lattice_segments,    ///< a lattice scaled by 0.1; segments through (nearly) other points
    nearly_parallel,     ///< a bundle of segments within ulps of one line, plus a few across
    polygon_with_holes,  ///< a star polygon with a star hole, points within ulps of the sides
    random_segments,     ///< random segments between random points (the control)
};
inline constexpr std::array all_constrained_families{
    ConstrainedFamily::crossing_grid, ConstrainedFamily::lattice_segments,
    ConstrainedFamily::nearly_parallel, ConstrainedFamily::polygon_with_holes,
    ConstrainedFamily::random_segments};
std::string_view to_string(ConstrainedFamily f) noexcept;
/// One sentence saying how a family's inputs are drawn.
std::string_view constrained_family_definition(ConstrainedFamily f);
/// Families from a comma-separated list of the names above and "all", in the order
/// given, repeats dropped. Throws std::invalid_argument naming the spellings.
std::vector<ConstrainedFamily> parse_constrained_families(std::string_view list);

/// One constrained input.
struct ConstrainedInput {
    std::vector<Point2> points;
    std::vector<delaunay::Segment> segments;
};

/// The input of `family` drawn from `seed`: about `points` points and at most `segments`
/// segments (a pure function of the three).
ConstrainedInput draw_constrained_input(ConstrainedFamily family, std::uint64_t seed,
                                        std::size_t points, std::size_t segments);

enum class ConstrainedOutcome {
    certified,           ///< certify_constrained found nothing
    wrong,               ///< a result whose certificate has findings (detail: their kinds)
    failure,             ///< a typed Failure other than too_many_crossings (detail: its kind)
    too_many_crossings,  ///< more crossings than max_added_points (not a kernel error)
};
inline constexpr std::array all_constrained_outcomes{
    ConstrainedOutcome::certified, ConstrainedOutcome::wrong, ConstrainedOutcome::failure,
    ConstrainedOutcome::too_many_crossings};
std::string_view to_string(ConstrainedOutcome o) noexcept;

struct ConstrainedClassification {
    ConstrainedOutcome outcome = ConstrainedOutcome::certified;
    /// wrong: the distinct FindingKind names of the certificate (of its first 64 findings);
    /// failure and too_many_crossings: the FailureKind name; certified: empty.
    std::vector<std::string> kinds;
    std::size_t added_points = 0;  ///< crossing points added (a result only)
};

/// Runs constrained_delaunay with `kernel` and certifies the result exactly. An exception
/// from the library (anything but its typed Failure, which is an outcome) is a bug: it is
/// rethrown as std::runtime_error saying what was running.
ConstrainedClassification classify_constrained(const ConstrainedInput& input, const Kernel& kernel);

struct ConstrainedStudyOptions {
    /// empty: double, long-double, mpfr:53, mpfr:106, adaptive, exact
    std::vector<std::string> kernels;
    std::vector<ConstrainedFamily> families;  ///< empty: every family
    std::size_t seeds = 0;                    ///< inputs per family; 0: 24 (quick: 3)
};

struct ConstrainedRun {
    ConstrainedFamily family;
    std::size_t seed_index = 0, points = 0, segments = 0;
    std::string kernel;
    ConstrainedClassification result;
};

/// Outcome counts of one kernel on one family, in all_constrained_outcomes order.
using ConstrainedCounts = std::array<std::uint64_t, all_constrained_outcomes.size()>;

struct ConstrainedStudy : StudyResult {
    std::vector<std::string> kernels;
    std::vector<ConstrainedFamily> families;
    std::vector<ConstrainedRun> runs;  ///< per family, seed, then kernel
    /// counts[k * families.size() + f]: kernel k on family f.
    std::vector<ConstrainedCounts> counts;
    const ConstrainedCounts& at(std::size_t kernel, std::size_t family) const {
        return counts[kernel * families.size() + family];
    }
};

/// Every kernel on the same seeded inputs of every family: how constrained_delaunay ends
/// (certified, wrong, failure detected, too_many_crossings). Writes constrained.csv (one
/// row per run) and constrained_kinds.csv into run.out and returns the report (the caller
/// writes report.md, as `exidel study constrained` does) and the main table.
ConstrainedStudy run_constrained_study(const ConstrainedStudyOptions& options,
                                       const RunOptions& run);

}  // namespace exidel::research
