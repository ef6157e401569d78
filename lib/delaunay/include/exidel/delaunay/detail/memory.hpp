// exidel: large working arrays in fresh memory, backed by transparent huge pages.
//
// Why: on the project's machines the first write to a fresh 4 KiB page costs far more than
// the write itself (a page fault; about 2.5 ms per MB, against 0.03 ms per MB for the
// same memory written a second time; docs/measurements.md, "Fresh memory"). A
// triangulation of n points fills about 90 n bytes of arrays, so a one-shot triangulation
// of 10^6 points spent a quarter of its time in the kernel's page-fault path. With
// madvise(MADV_HUGEPAGE) on a range before it is touched, the kernel backs it with 2 MiB
// pages where it can: 512 times fewer faults. Linux with transparent huge pages in
// `madvise` or `always` mode; elsewhere, or when the kernel says no, the advice changes
// nothing and the arrays are ordinary memory.
//
// Two kinds of arrays, two tools:
//   internal arrays (the sort's records, the sorted points, the compaction's map, the
//       mesh's hull lists, ...) live in FreshVector / FreshBuffer: each large one is a
//       mapping of its own, aligned to 2 MiB so that every page of it can be a huge page,
//       and unmapped when freed, so that neither its pages nor its advice stay behind in
//       the caller's heap. (Advice given to memory malloc hands out outlives the array:
//       a freed range that malloc keeps carries it, and the caller's later allocations
//       there get huge pages they did not ask for; issue 17 measured CGAL 9-21% slower
//       after an exidel run in the same process when every array was advised that way.)
//   output arrays (the Triangulation's std::vectors, which the caller owns and frees)
//       come from operator new, and whether freeing them returns their pages is the
//       caller's allocator's business. Where transparent huge pages are in `madvise`
//       mode they are advised before they are touched (reserve_fresh & co.) and settled
//       (settle_huge_pages) once the triangulation is written: MADV_NOHUGEPAGE, which in
//       that mode means for later faults in the range what no advice means (no huge
//       pages unless asked for), so whatever the caller's allocator does with the range
//       afterwards behaves as if exidel had never advised it. In `always` mode the kernel
//       uses huge pages without advice, and none is given; in `never` mode neither.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace exidel::delaunay::detail {

/// Arrays below this many bytes are left to malloc and never advised: no aligned huge
/// page fits in less than 2 MiB.
inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

/// `bytes` of fresh memory for an internal array: from huge_page_bytes up, a mapping of
/// its own, aligned to huge_page_bytes and advised to use huge pages; below, operator
/// new. Throws std::bad_alloc when the memory is not there.
void* map_fresh(std::size_t bytes);
/// Frees what map_fresh(bytes) returned (the same `bytes`); a mapping is unmapped.
void unmap_fresh(void* p, std::size_t bytes) noexcept;

/// Bytes of map_fresh's own mappings live now (what the program's operator new does not
/// see). For memory accounting in benchmarks and tests.
std::size_t mapped_fresh_bytes() noexcept;
/// Called with the new total after every map_fresh mapping and unmapping (nullptr: no
/// call). For a benchmark that records the peak of heap plus mappings; set it before
/// any triangulation runs.
void set_mapped_fresh_hook(void (*hook)(std::size_t total)) noexcept;

/// A standard allocator over map_fresh: std::vector<T, FreshAllocator<T>> is an internal
/// array in memory of its own (see above).
template <class T>
struct FreshAllocator {
    using value_type = T;
    FreshAllocator() = default;
    template <class U>
    FreshAllocator(const FreshAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_alloc();
        return static_cast<T*>(map_fresh(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept { unmap_fresh(p, n * sizeof(T)); }
    template <class U>
    bool operator==(const FreshAllocator<U>&) const noexcept {
        return true;
    }
};

template <class T>
using FreshVector = std::vector<T, FreshAllocator<T>>;

/// n uninitialised elements of a trivial type in map_fresh memory, for internal arrays
/// written before they are read (a std::vector would zero-fill them first).
template <class T>
class FreshBuffer {
    static_assert(std::is_trivially_default_constructible_v<T> &&
                  std::is_trivially_destructible_v<T>);

public:
    FreshBuffer() = default;
    explicit FreshBuffer(std::size_t n) : p_(FreshAllocator<T>().allocate(n)), n_(n) {}
    FreshBuffer(FreshBuffer&& o) noexcept
        : p_(std::exchange(o.p_, nullptr)), n_(std::exchange(o.n_, 0)) {}
    FreshBuffer& operator=(FreshBuffer&& o) noexcept {
        std::swap(p_, o.p_);
        std::swap(n_, o.n_);
        return *this;
    }
    ~FreshBuffer() {
        if (p_ != nullptr) FreshAllocator<T>().deallocate(p_, n_);
    }
    T* get() const noexcept { return p_; }
    std::size_t size() const noexcept { return n_; }

private:
    T* p_ = nullptr;
    std::size_t n_ = 0;
};

/// For an output array (see above): in `madvise` mode, advises the kernel to back the
/// whole 4 KiB pages inside [p, p + bytes) with huge pages; otherwise, or below
/// huge_page_bytes, nothing. Never fails: it is only advice.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;
/// Undoes advise_huge_pages(p, bytes) for the range's later faults (see above); call it
/// once the array is written. The huge pages it already has stay.
void settle_huge_pages(void* p, std::size_t bytes) noexcept;

/// settle_huge_pages over v's whole capacity.
template <class T>
void settle_huge_pages(std::vector<T>& v) noexcept {
    settle_huge_pages(v.data(), v.capacity() * sizeof(T));
}

/// Makes room for n elements in v, an array that may leave the library (the
/// Triangulation's). When v must grow, it is reallocated to exactly n and the new memory
/// is advised (advise_huge_pages) before anything touches it.
template <class T>
void reserve_fresh(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) {
        std::vector<T>().swap(v);
        v.reserve(n);
        advise_huge_pages(v.data(), n * sizeof(T));
    }
}

/// Makes room for n elements in an internal array (its memory is fresh already).
template <class T>
void reserve_fresh(FreshVector<T>& v, std::size_t n) {
    if (v.capacity() < n) {
        FreshVector<T>().swap(v);
        v.reserve(n);
    }
}

/// v becomes n copies of `value`, in memory from reserve_fresh.
template <class V, class T>
void assign_fresh(V& v, std::size_t n, const T& value) {
    reserve_fresh(v, n);
    v.assign(n, value);
}

/// v becomes n value-initialised elements, in memory from reserve_fresh (for arrays whose
/// every element is written before it is read: std::vector cannot skip the fill).
template <class V>
void resize_fresh(V& v, std::size_t n) {
    reserve_fresh(v, n);
    v.assign(n, typename V::value_type{});
}

}  // namespace exidel::delaunay::detail
