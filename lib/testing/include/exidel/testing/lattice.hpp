// exidel::testing: integer points exactly on circles with many lattice points.
//
// The circle x^2 + y^2 = r^2 with r = 5 * 13 * 17 * 29 * 37 * 41 (the first primes
// p = 1 mod 4) has 4 * 3^6 = 2916 integer points, and every four of them are exactly
// cocircular. Rather than search for them, they are built as Gaussian integers: each
// prime splits as p = pi * conj(pi) with pi = a + bi, so p^2 = pi^2 * conj(pi)^2 and
// r^2 = |z|^2 exactly when z is a product, over the primes, of one of
//   p (choice 0), pi^2 (choice 1) or conj(pi)^2 (choice 2),
// times a unit i^u. Choice 0 everywhere gives the axis points (r, 0), (0, r), ...,
// which is where the generators shrink to. All arithmetic is in 64-bit integers
// (|x|, |y| <= r < 2^26 at every step), so there is no rounding at all.
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace exidel::testing {

/// Number of primes available for lattice circles.
inline constexpr int lattice_prime_count = 6;

namespace detail {
struct GaussianPrime {
    std::int64_t p, a, b;  // p = a^2 + b^2
};
inline constexpr std::array<GaussianPrime, lattice_prime_count> gaussian_primes{
    {{5, 1, 2}, {13, 2, 3}, {17, 1, 4}, {29, 2, 5}, {37, 1, 6}, {41, 4, 5}}};
}  // namespace detail

/// An integer point (x, y).
using LatticePoint = std::pair<std::int64_t, std::int64_t>;

/// r for the lattice circle built from the first `primes` primes (1 <= primes <= 6):
/// 5, 65, 1105, 32045, 1185665, 48612265.
inline std::int64_t lattice_circle_radius(int primes) {
    if (primes < 1 || primes > lattice_prime_count) {
        throw std::invalid_argument("lattice_circle_radius: primes must be in [1, 6]");
    }
    std::int64_t r = 1;
    for (int i = 0; i < primes; ++i) r *= detail::gaussian_primes[i].p;
    return r;
}

/// The lattice point with the given per-prime choices (each 0, 1 or 2; see the file
/// comment) and unit i^unit, on the circle of radius lattice_circle_radius(choices.size()).
inline LatticePoint lattice_circle_point(std::span<const int> choices, int unit) {
    if (choices.empty() || choices.size() > lattice_prime_count) {
        throw std::invalid_argument("lattice_circle_point: between 1 and 6 choices");
    }
    std::int64_t x = 1, y = 0;
    const auto times = [&](std::int64_t re, std::int64_t im) {
        const std::int64_t nx = x * re - y * im;
        y = x * im + y * re;
        x = nx;
    };
    for (std::size_t i = 0; i < choices.size(); ++i) {
        const auto& g = detail::gaussian_primes[i];
        // pi^2 = (a^2 - b^2) + 2ab i; its conjugate flips the imaginary part.
        switch (choices[i]) {
            case 0: times(g.p, 0); break;
            case 1: times(g.a * g.a - g.b * g.b, 2 * g.a * g.b); break;
            case 2: times(g.a * g.a - g.b * g.b, -2 * g.a * g.b); break;
            default: throw std::invalid_argument("lattice_circle_point: choice not in {0,1,2}");
        }
    }
    for (int u = ((unit % 4) + 4) % 4; u > 0; --u) times(0, 1);
    return {x, y};
}

/// Every integer point of the circle of radius lattice_circle_radius(primes), sorted:
/// 4 * 3^primes points.
inline std::vector<LatticePoint> lattice_circle_points(int primes) {
    (void)lattice_circle_radius(primes);  // validates `primes`
    std::set<LatticePoint> all;
    std::vector<int> choices(static_cast<std::size_t>(primes), 0);
    while (true) {
        for (int unit = 0; unit < 4; ++unit) all.insert(lattice_circle_point(choices, unit));
        std::size_t i = 0;  // odometer over {0,1,2}^primes
        while (i < choices.size() && ++choices[i] == 3) choices[i++] = 0;
        if (i == choices.size()) break;
    }
    return {all.begin(), all.end()};
}

}  // namespace exidel::testing
