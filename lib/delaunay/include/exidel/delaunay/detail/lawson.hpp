// exidel: Lawson's algorithm (1977) as a registered algorithm (algorithms.hpp: `lawson`):
// build any triangulation, then flip illegal edges until none is left.
//
//   1. the sorted fan: the points in lexicographic order, each fanned to the chain of hull
//      edges it sees, with no in-circle test (the external sweep, builder.hpp, with
//      Repair::none). Every new point is the largest so far, so no point location is
//      needed and the fan costs O(n) after the sort;
//   2. flips: every interior edge is queued, each illegal edge is flipped and the four
//      sides of its quadrilateral queued again (flips.hpp, flip_all).
//
// Its cost is the flip count, which depends on how far the fan is from Delaunay: at most
// n (n - 1) / 2 (no flipped edge returns, flips.hpp), and the sorted fan of points spread
// over a square starts with long thin triangles that span the whole hull's width. The
// docs/research.md ("The work each algorithm does") and docs/benchmarks.md give the counts.
#pragma once

#include <cstddef>
#include <string>

#include "exidel/delaunay/detail/builder.hpp"
#include "exidel/delaunay/detail/counting.hpp"
#include "exidel/delaunay/detail/flips.hpp"
#include "exidel/delaunay/detail/hull_start.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/external.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

struct Lawson {
    template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
    static void run(const K& kernel, const SortedInput& in, const Options&, MeshOutput& out,
                    Result& result) {
        const std::size_t n = in.points.size();
        if (n < 3) {
            out.mesh.collinear = true;
            return;
        }
        Builder<K, I, P, LastPointStart, Repair::none> fan(kernel, in.points, in.input_of);
        result.failure = fan.run(out.mesh);
        result.counters = fan.counters();
        if (result.failure || out.mesh.collinear) return;
        Counting<I> flips;
        const std::size_t budget = n * (n - 1) / 2;
        if (!flip_all<P>(kernel, std::span<const Point2>(in.points), out.mesh, flips, budget)) {
            result.failure =
                Failure{FailureKind::flips_exceeded, no_index, no_index,
                        "Lawson's flips passed n (n - 1) / 2 = " + std::to_string(budget) +
                            ", more than an exact kernel can need"};
        }
        result.counters += flips.counters_;
    }
};

}  // namespace exidel::delaunay::detail
