// exidel (private): the first stage of the adaptive kernel's orient2d and incircle, the
// floating-point filters that decide almost every call, as inline functions.
//
// adaptive.cpp builds its predicates on them. The library's triangulation includes them
// too (lib/delaunay/src/inline_adaptive.hpp), so that its hottest calls do not pay an
// out-of-line call each (docs/measurements.md, "The adaptive kernel inside the triangulation").
// Only translation units of exidel's own libraries may include this header: the bounds hold for the
// expressions exactly as written, rounded operation by operation, which the libraries'
// -ffp-contract=off guarantees and a user's compile line might not (a contracted a*b - c*d is not
// the expression constants.hpp bounds). fp_hygiene.hpp refuses the flags that can be detected.
#pragma once

#include <algorithm>
#include <cmath>

#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/types.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"

namespace exidel::detail {

/// Decides a filter: one predictable branch ("decided?") instead of one per sign; on
/// random input the sign is a coin flip, and a branch on it mispredicts half the time.
/// Strict comparisons: when an overflow makes the value and the bound infinite or NaN,
/// neither test passes.
inline bool filter_decides(double value, double errbound, Sign& sign) {
    const bool positive = value > errbound, negative = -value > errbound;
    sign = static_cast<Sign>(static_cast<int>(positive) - static_cast<int>(negative));
    return positive | negative;
}

/// orient2d's stage A, (a - c) x (b - c), which equals (b - a) x (c - a), with Shewchuk's
/// bound relative to the permanent `detsum` (constants.hpp: ccw_a, underflow_orient).
/// True when it decides; `detsum` is handed to the later stages either way.
inline bool orient2d_filter(Point2 a, Point2 b, Point2 c, Sign& sign, double& detsum) {
    const double detleft = (a.x - c.x) * (b.y - c.y);
    const double detright = (a.y - c.y) * (b.x - c.x);
    const double det = detleft - detright;
    detsum = std::fabs(detleft) + std::fabs(detright);
    const double errbound = bounds::ccw_a * detsum + bounds::underflow_orient;
    return filter_decides(det, errbound, sign);
}

/// The rounded differences a - d, b - d, c - d every stage of incircle starts from:
/// computed once by the filter and handed down to the slower stages.
struct IncircleDifferences {
    double adx, ady, bdx, bdy, cdx, cdy;
};

/// incircle's semi-static filter: one bound from the largest difference M, icc_static *
/// M^4, valid for M in [icc_static_min, icc_static_max] (constants.hpp). The expression is
/// stage A's, operation for operation. True when it decides; `v` is set either way.
inline bool incircle_filter(Point2 a, Point2 b, Point2 c, Point2 d, IncircleDifferences& v,
                            Sign& sign) {
    v = {a.x - d.x, a.y - d.y, b.x - d.x, b.y - d.y, c.x - d.x, c.y - d.y};
    const auto [adx, ady, bdx, bdy, cdx, cdy] = v;
    const double m = std::max({std::fabs(adx), std::fabs(ady), std::fabs(bdx), std::fabs(bdy),
                               std::fabs(cdx), std::fabs(cdy)});
    const double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                       (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                       (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    if (m >= bounds::icc_static_min && m <= bounds::icc_static_max) [[likely]] {
        const double m2 = m * m;
        return filter_decides(det, bounds::icc_static * (m2 * m2), sign);
    }
    return false;
}

}  // namespace exidel::detail
