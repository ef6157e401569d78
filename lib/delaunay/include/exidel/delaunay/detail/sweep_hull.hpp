// exidel: Sinclair's sweep-hull (s-hull, 2010), the algorithm delaunator descends from, as
// a registered algorithm (algorithms.hpp: `sweep-hull`):
//
//   1. seed    the point nearest the bounding-box centre, its nearest neighbour and the
//              point making the smallest circumcircle with them; their circumcentre c is
//              the centre of the sweep (radial.hpp, radial_centre);
//   2. order   the points by ascending distance from c, exactly (radial.hpp, radial_order:
//              a floating-point key with a proven error bound, the kernel's exact distance
//              comparison inside runs it cannot separate). Every point is then strictly
//              outside the hull of the earlier ones;
//   3. sweep   each point is fanned to the whole chain of hull edges it sees (strictly),
//              found through an angular hash of the hull about c (hull_start.hpp);
//   4. flips   the fan's outer edges are legalized by Lawson flips, recursively
//              (flips.hpp, legalize), as delaunator does after each triangle.
//
// Steps 1-3 are the external algorithm's radial sweep (builder.hpp) with Repair::legalize
// in place of its erosion: the two algorithms differ only in how a new point's cavity is
// cleared, erosion before the fan or flips after it, which is what a comparison of the
// two measures. Sinclair sorts by a floating-point distance and skips points that fail
// an epsilon test; here the order is exact, so no point is skipped and nothing depends on
// an epsilon.
#pragma once

#include "exidel/delaunay/detail/builder.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/external.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

struct SweepHull {
    template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
    static void run(const K& kernel, const SortedInput& in, const Options&, MeshOutput& out,
                    Result& result) {
        if (in.points.size() < 3) {
            out.mesh.collinear = true;
            return;
        }
        build_radial_output<K, I, P, Repair::legalize>(kernel, in, out, result);
    }
};

}  // namespace exidel::delaunay::detail
