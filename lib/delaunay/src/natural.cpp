// exidel: Sibson's areas from a cavity, in doubles or in exact rationals (natural.hpp says
// the geometry and the arithmetic).
#include "exidel/delaunay/natural.hpp"

#include <cmath>
#include <vector>

#include "rational.hpp"

namespace exidel::delaunay::detail {

namespace {

template <class Num>
struct Vec {
    Num x, y;
};

bool finite(double v) { return std::isfinite(v); }
bool finite(const Rational&) { return true; }

/// p - q, rounded to double or exact.
template <class Num>
Vec<Num> minus(Point2 p, Point2 q) {
    return {Num(p.x) - Num(q.x), Num(p.y) - Num(q.y)};
}

template <class V>
auto cross(const V& u, const V& v) {
    return u.x * v.y - u.y * v.x;
}

/// The circumcentre of the origin, u and v, which must turn counter-clockwise (false when
/// the determinant, rounded or exact, is not positive).
template <class Num, class V>
bool centre(const Vec<Num>& u, const Vec<Num>& v, V& out) {
    const Num d = 2 * cross(u, v);
    if (!(d > 0)) return false;
    const Num uu = u.x * u.x + u.y * u.y, vv = v.x * v.x + v.y * v.y;
    out = {(uu * v.y - vv * u.y) / d, (vv * u.x - uu * v.x) / d};
    return finite(out.x) && finite(out.y);
}

/// Twice the areas taken from the boundary vertices' cells (natural.hpp's top), with the
/// query at the origin; false when the arithmetic cannot decide (a determinant not
/// positive, an area negative, a sum not finite or not positive). fresh, old and area are
/// work space (V is Point2 for doubles: no allocation per query once they have grown).
template <class Num, class V>
bool areas(const LocalMesh& mesh, Point2 q, const NaturalCavity& c, std::vector<V>& fresh,
           std::vector<V>& old, std::vector<Num>& area, Num& total) {
    const auto& T = mesh.triangles;
    const auto& P = mesh.points;
    const std::size_t k = c.boundary.size();
    fresh.resize(k);
    old.resize(c.triangles.size());
    for (std::size_t j = 0; j < k; ++j) {  // c(q, v_j, v_{j+1})
        const std::size_t e = c.boundary[j];
        if (!centre(minus<Num>(P[T[e]], q), minus<Num>(P[T[next_halfedge(e)]], q), fresh[j]))
            return false;
    }
    for (std::size_t i = 0; i < old.size(); ++i) {  // the cavity triangles' centres
        const std::size_t t = c.triangles[i];
        const Point2 a = P[T[3 * t]];
        Vec<Num> o;
        if (!centre(minus<Num>(P[T[3 * t + 1]], a), minus<Num>(P[T[3 * t + 2]], a), o))
            return false;
        const Vec<Num> aq = minus<Num>(a, q);
        old[i] = {o.x + aq.x, o.y + aq.y};
    }
    area.resize(k);
    total = 0;
    for (std::size_t j = 0; j < k; ++j) {
        // v_{j+1}'s polygon, clockwise: c(q, v_j, v_{j+1}), the centres of the fan,
        // c(q, v_{j+1}, v_{j+2}); its area is minus the shoelace sum.
        const V& from = fresh[j];
        const V& to = fresh[j + 1 == k ? 0 : j + 1];
        Num s = cross(to, from);
        const V* previous = &from;
        for (std::size_t f = c.fan_start[j]; f < c.fan_start[j + 1]; ++f) {
            const V& corner = old[c.fan[f]];
            s += cross(*previous, corner);
            previous = &corner;
        }
        s += cross(*previous, to);
        area[j] = -s;
        if (!(area[j] >= 0)) return false;
        total += area[j];
    }
    return total > 0 && finite(total);
}

bool all_finite(const double* v, std::size_t count, std::size_t stride) {
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(v[i * stride])) return false;
    return true;
}

}  // namespace

bool sibson(const LocalMesh& mesh, Point2 q, NaturalCavity& c, NaturalArithmetic arithmetic,
            std::vector<double>& weights, std::span<const double> values, std::size_t columns,
            double* out) {
    const std::size_t k = c.boundary.size();
    const std::size_t first = weights.size();
    const auto value_of = [&](std::size_t j, std::size_t column) {
        const std::uint32_t v = mesh.input_of_local[mesh.triangles[next_halfedge(c.boundary[j])]];
        return values[std::size_t{v} * columns + column];
    };
    if (arithmetic == NaturalArithmetic::rounded) {
        double total = 0;
        auto& area = c.rounded_areas;
        if (areas(mesh, q, c, c.rounded_fresh, c.rounded_old, area, total)) {
            for (std::size_t j = 0; j < k; ++j) weights.push_back(area[j] / total);
            for (std::size_t col = 0; col < columns; ++col) {
                double sum = 0;
                for (std::size_t j = 0; j < k; ++j) sum += weights[first + j] * value_of(j, col);
                out[col] = sum;
            }
            return true;
        }
    }
    std::vector<Vec<Rational>> fresh, old;
    std::vector<Rational> area;
    Rational total;
    if (!areas(mesh, q, c, fresh, old, area, total)) return false;
    for (std::size_t j = 0; j < k; ++j) weights.push_back(round_rational(area[j] / total));
    std::vector<double> column(k);
    for (std::size_t col = 0; col < columns; ++col) {
        for (std::size_t j = 0; j < k; ++j) column[j] = value_of(j, col);
        if (!all_finite(column.data(), k, 1)) {  // NaN and infinities propagate
            double sum = 0;
            for (std::size_t j = 0; j < k; ++j) sum += weights[first + j] * column[j];
            out[col] = sum;
            continue;
        }
        Rational sum;
        for (std::size_t j = 0; j < k; ++j) sum += area[j] * Rational(column[j]);
        out[col] = round_rational(sum / total);
    }
    return true;
}

void along_segment(Point2 a, Point2 b, Point2 q, NaturalArithmetic arithmetic, double weights[2],
                   const double* va, const double* vb, std::size_t columns, double* out) {
    if (arithmetic == NaturalArithmetic::rounded) {
        const double dx = b.x - a.x, dy = b.y - a.y;
        const double t = ((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy);
        if (t >= 0 && t <= 1) {  // else an overflow or underflow: exactly, below
            weights[0] = 1 - t, weights[1] = t;
            for (std::size_t col = 0; col < columns; ++col)
                out[col] = (1 - t) * va[col] + t * vb[col];
            return;
        }
    }
    const Vec<Rational> d = minus<Rational>(b, a), r = minus<Rational>(q, a);
    const Rational t = (r.x * d.x + r.y * d.y) / (d.x * d.x + d.y * d.y);
    const Rational s = 1 - t;
    weights[0] = round_rational(s), weights[1] = round_rational(t);
    for (std::size_t col = 0; col < columns; ++col) {
        out[col] = std::isfinite(va[col]) && std::isfinite(vb[col])
                       ? round_rational(s * Rational(va[col]) + t * Rational(vb[col]))
                       : weights[0] * va[col] + weights[1] * vb[col];
    }
}

}  // namespace exidel::delaunay::detail
