// exidel predicate benchmarks: ns per call of each predicate x kernel x input, with CGAL's
// Epick predicates measured in the same run as the peer.
//
// Each benchmark cycles through an array of 2^16 pre-generated queries, one call per
// iteration, so the reported time is the cost of one call on varied data (branch
// predictors and caches see the array, not one repeated query). The signs are summed and
// the sum passed to benchmark::DoNotOptimize, so no call can be dropped.
//
// Inputs: every family of generators.hpp (uniform, uniform-near: collinear / cocircular up
// to double rounding, then moved by a few ulps; exact ties on lattice circles, grids and
// lines and their -near variants; Kettner et al.'s configurations; wide exponents;
// duplicates). Every kernel runs on uniform and uniform-near; double, adaptive and CGAL on
// all. incircle_cosine runs on the incircle arrays; compare_distance on the families with
// a distance tie (generators.hpp).
//
// Repetitions and ratios (medians), see bench/ratios.py:
//   exidel_bench_predicates --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true --benchmark_format=json > predicates.json
//   python3 bench/ratios.py predicates.json
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <span>
#include <string>
#include <vector>

#include "exidel/predicates/all.hpp"
#include "cycle.hpp"
#include "generators.hpp"

namespace {

using namespace exidel;
using exidel::bench::Quad;

constexpr std::size_t queries_per_array = std::size_t{1} << 16;

struct Input {
    std::string name;
    std::vector<Quad> orient;    // a, b, c
    std::vector<Quad> incircle;  // a, b, c, d
    std::vector<Quad> distance;  // (c, p, q) as (a, b, c); empty if the family has none
    bool every_kernel;           // false: only double, adaptive and the peer
};

std::vector<Quad> make(Quad (*generate)(exidel::bench::Rng&), std::uint64_t seed) {
    std::vector<Quad> v;
    if (generate == nullptr) return v;
    exidel::bench::Rng rng(seed);
    v.reserve(queries_per_array);
    for (std::size_t i = 0; i < queries_per_array; ++i) v.push_back(generate(rng));
    return v;
}

// Every family of generators.hpp; the slow kernels only on uniform and uniform-near.
const std::vector<Input>& inputs() {
    static const std::vector<Input> all = [] {
        std::vector<Input> v;
        std::uint64_t seed = 1;
        for (const exidel::bench::Family& f : exidel::bench::families()) {
            const bool every = f.name == "uniform" || f.name == "uniform-near";
            v.push_back({f.name, make(f.orient, seed), make(f.incircle, seed + 1),
                         make(f.distance, seed + 2), every});
            seed += 3;
        }
        return v;
    }();
    return all;
}

template <PredicateKernel K>
void register_kernel(const K& k, bool every_family) {
    for (const Input& in : inputs()) {
        if (!in.every_kernel && !every_family) continue;
        const std::string suffix = "/" + in.name + "/" + std::string(k.name());
        benchmark::RegisterBenchmark(("orient2d" + suffix).c_str(), [k, &in](benchmark::State& s) {
            exidel::bench::cycle(s, in.orient,
                                 [&k](const Quad& q) { return to_int(k.orient2d(q.a, q.b, q.c)); });
        });
        benchmark::RegisterBenchmark(("incircle" + suffix).c_str(), [k, &in](benchmark::State& s) {
            exidel::bench::cycle(s, in.incircle, [&k](const Quad& q) {
                return to_int(k.incircle(q.a, q.b, q.c, q.d));
            });
        });
        benchmark::RegisterBenchmark(("incircle_cosine" + suffix).c_str(),
                                     [k, &in](benchmark::State& s) {
                                         exidel::bench::cycle(s, in.incircle, [&k](const Quad& q) {
                                             return to_int(k.incircle_cosine(q.a, q.b, q.c, q.d));
                                         });
                                     });
        if (in.distance.empty()) continue;
        benchmark::RegisterBenchmark(("compare_distance" + suffix).c_str(),
                                     [k, &in](benchmark::State& s) {
                                         exidel::bench::cycle(s, in.distance, [&k](const Quad& q) {
                                             return to_int(k.compare_distance(q.a, q.b, q.c));
                                         });
                                     });
    }
}

// ---- batched (batch.hpp) -------------------------------------------------------------------
// Each iteration runs the batched predicate over a chunk of `chunk` queries of the same
// array (cycling through it); the counter per_iteration tells bench/ratios.py to divide,
// so the reported time is per query, comparable with one call per query above.
constexpr std::size_t chunk = 1024;

struct Columns {
    std::vector<Point2> a, b, c, d;
};

Columns columns(const std::vector<Quad>& queries) {
    Columns k;
    for (const Quad& q : queries) {
        k.a.push_back(q.a);
        k.b.push_back(q.b);
        k.c.push_back(q.c);
        k.d.push_back(q.d);
    }
    return k;
}

template <class Call>
void run_batch(benchmark::State& state, const std::vector<Quad>& queries, Call call) {
    const Columns k = columns(queries);
    std::vector<Sign> out(chunk);
    std::size_t start = 0;
    int sum = 0;
    for (auto _ : state) {
        const auto part = [&](const std::vector<Point2>& v) {
            return std::span<const Point2>(v).subspan(start, chunk);
        };
        call(part(k.a), part(k.b), part(k.c), part(k.d), std::span<Sign>(out));
        sum += to_int(out[0]) + to_int(out[chunk - 1]);
        start = (start + chunk) % queries.size();  // the size is a multiple of chunk
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * chunk));
    state.counters["per_iteration"] = static_cast<double>(chunk);
}

using Span = std::span<const Point2>;

void register_batch() {
    for (const Input& in : inputs()) {
        const std::string suffix = "/" + in.name + "/adaptive-batch";
        benchmark::RegisterBenchmark(("orient2d" + suffix).c_str(), [&in](benchmark::State& s) {
            run_batch(s, in.orient, [](Span a, Span b, Span c, Span, std::span<Sign> out) {
                batch::orient2d(a, b, c, out);
            });
        });
        benchmark::RegisterBenchmark(("incircle" + suffix).c_str(), [&in](benchmark::State& s) {
            run_batch(s, in.incircle, [](Span a, Span b, Span c, Span d, std::span<Sign> out) {
                batch::incircle(a, b, c, d, out);
            });
        });
        benchmark::RegisterBenchmark(
            ("incircle_cosine" + suffix).c_str(), [&in](benchmark::State& s) {
                run_batch(s, in.incircle, [](Span a, Span b, Span c, Span d, std::span<Sign> out) {
                    batch::incircle_cosine(a, b, c, d, out);
                });
            });
        if (in.distance.empty()) continue;
        benchmark::RegisterBenchmark(
            ("compare_distance" + suffix).c_str(), [&in](benchmark::State& s) {
                run_batch(s, in.distance, [](Span c, Span p, Span q, Span, std::span<Sign> out) {
                    batch::compare_distance(c, p, q, out);
                });
            });
    }
}

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

// The peer: CGAL's filtered exact predicates on the same arrays. Points are converted in
// the timed loop as a real caller holding doubles would; Epick's Point_2 is two doubles,
// so this costs two loads. CGAL has no cosine form, so it has no incircle_cosine entry.
void register_cgal() {
    for (const Input& in : inputs()) {
        benchmark::RegisterBenchmark(
            ("orient2d/" + in.name + "/cgal-epick").c_str(), [&in](benchmark::State& s) {
                exidel::bench::cycle(s, in.orient, [](const Quad& q) {
                    return static_cast<int>(CGAL::orientation(Epick::Point_2(q.a.x, q.a.y),
                                                              Epick::Point_2(q.b.x, q.b.y),
                                                              Epick::Point_2(q.c.x, q.c.y)));
                });
            });
        benchmark::RegisterBenchmark(
            ("incircle/" + in.name + "/cgal-epick").c_str(), [&in](benchmark::State& s) {
                exidel::bench::cycle(s, in.incircle, [](const Quad& q) {
                    return static_cast<int>(CGAL::side_of_oriented_circle(
                        Epick::Point_2(q.a.x, q.a.y), Epick::Point_2(q.b.x, q.b.y),
                        Epick::Point_2(q.c.x, q.c.y), Epick::Point_2(q.d.x, q.d.y)));
                });
            });
        if (in.distance.empty()) continue;
        // compare_distance_to_point(c, p, q) is LARGER when p is farther from c: our sign.
        benchmark::RegisterBenchmark(
            ("compare_distance/" + in.name + "/cgal-epick").c_str(), [&in](benchmark::State& s) {
                exidel::bench::cycle(s, in.distance, [](const Quad& q) {
                    return static_cast<int>(CGAL::compare_distance_to_point(
                        Epick::Point_2(q.a.x, q.a.y), Epick::Point_2(q.b.x, q.b.y),
                        Epick::Point_2(q.c.x, q.c.y)));
                });
            });
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_kernel(DoubleKernel{}, true);
    register_kernel(LongDoubleKernel{}, false);
    register_kernel(AdaptiveKernel{}, true);
    register_kernel(GmpExactKernel{}, false);
    register_kernel(CppIntExactKernel{}, false);
    for (unsigned bits : {53u, 106u, 256u}) register_kernel(MpfrKernel(bits), false);
    register_batch();
    register_cgal();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
