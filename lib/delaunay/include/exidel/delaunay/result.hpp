// exidel: the result types of the triangulation, the hull algorithm and the certifier.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/detail/memory.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay {

/// How the erosion step decides "the new point is strictly inside the circumcircle of
/// the triangle behind this border edge".
enum class InCirclePolicy {
    determinant,  ///< k.incircle(a, b, c, p) with abc the CCW triangle.
    cosine,       ///< the paper's Section 5 test, k.incircle_cosine(a, b, c, p).
};

/// The external algorithm's insertion order (Options::strategy; other algorithms ignore
/// it). Every strategy gives a Delaunay triangulation with an exact kernel, and the same
/// one whenever no four points are cocircular.
enum class Strategy {
    automatic,      ///< radial for small inputs and convex curves, else strips (choose_strategy)
    lexicographic,  ///< the paper: one external incremental run in (x, y) order
    radial,         ///< one external incremental run, ascending distance from a centre
    strips,         ///< lexicographic strips, each radial, merged by the Guibas-Stolfi zipper
};

std::string_view to_string(Strategy strategy) noexcept;

struct Options {
    InCirclePolicy incircle = InCirclePolicy::determinant;
    Strategy strategy = Strategy::automatic;
    /// Worker threads for the strips strategy (1 = the calling thread only). The output
    /// does not depend on it.
    unsigned threads = 1;
    /// Points per strip for the strips strategy; 0 chooses by input size. A strip is
    /// extended until its points are not all collinear (the merge needs triangles on both
    /// sides), so 1 or 2 mean "the smallest non-collinear strips": pure divide and conquer.
    std::size_t strip_points = 0;
    /// Which algorithm runs (algorithms.hpp lists them). Every algorithm gives a Delaunay
    /// triangulation with an exact kernel, and the same one whenever no four points are
    /// cocircular.
    Algorithm algorithm = Algorithm::external;
    /// Tiles per strip for the strips strategy: each strip holds about strip_tiles x
    /// strip_points points and is cut across (by y) into strip_tiles tiles of about
    /// strip_points, so that pieces stay roughly square when strips would be thin; 1 =
    /// plain strips; 0 chooses by input size (default_strip_tiles, external.hpp).
    std::size_t strip_tiles = 0;

    // Chainable setters, one per field: `Options{}.with_algorithm(a).with_threads(n)`
    // names each field it sets, in any order, and leaves the others at their defaults.
    // Every place that builds Options from its own settings uses them: a new field is its
    // declaration and its setter here, and no call site depends on the order of the fields.
    constexpr Options with_incircle(InCirclePolicy v) const noexcept {
        return with(&Options::incircle, v);
    }
    constexpr Options with_strategy(Strategy v) const noexcept {
        return with(&Options::strategy, v);
    }
    constexpr Options with_threads(unsigned v) const noexcept { return with(&Options::threads, v); }
    constexpr Options with_strip_points(std::size_t v) const noexcept {
        return with(&Options::strip_points, v);
    }
    constexpr Options with_algorithm(Algorithm v) const noexcept {
        return with(&Options::algorithm, v);
    }
    constexpr Options with_strip_tiles(std::size_t v) const noexcept {
        return with(&Options::strip_tiles, v);
    }

private:
    template <class T>
    constexpr Options with(T Options::*field, T value) const noexcept {
        Options copy = *this;
        copy.*field = value;
        return copy;
    }
};
static_assert(std::is_aggregate_v<Options>, "Options stays an aggregate: designated initializers");

/// What a run records. `off` compiles every counter away.
enum class Instrumentation {
    off,
    counters,  ///< count predicate calls, flips, triangles created and destroyed
    theorem1,  ///< counters, and check the paper's Theorem 1 exactly at every in-circle test
};

/// The counters, defined once: X(name) per field, in the order `--stats` prints them.
/// seed_orientations: orient2d calls looking for the seed; tangent_orientations: in the
/// tangent walks; eroded_edges = edge flips of the incremental view; theorem1_checks and
/// theorem1_violations: Theorem 1, at each in-circle test of border edge ab with opposite
/// vertex c, the new point p and c are strictly on opposite sides of ab (exact
/// orientation); visible_search_orientations: the radial order's search for a visible
/// hull edge from the hash; merge_*: the strips' zipper (orientations in the tangent
/// search and candidate validity; deleted edges: of the two sides, removed by a merge);
/// location_steps: triangles a point-location walk entered, or history-DAG nodes a
/// descent passed through (bowyer-watson, randomized); location_orientations: the
/// orient2d calls of point location; cavity_orientations: bowyer-watson's orient2d calls
/// deciding whether a triangle is in conflict (ghost triangles; with the cosine policy
/// the side test before an in-circle test); lawson_flips: edges flipped to restore the
/// Delaunay property (randomized). Bowyer-Watson counts the edges inside each cavity as
/// eroded_edges: the flips a split and Lawson's flips would have made.
#define EXIDEL_DELAUNAY_COUNTERS(X) \
    X(seed_orientations)            \
    X(tangent_orientations)         \
    X(incircle_tests)               \
    X(eroded_edges)                 \
    X(triangles_created)            \
    X(triangles_destroyed)          \
    X(theorem1_checks)              \
    X(theorem1_violations)          \
    X(visible_search_orientations)  \
    X(merge_orientations)           \
    X(merge_incircle_tests)         \
    X(merge_deleted_edges)          \
    X(merge_cross_edges)            \
    X(location_steps)               \
    X(location_orientations)        \
    X(cavity_orientations)          \
    X(lawson_flips)

struct Counters {
#define EXIDEL_DELAUNAY_COUNTER_FIELD(name) std::uint64_t name = 0;
    EXIDEL_DELAUNAY_COUNTERS(EXIDEL_DELAUNAY_COUNTER_FIELD)
#undef EXIDEL_DELAUNAY_COUNTER_FIELD

    /// Calls f(name, value) for every counter, in the order of the list.
    template <class F>
    void for_each(F&& f) const {
#define EXIDEL_DELAUNAY_COUNTER_VISIT(name) f(std::string_view(#name), name);
        EXIDEL_DELAUNAY_COUNTERS(EXIDEL_DELAUNAY_COUNTER_VISIT)
#undef EXIDEL_DELAUNAY_COUNTER_VISIT
    }

    /// Edge flips in the incremental view plus edges deleted by merges plus Lawson flips:
    /// the work that depends on the insertion order.
    std::uint64_t flips() const noexcept {
        return eroded_edges + merge_deleted_edges + lawson_flips;
    }
    Counters& operator+=(const Counters& o) noexcept;
};

/// Why a run stopped. Everything but non_finite_input, too_many_points, unknown_algorithm,
/// invalid_segment and too_many_crossings means the
/// kernel's answers were geometrically inconsistent (only possible with an inexact
/// kernel); the structure is then abandoned instead of being walked further.
enum class FailureKind {
    non_finite_input,         ///< a NaN or infinite coordinate
    too_many_points,          ///< more points than 32-bit half-edge indices can address
    no_visible_edge,          ///< the new point saw no hull edge from the last point
    hull_walk_exceeded,       ///< a tangent walk went all the way round the hull
    erosion_inconsistent,     ///< the erosion reached an edge that is not on the border
    erosion_exceeded,         ///< the erosion destroyed more triangles than exist
    point_inside_hull,        ///< radial order: the new point saw no edge of the current hull
    merge_inconsistent,       ///< strips: the zipper's answers do not describe a merge
    result_inconsistent,      ///< the finished structure does not close (hull or neighbours)
    unknown_algorithm,        ///< Options::algorithm holds no Algorithm enumerator
    location_exceeded,        ///< a point-location walk or DAG descent did not end where it must
    cavity_inconsistent,      ///< bowyer-watson: the conflict triangles do not form a disc
    flips_exceeded,           ///< randomized: more flips than the new point can have neighbours
    location_inconsistent,    ///< a located point is on all three edge lines of a triangle
    update_inconsistent,      ///< an insertion or removal met a mesh no consistent kernel leaves
    invalid_segment,          ///< a constraint names a point index past the input
    too_many_crossings,       ///< constraints: more crossing points than allowed
    constraint_inconsistent,  ///< constraints: a segment's insertion met what no consistent kernel
                              ///< leaves
};

std::string_view to_string(FailureKind kind) noexcept;

inline constexpr std::size_t no_index = std::numeric_limits<std::size_t>::max();

struct Failure {
    FailureKind kind;
    std::size_t input_index = no_index;  ///< the offending / inserted input point
    /// Its position in the insertion order (the insertion step); no_index for failures
    /// of a merge or of the finished structure, which belong to no single insertion.
    std::size_t insertion = no_index;
    std::string message;  ///< where it happened, in words
};

/// A triangulation in compact index arrays (the layout of delaunator).
///
///   triangles[3t], [3t+1], [3t+2]  the vertices of triangle t, counter-clockwise, as
///                                  input indices (of the first occurrence of a point).
///   halfedges[e]                   the twin of half-edge e, -1 on the boundary. Half-edge
///                                  e runs from triangles[e] to triangles[next(e)], with
///                                  next(e) = e % 3 == 2 ? e - 2 : e + 1.
///   hull                           the boundary as a counter-clockwise cycle starting at
///                                  the lexicographically smallest point; collinear
///                                  boundary points are vertices. When `collinear` is set
///                                  there are no triangles and `hull` is the chain of all
///                                  distinct points in lexicographic order.
///
/// Correspondence with the paper (Section 3): its hull list L_ch is `hull`; its
/// dictionary D_tri maps an edge (i1, i2) to the one or two opposite vertices; here the
/// edge is a half-edge e with i1 = triangles[e], i2 = triangles[next(e)], its opposite
/// vertex is triangles[prev(e)], and the second entry of D_tri is the opposite vertex
/// of halfedges[e] (none when it is -1, the boundary edges of D_tri with one entry).
struct Triangulation {
    std::vector<std::uint32_t> triangles;
    std::vector<std::int32_t> halfedges;
    std::vector<std::uint32_t> hull;
    /// For every input index i, the input index of the first occurrence of points[i].
    std::vector<std::uint32_t> vertex_of_input;
    /// Input indices that repeat an earlier point exactly (increasing).
    std::vector<std::uint32_t> duplicates;
    bool collinear = false;  ///< fewer than three distinct points, or all on one line

    std::size_t triangle_count() const noexcept { return triangles.size() / 3; }
};

constexpr std::size_t next_halfedge(std::size_t e) noexcept { return e % 3 == 2 ? e - 2 : e + 1; }
constexpr std::size_t prev_halfedge(std::size_t e) noexcept { return e % 3 == 0 ? e + 2 : e - 1; }

struct Result {
    Triangulation triangulation;  ///< meaningful only when ok()
    Counters counters;            ///< zero unless instrumented
    std::optional<Failure> failure;
    Algorithm algorithm = Algorithm::external;  ///< the algorithm that ran
    Strategy strategy =
        Strategy::lexicographic;  ///< external: the strategy that ran (never automatic)
    std::size_t strips = 1;       ///< pieces merged (1 unless strips ran): strips, or their tiles
    /// external, automatic: pieces (or the one radial run) whose radial insertion gave up
    /// on too many flips and were inserted by cavities instead (external.hpp)
    std::size_t cavity_pieces = 0;
    bool ok() const noexcept { return !failure.has_value(); }
};

namespace detail {

/// Points sorted lexicographically (x, then y) with exact duplicates removed.
struct SortedInput {
    FreshVector<Point2> points;           ///< distinct, increasing
    FreshVector<std::uint32_t> input_of;  ///< sorted position -> input index (first occurrence)
    std::vector<std::uint32_t> vertex_of_input;
    std::vector<std::uint32_t> duplicates;
};

/// Largest input size: 6n half-edges must fit in std::int32_t.
inline constexpr std::size_t max_points = 350'000'000;

/// Rejects non-finite coordinates (naming the first bad index) and oversized input
/// before any other work, then sorts and removes duplicates, on `threads` threads over
/// chunks of `chunk` points (tests make them small). The result depends on neither.
std::optional<Failure> sort_and_dedupe(std::span<const Point2> input, SortedInput& out,
                                       unsigned threads = 1,
                                       std::size_t chunk = std::size_t{1} << 16);

}  // namespace detail

}  // namespace exidel::delaunay
