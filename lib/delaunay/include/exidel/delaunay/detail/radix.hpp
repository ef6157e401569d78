// exidel: a stable sort of (64-bit key, index) records by key, for the two sorts every
// triangulation starts with (the lexicographic sort of the input and the radial sort of
// each strip). Both sort doubles, and a double's order is an order on its bits
// (order_key below), so a least-significant-digit radix sort does in six linear passes
// what a comparison sort does in log2(n) ~ 20 (docs/measurements.md).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/memory.hpp"

namespace exidel::delaunay::detail {

struct KeyIndex {
    std::uint64_t key;
    std::uint32_t index;
};

/// An unsigned integer whose order is the numerical order of the finite or infinite
/// double v (not NaN), with -0.0 and +0.0 mapped to the same key, as every predicate
/// treats them: negative values have their bits inverted, non-negative ones the sign
/// bit set. Decided on the bits, so it does not depend on the rounding mode.
constexpr std::uint64_t order_key(double v) noexcept {
    constexpr std::uint64_t sign = std::uint64_t{1} << 63;
    std::uint64_t b = std::bit_cast<std::uint64_t>(v);
    if (b == sign) b = 0;  // -0.0 is +0.0
    return (b & sign) ? ~b : (b | sign);
}

/// Sorts `v` by key, stably (equal keys keep their order). LSD radix sort with 11-bit
/// digits; a pass whose digit is the same in every key is skipped (the exponent bits of
/// points in a small box, the high bits of the distances in one strip).
/// `buffer` is scratch memory, reused by callers that sort many times.
template <class Keys>
void radix_sort(Keys& v, FreshVector<KeyIndex>& buffer) {
    if (v.size() < 256) {  // the histograms would cost more than the sort
        std::stable_sort(v.begin(), v.end(),
                         [](const KeyIndex& a, const KeyIndex& b) { return a.key < b.key; });
        return;
    }
    constexpr unsigned bits = 11, passes = 6;  // 66 >= 64 bits
    constexpr std::size_t buckets = std::size_t{1} << bits;
    auto digit = [](std::uint64_t key, unsigned pass) {
        return static_cast<std::size_t>((key >> (bits * pass)) & (buckets - 1));
    };
    std::vector<std::array<std::uint32_t, buckets>> count(passes);
    for (const KeyIndex& r : v) {
        for (unsigned p = 0; p < passes; ++p) ++count[p][digit(r.key, p)];
    }
    buffer.resize(v.size());
    std::span<KeyIndex> from(v), to(buffer);
    for (unsigned p = 0; p < passes; ++p) {
        auto& c = count[p];
        if (c[digit(from[0].key, p)] == from.size()) continue;  // one digit everywhere
        std::uint32_t sum = 0;
        for (std::uint32_t& x : c) sum += std::exchange(x, sum);  // bucket starts
        for (const KeyIndex& r : from) to[c[digit(r.key, p)]++] = r;
        std::swap(from, to);
    }
    if (from.data() != v.data()) std::copy(from.begin(), from.end(), v.begin());
}

template <class Keys>
void radix_sort(Keys& v) {
    FreshVector<KeyIndex> buffer;
    radix_sort(v, buffer);
}

}  // namespace exidel::delaunay::detail
