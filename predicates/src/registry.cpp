// exidel: kernels by name, from the one list in registry.hpp.
#include "exidel/predicates/registry.hpp"

#include <algorithm>
#include <charconv>
#include <utility>

// No geometry here, but every translation unit of the library refuses -ffast-math
// (tests/hygiene builds each one with it).
#include "exidel/predicates/internal/fp_hygiene.hpp"

namespace exidel {

namespace {

// A kernel without parameters is spelled by its name().
template <class K>
std::optional<K> make_kernel(std::string_view name, std::string&) {
    if (name == K::name()) return K{};
    return std::nullopt;
}

template <>
std::optional<MpfrKernel> make_kernel<MpfrKernel>(std::string_view name, std::string& error) {
    constexpr std::string_view prefix = "mpfr:";
    if (!name.starts_with(prefix)) return std::nullopt;
    const std::string_view digits = name.substr(prefix.size());
    unsigned bits = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), bits);
    if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size() ||
        bits < MpfrKernel::min_bits || bits > MpfrKernel::max_bits) {
        error = "mpfr precision must be an integer number of bits in [" +
                std::to_string(MpfrKernel::min_bits) + ", " + std::to_string(MpfrKernel::max_bits) +
                "], got '" + std::string(digits) + "'";
        return std::nullopt;
    }
    return MpfrKernel(bits);
}

#define EXIDEL_KERNEL_ENTRY_(K, spelling, summary) HelpEntry{spelling, summary},
constexpr HelpEntry entries[] = {EXIDEL_KERNELS(EXIDEL_KERNEL_ENTRY_)};
#undef EXIDEL_KERNEL_ENTRY_

}  // namespace

std::string format_help(std::span<const HelpEntry> list) {
    std::size_t width = 0;
    for (const HelpEntry& e : list) width = std::max(width, e.name.size());
    std::string out;
    for (const HelpEntry& e : list) {
        out += "  ";
        out += e.name;
        out.append(width + 2 - e.name.size(), ' ');
        out += e.summary;
        out += '\n';
    }
    return out;
}

std::string join_names(std::span<const HelpEntry> list) {
    std::string out;
    for (const HelpEntry& e : list) {
        if (!out.empty()) out += '|';
        out += e.name;
    }
    return out;
}

std::string kernel_spellings() { return join_names(entries); }

std::string kernel_help() { return format_help(entries); }

std::optional<AnyKernel> parse_kernel(std::string_view name, std::string& error) {
    error.clear();
    std::optional<AnyKernel> found;
#define EXIDEL_KERNEL_PARSE_(K, spelling, summary)                              \
    if (!found && error.empty()) {                                              \
        if (auto k = make_kernel<K>(name, error)) found.emplace(std::move(*k)); \
    }
    EXIDEL_KERNELS(EXIDEL_KERNEL_PARSE_)
#undef EXIDEL_KERNEL_PARSE_
    if (!found && error.empty()) {
        error = "unknown kernel '" + std::string(name) + "' (expected " +
                std::string(kernel_spellings()) + ")";
    }
    return found;
}

std::string kernel_name(const AnyKernel& kernel) {
    return std::visit([](const auto& k) { return std::string(k.name()); }, kernel);
}

bool kernel_is_exact(const AnyKernel& kernel) noexcept {
    return std::visit([](const auto& k) { return std::decay_t<decltype(k)>::is_exact; }, kernel);
}

}  // namespace exidel
