// exidel: algorithms by name, from the one list in algorithms.hpp.
#include "exidel/delaunay/algorithms.hpp"

#include <algorithm>

namespace exidel::delaunay {

namespace {

#define EXIDEL_ALGORITHM_INFO_(name, Type, takes_order, summary) \
    AlgorithmInfo{Algorithm::name, #name, takes_order, summary},
constexpr AlgorithmInfo table[] = {EXIDEL_DELAUNAY_ALGORITHMS(EXIDEL_ALGORITHM_INFO_)};
#undef EXIDEL_ALGORITHM_INFO_

}  // namespace

std::span<const AlgorithmInfo> algorithms() noexcept { return table; }

std::string_view to_string(Algorithm algorithm) noexcept {
    for (const AlgorithmInfo& a : table) {
        if (a.id == algorithm) return a.name;
    }
    return "unknown";
}

std::optional<Algorithm> algorithm_from_name(std::string_view name) noexcept {
    for (const AlgorithmInfo& a : table) {
        if (a.name == name) return a.id;
    }
    return std::nullopt;
}

std::string algorithm_spellings() {
    std::string out;
    for (const AlgorithmInfo& a : table) {
        if (!out.empty()) out += '|';
        out += a.name;
    }
    return out;
}

std::string algorithm_help() {
    std::size_t width = 0;
    for (const AlgorithmInfo& a : table) width = std::max(width, a.name.size());
    std::string out;
    for (const AlgorithmInfo& a : table) {
        out += "  ";
        out += a.name;
        out.append(width + 2 - a.name.size(), ' ');
        out += a.summary;
        out += '\n';
    }
    return out;
}

}  // namespace exidel::delaunay
