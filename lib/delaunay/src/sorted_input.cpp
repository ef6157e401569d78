// exidel: input validation, lexicographic sort and duplicate removal.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>
#include <string>

#include "exidel/delaunay/detail/radix.hpp"
#include "exidel/delaunay/result.hpp"

namespace exidel::delaunay {

std::string_view to_string(FailureKind kind) noexcept {
    switch (kind) {
        case FailureKind::non_finite_input: return "non_finite_input";
        case FailureKind::too_many_points: return "too_many_points";
        case FailureKind::no_visible_edge: return "no_visible_edge";
        case FailureKind::hull_walk_exceeded: return "hull_walk_exceeded";
        case FailureKind::erosion_inconsistent: return "erosion_inconsistent";
        case FailureKind::erosion_exceeded: return "erosion_exceeded";
        case FailureKind::point_inside_hull: return "point_inside_hull";
        case FailureKind::merge_inconsistent: return "merge_inconsistent";
        case FailureKind::result_inconsistent: return "result_inconsistent";
        case FailureKind::unknown_algorithm: return "unknown_algorithm";
        case FailureKind::location_exceeded: return "location_exceeded";
        case FailureKind::cavity_inconsistent: return "cavity_inconsistent";
        case FailureKind::flips_exceeded: return "flips_exceeded";
    }
    return "unknown";
}

std::string_view to_string(Strategy strategy) noexcept {
    switch (strategy) {
        case Strategy::automatic: return "automatic";
        case Strategy::lexicographic: return "lexicographic";
        case Strategy::radial: return "radial";
        case Strategy::strips: return "strips";
    }
    return "unknown";
}

Counters& Counters::operator+=(const Counters& o) noexcept {
#define EXIDEL_DELAUNAY_COUNTER_ADD(name) name += o.name;
    EXIDEL_DELAUNAY_COUNTERS(EXIDEL_DELAUNAY_COUNTER_ADD)
#undef EXIDEL_DELAUNAY_COUNTER_ADD
    return *this;
}

namespace detail {

namespace {

// Decided on the bits, so the answer does not depend on the caller's -ffinite-math-only.
bool finite(double v) noexcept {
    constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
    return (std::bit_cast<std::uint64_t>(v) & exponent) != exponent;
}

}  // namespace

std::optional<Failure> sort_and_dedupe(std::span<const Point2> input, SortedInput& out) {
    for (std::size_t i = 0; i < input.size(); ++i) {
        if (!finite(input[i].x) || !finite(input[i].y)) {
            return Failure{FailureKind::non_finite_input, i, no_index,
                           "input point " + std::to_string(i) + " has a non-finite coordinate"};
        }
    }
    if (input.size() > max_points) {
        return Failure{FailureKind::too_many_points, no_index, no_index,
                       std::to_string(input.size()) + " points, at most " +
                           std::to_string(max_points) + " are supported"};
    }
    // Lexicographic order, ties by index (so the first occurrence of a repeated point
    // comes first): a stable radix sort by x of records in index order, then each run of
    // equal x (rare but for grids) sorted by (y, index).
    std::vector<KeyIndex> sorted(input.size());
    for (std::size_t i = 0; i < input.size(); ++i) {
        sorted[i] = {order_key(input[i].x), static_cast<std::uint32_t>(i)};
    }
    radix_sort(sorted);
    for (std::size_t lo = 0; lo < sorted.size();) {
        std::size_t hi = lo + 1;
        while (hi < sorted.size() && sorted[hi].key == sorted[lo].key) ++hi;
        if (hi - lo > 1) {
            std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(lo),
                      sorted.begin() + static_cast<std::ptrdiff_t>(hi),
                      [&](const KeyIndex& a, const KeyIndex& b) {
                          const double ya = input[a.index].y, yb = input[b.index].y;
                          return ya != yb ? ya < yb : a.index < b.index;
                      });
        }
        lo = hi;
    }
    out.points.clear();
    out.input_of.clear();
    out.duplicates.clear();
    out.vertex_of_input.assign(input.size(), 0);
    out.points.reserve(input.size());
    out.input_of.reserve(input.size());
    for (std::size_t j = 0; j < sorted.size(); ++j) {
        const std::uint32_t i = sorted[j].index;
        const Point2 p = input[i];
        // == treats -0.0 and +0.0 as the same point, as every predicate does.
        if (j > 0 && p == input[sorted[j - 1].index]) {
            out.vertex_of_input[i] = out.input_of.back();
            out.duplicates.push_back(i);
            continue;
        }
        out.points.push_back(p);
        out.input_of.push_back(i);
        out.vertex_of_input[i] = i;
    }
    std::sort(out.duplicates.begin(), out.duplicates.end());
    return std::nullopt;
}

}  // namespace detail

}  // namespace exidel::delaunay
