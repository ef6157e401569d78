// exidel-agreement: how often each kernel's sign differs from CGAL's exact predicates.
//
// For every input family (generators.hpp) and predicate, N seeded queries are evaluated
// by every kernel and by CGAL's Epick (exact predicates: static filter, interval
// arithmetic, then exact rationals). Each cell of the table is the number of sign
// disagreements out of the N of its row. Exit status 1 if any kernel that claims to be
// exact (K::is_exact, or MPFR at the proven precision of its row) disagrees even once.
//
//   exidel-agreement [--n N] [--seed S]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "exidel/predicates/all.hpp"
#include "exidel/testing/ulp.hpp"
#include "generators.hpp"

namespace {

using namespace exidel;
using exidel::bench::Quad;

// The predicates the table compares (compare_distance has no CGAL counterpart here).
constexpr std::array table_predicates{Predicate::orient2d, Predicate::incircle,
                                      Predicate::incircle_cosine};

std::array<Point2, 4> points_of(const Quad& q) { return {q.a, q.b, q.c, q.d}; }

// ---- the oracle ------------------------------------------------------------------------

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

Epick::Point_2 cgal(Point2 p) { return {p.x, p.y}; }

int cgal_orient(Point2 a, Point2 b, Point2 c) {
    return static_cast<int>(CGAL::orientation(cgal(a), cgal(b), cgal(c)));
}

// CGAL's side_of_oriented_circle has Shewchuk's convention: positive iff d is inside the
// circle through a, b, c when abc turns counter-clockwise.
int cgal_sign(Predicate p, const Quad& q) {
    switch (p) {
        case Predicate::orient2d: return cgal_orient(q.a, q.b, q.c);
        case Predicate::incircle:
            return static_cast<int>(
                CGAL::side_of_oriented_circle(cgal(q.a), cgal(q.b), cgal(q.c), cgal(q.d)));
        case Predicate::incircle_cosine:
            // Under the cosine form's precondition it equals orient2d(a,b,c) * incircle.
            return cgal_orient(q.a, q.b, q.c) * cgal_sign(Predicate::incircle, q);
        case Predicate::compare_distance: break;
    }
    return 0;
}

// The cosine form answers the in-circle question only when c and d are strictly on
// opposite sides of line ab (kernel.hpp); its rows keep only such queries.
bool cosine_precondition(const Quad& q) {
    return cgal_orient(q.a, q.b, q.c) * cgal_orient(q.a, q.b, q.d) < 0;
}

// ---- the precision that makes the MPFR kernel exact ------------------------------------
// On the grid of its smallest exponent the query's coordinates are integers of b bits;
// a p-bit float holds every integer below 2^p exactly, so if every intermediate of the
// formula (formulas.hpp) stays below 2^p nothing rounds and the sign is exact. The counts
// for our evaluation order (2b+3, 4b+8, 8b+12) are derived in proofs/bitcounts.md.
unsigned proven_bits(Predicate p, const Quad& q) {
    const auto points = points_of(q);
    const int b = testing::grid_bits(std::span(points.data(), point_count(p)));
    return testing::exact_bits(p, b);
}

// ---- columns ---------------------------------------------------------------------------

struct Column {
    std::string name;
    bool claims_exact;
    std::function<Sign(Predicate, const Quad&)> eval;
};

template <PredicateKernel K>
Column column(K k, bool claims_exact) {
    std::string name = k.name();
    return {name, claims_exact,
            [k](Predicate p, const Quad& q) { return evaluate(k, p, points_of(q)); }};
}

// The precision of the last column depends on the row, so columns are built per row.
std::vector<Column> columns(unsigned proven) {
    return {
        column(DoubleKernel{}, DoubleKernel::is_exact),
        column(LongDoubleKernel{}, LongDoubleKernel::is_exact),
        column(AdaptiveKernel{}, AdaptiveKernel::is_exact),
        column(GmpExactKernel{}, GmpExactKernel::is_exact),
        column(CppIntExactKernel{}, CppIntExactKernel::is_exact),
        column(MpfrKernel(53), false),
        column(MpfrKernel(106), false),
        column(MpfrKernel(proven), true),
    };
}

const std::vector<std::string> column_titles{"double",    "long-double", "adaptive", "exact",
                                             "exact-cpp", "mpfr:53",     "mpfr:106", "mpfr:proven"};

// ---- command line ----------------------------------------------------------------------

struct Options {
    std::size_t n = 2000;
    std::uint64_t seed = 1;
};

constexpr const char* usage =
    "usage: exidel-agreement [--n N] [--seed S]\n"
    "  --n N     queries per family and predicate (default 2000)\n"
    "  --seed S  seed of every generator (default 1); rows are seeded from (S, family,\n"
    "            predicate), so one row is reproducible on its own\n"
    "Prints, per family x predicate, the number of sign disagreements with CGAL's exact\n"
    "predicates (Epick) of each kernel. Exit status 1 if a kernel claiming exactness\n"
    "(adaptive, exact, exact-cpp, mpfr at the row's proven precision) disagrees, 2 on bad\n"
    "usage.\n";

template <class T>
bool parse_number(std::string_view s, T& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc{} && end == s.data() + s.size();
}

bool parse_options(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            std::cout << usage;
            std::exit(0);
        }
        if (i + 1 >= argc) return false;
        const std::string_view value = argv[++i];
        if (arg == "--n") {
            if (!parse_number(value, o.n) || o.n == 0) return false;
        } else if (arg == "--seed") {
            if (!parse_number(value, o.seed)) return false;
        } else {
            return false;
        }
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    if (!parse_options(argc, argv, opt)) {
        std::cerr << usage;
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    std::printf(
        "exidel-agreement: seed %llu, n %zu per row; cell = sign disagreements with "
        "CGAL Epick out of N\n\n",
        static_cast<unsigned long long>(opt.seed), opt.n);
    std::printf("%-16s %-16s %6s", "family", "predicate", "N");
    for (const std::string& t : column_titles) std::printf(" %11s", t.c_str());
    std::printf(" %6s\n", "bits");

    bool exactness_broken = false;
    const auto& fams = exidel::bench::families();
    for (std::size_t fi = 0; fi < fams.size(); ++fi) {
        for (Predicate p : table_predicates) {
            std::seed_seq seq{opt.seed, static_cast<std::uint64_t>(fi),
                              static_cast<std::uint64_t>(p)};
            exidel::bench::Rng rng(seq);
            const auto generate = p == Predicate::orient2d ? fams[fi].orient : fams[fi].incircle;
            std::vector<Quad> queries;
            // The cosine rows keep only queries meeting the precondition; families where
            // it never holds (collinear points, duplicates) give up after 50 N tries.
            for (std::size_t tries = 0; queries.size() < opt.n && tries < 50 * opt.n; ++tries) {
                const Quad q = generate(rng);
                if (p != Predicate::incircle_cosine || cosine_precondition(q)) queries.push_back(q);
            }
            std::vector<int> oracle;
            unsigned proven = MpfrKernel::min_bits;
            for (const Quad& q : queries) {
                oracle.push_back(cgal_sign(p, q));
                proven = std::max(proven, proven_bits(p, q));
            }
            std::printf("%-16s %-16s %6zu", fams[fi].name.c_str(),
                        std::string(predicate_name(p)).c_str(), queries.size());
            for (const Column& c : columns(proven)) {
                if (queries.empty()) {
                    std::printf(" %11s", "-");
                    continue;
                }
                std::size_t wrong = 0;
                for (std::size_t i = 0; i < queries.size(); ++i) {
                    wrong += to_int(c.eval(p, queries[i])) != oracle[i];
                }
                if (wrong > 0 && c.claims_exact) exactness_broken = true;
                std::printf(" %11zu", wrong);
            }
            std::printf(" %6u\n", queries.empty() ? 0u : proven);
            std::fflush(stdout);
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "\nbits: precision of the mpfr:proven column (the row's largest 2b+3 / 4b+8 / "
        "8b+12).\nfamilies:\n");
    for (const auto& f : fams) std::printf("  %-16s %s\n", f.name.c_str(), f.description.c_str());
    std::printf("%.1f s\n", seconds);
    if (exactness_broken) {
        std::printf("FAILED: a kernel claiming exactness disagrees with CGAL\n");
        return 1;
    }
    return 0;
}
