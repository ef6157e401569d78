// exidel bench: the input families (see generators.hpp).
#include "generators.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace exidel::bench {

double ulps(double v, int k) {
    for (; k > 0; --k) v = std::nextafter(v, INFINITY);
    for (; k < 0; ++k) v = std::nextafter(v, -INFINITY);
    return v;
}

double unit(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

std::int64_t integer(Rng& rng, std::int64_t lo, std::int64_t hi) {
    // Rejection-free is not needed here: the modulo bias of a 64-bit draw is far below
    // anything a table of a few thousand queries could show.
    const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
    return lo + static_cast<std::int64_t>(rng() % span);
}

namespace {

Point2 uniform_point(Rng& rng) { return {unit(rng), unit(rng)}; }

Quad triple(const std::array<Point2, 3>& p) { return {p[0], p[1], p[2], Point2{0, 0}}; }
Quad quad(const std::array<Point2, 4>& p) { return {p[0], p[1], p[2], p[3]}; }

Point2 nudged(Point2 p, Rng& rng) {
    return {ulps(p.x, static_cast<int>(integer(rng, -3, 3))),
            ulps(p.y, static_cast<int>(integer(rng, -3, 3)))};
}

// ---- uniform in [0,1)^2 --------------------------------------------------------------

Quad uniform3(Rng& rng) {
    return triple({uniform_point(rng), uniform_point(rng), uniform_point(rng)});
}
Quad uniform4(Rng& rng) {
    return quad({uniform_point(rng), uniform_point(rng), uniform_point(rng), uniform_point(rng)});
}

// ---- uniform, made nearly degenerate by rounding -------------------------------------
// c = a + t (b - a) evaluated in doubles is collinear up to rounding; d placed on the
// circumcircle of abc with doubles is cocircular up to rounding. Both then move by ulps.

Quad uniform_near3(Rng& rng) {
    const Point2 a = uniform_point(rng), b = uniform_point(rng);
    const double t = 2 * unit(rng) - 0.5;
    const Point2 c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    return triple({a, b, nudged(c, rng)});
}

Quad uniform_near4(Rng& rng) {
    const double cx = unit(rng), cy = unit(rng), r = 0.05 + unit(rng) * 0.5;
    std::array<Point2, 4> p{};
    for (Point2& q : p) {
        const double angle = unit(rng) * 6.283185307179586;
        q = {cx + r * std::cos(angle), cy + r * std::sin(angle)};
    }
    p[3] = nudged(p[3], rng);
    return quad(p);
}

// ---- 2^k-scaled uniform: one scale per query, k across the whole exponent range ------
// Products of such coordinates overflow or underflow doubles (degree 2, 4 and 8).

Quad scaled(Quad q, Rng& rng) {
    const int k = static_cast<int>(integer(rng, -1000, 1000));
    for (Point2* p : {&q.a, &q.b, &q.c, &q.d}) *p = {std::ldexp(p->x, k), std::ldexp(p->y, k)};
    return q;
}
Quad scaled3(Rng& rng) { return scaled(uniform3(rng), rng); }
Quad scaled4(Rng& rng) { return scaled(uniform4(rng), rng); }

// ---- small integer grid: many exact collinear and cocircular cases -------------------

Point2 grid_point(Rng& rng) {
    return {static_cast<double>(integer(rng, -8, 8)), static_cast<double>(integer(rng, -8, 8))};
}
Quad grid3(Rng& rng) { return triple({grid_point(rng), grid_point(rng), grid_point(rng)}); }
Quad grid4(Rng& rng) {
    return quad({grid_point(rng), grid_point(rng), grid_point(rng), grid_point(rng)});
}

// ---- lattice circle: exactly cocircular integer points -------------------------------
// x^2 + y^2 = N with N a product of nine distinct primes = 1 (mod 4) has 4 * 2^9 = 2048
// integer solutions, radius about 3.4e6 (2^21.7). A query takes distinct ones, translates
// them by an integer offset and scales by a power of two: both exact, so still cocircular,
// while differences up to 2^23 make the plain incircle formula round.

const std::vector<Point2>& lattice_circle() {
    static const std::vector<Point2> points = [] {
        constexpr std::int64_t n = 5LL * 13 * 17 * 29 * 37 * 41 * 53 * 61 * 73;
        std::vector<Point2> pts;
        for (std::int64_t x = 0; x * x <= n; ++x) {
            const std::int64_t rest = n - x * x;
            auto y = static_cast<std::int64_t>(std::sqrt(static_cast<double>(rest)));
            while (y * y > rest) --y;
            while ((y + 1) * (y + 1) <= rest) ++y;
            if (y * y != rest) continue;
            for (int sx : {1, -1}) {
                for (int sy : {1, -1}) {
                    if ((sx < 0 && x == 0) || (sy < 0 && y == 0)) continue;
                    pts.push_back({static_cast<double>(sx * x), static_cast<double>(sy * y)});
                }
            }
        }
        return pts;
    }();
    return points;
}

template <std::size_t N>
std::array<Point2, N> circle_points(Rng& rng) {
    const std::vector<Point2>& all = lattice_circle();
    std::array<std::size_t, N> idx{};
    for (std::size_t i = 0; i < N; ++i) {
        do {
            const auto last = static_cast<std::int64_t>(all.size()) - 1;
            idx[i] = static_cast<std::size_t>(integer(rng, 0, last));
        } while (std::find(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(i), idx[i]) !=
                 idx.begin() + static_cast<std::ptrdiff_t>(i));
    }
    const double ox = static_cast<double>(integer(rng, -(1 << 24), 1 << 24));
    const double oy = static_cast<double>(integer(rng, -(1 << 24), 1 << 24));
    const int scale = static_cast<int>(integer(rng, -30, 0));
    std::array<Point2, N> p{};
    for (std::size_t i = 0; i < N; ++i) {
        p[i] = {std::ldexp(all[idx[i]].x + ox, scale), std::ldexp(all[idx[i]].y + oy, scale)};
    }
    return p;
}
Quad circle3(Rng& rng) { return triple(circle_points<3>(rng)); }
Quad circle4(Rng& rng) { return quad(circle_points<4>(rng)); }

// compare_distance(centre, p, q) with p and q on the lattice circle: an exact tie. The
// centre is the translation, scaled like the points (exact).
Quad circle_distance(Rng& rng) {
    const std::vector<Point2>& all = lattice_circle();
    const auto last = static_cast<std::int64_t>(all.size()) - 1;
    const Point2 p = all[static_cast<std::size_t>(integer(rng, 0, last))];
    const Point2 q = all[static_cast<std::size_t>(integer(rng, 0, last))];
    const double ox = static_cast<double>(integer(rng, -(1 << 24), 1 << 24));
    const double oy = static_cast<double>(integer(rng, -(1 << 24), 1 << 24));
    const int scale = static_cast<int>(integer(rng, -30, 0));
    const auto place = [&](Point2 v) {
        return Point2{std::ldexp(v.x + ox, scale), std::ldexp(v.y + oy, scale)};
    };
    return triple({place({0, 0}), place(p), place(q)});
}

// The same in uniform coordinates: q is p turned about the centre by a random angle, in
// doubles, so the distances agree only up to rounding.
Quad uniform_near_distance(Rng& rng) {
    const Point2 c = uniform_point(rng), p = uniform_point(rng);
    const double angle = unit(rng) * 6.283185307179586;
    const double dx = p.x - c.x, dy = p.y - c.y;
    const Point2 q{c.x + (dx * std::cos(angle) - dy * std::sin(angle)),
                   c.y + (dx * std::sin(angle) + dy * std::cos(angle))};
    return triple({c, p, q});
}

// ---- dyadic-slope collinear ----------------------------------------------------------
// a = (ax, ay) integers below 2^30, direction (1, p / 2^q) with p odd below 2^10 and
// q <= 10, points a + t (1, p / 2^q) for integers |t| <= 2^20: every coordinate needs at
// most 31 integer and 10 fraction bits, so it is exact, and the points are exactly
// collinear. Axes swap at random (steep lines); everything is scaled by 2^-30 (exact).

template <std::size_t N>
std::array<Point2, N> collinear_points(Rng& rng) {
    const double ax = static_cast<double>(integer(rng, -(1LL << 30), 1LL << 30));
    const double ay = static_cast<double>(integer(rng, -(1LL << 30), 1LL << 30));
    const double slope = std::ldexp(static_cast<double>(2 * integer(rng, -512, 511) + 1),
                                    -static_cast<int>(integer(rng, 0, 10)));
    const bool swap_axes = integer(rng, 0, 1) == 1;
    std::array<Point2, N> p{};
    for (Point2& q : p) {
        const double t = static_cast<double>(integer(rng, -(1 << 20), 1 << 20));
        Point2 r{ax + t, ay + t * slope};
        if (swap_axes) std::swap(r.x, r.y);
        q = {std::ldexp(r.x, -30), std::ldexp(r.y, -30)};
    }
    return p;
}
Quad collinear3(Rng& rng) { return triple(collinear_points<3>(rng)); }
Quad collinear4(Rng& rng) { return quad(collinear_points<4>(rng)); }

// ---- Kettner, Mehlhorn, Pion, Schirra, Yap (CGTA 2008): p over a 256 x 256 ulp grid ----

struct Config {
    Point2 p, q, r, s;  // s: the fourth point of the in-circle variants
};

Point2 on_ulp_grid(Point2 p, Rng& rng) {
    return {ulps(p.x, static_cast<int>(integer(rng, 0, 255))),
            ulps(p.y, static_cast<int>(integer(rng, 0, 255)))};
}

Quad kettner3(Rng& rng) {
    static constexpr std::array<Config, 3> configs{{
        {{0.5, 0.5}, {12, 12}, {24, 24}, {}},
        {{0.50000000000002531, 0.5000000000000171},
         {17.300000000000001, 17.300000000000001},
         {24.00000000000005, 24.0000000000000517765},
         {}},
        {{0.5, 0.5}, {8.8000000000000007, 8.8000000000000007}, {12.1, 12.1}, {}},
    }};
    const Config& c = configs[static_cast<std::size_t>(integer(rng, 0, 2))];
    return triple({on_ulp_grid(c.p, rng), c.q, c.r});
}

// In-circle analogues: the moved point with three exactly collinear ones on the diagonal
// (the "circle" is the line), and the lattice points (-4,3), (5,0), (3,4), (-3,-4) of the
// circle of radius 5 shifted by (0.1, 0.3) (rounded, so only nearly cocircular), with the
// last one moved. In the second, c and d lie on opposite sides of ab, so the cosine form
// applies to it.
Quad kettner4(Rng& rng) {
    if (integer(rng, 0, 1) == 0) {
        constexpr double diagonal = 17.300000000000001;
        return quad({on_ulp_grid({0.5, 0.5}, rng), {12, 12}, {24, 24}, {diagonal, diagonal}});
    }
    const auto shifted = [](double x, double y) { return Point2{x + 0.1, y + 0.3}; };
    return quad({shifted(-4, 3), shifted(5, 0), shifted(3, 4), on_ulp_grid(shifted(-3, -4), rng)});
}

// ---- duplicates: some points of the query coincide -------------------------------------

Quad duplicates3(Rng& rng) {
    std::array<Point2, 3> p{uniform_point(rng), uniform_point(rng), uniform_point(rng)};
    switch (integer(rng, 0, 3)) {
        case 0: p[1] = p[0]; break;
        case 1: p[2] = p[0]; break;
        case 2: p[2] = p[1]; break;
        default: p[1] = p[2] = p[0]; break;
    }
    return triple(p);
}

Quad duplicates4(Rng& rng) {
    std::array<Point2, 4> p{uniform_point(rng), uniform_point(rng), uniform_point(rng),
                            uniform_point(rng)};
    const auto i = static_cast<std::size_t>(integer(rng, 0, 3));
    auto j = static_cast<std::size_t>(integer(rng, 0, 2));
    if (j >= i) ++j;
    p[j] = p[i];
    if (integer(rng, 0, 3) == 0) p[(std::max(i, j) + 1) % 4] = p[i];  // sometimes three
    return quad(p);
}

// ---- "-near": the last point of a degenerate configuration moved by a few ulps -------

template <Quad (*Base)(Rng&)>
Quad near3(Rng& rng) {
    Quad q = Base(rng);
    q.c = nudged(q.c, rng);
    return q;
}
template <Quad (*Base)(Rng&)>
Quad near4(Rng& rng) {
    Quad q = Base(rng);
    q.d = nudged(q.d, rng);
    return q;
}

}  // namespace

const std::vector<Family>& families() {
    static const std::vector<Family> all{
        {"uniform", "uniform in [0,1)^2", uniform3, uniform4, uniform3},
        {"uniform-near", "collinear / cocircular up to double rounding, then +-3 ulps",
         uniform_near3, uniform_near4, uniform_near_distance},
        {"scaled", "uniform times 2^k, k in [-1000, 1000] per query", scaled3, scaled4},
        {"grid", "integers in [-8, 8]^2", grid3, grid4},
        {"grid-near", "grid, last point +-3 ulps", near3<grid3>, near4<grid4>},
        {"circle", "exactly cocircular lattice points, translated and scaled by 2^-s", circle3,
         circle4, circle_distance},
        {"circle-near", "circle, last point +-3 ulps", near3<circle3>, near4<circle4>,
         near3<circle_distance>},
        {"collinear", "exactly collinear, dyadic slopes", collinear3, collinear4},
        {"collinear-near", "collinear, last point +-3 ulps", near3<collinear3>, near4<collinear4>},
        {"kettner", "Kettner et al. configurations, p over a 256x256 ulp grid", kettner3, kettner4},
        {"duplicates", "uniform with coinciding points", duplicates3, duplicates4},
        {"duplicates-near", "duplicates, last point +-3 ulps", near3<duplicates3>,
         near4<duplicates4>},
    };
    return all;
}

const Family& family(const std::string& name) {
    for (const Family& f : families()) {
        if (f.name == name) return f;
    }
    throw std::invalid_argument("no input family named '" + name + "'");
}

std::vector<Point2> uniform_or_grid(const std::string& input, std::size_t n, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<Point2> p;
    if (input == "uniform") {
        for (std::size_t i = 0; i < n; ++i) p.push_back({unit(rng), unit(rng)});
    } else if (input == "grid") {
        const auto side = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
        for (std::size_t i = 0; i < side; ++i)
            for (std::size_t j = 0; j < side; ++j) p.push_back({double(i), double(j)});
    } else {
        std::fprintf(stderr, "unknown --input '%s' (uniform or grid)\n", input.c_str());
        std::exit(2);
    }
    return p;
}

}  // namespace exidel::bench
