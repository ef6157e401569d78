// exidel bench: point location against CGAL's Delaunay_triangulation_2::locate, in one
// process, with the same hints policy on both sides: the queries sorted along a Hilbert
// curve (exidel's batch; CGAL::hilbert_sort), each walk starting from the previous
// answer. The sort is timed on both sides. With --task natural: natural neighbour
// interpolation of one value per point (exidel's interpolate_natural, rounded arithmetic)
// against CGAL's natural_neighbor_coordinates_2 with Epick (its areas in doubles too),
// each query located from the previous one's face and the value summed from the
// coordinates; the largest difference between the two sides' values is printed.
//
//   exidel-bench-locate [--n N] [--queries Q] [--reps R] [--input uniform|grid]
//                       [--task locate|natural]
//
// uniform: N points uniform in the unit square, Q queries uniform in it. grid: the
// sqrt(N) x sqrt(N) integer lattice (every cell's corners cocircular), Q queries drawn from
// the half-step lattice over it, each on a vertex, on an edge (an axis edge, or where the
// two diagonals of a cell cross) or just outside the hull: every query degenerate.
// Repetitions are interleaved (exidel, CGAL, exidel, ...) and medians printed. After timing,
// every exidel answer's kind is checked against CGAL's locate type (vertex, edge, face,
// outside); the program fails on any disagreement.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/natural_neighbor_coordinates_2.h>

#include "exidel/delaunay/locate.hpp"
#include "exidel/delaunay/natural.hpp"
#include "exidel/delaunay/triangulate.hpp"
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

struct Input {
    std::vector<Point2> points, queries;
};

Input make_input(const std::string& input, std::size_t n, std::size_t q) {
    bench::Rng rng(20261205);
    Input in;
    if (input == "uniform") {
        for (std::size_t i = 0; i < n; ++i)
            in.points.push_back({bench::unit(rng), bench::unit(rng)});
        for (std::size_t i = 0; i < q; ++i)
            in.queries.push_back({bench::unit(rng), bench::unit(rng)});
    } else if (input == "grid") {
        const auto side = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
        for (std::size_t i = 0; i < side; ++i)
            for (std::size_t j = 0; j < side; ++j) in.points.push_back({double(i), double(j)});
        // Half steps from -0.5 to side - 0.5: the outermost row is outside the hull.
        const auto steps = 2 * side + 1;
        for (std::size_t i = 0; i < q; ++i) {
            const double x = static_cast<double>(rng() % steps) * 0.5 - 0.5;
            const double y = static_cast<double>(rng() % steps) * 0.5 - 0.5;
            in.queries.push_back({x, y});
        }
    } else {
        std::fprintf(stderr, "unknown --input '%s' (uniform or grid)\n", input.c_str());
        std::exit(2);
    }
    return in;
}

char kind_letter(delaunay::LocationKind k) {
    switch (k) {
        case delaunay::LocationKind::inside: return 'F';
        case delaunay::LocationKind::on_edge: return 'E';
        case delaunay::LocationKind::on_vertex: return 'V';
        case delaunay::LocationKind::outside: return 'O';
    }
    return '?';
}

char cgal_letter(DT::Locate_type lt) {
    switch (lt) {
        case DT::VERTEX: return 'V';
        case DT::EDGE: return 'E';
        case DT::FACE: return 'F';
        default: return 'O';
    }
}

// CGAL sorts points, not indices: (point, index) pairs sorted through a property map, so
// that answers are recorded by index (the sort is timed, the pairing is not).
using IndexedPoint = std::pair<Epick::Point_2, std::uint32_t>;

std::vector<IndexedPoint> indexed(const std::vector<Point2>& queries) {
    std::vector<IndexedPoint> out;
    out.reserve(queries.size());
    for (std::uint32_t i = 0; i < queries.size(); ++i)
        out.emplace_back(Epick::Point_2(queries[i].x, queries[i].y), i);
    return out;
}

void hilbert_sort(std::vector<IndexedPoint>& points) {
    using Traits =
        CGAL::Spatial_sort_traits_adapter_2<Epick, CGAL::First_of_pair_property_map<IndexedPoint>>;
    CGAL::hilbert_sort(points.begin(), points.end(), Traits());
}

/// Natural neighbour interpolation, both sides, reps interleaved; returns main's status.
int natural(const Input& in, const delaunay::Triangulation& t, int reps, const std::string& input) {
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<double, Epick>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb>;
    using VDT = CGAL::Delaunay_triangulation_2<Epick, Tds>;
    std::vector<double> values(in.points.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        const Point2 p = in.points[i];
        values[i] = std::sin(3 * p.x) * std::cos(2 * p.y) + p.x * p.y;
    }
    std::vector<std::pair<Epick::Point_2, double>> cp;
    for (std::size_t i = 0; i < in.points.size(); ++i)
        cp.emplace_back(Epick::Point_2(in.points[i].x, in.points[i].y), values[i]);
    VDT dt(cp.begin(), cp.end());
    std::vector<double> ours_ms, ctor_ms, cgal_ms;
    std::vector<double> ours(in.queries.size()), theirs(in.queries.size());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int r = 0; r < reps; ++r) {
        {
            const auto t0 = Clock::now();
            const delaunay::Locator<AdaptiveKernel> locator(in.points, t);
            const auto t1 = Clock::now();
            if (delaunay::interpolate_natural(locator, values, 1, in.queries, ours, nan)) return 1;
            ctor_ms.push_back(ms(t0, t1));
            ours_ms.push_back(ms(t1, Clock::now()));
        }
        {
            std::vector<IndexedPoint> cq = indexed(in.queries);
            const auto t0 = Clock::now();
            hilbert_sort(cq);
            using Coordinate = std::pair<VDT::Vertex_handle, double>;
            std::vector<Coordinate> coords;
            VDT::Face_handle hint;
            VDT::Locate_type lt;
            int li = 0;
            for (const auto& [p, i] : cq) {
                hint = dt.locate(p, lt, li, hint);
                coords.clear();
                const auto c = CGAL::natural_neighbor_coordinates_2(
                    dt, p, std::back_inserter(coords), CGAL::Identity<Coordinate>(), hint);
                double sum = 0;
                for (const auto& [v, a] : coords) sum += a * v->info();
                theirs[i] = c.third ? sum / c.second : nan;
            }
            cgal_ms.push_back(ms(t0, Clock::now()));
        }
    }
    double worst = 0;
    std::size_t outside_disagree = 0;
    for (std::size_t i = 0; i < ours.size(); ++i) {
        if (std::isnan(ours[i]) != std::isnan(theirs[i]))
            ++outside_disagree;
        else if (!std::isnan(ours[i]))
            worst = std::max(worst, std::abs(ours[i] - theirs[i]));
    }
    const double a = median(ours_ms), b = median(cgal_ms);
    std::printf(
        "input %s, n = %zu points, %zu queries, natural neighbour interpolation, "
        "medians of %d interleaved runs (ms)\n",
        input.c_str(), in.points.size(), in.queries.size(), reps);
    std::printf("exidel interpolate_natural (rounded)      %9.1f\n", a);
    std::printf("exidel Locator construction (checks)      %9.1f\n", median(ctor_ms));
    std::printf("CGAL Epick natural_neighbor_coordinates_2 %9.1f\n", b);
    std::printf("ratio exidel / CGAL                       %9.2fx (goal <= 1.0x)\n", a / b);
    std::printf("largest |exidel - CGAL| value: %.3g; inside/outside disagreements: %zu\n", worst,
                outside_disagree);
    return outside_disagree == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t n = 1000000, q = 1000000;
    int reps = 5;
    std::string input = "uniform", task = "locate";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--n")
            n = std::strtoull(argv[i + 1], nullptr, 10);
        else if (a == "--queries")
            q = std::strtoull(argv[i + 1], nullptr, 10);
        else if (a == "--reps")
            reps = std::atoi(argv[i + 1]);
        else if (a == "--input")
            input = argv[i + 1];
        else if (a == "--task")
            task = argv[i + 1];
        else {
            std::fprintf(stderr,
                         "usage: %s [--n N] [--queries Q] [--reps R] [--input uniform|grid] "
                         "[--task locate|natural]\n",
                         argv[0]);
            return 2;
        }
    }
    const Input in = make_input(input, n, q);
    const delaunay::Result res = delaunay::triangulate(in.points, AdaptiveKernel{});
    if (!res.ok()) return 1;
    if (task == "natural") return natural(in, res.triangulation, reps, input);
    if (task != "locate") {
        std::fprintf(stderr, "unknown --task '%s' (locate or natural)\n", task.c_str());
        return 2;
    }
    std::vector<Epick::Point_2> cp;
    for (const Point2& p : in.points) cp.emplace_back(p.x, p.y);
    DT dt;
    dt.insert(cp.begin(), cp.end());

    std::vector<double> ours_ms, ctor_ms, cgal_ms;
    std::vector<delaunay::Location> where(in.queries.size());
    std::vector<char> cgal_kind(in.queries.size());
    for (int r = 0; r < reps; ++r) {
        {
            const auto t0 = Clock::now();
            const delaunay::Locator<AdaptiveKernel> locator(in.points, res.triangulation);
            const auto t1 = Clock::now();
            if (locator.locate(in.queries, where)) return 1;
            const auto t2 = Clock::now();
            ctor_ms.push_back(ms(t0, t1));
            ours_ms.push_back(ms(t1, t2));
        }
        {
            std::vector<IndexedPoint> cq = indexed(in.queries);
            const auto t0 = Clock::now();
            hilbert_sort(cq);
            DT::Face_handle hint;
            DT::Locate_type lt;
            int li = 0;
            for (const auto& [p, i] : cq) {
                hint = dt.locate(p, lt, li, hint);
                cgal_kind[i] = cgal_letter(lt);
            }
            cgal_ms.push_back(ms(t0, Clock::now()));
        }
    }
    std::size_t disagree = 0, counts[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < where.size(); ++i) {
        disagree += kind_letter(where[i].kind) != cgal_kind[i];
        ++counts[static_cast<int>(where[i].kind)];
    }
    const double ours = median(ours_ms), cgal = median(cgal_ms);
    std::printf(
        "input %s, n = %zu points (%zu triangles), %zu queries, medians of %d "
        "interleaved runs (ms)\n",
        input.c_str(), in.points.size(), res.triangulation.triangle_count(), in.queries.size(),
        reps);
    std::printf("queries: %zu inside, %zu on an edge, %zu on a vertex, %zu outside\n", counts[0],
                counts[1], counts[2], counts[3]);
    std::printf("exidel Locator (adaptive), Hilbert batch  %9.1f\n", ours);
    std::printf("exidel Locator construction (checks)      %9.1f\n", median(ctor_ms));
    std::printf("CGAL Epick locate, hilbert_sort + hints   %9.1f\n", cgal);
    std::printf("ratio exidel / CGAL (same hints policy)   %9.2fx (goal <= 0.5x)\n", ours / cgal);
    std::printf("kinds disagreeing with CGAL's locate type: %zu\n", disagree);
    return disagree == 0 ? 0 : 1;
}
