// exidel: huge-page advice for large working arrays (detail/memory.hpp says why).
#include "exidel/delaunay/detail/memory.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace exidel::delaunay::detail {

void advise_huge_pages([[maybe_unused]] void* p, [[maybe_unused]] std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Below 2 MiB no aligned huge page fits (from 2 to 4 MiB, one at most: the 4 MB
    // arrays of 10^6 indices get one or two).
    constexpr std::size_t min_bytes = std::size_t{2} << 20, page = 4096;
    if (p == nullptr || bytes < min_bytes) return;
    const auto begin = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t lo = (begin + page - 1) & ~(page - 1);
    const std::uintptr_t hi = (begin + bytes) & ~(page - 1);
    // The result is ignored on purpose: EINVAL (no THP support) leaves ordinary pages.
    (void)madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
#endif
}

}  // namespace exidel::delaunay::detail
