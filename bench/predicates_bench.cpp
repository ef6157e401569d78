// exidel predicate benchmarks: ns per call of each predicate x kernel x input, with CGAL's
// Epick predicates measured in the same run as the peer.
//
// Each benchmark cycles through an array of 2^16 pre-generated queries, one call per
// iteration, so the reported time is the cost of one call on varied data (branch
// predictors and caches see the array, not one repeated query). The signs are summed and
// the sum passed to benchmark::DoNotOptimize, so no call can be dropped.
//
// Inputs: "uniform" (points uniform in [0,1)^2) and "near" (nearly collinear / nearly
// cocircular up to double rounding, then moved by a few ulps: the uniform-near family of
// generators.hpp). incircle_cosine runs on the incircle arrays.
//
// Repetitions and ratios (medians), see bench/ratios.py:
//   exidel_bench_predicates --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true --benchmark_format=json > predicates.json
//   python3 bench/ratios.py predicates.json
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "exidel/predicates/all.hpp"
#include "generators.hpp"

namespace {

using namespace exidel;
using exidel::bench::Quad;

constexpr std::size_t queries_per_array = std::size_t{1} << 16;

struct Input {
    std::string name;
    std::vector<Quad> orient;    // a, b, c
    std::vector<Quad> incircle;  // a, b, c, d
};

std::vector<Quad> make(Quad (*generate)(exidel::bench::Rng&), std::uint64_t seed) {
    exidel::bench::Rng rng(seed);
    std::vector<Quad> v;
    v.reserve(queries_per_array);
    for (std::size_t i = 0; i < queries_per_array; ++i) v.push_back(generate(rng));
    return v;
}

const std::vector<Input>& inputs() {
    static const std::vector<Input> all = [] {
        const auto& uniform = exidel::bench::family("uniform");
        const auto& near = exidel::bench::family("uniform-near");
        return std::vector<Input>{
            {"uniform", make(uniform.orient, 1), make(uniform.incircle, 2)},
            {"near", make(near.orient, 3), make(near.incircle, 4)},
        };
    }();
    return all;
}

// One call per iteration, cycling through the array.
template <class Call>
void run(benchmark::State& state, const std::vector<Quad>& queries, Call call) {
    const std::size_t mask = queries.size() - 1;  // size is a power of two
    std::size_t i = 0;
    int sum = 0;
    for (auto _ : state) {
        sum += call(queries[i]);
        i = (i + 1) & mask;
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <PredicateKernel K>
void register_kernel(const K& k) {
    for (const Input& in : inputs()) {
        const std::string suffix = "/" + in.name + "/" + std::string(k.name());
        benchmark::RegisterBenchmark(("orient2d" + suffix).c_str(), [k, &in](benchmark::State& s) {
            run(s, in.orient, [&k](const Quad& q) { return to_int(k.orient2d(q.a, q.b, q.c)); });
        });
        benchmark::RegisterBenchmark(("incircle" + suffix).c_str(), [k, &in](benchmark::State& s) {
            run(s, in.incircle,
                [&k](const Quad& q) { return to_int(k.incircle(q.a, q.b, q.c, q.d)); });
        });
        benchmark::RegisterBenchmark(
            ("incircle_cosine" + suffix).c_str(), [k, &in](benchmark::State& s) {
                run(s, in.incircle,
                    [&k](const Quad& q) { return to_int(k.incircle_cosine(q.a, q.b, q.c, q.d)); });
            });
    }
}

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

// The peer: CGAL's filtered exact predicates on the same arrays. Points are converted in
// the timed loop as a real caller holding doubles would; Epick's Point_2 is two doubles,
// so this costs two loads. CGAL has no cosine form, so it has no incircle_cosine entry.
void register_cgal() {
    for (const Input& in : inputs()) {
        benchmark::RegisterBenchmark(("orient2d/" + in.name + "/cgal-epick").c_str(),
                                     [&in](benchmark::State& s) {
            run(s, in.orient, [](const Quad& q) {
                return static_cast<int>(CGAL::orientation(Epick::Point_2(q.a.x, q.a.y),
                                                          Epick::Point_2(q.b.x, q.b.y),
                                                          Epick::Point_2(q.c.x, q.c.y)));
            });
        });
        benchmark::RegisterBenchmark(("incircle/" + in.name + "/cgal-epick").c_str(),
                                     [&in](benchmark::State& s) {
            run(s, in.incircle, [](const Quad& q) {
                return static_cast<int>(CGAL::side_of_oriented_circle(
                    Epick::Point_2(q.a.x, q.a.y), Epick::Point_2(q.b.x, q.b.y),
                    Epick::Point_2(q.c.x, q.c.y), Epick::Point_2(q.d.x, q.d.y)));
            });
        });
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_kernel(DoubleKernel{});
    register_kernel(LongDoubleKernel{});
    register_kernel(AdaptiveKernel{});
    register_kernel(GmpExactKernel{});
    register_kernel(CppIntExactKernel{});
    for (unsigned bits : {53u, 106u, 256u}) register_kernel(MpfrKernel(bits));
    register_cgal();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
