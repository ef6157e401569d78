// exidel hygiene tests: the query generator. Compiled with -ffp-contract=off and without
// -ffast-math (see CMakeLists.txt): every coordinate is a literal, an exact scaling by a
// power of two, one rounded addition, or a std::nextafter step.
#include "queries.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace exidel::hygiene {

namespace {

// x moved by `steps` ulps (negative: downwards). Exact, and it walks through the
// subnormals like any other double.
double ulps(double x, int steps) {
    const double toward = steps >= 0 ? std::numeric_limits<double>::infinity()
                                     : -std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::abs(steps); ++i) x = std::nextafter(x, toward);
    return x;
}

// Points with integer coordinates on the circle x^2 + y^2 = 65^2 (65 = 5 * 13 has four
// essentially different Pythagorean representations), in counter-clockwise order. None has
// a zero coordinate: an ulp step away from 0 is the smallest subnormal, and the families
// that claim to stay in the normal range must not meet subnormals by accident.
constexpr std::array<Point2, 12> circle65 = {{
    {63, 16},
    {56, 33},
    {39, 52},
    {16, 63},
    {-25, 60},
    {-52, 39},
    {-63, -16},
    {-60, -25},
    {-33, -56},
    {16, -63},
    {33, -56},
    {60, -25},
}};

struct Placement {
    int exponent;  // coordinates are (point + offset) * 2^exponent
    Point2 offset;
};

Point2 place(Point2 p, const Placement& where) {
    // One rounded addition (exact when the offset is an integer), then an exact scaling
    // (as long as the result stays normal, or the value is an integer small enough).
    return {std::ldexp(p.x + where.offset.x, where.exponent),
            std::ldexp(p.y + where.offset.y, where.exponent)};
}

// Quadruples (a, b, c, d) of the circle, all four in counter-clockwise order so that the
// in-circle and the cosine test both mean "d inside"; d is moved over the ulp grid.
void add_cocircular(QueryFamily& family, const Placement& where, int ulp_radius) {
    const int n = static_cast<int>(circle65.size());
    for (int i = 0; i < n; ++i) {
        for (int gap = 1; gap <= 3; ++gap) {
            const Point2 a = place(circle65[i], where);
            const Point2 b = place(circle65[(i + gap) % n], where);
            const Point2 c = place(circle65[(i + 2 * gap) % n], where);
            const Point2 d0 = place(circle65[(i + 3 * gap) % n], where);
            // e = 2b - a lies on line ab (exactly, when the placement is exact): the
            // orient2d work at the same scale.
            const Point2 pa = circle65[i], pb = circle65[(i + gap) % n];
            const Point2 e0 = place({2 * pb.x - pa.x, 2 * pb.y - pa.y}, where);
            for (int dx = -ulp_radius; dx <= ulp_radius; ++dx) {
                for (int dy = -ulp_radius; dy <= ulp_radius; ++dy) {
                    family.incircle.push_back({a, b, c, {ulps(d0.x, dx), ulps(d0.y, dy)}});
                    family.orient2d.push_back({a, b, {ulps(e0.x, dx), ulps(e0.y, dy)}});
                }
            }
        }
    }
}

// The integer points of the sphere x^2 + y^2 + z^2 = 65^2 with no zero coordinate (as
// for the circle: an ulp step from 0 would be a subnormal), in a fixed order.
std::vector<Point3> sphere65() {
    std::vector<Point3> points;
    for (int x = -64; x <= 64; ++x) {
        for (int y = -64; y <= 64; ++y) {
            const int zz = 65 * 65 - x * x - y * y;
            if (x == 0 || y == 0 || zz <= 0) continue;
            const int z = static_cast<int>(std::lround(std::sqrt(zz)));
            if (z * z == zz) points.push_back({double(x), double(y), double(z)});
        }
    }
    return points;
}

Point3 place(Point3 p, const Placement& where) {
    return {std::ldexp(p.x + where.offset.x, where.exponent),
            std::ldexp(p.y + where.offset.y, where.exponent),
            std::ldexp(p.z + where.offset.x + where.offset.y, where.exponent)};
}

// Quintuples of the sphere (every fifth point apart, so the choices spread over it) with
// e moved over the ulp grid (in x and z); quadruples of the plane through a, b, c with
// d = b + c - a (integers: exactly coplanar before placement), moved alike.
void add_cospherical(QueryFamily& family, const Placement& where, int ulp_radius) {
    static const std::vector<Point3> sphere = sphere65();
    const std::size_t n = sphere.size();
    for (std::size_t i = 0; i < n; i += 7) {
        const Point3 p[5] = {sphere[i], sphere[(i + n / 5) % n], sphere[(i + 2 * n / 5) % n],
                             sphere[(i + 3 * n / 5) % n], sphere[(i + 4 * n / 5) % n]};
        const Point3 a = place(p[0], where), b = place(p[1], where), c = place(p[2], where),
                     d = place(p[3], where), e0 = place(p[4], where);
        const Point3 d0 = place(
            {p[1].x + p[2].x - p[0].x, p[1].y + p[2].y - p[0].y, p[1].z + p[2].z - p[0].z}, where);
        for (int dx = -ulp_radius; dx <= ulp_radius; ++dx) {
            for (int dz = -ulp_radius; dz <= ulp_radius; ++dz) {
                family.insphere.push_back({a, b, c, d, {ulps(e0.x, dx), e0.y, ulps(e0.z, dz)}});
                family.orient3d.push_back({a, b, c, {ulps(d0.x, dx), d0.y, ulps(d0.z, dz)}});
            }
        }
    }
}

// p walks over the grid; (p, q, r), (q, r, p) and (r, p, q) are the same orientation
// exactly, but the pivot changes where the naive formula fails.
void add_collinear_grid(QueryFamily& family, Point2 p, Point2 q, Point2 r, int grid_size,
                        int stride) {
    double x = p.x;
    for (int i = 0; i < grid_size; ++i, x = ulps(x, stride)) {
        double y = p.y;
        for (int j = 0; j < grid_size; ++j, y = ulps(y, stride)) {
            const Point2 moved{x, y};
            family.orient2d.push_back({moved, q, r});
            family.orient2d.push_back({q, r, moved});
            family.orient2d.push_back({r, moved, q});
        }
    }
}

}  // namespace

QueryFamily kettner_family(int grid_size) {
    QueryFamily family{"kettner", true, {}, {}, {}, {}};
    // A thinner grid keeps the same span of 256 ulps.
    const int stride = 256 / grid_size;
    add_collinear_grid(family, {0.5, 0.5}, {12, 12}, {24, 24}, grid_size, stride);
    add_collinear_grid(family, {0.50000000000002531, 0.5000000000000171},
                       {17.300000000000001, 17.300000000000001},
                       {24.00000000000005, 24.0000000000000517765}, grid_size, stride);
    add_collinear_grid(family, {0.5, 0.5}, {8.8000000000000007, 8.8000000000000007}, {12.1, 12.1},
                       grid_size, stride);
    return family;
}

QueryFamily cocircular_family(int ulp_radius) {
    QueryFamily family{"cocircular", true, {}, {}, {}, {}};
    // Exponents keep every product of the degree-8 cosine form well inside the normal
    // range (65 * 2^100 to the 8th is about 2^850).
    for (int exponent : {-100, 0, 100}) {
        for (Point2 offset :
             {Point2{0, 0}, Point2{1000, -3000}, Point2{0.1, 0.3}, Point2{1e6 + 0.7, 3e5 + 0.1}}) {
            add_cocircular(family, {exponent, offset}, ulp_radius);
            add_cospherical(family, {exponent, offset}, ulp_radius);
        }
    }
    return family;
}

QueryFamily huge_family(int ulp_radius) {
    // 65 * 2^950 is about 2^956: differences are fine, their squares overflow, and the
    // translated copies sit near the largest double.
    QueryFamily family{"huge", true, {}, {}, {}, {}};
    for (Point2 offset : {Point2{0, 0}, Point2{1000, -3000}, Point2{0.1, 0.3}}) {
        add_cocircular(family, {950, offset}, ulp_radius);
        add_cospherical(family, {950, offset}, ulp_radius);
    }
    add_cocircular(family, {1010, {0, 0}}, ulp_radius);  // coordinates up to ~2^1016
    add_cospherical(family, {1010, {0, 0}}, ulp_radius);
    return family;
}

QueryFamily underflow_family(int ulp_radius) {
    QueryFamily family{"underflow", false, {}, {}, {}, {}};
    // Subnormal coordinates: integers times 2^-1074 (the smallest subnormal) are exact.
    add_cocircular(family, {-1074, {0, 0}}, ulp_radius);
    add_cocircular(family, {-1074, {1000, -3000}}, ulp_radius);
    add_cospherical(family, {-1074, {0, 0}}, ulp_radius);
    add_cospherical(family, {-1074, {1000, -3000}}, ulp_radius);
    // Normal coordinates whose squares (2^-1200) and products underflow.
    add_cocircular(family, {-600, {0, 0}}, ulp_radius);
    add_cocircular(family, {-600, {0.1, 0.3}}, ulp_radius);
    add_cospherical(family, {-600, {0, 0}}, ulp_radius);
    add_cospherical(family, {-600, {0.1, 0.3}}, ulp_radius);
    // Kettner's first configuration shrunk into the subnormals: (1,1), (24,24), (48,48)
    // units of 2^-1074, moved by single subnormal steps.
    const double unit = std::numeric_limits<double>::denorm_min();
    add_collinear_grid(family, {1 * unit, 1 * unit}, {24 * unit, 24 * unit}, {48 * unit, 48 * unit},
                       16, 1);
    // Mixed magnitudes: one subnormal point against points of size 1.
    add_collinear_grid(family, {3 * unit, 3 * unit}, {0.5, 0.5}, {1, 1}, 16, 1);
    return family;
}

std::vector<QueryFamily> all_families(int scale) {
    std::vector<QueryFamily> families;
    families.push_back(kettner_family(256 / scale));
    const int radius = scale == 1 ? 3 : 1;
    families.push_back(cocircular_family(radius));
    families.push_back(huge_family(radius));
    families.push_back(underflow_family(radius));
    return families;
}

}  // namespace exidel::hygiene
