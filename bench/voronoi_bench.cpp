// exidel bench: the Voronoi diagram against the triangulation it is built from and against
// CGAL computing the duals with Epick, in one process (issue 12's goal).
//
//   exidel-bench-voronoi [--n N] [--reps R] [--input uniform|grid] [--threads T]
//
// Per repetition, interleaved: exidel's default triangulation (adaptive kernel, T threads,
// default 1), then exidel's Voronoi diagram of it (T threads) (correctly rounded vertices, exact
// cocircular merging); CGAL's Delaunay_triangulation_2<Epick> range insertion, then
// dt.dual(f) (Epick's circumcentre in doubles, nothing merged) for every finite face, and
// CGAL's Voronoi_diagram_2 adaptor with its exact degeneracy removal walking every vertex.
// Prints medians and the ratios the goal names, and the fraction of circumcentres each
// stage of exidel::circumcenter decided.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_adaptation_policies_2.h>
#include <CGAL/Delaunay_triangulation_adaptation_traits_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Voronoi_diagram_2.h>

#include "exidel/delaunay/triangulate.hpp"
#include "exidel/delaunay/voronoi.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "generators.hpp"
#include "timing.hpp"

namespace {

using namespace exidel;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using DT = CGAL::Delaunay_triangulation_2<Epick>;
using VD =
    CGAL::Voronoi_diagram_2<DT, CGAL::Delaunay_triangulation_adaptation_traits_2<DT>,
                            CGAL::Delaunay_triangulation_caching_degeneracy_removal_policy_2<DT>>;
using bench::Clock;
using bench::median;
using bench::ms;

std::vector<Point2> make_points(const std::string& input, std::size_t n) {
    return bench::uniform_or_grid(input, n, 20261202);  // grid: every square cocircular
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t n = 1000000;
    int reps = 5;
    std::string input = "uniform";
    unsigned threads = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--n")
            n = std::strtoull(argv[i + 1], nullptr, 10);
        else if (a == "--reps")
            reps = std::atoi(argv[i + 1]);
        else if (a == "--input")
            input = argv[i + 1];
        else if (a == "--threads")
            threads = static_cast<unsigned>(std::atoi(argv[i + 1]));
        else {
            std::fprintf(stderr,
                         "usage: %s [--n N] [--reps R] [--input uniform|grid] [--threads T]\n",
                         argv[0]);
            return 2;
        }
    }
    const std::vector<Point2> points = make_points(input, n);
    std::vector<double> tri_ms, vor_ms, centre_ms, cgal_tri_ms, cgal_dual_ms, cgal_vd_ms;
    std::uint64_t stages[3] = {0, 0, 0};
    std::size_t vertices = 0, triangles = 0, cgal_vd_vertices = 0;
    std::uint64_t tests = 0, merges = 0;
    delaunay::Options options;
    options.threads = threads;
    for (int r = 0; r < reps; ++r) {
        {
            const auto t0 = Clock::now();
            const delaunay::Result res = delaunay::triangulate(points, AdaptiveKernel{}, options);
            const auto t1 = Clock::now();
            if (!res.ok()) return 1;
            const delaunay::VoronoiDiagram d =
                delaunay::voronoi(points, res.triangulation, AdaptiveKernel{}, threads);
            const auto t2 = Clock::now();
            tri_ms.push_back(ms(t0, t1));
            vor_ms.push_back(ms(t1, t2));
            // The step's first part alone (every circumcentre, correctly rounded), timed
            // again apart from the step: the rest is merging and the cells.
            const auto t3 = Clock::now();
            const delaunay::detail::VoronoiBuilder centres(points, res.triangulation, threads);
            centre_ms.push_back(ms(t3, Clock::now()));
            std::copy(std::begin(d.stage_counts), std::end(d.stage_counts), stages);
            vertices = d.vertex_count();
            triangles = res.triangulation.triangle_count();
            tests = d.cocircular_tests;
            merges = d.cocircular_merges;
        }
        {
            std::vector<Epick::Point_2> cp;
            cp.reserve(points.size());
            for (const Point2& p : points) cp.emplace_back(p.x, p.y);
            const auto t0 = Clock::now();
            DT dt;
            dt.insert(cp.begin(), cp.end());
            const auto t1 = Clock::now();
            std::vector<Epick::Point_2> duals;
            duals.reserve(dt.number_of_faces());
            for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
                duals.push_back(dt.dual(f));
            const auto t2 = Clock::now();
            cgal_tri_ms.push_back(ms(t0, t1));
            cgal_dual_ms.push_back(ms(t1, t2));
            // The adaptor merges cocircular faces with exact predicates; walking its
            // vertices computes each point (Epick's circumcentre).
            const auto t3 = Clock::now();
            VD vd(dt, true);
            double sum = 0;
            std::size_t count = 0;
            for (auto v = vd.vertices_begin(); v != vd.vertices_end(); ++v) {
                sum += v->point().x();
                ++count;
            }
            const auto t4 = Clock::now();
            cgal_vd_ms.push_back(ms(t3, t4));
            cgal_vd_vertices = count;
            if (sum == 0.123) std::puts("");
        }
    }
    const double tri = median(tri_ms), vor = median(vor_ms);
    const double ctri = median(cgal_tri_ms), cdual = median(cgal_dual_ms), cvd = median(cgal_vd_ms);
    const double total_stages = double(stages[0] + stages[1] + stages[2]);
    std::printf("input %s, n = %zu, exidel on %u thread(s), medians of %d runs (ms)\n",
                input.c_str(), n, threads, reps);
    std::printf("exidel triangulate          %9.1f   (%zu triangles)\n", tri, triangles);
    std::printf(
        "exidel voronoi step         %9.1f   (%zu vertices; %llu cocircular tests, %llu merges)\n",
        vor, vertices, static_cast<unsigned long long>(tests),
        static_cast<unsigned long long>(merges));
    std::printf("  of which circumcentres    %9.1f   (timed apart; the rest: merging and cells)\n",
                median(centre_ms));
    std::printf("exidel total                %9.1f\n", tri + vor);
    std::printf("CGAL Epick triangulate      %9.1f\n", ctri);
    std::printf("CGAL dual() of every face   %9.1f\n", cdual);
    std::printf("CGAL total (tri + duals)    %9.1f\n", ctri + cdual);
    std::printf("CGAL Voronoi_diagram_2 walk %9.1f   (%zu vertices, from the triangulation)\n", cvd,
                cgal_vd_vertices);
    std::printf("circumcentres decided: floating %.4f, double-word %.4f, exact %.6f\n",
                stages[0] / total_stages, stages[1] / total_stages, stages[2] / total_stages);
    std::printf("goal 1: exidel total / exidel triangulate = %.2fx (goal <= 1.5x)\n",
                (tri + vor) / tri);
    std::printf("goal 2: exidel total / CGAL total          = %.2fx (goal < 1x)\n",
                (tri + vor) / (ctri + cdual));
    std::printf("        exidel voronoi step / CGAL duals    = %.2fx\n", vor / cdual);
    return 0;
}
