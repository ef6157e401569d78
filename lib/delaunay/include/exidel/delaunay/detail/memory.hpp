// exidel: large working arrays in fresh memory, backed by transparent huge pages.
//
// Why: on the project's machines the first write to a fresh 4 KiB page costs far more than
// the write itself (a page fault; about 2.5 ms per MB, against 0.03 ms per MB for the
// same memory written a second time; docs/measurements.md, "Fresh memory"). A
// triangulation of n points fills about 90 n bytes of arrays that malloc serves from new
// mappings, so a one-shot triangulation of 10^6 points spent a quarter of its time in the
// kernel's page-fault path. With madvise(MADV_HUGEPAGE) on the range before it is
// touched, the kernel backs it with 2 MiB pages where it can: 512 times fewer faults.
// Linux with transparent huge pages in `madvise` or `always` mode; elsewhere, or when the
// kernel says no, the advice changes nothing and the arrays are ordinary memory.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

namespace exidel::delaunay::detail {

/// Advises the kernel to back the whole 4 KiB pages inside [p, p + bytes) with huge pages.
/// Ranges below one huge page (2 MiB) are left alone. Never fails: it is only advice.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;

/// Makes room for n elements in v. When v must grow, it is reallocated to exactly n and
/// the new memory is advised (advise_huge_pages) before anything touches it.
template <class T>
void reserve_fresh(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) {
        std::vector<T>().swap(v);
        v.reserve(n);
        advise_huge_pages(v.data(), n * sizeof(T));
    }
}

/// v becomes n copies of `value`, in memory from reserve_fresh.
template <class T>
void assign_fresh(std::vector<T>& v, std::size_t n, const T& value) {
    reserve_fresh(v, n);
    v.assign(n, value);
}

/// v becomes n value-initialised elements, in memory from reserve_fresh (for arrays whose
/// every element is written before it is read: std::vector cannot skip the fill).
template <class T>
void resize_fresh(std::vector<T>& v, std::size_t n) {
    reserve_fresh(v, n);
    v.assign(n, T{});
}

/// n uninitialised elements of a trivial type, advised (advise_huge_pages): for internal
/// arrays written before they are read, where a std::vector would zero-fill first.
template <class T>
std::unique_ptr<T[]> allocate_fresh(std::size_t n) {
    static_assert(std::is_trivially_default_constructible_v<T>);
    std::unique_ptr<T[]> p(new T[n]);  // default-initialised: no fill
    advise_huge_pages(p.get(), n * sizeof(T));
    return p;
}

}  // namespace exidel::delaunay::detail
