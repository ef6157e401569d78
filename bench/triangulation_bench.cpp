// exidel triangulation benchmark: the external incremental algorithm (adaptive, double and
// exact GMP kernels) against CGAL's Delaunay_triangulation_2<Epick> range insertion, in
// one process, on the same points.
//
// Names: tri/<input>/<n>/<implementation>; times are CPU time (the machine is shared, and
// the run is single-threaded). Each iteration triangulates the whole input
// (constructing and destroying the result; for CGAL, `insert(begin, end)`, which sorts
// spatially inside). Counters, from one extra untimed run per benchmark:
//   flips_per_pt  exidel: Counters::eroded_edges / n (an Instrumentation::counters run)
//   bytes_per_pt  the peak of live heap bytes during the run minus those live before it,
//                 over n. Counted by replacing global operator new/delete in this program
//                 (malloc_usable_size of each block, so allocator rounding is included;
//                 GMP's own malloc calls in the exact kernel are not seen). The input
//                 vector exists before the run and is not counted.
//
// Inputs (points generated once per input and n, seeded):
//   uniform        x, y uniform in [0, 1), 53 random bits each
//   gaussian       x, y standard normal (std::normal_distribution, libstdc++)
//   grid           s x s integer grid, s = round(sqrt(n)) (n = s^2 is reported)
//   circle         (cos 2 pi i/n, sin 2 pi i/n): nearly cocircular after rounding
//   parabola-asc   (x, x^2), x = -n .. -1: exidel sorts by x, so it inserts towards the
//                  vertex, the paper's worst case: every insertion rebuilds the whole
//                  triangulation, n/2 flips per point, quadratic time. Capped at 2^13.
//   parabola-desc  (x, x^2), x = 1 .. n: inserted away from the vertex (the same curve in
//                  the opposite order, mirrored): no flips.
// The input order does not matter to exidel (it sorts) nor much to CGAL (it sorts along
// a Hilbert curve after a random shuffle).
//
// Sizes: n = 10^4, 10^5, 10^6; the exact kernel only at 10^4; grids 100^2 and 316^2, and
// 1000^2 only with --exidel_slow (about s/2 = 500 flips per point: minutes per run);
// 10^7 uniform only with --exidel_huge (several GB of memory).
//
//   exidel_bench_triangulation --benchmark_repetitions=3 --benchmark_format=json
//   python3 bench/triangulation_table.py --run build/bench/exidel_bench_triangulation
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <new>
#include <numbers>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "exidel/delaunay/triangulate.hpp"
#include "generators.hpp"

// ---------------------------------------------------------------------------------------
// Heap accounting: every operator new/delete of the program goes through here.
namespace {
std::atomic<std::size_t> live_bytes{0};
std::atomic<std::size_t> peak_bytes{0};

void* counted_alloc(std::size_t size) {
    void* p = std::malloc(size == 0 ? 1 : size);
    if (!p) throw std::bad_alloc();
    const std::size_t now =
        live_bytes.fetch_add(malloc_usable_size(p), std::memory_order_relaxed) +
        malloc_usable_size(p);
    std::size_t peak = peak_bytes.load(std::memory_order_relaxed);
    while (now > peak && !peak_bytes.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
    }
    return p;
}

void counted_free(void* p) noexcept {
    if (!p) return;
    live_bytes.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
    std::free(p);
}
}  // namespace

void* operator new(std::size_t size) { return counted_alloc(size); }
void* operator new[](std::size_t size) { return counted_alloc(size); }
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }

namespace {

using namespace exidel;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_2<Epick>;

// Extra heap bytes at the peak of f(), over those live when it started.
template <class F>
std::size_t peak_extra_bytes(F&& f) {
    const std::size_t before = live_bytes.load();
    peak_bytes.store(before);
    f();
    return peak_bytes.load() - before;
}

struct Input {
    std::vector<Point2> points;
    std::vector<Epick::Point_2> cgal;
};

std::vector<Point2> generate(const std::string& name, std::size_t n) {
    std::vector<Point2> p;
    bench::Rng rng(20250101 + n);
    if (name == "uniform") {
        for (std::size_t i = 0; i < n; ++i) p.push_back({bench::unit(rng), bench::unit(rng)});
    } else if (name == "gaussian") {
        std::normal_distribution<double> g(0.0, 1.0);
        for (std::size_t i = 0; i < n; ++i) p.push_back({g(rng), g(rng)});
    } else if (name == "grid") {
        const auto s = static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(n))));
        for (std::size_t i = 0; i < s; ++i) {
            for (std::size_t j = 0; j < s; ++j) {
                p.push_back({static_cast<double>(i), static_cast<double>(j)});
            }
        }
        std::shuffle(p.begin(), p.end(), rng);
    } else if (name == "circle") {
        for (std::size_t i = 0; i < n; ++i) {
            const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
            p.push_back({std::cos(t), std::sin(t)});
        }
    } else if (name == "parabola-asc" || name == "parabola-desc") {
        const bool asc = name == "parabola-asc";
        for (std::size_t i = 1; i <= n; ++i) {
            const double x = asc ? -static_cast<double>(i) : static_cast<double>(i);
            p.push_back({x, x * x});  // exact: |x| <= 2^24
        }
    }
    return p;
}

const Input& input(const std::string& name, std::size_t n) {
    static std::map<std::pair<std::string, std::size_t>, Input> cache;
    auto [it, fresh] = cache.try_emplace({name, n});
    if (fresh) {
        it->second.points = generate(name, n);
        for (const Point2& q : it->second.points) it->second.cgal.emplace_back(q.x, q.y);
    }
    return it->second;
}

// Untimed statistics, computed once per benchmark name (Google Benchmark calls the
// function again for every repetition).
struct Untimed {
    double flips_per_pt = -1;  // -1: not measured (CGAL)
    double bytes_per_pt = 0;
    std::string failure;
};

template <class Compute>
const Untimed& untimed(const std::string& key, Compute compute) {
    static std::map<std::string, Untimed> cache;
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, compute()).first;
    return it->second;
}

void report(benchmark::State& state, std::size_t n, const Untimed& u) {
    state.counters["n"] = static_cast<double>(n);
    state.counters["bytes_per_pt"] = u.bytes_per_pt;
    if (u.flips_per_pt >= 0) state.counters["flips_per_pt"] = u.flips_per_pt;
}

template <class K>
void exidel_bench(benchmark::State& state, const std::string& name, const std::string& in_name,
                  std::size_t n) {
    const Input& in = input(in_name, n);
    const std::span<const Point2> pts(in.points);
    const std::size_t count = pts.size();
    const Untimed& u = untimed(name, [&] {
        Untimed r;
        const delaunay::Result counted =
            delaunay::triangulate<delaunay::Instrumentation::counters>(pts, K{});
        if (!counted.ok()) {
            r.failure = counted.failure->message;
            return r;
        }
        r.flips_per_pt = static_cast<double>(counted.counters.eroded_edges) /
                         static_cast<double>(count);
        r.bytes_per_pt = static_cast<double>(peak_extra_bytes([&] {
                             benchmark::DoNotOptimize(delaunay::triangulate(pts, K{}));
                         })) /
                         static_cast<double>(count);
        return r;
    });
    if (!u.failure.empty()) {
        state.SkipWithError(("triangulation failed: " + u.failure).c_str());
        return;
    }
    for (auto _ : state) {
        delaunay::Result r = delaunay::triangulate(pts, K{});
        benchmark::DoNotOptimize(r.triangulation.triangles.data());
    }
    report(state, count, u);
}

void cgal_bench(benchmark::State& state, const std::string& name, const std::string& in_name,
                std::size_t n) {
    const Input& in = input(in_name, n);
    const std::size_t count = in.points.size();
    const Untimed& u = untimed(name, [&] {
        Untimed r;
        r.bytes_per_pt = static_cast<double>(peak_extra_bytes([&] {
                             CgalDelaunay dt;
                             dt.insert(in.cgal.begin(), in.cgal.end());
                             benchmark::DoNotOptimize(dt.number_of_faces());
                         })) /
                         static_cast<double>(count);
        return r;
    });
    for (auto _ : state) {
        CgalDelaunay dt;
        dt.insert(in.cgal.begin(), in.cgal.end());
        benchmark::DoNotOptimize(dt.number_of_faces());
    }
    report(state, count, u);
}

void add(const std::string& in_name, std::size_t n, bool exact, bool dbl = true) {
    const std::string prefix = "tri/" + in_name + "/" + std::to_string(n) + "/";
    const auto reg = [](const std::string& name, auto fn) {
        benchmark::RegisterBenchmark(name.c_str(), fn)->Unit(benchmark::kMillisecond);
    };
    reg(prefix + "exidel-adaptive", [=](benchmark::State& s) {
        exidel_bench<AdaptiveKernel>(s, prefix + "exidel-adaptive", in_name, n);
    });
    if (dbl) {
        reg(prefix + "exidel-double", [=](benchmark::State& s) {
            exidel_bench<DoubleKernel>(s, prefix + "exidel-double", in_name, n);
        });
    }
    if (exact) {
        reg(prefix + "exidel-exact", [=](benchmark::State& s) {
            exidel_bench<GmpExactKernel>(s, prefix + "exidel-exact", in_name, n);
        });
    }
    reg(prefix + "cgal-epick", [=](benchmark::State& s) { cgal_bench(s, prefix + "cgal-epick", in_name, n); });
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    bool slow = false, huge = false;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--exidel_slow") {
            slow = true;
        } else if (a == "--exidel_huge") {
            huge = true;
        } else {
            std::fprintf(stderr, "unknown option %s (besides Google Benchmark's: "
                                 "--exidel_slow, --exidel_huge)\n", argv[i]);
            return 2;
        }
    }
    for (const char* in : {"uniform", "gaussian", "circle", "parabola-desc"}) {
        for (std::size_t n : {10'000u, 100'000u, 1'000'000u}) add(in, n, n == 10'000u);
    }
    add("grid", 100 * 100, true);
    add("grid", 316 * 316, false);
    if (slow) add("grid", 1000 * 1000, false, false);
    for (std::size_t n : {1024u, 2048u, 4096u}) add("parabola-asc", n, n == 1024u);
    add("parabola-asc", 8192, false, false);
    if (huge) add("uniform", 10'000'000u, false, false);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
