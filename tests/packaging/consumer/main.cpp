// A consumer of exidel: decides orient2d on a degenerate and an ulp-perturbed
// configuration with the adaptive and the exact kernel, and (with exidel::delaunay)
// triangulates with every kernel and algorithm of the registries. Exit code 0 iff every
// sign is the known exact answer and every triangulation is right.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <variant>

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

#ifdef EXIDEL_CONSUMER_HAS_DELAUNAY
// Every kernel of the registry, by name, triangulates four cocircular points with every
// algorithm of the registry: the instantiations compiled in the installed library link,
// and the exact kernels' results are certified.
void triangulate_with_every_kernel() {
    const exidel::Point2 square[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const char* name :
         {"double", "long-double", "adaptive", "exact", "exact-cpp", "mpfr:64"}) {
        std::string error;
        const std::optional<exidel::AnyKernel> kernel = exidel::parse_kernel(name, error);
        if (!kernel) {
            std::printf("FAIL kernel %s: %s\n", name, error.c_str());
            ++failures;
            continue;
        }
        for (const exidel::delaunay::AlgorithmInfo& a : exidel::delaunay::algorithms()) {
            exidel::delaunay::Options options;
            options.algorithm = a.id;
            const exidel::delaunay::Result r = std::visit(
                [&](const auto& k) { return exidel::delaunay::triangulate(square, k, options); },
                *kernel);
            const bool exact = exidel::kernel_is_exact(*kernel);
            if (!r.ok() || r.triangulation.triangle_count() != 2 ||
                (exact && !exidel::delaunay::certify(square, r.triangulation).ok())) {
                std::printf("FAIL triangulate with %s, %s\n", name, std::string(a.name).c_str());
                ++failures;
            }
        }
    }
}
#endif

}  // namespace

int main() {
    check<exidel::AdaptiveKernel>("adaptive");
    check<exidel::GmpExactKernel>("exact");
#ifdef EXIDEL_CONSUMER_HAS_DELAUNAY
    triangulate_with_every_kernel();
#endif
    if (failures == 0) std::printf("exidel consumer: all signs exact\n");
    return failures == 0 ? 0 : 1;
}
