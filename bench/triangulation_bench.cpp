// exidel triangulation benchmark: the external incremental algorithm with each
// triangulation strategy, against CGAL's Delaunay_triangulation_2<Epick> range insertion,
// in one process, on the same points.
//
// Names: tri/<input>/<n>/<implementation>[/real_time], n the nominal size (grids have
// s^2 points, s = round(sqrt(n)); the counter `n` is the actual count). Implementations,
// for every algorithm of the registry (delaunay/algorithms.hpp):
//   adaptive-<strategy>-t<threads>  the external algorithm (exidel::delaunay::triangulate
//                                   with AdaptiveKernel and Options{.strategy, .threads});
//                                   strategies lexicographic (the paper), radial, strips
//                                   (t1, t2), automatic (the default; t1, t2)
//   adaptive-<algorithm>-t1         any other algorithm, by its registry name
//   double-automatic-t1, exact-automatic-t1   the default strategy with DoubleKernel and
//                                   GmpExactKernel (uniform only: the price of robustness)
//   cgal-epick                      `CgalDelaunay dt; dt.insert(begin, end)` (spatial sort
//                                   inside)
// Times are wall-clock (UseRealTime) for every implementation, CGAL included: the strips
// strategy runs worker threads, and CPU time of the benchmark thread would miss them. The
// machine may be shared: compare ratios measured in one run only. Each iteration
// triangulates the whole input (constructing and destroying the result). Counters, from
// untimed runs once per benchmark (not per repetition):
//   flips_per_pt  exidel: Counters::flips() / n (eroded edges plus edges deleted by strip
//                 merges), from an Instrumentation::counters run with the same options
//   strips        exidel: Result::strips, the pieces merged (1 unless strips ran); the
//                 label names the strategy that ran (what `automatic` resolved to)
//   bytes_per_pt  the peak of live heap bytes during one run minus those live before it,
//                 over n. Counted by replacing global operator new/delete in this program
//                 with atomic counters (so worker threads are counted too), using
//                 malloc_usable_size of each block, so allocator rounding is included,
//                 plus the mappings exidel makes itself for its large internal arrays
//                 (whole 2 MiB pages; detail::set_mapped_fresh_hook). Not seen: GMP's own malloc
//                 calls (exact kernel) and thread stacks. The input vector exists before the run
//                 and is not counted.
// Every benchmark run starts from the same allocator state: malloc_trim(0) before the
// timed loop returns every free page of the heap to the kernel. Without it a run inherits
// whatever the runs before it left mapped, and the order of the runs moved the times by
// up to 25% (CGAL after an exidel run: 800 to 990 ms, alone 880 ms; issue 17,
// docs/measurements.md "Fresh memory"). With it, every implementation's first touch of
// its memory is a page fault, as in a process that triangulates once.
// The benchmark certifies nothing (tests/ does); it only checks Result::ok() and reports
// a failure with SkipWithError.
//
// Inputs (generated once per input and n, seeded; shuffled where the generator is ordered
// so that no implementation profits from the order it is given):
//   uniform        x, y uniform in [0, 1), 53 random bits each
//   gaussian       x, y standard normal (std::normal_distribution, libstdc++)
//   clustered      100 Gaussian clusters, centres uniform in [0, 1)^2, sigma 10^-3
//   grid           s x s integer grid: every cell is four cocircular points
//   rotated-grid   the s x s integer grid rotated by 30 degrees in doubles: nearly
//                  cocircular and nearly collinear everywhere (the adaptive kernel's
//                  exact stages)
//   circle         (cos 2 pi i/n, sin 2 pi i/n): nearly cocircular after rounding
//   parabola-asc   (x, x^2), x = -n .. -1: the lexicographic order inserts towards the
//                  vertex, the paper's worst case (each insertion erodes the whole visible
//                  chain, n/2 flips per point, quadratic time)
//   parabola-desc  (x, x^2), x = 1 .. n: the same curve, inserted away from the vertex
//
// Sizes (default run): n = 10^4, 10^5 and 10^6 for every input and every strategy, except
// where a strategy is quadratic:
//   - lexicographic on parabola-asc: n/2 flips per point, run at n = 8192 only (1.3 s;
//     10^5 would take minutes, 10^6 hours), never at 10^5 or 10^6;
//   - lexicographic on the 1000 x 1000 grid: about s/2 = 500 flips per point, minutes
//     per run, only with --exidel_slow;
//   - lawson (the sorted fan, then flips) wherever lexicographic is left out: it flips
//     what that order erodes;
//   (radial on the parabolas at 10^6 used to be here too: the walk to a visible hull
//   edge went round the curve, thousands of orientations per point. The hash now spans
//   the points' own angular range and the walk goes both ways: 1.7 per point.)
// The kernel comparison (double, exact) runs on uniform only, exact at 10^4 only.
// --exidel_huge adds 10^7 uniform (every strategy; several GB of memory).
// --exidel_giant adds 10^8 uniform and every realistic family, the default (t1, t2) and
// CGAL only: about 9 GB for exidel, 15 GB for CGAL, 3.2 GB for the input in both forms
// (issue 17's scale check; choose inputs with --benchmark_filter, e.g. '/100000000/').
// Measured on the 2-core development machine under a load of 3-4 (another build
// running): 16 minutes for uniform with --benchmark_repetitions=3; lonlat with the
// default single repetition took 13 minutes on 2026-12-06 (CGAL alone 2 minutes per run).
// Every input in one process takes well over an hour: choose inputs with the filter.
//
//   exidel_bench_triangulation --benchmark_filter='/100000/'         # 10^5 only
//   exidel_bench_triangulation --benchmark_filter='uniform/1000000/(adaptive-auto|cgal)'
//   python3 bench/triangulation_table.py --run build/bench/exidel_bench_triangulation
//       --repetitions 3 [--filter REGEX] [-- --exidel_slow --exidel_huge]   (one line)
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <new>
#include <numbers>
#include <span>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exidel/delaunay/algorithms.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/testing/point_sets.hpp"
#include "generators.hpp"

// ---------------------------------------------------------------------------------------
// Heap accounting: every operator new/delete of the program goes through here.
namespace {
std::atomic<std::size_t> live_bytes{0};
std::atomic<std::size_t> mapped_bytes{0};  // exidel's own mappings (detail/memory.hpp)
std::atomic<std::size_t> peak_bytes{0};

void raise_peak(std::size_t now) {
    std::size_t peak = peak_bytes.load(std::memory_order_relaxed);
    while (now > peak && !peak_bytes.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {}
}

void* counted_alloc(std::size_t size) {
    void* p = std::malloc(size == 0 ? 1 : size);
    if (!p) throw std::bad_alloc();
    const std::size_t now = live_bytes.fetch_add(malloc_usable_size(p), std::memory_order_relaxed) +
                            malloc_usable_size(p);
    raise_peak(now + mapped_bytes.load(std::memory_order_relaxed));
    return p;
}

// exidel maps its large internal arrays itself, past operator new: counted here.
void count_mapped(std::size_t total) {
    mapped_bytes.store(total, std::memory_order_relaxed);
    raise_peak(total + live_bytes.load(std::memory_order_relaxed));
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
using delaunay::Strategy;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_2<Epick>;

// Extra heap bytes at the peak of f(), over those live when it started.
template <class F>
std::size_t peak_extra_bytes(F&& f) {
    const std::size_t before = live_bytes.load() + mapped_bytes.load();
    peak_bytes.store(before);
    f();
    return peak_bytes.load() - before;
}

struct Input {
    std::vector<Point2> points;
    std::vector<Epick::Point_2> cgal;
};

// s x s grid points (i, j) mapped by `at`, shuffled.
template <class At>
std::vector<Point2> grid(std::size_t n, bench::Rng& rng, At at) {
    const auto s = static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(n))));
    std::vector<Point2> p;
    p.reserve(s * s);
    for (std::size_t i = 0; i < s; ++i) {
        for (std::size_t j = 0; j < s; ++j)
            p.push_back(at(static_cast<double>(i), static_cast<double>(j)));
    }
    std::shuffle(p.begin(), p.end(), rng);
    return p;
}

std::vector<Point2> generate(const std::string& name, std::size_t n) {
    std::vector<Point2> p;
    p.reserve(n);
    bench::Rng rng(20250101 + n);
    if (name == "uniform") {
        for (std::size_t i = 0; i < n; ++i) p.push_back({bench::unit(rng), bench::unit(rng)});
    } else if (name == "gaussian") {
        std::normal_distribution<double> g(0.0, 1.0);
        for (std::size_t i = 0; i < n; ++i) p.push_back({g(rng), g(rng)});
    } else if (name == "clustered") {
        constexpr int clusters = 100;
        std::vector<Point2> centre(clusters);
        for (Point2& c : centre) c = {bench::unit(rng), bench::unit(rng)};
        std::normal_distribution<double> g(0.0, 1e-3);
        for (std::size_t i = 0; i < n; ++i) {
            const Point2& c =
                centre[static_cast<std::size_t>(bench::integer(rng, 0, clusters - 1))];
            p.push_back({c.x + g(rng), c.y + g(rng)});
        }
    } else if (name == "grid") {
        p = grid(n, rng, [](double i, double j) { return Point2{i, j}; });
    } else if (name == "rotated-grid") {
        const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
        p = grid(n, rng, [=](double i, double j) { return Point2{i * c - j * s, i * s + j * c}; });
    } else if (name == "circle") {
        for (std::size_t i = 0; i < n; ++i) {
            const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
            p.push_back({std::cos(t), std::sin(t)});
        }
        std::shuffle(p.begin(), p.end(), rng);
    } else if (name == "parabola-asc" || name == "parabola-desc") {
        const bool asc = name == "parabola-asc";
        for (std::size_t i = 1; i <= n; ++i) {
            const double x = asc ? -static_cast<double>(i) : static_cast<double>(i);
            p.push_back({x, x * x});  // exact: |x| <= 2^26
        }
        std::shuffle(p.begin(), p.end(), rng);
    } else {
        // The realistic families (exidel/testing/point_sets.hpp), in their own file order:
        // throws for a registration typo in this file.
        p = testing::realistic_points(testing::realistic_from_name(name), n, 20250101 + n);
    }
    return p;
}

// Benchmarks run in registration order, grouped by input: keeping only the latest input
// bounds the memory of the process to one input (10^7 points with --exidel_huge).
const Input& input(const std::string& name, std::size_t n) {
    static std::pair<std::string, std::size_t> key;
    static Input cached;
    if (key != std::pair{name, n}) {
        cached = {};
        cached.points = generate(name, n);
        cached.cgal.reserve(cached.points.size());
        for (const Point2& q : cached.points) cached.cgal.emplace_back(q.x, q.y);
        key = {name, n};
    }
    return cached;
}

// Untimed statistics, computed once per benchmark name (Google Benchmark calls the
// function again for every repetition).
struct Untimed {
    double flips_per_pt = -1;  // -1: not measured (CGAL)
    double bytes_per_pt = 0;
    double strips = 0;
    double cavity_pieces = 0;
    std::string ran;  // the strategy that ran
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
    if (u.flips_per_pt >= 0) {
        state.counters["flips_per_pt"] = u.flips_per_pt;
        state.counters["strips"] = u.strips;
        state.counters["cavity_pieces"] = u.cavity_pieces;
        state.SetLabel(u.ran);
    }
}

template <class K>
void exidel_bench(benchmark::State& state, const std::string& name, const std::string& in_name,
                  std::size_t n, delaunay::Options options) {
    const Input& in = input(in_name, n);
    const std::span<const Point2> pts(in.points);
    const std::size_t count = pts.size();
    const Untimed& u = untimed(name, [&] {
        Untimed r;
        const delaunay::Result counted =
            delaunay::triangulate<delaunay::Instrumentation::counters>(pts, K{}, options);
        if (!counted.ok()) {
            r.failure = counted.failure->message;
            return r;
        }
        r.flips_per_pt = static_cast<double>(counted.counters.flips()) / static_cast<double>(count);
        r.strips = static_cast<double>(counted.strips);
        r.cavity_pieces = static_cast<double>(counted.cavity_pieces);
        // The label names the strategy that ran, for an algorithm that takes one.
        const bool takes_order =
            std::any_of(delaunay::algorithms().begin(), delaunay::algorithms().end(),
                        [&](const delaunay::AlgorithmInfo& a) {
                            return a.id == options.algorithm && a.takes_order;
                        });
        if (takes_order) r.ran = std::string(delaunay::to_string(counted.strategy));
        r.bytes_per_pt = static_cast<double>(peak_extra_bytes([&] {
                             benchmark::DoNotOptimize(delaunay::triangulate(pts, K{}, options));
                         })) /
                         static_cast<double>(count);
        return r;
    });
    if (!u.failure.empty()) {
        state.SkipWithError(("triangulation failed: " + u.failure).c_str());
        return;
    }
    malloc_trim(0);
    for (auto _ : state) {
        delaunay::Result r = delaunay::triangulate(pts, K{}, options);
        if (!r.ok()) {
            state.SkipWithError(("triangulation failed: " + r.failure->message).c_str());
            break;
        }
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
    malloc_trim(0);
    for (auto _ : state) {
        CgalDelaunay dt;
        dt.insert(in.cgal.begin(), in.cgal.end());
        benchmark::DoNotOptimize(dt.number_of_faces());
    }
    report(state, count, u);
}

benchmark::internal::Benchmark* reg(const std::string& name, std::size_t n,
                                    std::function<void(benchmark::State&)> fn) {
    auto* b = benchmark::RegisterBenchmark(name.c_str(), std::move(fn));
    b->Unit(benchmark::kMillisecond)->UseRealTime();
    // From 10^6 points one run lasts long enough to be timed alone; Google Benchmark's
    // default would run several to fill half a second. Repetitions give the spread.
    if (n >= 1'000'000) b->Iterations(1);
    return b;
}

// --exidel_strip_tiles=N: Options::strip_tiles of every exidel run (0, the default:
// chosen by input size), to compare tile counts.
std::size_t strip_tiles = 0;

// The external algorithm is named by its order (adaptive-radial-t1, the names its
// tables have always used); every other algorithm by its registry name.
template <class K>
void add_exidel(const std::string& prefix, const std::string& kernel, const std::string& in_name,
                std::size_t n, Strategy strategy, unsigned threads,
                delaunay::Algorithm algorithm = delaunay::Algorithm::external) {
    const std::string what = algorithm == delaunay::Algorithm::external
                                 ? std::string(delaunay::to_string(strategy))
                                 : std::string(delaunay::to_string(algorithm));
    const std::string name = prefix + kernel + "-" + what + "-t" + std::to_string(threads);
    const delaunay::Options options{.strategy = strategy,
                                    .threads = threads,
                                    .algorithm = algorithm,
                                    .strip_tiles = strip_tiles};
    reg(name, n, [=](benchmark::State& s) { exidel_bench<K>(s, name, in_name, n, options); });
}

// Every algorithm of the registry with the adaptive kernel, and CGAL, on one input: an
// algorithm that takes an order in each order (lexicographic and radial only when asked:
// each is quadratic on some inputs), the others once.
void add(const std::string& in_name, std::size_t n, bool lexicographic, bool radial) {
    const std::string prefix = "tri/" + in_name + "/" + std::to_string(n) + "/";
    for (const delaunay::AlgorithmInfo& a : delaunay::algorithms()) {
        // Lawson's flips from the sorted fan are the lexicographic order's erosions, one
        // for one on grids (tests/delaunay/flips_test.cpp): it is quadratic where that
        // order is, and runs where it runs.
        if (a.id == delaunay::Algorithm::lawson && !lexicographic) continue;
        if (!a.takes_order) {
            add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 1,
                                       a.id);
            continue;
        }
        if (lexicographic)
            add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::lexicographic, 1,
                                       a.id);
        if (radial)
            add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::radial, 1, a.id);
        add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::strips, 1, a.id);
        add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::strips, 2, a.id);
        add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 1, a.id);
        add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 2, a.id);
    }
    reg(prefix + "cgal-epick", n,
        [=](benchmark::State& s) { cgal_bench(s, prefix + "cgal-epick", in_name, n); });
}

// The default (t1, t2), the orders it chooses between, the sweep-hull and Bowyer-Watson
// (t1: a sweep with Lawson's flips, and BRIO insertion with point location), and CGAL:
// where the default's choice and its fixed costs are measured on the realistic families.
void add_default(const std::string& in_name, std::size_t n) {
    const std::string prefix = "tri/" + in_name + "/" + std::to_string(n) + "/";
    add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 1);
    add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 2);
    add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::radial, 1);
    add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::strips, 1);
    add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 1,
                               delaunay::Algorithm::sweep_hull);
    add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 1,
                               delaunay::Algorithm::bowyer_watson);
    reg(prefix + "cgal-epick", n,
        [=](benchmark::State& s) { cgal_bench(s, prefix + "cgal-epick", in_name, n); });
}

}  // namespace

int main(int argc, char** argv) {
    delaunay::detail::set_mapped_fresh_hook(count_mapped);
    benchmark::Initialize(&argc, argv);
    bool slow = false, huge = false, giant = false;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--exidel_slow") {
            slow = true;
        } else if (a == "--exidel_huge") {
            huge = true;
        } else if (a == "--exidel_giant") {
            giant = true;
        } else if (a.starts_with("--exidel_write=")) {
            // --exidel_write=FAMILY:N:FILE writes the benchmark's input (FAMILY at N points,
            // the same seed) as "x y" lines, 17 significant digits (read back exactly), and
            // exits: the input of bench/end_to_end.py.
            const std::string spec(a.substr(15));
            const std::size_t c1 = spec.find(':'), c2 = spec.find(':', c1 + 1);
            if (c1 == std::string::npos || c2 == std::string::npos) {
                std::fprintf(stderr, "--exidel_write=FAMILY:N:FILE\n");
                return 2;
            }
            const std::vector<Point2> p =
                generate(spec.substr(0, c1),
                         std::strtoull(spec.substr(c1 + 1, c2 - c1 - 1).c_str(), nullptr, 10));
            std::FILE* out = std::fopen(spec.substr(c2 + 1).c_str(), "w");
            if (!out) {
                std::perror(spec.substr(c2 + 1).c_str());
                return 1;
            }
            for (const Point2& q : p) std::fprintf(out, "%.17g %.17g\n", q.x, q.y);
            return std::fclose(out) == 0 ? 0 : 1;
        } else if (a.starts_with("--exidel_strip_tiles=")) {
            strip_tiles = std::strtoull(a.substr(21).data(), nullptr, 10);
        } else {
            std::fprintf(stderr,
                         "unknown option %s (besides Google Benchmark's: "
                         "--exidel_slow, --exidel_huge, --exidel_giant, "
                         "--exidel_strip_tiles=N, --exidel_write=FAMILY:N:FILE)\n",
                         argv[i]);
            return 2;
        }
    }
    // The price of robustness: the default strategy with the exact GMP kernel and with
    // the plain double kernel (not robust), on uniform input.
    {
        const std::string prefix = "tri/uniform/10000/";
        add_exidel<GmpExactKernel>(prefix, "exact", "uniform", 10'000, Strategy::automatic, 1);
    }
    for (const char* in : {"uniform", "gaussian", "clustered", "grid", "rotated-grid", "circle",
                           "parabola-desc", "parabola-asc"}) {
        const std::string_view name = in;
        for (std::size_t n : {10'000u, 100'000u, 1'000'000u}) {
            const bool big = n == 1'000'000;
            const bool lexicographic = name != "parabola-asc" && (name != "grid" || !big || slow);
            add(in, n, lexicographic, true);
            if (name == "uniform") {
                const std::string prefix = "tri/uniform/" + std::to_string(n) + "/";
                add_exidel<DoubleKernel>(prefix, "double", in, n, Strategy::automatic, 1);
            }
        }
    }
    // The lexicographic order's worst case, small enough to run (n^2/8 flips).
    add("parabola-asc", 8192, true, true);
    if (huge) add("uniform", 10'000'000, true, true);
    // The realistic families, every size from 10^3 (10^7 with --exidel_huge).
    for (const testing::RealisticInfo& f : testing::realistic_families()) {
        for (std::size_t n : {1'000u, 10'000u, 100'000u, 1'000'000u})
            add_default(std::string(f.name), n);
        if (huge) add_default(std::string(f.name), 10'000'000);
    }
    if (giant) {
        // 10^8: the default (t1, t2) and CGAL only, uniform and every realistic family.
        const std::size_t n = 100'000'000;
        std::vector<std::string> inputs{"uniform"};
        for (const testing::RealisticInfo& f : testing::realistic_families()) {
            inputs.emplace_back(f.name);
        }
        for (const std::string& in_name : inputs) {
            const std::string prefix = "tri/" + in_name + "/" + std::to_string(n) + "/";
            add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 1);
            add_exidel<AdaptiveKernel>(prefix, "adaptive", in_name, n, Strategy::automatic, 2);
            reg(prefix + "cgal-epick", n,
                [=](benchmark::State& s) { cgal_bench(s, prefix + "cgal-epick", in_name, n); });
        }
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
