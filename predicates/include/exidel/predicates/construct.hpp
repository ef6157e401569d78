// exidel: constructions. A predicate returns a sign; a construction returns a point, and
// the only honest promise for a point of doubles is "the nearest doubles to the exact
// value". circumcenter() keeps that promise whatever the input and whatever flags the
// caller's own code is compiled with: equal exact circumcentres (the Delaunay triangles
// of one circle) give bit-identical doubles, so nothing downstream needs a tolerance.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "exidel/predicates/types.hpp"

namespace exidel {

/// What circumcenter() found.
enum class CircumcenterStatus : std::uint8_t {
    ok,                ///< both coordinates are the nearest doubles to the exact circumcentre
    collinear,         ///< a, b, c are collinear (or two coincide): no circle; point is NaN, NaN
    overflow,          ///< a coordinate's exact value rounds beyond the largest double: that
                       ///< coordinate is +-infinity (round to nearest's answer), the other is
                       ///< still correctly rounded
    non_finite_input,  ///< a NaN or infinite coordinate; point is NaN, NaN
};

std::string_view to_string(CircumcenterStatus status) noexcept;

/// Which stage decided a circumcentre (for measurements: the value never depends on it).
enum class CircumcenterStage : std::uint8_t {
    floating,     ///< plain doubles with a proven error bound
    double_word,  ///< double-word (about 106-bit) evaluation, verified
    exact,        ///< exact integers (GMP), rounded once
};

std::string_view to_string(CircumcenterStage stage) noexcept;

struct Circumcenter {
    /// Each coordinate is the exact circumcentre's coordinate rounded to nearest, ties to
    /// even, with gradual underflow (a value below the smallest subnormal's half rounds to
    /// a signed zero: +0 or -0 by the exact value's sign).
    Point2 point;
    CircumcenterStatus status;
    CircumcenterStage stage = CircumcenterStage::exact;

    bool ok() const noexcept { return status == CircumcenterStatus::ok; }
};

/// The circumcentre of triangle abc (either orientation), correctly rounded.
///
/// Each stage accepts a coordinate s only when it has proven that the exact value lies
/// strictly within half the gap between s and its nearer neighbour double: then no other
/// double can be nearest (proofs/bounds.md#circumcenter). Stage 1 evaluates the centre's
/// offset from a in doubles with an error bound: enough whenever the triangle is small
/// next to its coordinates, as Delaunay triangles of many points are. Stage 2 proposes s
/// from a double-word evaluation and verifies it with another. Stage 3 evaluates the
/// exact rational value with integers (GMP) and rounds it once: exact ties between two
/// doubles, nearly flat triangles, and coordinates beyond 2^+-150 or subnormal go there.
Circumcenter circumcenter(Point2 a, Point2 b, Point2 c) noexcept;

/// The circumcentres of many triangles: out[t] = circumcenter(points[triangles[3t]],
/// points[triangles[3t + 1]], points[triangles[3t + 2]]) for every t (indices must be
/// valid; out.size() == triangles.size() / 3). One call, so the stages inline into one
/// loop; stage_counts, when given, receives how many triangles each stage decided
/// (indexed by CircumcenterStage).
void circumcenters(std::span<const Point2> points, std::span<const std::uint32_t> triangles,
                   std::span<Circumcenter> out, std::uint64_t* stage_counts = nullptr) noexcept;

/// The quotient num / den * 2^exp2, negated when `negative`, rounded to nearest (ties to
/// even) with gradual underflow and overflow to infinity: stage 3's one rounding, for
/// other exact constructions (the clipped Voronoi diagram's corners). num and den are
/// magnitudes in little-endian 64-bit words; den must be nonzero (else NaN).
double round_quotient(std::span<const std::uint64_t> num, std::span<const std::uint64_t> den,
                      bool negative, long exp2 = 0) noexcept;

/// What intersection() found.
enum class IntersectionStatus : std::uint8_t {
    ok,                ///< both coordinates are the nearest doubles to the exact intersection
    parallel,          ///< the lines are parallel or the same, or a point pair coincides: NaN
    overflow,          ///< a coordinate rounds beyond the largest double (+-infinity there)
    non_finite_input,  ///< a NaN or infinite coordinate; point is NaN, NaN
};

std::string_view to_string(IntersectionStatus status) noexcept;

struct Intersection {
    Point2 point;  ///< each coordinate rounded to nearest, ties to even, gradual underflow
    IntersectionStatus status;
    bool ok() const noexcept { return status == IntersectionStatus::ok; }
};

/// The intersection of line ab with line cd, each coordinate the double nearest to the
/// exact value: the coordinates are lifted to integers on their common binary grid, the
/// point a + t (b - a) with t = ((c - a) x (d - c)) / ((b - a) x (d - c)) is formed as one
/// exact quotient per coordinate, and that quotient is rounded once by round_quotient()
/// (proofs/bounds.md#intersection). When the segments ab and cd cross, the exact point
/// lies in the bounding box of each, whose corners are doubles, so the rounded point does
/// too. Always exact integers (GMP): constrained triangulations call it once per crossing.
Intersection intersection(Point2 a, Point2 b, Point2 c, Point2 d) noexcept;

/// The sign of dist(p, ab) - r: the Euclidean distance from p to the closed segment ab
/// (to the point a when a == b) compared with r >= 0, exactly. The coordinates and r are
/// lifted to integers on their common binary grid and the squares compared there (with the
/// projection's parameter t = (p - a).(b - a) / |b - a|^2 deciding between the ends and the
/// line): no rounding at all. Sign::positive for a NaN or infinite input or r < 0.
Sign compare_segment_distance(Point2 p, Point2 a, Point2 b, double r) noexcept;

/// Stage 3 alone: the exact rational circumcentre rounded once (the reference the fast
/// path is tested against; always correct, much slower).
Circumcenter circumcenter_exact(Point2 a, Point2 b, Point2 c) noexcept;

}  // namespace exidel
