// exidel benchmarks of the predicates of space: ns per call of orient3d and insphere per
// kernel and input, with CGAL's Epick predicates measured in the same run as the peer.
//
// As predicates_bench.cpp: each benchmark cycles through an array of 2^16 pre-generated
// queries, one call per iteration, and sums the signs into benchmark::DoNotOptimize.
//
// Inputs (seeded std::mt19937_64, compiled with -ffp-contract=off so every generated
// double is what the code says):
//   uniform         points uniform in [0, 1)^3;
//   near            orient3d: d = a + s (b - a) + t (c - a) rounded, then moved by up to
//                   3 ulps per coordinate (coplanar up to rounding); insphere: five points
//                   on a sphere (centre in [0, 1)^3, radius in [1/8, 1]) rounded, the last
//                   moved by up to 3 ulps (cospherical up to rounding);
//   lattice         exact ties: four points of an integer plane, five of an integer sphere
//                   (exidel/testing/generators3d.hpp's constructions), scaled by 2^-20;
//   lattice-near    the same with the last point moved by up to 3 ulps per coordinate.
//
// Ratios of medians, as for the plane (bench/ratios.py):
//   exidel_bench_predicates3d --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true --benchmark_format=json > p3.json
//   python3 bench/ratios.py p3.json
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "cycle.hpp"
#include "exidel/predicates/all.hpp"

namespace {

using namespace exidel;
using Rng = std::mt19937_64;
using Query = std::array<Point3, 5>;  // orient3d uses the first four

constexpr std::size_t queries_per_array = std::size_t{1} << 16;

double unit(Rng& rng) { return std::ldexp(static_cast<double>(rng() >> 11), -53); }
std::int64_t integer(Rng& rng, std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
}
Point3 uniform_point(Rng& rng) { return {unit(rng), unit(rng), unit(rng)}; }

double ulps(double v, std::int64_t k) {
    for (; k > 0; --k) v = std::nextafter(v, HUGE_VAL);
    for (; k < 0; ++k) v = std::nextafter(v, -HUGE_VAL);
    return v;
}
Point3 jiggle(Rng& rng, Point3 p) {
    return {ulps(p.x, integer(rng, -3, 3)), ulps(p.y, integer(rng, -3, 3)),
            ulps(p.z, integer(rng, -3, 3))};
}

Query uniform_query(Rng& rng) {
    Query q;
    for (Point3& p : q) p = uniform_point(rng);
    return q;
}

// d = a + s (b - a) + t (c - a), each coordinate rounded once per operation.
Query near_coplanar(Rng& rng) {
    Query q = uniform_query(rng);
    const double s = unit(rng) * 2 - 0.5, t = unit(rng) * 2 - 0.5;
    const Point3 a = q[0], b = q[1], c = q[2];
    q[3] = jiggle(rng,
                  {a.x + s * (b.x - a.x) + t * (c.x - a.x), a.y + s * (b.y - a.y) + t * (c.y - a.y),
                   a.z + s * (b.z - a.z) + t * (c.z - a.z)});
    return q;
}

Query near_cospherical(Rng& rng) {
    const Point3 c = uniform_point(rng);
    const double r = 0.125 + unit(rng) * 0.875;
    Query q;
    for (Point3& p : q) {
        const double theta = unit(rng) * 6.283185307179586, z = unit(rng) * 2 - 1;
        const double rho = std::sqrt(1 - z * z);
        p = {c.x + r * rho * std::cos(theta), c.y + r * rho * std::sin(theta), c.z + r * z};
    }
    q[4] = jiggle(rng, q[4]);
    return q;
}

Point3 scaled(std::int64_t x, std::int64_t y, std::int64_t z) {
    return {std::ldexp(double(x), -20), std::ldexp(double(y), -20), std::ldexp(double(z), -20)};
}

// Four points of o + s u + t v (integers), scaled by 2^-20: exactly coplanar.
Query lattice_plane(Rng& rng) {
    std::array<std::int64_t, 3> o{}, u{}, v{};
    for (int i = 0; i < 3; ++i) {
        o[i] = integer(rng, -(1 << 20), 1 << 20);
        u[i] = integer(rng, -64, 64);
        v[i] = integer(rng, -64, 64);
    }
    Query q;
    for (Point3& p : q) {
        const std::int64_t s = integer(rng, -1024, 1024), t = integer(rng, -1024, 1024);
        p = scaled(o[0] + s * u[0] + t * v[0], o[1] + s * u[1] + t * v[1],
                   o[2] + s * u[2] + t * v[2]);
    }
    return q;
}

// Five points of one integer sphere (Euler's four-square parametrisation, permutations and
// signs of one quadruple), scaled by 2^-20: exactly cospherical.
Query lattice_sphere(Rng& rng) {
    std::array<std::int64_t, 4> base{};
    for (std::int64_t& b : base) b = integer(rng, -256, 256);
    std::array<std::int64_t, 3> centre{};
    for (std::int64_t& c : centre) c = integer(rng, -(1 << 20), 1 << 20);
    Query q;
    for (Point3& p : q) {
        std::array<std::int64_t, 4> v = base;
        std::shuffle(v.begin(), v.end(), rng);
        for (std::int64_t& x : v) x = (rng() & 1) ? -x : x;
        const auto [m, n, s, t] = v;
        p = scaled(centre[0] + m * m + n * n - s * s - t * t, centre[1] + 2 * (m * t + n * s),
                   centre[2] + 2 * (n * t - m * s));
    }
    return q;
}

Query jiggled(Query q, Rng& rng) {
    q[3] = jiggle(rng, q[3]);
    q[4] = jiggle(rng, q[4]);
    return q;
}

struct Input {
    std::string name;
    std::vector<Query> orient, insphere;
    bool every_kernel;
};

template <class Generate>
std::vector<Query> make(Generate generate, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<Query> v;
    v.reserve(queries_per_array);
    for (std::size_t i = 0; i < queries_per_array; ++i) v.push_back(generate(rng));
    return v;
}

const std::vector<Input>& inputs() {
    static const std::vector<Input> all = [] {
        std::vector<Input> v;
        v.push_back({"uniform", make(uniform_query, 1), make(uniform_query, 2), true});
        v.push_back({"near", make(near_coplanar, 3), make(near_cospherical, 4), true});
        v.push_back({"lattice", make(lattice_plane, 5), make(lattice_sphere, 6), false});
        v.push_back({"lattice-near", make([](Rng& r) { return jiggled(lattice_plane(r), r); }, 7),
                     make([](Rng& r) { return jiggled(lattice_sphere(r), r); }, 8), false});
        return v;
    }();
    return all;
}

template <PredicateKernel3D K>
void register_kernel(const K& k, bool every_family) {
    for (const Input& in : inputs()) {
        if (!in.every_kernel && !every_family) continue;
        const std::string suffix = "/" + in.name + "/" + std::string(k.name());
        benchmark::RegisterBenchmark(("orient3d" + suffix).c_str(), [k, &in](benchmark::State& s) {
            exidel::bench::cycle(s, in.orient, [&k](const Query& q) {
                return to_int(k.orient3d(q[0], q[1], q[2], q[3]));
            });
        });
        benchmark::RegisterBenchmark(("insphere" + suffix).c_str(), [k, &in](benchmark::State& s) {
            exidel::bench::cycle(s, in.insphere, [&k](const Query& q) {
                return to_int(k.insphere(q[0], q[1], q[2], q[3], q[4]));
            });
        });
    }
}

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
Epick::Point_3 to_cgal(Point3 p) { return {p.x, p.y, p.z}; }

// The peer: CGAL's filtered exact predicates, points converted in the timed loop as a
// caller holding doubles would (three loads each). CGAL's orientation and
// side_of_oriented_sphere are the opposites of orient3d and insphere (kernel.hpp); the
// sign is negated so both sides compute the same sum.
void register_cgal() {
    for (const Input& in : inputs()) {
        benchmark::RegisterBenchmark(
            ("orient3d/" + in.name + "/cgal-epick").c_str(), [&in](benchmark::State& s) {
                exidel::bench::cycle(s, in.orient, [](const Query& q) {
                    return -static_cast<int>(CGAL::orientation(to_cgal(q[0]), to_cgal(q[1]),
                                                               to_cgal(q[2]), to_cgal(q[3])));
                });
            });
        benchmark::RegisterBenchmark(
            ("insphere/" + in.name + "/cgal-epick").c_str(), [&in](benchmark::State& s) {
                exidel::bench::cycle(s, in.insphere, [](const Query& q) {
                    return -static_cast<int>(CGAL::side_of_oriented_sphere(
                        to_cgal(q[0]), to_cgal(q[1]), to_cgal(q[2]), to_cgal(q[3]), to_cgal(q[4])));
                });
            });
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_kernel(DoubleKernel{}, true);
    register_kernel(AdaptiveKernel{}, true);
    register_kernel(GmpExactKernel{}, false);
    register_cgal();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
