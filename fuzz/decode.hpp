// libFuzzer harnesses (internal): points decoded from arbitrary bytes, shared by
// triangulate.cpp and constrained.cpp. Decoding (the first byte's low two bits): 0 raw
// float64 pairs, little-endian (any double, NaN and infinities included); 1 pairs of signed
// bytes, a small integer grid full of collinear, cocircular and repeated points; 2 the same
// grid scaled by 2^k (k from the second byte, -1100 to 1100: subnormals, and products that
// overflow); 3 the grid plus an ulp-sized nudge per coordinate (the third byte's bits),
// near-degenerate.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "exidel/predicates/types.hpp"

namespace exidel::fuzz {

inline std::vector<Point2> decode(const std::uint8_t* data, std::size_t size) {
    std::vector<Point2> points;
    if (size == 0) return points;
    const unsigned mode = data[0] & 3u;
    ++data;
    --size;
    if (mode == 0) {
        for (std::size_t i = 0; i + 16 <= size; i += 16) {
            std::uint64_t x = 0, y = 0;
            std::memcpy(&x, data + i, 8);
            std::memcpy(&y, data + i + 8, 8);
            points.push_back({std::bit_cast<double>(x), std::bit_cast<double>(y)});
        }
        return points;
    }
    int k = 0;
    std::uint8_t nudge = 0;
    if (mode >= 2 && size >= 2) {
        k = mode == 2 ? int(data[0]) * 2200 / 255 - 1100 : 0;
        nudge = data[1];
        data += 2;
        size -= 2;
    }
    for (std::size_t i = 0; i + 2 <= size; i += 2) {
        double x = std::ldexp(double(std::int8_t(data[i])), k);
        double y = std::ldexp(double(std::int8_t(data[i + 1])), k);
        if (mode == 3) {
            // One ulp up or down per coordinate, from the nudge byte's bits in turn.
            const unsigned bit = unsigned(i) % 8;
            x = std::nextafter(x, (nudge >> bit) & 1u ? INFINITY : -INFINITY);
            y = std::nextafter(y, (nudge >> ((bit + 1) % 8)) & 1u ? INFINITY : -INFINITY);
        }
        points.push_back({x, y});
    }
    return points;
}

inline bool all_finite(const std::vector<Point2>& points) {
    for (const Point2& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    }
    return true;
}

}  // namespace exidel::fuzz
