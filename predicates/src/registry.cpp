// exidel: kernels by name, from the one list in registry.hpp.
#include "exidel/predicates/registry.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <utility>

// No geometry here, but every translation unit of the library refuses -ffast-math
// (tests/hygiene builds each one with it).
#include "fp_hygiene.hpp"

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

struct Entry {
    std::string_view spelling, summary;
};
#define EXIDEL_KERNEL_ENTRY_(K, spelling, summary) Entry{spelling, summary},
constexpr Entry entries[] = {EXIDEL_KERNELS(EXIDEL_KERNEL_ENTRY_)};
#undef EXIDEL_KERNEL_ENTRY_

constexpr auto spellings = [] {
    std::array<char, 256> out{};
    std::size_t n = 0;
    for (const Entry& e : entries) {
        if (n > 0) out[n++] = '|';
        for (const char c : e.spelling) out[n++] = c;
    }
    return std::pair{out, n};
}();

}  // namespace

std::string_view kernel_spellings() noexcept {
    return {spellings.first.data(), spellings.second};
}

std::string kernel_help() {
    std::size_t width = 0;
    for (const Entry& e : entries) width = std::max(width, e.spelling.size());
    std::string out;
    for (const Entry& e : entries) {
        out += "  ";
        out += e.spelling;
        out.append(width + 2 - e.spelling.size(), ' ');
        out += e.summary;
        out += '\n';
    }
    return out;
}

std::optional<AnyKernel> parse_kernel(std::string_view name, std::string& error) {
    error.clear();
    std::optional<AnyKernel> found;
#define EXIDEL_KERNEL_PARSE_(K, spelling, summary)                        \
    if (!found && error.empty()) {                                        \
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
