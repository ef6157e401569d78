// exidel example: cost of the external incremental triangulation on uniform points.
//
//   exidel_delaunay_flips [n ...]      (default: 10000 100000 1000000)
//
// Prints, per n: flips (eroded edges) per point, in-circle and tangent orientation tests
// per point, and the wall time of an uninstrumented run with the adaptive kernel under
// both in-circle policies, and with the plain double kernel (determinant; its time is the
// algorithm's own cost plus the cheapest predicates). One run each: compare ratios
// within one invocation only.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"

namespace ed = exidel::delaunay;

int main(int argc, char** argv) {
    std::vector<std::size_t> sizes;
    for (int i = 1; i < argc; ++i) sizes.push_back(std::strtoull(argv[i], nullptr, 10));
    if (sizes.empty()) sizes = {10'000, 100'000, 1'000'000};
    std::printf("%10s %10s %12s %12s %12s %12s %12s %s\n", "n", "flips/pt", "incircle/pt",
                "tangent/pt", "det ms", "cos ms", "double ms", "certified");
    for (std::size_t n : sizes) {
        std::mt19937_64 rng(12345 + n);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<exidel::Point2> pts(n);
        for (auto& p : pts) p = {u(rng), u(rng)};
        const exidel::AdaptiveKernel k;
        const auto counted = ed::triangulate<ed::Instrumentation::counters>(pts, k);
        if (!counted.ok()) {
            std::printf("failure: %s\n", counted.failure->message.c_str());
            return 1;
        }
        const auto time = [&](ed::InCirclePolicy policy, const auto& kernel) {
            const auto t0 = std::chrono::steady_clock::now();
            const auto r = ed::triangulate(pts, kernel, ed::Options{policy});
            const auto t1 = std::chrono::steady_clock::now();
            if (!r.ok()) std::exit(1);
            return std::chrono::duration<double, std::milli>(t1 - t0).count();
        };
        const double det_ms = time(ed::InCirclePolicy::determinant, k);
        const double cos_ms = time(ed::InCirclePolicy::cosine, k);
        const double dbl_ms = time(ed::InCirclePolicy::determinant, exidel::DoubleKernel{});
        const bool certified = n > 2'000'000 || ed::certify(pts, counted.triangulation).ok();
        const auto& c = counted.counters;
        const double dn = static_cast<double>(n);
        std::printf("%10zu %10.3f %12.3f %12.3f %12.1f %12.1f %12.1f %s\n", n,
                    static_cast<double>(c.eroded_edges) / dn,
                    static_cast<double>(c.incircle_tests) / dn,
                    static_cast<double>(c.tangent_orientations) / dn, det_ms, cos_ms, dbl_ms,
                    certified ? "yes" : "NO");
    }
    return 0;
}
