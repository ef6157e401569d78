// A consumer of exidel: decides orient2d on a degenerate and an ulp-perturbed
// configuration with the adaptive and the exact kernel. Exit code 0 iff every sign is the
// known exact answer.
#include <cmath>
#include <cstdio>

#include <exidel/predicates/all.hpp>
#ifdef EXIDEL_CONSUMER_HAS_DELAUNAY
#include <exidel/delaunay/certify.hpp>
#include <exidel/delaunay/triangulate.hpp>
#endif

namespace {

int failures = 0;

void expect(const char* what, exidel::Sign got, exidel::Sign want) {
    if (got != want) {
        std::printf("FAIL %s: got %d, want %d\n", what, exidel::to_int(got), exidel::to_int(want));
        ++failures;
    }
}

template <class Kernel>
void check(const char* kernel) {
    const exidel::Point2 p{0.5, 0.5}, q{12, 12}, r{24, 24};
    // Exactly collinear (Kettner et al.'s first configuration).
    std::printf("%s: collinear -> %d\n", kernel, exidel::to_int(Kernel::orient2d(p, q, r)));
    expect("collinear", Kernel::orient2d(p, q, r), exidel::Sign::zero);
    // One ulp up moves p above the line y = x, to the left of the direction q -> r:
    // p, q, r turn counter-clockwise ((q-p) x (r-p) = 12 ulps > 0); one ulp down, clockwise.
    const exidel::Point2 above{p.x, std::nextafter(p.y, 1.0)};
    expect("p one ulp above", Kernel::orient2d(above, q, r), exidel::Sign::positive);
    const exidel::Point2 below{p.x, std::nextafter(p.y, 0.0)};
    expect("p one ulp below", Kernel::orient2d(below, q, r), exidel::Sign::negative);
}

}  // namespace

int main() {
    check<exidel::AdaptiveKernel>("adaptive");
    check<exidel::GmpExactKernel>("exact");
    if (failures == 0) std::printf("exidel consumer: all signs exact\n");
    return failures == 0 ? 0 : 1;
}
