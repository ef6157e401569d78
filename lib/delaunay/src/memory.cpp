// exidel: huge-page advice for large working arrays (detail/memory.hpp says why).
#include "exidel/delaunay/detail/memory.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace exidel::delaunay::detail {

void advise_huge_pages([[maybe_unused]] void* p, [[maybe_unused]] std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Below 4 MiB at most one aligned 2 MiB extent fits: not worth a system call.
    constexpr std::size_t min_bytes = std::size_t{4} << 20, page = 4096;
    if (p == nullptr || bytes < min_bytes) return;
    const auto begin = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t lo = (begin + page - 1) & ~(page - 1);
    const std::uintptr_t hi = (begin + bytes) & ~(page - 1);
    // The result is ignored on purpose: EINVAL (no THP support) leaves ordinary pages.
    (void)madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
#endif
}

}  // namespace exidel::delaunay::detail
