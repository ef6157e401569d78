// exidel: fresh memory for large arrays (detail/memory.hpp says why and which).
#include "exidel/delaunay/detail/memory.hpp"

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace exidel::delaunay::detail {

namespace {

std::atomic<std::size_t> mapped_bytes{0};
std::atomic<void (*)(std::size_t)> mapped_hook{nullptr};

void account(std::size_t total) noexcept {
    if (auto* hook = mapped_hook.load(std::memory_order_relaxed)) hook(total);
}

constexpr std::uintptr_t round_up(std::uintptr_t v, std::uintptr_t to) noexcept {
    return (v + to - 1) & ~(to - 1);
}

#if defined(__linux__) && defined(MADV_HUGEPAGE)
constexpr bool maps = true;
#else
constexpr bool maps = false;
#endif

}  // namespace

void* map_fresh(std::size_t bytes) {
    if (!maps || bytes < huge_page_bytes) return ::operator new(bytes == 0 ? 1 : bytes);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Map one huge page more than needed, keep the aligned part, return the rest: an
    // unaligned mapping would leave up to 2 MiB at each end in 4 KiB pages.
    const std::size_t size = round_up(bytes, huge_page_bytes);
    if (size < bytes || size + huge_page_bytes < size) throw std::bad_alloc();
    void* raw = mmap(nullptr, size + huge_page_bytes, PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const auto begin = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = round_up(begin, huge_page_bytes);
    if (aligned > begin) munmap(raw, aligned - begin);
    const std::uintptr_t tail = begin + size + huge_page_bytes - (aligned + size);
    if (tail > 0) munmap(reinterpret_cast<void*>(aligned + size), tail);
    // The result is ignored on purpose: EINVAL (no THP support) leaves ordinary pages.
    (void)madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);
    account(mapped_bytes.fetch_add(size, std::memory_order_relaxed) + size);
    return reinterpret_cast<void*>(aligned);
#endif
}

void unmap_fresh(void* p, std::size_t bytes) noexcept {
    if (p == nullptr) return;
    if (!maps || bytes < huge_page_bytes) {
        ::operator delete(p);
        return;
    }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const std::size_t size = round_up(bytes, huge_page_bytes);
    munmap(p, size);
    account(mapped_bytes.fetch_sub(size, std::memory_order_relaxed) - size);
#endif
}

std::size_t mapped_fresh_bytes() noexcept { return mapped_bytes.load(std::memory_order_relaxed); }

void set_mapped_fresh_hook(void (*hook)(std::size_t)) noexcept {
    mapped_hook.store(hook, std::memory_order_relaxed);
}

namespace {

// The transparent-huge-page mode, read once: the bracketed word of
// /sys/kernel/mm/transparent_hugepage/enabled ("always [madvise] never").
enum class ThpMode { always, madvise, never };

ThpMode read_thp_mode() noexcept {
    ThpMode mode = ThpMode::never;
    if (std::FILE* f = std::fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r")) {
        char line[128] = {};
        if (std::fgets(line, sizeof line, f) != nullptr) {
            if (std::strstr(line, "[always]") != nullptr) mode = ThpMode::always;
            if (std::strstr(line, "[madvise]") != nullptr) mode = ThpMode::madvise;
        }
        std::fclose(f);
    }
    return mode;
}

bool advises_output() noexcept {
    static const bool madvise_mode = read_thp_mode() == ThpMode::madvise;
    return madvise_mode;
}

// The whole 4 KiB pages of [p, p + bytes), given `advice`, when the range is large
// enough to hold a huge page and the mode is `madvise`.
void advise_pages([[maybe_unused]] void* p, [[maybe_unused]] std::size_t bytes,
                  [[maybe_unused]] int advice) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::size_t page = 4096;
    if (p == nullptr || bytes < huge_page_bytes || !advises_output()) return;
    const auto begin = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t lo = round_up(begin, page);
    const std::uintptr_t hi = (begin + bytes) & ~(page - 1);
    // The result is ignored on purpose: EINVAL (no THP support) leaves ordinary pages.
    (void)madvise(reinterpret_cast<void*>(lo), hi - lo, advice);
#endif
}

}  // namespace

void advise_huge_pages(void* p, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    advise_pages(p, bytes, MADV_HUGEPAGE);
#else
    (void)p, (void)bytes;
#endif
}

void settle_huge_pages(void* p, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_NOHUGEPAGE)
    advise_pages(p, bytes, MADV_NOHUGEPAGE);
#else
    (void)p, (void)bytes;
#endif
}

}  // namespace exidel::delaunay::detail
