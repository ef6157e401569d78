// exidel bench: seeded, deterministic input families for the agreement table and the
// benchmarks.
//
// Kept here, self-contained, while the RapidCheck generators in lib/testing/ are being
// written; the two should be unified later (these are plain functions of a std::mt19937_64,
// usable from both). Compiled with -ffp-contract=off, so every generated double is exactly
// what the code below says (docs/background.md section 2: contraction changes generated inputs
// too).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "exidel/predicates/types.hpp"

namespace exidel::bench {

/// Four points; orient2d queries use a, b, c and leave d unused.
struct Quad {
    Point2 a, b, c, d;
};

using Rng = std::mt19937_64;

/// One input family: a generator of orient2d triples and one of incircle quadruples, and
/// for the families with a natural distance tie, one of compare_distance(c, p, q) queries
/// as (a, b, c) = (c, p, q) (null for the others).
struct Family {
    std::string name;
    std::string description;
    Quad (*orient)(Rng&);
    Quad (*incircle)(Rng&);
    Quad (*distance)(Rng&) = nullptr;
};

/// All families of the agreement table, in table order. The "-near" families take the
/// exactly degenerate configuration of their base family and move the last point (c for
/// orient2d, d for incircle) by -3..3 ulps per coordinate with std::nextafter.
const std::vector<Family>& families();

/// The family called `name`; throws std::invalid_argument if there is none.
const Family& family(const std::string& name);

/// `v` moved by `k` ulps (towards +inf for k > 0), each step one std::nextafter.
double ulps(double v, int k);

/// A uniformly random double in [0, 1) with 53 random bits.
double unit(Rng& rng);

/// A uniformly random integer in [lo, hi].
std::int64_t integer(Rng& rng, std::int64_t lo, std::int64_t hi);

/// The benchmarks' point sets: "uniform", n points uniform in the unit square from `seed`;
/// "grid", the sqrt(n) x sqrt(n) integer lattice (every square's corners cocircular), in
/// row order. Exits with status 2 and a message for any other name.
std::vector<Point2> uniform_or_grid(const std::string& input, std::size_t n, std::uint64_t seed);

}  // namespace exidel::bench
