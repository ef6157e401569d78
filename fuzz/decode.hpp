// libFuzzer harnesses (internal): points decoded from arbitrary bytes, shared by
// triangulate.cpp, constrained.cpp and (the header and the points) mutable_ops.cpp.
// Decoding (the first byte's low two bits): 0 raw float64 pairs, little-endian (any double,
// NaN and infinities included); 1 pairs of signed bytes, a small integer grid full of
// collinear, cocircular and repeated points; 2 the same grid scaled by 2^k (k from the
// second byte, -1100 to 1100: subnormals, and products that overflow); 3 the grid plus an
// ulp-sized nudge per coordinate (the third byte's bits), near-degenerate.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "exidel/predicates/types.hpp"

namespace exidel::fuzz {

/// The decoding's header: the mode and, for modes 2 and 3, the scale exponent and the nudge
/// byte. read_header() takes them from data (size >= 1) and advances past them.
struct Header {
    unsigned mode = 0;
    int k = 0;
    std::uint8_t nudge = 0;
};
inline Header read_header(const std::uint8_t*& data, std::size_t& size) {
    Header h;
    h.mode = data[0] & 3u;
    ++data;
    --size;
    if (h.mode >= 2 && size >= 2) {
        h.k = h.mode == 2 ? int(data[0]) * 2200 / 255 - 1100 : 0;
        h.nudge = data[1];
        data += 2;
        size -= 2;
    }
    return h;
}
/// Mode 0: a point from 16 raw bytes.
inline Point2 raw_point(const std::uint8_t* p) {
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, p, 8);
    std::memcpy(&y, p + 8, 8);
    return {std::bit_cast<double>(x), std::bit_cast<double>(y)};
}
/// Modes 1-3: a grid point from two signed bytes, scaled by 2^k, and in mode 3 one ulp up or
/// down per coordinate from the nudge byte's bits `bit` and `bit + 1` (mod 8).
inline Point2 grid_point(const Header& h, std::uint8_t x_byte, std::uint8_t y_byte, unsigned bit) {
    double x = std::ldexp(double(std::int8_t(x_byte)), h.k);
    double y = std::ldexp(double(std::int8_t(y_byte)), h.k);
    if (h.mode == 3) {
        x = std::nextafter(x, (h.nudge >> (bit % 8)) & 1u ? INFINITY : -INFINITY);
        y = std::nextafter(y, (h.nudge >> ((bit + 1) % 8)) & 1u ? INFINITY : -INFINITY);
    }
    return {x, y};
}

inline std::vector<Point2> decode(const std::uint8_t* data, std::size_t size) {
    std::vector<Point2> points;
    if (size == 0) return points;
    const Header h = read_header(data, size);
    if (h.mode == 0) {
        for (std::size_t i = 0; i + 16 <= size; i += 16) points.push_back(raw_point(data + i));
        return points;
    }
    for (std::size_t i = 0; i + 2 <= size; i += 2)
        points.push_back(grid_point(h, data[i], data[i + 1], unsigned(i) % 8));
    return points;
}

inline bool all_finite(const std::vector<Point2>& points) {
    for (const Point2& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    }
    return true;
}

}  // namespace exidel::fuzz
