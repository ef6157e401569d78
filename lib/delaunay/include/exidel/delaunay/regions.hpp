// exidel: the regions of a constrained triangulation: which triangles lie inside the polygons
// its segments draw, which are holes, and which region each belongs to.
//
// The segments are the borders. Starting outside the convex hull (depth 0, winding 0), a
// walk from triangle to triangle that crosses an edge carrying pieces of k segments adds k
// to the depth and, for each piece, +1 when it crosses the piece from its right to its left
// (its direction is its chain's, first end to second) and -1 the other way. A triangle's
// depth is the fewest pieces any walk from outside crosses to reach it (Dijkstra over the
// triangles); its winding number is the sum along that walk. When the chains form closed
// curves every walk gives the same winding number (and the same parity of crossings), and
// `closed` is true; for open polylines (breaklines) the numbers depend on the walk, and
// `closed` says so.
//
// The domain (`inside`): under FillRule::even_odd the triangles of odd depth, under
// FillRule::non_zero those of nonzero winding number (for polygons given as rings,
// counter-clockwise outer rings and clockwise holes, both agree); FillRule::all keeps every
// triangle. Then each hole seed (Triangle's convention) removes every triangle reachable from
// the triangle holding it without crossing a piece. A seed outside the hull, or exactly on a
// piece or a vertex, removes nothing and is listed in `unplaced_holes`. Regional attributes
// (Triangle's -A) label the region around each seed the same way (`attribute`,
// `unplaced_attributes`). `region` numbers the
// parts the pieces cut the hull into (0, 1, ... in order of their first triangle).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "exidel/delaunay/constrained.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::delaunay {

enum class FillRule : std::uint8_t {
    even_odd,  ///< inside where a walk from outside crosses an odd number of pieces
    non_zero,  ///< inside where the winding number of the chains is not zero
    /// inside where every walk from outside crosses a piece (depth > 0): Triangle's -p,
    /// which removes the triangles reachable from the hull without crossing a segment
    enclosed,
    all,  ///< every triangle (only hole seeds remove triangles)
};

struct RegionOptions {
    FillRule rule = FillRule::even_odd;
    /// Hole seeds: each removes the region (bounded by pieces) that holds it.
    std::vector<Point2> holes;
    /// Regional attributes (Triangle's -A): each labels the region that holds its seed;
    /// a later seed in the same region overrides an earlier one.
    struct Attribute {
        Point2 seed;
        double attribute = 0;
    };
    std::vector<Attribute> attributes{};
};

struct Regions {
    std::vector<std::uint32_t> region;  ///< per triangle: its part of the hull
    std::vector<std::uint32_t> depth;   ///< per triangle: fewest pieces crossed from outside
    std::vector<std::int32_t> winding;  ///< per triangle: winding number of the chains
    std::vector<std::uint8_t> inside;   ///< per triangle: 1 in the domain, 0 removed
    std::uint32_t region_count = 0;
    bool closed = true;                       ///< the winding numbers agree across every edge
    std::vector<std::size_t> unplaced_holes;  ///< seeds outside, or on a piece or vertex
    /// Per triangle the attribute of its region (0 where no seed labels it); empty when
    /// no attributes were given.
    std::vector<double> attribute{};
    std::vector<std::size_t> unplaced_attributes{};  ///< as unplaced_holes

    /// The indices of the triangles in the domain, in order.
    std::vector<std::uint32_t> inside_triangles() const;
};

/// The regions of `cdt` (a result of constrained_delaunay, with its points and chains).
/// Exact: seeds are located with exact predicates. O(t log t) in the triangles.
Regions classify_regions(const ConstrainedTriangulation& cdt, const RegionOptions& options = {});

}  // namespace exidel::delaunay
