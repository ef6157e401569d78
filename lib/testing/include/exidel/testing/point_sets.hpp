// exidel::testing: seeded point sets that look like the data users triangulate (places,
// coastlines, administrative borders, LiDAR lattices, blue noise, GPS tracks), for
// benchmarks and property tests, so that nothing is tuned to one real data set.
//
//   for (const RealisticInfo& f : realistic_families())
//       std::vector<Point2> p = realistic_points(f.family, 100'000, /*seed=*/1);
//
// Each family reproduces what makes real data differ from uniform points: duplicates,
// runs of (nearly or exactly) collinear points, dense clusters beside empty space,
// coordinates with few significant digits (exact ties), large offsets with small
// differences, and the file order the data usually comes in. realistic_points(f, n, seed)
// returns exactly n points, the same ones for the same (f, n, seed) on every run.
//
// Needs no RapidCheck (plain functions of a std::mt19937_64, whose output the C++ standard
// fixes; no std:: distribution is used, their outputs are implementation-defined). Every
// product that meets a sum is written with std::fma, and each coordinate is rounded to its
// family's decimal or integer grid last, so the points do not depend on the consumer's
// -ffp-contract setting. They do depend on the C library's log, sin and cos (the same glibc
// gives the same points).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "exidel/predicates/types.hpp"

namespace exidel::testing {

enum class Realistic {
    lonlat,        ///< a gazetteer: places in lon/lat, 5 decimals, 10% duplicates
    coastline,     ///< polygon rings: fractal coasts, straight runs, closing duplicates
    borders,       ///< administrative borders quantized to an integer grid, shared twice
    lidar,         ///< a LiDAR-like lattice: 0.01 m steps at UTM offsets, duplicates
    poisson_disc,  ///< blue noise: no two points closer than r
    tracks,        ///< GPS tracks: smooth curves, straight roads, stops (duplicates)
};

struct RealisticInfo {
    Realistic family;
    std::string_view name;
    std::string_view description;
};

/// Every realistic family, with its name (stable: used on command lines and in tables).
inline constexpr std::array<RealisticInfo, 6> realistic_families() {
    return {{
        {Realistic::lonlat, "lonlat",
         "places in lon/lat rounded to 5 decimals: towns of Zipf-distributed sizes on a few "
         "land masses, empty oceans between, 10% exact duplicates; file order random"},
        {Realistic::coastline, "coastline",
         "vertices of closed rings (a few large, many small, Pareto sizes): midpoint-displaced "
         "fractal coasts with evenly subdivided straight runs, 6 decimals, cut at the map's "
         "edges, each ring's first vertex repeated at its end; in ring order"},
        {Realistic::borders, "borders",
         "administrative borders quantized to an integer grid (10^4 cells a side up to 10^6 "
         "points): random-walk polylines with exactly collinear runs, most emitted twice "
         "(the two polygons that share them); in ring order"},
        {Realistic::lidar, "lidar",
         "a LiDAR tile: x, y on a 0.01 m lattice at UTM-like offsets (500000 m, 4500000 m) "
         "as the doubles nearest the decimals, lattice nodes drawn with repetition (about "
         "12% duplicates); in scan-line order"},
        {Realistic::poisson_disc, "poisson-disc",
         "blue noise in the unit square: dart throwing on a grid of cells, no two points "
         "closer than r; random order"},
        {Realistic::tracks, "tracks",
         "GPS tracks in lon/lat, 6 decimals: smooth random headings, straight roads, stops "
         "(repeated positions, about 5%), all within one city; in track order"},
    }};
}

/// The family called `name`; throws std::invalid_argument for any other name.
inline Realistic realistic_from_name(std::string_view name) {
    for (const RealisticInfo& f : realistic_families())
        if (f.name == name) return f.family;
    throw std::invalid_argument("no realistic point family '" + std::string(name) + "'");
}

inline std::string_view realistic_name(Realistic f) {
    for (const RealisticInfo& i : realistic_families())
        if (i.family == f) return i.name;
    return "?";
}

namespace realistic_detail {

using Rng = std::mt19937_64;

/// Uniform in [0, 1), 53 random bits: exact.
inline double unit(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

/// Uniform in [lo, hi): one rounding (fma).
inline double uniform(Rng& rng, double lo, double hi) { return std::fma(unit(rng), hi - lo, lo); }

/// Uniform integer in [0, m), m > 0 (modulo bias below 2^-40 for every m used here).
inline std::uint64_t below(Rng& rng, std::uint64_t m) { return rng() % m; }

/// Standard normal (Box-Muller, one of the pair).
inline double normal(Rng& rng) {
    const double u = 1.0 - unit(rng);  // (0, 1]
    const double v = unit(rng);
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

/// The double nearest to round(v * scale) / scale: what reading v printed with
/// log10(scale) decimals gives (both operands of the division are exact integers).
inline double snap(double v, double scale) { return std::nearbyint(v * scale) / scale; }

/// Shared by lonlat: a uniformly random point of the ellipse (cx, cy, rx, ry).
inline Point2 in_ellipse(Rng& rng, double cx, double cy, double rx, double ry) {
    for (;;) {
        const double u = uniform(rng, -1.0, 1.0), v = uniform(rng, -1.0, 1.0);
        if (std::fma(u, u, v * v) <= 1.0) return {std::fma(u, rx, cx), std::fma(v, ry, cy)};
    }
}

inline std::vector<Point2> lonlat(std::size_t n, Rng& rng) {
    struct Land {
        double cx, cy, rx, ry;
    };
    std::vector<Land> lands(24);
    std::vector<double> land_area(lands.size());
    for (std::size_t i = 0; i < lands.size(); ++i) {
        lands[i] = {uniform(rng, -165.0, 165.0), uniform(rng, -50.0, 65.0), uniform(rng, 3.0, 25.0),
                    uniform(rng, 2.0, 15.0)};
        land_area[i] = lands[i].rx * lands[i].ry + (i ? land_area[i - 1] : 0.0);
    }
    // Towns: centre on a land mass chosen by area, a spread, a Zipf weight 1 / (i + 1).
    const std::size_t towns = std::max<std::size_t>(1, n / 20);
    std::vector<Point2> centre(towns);
    std::vector<double> spread(towns), weight(towns);
    for (std::size_t t = 0; t < towns; ++t) {
        const double a = unit(rng) * land_area.back();
        const std::size_t l = static_cast<std::size_t>(
            std::upper_bound(land_area.begin(), land_area.end() - 1, a) - land_area.begin());
        centre[t] = in_ellipse(rng, lands[l].cx, lands[l].cy, lands[l].rx, lands[l].ry);
        const double s = unit(rng);
        spread[t] = std::fma(0.3 * s, s * s, 0.01);  // degrees: mostly small towns
        weight[t] = 1.0 / static_cast<double>(t + 1) + (t ? weight[t - 1] : 0.0);
    }
    std::vector<Point2> p;
    p.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0 && below(rng, 10) == 0) {  // an exact duplicate of an earlier place
            p.push_back(p[below(rng, i)]);
            continue;
        }
        const double w = unit(rng) * weight.back();
        const std::size_t t = static_cast<std::size_t>(
            std::upper_bound(weight.begin(), weight.end() - 1, w) - weight.begin());
        double lon = std::fma(spread[t], normal(rng), centre[t].x);
        double lat = std::fma(spread[t], normal(rng), centre[t].y);
        lon = std::clamp(lon, -180.0, 180.0);
        lat = std::clamp(lat, -90.0, 90.0);
        p.push_back({snap(lon, 1e5), snap(lat, 1e5)});
    }
    return p;
}

// A closed fractal ring of `count` vertices (count >= 1) around (cx, cy) with mean radius r,
// by midpoint displacement from an octagon: each edge's midpoint moves across the edge by
// a normal deviate times a quarter of its length, except on "straight" edges (chosen with
// probability 1/25 per edge and level, inherited by both halves), whose midpoints stay put:
// evenly spaced runs of nearly collinear points. Subdivided until it has at least `count`
// vertices, then thinned in order to exactly `count`.
inline void ring(Rng& rng, double cx, double cy, double r, std::size_t count,
                 std::vector<Point2>& out) {
    struct V {
        Point2 p;
        bool straight;  // the edge from this vertex to the next
    };
    std::vector<V> v;
    for (int k = 0; k < 8; ++k) {
        const double t = std::fma(unit(rng), 0.5, k) * (std::numbers::pi / 4);
        const double rr = r * uniform(rng, 0.7, 1.3);
        v.push_back({{std::fma(rr, std::cos(t), cx), std::fma(rr, std::sin(t), cy)}, false});
    }
    std::vector<V> next;
    while (v.size() < count) {
        next.clear();
        for (std::size_t i = 0; i < v.size(); ++i) {
            const V& a = v[i];
            const Point2 b = v[(i + 1) % v.size()].p;
            const bool straight = a.straight || below(rng, 25) == 0;
            Point2 m{(a.p.x + b.x) * 0.5, (a.p.y + b.y) * 0.5};
            if (!straight) {
                const double d = 0.25 * normal(rng);  // times the edge, turned a quarter
                m = {std::fma(-d, b.y - a.p.y, m.x), std::fma(d, b.x - a.p.x, m.y)};
            }
            next.push_back({a.p, straight});
            next.push_back({m, straight});
        }
        v.swap(next);
    }
    // Keep `count` of the v.size() vertices, evenly in order (Bresenham).
    const std::size_t m = v.size();
    for (std::size_t i = 0, kept = 0; i < m && kept < count; ++i) {
        if ((i + 1) * count / m > kept) {
            // On a world map, land beyond the edges is cut at them (collinear runs there).
            out.push_back({snap(std::clamp(v[i].p.x, -180.0, 180.0), 1e6),
                           snap(std::clamp(v[i].p.y, -90.0, 90.0), 1e6)});
            ++kept;
        }
    }
}

inline std::vector<Point2> coastline(std::size_t n, Rng& rng) {
    std::vector<Point2> p;
    p.reserve(n);
    // Vertex spacing about 600 / n degrees: the coasts of a world map at n vertices.
    const double spacing = 600.0 / static_cast<double>(std::max<std::size_t>(n, 1));
    std::array<Point2, 8> regions;
    for (Point2& c : regions) c = {uniform(rng, -150.0, 150.0), uniform(rng, -50.0, 60.0)};
    while (p.size() < n) {
        const std::size_t left = n - p.size();
        // Pareto ring sizes (index 1.5): most rings small, a few holding most vertices.
        const double u = 1.0 - unit(rng);
        std::size_t size = static_cast<std::size_t>(std::min(1e18, 6.0 / std::pow(u, 1.5)));
        if (left < 10) {
            size = left;
        } else {
            size = std::clamp<std::size_t>(size, 5, left);
            if (left - size < 5) size = left;  // never leave a tail too small for a ring
        }
        const Point2 c = regions[below(rng, regions.size())];
        const double cx = std::clamp(std::fma(20.0, normal(rng), c.x), -170.0, 170.0);
        const double cy = std::clamp(std::fma(12.0, normal(rng), c.y), -70.0, 75.0);
        const double r =
            std::min(30.0, static_cast<double>(size) * spacing / (2.0 * std::numbers::pi * 1.6));
        const std::size_t first = p.size();
        if (size == 1) {
            p.push_back({snap(cx, 1e6), snap(cy, 1e6)});
            continue;
        }
        ring(rng, cx, cy, r, size - 1, p);
        p.push_back(p[first]);  // the ring closes on its first vertex
    }
    return p;
}

inline std::vector<Point2> borders(std::size_t n, Rng& rng) {
    const double side = std::max(1e4, std::round(10.0 * std::sqrt(static_cast<double>(n))));
    const auto q = static_cast<std::int64_t>(side);
    std::vector<Point2> p;
    p.reserve(n);
    std::vector<Point2> line;
    while (p.size() < n) {
        // One border: a walk of integer steps with a drifting heading; runs of one repeated
        // step are exactly collinear.
        line.clear();
        const std::size_t length = 4 + below(rng, 400);
        std::int64_t x = static_cast<std::int64_t>(below(rng, static_cast<std::uint64_t>(q)));
        std::int64_t y = static_cast<std::int64_t>(below(rng, static_cast<std::uint64_t>(q)));
        double heading = uniform(rng, 0.0, 2.0 * std::numbers::pi);
        while (line.size() < length) {
            heading = std::fma(0.4, normal(rng), heading);
            const double step = static_cast<double>(1 + below(rng, 12));
            const auto dx = static_cast<std::int64_t>(std::lround(step * std::cos(heading)));
            const auto dy = static_cast<std::int64_t>(std::lround(step * std::sin(heading)));
            const std::size_t run = below(rng, 8) == 0 ? 3 + below(rng, 30) : 1;
            for (std::size_t k = 0; k < run && line.size() < length; ++k) {
                x = std::clamp<std::int64_t>(x + dx, 0, q - 1);
                y = std::clamp<std::int64_t>(y + dy, 0, q - 1);
                line.push_back({static_cast<double>(x), static_cast<double>(y)});
            }
        }
        // Most borders separate two polygons, so their vertices appear in two rings (the
        // second in reverse); one in five is a coast and appears once.
        const bool shared = below(rng, 5) != 0;
        for (const Point2& v : line) {
            if (p.size() == n) break;
            p.push_back(v);
        }
        if (shared) {
            for (auto it = line.rbegin(); it != line.rend() && p.size() < n; ++it) p.push_back(*it);
        }
    }
    return p;
}

inline std::vector<Point2> lidar(std::size_t n, Rng& rng) {
    // A square of 4n lattice nodes, 0.01 m apart; n draws with repetition. Coordinates are
    // the doubles nearest (offset + k) / 100 metres.
    const auto side = static_cast<std::uint64_t>(
        std::ceil(2.0 * std::sqrt(static_cast<double>(std::max<std::size_t>(n, 1)))));
    std::vector<std::array<std::uint64_t, 2>> nodes(n);
    for (auto& k : nodes) k = {below(rng, side), below(rng, side)};
    // Scan lines: sorted by row band (16 lattice rows), then by x within the band,
    // alternating direction as a scanner sweeps back and forth.
    std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) {
        const std::uint64_t ba = a[1] / 16, bb = b[1] / 16;
        if (ba != bb) return ba < bb;
        return (ba % 2 == 0) ? a[0] < b[0] : a[0] > b[0];
    });
    std::vector<Point2> p;
    p.reserve(n);
    for (const auto& k : nodes)
        p.push_back({static_cast<double>(50'000'000 + k[0]) / 100.0,
                     static_cast<double>(450'000'000 + k[1]) / 100.0});
    return p;
}

inline std::vector<Point2> poisson_disc(std::size_t n, Rng& rng) {
    if (n == 0) return {};
    // Dart throwing on a grid of cells of side r / sqrt(2) (at most one point per cell),
    // eight darts per cell in row order; a dart is kept if no kept point is within r.
    // r is chosen so that about 1.2 n points are kept; if fewer than n are, r shrinks.
    double r = std::sqrt(0.62 / (1.2 * static_cast<double>(n)));
    for (;;) {
        const double cell = r / std::numbers::sqrt2;
        const auto g = static_cast<std::int64_t>(std::ceil(1.0 / cell));
        std::vector<std::int64_t> grid(static_cast<std::size_t>(g * g), -1);
        std::vector<Point2> kept;
        kept.reserve(n + n / 4);
        const double r2 = r * r;
        for (std::int64_t cy = 0; cy < g; ++cy) {
            for (std::int64_t cx = 0; cx < g; ++cx) {
                for (int dart = 0; dart < 8; ++dart) {
                    const Point2 d{(static_cast<double>(cx) + unit(rng)) * cell,
                                   (static_cast<double>(cy) + unit(rng)) * cell};
                    if (d.x >= 1.0 || d.y >= 1.0) continue;
                    bool free = true;
                    for (std::int64_t y = std::max<std::int64_t>(cy - 2, 0);
                         free && y <= std::min(cy + 2, g - 1); ++y) {
                        for (std::int64_t x = std::max<std::int64_t>(cx - 2, 0);
                             x <= std::min(cx + 2, g - 1); ++x) {
                            const std::int64_t k = grid[static_cast<std::size_t>(y * g + x)];
                            if (k < 0) continue;
                            const Point2& o = kept[static_cast<std::size_t>(k)];
                            const double dx = o.x - d.x, dy = o.y - d.y;
                            if (std::fma(dx, dx, dy * dy) < r2) {
                                free = false;
                                break;
                            }
                        }
                    }
                    if (!free) continue;
                    grid[static_cast<std::size_t>(cy * g + cx)] =
                        static_cast<std::int64_t>(kept.size());
                    kept.push_back(d);
                    break;
                }
            }
        }
        if (kept.size() >= n) {
            // n of them in random order (a partial Fisher-Yates shuffle); dropping points
            // keeps every distance at least r.
            for (std::size_t i = 0; i < n; ++i)
                std::swap(kept[i], kept[i + below(rng, kept.size() - i)]);
            kept.resize(n);
            return kept;
        }
        r *= 0.9;
    }
}

inline std::vector<Point2> tracks(std::size_t n, Rng& rng) {
    // A city of 0.2 x 0.15 degrees; steps of about 10^-4 degrees (10 m).
    const double lon0 = uniform(rng, -120.0, 140.0), lat0 = uniform(rng, -40.0, 60.0);
    const double w = 0.2, h = 0.15;
    std::vector<Point2> p;
    p.reserve(n);
    while (p.size() < n) {
        const std::size_t length = 10 + below(rng, 2000);
        double x = std::fma(0.15, normal(rng), 0.5), y = std::fma(0.15, normal(rng), 0.5);
        double heading = uniform(rng, 0.0, 2.0 * std::numbers::pi);
        std::size_t straight = 0;  // steps left on a straight road
        for (std::size_t k = 0; k < length && p.size() < n; ++k) {
            const std::uint64_t event = below(rng, 100);
            if (event < 5 && !p.empty() && k > 0) {  // stopped: the same position again
                p.push_back(p.back());
                continue;
            }
            if (straight > 0) {
                --straight;
            } else if (event < 7) {
                straight = 20 + below(rng, 200);
            } else {
                heading = std::fma(0.15, normal(rng), heading);
            }
            const double step = 5e-4 * uniform(rng, 0.8, 1.2);
            x = std::fma(step, std::cos(heading), x);
            y = std::fma(step, std::sin(heading), y);
            if (x < 0.0 || x > 1.0) {  // turned back at the city's edge
                heading = std::numbers::pi - heading;
                x = std::clamp(x, 0.0, 1.0);
            }
            if (y < 0.0 || y > 1.0) {
                heading = -heading;
                y = std::clamp(y, 0.0, 1.0);
            }
            p.push_back({snap(std::fma(x, w, lon0), 1e6), snap(std::fma(y, h, lat0), 1e6)});
        }
    }
    return p;
}

}  // namespace realistic_detail

/// n points of family `f` drawn with `seed` (the same points for the same arguments).
inline std::vector<Point2> realistic_points(Realistic f, std::size_t n, std::uint64_t seed) {
    realistic_detail::Rng rng(seed ^ (0x9E3779B97F4A7C15ULL * (static_cast<std::uint64_t>(f) + 1)));
    switch (f) {
        case Realistic::lonlat: return realistic_detail::lonlat(n, rng);
        case Realistic::coastline: return realistic_detail::coastline(n, rng);
        case Realistic::borders: return realistic_detail::borders(n, rng);
        case Realistic::lidar: return realistic_detail::lidar(n, rng);
        case Realistic::poisson_disc: return realistic_detail::poisson_disc(n, rng);
        case Realistic::tracks: return realistic_detail::tracks(n, rng);
    }
    throw std::invalid_argument("unknown realistic point family");
}

}  // namespace exidel::testing
