// Stage fixtures: for each predicate of the plane and each stage of the adaptive kernel, a
// query that the stage decides, with the sign and the stage it must report. They were
// found so that mutation testing (docs/mutation.md) has a test that reaches each stage and
// fails when the stage answers differently: a stage skipped or merged into the next one,
// a stage reporting another's name (the `stages` study reads it), an exact-differences
// shortcut taken or not, an exact stage that sums where it should subtract.
//
// The generated ones come from seeded searches over near-collinear and near-cocircular
// points (rounded, nudged by up to 3 ulps, translated by up to 2^61, scaled by 2^228 or
// 2^-228 to leave the double-word range), the first query each stage decided; the
// constructed ones are exact degeneracies built to reach a stage no random query reached
// (each says how). Every sign is checked against GMP here as well.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/predicate.hpp"
#include "exidel/predicates/staged.hpp"

namespace exidel {
namespace {

struct StageFixture {
    const char* name;
    Predicate predicate;
    std::vector<Point2> points;
    AdaptiveStage stage;
    Sign sign;
};

Sign gmp_sign(Predicate which, std::span<const Point2> p) {
    switch (which) {
        case Predicate::orient2d: return GmpExactKernel::orient2d(p[0], p[1], p[2]);
        case Predicate::incircle: return GmpExactKernel::incircle(p[0], p[1], p[2], p[3]);
        case Predicate::incircle_cosine:
            return GmpExactKernel::incircle_cosine(p[0], p[1], p[2], p[3]);
        case Predicate::compare_distance: return GmpExactKernel::compare_distance(p[0], p[1], p[2]);
    }
    return Sign::zero;
}

// clang-format off
const std::vector<StageFixture> generated = {
    {"compare_distance exact (circle)", Predicate::compare_distance, {{-0x1.1e67898403682p-11, 0x1.83555e3b7cc7ep-10}, {-0x1.299cbbe64135p+8, 0x1.0ce17bd1e76fdp+3}, {-0x1.8b9d13279a79p+6, -0x1.18d24ba1953f3p+8}}, AdaptiveStage::exact, Sign::positive},
    {"compare_distance exact (circle+T)", Predicate::compare_distance, {{-0x1.9f53b521e92dp+3, 0x1.0e1ac5f7d8f9bp+6}, {0x1.623294bf67966p+3, 0x1.41146029a85cbp+5}, {0x1.7650639d367cdp+4, 0x1.04b3165b2eb45p+6}}, AdaptiveStage::exact, Sign::positive},
    {"incircle double_word (circle)", Predicate::incircle, {{-0x1.299cbbe64135p+8, 0x1.0ce17bd1e76fdp+3}, {-0x1.47c4e67ffbf71p+7, 0x1.f122d36246725p+7}, {-0x1.2559ff7ed338cp+8, 0x1.9707707a7ef55p+5}, {-0x1.8b9d13279a79p+6, -0x1.18d24ba1953f3p+8}}, AdaptiveStage::double_word, Sign::negative},
    {"incircle double_word (circle+T)", Predicate::incircle, {{0x1.623294bf67966p+3, 0x1.41146029a85cbp+5}, {-0x1.28367fc0ce7c1p+5, 0x1.7bab5bdaddc51p+6}, {-0x1.436789ef67782p+1, 0x1.99c7825177701p+6}, {0x1.7650639d367cdp+4, 0x1.04b3165b2eb45p+6}}, AdaptiveStage::double_word, Sign::negative},
    {"incircle_cosine double_word (circle)", Predicate::incircle_cosine, {{-0x1.299cbbe64135p+8, 0x1.0ce17bd1e76fdp+3}, {-0x1.47c4e67ffbf71p+7, 0x1.f122d36246725p+7}, {-0x1.2559ff7ed338cp+8, 0x1.9707707a7ef55p+5}, {-0x1.8b9d13279a79p+6, -0x1.18d24ba1953f3p+8}}, AdaptiveStage::double_word, Sign::negative},
    {"incircle_cosine double_word (circle+T)", Predicate::incircle_cosine, {{0x1.623294bf67966p+3, 0x1.41146029a85cbp+5}, {-0x1.436789ef67782p+1, 0x1.99c7825177701p+6}, {-0x1.28367fc0ce7c1p+5, 0x1.7bab5bdaddc51p+6}, {0x1.7650639d367cdp+4, 0x1.04b3165b2eb45p+6}}, AdaptiveStage::double_word, Sign::positive},
    {"incircle_cosine exact (circle+T)", Predicate::incircle_cosine, {{0x1.019e933c1ad4dp+18, 0x1.067f4011e9503p+18}, {0x1.98caaf5220d64p+17, 0x1.8d95242d9e13cp+17}, {0x1.845d267588f3p+17, 0x1.f395c969f1192p+17}, {0x1.9703b88d209ffp+17, 0x1.05bbae1e248f4p+18}}, AdaptiveStage::exact, Sign::positive},
    {"incircle_cosine stage_b (circle)", Predicate::incircle_cosine, {{0x1.6b21a06a4409bp+21, -0x1.49eca0ef41e54p+22}, {0x1.6b21a06a4409ap+21, -0x1.49eca0ef41e55p+22}, {0x1.6b21a06a4409ap+21, -0x1.49eca0ef41e54p+22}, {0x1.6b21a06a4409ap+21, -0x1.49eca0ef41e55p+22}}, AdaptiveStage::stage_b, Sign::zero},
    {"incircle_cosine stage_b (circle+T)", Predicate::incircle_cosine, {{0x1.6704b3ab2629ap+57, 0x1.6704b3ab22c9dp+57}, {0x1.6704b3ab2629ap+57, 0x1.6704b3ab22c9dp+57}, {0x1.6704b3ab2629ap+57, 0x1.6704b3ab22c9dp+57}, {0x1.6704b3ab2629ap+57, 0x1.6704b3ab22c9dp+57}}, AdaptiveStage::stage_b, Sign::zero},
    {"incircle_cosine stage_c (circle+T)", Predicate::incircle_cosine, {{0x1.623294bf67966p+3, 0x1.41146029a85cbp+5}, {-0x1.28367fc0ce7c1p+5, 0x1.7bab5bdaddc51p+6}, {-0x1.436789ef67782p+1, 0x1.99c7825177701p+6}, {0x1.7650639d367cdp+4, 0x1.04b3165b2eb45p+6}}, AdaptiveStage::stage_c, Sign::positive},
    {"orient2d stage_b (line)", Predicate::orient2d, {{0x1.b739dc21534c8p-26, -0x1.ac172f28ad158p-27}, {0x1.13d3976999ddp+0, -0x1.38bda38cc009p+0}, {0x1.db1f14080067fp-2, -0x1.0d5a90e5ac85bp-1}}, AdaptiveStage::stage_b, Sign::negative},
    {"orient2d stage_b (line+T)", Predicate::orient2d, {{0x1.75c8ad799f3a7p+21, 0x1.75c8ad7736762p+21}, {0x1.c20a9fa558268p+26, 0x1.4f8defbb29ccep+26}, {0x1.9d60b22e95ee7p+25, 0x1.37844fbc263cp+25}}, AdaptiveStage::stage_b, Sign::positive},
    {"orient2d stage_c (line)", Predicate::orient2d, {{0x1.2a68d760a9188p-8, -0x1.8c369c1a6659cp-8}, {-0x1.c649c8d0e98cp-3, -0x1.c05ce7016f586p+0}, {0x1.6c44f635dd50ap-9, -0x1.432d4bd4fb722p-6}}, AdaptiveStage::stage_c, Sign::positive},
    {"orient2d stage_c (line+T)", Predicate::orient2d, {{0x1.e328d54aacf15p+3, 0x1.e328d555f0cadp+3}, {-0x1.fac83c40a5dcp+26, -0x1.d3ef99eaddbaap+28}, {-0x1.9c08bb6f851fap+26, -0x1.7c735997f8138p+28}}, AdaptiveStage::stage_c, Sign::negative},
    {"incircle stage_b (circle*2^-228)", Predicate::incircle, {{-0x1.ef4b47321a44cp-215, 0x1.a35e2c7424b27p-214}, {0x1.711342f23f5dfp-214, -0x1.3c917d4848dc7p-214}, {0x1.f6e4625998b6dp-216, 0x1.cd9a71a30bdb1p-214}, {0x1.6ec111c5f1fc1p-214, 0x1.2f4e3bdd13542p-214}}, AdaptiveStage::stage_b, Sign::negative},
    {"incircle stage_b (circle*2^228)", Predicate::incircle, {{-0x1.db93d5a2240dep+243, -0x1.0e3dc8827b023p+245}, {-0x1.1cdab39b1e5cap+245, -0x1.35ed6f89f8446p+243}, {-0x1.333b541b939a3p+244, 0x1.f7d4fa771fbf3p+244}, {-0x1.0b40f652a062cp+245, 0x1.f4cf3a75be3c2p+243}}, AdaptiveStage::stage_b, Sign::positive},
    {"incircle stage_c (circle*2^-228)", Predicate::incircle, {{-0x1.f1bfb98adcc67p-215, -0x1.a727e3790e6a6p-215}, {0x1.d2778ed6040b7p-216, -0x1.31218512bafe2p-214}, {-0x1.c00fe3654dfdfp-215, -0x1.db73f77d25097p-215}, {-0x1.b956f8a857a4fp-215, 0x1.e1b219ff25ce7p-215}}, AdaptiveStage::stage_c, Sign::positive},
    {"incircle stage_c (circle*2^228)", Predicate::incircle, {{0x1.4c8481cef979p+246, -0x1.5a66a5fa9e68ap+248}, {0x1.98175a3ada48p+247, -0x1.12eecd54ffceap+247}, {-0x1.6365ed4505fa9p+247, 0x1.a44c18bdfd7eep+247}, {0x1.408139b483046p+245, -0x1.760dd4ff0746fp+248}}, AdaptiveStage::stage_c, Sign::positive},
    {"incircle_cosine exact (circle+T*2^-228)", Predicate::incircle_cosine, {{0x1.c0e97a4e60e37p-184, 0x1.c0e1ffd70a01fp-184}, {0x1.c0e26d3017e09p-184, 0x1.c0e9e7a772ecp-184}, {0x1.c0e472f19ee08p-184, 0x1.c0e0df8e78097p-184}, {0x1.c0e302be08382p-184, 0x1.c0e18c1d93f4ep-184}}, AdaptiveStage::exact, Sign::positive},
    {"incircle_cosine stage_c (circle*2^-228)", Predicate::incircle_cosine, {{-0x1.f1bfb98adcc67p-215, -0x1.a727e3790e6a6p-215}, {0x1.d2778ed6040b7p-216, -0x1.31218512bafe2p-214}, {-0x1.c00fe3654dfdfp-215, -0x1.db73f77d25097p-215}, {-0x1.b956f8a857a4fp-215, 0x1.e1b219ff25ce7p-215}}, AdaptiveStage::stage_c, Sign::negative},
};
// clang-format on

const std::vector<StageFixture> constructed = {
    // Exactly collinear through the origin, every difference exact (c is the origin) but
    // 70 bits apart, too wide for the small integers: stage B's value is the exact one,
    // zero, and with no tail it is the answer (the exact-differences shortcut).
    {"orient2d exact differences, tie",
     Predicate::orient2d,
     {{0x1p-60, 0x1.8p-59}, {0x1p+10, 0x1.8p+11}, {0, 0}},
     AdaptiveStage::stage_b,
     Sign::zero},
    // Exactly collinear on y = x, 2^60 away from c: every difference rounds (tail 1 or 3)
    // and the tail correction cancels too, so only the exact stage can say zero.
    {"orient2d inexact differences, tie",
     Predicate::orient2d,
     {{1, 1}, {3, 3}, {0x1p+60, 0x1p+60}},
     AdaptiveStage::exact,
     Sign::zero},
    // |p - c| = |q - c| exactly, differences exact but 70 bits apart: the squares' exact
    // sum (stage B) says zero.
    {"compare_distance exact differences, tie",
     Predicate::compare_distance,
     {{0, 0}, {0x1p-60, 0x1p+10}, {0x1p+10, 0x1p-60}},
     AdaptiveStage::stage_b,
     Sign::zero},
    // A rectangle centred at the origin, (u, v), (-u, v), (-u, -v), (u, -v) with u = 2^228,
    // v = 1: cocircular, every difference exact (2u, 2v, 0) but 229 bits apart and beyond
    // the double-word range, so stage B's exact value says zero (the exact-differences
    // shortcut).
    {"incircle exact differences, tie",
     Predicate::incircle,
     {{0x1p+228, 1}, {-0x1p+228, 1}, {-0x1p+228, -1}, {0x1p+228, -1}},
     AdaptiveStage::stage_b,
     Sign::zero},
    // The same rectangle with its last corner moved down by 1: exact differences, a
    // nonzero value too small for stage B's estimate, so the shortcut gives its sign.
    {"incircle exact differences, off the circle",
     Predicate::incircle,
     {{0x1p+228, 1}, {-0x1p+228, 1}, {-0x1p+228, -1}, {0x1p+228, -2}},
     AdaptiveStage::stage_b,
     Sign::negative},
    // c and d on the same side of ab with dot products of opposite signs, |a-c|^2 |b-c|^2
    // u^2 = |a-d|^2 |b-d|^2 v^2 = 40 exactly (u = 2, v = -1): a tie only the small integers
    // of the cosine test decide.
    {"incircle_cosine, same side, opposite dot products, tie",
     Predicate::incircle_cosine,
     {{0, 0}, {3, 0}, {1, 1}, {1, 2}},
     AdaptiveStage::small_integer,
     Sign::zero},
    // A right angle at c, (a - c).(b - c) = 0 exactly, with d on the same side of ab: the
    // second dot product is zero, so the answer is the first one's, negated, at stage B.
    {"incircle_cosine, right angle at c",
     Predicate::incircle_cosine,
     {{0, 0}, {2, 0}, {1, 1}, {1, 2}},
     AdaptiveStage::stage_b,
     Sign::negative},
    // Near-cocircular with d next to a (seeded search): the semi-static bound, 130 eps
    // times the fourth power of the largest difference, is too loose, and Shewchuk's stage
    // A, relative to the permanent, decides; both report the filter.
    {"incircle, decided by stage A after the semi-static filter",
     Predicate::incircle,
     {{0x1.ee3dd75bda907p+4, -0x1.38b4d24e14161p+3},
      {0x1.9665b6af5f99cp+4, -0x1.3d9869981d6dep+4},
      {0x1.4b32e6bbfbe8fp+4, 0x1.9118fd2959408p+4},
      {0x1.ee401a477aee3p+4, -0x1.38a71b0a33a19p+3}},
     AdaptiveStage::filter,
     Sign::positive},
    {"incircle, decided by stage A after the semi-static filter (2)",
     Predicate::incircle,
     {{0x1.d1fb73e99f9a7p-2, 0x1.77711fd301e5bp-2},
      {0x1.d5652a9f9f2b2p-2, 0x1.78b38f5adac3dp-2},
      {0x1.3ff8bd6d8445cp-1, 0x1.f8613a4b1869fp-3},
      {0x1.d1dd1357fc484p-2, 0x1.7765674854751p-2}},
     AdaptiveStage::filter,
     Sign::negative},
    // Four points of the circle x^2 + y^2 = 2^456 + 1, (u, v), (v, u), (-u, v), (-v, -u)
    // with u = 2^228, v = 1: cocircular exactly, differences u + v that round, outside the
    // double-word range: the exact stage decides the tie.
    {"incircle inexact differences, tie",
     Predicate::incircle,
     {{0x1p+228, 1}, {1, 0x1p+228}, {-0x1p+228, 1}, {-1, -0x1p+228}},
     AdaptiveStage::exact,
     Sign::zero},
    // (a - d).(b - d) = 0 exactly with a = (2^60, 1.5), b = (0.5, 2^60), d = (1, 1): the
    // differences round (2^60 - 1), stage B's and C's values are zero, so the dot product's
    // exact stage decides; c far off makes the other dot product positive.
    {"incircle_cosine, a dot product zero with rounded differences",
     Predicate::incircle_cosine,
     {{0x1p+60, 1.5}, {0.5, 0x1p+60}, {0x1p+61, 0x1p+61}, {1, 1}},
     AdaptiveStage::exact,
     Sign::negative},
};

// The cosine test's filter (incircle_cosine_impl): the entry test |u| > eu && |v| > ev,
// the shortcut for equal signs, the limit du, dv <= 1/4 and the comparison of L with R
// against its bound, each met at its boundary or just past it, so that a comparison
// moved across its boundary, a bound computed otherwise or a return removed changes the
// stage reported (the filter, or a later stage when the filter must not decide) or the
// sign. The ones with long coordinates come from scripts/stage_fixture_search.cpp, which
// replays the filter's arithmetic: a = (2^26, 0), b = (0, 2^26), c = (-s, 0) just outside
// the circle on the diameter ab (v = (2^26 + s) s has one term), d rounded to integers on
// that circle at 185 or 220 degrees from its centre, its y coordinate then bisected until
// |u| is a chosen multiple of eu (u cancels, d just inside the circle), and s tuned.
const std::vector<StageFixture> cosine_filter_edges = {
    // |u| == eu exactly: a - d = (2^-535, 0), b - d = (2^-535, 1), so u = 2^-1070 in one
    // term and fl(ccw_a * 2^-1070) = 0, eu = underflow_orient = 2^-1070. v = 1. The filter
    // must not decide (u's sign is not certain to it); below expansion_safe's range, the
    // exact stage answers.
    {"incircle_cosine, |u| exactly its bound",
     Predicate::incircle_cosine,
     {{0x1p-535, 0}, {0x1p-535, 1}, {-1, 0}, {0, 0}},
     AdaptiveStage::exact,
     Sign::negative},
    // The same with c and d exchanged: |v| == ev exactly.
    {"incircle_cosine, |v| exactly its bound",
     Predicate::incircle_cosine,
     {{0x1p-535, 0}, {0x1p-535, 1}, {0, 0}, {-1, 0}},
     AdaptiveStage::exact,
     Sign::negative},
    // u = 1 - (1 - 2^-53) = 2^-53, below eu (about 6 eps), and v = 120 of the same sign:
    // only one dot product is certain, so the filter must not decide; stage B finds u's
    // sign from exact differences.
    {"incircle_cosine, u below its bound, v above, same signs",
     Predicate::incircle_cosine,
     {{1, 0x1.fffffffffffffp-1}, {1, -1}, {-10, 0}, {0, 0}},
     AdaptiveStage::stage_b,
     Sign::negative},
    // u = -2, v = -3: both dot products negative and certain, the filter decides.
    {"incircle_cosine, both dot products negative",
     Predicate::incircle_cosine,
     {{0, 0}, {4, 0}, {2, 1}, {1, 1}},
     AdaptiveStage::filter,
     Sign::positive},
    // c and d on the same side of ab, u = 7, v = -1: L = 2 * 5 * 49 = 490 is far above
    // R = 10 * 13 * 1 = 130, the filter answers -sign(u).
    {"incircle_cosine, opposite dot products, L above R",
     Predicate::incircle_cosine,
     {{0, 0}, {3, 0}, {1, 1}, {1, 3}},
     AdaptiveStage::filter,
     Sign::negative},
    // u = 0.25, v = -1: L = 0.625 far below R = 20.3125, the filter answers -sign(v).
    {"incircle_cosine, opposite dot products, R above L",
     Predicate::incircle_cosine,
     {{0, 0}, {3, 0}, {1, 1}, {1, 1.5}},
     AdaptiveStage::filter,
     Sign::positive},
    // Search (cosine_du_window): |u| = 4.56 eu, du = 0.281 just above the limit 1/4, and R
    // thousands of times L: the filter must hand the query on (du computed as eu / |u| or
    // eu / (|u| + eu) would be below 1/4 and let it decide).
    {"incircle_cosine, |u| between 4 and 5 times its bound",
     Predicate::incircle_cosine,
     {{0x1p+26, 0}, {0, 0x1p+26}, {-0x1p-20, 0}, {-0x1.556748p+21, 0x1.7493945dff64ap+21}},
     AdaptiveStage::double_word,
     Sign::negative},
    // The same with c and d exchanged: dv = 0.281.
    {"incircle_cosine, |v| between 4 and 5 times its bound",
     Predicate::incircle_cosine,
     {{0x1p+26, 0}, {0, 0x1p+26}, {-0x1.556748p+21, 0x1.7493945dff64ap+21}, {-0x1p-20, 0}},
     AdaptiveStage::double_word,
     Sign::negative},
    // Search (cosine_constructed): that d with c = (2^-20, 0) inside the circle: both dot
    // products negative and certain, du = 0.281. Equal signs decide at once, whatever du.
    {"incircle_cosine, same signs, |u| between 4 and 5 times its bound",
     Predicate::incircle_cosine,
     {{0x1p+26, 0}, {0, 0x1p+26}, {0x1p-20, 0}, {-0x1.556748p+21, 0x1.7493945dff64ap+21}},
     AdaptiveStage::filter,
     Sign::positive},
    // Search (cosine_boundaries): |u| = 6.26 eu (du = 0.190) and s scanned double by double
    // until fl(L - R) equals the filter's bound exactly (0x1.042d5fdc30dacp+108): not
    // certain, the double-word stage decides.
    {"incircle_cosine, L - R exactly the filter's bound",
     Predicate::incircle_cosine,
     {{0x1p+26, 0},
      {0, 0x1p+26},
      {-0x1.7a704bd525c65p-25, 0},
      {-0x1.a2a4dep+23, 0x1.c0e4775c403d9p+24}},
     AdaptiveStage::double_word,
     Sign::positive},
    // Search (cosine_boundaries): |u| = 7.11 eu (du = 0.164), fl(R - L) equal to the bound
    // exactly (0x1.20cd5db7413cbp+108).
    {"incircle_cosine, R - L exactly the filter's bound",
     Predicate::incircle_cosine,
     {{0x1p+26, 0},
      {0, 0x1p+26},
      {-0x1.1a1f809f4c3bfp-23, 0},
      {-0x1.a2a4dep+23, 0x1.c0e4775c403f1p+24}},
     AdaptiveStage::double_word,
     Sign::negative},
};

// compare_distance past its filter: the filter's permanent, stage B when the differences
// are exact but the squares are not (every low part of a Two-Product must count), and the
// exact stage's squares of two-component differences (scripts/stage_fixture_search.cpp,
// distance_filter_permanent and distance_stage_b, prints them all).
//
// The stage B ties: N^2 = m^2 + n^2 with N = s^2 + r^2 = 2^27 + 2^14 + 1, m = 2 s r =
// 2^27 + 2^14, n = s^2 - r^2 = 2^14 + 1 (s = 2^13 + 1, r = 2^13). m^2 and n^2 are exact
// doubles, N^2 needs 55 bits: its Two-Product is N^2 - 1 plus a low part 1. With
// t = 2^-40 beside N the differences span 68 bits (no small integers), and
// |(N, t)|^2 - |(m, n)|^2 = t^2 > 0, while the high parts alone give t^2 - 1 < 0. Each
// position of the inexact square (x or y, p or q) is one fixture.
const std::vector<StageFixture> distance_stages = {
    // Scan p = (1 + k ulps, 0), q = (1, 0): at k = 2 the computed difference 2^-50 is above
    // dist_a |p|^2 but not above dist_a (|p|^2 + |q|^2): the filter must not decide.
    {"compare_distance, beyond half the filter's bound",
     Predicate::compare_distance,
     {{0, 0}, {0x1.0000000000002p+0, 0}, {1, 0}},
     AdaptiveStage::small_integer,
     Sign::positive},
    // The differences exact, 70 bits apart, their squares exact: stage B's short path, a
    // difference of 2^-120.
    {"compare_distance stage B, exact squares, not a tie",
     Predicate::compare_distance,
     {{0, 0}, {0x1p-60, 0x1p+10}, {0x1p+10, 0}},
     AdaptiveStage::stage_b,
     Sign::positive},
    {"compare_distance stage B, the low part of |p-c|^2 in x decides",
     Predicate::compare_distance,
     {{0, 0}, {0x1.0008002p+27, 0x1p-40}, {0x1.0008p+27, 0x1.0004p+14}},
     AdaptiveStage::stage_b,
     Sign::positive},
    {"compare_distance stage B, the low part of |p-c|^2 in y decides",
     Predicate::compare_distance,
     {{0, 0}, {0x1p-40, 0x1.0008002p+27}, {0x1.0008p+27, 0x1.0004p+14}},
     AdaptiveStage::stage_b,
     Sign::positive},
    {"compare_distance stage B, the low part of |q-c|^2 in x decides",
     Predicate::compare_distance,
     {{0, 0}, {0x1.0008p+27, 0x1.0004p+14}, {0x1.0008002p+27, 0x1p-40}},
     AdaptiveStage::stage_b,
     Sign::negative},
    {"compare_distance stage B, the low part of |q-c|^2 in y decides",
     Predicate::compare_distance,
     {{0, 0}, {0x1.0008p+27, 0x1.0004p+14}, {0x1p-40, 0x1.0008002p+27}},
     AdaptiveStage::stage_b,
     Sign::negative},
    // c = (0, -1): p - c = (1, 2^60 + 1) and q - c = (0, 2^60 + 1), the y differences
    // rounding to 2^60 with a tail of 1. The exact stage squares (1 + 0) and (2^60 + 1):
    // components equal to 1 and 0 must be told apart.
    {"compare_distance exact, a difference of 1 and a tail of 1",
     Predicate::compare_distance,
     {{0, -1}, {1, 0x1p+60}, {0, 0x1p+60}},
     AdaptiveStage::exact,
     Sign::positive},
    // Search (distance_sixteen_components, a fixed pseudo-random sequence): |q - c|^2 has
    // 16 components in the exact stage, all its array holds (a loop one past them is seen
    // by a sanitizer build here); p is q moved by one ulp in x.
    {"compare_distance exact, 16 components in |q-c|^2",
     Predicate::compare_distance,
     {{-0x1.0b1333ad37da4p-32, -0x1.5ac196d951a5p-76},
      {-0x1.b046002d3153dp+69, 0x1.141c88d67c83p-10},
      {-0x1.b046002d3153ep+69, 0x1.141c88d67c83p-10}},
     AdaptiveStage::exact,
     Sign::negative},
};

// Copies of fixtures scaled by 2^k (exact, and every stage decides relative to the
// inputs' magnitude): near the bottom of the range where the expansions are error-free for
// the predicate's degree (a stage that checked the range for a higher degree would hand
// them to GMP), and beyond its top, where GMP decides. (The generated incircle fixtures at
// 2^-228 are near the bottom of incircle's range already.)
struct Scaled {
    const char* fixture;
    int k;
    AdaptiveStage stage;
};

const std::vector<Scaled> scaled = {
    {"orient2d stage_c (line)", -400, AdaptiveStage::stage_c},
    {"orient2d inexact differences, tie", -400, AdaptiveStage::exact},
    {"orient2d inexact differences, tie", 500, AdaptiveStage::gmp},
    {"compare_distance exact (circle)", -400, AdaptiveStage::exact},
    {"compare_distance exact (circle)", 600, AdaptiveStage::gmp},
    {"incircle inexact differences, tie", -200, AdaptiveStage::exact},
    {"incircle inexact differences, tie", 30, AdaptiveStage::gmp},
    {"incircle_cosine stage_c (circle+T)", -400, AdaptiveStage::stage_c},
    // Beyond the dot products' range the degree-8 comparison runs on cpp_int at once.
    {"incircle_cosine exact (circle+T)", 600, AdaptiveStage::exact},
};

void check(const StageFixture& f) {
    AdaptiveStage stage{};
    const Sign sign = staged(f.predicate, f.points, stage);
    EXPECT_EQ(gmp_sign(f.predicate, f.points), f.sign) << f.name << ": the fixture's sign";
    EXPECT_EQ(sign, f.sign) << f.name;
    EXPECT_EQ(static_cast<int>(stage), static_cast<int>(f.stage)) << f.name;
}

TEST(StageFixtures, GeneratedQueriesAreDecidedByTheirStage) {
    for (const StageFixture& f : generated) check(f);
}

TEST(StageFixtures, ConstructedTiesAreDecidedByTheirStage) {
    for (const StageFixture& f : constructed) check(f);
}

TEST(StageFixtures, TheCosineFilterDecidesExactlyUpToItsBounds) {
    for (const StageFixture& f : cosine_filter_edges) check(f);
}

TEST(StageFixtures, CompareDistanceStagesSeeEveryLowOrderPart) {
    for (const StageFixture& f : distance_stages) check(f);
}

// Two equal points make orient2d and incircle zero, and compare_distance when p = q: the
// small-integer stage says so at once, for every pair of positions, even where the
// coordinates span 100 bits (too wide for the integers: without the check, a later stage
// would find the zero and report itself).
TEST(StageFixtures, TwoEqualPointsAreATieAtOnceInEveryPosition) {
    const std::array<Point2, 4> base = {
        {{0x1p-60, 1}, {0x1p+10, -3}, {-0x1p+40, 0x1p-70}, {5, 0x1p+30}}};
    for (const Predicate which :
         {Predicate::orient2d, Predicate::incircle, Predicate::compare_distance}) {
        const std::size_t n = which == Predicate::incircle ? 4 : 3;
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = i + 1; j < n; ++j) {
                // compare_distance(c, p, q) is zero for p = q only.
                if (which == Predicate::compare_distance && i == 0) continue;
                std::vector<Point2> points(base.begin(), base.begin() + n);
                points[j] = points[i];
                const std::string name = std::string(predicate_name(which)) + " points " +
                                         std::to_string(i) + " = " + std::to_string(j);
                check({name.c_str(), which, points, AdaptiveStage::small_integer, Sign::zero});
            }
        }
    }
}

TEST(StageFixtures, ScaledToTheEdgesOfTheExpansionRange) {
    for (const Scaled& s : scaled) {
        const StageFixture* original = nullptr;
        for (const auto* list : {&generated, &constructed}) {
            for (const StageFixture& f : *list) {
                if (std::string(f.name) == s.fixture) original = &f;
            }
        }
        ASSERT_NE(original, nullptr) << s.fixture;
        StageFixture f = *original;
        const std::string name = std::string(f.name) + " * 2^" + std::to_string(s.k);
        f.name = name.c_str();
        for (Point2& p : f.points) p = {std::ldexp(p.x, s.k), std::ldexp(p.y, s.k)};
        f.stage = s.stage;
        check(f);
    }
}

}  // namespace
}  // namespace exidel
