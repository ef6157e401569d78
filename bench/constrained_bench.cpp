// exidel bench: the constrained Delaunay triangulation against CGAL's
// Constrained_Delaunay_triangulation_2, in one process, repetitions interleaved, medians.
//
//   exidel-bench-constrained [--input cells|polygon|crossing] [--n N] [--segments S]
//                            [--reps R] [--peer cgal|none]  (none: exidel alone, to profile)
//
// cells: N points uniform in the unit square and S non-crossing segments: the square is cut
// into S cells and each segment joins two random points of its own cell (so segments never
// cross, and each crosses a few Delaunay edges). polygon: a star-shaped polygon of N
// vertices (sorted angles, random radii in [0.5, 1]), its N sides the segments. Both against
// CGAL with Epick and Exact_predicates_tag (no constructions needed). crossing: N uniform
// points and S random segments of length about 0.05 that cross one another, against CGAL
// with Epeck and Exact_intersections_tag (exact crossing points; exidel rounds each once).
// Both sides build everything from the points and index pairs: the Delaunay triangulation,
// then the constraints; CGAL inserts the points with their indices (spatially sorted) and
// the constraints by vertex handle. exidel's result is certified after timing, and the
// vertex and constraint counts of both sides are printed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "exidel/delaunay/constrained.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "generators.hpp"
#include "timing.hpp"

namespace {

using namespace exidel;
using delaunay::Segment;
using bench::Clock;
using bench::median;
using bench::ms;

struct Input {
    std::vector<Point2> points;
    std::vector<Segment> segments;
};

Input make_input(const std::string& input, std::size_t n, std::size_t s) {
    bench::Rng rng(20261207);
    Input in;
    if (input == "cells" || input == "crossing") {
        for (std::size_t i = 0; i < n; ++i)
            in.points.push_back({bench::unit(rng), bench::unit(rng)});
    }
    if (input == "cells") {
        const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(s))));
        std::vector<std::vector<std::uint32_t>> cells(side * side);
        for (std::uint32_t i = 0; i < n; ++i) {
            const auto cx = std::min(side - 1, static_cast<std::size_t>(in.points[i].x * side));
            const auto cy = std::min(side - 1, static_cast<std::size_t>(in.points[i].y * side));
            cells[cy * side + cx].push_back(i);
        }
        for (std::size_t c = 0; c < cells.size() && in.segments.size() < s; ++c) {
            const auto& cell = cells[c];
            if (cell.size() < 2) continue;
            const std::uint32_t a = cell[rng() % cell.size()], b = cell[rng() % cell.size()];
            if (a != b) in.segments.push_back({a, b});
        }
    } else if (input == "polygon") {
        std::vector<double> angles(n);
        for (double& t : angles) t = bench::unit(rng) * 2 * std::numbers::pi;
        std::sort(angles.begin(), angles.end());
        for (std::size_t i = 0; i < n; ++i) {
            const double r = 0.5 + 0.5 * bench::unit(rng);
            in.points.push_back({r * std::cos(angles[i]), r * std::sin(angles[i])});
            in.segments.push_back(
                {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>((i + 1) % n)});
        }
    } else if (input == "crossing") {
        for (std::size_t k = 0; k < s; ++k) {
            const auto a = static_cast<std::uint32_t>(in.points.size());
            const Point2 p{bench::unit(rng), bench::unit(rng)};
            const double t = bench::unit(rng) * 2 * std::numbers::pi;
            in.points.push_back(p);
            in.points.push_back({p.x + 0.05 * std::cos(t), p.y + 0.05 * std::sin(t)});
            in.segments.push_back({a, a + 1});
        }
    } else {
        std::fprintf(stderr, "unknown --input '%s' (cells, polygon or crossing)\n", input.c_str());
        std::exit(2);
    }
    return in;
}

/// CGAL's constrained triangulation of the input with kernel Kr and intersection tag Tag:
/// returns its vertex and constrained edge counts.
template <class Kr, class Tag>
std::pair<std::size_t, std::size_t> cgal_run(const Input& in) {
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kr>;
    using Fb = CGAL::Constrained_triangulation_face_base_2<Kr>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kr, Tds, Tag>;
    std::vector<std::pair<typename Kr::Point_2, std::uint32_t>> points;
    points.reserve(in.points.size());
    for (std::uint32_t i = 0; i < in.points.size(); ++i)
        points.emplace_back(typename Kr::Point_2(in.points[i].x, in.points[i].y), i);
    Cdt cdt;
    cdt.insert(points.begin(), points.end());
    std::vector<typename Cdt::Vertex_handle> handle(in.points.size());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
        handle[v->info()] = v;
    // A repeated point keeps one vertex: every index of it gets that vertex.
    for (std::uint32_t i = 0; i < in.points.size(); ++i)
        if (handle[i] == typename Cdt::Vertex_handle()) handle[i] = cdt.insert(points[i].first);
    for (const Segment& g : in.segments)
        if (handle[g.a] != handle[g.b]) cdt.insert_constraint(handle[g.a], handle[g.b]);
    std::size_t constrained = 0;
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
        constrained += cdt.is_constrained(*e);
    return {cdt.number_of_vertices(), constrained};
}

}  // namespace

int main(int argc, char** argv) {
    std::string input = "cells";
    std::size_t n = 1'000'000, s = 100'000;
    int reps = 5;
    bool peer = true;  // --peer none: exidel alone (profiling)
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--input")
            input = argv[i + 1];
        else if (a == "--n")
            n = std::strtoull(argv[i + 1], nullptr, 10);
        else if (a == "--segments")
            s = std::strtoull(argv[i + 1], nullptr, 10);
        else if (a == "--reps")
            reps = std::atoi(argv[i + 1]);
        else if (a == "--peer")
            peer = std::string(argv[i + 1]) != "none";
        else {
            std::fprintf(stderr, "unknown option %s\n", argv[i]);
            return 2;
        }
    }
    const Input in = make_input(input, n, s);
    const bool crossing = input == "crossing";
    std::vector<double> ours, theirs;
    delaunay::ConstrainedResult result;
    std::pair<std::size_t, std::size_t> cgal_counts;
    for (int r = 0; r < reps; ++r) {
        auto t0 = Clock::now();
        result =
            delaunay::constrained_delaunay(std::span<const Point2>(in.points),
                                           std::span<const Segment>(in.segments), AdaptiveKernel{});
        auto t1 = Clock::now();
        ours.push_back(ms(t0, t1));
        if (!peer) continue;
        t0 = Clock::now();
        cgal_counts = crossing ? cgal_run<CGAL::Epeck, CGAL::Exact_intersections_tag>(in)
                               : cgal_run<CGAL::Epick, CGAL::Exact_predicates_tag>(in);
        t1 = Clock::now();
        theirs.push_back(ms(t0, t1));
    }
    if (!result.ok()) {
        std::fprintf(stderr, "exidel failed: %s\n", result.failure->message.c_str());
        return 1;
    }
    const delaunay::Certificate c =
        delaunay::certify_constrained(in.points, in.segments, result.cdt);
    std::size_t vertices = 0;
    for (std::size_t i = 0; i < result.cdt.points.size(); ++i)
        vertices += result.cdt.triangulation.vertex_of_input[i] == i;
    std::printf("input %s: %zu points, %zu segments, %d reps (medians)\n", input.c_str(),
                in.points.size(), in.segments.size(), reps);
    std::printf("exidel  %10.1f ms  vertices %zu  constraint pieces %zu  added %zu  certified %s\n",
                median(ours), vertices, result.cdt.constraints.size(), result.cdt.added_count(),
                c.ok() ? "yes" : "NO");
    if (!peer) return c.ok() ? 0 : 1;
    std::printf("CGAL %s %10.1f ms  vertices %zu  constrained edges %zu\n",
                crossing ? "(Epeck, exact intersections)" : "(Epick, exact predicates)",
                median(theirs), cgal_counts.first, cgal_counts.second);
    std::printf("ratio exidel / CGAL: %.2fx\n", median(ours) / median(theirs));
    if (!c.ok()) std::fprintf(stderr, "%s\n", c.summary().c_str());
    return c.ok() ? 0 : 1;
}
