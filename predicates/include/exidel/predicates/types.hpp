// exidel: the value types every kernel speaks: points of two or three doubles and a sign.
#pragma once

#include <cstdint>

namespace exidel {

/// A point of the plane. Predicates require both coordinates to be finite.
struct Point2 {
    double x;
    double y;
    friend constexpr bool operator==(const Point2&, const Point2&) = default;
};

/// A point of space, for the 3D predicates (orient3d, insphere). Predicates require every
/// coordinate to be finite.
struct Point3 {
    double x;
    double y;
    double z;
    friend constexpr bool operator==(const Point3&, const Point3&) = default;
};

/// The result of every predicate. Never a raw determinant: callers must not compare a
/// floating-point value against a tolerance.
enum class Sign : std::int8_t { negative = -1, zero = 0, positive = 1 };

constexpr int to_int(Sign s) noexcept { return static_cast<int>(s); }

constexpr Sign operator-(Sign s) noexcept { return static_cast<Sign>(-to_int(s)); }

constexpr Sign operator*(Sign a, Sign b) noexcept {
    return static_cast<Sign>(to_int(a) * to_int(b));
}

/// Sign of a value of any ordered number type (double, GMP integers, MPFR values, ...).
template <class T>
constexpr Sign sign_of(const T& v) noexcept(noexcept(v > 0)) {
    return v > 0 ? Sign::positive : (v < 0 ? Sign::negative : Sign::zero);
}

}  // namespace exidel
