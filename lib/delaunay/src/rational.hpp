// exidel: exact rationals inside lib/delaunay's sources (Boost.Multiprecision over GMP,
// never in an installed header), and their rounding to the nearest double.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <boost/multiprecision/gmp.hpp>

#include "exidel/predicates/construct.hpp"

namespace exidel::delaunay::detail {

using Rational = boost::multiprecision::mpq_rational;

/// The magnitude of an integer in little-endian 64-bit words.
inline std::vector<std::uint64_t> words(const boost::multiprecision::mpz_int& v) {
    std::vector<std::uint64_t> w((mpz_sizeinbase(v.backend().data(), 2) + 63) / 64 + 1, 0);
    std::size_t count = 0;
    mpz_export(w.data(), &count, -1, sizeof(std::uint64_t), 0, 0, v.backend().data());
    w.resize(count);
    return w;
}

/// The exact value rounded to nearest, ties to even (exidel::round_quotient, the rounding
/// of the circumcentre's construction).
inline double round_rational(const Rational& r) {
    const auto num = numerator(r), den = denominator(r);
    return round_quotient(words(num), words(den), num < 0);
}

}  // namespace exidel::delaunay::detail
