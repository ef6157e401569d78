// exidel CLI (internal): kernel names to kernel objects.
#include "kernel_option.hpp"

#include <charconv>

namespace exidel::cli {

std::optional<AnyKernel> parse_kernel(std::string_view name, std::string& error) {
    if (name == DoubleKernel::name()) return AnyKernel{DoubleKernel{}};
    if (name == LongDoubleKernel::name()) return AnyKernel{LongDoubleKernel{}};
    if (name == AdaptiveKernel::name()) return AnyKernel{AdaptiveKernel{}};
    if (name == GmpExactKernel::name()) return AnyKernel{GmpExactKernel{}};
    if (name == CppIntExactKernel::name()) return AnyKernel{CppIntExactKernel{}};
    constexpr std::string_view mpfr_prefix = "mpfr:";
    if (name.starts_with(mpfr_prefix)) {
        const std::string_view digits = name.substr(mpfr_prefix.size());
        unsigned bits = 0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), bits);
        if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size() ||
            bits < MpfrKernel::min_bits || bits > MpfrKernel::max_bits) {
            error = "mpfr precision must be an integer number of bits in [" +
                    std::to_string(MpfrKernel::min_bits) + ", " +
                    std::to_string(MpfrKernel::max_bits) + "], got '" + std::string(digits) + "'";
            return std::nullopt;
        }
        return AnyKernel{MpfrKernel(bits)};
    }
    error = "unknown kernel '" + std::string(name) + "' (expected " + std::string(kernel_names) +
            ")";
    return std::nullopt;
}

}  // namespace exidel::cli
