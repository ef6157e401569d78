// The default triangulation's output arrays, pinned: issue 17 made the default faster
// (a parallel sort, a parallel compaction, memory handling) on the promise that with an
// exact kernel its arrays stay exactly what they were, for every thread count. These
// inputs are large enough for every parallel path (several chunks of the sort and the
// compaction, tens of strips) and the hashes are those of commit 7c2f955, the code
// before that work: the same inputs written as .f64 and triangulated by that commit's
// `exidel triangulate -o out.json --threads T` hash to the same values
// (tests/delaunay/golden_hash.py recomputes them from the JSON output).
//
// The points come from splitmix64 and exact double arithmetic only (no libm, no
// std::uniform_real_distribution, whose output is implementation-defined), so they are
// the same bits on every platform.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;

struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0, 1), exact
};

/// The four inputs; golden_hash.py generates the same points.
std::vector<Point2> golden_input(const std::string& name) {
    SplitMix64 g{17};
    std::vector<Point2> p;
    if (name == "uniform") {  // 200000 points in the unit square
        for (int i = 0; i < 200000; ++i) p.push_back({g.unit(), g.unit()});
    } else if (name == "grid") {  // 450 x 450 integers, shuffled: cocircular everywhere
        for (int i = 0; i < 450 * 450; ++i) p.push_back({double(i % 450), double(i / 450)});
        for (std::size_t i = p.size() - 1; i > 0; --i) std::swap(p[i], p[g.next() % (i + 1)]);
    } else if (name == "circle") {  // 150000 points ((1 - t^2) / (1 + t^2), 2t / (1 + t^2))
        for (int i = 0; i < 150000; ++i) {
            const double t = 4 * g.unit() - 2, d = 1 + t * t;
            p.push_back({(1 - t * t) / d, 2 * t / d});
        }
    } else {  // "repeats": 200000 integer points in [0, 400)^2, about a fifth repeated
        for (int i = 0; i < 200000; ++i) {
            p.push_back({double(g.next() % 400), double(g.next() % 400)});
        }
    }
    return p;
}

/// FNV-1a over the 32-bit values of each array in turn, with the arrays' sizes.
std::uint64_t hash_arrays(const Triangulation& t) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    auto add = [&](std::uint32_t v) {
        for (int byte = 0; byte < 4; ++byte) {
            h ^= (v >> (8 * byte)) & 0xffu;
            h *= 0x100000001b3ull;
        }
    };
    auto add_all = [&](const auto& values) {
        add(static_cast<std::uint32_t>(values.size()));
        for (const auto v : values) add(static_cast<std::uint32_t>(v));
    };
    add_all(t.triangles);
    add_all(t.halfedges);
    add_all(t.hull);
    add_all(t.duplicates);
    return h;
}

struct Golden {
    const char* input;
    std::uint64_t hash;
};

TEST(DelaunayGolden, DefaultArraysAreThoseOfCommit7c2f955ForEveryThreadCount) {
    const Golden golden[] = {
        {"uniform", 0x75d06d7d253557dfull},
        {"grid", 0x8a41ce6803d53bb8ull},
        {"circle", 0x86cb036e3cb8d6b0ull},
        {"repeats", 0x6bed8de4cdcd9053ull},
    };
    for (const Golden& g : golden) {
        const std::vector<Point2> pts = golden_input(g.input);
        for (const unsigned threads : {1u, 2u, 3u}) {
            Options o;
            o.threads = threads;
            const Result r = triangulate(pts, AdaptiveKernel{}, o);
            ASSERT_TRUE(r.ok()) << g.input << ": " << r.failure->message;
            EXPECT_EQ(hash_arrays(r.triangulation), g.hash)
                << g.input << ", " << threads << " threads, strategy " << to_string(r.strategy)
                << ", " << r.strips << " strips";
        }
    }
}

}  // namespace
