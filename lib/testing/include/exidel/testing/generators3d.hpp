// exidel::testing: RapidCheck generators of points in space, for the 3D predicates
// (orient3d, insphere).
//
// The same discipline as generators.hpp: every family first builds an exactly known
// structure from integers (a plane spanned by two integer vectors, an integer sphere), then
// places it with exact operations only (integer translation, scaling by 2^k), and the
// near-degenerate variants move every coordinate by a few ulps with std::nextafter. Every
// random choice shrinks toward 0: a failing property shrinks to the exact degenerate
// configuration, or to the fewest ulps away from one.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string_view>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "exidel/predicates/types.hpp"
#include "exidel/testing/generators.hpp"
#include "exidel/testing/ulp.hpp"

namespace exidel {

/// RapidCheck's customization point for points of space (hex floats, then decimals).
inline void showValue(const Point3& p, std::ostream& os) {
    char buf[192];
    std::snprintf(buf, sizeof buf, "{%a, %a, %a} (%.17g, %.17g, %.17g)", p.x, p.y, p.z, p.x, p.y,
                  p.z);
    os << buf;
}

}  // namespace exidel

namespace exidel::testing {

/// An integer point of space.
using LatticePoint3 = std::array<std::int64_t, 3>;

/// p with each coordinate moved by its own number of representable doubles (see nudge).
inline Point3 nudge(Point3 p, std::int64_t dx, std::int64_t dy, std::int64_t dz) {
    return {nudge(p.x, dx), nudge(p.y, dy), nudge(p.z, dz)};
}

/// Integer points translated by t and scaled by 2^k: exact while every |coordinate + t| <
/// 2^53 and k is in [min_exact_scale, max_scale_for_bits(bits of the largest)].
inline std::vector<Point3> place3(const std::vector<LatticePoint3>& points, LatticePoint3 t,
                                  int k) {
    std::vector<Point3> out;
    out.reserve(points.size());
    for (const auto& [x, y, z] : points) {
        out.push_back({dyadic(x + t[0], k), dyadic(y + t[1], k), dyadic(z + t[2], k)});
    }
    return out;
}

/// A point uniform in the box [-2^k, 2^k]^3 on the grid 2^(k-53).
inline rc::Gen<Point3> gen_point3_in_box(int k) {
    constexpr std::int64_t one = std::int64_t{1} << 53;
    return rc::gen::exec([k] {
        const std::int64_t mx = *gen_toward_zero(-one, one);
        const std::int64_t my = *gen_toward_zero(-one, one);
        const std::int64_t mz = *gen_toward_zero(-one, one);
        return Point3{dyadic(mx, k - 53), dyadic(my, k - 53), dyadic(mz, k - 53)};
    });
}

/// Each coordinate of each point moved by up to max_steps ulps (shrinking toward none).
inline rc::Gen<std::vector<Point3>> gen_nudged3(std::vector<Point3> points,
                                                std::int64_t max_steps) {
    return rc::gen::exec([points = std::move(points), max_steps] {
        std::vector<Point3> moved = points;
        for (Point3& p : moved) {
            const std::int64_t dx = *gen_ulp_offset(max_steps);
            const std::int64_t dy = *gen_ulp_offset(max_steps);
            const std::int64_t dz = *gen_ulp_offset(max_steps);
            p = nudge(p, dx, dy, dz);
        }
        return moved;
    });
}

// ---------------------------------------------------------------------------------
// Families. Each returns n points sharing one structure.

/// n points uniform in one box [-2^k, 2^k]^3, k anywhere from the subnormals to 2^1023.
inline rc::Gen<std::vector<Point3>> gen_uniform3_points(std::size_t n) {
    return rc::gen::exec([n] {
        const int k = *gen_scale_exponent(-1074, 1023);
        return *rc::gen::container<std::vector<Point3>>(n, gen_point3_in_box(k));
    });
}

/// n points whose nine coordinates each have their own exponent anywhere in the range.
inline rc::Gen<std::vector<Point3>> gen_wide_exponent3_points(std::size_t n) {
    return rc::gen::container<std::vector<Point3>>(
        n, rc::gen::build<Point3>(rc::gen::set(&Point3::x, gen_any_finite_double()),
                                  rc::gen::set(&Point3::y, gen_any_finite_double()),
                                  rc::gen::set(&Point3::z, gen_any_finite_double())));
}

/// n points of one plane: o + s u + t v with integer spanning vectors u, v (entries up to
/// 2^8), integer s, t up to 2^12 and an integer origin up to 2^30, scaled by 2^k. Every
/// four are exactly coplanar.
inline rc::Gen<std::vector<LatticePoint3>> gen_plane_integers(std::size_t n) {
    return rc::gen::exec([n] {
        const auto entry = gen_toward_zero(-(1 << 8), 1 << 8);
        const LatticePoint3 u{*entry, *entry, *entry}, v{*entry, *entry, *entry};
        constexpr std::int64_t o = std::int64_t{1} << 30;
        const LatticePoint3 origin{*gen_toward_zero(-o, o), *gen_toward_zero(-o, o),
                                   *gen_toward_zero(-o, o)};
        std::vector<LatticePoint3> ints;
        for (std::size_t i = 0; i < n; ++i) {
            const std::int64_t s = *gen_toward_zero(-(1 << 12), 1 << 12);
            const std::int64_t t = *gen_toward_zero(-(1 << 12), 1 << 12);
            ints.push_back({origin[0] + s * u[0] + t * v[0], origin[1] + s * u[1] + t * v[1],
                            origin[2] + s * u[2] + t * v[2]});  // |.| < 2^31
        }
        return ints;
    });
}

inline rc::Gen<std::vector<Point3>> gen_coplanar_points(std::size_t n) {
    return rc::gen::exec([n] {
        const int k = *gen_scale_exponent(min_exact_scale, max_scale_for_bits(32));
        return place3(*gen_plane_integers(n), {0, 0, 0}, k);
    });
}

/// Coplanar points moved by up to 3 ulps per coordinate.
inline rc::Gen<std::vector<Point3>> gen_coplanar_near_points(std::size_t n) {
    return rc::gen::exec([n] { return *gen_nudged3(*gen_coplanar_points(n), 3); });
}

/// A point of the integer sphere of radius s = m^2 + n^2 + p^2 + q^2 about the origin, from
/// the quaternion parametrisation (Euler's four-square identity): (m^2 + n^2 - p^2 - q^2,
/// 2 (m q + n p), 2 (n q - m p)) has squared length s^2. Permuting and negating the four
/// integers keeps s, so one quadruple gives up to 384 points of the same sphere.
inline LatticePoint3 sphere_point(std::int64_t m, std::int64_t n, std::int64_t p, std::int64_t q) {
    return {m * m + n * n - p * p - q * q, 2 * (m * q + n * p), 2 * (n * q - m * p)};
}

/// n points of one integer sphere (radius m^2 + n^2 + p^2 + q^2 with |m|, ... <= 2^12, so
/// coordinates below 2^26), about an integer centre of up to 2^26, scaled by 2^k: every
/// five are exactly cospherical (or repeat a point, which small radii do often).
inline rc::Gen<std::vector<LatticePoint3>> gen_sphere_integers(std::size_t n) {
    return rc::gen::exec([n] {
        const auto entry = gen_toward_zero(-(1 << 12), 1 << 12);
        const std::array<std::int64_t, 4> base{*entry, *entry, *entry, *entry};
        constexpr std::int64_t c = std::int64_t{1} << 26;
        const LatticePoint3 centre{*gen_toward_zero(-c, c), *gen_toward_zero(-c, c),
                                   *gen_toward_zero(-c, c)};
        std::vector<LatticePoint3> ints;
        for (std::size_t i = 0; i < n; ++i) {
            // A permutation (as a random order of indices) and four signs.
            std::array<int, 4> order{0, 1, 2, 3};
            for (int j = 3; j > 0; --j) std::swap(order[j], order[*rc::gen::inRange(0, j + 1)]);
            std::array<std::int64_t, 4> v{};
            for (int j = 0; j < 4; ++j) {
                v[j] = base[order[j]] * (*rc::gen::arbitrary<bool>() ? -1 : 1);
            }
            const LatticePoint3 p = sphere_point(v[0], v[1], v[2], v[3]);
            ints.push_back({p[0] + centre[0], p[1] + centre[1], p[2] + centre[2]});
        }
        return ints;
    });
}

inline rc::Gen<std::vector<Point3>> gen_cospherical_points(std::size_t n) {
    return rc::gen::exec([n] {
        const int k = *gen_scale_exponent(min_exact_scale, max_scale_for_bits(28));
        return place3(*gen_sphere_integers(n), {0, 0, 0}, k);
    });
}

/// Cospherical points moved by up to 3 ulps per coordinate.
inline rc::Gen<std::vector<Point3>> gen_cospherical_near_points(std::size_t n) {
    return rc::gen::exec([n] { return *gen_nudged3(*gen_cospherical_points(n), 3); });
}

/// n points drawn from at most three distinct uniform points: repeated points.
inline rc::Gen<std::vector<Point3>> gen_duplicate3_points(std::size_t n) {
    return rc::gen::exec([n] {
        const auto pool = *rc::gen::container<std::vector<Point3>>(3, gen_point3_in_box(0));
        std::vector<Point3> out;
        for (std::size_t i = 0; i < n; ++i) out.push_back(pool[*rc::gen::inRange(0, 3)]);
        return out;
    });
}

// ---------------------------------------------------------------------------------
// The families by name, for properties that run over all of them.

enum class Family3 {
    uniform,
    wide_exponents,
    coplanar,
    coplanar_near,
    cospherical,
    cospherical_near,
    duplicates,
};

struct Family3Info {
    Family3 family;
    std::string_view name;
};

inline constexpr std::array<Family3Info, 7> all_families3{{
    {Family3::uniform, "uniform"},
    {Family3::wide_exponents, "wide-exponents"},
    {Family3::coplanar, "coplanar"},
    {Family3::coplanar_near, "coplanar-near"},
    {Family3::cospherical, "cospherical"},
    {Family3::cospherical_near, "cospherical-near"},
    {Family3::duplicates, "duplicates"},
}};

inline rc::Gen<std::vector<Point3>> gen_family3_points(Family3 f, std::size_t n) {
    switch (f) {
        case Family3::uniform: return gen_uniform3_points(n);
        case Family3::wide_exponents: return gen_wide_exponent3_points(n);
        case Family3::coplanar: return gen_coplanar_points(n);
        case Family3::coplanar_near: return gen_coplanar_near_points(n);
        case Family3::cospherical: return gen_cospherical_points(n);
        case Family3::cospherical_near: return gen_cospherical_near_points(n);
        case Family3::duplicates: return gen_duplicate3_points(n);
    }
    return gen_uniform3_points(n);
}

/// Four points of one family: an orient3d query.
inline rc::Gen<std::array<Point3, 4>> gen_query3d4(Family3 f) {
    return rc::gen::map(gen_family3_points(f, 4), [](const std::vector<Point3>& v) {
        return std::array<Point3, 4>{v[0], v[1], v[2], v[3]};
    });
}

/// Five points of one family: an insphere query.
inline rc::Gen<std::array<Point3, 5>> gen_query3d5(Family3 f) {
    return rc::gen::map(gen_family3_points(f, 5), [](const std::vector<Point3>& v) {
        return std::array<Point3, 5>{v[0], v[1], v[2], v[3], v[4]};
    });
}

}  // namespace exidel::testing
