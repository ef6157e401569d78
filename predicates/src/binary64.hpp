// exidel (private): the one decoder of a double's bits.
//
// A finite double is significand * 2^exponent with an integer significand below 2^53.
// Reading the fields from the bits, rather than with frexp or ilogb, makes the answer
// independent of the caller's floating-point environment (denormals-are-zero would read
// a subnormal as 0) and avoids a library call on the predicates' slow paths.
#pragma once

#include <bit>
#include <cstdint>

namespace exidel::detail {

struct Binary64 {
    bool negative;
    /// The raw exponent field, 0 for zero and subnormals, 2047 for infinities and NaN.
    int biased_exponent;
    /// The integer significand, hidden bit included for normal numbers (< 2^53).
    std::uint64_t significand;
    /// |v| = significand * 2^exponent (finite v).
    int exponent;

    /// The significand with v's sign.
    constexpr std::int64_t signed_significand() const noexcept {
        const auto m = static_cast<std::int64_t>(significand);
        return negative ? -m : m;
    }
};

/// 2^e for -1074 <= e <= 1023, from its bits (exact; no library call).
constexpr double pow2(int e) noexcept {
    if (e >= -1022) return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
    return std::bit_cast<double>(std::uint64_t{1} << (e + 1074));
}

constexpr Binary64 decode(double v) noexcept {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    const auto field = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t significand = bits & ((std::uint64_t{1} << 52) - 1);
    int exponent = -1074;  // subnormal: no hidden bit
    if (field != 0) {
        significand |= std::uint64_t{1} << 52;
        exponent = field - 1075;
    }
    return {(bits >> 63) != 0, field, significand, exponent};
}

}  // namespace exidel::detail
