// exidel::testing: how RapidCheck prints points and signs in a counterexample.
//
// Coordinates are printed as hex floats (exact, and what a regression fixture should
// contain) followed by the decimal value to 17 significant digits for reading.
#pragma once

#include <cstdio>
#include <ostream>

#include "exidel/predicates/types.hpp"

namespace exidel {

/// RapidCheck's customization point (found by argument-dependent lookup).
inline void showValue(const Point2& p, std::ostream& os) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "{%a, %a} (%.17g, %.17g)", p.x, p.y, p.x, p.y);
    os << buf;
}

inline void showValue(Sign s, std::ostream& os) {
    os << (s == Sign::positive ? "positive" : s == Sign::negative ? "negative" : "zero");
}

}  // namespace exidel
