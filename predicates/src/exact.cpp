// exidel: the exact reference kernel (exponent-aligned integers, GMP or cpp_int).
#include "exidel/predicates/exact.hpp"

#include <algorithm>
#include <initializer_list>

#include <boost/multiprecision/cpp_int.hpp>
#include <boost/multiprecision/gmp.hpp>

#include "binary64.hpp"
#include "formulas.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"

namespace exidel {

namespace {

template <ExactBackend B>
struct IntegerOf;
template <>
struct IntegerOf<ExactBackend::gmp> {
    using type = boost::multiprecision::mpz_int;
};
template <>
struct IntegerOf<ExactBackend::cpp_int> {
    using type = boost::multiprecision::cpp_int;
};

// Maps the coordinates of one query to integers on the common grid 2^g, where g is the
// smallest q among them. All predicates are homogeneous in coordinate differences, so the
// scale 2^-g changes no sign (proofs/exact-kernel.md).
template <class Int>
class AlignedLift {
public:
    AlignedLift(std::initializer_list<Point2> points) {
        for (const Point2& p : points) {
            for (double v : {p.x, p.y}) lower_grid(v);
        }
    }
    AlignedLift(std::initializer_list<Point3> points) {
        for (const Point3& p : points) {
            for (double v : {p.x, p.y, p.z}) lower_grid(v);
        }
    }
    Int operator()(double v) const {
        const detail::Binary64 d = detail::decode(v);
        if (d.significand == 0) return Int(0);
        Int r(d.signed_significand());
        r <<= static_cast<unsigned>(d.exponent - grid_);
        return r;
    }

private:
    void lower_grid(double v) {
        // v = m * 2^q, m an integer of at most 53 bits (binary64.hpp).
        const detail::Binary64 d = detail::decode(v);
        if (d.significand != 0) grid_ = std::min(grid_, d.exponent);
    }

    int grid_ = 1 << 20;  // larger than any exponent: every nonzero value lowers it
};

}  // namespace

template <ExactBackend B>
std::string ExactKernel<B>::name() {
    return B == ExactBackend::gmp ? "exact" : "exact-cpp";
}

template <ExactBackend B>
Sign ExactKernel<B>::orient2d(Point2 a, Point2 b, Point2 c) {
    using Int = typename IntegerOf<B>::type;
    return detail::orient2d_formula<Int>(a, b, c, AlignedLift<Int>{a, b, c});
}

template <ExactBackend B>
Sign ExactKernel<B>::incircle(Point2 a, Point2 b, Point2 c, Point2 d) {
    using Int = typename IntegerOf<B>::type;
    return detail::incircle_formula<Int>(a, b, c, d, AlignedLift<Int>{a, b, c, d});
}

template <ExactBackend B>
Sign ExactKernel<B>::incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) {
    using Int = typename IntegerOf<B>::type;
    return detail::incircle_cosine_formula<Int>(a, b, c, d, AlignedLift<Int>{a, b, c, d});
}

template <ExactBackend B>
Sign ExactKernel<B>::compare_distance(Point2 c, Point2 p, Point2 q) {
    using Int = typename IntegerOf<B>::type;
    return detail::compare_distance_formula<Int>(c, p, q, AlignedLift<Int>{c, p, q});
}

template <ExactBackend B>
Sign ExactKernel<B>::orient3d(Point3 a, Point3 b, Point3 c, Point3 d) {
    using Int = typename IntegerOf<B>::type;
    return detail::orient3d_formula<Int>(a, b, c, d, AlignedLift<Int>{a, b, c, d});
}

template <ExactBackend B>
Sign ExactKernel<B>::insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e) {
    using Int = typename IntegerOf<B>::type;
    return detail::insphere_formula<Int>(a, b, c, d, e, AlignedLift<Int>{a, b, c, d, e});
}

template struct ExactKernel<ExactBackend::gmp>;
template struct ExactKernel<ExactBackend::cpp_int>;

}  // namespace exidel
