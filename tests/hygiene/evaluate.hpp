// exidel hygiene tests: one kernel over one query family, and the comparison of two runs.
#pragma once

#include <cstdint>
#include <cstdio>
#include <vector>

#include <exidel/predicates/all.hpp>

#include "queries.hpp"

namespace exidel::hygiene {

struct Signs {
    std::vector<Sign> orient2d;
    std::vector<Sign> incircle;
    std::vector<Sign> incircle_cosine;
    std::vector<Sign> orient3d;  // empty for the batched predicates, which are planar only
    std::vector<Sign> insphere;
};

template <class Kernel>
Signs evaluate(const Kernel& kernel, const QueryFamily& family) {
    Signs s;
    s.orient2d.reserve(family.orient2d.size());
    for (const Orient2dQuery& q : family.orient2d)
        s.orient2d.push_back(kernel.orient2d(q.a, q.b, q.c));
    s.incircle.reserve(family.incircle.size());
    s.incircle_cosine.reserve(family.incircle.size());
    for (const IncircleQuery& q : family.incircle) {
        s.incircle.push_back(kernel.incircle(q.a, q.b, q.c, q.d));
        s.incircle_cosine.push_back(kernel.incircle_cosine(q.a, q.b, q.c, q.d));
    }
    for (const Orient3dQuery& q : family.orient3d)
        s.orient3d.push_back(kernel.orient3d(q.a, q.b, q.c, q.d));
    for (const InsphereQuery& q : family.insphere) {
        s.insphere.push_back(kernel.insphere(q.a, q.b, q.c, q.d, q.e));
    }
    return s;
}

/// The batched predicates (batch.hpp) over the same queries.
inline Signs evaluate_batch(const QueryFamily& family) {
    std::vector<Point2> a, b, c, d;
    for (const Orient2dQuery& q : family.orient2d)
        a.push_back(q.a), b.push_back(q.b), c.push_back(q.c);
    Signs s;
    s.orient2d.resize(a.size());
    batch::orient2d(a, b, c, s.orient2d);
    a.clear(), b.clear(), c.clear();
    for (const IncircleQuery& q : family.incircle) {
        a.push_back(q.a), b.push_back(q.b), c.push_back(q.c), d.push_back(q.d);
    }
    s.incircle.resize(a.size());
    s.incircle_cosine.resize(a.size());
    batch::incircle(a, b, c, d, s.incircle);
    batch::incircle_cosine(a, b, c, d, s.incircle_cosine);
    return s;
}

inline void print_point(Point2 p) { std::printf("(%a, %a)", p.x, p.y); }
inline void print_point(Point3 p) { std::printf("(%a, %a, %a)", p.x, p.y, p.z); }

/// Counts the queries where `got` differs from `want`, printing the first few with their
/// exact coordinates (hex floats) so that a failure can become a named regression test.
inline std::size_t count_mismatches(const char* label, const QueryFamily& family, const Signs& got,
                                    const Signs& want) {
    std::size_t bad = 0;
    auto report = [&](const char* predicate, std::size_t i, Sign g, Sign w, auto print_query) {
        if (g == w) return;
        if (++bad <= 5) {
            std::printf("  MISMATCH %s %s %s #%zu: got %d, exact %d at ", label,
                        family.name.c_str(), predicate, i, to_int(g), to_int(w));
            print_query();
            std::printf("\n");
        }
    };
    for (std::size_t i = 0; i < family.orient2d.size(); ++i) {
        const Orient2dQuery& q = family.orient2d[i];
        report("orient2d", i, got.orient2d[i], want.orient2d[i],
               [&] { print_point(q.a), print_point(q.b), print_point(q.c); });
    }
    for (std::size_t i = 0; i < family.incircle.size(); ++i) {
        const IncircleQuery& q = family.incircle[i];
        auto print_query = [&] {
            print_point(q.a), print_point(q.b), print_point(q.c), print_point(q.d);
        };
        report("incircle", i, got.incircle[i], want.incircle[i], print_query);
        report("incircle_cosine", i, got.incircle_cosine[i], want.incircle_cosine[i], print_query);
    }
    // The 3D signs, unless `got` has none (the batched predicates are planar only).
    for (std::size_t i = 0; i < got.orient3d.size(); ++i) {
        const Orient3dQuery& q = family.orient3d[i];
        report("orient3d", i, got.orient3d[i], want.orient3d[i],
               [&] { print_point(q.a), print_point(q.b), print_point(q.c), print_point(q.d); });
    }
    for (std::size_t i = 0; i < got.insphere.size(); ++i) {
        const InsphereQuery& q = family.insphere[i];
        report("insphere", i, got.insphere[i], want.insphere[i], [&] {
            print_point(q.a), print_point(q.b), print_point(q.c), print_point(q.d),
                print_point(q.e);
        });
    }
    return bad;
}

/// FNV-1a over a sign sequence: a short fingerprint to compare runs of other programs.
inline std::uint64_t fingerprint(const std::vector<Sign>& signs) {
    std::uint64_t h = 14695981039346656037ull;
    for (Sign s : signs) {
        h ^= static_cast<std::uint8_t>(to_int(s) + 1);
        h *= 1099511628211ull;
    }
    return h;
}

}  // namespace exidel::hygiene
