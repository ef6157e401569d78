// exidel hygiene test: a consumer translation unit. CMakeLists.txt builds this one source
// three times: with exidel's own strict flags (the reference), with
// -O3 -march=native -ffp-contract=fast, and with -ffast-math (compiled and linked, so the
// process starts with flush-to-zero and denormals-are-zero set).
//
//   exidel-hygiene-<flavour>                 AdaptiveKernel and the batched predicates must
//                                            give the exact sign on every near-degenerate
//                                            query; exit code 1 otherwise
//   exidel-hygiene-<flavour> --double-signs  fingerprints of the plain kernels' answers, which
//                                            tests/hygiene/same_output.cmake compares across
//                                            the three builds: compiled in the library, they
//                                            must not depend on the consumer's flags
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

#include "evaluate.hpp"
#include "fp_environment.hpp"
#include "queries.hpp"

using namespace exidel;
using namespace exidel::hygiene;

namespace {

#ifndef EXIDEL_HYGIENE_FLAVOUR
#error "CMakeLists.txt names each build with -DEXIDEL_HYGIENE_FLAVOUR=\"...\""
#endif

int check_adaptive(const std::vector<QueryFamily>& families) {
    std::size_t total_bad = 0;
    for (const QueryFamily& family : families) {
        // The exact answers, computed in the default environment whatever this process
        // started with; the adaptive kernel then runs in the process's own environment.
        const Signs exact =
            in_default_environment([&] { return evaluate(GmpExactKernel{}, family); });
        const Signs adaptive = evaluate(AdaptiveKernel{}, family);
        const Signs plain = evaluate(DoubleKernel{}, family);
        const std::size_t bad = count_mismatches("adaptive", family, adaptive, exact) +
                                count_mismatches("batch", family, evaluate_batch(family), exact);
        total_bad += bad;
        const std::size_t queries = family.orient2d.size() + 2 * family.incircle.size() +
                                    family.orient3d.size() + family.insphere.size();
        // The plain kernel is expected to be wrong here: the count is information, and
        // shows that the queries are hard. It is not printed query by query.
        std::size_t plain_wrong = 0;
        for (std::size_t i = 0; i < exact.orient2d.size(); ++i)
            plain_wrong += plain.orient2d[i] != exact.orient2d[i];
        for (std::size_t i = 0; i < exact.incircle.size(); ++i) {
            plain_wrong += plain.incircle[i] != exact.incircle[i];
            plain_wrong += plain.incircle_cosine[i] != exact.incircle_cosine[i];
        }
        for (std::size_t i = 0; i < exact.orient3d.size(); ++i)
            plain_wrong += plain.orient3d[i] != exact.orient3d[i];
        for (std::size_t i = 0; i < exact.insphere.size(); ++i)
            plain_wrong += plain.insphere[i] != exact.insphere[i];
        std::printf("%-10s %7zu queries: adaptive and batch wrong %zu, double wrong %zu\n",
                    family.name.c_str(), queries, bad, plain_wrong);
    }
    return total_bad == 0 ? 0 : 1;
}

// Only the families where the environment cannot matter (no subnormal operand or result):
// the -ffast-math build runs with FTZ/DAZ, which legitimately changes what the plain
// formulas compute on subnormals. That the plain kernel follows the caller's environment
// is documented; that it follows the caller's compiler flags would be a bug.
int print_double_signs(const std::vector<QueryFamily>& families) {
    for (const QueryFamily& family : families) {
        if (!family.normal_range) continue;
        const Signs d = evaluate(DoubleKernel{}, family);
        const Signs ld = evaluate(LongDoubleKernel{}, family);
        for (const auto& [name, s] : {std::pair{"double", &d}, std::pair{"long-double", &ld}}) {
            std::printf("%s %s", family.name.c_str(), name);
            for (const std::vector<Sign>* signs :
                 {&s->orient2d, &s->incircle, &s->incircle_cosine, &s->orient3d, &s->insphere}) {
                std::printf(" %016llx", static_cast<unsigned long long>(fingerprint(*signs)));
            }
            std::printf("\n");
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool double_signs = argc == 2 && std::strcmp(argv[1], "--double-signs") == 0;
    if (argc > 2 || (argc == 2 && !double_signs)) {
        std::fprintf(stderr, "usage: %s [--double-signs]\n", argv[0]);
        return 2;
    }
    const std::vector<QueryFamily> families = all_families(1);
    if (double_signs) return print_double_signs(families);

    std::printf("flavour %s, FTZ/DAZ at start: %s\n", EXIDEL_HYGIENE_FLAVOUR,
                ftz_or_daz_on() ? "on" : "off");
#if defined(EXIDEL_HYGIENE_EXPECT_FTZ) && EXIDEL_HYGIENE_HAVE_MXCSR
    // Otherwise this build would not test what it claims to.
    if (!ftz_or_daz_on()) {
        std::printf("FAIL: linking with -ffast-math was expected to set FTZ/DAZ\n");
        return 1;
    }
#endif
    return check_adaptive(families);
}
