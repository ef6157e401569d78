// exidel: the batched predicates (batch.hpp).
//
// Per array: one check of the floating-point environment, then a loop. The AVX2 loops
// evaluate orient2d's stage A and incircle's semi-static filter for four queries at once,
// with the same IEEE operations in the same order as adaptive.cpp's scalar filters (so the
// bounds proven for those hold lane by lane: proofs/bounds.md#orient2d and
// #incircle-semi-static), and send every query a filter leaves undecided through the
// scalar stages. Compiled with -ffp-contract=off like every exact translation unit, so no
// multiply and add are fused; the AVX2 functions are compiled for AVX2 only (no FMA) and
// chosen at run time.
#include "exidel/predicates/batch.hpp"

#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
#include <immintrin.h>
#define EXIDEL_BATCH_AVX2 1
#else
#define EXIDEL_BATCH_AVX2 0
#endif

#include "exidel/predicates/internal/adaptive_unchecked.hpp"
#include "batch_dispatch.hpp"
#include "exidel/predicates/constants.hpp"
#include "exidel/predicates/internal/fp_environment.hpp"
#include "exidel/predicates/internal/fp_hygiene.hpp"

namespace exidel {

namespace detail {
bool& batch_use_avx2() noexcept {
#if EXIDEL_BATCH_AVX2
    static bool use = (__builtin_cpu_init(), __builtin_cpu_supports("avx2") != 0);
#else
    static bool use = false;
#endif
    return use;
}
}  // namespace detail

namespace {

namespace eb = bounds;

void require_same_size(std::size_t n, std::initializer_list<std::size_t> sizes, const char* what) {
    for (const std::size_t s : sizes) {
        if (s != n) {
            throw std::invalid_argument(std::string("exidel::batch::") + what +
                                        ": every span must have out's length");
        }
    }
}

// Runs `body` in the standard floating-point environment (fp_environment.hpp): directly
// when the caller's is standard, else through a call the compiler cannot inline, between
// the MXCSR writes.
template <class Body>
[[gnu::noinline]] void call_opaque(Body& body) {
    body();
}

template <class Body>
void run_in_standard_environment(Body body) {
    if (detail::environment_is_standard()) [[likely]] {
        body();
        return;
    }
    const detail::StandardEnvironment guard;
    call_opaque(body);
}

// ---- AVX2 ----------------------------------------------------------------------------------
#if EXIDEL_BATCH_AVX2

/// Four points from p: x and y in lanes ordered 0, 2, 1, 3 (unpacking two loads of two
/// interleaved points each without a cross-lane permute). The order is the same for every
/// array, so lane j of every result belongs to query lane_query[j].
struct Lanes {
    __m256d x, y;
};
constexpr int lane_query[4] = {0, 2, 1, 3};

[[gnu::target("avx2")]] inline Lanes load4(const Point2* p) {
    const __m256d v0 = _mm256_loadu_pd(&p[0].x);  // x0 y0 x1 y1
    const __m256d v1 = _mm256_loadu_pd(&p[2].x);  // x2 y2 x3 y3
    return {_mm256_unpacklo_pd(v0, v1), _mm256_unpackhi_pd(v0, v1)};
}

[[gnu::target("avx2")]] inline __m256d abs4(__m256d v) {
    return _mm256_andnot_pd(_mm256_set1_pd(-0.0), v);
}

/// Writes the four signs a filter decided (bits of `positive`, `negative` per lane) and
/// sends the undecided queries to `slow(k)`.
template <class Slow>
inline void write_signs(int positive, int negative, Sign* out, Slow slow) {
    for (int j = 0; j < 4; ++j) {
        const int k = lane_query[j];
        const int p = (positive >> j) & 1, n = (negative >> j) & 1;
        out[k] = (p | n) ? static_cast<Sign>(p - n) : slow(k);
    }
}

/// Stage A of adaptive.cpp's orient2d_impl, four queries at a time.
[[gnu::target("avx2")]] void orient2d_avx2(const Point2* a, const Point2* b, const Point2* c,
                                           Sign* out, std::size_t n) {
    const __m256d ccw_a = _mm256_set1_pd(eb::ccw_a);
    const __m256d underflow = _mm256_set1_pd(eb::underflow_orient);
    const __m256d sign_bit = _mm256_set1_pd(-0.0);
    for (std::size_t i = 0; i + 4 <= n; i += 4) {
        const Lanes pa = load4(a + i), pb = load4(b + i), pc = load4(c + i);
        const __m256d detleft = _mm256_mul_pd(_mm256_sub_pd(pa.x, pc.x), _mm256_sub_pd(pb.y, pc.y));
        const __m256d detright =
            _mm256_mul_pd(_mm256_sub_pd(pa.y, pc.y), _mm256_sub_pd(pb.x, pc.x));
        const __m256d det = _mm256_sub_pd(detleft, detright);
        const __m256d detsum = _mm256_add_pd(abs4(detleft), abs4(detright));
        const __m256d errbound = _mm256_add_pd(_mm256_mul_pd(ccw_a, detsum), underflow);
        const int positive = _mm256_movemask_pd(_mm256_cmp_pd(det, errbound, _CMP_GT_OQ));
        const int negative =
            _mm256_movemask_pd(_mm256_cmp_pd(_mm256_xor_pd(det, sign_bit), errbound, _CMP_GT_OQ));
        write_signs(positive, negative, out + i, [&](int k) {
            return detail::orient2d_unchecked(a[i + k], b[i + k], c[i + k]);
        });
    }
}

/// x x + y y and p q - r s, as the scalar expressions evaluate them.
[[gnu::target("avx2")]] inline __m256d lift(__m256d x, __m256d y) {
    return _mm256_add_pd(_mm256_mul_pd(x, x), _mm256_mul_pd(y, y));
}
[[gnu::target("avx2")]] inline __m256d cross(__m256d p, __m256d q, __m256d r, __m256d s) {
    return _mm256_sub_pd(_mm256_mul_pd(p, q), _mm256_mul_pd(r, s));
}

/// The semi-static filter of adaptive.cpp's incircle_impl, four queries at a time.
[[gnu::target("avx2")]] void incircle_avx2(const Point2* a, const Point2* b, const Point2* c,
                                           const Point2* d, Sign* out, std::size_t n) {
    const __m256d sign_bit = _mm256_set1_pd(-0.0);
    const __m256d lo = _mm256_set1_pd(eb::icc_static_min), hi = _mm256_set1_pd(eb::icc_static_max);
    const __m256d coefficient = _mm256_set1_pd(eb::icc_static);
    for (std::size_t i = 0; i + 4 <= n; i += 4) {
        const Lanes pa = load4(a + i), pb = load4(b + i), pc = load4(c + i), pd = load4(d + i);
        const __m256d adx = _mm256_sub_pd(pa.x, pd.x), ady = _mm256_sub_pd(pa.y, pd.y);
        const __m256d bdx = _mm256_sub_pd(pb.x, pd.x), bdy = _mm256_sub_pd(pb.y, pd.y);
        const __m256d cdx = _mm256_sub_pd(pc.x, pd.x), cdy = _mm256_sub_pd(pc.y, pd.y);
        const __m256d m = _mm256_max_pd(
            _mm256_max_pd(_mm256_max_pd(abs4(adx), abs4(ady)), _mm256_max_pd(abs4(bdx), abs4(bdy))),
            _mm256_max_pd(abs4(cdx), abs4(cdy)));
        // ((alift * bc + blift * ca) + clift * ab), as the scalar expression associates.
        const __m256d det =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(lift(adx, ady), cross(bdx, cdy, cdx, bdy)),
                                        _mm256_mul_pd(lift(bdx, bdy), cross(cdx, ady, adx, cdy))),
                          _mm256_mul_pd(lift(cdx, cdy), cross(adx, bdy, bdx, ady)));
        const __m256d m2 = _mm256_mul_pd(m, m);
        const __m256d bound = _mm256_mul_pd(coefficient, _mm256_mul_pd(m2, m2));
        const __m256d in_range =
            _mm256_and_pd(_mm256_cmp_pd(m, lo, _CMP_GE_OQ), _mm256_cmp_pd(m, hi, _CMP_LE_OQ));
        const int positive =
            _mm256_movemask_pd(_mm256_and_pd(in_range, _mm256_cmp_pd(det, bound, _CMP_GT_OQ)));
        const int negative = _mm256_movemask_pd(_mm256_and_pd(
            in_range, _mm256_cmp_pd(_mm256_xor_pd(det, sign_bit), bound, _CMP_GT_OQ)));
        write_signs(positive, negative, out + i, [&](int k) {
            return detail::incircle_unchecked(a[i + k], b[i + k], c[i + k], d[i + k]);
        });
    }
}

#endif

}  // namespace

namespace batch {

void orient2d(std::span<const Point2> a, std::span<const Point2> b, std::span<const Point2> c,
              std::span<Sign> out) {
    const std::size_t n = out.size();
    require_same_size(n, {a.size(), b.size(), c.size()}, "orient2d");
    run_in_standard_environment([&] {
        std::size_t done = 0;
#if EXIDEL_BATCH_AVX2
        if (detail::batch_use_avx2()) {
            orient2d_avx2(a.data(), b.data(), c.data(), out.data(), n);
            done = n - n % 4;
        }
#endif
        for (std::size_t i = done; i < n; ++i)
            out[i] = detail::orient2d_unchecked(a[i], b[i], c[i]);
    });
}

void incircle(std::span<const Point2> a, std::span<const Point2> b, std::span<const Point2> c,
              std::span<const Point2> d, std::span<Sign> out) {
    const std::size_t n = out.size();
    require_same_size(n, {a.size(), b.size(), c.size(), d.size()}, "incircle");
    run_in_standard_environment([&] {
        std::size_t done = 0;
#if EXIDEL_BATCH_AVX2
        if (detail::batch_use_avx2()) {
            incircle_avx2(a.data(), b.data(), c.data(), d.data(), out.data(), n);
            done = n - n % 4;
        }
#endif
        for (std::size_t i = done; i < n; ++i) {
            out[i] = detail::incircle_unchecked(a[i], b[i], c[i], d[i]);
        }
    });
}

void incircle_cosine(std::span<const Point2> a, std::span<const Point2> b,
                     std::span<const Point2> c, std::span<const Point2> d, std::span<Sign> out) {
    const std::size_t n = out.size();
    require_same_size(n, {a.size(), b.size(), c.size(), d.size()}, "incircle_cosine");
    run_in_standard_environment([&] {
        for (std::size_t i = 0; i < n; ++i) {
            out[i] = detail::incircle_cosine_unchecked(a[i], b[i], c[i], d[i]);
        }
    });
}

void compare_distance(std::span<const Point2> c, std::span<const Point2> p,
                      std::span<const Point2> q, std::span<Sign> out) {
    const std::size_t n = out.size();
    require_same_size(n, {c.size(), p.size(), q.size()}, "compare_distance");
    run_in_standard_environment([&] {
        for (std::size_t i = 0; i < n; ++i)
            out[i] = detail::compare_distance_unchecked(c[i], p[i], q[i]);
    });
}

const char* implementation() noexcept { return detail::batch_use_avx2() ? "avx2" : "scalar"; }

}  // namespace batch
}  // namespace exidel
