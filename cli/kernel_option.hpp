// exidel CLI (internal): the `--kernel NAME` option shared by every subcommand.
//
// The kernel is chosen once per run and held in a variant; a subcommand calls std::visit
// once with a generic lambda, so its inner loop is compiled per kernel type (the
// PredicateKernel concept) and no per-query virtual call or branch on the kernel remains.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "exidel/predicates/all.hpp"

namespace exidel::cli {

using AnyKernel = std::variant<DoubleKernel, LongDoubleKernel, AdaptiveKernel,
                               GmpExactKernel, CppIntExactKernel, MpfrKernel>;

/// The spellings accepted by parse_kernel, for help texts.
inline constexpr std::string_view kernel_names =
    "double|long-double|adaptive|exact|exact-cpp|mpfr:<bits>";

/// Parses a kernel name (the strings kernel's name() returns; MPFR as "mpfr:<bits>" with
/// bits in [MpfrKernel::min_bits, MpfrKernel::max_bits]). On failure returns nullopt and
/// sets `error`.
std::optional<AnyKernel> parse_kernel(std::string_view name, std::string& error);

}  // namespace exidel::cli
