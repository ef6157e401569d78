// exidel: input validation, lexicographic sort and duplicate removal.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>
#include <string>

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
    }
    return "unknown";
}

namespace detail {

namespace {

// Decided on the bits, so the answer does not depend on the caller's -ffinite-math-only.
bool finite(double v) noexcept {
    constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
    return (std::bit_cast<std::uint64_t>(v) & exponent) != exponent;
}

struct Keyed {
    Point2 p;
    std::uint32_t index;
};

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
    std::vector<Keyed> keyed(input.size());
    for (std::size_t i = 0; i < input.size(); ++i) {
        keyed[i] = {input[i], static_cast<std::uint32_t>(i)};
    }
    // The index breaks ties, so the first occurrence of a repeated point comes first.
    std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
        if (a.p.x != b.p.x) return a.p.x < b.p.x;
        if (a.p.y != b.p.y) return a.p.y < b.p.y;
        return a.index < b.index;
    });
    out.points.clear();
    out.input_of.clear();
    out.duplicates.clear();
    out.vertex_of_input.assign(input.size(), 0);
    for (std::size_t j = 0; j < keyed.size(); ++j) {
        // == treats -0.0 and +0.0 as the same point, as every predicate does.
        if (j > 0 && keyed[j].p == keyed[j - 1].p) {
            out.vertex_of_input[keyed[j].index] = out.input_of.back();
            out.duplicates.push_back(keyed[j].index);
            continue;
        }
        out.points.push_back(keyed[j].p);
        out.input_of.push_back(keyed[j].index);
        out.vertex_of_input[keyed[j].index] = keyed[j].index;
    }
    std::sort(out.duplicates.begin(), out.duplicates.end());
    return std::nullopt;
}

}  // namespace detail

}  // namespace exidel::delaunay
