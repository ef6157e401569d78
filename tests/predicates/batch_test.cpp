// The batched predicates give exactly the adaptive kernel's signs (and so CGAL's): on every
// family, with the AVX2 filters and with the scalar loops, for lengths that are not
// multiples of four, in a non-standard rounding mode, and they reject spans of different
// lengths.
#include <cfenv>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "batch_dispatch.hpp"
#include "cgal_oracle.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/batch.hpp"
#include "exidel/testing/all.hpp"

namespace exidel::test {
namespace {

struct Queries {
    std::vector<Point2> a, b, c, d;
};

/// n queries of family f (incircle quadruples; orient2d and compare_distance use a, b, c).
Queries gen_queries(testing::Family f, std::size_t n) {
    Queries q;
    for (std::size_t i = 0; i < n; ++i) {
        const auto [a, b, c, d] = *testing::gen_query4(f);
        q.a.push_back(a);
        q.b.push_back(b);
        q.c.push_back(c);
        q.d.push_back(d);
    }
    return q;
}

/// Every batched predicate on `q` against one call per query (and CGAL where it has the
/// predicate), as RapidCheck assertions.
void check_batch(const Queries& q) {
    const std::size_t n = q.a.size();
    std::vector<Sign> out(n);
    batch::orient2d(q.a, q.b, q.c, out);
    for (std::size_t i = 0; i < n; ++i) {
        RC_ASSERT(out[i] == AdaptiveKernel::orient2d(q.a[i], q.b[i], q.c[i]));
        RC_ASSERT(out[i] == cgal_orient2d(q.a[i], q.b[i], q.c[i]));
    }
    batch::incircle(q.a, q.b, q.c, q.d, out);
    for (std::size_t i = 0; i < n; ++i) {
        RC_ASSERT(out[i] == AdaptiveKernel::incircle(q.a[i], q.b[i], q.c[i], q.d[i]));
        RC_ASSERT(out[i] == cgal_incircle(q.a[i], q.b[i], q.c[i], q.d[i]));
    }
    batch::incircle_cosine(q.a, q.b, q.c, q.d, out);
    for (std::size_t i = 0; i < n; ++i) {
        RC_ASSERT(out[i] == AdaptiveKernel::incircle_cosine(q.a[i], q.b[i], q.c[i], q.d[i]));
    }
    batch::compare_distance(q.a, q.b, q.c, out);
    for (std::size_t i = 0; i < n; ++i) {
        RC_ASSERT(out[i] == AdaptiveKernel::compare_distance(q.a[i], q.b[i], q.c[i]));
    }
}

void check_every_family(const std::string& what) {
    for (const testing::FamilyInfo& f : testing::all_families()) {
        const bool ok = rc::check(what + " on " + std::string(f.name), [&] {
            const auto n = *rc::gen::inRange<std::size_t>(0, 23);  // every remainder mod 4
            check_batch(gen_queries(f.family, n));
        });
        EXPECT_TRUE(ok) << what << " failed on family " << f.name;
    }
}

/// Runs `body` with the AVX2 filters on or off, restoring the setting after.
template <class Body>
void with_avx2(bool on, Body body) {
    bool& use = detail::batch_use_avx2();
    const bool saved = use;
    use = on;
    body();
    use = saved;
}

TEST(Batch, MatchesOneCallPerQueryWithTheDetectedImplementation) {
    std::cout << "batched filters: " << batch::implementation() << "\n";
    check_every_family(std::string("batch (") + batch::implementation() + ")");
}

TEST(Batch, MatchesOneCallPerQueryWithTheScalarLoops) {
    with_avx2(false, [] { check_every_family("batch (scalar)"); });
}

TEST(Batch, IsExactInEveryRoundingMode) {
    for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
        const bool ok = rc::check("batch in a directed rounding mode", [mode] {
            const auto f =
                *rc::gen::element(testing::Family::near_rounded_circle,
                                  testing::Family::near_rounded_line, testing::Family::uniform);
            const Queries q = gen_queries(f, 16);
            std::vector<Sign> want(16), got(16);
            batch::incircle(q.a, q.b, q.c, q.d, want);
            std::fesetround(mode);
            batch::incircle(q.a, q.b, q.c, q.d, got);
            std::fesetround(FE_TONEAREST);
            RC_ASSERT(got == want);
            batch::orient2d(q.a, q.b, q.c, want);
            std::fesetround(mode);
            batch::orient2d(q.a, q.b, q.c, got);
            std::fesetround(FE_TONEAREST);
            RC_ASSERT(got == want);
        });
        EXPECT_TRUE(ok);
    }
}

TEST(Batch, RejectsSpansOfDifferentLengths) {
    const std::vector<Point2> three(3), four(4);
    std::vector<Sign> out(4);
    EXPECT_THROW(batch::orient2d(four, four, three, out), std::invalid_argument);
    EXPECT_THROW(batch::incircle(four, three, four, four, out), std::invalid_argument);
    EXPECT_THROW(batch::incircle_cosine(four, four, four, four, std::span<Sign>(out).first(3)),
                 std::invalid_argument);
    EXPECT_THROW(batch::compare_distance(three, four, four, out), std::invalid_argument);
    EXPECT_NO_THROW(batch::orient2d({}, {}, {}, {}));
}

}  // namespace
}  // namespace exidel::test
