// exidel: the error-bound constants of the adaptive kernel, each a formula in machine
// epsilon with the name of the document in proofs/ that derives it. A test in proofs/
// (label `proofs`) reads the proven values and checks that every constant here is at least
// its proven bound, so the code and the proofs cannot drift apart silently.
#pragma once

namespace exidel::bounds {

/// Unit roundoff of binary64 with round to nearest: half an ulp of 1.
inline constexpr double epsilon = 0x1p-53;

// ---- orient2d and the two-product sums of the same shape --------------------------------
// The filter evaluates (ax-cx)(by-cy) -/+ (ay-cy)(bx-cx) with five roundings; Shewchuk
// (1997), "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", Section 4.2 and 4.3; proofs/bounds.md#orient2d.
/// Stage A: if |D| > fl(ccw_a * T) for the computed value D and computed permanent
/// T = |(ax-cx)(by-cy)| + |(ay-cy)(bx-cx)|, then D has the exact sign. (The bound certifies
/// the sign; the error itself is at most eps |D| + (1 - eps) fl(ccw_a * T).)
inline constexpr double ccw_a = (3.0 + 16.0 * epsilon) * epsilon;
/// Stage B: error of the rounded estimate of the exact determinant of the rounded
/// differences, plus the effect of the differences' rounding.
inline constexpr double ccw_b = (2.0 + 12.0 * epsilon) * epsilon;
/// Stage C: second-order terms dropped by the first-order tail correction.
inline constexpr double ccw_c = (9.0 + 64.0 * epsilon) * epsilon * epsilon;
/// Stage C (orient2d and incircle): the error of stage B's estimate of its expansion,
/// relative to the estimate. Shewchuk's (3 + 8 eps) eps is not covered by our proof for
/// incircle, whose expansion is only in the class W (checked at run time, since Shewchuk's
/// Theorem 13 is false): proofs/bounds.md#expansion-estimate proves (40/7) eps + O(eps^2)
/// there (7/3 eps for orient2d), hence 6 eps.
inline constexpr double result_err = 6.0 * epsilon;

// ---- incircle ---------------------------------------------------------------------------
// Shewchuk (1997), Section 4.4; proofs/bounds.md#incircle. Shewchuk's stage A constant is
// (10 + 96 eps) eps; our written derivation only reaches (10 + 104 eps + O(eps^2)) eps, so
// the code uses 112: it costs nothing measurable and every constant here is one we prove.
inline constexpr double icc_a = (10.0 + 112.0 * epsilon) * epsilon;
/// Stage B. Shewchuk's (4 + 48 eps) eps is not covered by our proof: with the error of the
/// estimate of an expansion in class W (checked at run time), proofs/bounds.md#incircle-
/// stages-b-and-c proves (4 + 60.86 eps + O(eps^2)) eps, hence 64.
inline constexpr double icc_b = (4.0 + 64.0 * epsilon) * epsilon;
inline constexpr double icc_c = (44.0 + 576.0 * epsilon) * epsilon * epsilon;

// ---- incircle, double-word stage -------------------------------------------------------
// After stage A: the determinant of the exact differences (Two-Diff) in double-word
// arithmetic (adaptive.cpp). With t the permanent computed from the high parts, the error
// is at most (36 + O(eps)) eps^2 T and T <= (1 + O(eps)) t, so |det.hi| > fl(icc_dw * t)
// certifies the sign (proofs/bounds.md#incircle-double-word). A double (3 * 2^-102).
inline constexpr double icc_dw = 48.0 * epsilon * epsilon;
/// Used only when every nonzero |difference| is in [icc_dw_min, icc_dw_max]: above, a
/// product could overflow; below, underflow could add errors the bound does not cover.
inline constexpr double icc_dw_min = 0x1p-220;
inline constexpr double icc_dw_max = 0x1p220;

// ---- incircle, semi-static filter ------------------------------------------------------
// Tried before Shewchuk's stage A: with M the largest |rounded difference| (x - dx, ...),
// every one of the determinant's 12 degree-4 monomials is at most M^4, so one bound
// icc_static * M^4 covers the rounding of the differences (12 ((1-eps)^-4 - 1) M^4) and of
// the evaluation (80 eps M^4 to first order): 128 eps + O(eps^2) in all
// (proofs/bounds.md#incircle-semi-static). It costs a max over six magnitudes where the
// permanent costs a sum of products, and is faster than stage A on uniform input
// (docs/measurements.md). Used only for M in [icc_static_min, icc_static_max]: above, M^4
// could overflow; below, underflow could add errors the bound does not cover.
inline constexpr double icc_static = 130.0 * epsilon;
inline constexpr double icc_static_min = 0x1p-240;
inline constexpr double icc_static_max = 0x1p250;

// ---- gradual underflow ------------------------------------------------------------------
// Shewchuk's bounds assume no underflow. A product that lands in the subnormal range has
// an absolute error up to 2^-1075 beyond its relative error; sums and differences of
// doubles are exact when their result is subnormal. The filters therefore add an absolute
// term: orient2d has two products summed directly (2 * 2^-1075 plus the rounding of the
// bound itself), incircle's underflow errors are scaled by the lifts and the cross-product
// pairs they multiply (proofs/bounds.md#underflow).
inline constexpr double underflow_orient = 0x1p-1070;
inline constexpr double underflow_incircle = 0x1p-1068;

// ---- compare_distance -------------------------------------------------------------------
// The filter evaluates the squared lengths lp = fl(fl(dpx dpx) + fl(dpy dpy)) (dpx =
// fl(px - cx), ...) and lq alike, D = fl(lp - lq), and the permanent T = fl(lp + lq) (both
// lengths are nonnegative: the permanent is their sum). Each length is within
// ((1 + eps)^4 - 1) of its exact value, so the filter is orient2d's with four roundings per
// term instead of three (proofs/bounds.md#compare-distance proves (4 + 22 eps + O(eps^2))
// eps; lemma gappa/distance_term.g).
/// Stage A: if |D| > fl(fl(dist_a * T) + underflow_dist), D has the exact sign.
inline constexpr double dist_a = (4.0 + 32.0 * epsilon) * epsilon;
/// What gradual underflow can add: four squares (2^-1075 each) and the rounding of the
/// bound (proofs/bounds.md#underflow proves about 9 * 2^-1075).
inline constexpr double underflow_dist = 0x1p-1070;

// ---- the radial pre-sort key -------------------------------------------------------------
// key = fl(fl(dx dx) + fl(dy dy)) with dx = fl(px - cx), dy = fl(py - cy), the exact squared
// distance K = (px - cx)^2 + (py - cy)^2. When radial_key_min <= key <= radial_key_max,
//     |key - K| <= radial_key_rel * min(key, K),
// so key / (1 + radial_key_rel) <= K <= key * (1 + radial_key_rel): two points whose keys
// differ by more than that factor are ordered by their keys exactly, and only the others
// need compare_distance. proofs/bounds.md#radial-key proves (4 + O(eps)) eps for every key
// in [2^-1000, 2^1022]; the limits keep what underflow and overflow can do out of the bound
// (below 2^-1000 a square's underflow would be a large relative error; above, a square can
// overflow).
inline constexpr double radial_key_rel = 8.0 * epsilon;
inline constexpr double radial_key_min = 0x1p-960;
inline constexpr double radial_key_max = 0x1p1000;

// ---- incircle_cosine: the squared comparison --------------------------------------------
// L = |a-c|^2 |b-c|^2 u^2 and R = |a-d|^2 |b-d|^2 v^2 are computed in floating point from
// rounded differences: 11 roundings on each side, and u (v) carries the relative error
// du = eu / (|u~| - eu) certified by its own filter. For du <= 1/4 the computed L~ is
// within (cos_rel + cos_rel_dot * du) * L~ of L (proofs/bounds.md#cosine derives
// 11 eps + 3 du; the constants leave room for the rounding of the bound itself). The
// filter decides L > R only when L~ - R~ exceeds the sum of both sides' bounds.
inline constexpr double cos_rel = 16.0 * epsilon;
inline constexpr double cos_rel_dot = 4.0;
/// Largest relative error of a dot product for which the squared filter is tried.
inline constexpr double cos_max_dot_rel = 0.25;
/// The squared comparison is tried only when every factor and partial product is at least
/// this large (so none is subnormal) and finite.
inline constexpr double cos_min_factor = 0x1p-1000;

// ---- incircle_cosine: the double-word stage ---------------------------------------------
// When the dot products u, v have opposite exact signs, L - R (above) is evaluated from the
// exact differences in double-word arithmetic (adaptive.cpp): with t computed from the high
// parts, |diff.hi| > fl(cos_dw * t) certifies the sign of L - R
// (proofs/bounds.md#cosine-double-word proves (71 + O(eps)) eps^2). A double (3 * 2^-101).
inline constexpr double cos_dw = 96.0 * epsilon * epsilon;
/// Every nonzero |difference| in [cos_dw_min, cos_dw_max]: degree 8 needs a narrower range
/// than incircle's degree 4 for the same margins against overflow and underflow.
inline constexpr double cos_dw_min = 0x1p-110;
inline constexpr double cos_dw_max = 0x1p110;

// ---- orient3d -------------------------------------------------------------------------
// The filter evaluates Shewchuk's expansion along z of det(a - d, b - d, c - d) from the
// rounded differences (formulas.hpp, orient3d_of_differences, operation for operation) and
// its permanent T = |adz| (|bdx cdy| + |cdx bdy|) + |bdz| (...) + |cdz| (...). Each of its
// six monomials meets at most eight roundings (three differences, the product, the minor,
// the product by z, two sums), the last of which cannot change the sign: seven count.
// Shewchuk (1997), Section 4.4, publishes (7 + 56 eps) eps; proofs/bounds.md#orient3d
// proves (7 + 62 eps + O(eps^2)) eps, and 64 is the first double above it.
/// Stage A: if |D| > fl(fl(o3d_a * T) + fl(underflow_orient3d * S)), D has the exact sign
/// (S = |adz| + |bdz| + |cdz| + 1; the second term is skipped where it cannot change the
/// sum, adaptive3d.cpp).
inline constexpr double o3d_a = (7.0 + 64.0 * epsilon) * epsilon;
/// What gradual underflow can add: six minor products, each scaled by one |z|, three
/// products by z, the rounding of the bound (proofs/bounds.md#underflow-3d).
inline constexpr double underflow_orient3d = 0x1p-1068;

// ---- orient3d, double-word stage --------------------------------------------------------
// After stage A: det(a - d, b - d, c - d) from the exact differences (Two-Sum) in
// double-word arithmetic (adaptive3d.cpp), in the filter's order, against the permanent t
// computed from the high parts: |det.hi| > fl(o3d_dw * t) certifies the sign
// (proofs/bounds.md#orient3d-double-word, the rules of #incircle-double-word). Used only
// when every nonzero |difference| is in [o3d_dw_min, o3d_dw_max].
inline constexpr double o3d_dw = 32.0 * epsilon * epsilon;
inline constexpr double o3d_dw_min = 0x1p-220;
inline constexpr double o3d_dw_max = 0x1p220;

// ---- insphere ---------------------------------------------------------------------------
// Shewchuk's insphere with e as the pivot (formulas.hpp, insphere_of_differences) and its
// permanent. Each monomial lift x z x minor product meets at most sixteen roundings (five
// differences, three for the lift, five for the 3 x 3 orientation, the product by the lift,
// two sums), the last free: fifteen count. Shewchuk (1997), Section 4.4, publishes
// (16 + 224 eps) eps; proofs/bounds.md#insphere proves (15 + 262 eps + O(eps^2)) eps.
inline constexpr double isp_a = (16.0 + 320.0 * epsilon) * epsilon;
/// What gradual underflow can add, relative to S = L Z + L + C + 1 with L the sum of the
/// lifts, Z of the |z| differences and C of the four |3 x 3 orientations|
/// (proofs/bounds.md#underflow-3d).
inline constexpr double underflow_insphere = 0x1p-1066;

// ---- insphere, semi-static filter --------------------------------------------------------
// Tried before stage A, as incircle's: with M the largest |rounded difference|, each of
// the determinant's 72 degree-5 monomials is at most M^5, so one bound isp_static * M^5
// covers the rounding of the differences (72 ((1-eps)^-5 - 1) M^5, 360 eps M^5 to first
// order) and of the evaluation (at most ten roundings on each monomial's path besides the
// last, free: 720 eps M^5), 1080 eps + O(eps^2) in all, and the bound's own four
// roundings; proofs/bounds.md#insphere-semi-static proves 1032 eps + O(eps^2) (a tighter
// count of the evaluation). It costs a max over twelve magnitudes where stage A's
// permanent costs some forty operations. Used only for M in [isp_static_min,
// isp_static_max]: above, M^5 could overflow; below, it or underflow's absolute errors
// would not be negligible.
inline constexpr double isp_static = 1152.0 * epsilon;
inline constexpr double isp_static_min = 0x1p-190;
inline constexpr double isp_static_max = 0x1p200;

// ---- insphere, double-word stage --------------------------------------------------------
// As orient3d's, for the degree-5 determinant (proofs/bounds.md#insphere-double-word); a
// narrower range keeps degree 5 clear of overflow and its absolute terms negligible.
inline constexpr double isp_dw = 80.0 * epsilon * epsilon;
inline constexpr double isp_dw_min = 0x1p-160;
inline constexpr double isp_dw_max = 0x1p160;

// ---- the circumcentre construction (construct.hpp) --------------------------------------
// Stage 2 works in double-word arithmetic (a value is an unevaluated sum hi + lo of two
// doubles): the differences b - a, c - a exactly (Two-Diff), D = bx cy - by cx and
// Nx = cy |b|^2 - by |c|^2 (Ny alike) by double-word products and sums. It proposes the
// nearest double s to the centre x = a.x + Nx / (2 D), then evaluates
//     F = Nx + 2 D (a.x - s) = 2 D (x - s)          (a.x - s exact by Two-Diff)
// and accepts s only when |F| + its error bound < 2 (|D| - D's error bound) h, h half the
// smaller gap from s to a neighbour double: then |x - s| < h, and s is the nearest double.
// proofs/bounds.md#circumcenter proves |D~ - D| <= (11 + O(eps)) eps^2 T_D and
// |F~ - F| <= (25 + O(eps)) eps^2 (T_N + 2 T_D |a.x - s|), with T the permanents
// (the polynomials with every monomial's absolute value), under the range conditions
// below; circumcenter_rel = 2^-99 = 128 eps^2 covers both with room for the O(eps) terms,
// for gradual underflow inside the low parts, and for the permanents being evaluated in
// double from the high parts. A power of two, so multiplying by it is exact.
inline constexpr double circumcenter_rel = 0x1p-99;
/// Stage 1 (plain doubles, the same differences' high parts): |d~ - D| and |n~ - N| are at
/// most this times the computed permanent. At most 4 (D) and 7 (N) roundings per monomial,
/// the difference's included: gamma_7 / (1 - eps)^7 = (7 + O(eps)) eps. A power of two.
inline constexpr double circumcenter_float_rel = 8.0 * epsilon;
/// Stage 1's bound on the offset, fl(fl(E1 / 2) + 2 eps |u|), times this covers the
/// roundings of its own evaluation (proofs/bounds.md#circumcenter proves 1 + 9 eps + O(eps^2)).
inline constexpr double circumcenter_float_factor = 1.0 + 16.0 * epsilon;
/// Relative margin for the few double operations that evaluate the acceptance test
/// itself (at most 12 roundings, each at most eps = 2^-53).
inline constexpr double circumcenter_margin = 0x1p-40;
/// Stage 1 runs only when the largest |difference| is in [min_scale, max_scale], every
/// nonzero difference is at least min_part times the largest, and |a|, |s| and
/// |a - s| (when nonzero) are in [min_offset, max_offset]: then every monomial of the
/// permanents is 0 or in [2^-750, 2^453] and every product in the test is at most 2^703,
/// so nothing overflows and underflow can only touch the low parts
/// (proofs/bounds.md#circumcenter).
inline constexpr double circumcenter_min_scale = 0x1p-150;
inline constexpr double circumcenter_max_scale = 0x1p150;
inline constexpr double circumcenter_min_part = 0x1p-100;
inline constexpr double circumcenter_min_offset = 0x1p-400;
inline constexpr double circumcenter_max_offset = 0x1p400;

}  // namespace exidel::bounds
