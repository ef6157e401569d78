// exidel: algorithms by name, from the one list in algorithms.hpp.
#include "exidel/delaunay/algorithms.hpp"

#include <vector>

#include "exidel/predicates/registry.hpp"

namespace exidel::delaunay {

namespace {

#define EXIDEL_ALGORITHM_INFO_(name, spelling, Type, takes_order, summary) \
    AlgorithmInfo{Algorithm::name, spelling, takes_order, summary},
constexpr AlgorithmInfo table[] = {EXIDEL_DELAUNAY_ALGORITHMS(EXIDEL_ALGORITHM_INFO_)};
#undef EXIDEL_ALGORITHM_INFO_

std::vector<HelpEntry> help_entries() {
    std::vector<HelpEntry> out;
    for (const AlgorithmInfo& a : table) out.push_back({a.name, a.summary});
    return out;
}

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

std::string algorithm_spellings() { return join_names(help_entries()); }

std::string algorithm_help() { return format_help(help_entries()); }

}  // namespace exidel::delaunay
