// exidel: the paper's sorted (external) incremental convex hull, Appendix A (Alg. 4, 5),
// implemented as written so that its ToLeft count can be compared with Theorem 6.
//
// ToLeft(p, a, b) > 0 means p strictly left of a->b, i.e. orient2d(a, b, p) > 0. Alg. 5
// treats ToLeft <= 0 as "not yet the tangent", so of collinear points the farther one is
// kept: the result has no collinear hull vertices (unlike the triangulation's boundary).
// The hull is a linked cycle instead of the paper's sliced list; the ToLeft calls are
// the same, one counter increment per call, including the call that the `else` branch
// of Alg. 5 repeats as the first test of its while loop.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/registry.hpp"

namespace exidel::delaunay {

struct SortedHull {
    std::vector<std::uint32_t> hull;  ///< CCW cycle of input indices from the smallest point
    bool collinear = false;           ///< no triangle could be made (then hull is empty)
    std::size_t n = 0;                ///< distinct points
    std::size_t k1 = 0;               ///< points used by the first triangle (Theorem 3)
    std::size_t h = 0;                ///< insertions where P[i]A[i_xmax] was not the lower tangent
    std::uint64_t to_left = 0;        ///< every ToLeft() call, seed included
    std::optional<Failure> failure;
};

template <PredicateKernel K>
SortedHull sorted_convex_hull(std::span<const Point2> points, const K& k) {
    SortedHull r;
    detail::SortedInput in;
    if (auto f = detail::sort_and_dedupe(points, in)) {
        r.failure = std::move(f);
        return r;
    }
    const auto& P = in.points;
    const std::size_t n = P.size();
    r.n = n;
    const auto to_left = [&](std::uint32_t p, std::uint32_t a, std::uint32_t b) {
        ++r.to_left;
        return k.orient2d(P[a], P[b], P[p]);
    };
    // Alg. 4's "try to create a triangle": P[i] against P[0] P[i-1] (Theorem 3).
    std::size_t i = 2;
    Sign side = Sign::zero;
    for (; i < n; ++i) {
        side = to_left(static_cast<std::uint32_t>(i), 0, static_cast<std::uint32_t>(i - 1));
        if (side != Sign::zero) break;
    }
    if (i >= n) {
        r.collinear = true;
        return r;
    }
    r.k1 = i + 1;
    std::vector<std::uint32_t> next(n), prev(n);
    const auto set_next = [&](std::uint32_t a, std::uint32_t b) {
        next[a] = b;
        prev[b] = a;
    };
    // The first hull is the triangle of the extreme points P[0], P[i-1], P[i].
    const auto a = static_cast<std::uint32_t>(i - 1), c = static_cast<std::uint32_t>(i);
    if (side == Sign::positive) {
        set_next(0, a), set_next(a, c), set_next(c, 0);
    } else {
        set_next(0, c), set_next(c, a), set_next(a, 0);
    }
    std::size_t size = 3;
    std::uint32_t a1 = c;  // i_xmax
    for (++i; i < n; ++i) {
        const auto p = static_cast<std::uint32_t>(i);
        std::uint32_t a2;
        std::size_t steps = 0;  // guard: no walk may pass the whole hull
        const auto guard = [&](const char* what) {
            if (++steps <= size) return false;
            r.failure = Failure{
                FailureKind::hull_walk_exceeded, in.input_of[p], p,
                std::string("sorted hull: ") + what + " walk at sorted point " + std::to_string(p)};
            return true;
        };
        if (to_left(p, prev[a1], a1) == Sign::positive) {
            a2 = next[a1];
        } else {
            ++r.h;
            a2 = a1;
            while (to_left(p, prev[a1], a1) != Sign::positive) {
                a1 = prev[a1];
                if (guard("lower")) return r;
            }
        }
        while (to_left(p, a2, next[a2]) != Sign::positive) {
            a2 = next[a2];
            if (guard("upper")) return r;
        }
        // Vertices strictly between a1 and a2 leave the hull.
        std::size_t removed = 0;
        for (std::uint32_t v = next[a1]; v != a2; v = next[v]) {
            if (++removed > size) {
                r.failure = Failure{FailureKind::hull_walk_exceeded, in.input_of[p], p,
                                    "sorted hull: tangents out of order"};
                return r;
            }
        }
        set_next(a1, p);
        set_next(p, a2);
        size = size - removed + 1;
        a1 = p;
    }
    std::uint32_t v = 0;
    for (std::size_t s = 0; s < size; ++s, v = next[v]) r.hull.push_back(in.input_of[v]);
    return r;
}

/// Theorem 6 as the paper states it: 3n - 2 k1 - l + h + 1 ToLeft() calls.
inline std::int64_t theorem6_paper(const SortedHull& r) {
    return 3 * static_cast<std::int64_t>(r.n) - 2 * static_cast<std::int64_t>(r.k1) -
           static_cast<std::int64_t>(r.hull.size()) + static_cast<std::int64_t>(r.h) + 1;
}

/// The count Alg. 5 as written performs: each of the h insertions whose first test fails
/// repeats that test as the first condition of its while loop, so Theorem 4's "m_i - 3
/// points deleted" is really m_i - 4 and the total gains h: 3n - 2 k1 - l + 2h + 1.
inline std::int64_t theorem6_corrected(const SortedHull& r) {
    return theorem6_paper(r) + static_cast<std::int64_t>(r.h);
}

#define EXIDEL_HULL_EXTERN(K, spelling, summary) \
    extern template SortedHull sorted_convex_hull<K>(std::span<const Point2>, const K&);
EXIDEL_KERNELS(EXIDEL_HULL_EXTERN)
#undef EXIDEL_HULL_EXTERN

}  // namespace exidel::delaunay
