// exidel: any kernel behind one type, each predicate an indirect call.
//
// Code templated on the kernel is compiled once per kernel type. For kernels whose
// predicates cost hundreds of nanoseconds (exact integers, MPFR), one indirect call more
// is lost in the noise, and compiling that code once for all of them instead of once
// each saves most of a build: exidel::delaunay runs the triangulation of the exact and
// MPFR kernels through DynamicKernel (triangulate.hpp), and the research studies run
// every kernel through it.
//
// A DynamicKernel refers to a kernel it does not own: the kernel must outlive it. Its
// answers are the kernel's, call for call. Its members are generated from the lists of
// predicate.hpp; those of space exist only when the kernel has them (has_space()), and
// calling one of a kernel without them is a precondition violation (it throws
// std::logic_error).
#pragma once

#include <stdexcept>
#include <string>

#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/predicate.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel {

class DynamicKernel {
public:
    /// Not exact as a type: the kernel behind it may or may not be (is_exact() says).
    static constexpr bool is_exact = false;

    template <PredicateKernel K>
    explicit DynamicKernel(const K& kernel) : kernel_(&kernel), table_(&table_for<K>) {}

    std::string name() const { return table_->name(kernel_); }
    /// Whether the kernel behind it is exact (K::is_exact).
    bool exact() const { return table_->exact; }
    /// Whether the kernel behind it has the predicates of space.
    bool has_space() const { return table_->space; }

#define EXIDEL_DYNAMIC_MEMBER_(name, points, arguments, summary)       \
    Sign name(EXIDEL_PREDICATE_PARAMETERS_##points(Point2)) const {    \
        return table_->name(kernel_, EXIDEL_PREDICATE_NAMES_##points); \
    }
    EXIDEL_PREDICATES(EXIDEL_DYNAMIC_MEMBER_)
#define EXIDEL_DYNAMIC_SPACE_MEMBER_(name, points, arguments, summary) \
    Sign name(EXIDEL_PREDICATE_PARAMETERS_##points(Point3)) const {    \
        return table_->name(kernel_, EXIDEL_PREDICATE_NAMES_##points); \
    }
    EXIDEL_SPACE_PREDICATES(EXIDEL_DYNAMIC_SPACE_MEMBER_)
#undef EXIDEL_DYNAMIC_SPACE_MEMBER_
#undef EXIDEL_DYNAMIC_MEMBER_

private:
    struct Table {
        std::string (*name)(const void*);
        bool exact;
        bool space;
#define EXIDEL_DYNAMIC_SLOT_(name, points, arguments, summary) \
    Sign (*name)(const void*, EXIDEL_PREDICATE_PARAMETERS_##points(Point2));
        EXIDEL_PREDICATES(EXIDEL_DYNAMIC_SLOT_)
#undef EXIDEL_DYNAMIC_SLOT_
#define EXIDEL_DYNAMIC_SPACE_SLOT_(name, points, arguments, summary) \
    Sign (*name)(const void*, EXIDEL_PREDICATE_PARAMETERS_##points(Point3));
        EXIDEL_SPACE_PREDICATES(EXIDEL_DYNAMIC_SPACE_SLOT_)
#undef EXIDEL_DYNAMIC_SPACE_SLOT_
    };

    template <PredicateKernel K>
    static constexpr Table table_for{
        [](const void* k) -> std::string { return static_cast<const K*>(k)->name(); }, K::is_exact,
        has_3d_predicates<K>,
#define EXIDEL_DYNAMIC_ENTRY_(name, points, arguments, summary)                 \
    [](const void* k, EXIDEL_PREDICATE_PARAMETERS_##points(Point2)) {           \
        return static_cast<const K*>(k)->name(EXIDEL_PREDICATE_NAMES_##points); \
    },
        EXIDEL_PREDICATES(EXIDEL_DYNAMIC_ENTRY_)
#undef EXIDEL_DYNAMIC_ENTRY_
#define EXIDEL_DYNAMIC_SPACE_ENTRY_(name, points, arguments, summary)                          \
    [](const void* k, EXIDEL_PREDICATE_PARAMETERS_##points([[maybe_unused]] Point3)) -> Sign { \
        if constexpr (has_3d_predicates<K>) {                                                  \
            return static_cast<const K*>(k)->name(EXIDEL_PREDICATE_NAMES_##points);            \
        } else {                                                                               \
            (void)k;                                                                           \
            throw std::logic_error("the kernel has no predicates of space");                   \
        }                                                                                      \
    },
            EXIDEL_SPACE_PREDICATES(EXIDEL_DYNAMIC_SPACE_ENTRY_)
#undef EXIDEL_DYNAMIC_SPACE_ENTRY_
    };

    const void* kernel_;
    const Table* table_;
};

static_assert(PredicateKernel3D<DynamicKernel>);

}  // namespace exidel
