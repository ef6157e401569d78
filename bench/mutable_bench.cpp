// exidel bench: points inserted one at a time and removed one at a time, against CGAL's
// Delaunay_triangulation_2 insert(p) and remove(v), in one process.
//
//   exidel-bench-mutable [--n N] [--reps R] [--input uniform|grid] [--hint none|last]
//
// N points (uniform in the unit square, or the sqrt(N) x sqrt(N) integer lattice with its
// cocircular cells, shuffled) are inserted one by one in their random order into an empty
// triangulation, then a random half of them is removed one by one. --hint none: each
// insertion without a hint (exidel: jump-and-walk from its sample; CGAL: its default start
// at the infinite vertex); --hint last: both start at the vertex inserted last. Repetitions
// are interleaved (exidel, CGAL, ...) and medians printed. After timing, exidel's final
// state is compared with CGAL's: the same number of vertices and triangles, and exidel's
// certified exactly; the program fails otherwise.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/mutable_triangulation.hpp"
#include "exidel/predicates/adaptive.hpp"
#include "generators.hpp"
#include "timing.hpp"

namespace {

using namespace exidel;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using DT = CGAL::Delaunay_triangulation_2<Epick>;
using bench::Clock;
using bench::median;
using bench::ms;

std::vector<Point2> make_points(const std::string& input, std::size_t n) {
    std::vector<Point2> p = bench::uniform_or_grid(input, n, 20261206);
    if (input == "grid") {  // inserted in a random order
        std::mt19937_64 shuffle(7);
        std::shuffle(p.begin(), p.end(), shuffle);
    }
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t n = 1000000;
    int reps = 3;
    std::string input = "uniform", hint = "none";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--n") {
            n = std::strtoull(argv[i + 1], nullptr, 10);
        } else if (a == "--reps") {
            reps = std::atoi(argv[i + 1]);
        } else if (a == "--input") {
            input = argv[i + 1];
        } else if (a == "--hint") {
            hint = argv[i + 1];
        } else {
            std::fprintf(stderr,
                         "usage: %s [--n N] [--reps R] [--input uniform|grid] "
                         "[--hint none|last]\n",
                         argv[0]);
            return 2;
        }
    }
    const bool last = hint == "last";
    const std::vector<Point2> points = make_points(input, n);
    std::vector<std::size_t> order(points.size());  // which half is removed, in which order
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::mt19937_64 rng(3);
    std::shuffle(order.begin(), order.end(), rng);
    order.resize(points.size() / 2);

    std::vector<double> ins_ours, ins_cgal, rem_ours, rem_cgal;
    std::size_t our_triangles = 0, cgal_triangles = 0, our_vertices = 0, cgal_vertices = 0;
    bool certified = true;
    for (int r = 0; r < reps; ++r) {
        {
            delaunay::MutableTriangulation<AdaptiveKernel> m;
            std::vector<std::uint32_t> ids(points.size());
            const auto t0 = Clock::now();
            if (last) {
                std::uint32_t previous = 0;
                for (std::size_t i = 0; i < points.size(); ++i) {
                    previous = ids[i] = i < 3 ? m.insert(points[i]) : m.insert(points[i], previous);
                }
            } else {
                for (std::size_t i = 0; i < points.size(); ++i) ids[i] = m.insert(points[i]);
            }
            const auto t1 = Clock::now();
            for (const std::size_t i : order) m.remove(ids[i]);
            const auto t2 = Clock::now();
            ins_ours.push_back(ms(t0, t1));
            rem_ours.push_back(ms(t1, t2));
            if (r == 0) {
                const auto s = m.snapshot();
                our_triangles = s.triangulation.triangle_count();
                our_vertices = m.vertex_count();
                certified = delaunay::certify(s.points, s.triangulation).ok();
            }
        }
        {
            DT dt;
            std::vector<DT::Vertex_handle> handles(points.size());
            const auto t0 = Clock::now();
            DT::Vertex_handle previous;
            for (std::size_t i = 0; i < points.size(); ++i) {
                const Epick::Point_2 p(points[i].x, points[i].y);
                previous = handles[i] = last && previous != DT::Vertex_handle()
                                            ? dt.insert(p, previous->face())
                                            : dt.insert(p);
            }
            const auto t1 = Clock::now();
            for (const std::size_t i : order) dt.remove(handles[i]);
            const auto t2 = Clock::now();
            ins_cgal.push_back(ms(t0, t1));
            rem_cgal.push_back(ms(t1, t2));
            cgal_triangles = dt.number_of_faces();
            cgal_vertices = dt.number_of_vertices();
        }
    }
    const double io = median(ins_ours), ic = median(ins_cgal);
    const double ro = median(rem_ours), rc = median(rem_cgal);
    std::printf(
        "input %s, n = %zu points inserted one by one (hint: %s), %zu removed; medians "
        "of %d interleaved runs (ms)\n",
        input.c_str(), points.size(), hint.c_str(), order.size(), reps);
    std::printf("exidel MutableTriangulation insert  %10.1f\n", io);
    std::printf("CGAL Epick insert                   %10.1f\n", ic);
    std::printf("ratio insert exidel / CGAL          %10.2fx (goal <= 1.0x)\n", io / ic);
    std::printf("exidel MutableTriangulation remove  %10.1f\n", ro);
    std::printf("CGAL Epick remove                   %10.1f\n", rc);
    std::printf("ratio remove exidel / CGAL          %10.2fx (goal <= 1.0x)\n", ro / rc);
    std::printf(
        "final state: exidel %zu vertices %zu triangles (certified: %s), CGAL %zu vertices "
        "%zu triangles\n",
        our_vertices, our_triangles, certified ? "yes" : "NO", cgal_vertices, cgal_triangles);
    return certified && our_triangles == cgal_triangles && our_vertices == cgal_vertices ? 0 : 1;
}
