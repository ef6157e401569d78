// exidel: the one list of predicate kernels.
//
// EXIDEL_KERNELS(X) expands X(Type, "spelling", "summary") once per shipped kernel, in the
// order help texts list them. Everything that enumerates kernels derives from it:
//   - AnyKernel, a std::variant of every kernel (the CLI, the research studies, Python);
//   - parse_kernel / kernel_spellings / kernel_help, the names on every command line;
//   - the explicit instantiations of the algorithms in lib/ (compiled once, in the
//     library's own translation units with its floating-point flags, never in a user's;
//     lib/delaunay/CMakeLists.txt generates them from this list).
// A new kernel (docs/architecture.md, "Adding a kernel"):
//   1. a header and source in predicates/ with a type satisfying PredicateKernel (and
//      PredicateKernel3D if it decides orient3d and insphere: kernel.hpp), every member
//      a predicate of the lists in predicate.hpp;
//   2. one line here;
//   3. if it claims exactness, its name in ExactKernels (tests/support/
//      kernels_under_test.hpp; a static_assert there fails until it is);
//   4. if its predicates are slow (big numbers), one line in
//      EXIDEL_DELAUNAY_DYNAMIC_KERNELS (lib/delaunay/.../triangulate.hpp), so that the
//      triangulation is not compiled once more for it.
//
// A spelling is what K::name() returns; a kernel with a parameter writes it in angle
// brackets ("mpfr:<bits>") and provides a make_kernel overload below that parses it.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/floating.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/mpfr.hpp"

// clang-format off
#define EXIDEL_KERNELS(X)                                                                      \
    X(DoubleKernel, "double",                                                                  \
      "the textbook formulas in double: fast, wrong near degeneracy")                          \
    X(LongDoubleKernel, "long-double",                                                         \
      "the same formulas in x87 long double (64-bit significand): wrong less often")           \
    X(AdaptiveKernel, "adaptive",                                                              \
      "Shewchuk-style filters, then adaptive expansions, then exact: exact, the fastest")      \
    X(GmpExactKernel, "exact",                                                                 \
      "exponent-aligned GMP integers: exact, the reference")                                   \
    X(CppIntExactKernel, "exact-cpp",                                                          \
      "exponent-aligned Boost cpp_int integers: exact, header-only arithmetic")                \
    X(MpfrKernel, "mpfr:<bits>",                                                               \
      "the textbook formulas with every operation rounded to <bits> bits (MPFR)")
// clang-format on

namespace exidel {

namespace detail {
// Builds a type list from the X-macro: Types<> + Types<A> + Types<B> ... = Types<A, B, ...>.
template <class... Ks>
struct Types {
    template <template <class...> class T>
    using apply = T<Ks...>;
};
template <class... A, class B>
Types<A..., B> operator+(Types<A...>, Types<B>);
#define EXIDEL_KERNEL_TYPE_(K, spelling, summary) \
    +Types<K> {                                   \
    }
using KernelTypes = decltype(Types<> {} EXIDEL_KERNELS(EXIDEL_KERNEL_TYPE_));
#undef EXIDEL_KERNEL_TYPE_
}  // namespace detail

/// Any shipped kernel, chosen at run time (std::visit once per batch of queries, so the
/// inner loop is compiled per kernel type and no per-query dispatch remains).
using AnyKernel = detail::KernelTypes::apply<std::variant>;

/// An entry of a registry (kernels here, algorithms in lib/delaunay) as help texts show it.
struct HelpEntry {
    std::string_view name, summary;
};
/// "  <name>  <summary>\n" per entry, the names padded to one column.
std::string format_help(std::span<const HelpEntry> entries);
/// The names joined by '|'.
std::string join_names(std::span<const HelpEntry> entries);

/// "double|long-double|adaptive|exact|exact-cpp|mpfr:<bits>", for usage lines.
std::string kernel_spellings();

/// One line per kernel, "  <spelling>  <summary>", for --help texts.
std::string kernel_help();

/// The kernel a name spells (what its name() returns; MPFR as "mpfr:<bits>" with bits
/// in [MpfrKernel::min_bits, MpfrKernel::max_bits]). On failure: nullopt, and `error`
/// says why in a sentence that names the accepted spellings.
std::optional<AnyKernel> parse_kernel(std::string_view name, std::string& error);

/// The name of the kernel held (its name(); parse_kernel accepts it back).
std::string kernel_name(const AnyKernel& kernel);

/// Whether the kernel held claims exactness (K::is_exact).
bool kernel_is_exact(const AnyKernel& kernel) noexcept;

}  // namespace exidel
