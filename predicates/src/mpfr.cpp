// exidel: the MPFR kernel: the floating kernel's formulas at a runtime precision.
//
// MPFR's C interface is used directly (rather than Boost's mpfr_float, whose precision is
// set in decimal digits) so that the precision is exactly `bits` significand bits for every
// intermediate, each operation rounded to nearest.
#include "exidel/predicates/mpfr.hpp"

#include <mpfr.h>

#include <stdexcept>
#include <utility>

#include "formulas.hpp"
#include "exidel/predicates/internal/fp_environment.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"

namespace exidel {

namespace {

// A value of fixed precision; results of + - * take the precision of their left operand,
// and every leaf is created at the kernel's precision, so all intermediates share it.
class MpfrValue {
public:
    MpfrValue(double v, mpfr_prec_t bits) {
        mpfr_init2(v_, bits);
        mpfr_set_d(v_, v, MPFR_RNDN);  // exact when bits >= 53; rounded to nearest below
    }
    explicit MpfrValue(mpfr_prec_t bits) { mpfr_init2(v_, bits); }
    MpfrValue(const MpfrValue& o) {
        mpfr_init2(v_, mpfr_get_prec(o.v_));
        mpfr_set(v_, o.v_, MPFR_RNDN);
    }
    MpfrValue& operator=(const MpfrValue&) = delete;
    ~MpfrValue() { mpfr_clear(v_); }

    friend MpfrValue operator+(const MpfrValue& x, const MpfrValue& y) {
        MpfrValue r(mpfr_get_prec(x.v_));
        mpfr_add(r.v_, x.v_, y.v_, MPFR_RNDN);
        return r;
    }
    friend MpfrValue operator-(const MpfrValue& x, const MpfrValue& y) {
        MpfrValue r(mpfr_get_prec(x.v_));
        mpfr_sub(r.v_, x.v_, y.v_, MPFR_RNDN);
        return r;
    }
    friend MpfrValue operator*(const MpfrValue& x, const MpfrValue& y) {
        MpfrValue r(mpfr_get_prec(x.v_));
        mpfr_mul(r.v_, x.v_, y.v_, MPFR_RNDN);
        return r;
    }
    friend bool operator>(const MpfrValue& x, const MpfrValue& y) {
        return mpfr_greater_p(x.v_, y.v_) != 0;
    }
    friend bool operator>(const MpfrValue& x, int zero) { return mpfr_cmp_si(x.v_, zero) > 0; }
    friend bool operator<(const MpfrValue& x, int zero) { return mpfr_cmp_si(x.v_, zero) < 0; }

private:
    mpfr_t v_;
};

// MPFR's default exponent range is far wider than any product of doubles can reach
// (degree 8 of 2^1024 is 2^8192), so no intermediate overflows or underflows.
struct MpfrLift {
    mpfr_prec_t bits;
    MpfrValue operator()(double v) const { return MpfrValue(v, bits); }
};

}  // namespace

MpfrKernel::MpfrKernel(unsigned bits) : bits_(bits) {
    if (bits < min_bits || bits > max_bits) {
        throw std::invalid_argument("MpfrKernel: precision must be in [" +
                                    std::to_string(min_bits) + ", " + std::to_string(max_bits) +
                                    "] bits");
    }
}

std::string MpfrKernel::name() const { return "mpfr:" + std::to_string(bits_); }

// MPFR converts doubles with the processor's arithmetic, which denormals-are-zero would
// distort: run in the standard environment like the adaptive kernel.
namespace {
Sign orient2d_mpfr(Point2 a, Point2 b, Point2 c, mpfr_prec_t bits) {
    return detail::orient2d_formula<MpfrValue>(a, b, c, MpfrLift{bits});
}
Sign incircle_mpfr(Point2 a, Point2 b, Point2 c, Point2 d, mpfr_prec_t bits) {
    return detail::incircle_formula<MpfrValue>(a, b, c, d, MpfrLift{bits});
}
Sign incircle_cosine_mpfr(Point2 a, Point2 b, Point2 c, Point2 d, mpfr_prec_t bits) {
    return detail::incircle_cosine_formula<MpfrValue>(a, b, c, d, MpfrLift{bits});
}
Sign compare_distance_mpfr(Point2 c, Point2 p, Point2 q, mpfr_prec_t bits) {
    return detail::compare_distance_formula<MpfrValue>(c, p, q, MpfrLift{bits});
}
Sign orient3d_mpfr(Point3 a, Point3 b, Point3 c, Point3 d, mpfr_prec_t bits) {
    return detail::orient3d_formula<MpfrValue>(a, b, c, d, MpfrLift{bits});
}
Sign insphere_mpfr(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e, mpfr_prec_t bits) {
    return detail::insphere_formula<MpfrValue>(a, b, c, d, e, MpfrLift{bits});
}
}  // namespace

Sign MpfrKernel::orient2d(Point2 a, Point2 b, Point2 c) const {
    return detail::in_standard_environment<orient2d_mpfr>(a, b, c, mpfr_prec_t{bits_});
}

Sign MpfrKernel::incircle(Point2 a, Point2 b, Point2 c, Point2 d) const {
    return detail::in_standard_environment<incircle_mpfr>(a, b, c, d, mpfr_prec_t{bits_});
}

Sign MpfrKernel::incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) const {
    return detail::in_standard_environment<incircle_cosine_mpfr>(a, b, c, d, mpfr_prec_t{bits_});
}

Sign MpfrKernel::compare_distance(Point2 c, Point2 p, Point2 q) const {
    return detail::in_standard_environment<compare_distance_mpfr>(c, p, q, mpfr_prec_t{bits_});
}

Sign MpfrKernel::orient3d(Point3 a, Point3 b, Point3 c, Point3 d) const {
    return detail::in_standard_environment<orient3d_mpfr>(a, b, c, d, mpfr_prec_t{bits_});
}

Sign MpfrKernel::insphere(Point3 a, Point3 b, Point3 c, Point3 d, Point3 e) const {
    return detail::in_standard_environment<insphere_mpfr>(a, b, c, d, e, mpfr_prec_t{bits_});
}

}  // namespace exidel
