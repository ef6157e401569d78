// exidel bench: the wall-clock helpers the one-process benchmarks share.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace exidel::bench {

using Clock = std::chrono::steady_clock;

inline double ms(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

/// The median of the runs (the machines are shared: medians, not minima).
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

}  // namespace exidel::bench
