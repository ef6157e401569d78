// exidel bench: the timed loop of the predicate benchmarks (predicates_bench.cpp,
// predicates3d_bench.cpp).
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace exidel::bench {

/// One call per iteration, cycling through an array of pre-generated queries (its size a
/// power of two), so that branch predictors and caches see the array, not one repeated
/// query. The signs are summed into benchmark::DoNotOptimize, so no call can be dropped.
template <class Query, class Call>
void cycle(benchmark::State& state, const std::vector<Query>& queries, Call call) {
    const std::size_t mask = queries.size() - 1;
    std::size_t i = 0;
    int sum = 0;
    for (auto _ : state) {
        sum += call(queries[i]);
        i = (i + 1) & mask;
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

}  // namespace exidel::bench
