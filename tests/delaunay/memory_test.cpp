// Fresh memory (lib/delaunay/include/exidel/delaunay/detail/memory.hpp): the large internal
// arrays are mappings of their own, aligned to 2 MiB and unmapped when freed, and a
// triangulation leaves no huge-page advice behind in the process: after the Result is
// gone, no mapping of the process carries MADV_HUGEPAGE ("hg" in /proc/self/smaps), with
// one thread and with two.
#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cstdint>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "exidel/delaunay/detail/memory.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/adaptive.hpp"

namespace {

using namespace exidel;
using namespace exidel::delaunay;
namespace fresh = exidel::delaunay::detail;
using fresh::huge_page_bytes;

TEST(FreshMemory, LargeArraysAreAlignedMappingsThatGoAway) {
    const std::size_t before = fresh::mapped_fresh_bytes();
    {
        fresh::FreshBuffer<std::uint64_t> big(huge_page_bytes / 8 + 1);  // just over 2 MiB
        ASSERT_NE(big.get(), nullptr);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.get()) % huge_page_bytes, 0u);
        EXPECT_EQ(fresh::mapped_fresh_bytes(), before + 2 * huge_page_bytes);
        big.get()[0] = 1;
        big.get()[big.size() - 1] = 2;  // the whole range is writable
        EXPECT_EQ(big.get()[0] + big.get()[big.size() - 1], 3u);
        fresh::FreshBuffer<std::uint64_t> moved = std::move(big);
        EXPECT_EQ(big.get(), nullptr);
        EXPECT_EQ(moved.size(), huge_page_bytes / 8 + 1);
    }
    EXPECT_EQ(fresh::mapped_fresh_bytes(), before);
    {
        fresh::FreshBuffer<std::uint32_t> small(1000);  // below 2 MiB: operator new
        small.get()[999] = 7;
        EXPECT_EQ(fresh::mapped_fresh_bytes(), before);
    }
}

TEST(FreshMemory, VectorGrowsAcrossTheThresholdKeepingItsElements) {
    const std::size_t before = fresh::mapped_fresh_bytes();
    {
        fresh::FreshVector<std::uint32_t> v;
        for (std::uint32_t i = 0; i < 3 * huge_page_bytes / 4; ++i) v.push_back(i * 7u);
        for (std::uint32_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], i * 7u) << i;
        EXPECT_GT(fresh::mapped_fresh_bytes(), before);
    }
    EXPECT_EQ(fresh::mapped_fresh_bytes(), before);
}

/// The mappings of this process whose VmFlags include `flag`, as "start-end" lines; empty
/// where /proc/self/smaps cannot be read.
std::vector<std::string> mappings_with_flag(const std::string& flag) {
    std::ifstream smaps("/proc/self/smaps");
    std::vector<std::string> found;
    std::string line, range;
    while (std::getline(smaps, line)) {
        // A mapping's header line starts with its range, "start-end" in hex; the lines
        // about it start with a field name and a colon.
        const std::string first = line.substr(0, line.find(' '));
        if (!first.empty() && first.back() != ':' &&
            first.find_first_not_of("0123456789abcdef-") == std::string::npos) {
            range = first;
        }
        if (line.rfind("VmFlags:", 0) == 0) {
            std::istringstream flags(line.substr(8));
            std::string f;
            while (flags >> f) {
                if (f == flag) found.push_back(range);
            }
        }
    }
    return found;
}

// Twice: with malloc as it starts (arrays of megabytes get mappings of their own, which
// free() unmaps, advice and all), and then as a caller's malloc may be (here told to keep
// blocks up to 32 MB in its heap and freed memory there too, as glibc also decides by
// itself once a large block has been freed): then the output arrays come from the heap and stay
// there when freed, and only settle_huge_pages keeps their advice from outliving them (without it
// this fails).
TEST(FreshMemory, TriangulationLeavesNoHugePageAdviceBehind) {
    std::ifstream probe("/proc/self/smaps");
    if (!probe) GTEST_SKIP() << "no /proc/self/smaps here";
    ASSERT_TRUE(mappings_with_flag("hg").empty()) << "advice before any triangulation";
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Point2> pts(300'000);  // arrays of 7 MB: several huge pages each
    for (Point2& p : pts) p = {u(rng), u(rng)};
    const std::size_t before = fresh::mapped_fresh_bytes();
    auto run = [&](const std::string& label) {
        for (const unsigned threads : {1u, 2u}) {
            for (int round = 0; round < 2; ++round) {  // the second reuses freed memory
                Options options;
                options.threads = threads;
                {
                    const Result r = triangulate(pts, AdaptiveKernel{}, options);
                    ASSERT_TRUE(r.ok());
                    ASSERT_GT(r.strips, 1u) << "the strips must run";
                }
                EXPECT_EQ(fresh::mapped_fresh_bytes(), before) << label << threads;
                const auto left = mappings_with_flag("hg");
                EXPECT_TRUE(left.empty())
                    << label << ", " << threads << " threads, round " << round << ": "
                    << left.size() << " advised mapping(s) left, first "
                    << (left.empty() ? "" : left.front());
            }
        }
    };
    run("malloc as it starts");
    // glibc's malloc tuned to keep blocks; under AddressSanitizer or ThreadSanitizer malloc
    // is the sanitizer's, which has no such parameters (mallopt returns 0).
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
    ASSERT_EQ(mallopt(M_MMAP_THRESHOLD, 32 << 20), 1);
    ASSERT_EQ(mallopt(M_TRIM_THRESHOLD, 1 << 30), 1);  // and to keep freed memory
    run("malloc keeping blocks in its heap");
#endif
}

}  // namespace
