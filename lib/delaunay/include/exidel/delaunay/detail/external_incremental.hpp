// exidel: the external incremental Delaunay triangulation (Yifeng Cai 2025) as a
// registered algorithm (algorithms.hpp: `external`). Its option is the insertion order,
// Options::strategy:
//
//   lexicographic  the paper's algorithm, unchanged: one run in (x, y) order. The
//                  reference, and quadratic on a sampled convex curve (each point erodes
//                  the whole visible chain).
//   radial         one run in ascending exact distance from a centre (radial.hpp): fewer
//                  flips on random input and near-linear on convex curves; still
//                  external, no point location.
//   strips         lexicographic strips, each triangulated in radial order, merged by the
//                  Guibas-Stolfi zipper, on one or more threads (strips.hpp); from 2^22
//                  points each strip cut across into tiles first (Options::strip_tiles).
//   automatic      radial below automatic_strips_from points, strips above, except on
//                  points along a convex curve that the radial order follows
//                  (curve_rule.hpp), where radial stays. A radial run (the one, or a
//                  strip's) that erodes more than automatic_erosion_limit edges per point
//                  gives up, and its points are inserted by cavities in BRIO order
//                  (build_by_cavities, builder.hpp): no longer external, but immune to
//                  the curves that cross a sweep. Decided per piece from its points alone,
//                  so the output still depends on neither the thread count nor timing.
//
// The insertion itself is builder.hpp, the merge merge.hpp.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/builder.hpp"
#include "exidel/delaunay/detail/curve_rule.hpp"
#include "exidel/delaunay/detail/mesh.hpp"
#include "exidel/delaunay/detail/strips.hpp"
#include "exidel/delaunay/external.hpp"
#include "exidel/delaunay/result.hpp"
#include "exidel/predicates/kernel.hpp"

namespace exidel::delaunay::detail {

struct ExternalIncremental {
    template <PredicateKernel K, Instrumentation I, InCirclePolicy P>
    /// `in` is consumed: tiled strips permute its points and input indices in place (the
    /// mesh's ids are positions in them; out.first says where the smallest point went).
    static void run(const K& kernel, SortedInput& in, const Options& options, MeshOutput& out,
                    Result& result) {
        const std::size_t n = in.points.size();
        result.strategy = choose_strategy(n, options.strategy);
        if (options.strategy == Strategy::automatic && result.strategy == Strategy::strips &&
            radial_follows_curve(in.points, kernel)) {
            result.strategy = Strategy::radial;
        }
        // Only `automatic` may hand a piece whose radial run erodes too much to cavity
        // insertion (automatic_erosion_limit); a requested order runs as requested.
        const std::size_t erosion_limit =
            options.strategy == Strategy::automatic ? automatic_erosion_limit : 0;
        auto radial = [&](Strategy reported) {
            result.strategy = reported;
            build_radial_output<K, I, P>(kernel, in, out, result, erosion_limit);
        };
        if (n < 3) {
            out.mesh.collinear = true;
        } else if (result.strategy == Strategy::lexicographic) {
            Builder<K, I, P, LastPointStart> builder(kernel, in.points, in.input_of);
            result.failure = builder.run(out.mesh);
            result.counters = builder.counters();
        } else if (result.strategy == Strategy::radial) {
            radial(Strategy::radial);
        } else {
            const std::size_t target =
                options.strip_points != 0 ? options.strip_points : default_strip_points(n);
            const std::size_t tiles =
                options.strip_tiles != 0 ? options.strip_tiles : default_strip_tiles(n, target);
            const std::size_t strip = target > n / tiles ? n : target * tiles;  // no overflow
            const std::vector<std::uint32_t> cuts = strip_cuts(in.points, strip, kernel);
            result.strips = cuts.size() - 1;
            // One strip: its radial run is the whole job, unless it is to be tiled (and
            // is not collinear, which the radial run reports as Builder does).
            if (result.strips == 1 &&
                (tiles <= 1 || all_on_one_line(std::span<const Point2>(in.points), kernel))) {
                radial(Strategy::strips);
            } else {
                result.failure = build_strips<K, I, P>(
                    kernel, std::span<Point2>(in.points), std::span<std::uint32_t>(in.input_of),
                    cuts, tiles, options.threads, out.mesh, out.first, result.counters,
                    result.strips, erosion_limit, result.cavity_pieces);
            }
        }
    }
};

}  // namespace exidel::delaunay::detail
