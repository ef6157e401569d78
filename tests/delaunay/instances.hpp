// The triangulations the tests of this directory instantiate themselves, compiled once
// (instances_*.cpp, the library exidel_delaunay_test_instances) instead of in every test
// file that runs them: the library compiles Instrumentation::off and counters for the
// registry's kernels, never theorem1 nor a test's own kernel. Each of these is every
// algorithm's body over one kernel; before they were shared, six test files compiled the
// two theorem1 ones, about half of the tests' build time.
#pragma once

#include <span>

#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/exact.hpp"
#include "lying_kernel.hpp"

// `prefix` is `template` (instances_*.cpp) or `extern template` (every other file).
#define EXIDEL_TEST_TRIANGULATE_(prefix, I, K)                                          \
    namespace exidel::delaunay {                                                        \
    prefix Result triangulate<Instrumentation::I, K>(std::span<const Point2>, const K&, \
                                                     const Options&);                   \
    }
#define EXIDEL_TEST_THEOREM1_ADAPTIVE(prefix) \
    EXIDEL_TEST_TRIANGULATE_(prefix, theorem1, exidel::AdaptiveKernel)
#define EXIDEL_TEST_THEOREM1_GMP(prefix) \
    EXIDEL_TEST_TRIANGULATE_(prefix, theorem1, exidel::GmpExactKernel)
#define EXIDEL_TEST_LYING(prefix) EXIDEL_TEST_TRIANGULATE_(prefix, off, exidel::test::LyingKernel)

EXIDEL_TEST_THEOREM1_ADAPTIVE(extern template)
EXIDEL_TEST_THEOREM1_GMP(extern template)
EXIDEL_TEST_LYING(extern template)
