// exidel (private): refuse to compile exact code under flags that break it.
//
// The exact stages rely on IEEE binary64 with round-to-nearest and on every product and
// sum being rounded as written (no contraction into FMA, no reassociation). docs/background.md
// section 1: -ffast-math made Shewchuk's incircle wrong on 35% of near-cocircular
// queries, and contraction broke Dekker's split in orient2d.
#pragma once

#include <cfloat>
#include <limits>

#if defined(__FAST_MATH__)
#error \
    "exidel's exact predicates must not be compiled with -ffast-math (or -Ofast): it breaks error-free transformations. Compile the exidel library without it; your own code may use it."
#endif

#if defined(__FLT_EVAL_METHOD__) && __FLT_EVAL_METHOD__ != 0
#error \
    "exidel's exact predicates need double arithmetic evaluated in double (FLT_EVAL_METHOD == 0), not x87 extended precision."
#endif

static_assert(std::numeric_limits<double>::is_iec559, "exidel needs IEEE 754 binary64 doubles");
static_assert(std::numeric_limits<double>::digits == 53, "exidel needs 53-bit doubles");
