// exidel: a research instrument of the adaptive kernel (the `stages` study, lib/research):
// the same predicates as AdaptiveKernel, each also saying which stage decided. Not part
// of the kernel's interface: exidel/predicates/adaptive.hpp and all.hpp do not include it.
#pragma once

#include <span>

#include "exidel/predicates/predicate.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel {

/// Which stage of the adaptive kernel decided a call (for the `stages` study):
///   filter   the floating-point filter (stage A);
///   small_integer  two equal points, or every difference exact and all within a window of
///            30 bits (24 for insphere, 62 for orient2d's and compare_distance's, and
///            incircle's second try) of each other; exact 64/128/256-bit integer
///            arithmetic (exact ties on lattices end here);
///   double_word  incircle and incircle_cosine: the value from the exact differences in
///            double-word arithmetic, with a proven bound (proofs/bounds.md#incircle-double-
///            word, #cosine-double-word);
///            orient3d and insphere: from the exact differences in double-word arithmetic
///            too (proofs/bounds.md#orient3d-double-word, #insphere-double-word);
///   stage_b  the exact value of the rounded differences (Shewchuk's stage B); for
///            incircle_cosine, the exact signs of the two dot products; for
///            compare_distance, only when the differences were exact (exact ties on
///            grids end here);
///   stage_c  the first-order tail correction (Shewchuk's stage C);
///   exact    exact arithmetic inside the range where expansions are error-free (for the
///            degree-8 comparison of incircle_cosine: cpp_int integers, measured cheaper);
///   gmp      magnitudes outside that range: exact GMP integers.
enum class AdaptiveStage : int {
    filter = 0,
    small_integer = 1,
    double_word = 2,
    stage_b = 3,
    stage_c = 4,
    exact = 5,
    gmp = 6,
};
inline constexpr int adaptive_stage_count = 7;

/// The adaptive kernel's predicates, also reporting which stage decided.
Sign orient2d_staged(Point2 a, Point2 b, Point2 c, AdaptiveStage& stage);
Sign incircle_staged(Point2 a, Point2 b, Point2 c, Point2 d, AdaptiveStage& stage);
Sign incircle_cosine_staged(Point2 a, Point2 b, Point2 c, Point2 d, AdaptiveStage& stage);
Sign compare_distance_staged(Point2 c, Point2 p, Point2 q, AdaptiveStage& stage);
Sign orient3d_staged(Point3 a, Point3 b, Point3 c, Point3 d, AdaptiveStage& stage);
Sign insphere_staged(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e, AdaptiveStage& stage);

/// The staged predicate `which` on its point_count(which) first points (a predicate of the
/// list without a staged form is a new one that needs its case in adaptive.cpp: -Wswitch
/// says so).
Sign staged(Predicate which, std::span<const Point2> points, AdaptiveStage& stage);

}  // namespace exidel
