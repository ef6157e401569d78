// exidel::research: what wrong signs do to a constrained Delaunay triangulation. Every
// kernel on the same seeded inputs of five families of points and segments; each run of
// constrained_delaunay classified by the exact certifier (certify_constrained) as
// certified, wrong (findings), failure detected (a typed Failure) or too_many_crossings
// (more crossing points than max_added_points allows: a limit the user sets, not a kernel
// error; never with the default options, which the study uses).
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>
#include <variant>

#include "campaign.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/research/studies.hpp"
#include "exidel/testing/ulp.hpp"

namespace exidel::research {

namespace {

constexpr std::uint64_t constrained_study_id = 5;

using delaunay::Segment;

/// The random choices of a generator: a SplitMix64 stream.
struct Draw {
    campaign::SplitMix64 bits;
    /// Uniform integer in [lo, hi].
    std::int64_t between(std::int64_t lo, std::int64_t hi) {
        return lo + std::int64_t(bits.below(std::uint64_t(hi - lo + 1)));
    }
    /// Uniform on the grid of step 2^-53 in [0, 1).
    double unit() { return std::ldexp(double(bits.next() >> 11), -53); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    std::size_t below(std::size_t n) { return std::size_t(bits.below(n)); }
};

/// p moved by up to `ulps` representable doubles in each coordinate, independently.
Point2 jitter(Draw& d, Point2 p, std::int64_t ulps) {
    return testing::nudge(p, d.between(-ulps, ulps), d.between(-ulps, ulps));
}

std::uint32_t add_point(ConstrainedInput& in, Point2 p) {
    in.points.push_back(p);
    return std::uint32_t(in.points.size() - 1);
}

void add_segment(ConstrainedInput& in, Point2 a, Point2 b) {
    const std::uint32_t i = add_point(in, a);
    const std::uint32_t j = add_point(in, b);
    in.segments.push_back({i, j});
}

/// Random points in [x0, x1] x [y0, y1] until the input has `n` points.
void fill_random(Draw& d, ConstrainedInput& in, std::size_t n, double x0, double x1, double y0,
                 double y1) {
    while (in.points.size() < n) add_point(in, {d.uniform(x0, x1), d.uniform(y0, y1)});
}

/// k segments along u and k along v = u turned by 90 degrees, u a unit vector of a
/// random Pythagorean-free direction (rounded); lines h apart, so the crossings are the
/// points o + j h u + i h v of a rotated lattice. Every segment end moved by up to 3 ulps;
/// points added within 2 ulps of the rounded crossings (near both segments at once) and
/// at random in the grid's box.
ConstrainedInput crossing_grid(Draw& d, std::size_t n, std::size_t s) {
    ConstrainedInput in;
    const std::size_t k = std::max<std::size_t>(2, s / 2);
    const double p = double(d.between(1, 7)), q = double(d.between(1, 7));
    const double norm = std::sqrt(p * p + q * q);
    const Point2 u{p / norm, q / norm}, v{-u.y, u.x};
    const Point2 o{d.uniform(-1, 1), d.uniform(-1, 1)};
    const double h = d.uniform(0.05, 0.2);
    const auto at = [&](double a, double b) {  // o + a h u + b h v, rounded step by step
        return Point2{o.x + a * h * u.x + b * h * v.x, o.y + a * h * u.y + b * h * v.y};
    };
    const double lo = -0.5, hi = double(k) - 0.5;
    for (std::size_t i = 0; i < k; ++i) {
        add_segment(in, jitter(d, at(lo, double(i)), 3), jitter(d, at(hi, double(i)), 3));
        add_segment(in, jitter(d, at(double(i), lo), 3), jitter(d, at(double(i), hi), 3));
    }
    const std::size_t near_crossings = n > in.points.size() ? (n - in.points.size()) / 2 : 0;
    for (std::size_t c = 0; c < near_crossings; ++c) {
        add_point(in, jitter(d, at(double(d.below(k)), double(d.below(k))), 2));
    }
    double x0 = o.x, x1 = o.x, y0 = o.y, y1 = o.y;
    for (const Point2& pt : in.points) {
        x0 = std::min(x0, pt.x), x1 = std::max(x1, pt.x);
        y0 = std::min(y0, pt.y), y1 = std::max(y1, pt.y);
    }
    fill_random(d, in, n, x0, x1, y0, y1);
    return in;
}

/// The lattice (0.1 i, 0.1 j), 0 <= i, j < G with G^2 about n, offset by a random
/// (non-representable) translation; each segment joins lattice point a to a + m (dx, dy)
/// with |dx|, |dy| <= 2 and m >= 2, so in the reals it passes through m - 1 lattice
/// points and crosses others at lattice points; in doubles they are all ulps off.
ConstrainedInput lattice_segments(Draw& d, std::size_t n, std::size_t s) {
    ConstrainedInput in;
    const auto g = std::int64_t(std::max(3.0, std::floor(std::sqrt(double(n)))));
    const Point2 t{0.1 * double(d.between(-30, 30)), 0.1 * double(d.between(-30, 30))};
    for (std::int64_t i = 0; i < g; ++i) {
        for (std::int64_t j = 0; j < g; ++j)
            add_point(in, {t.x + 0.1 * double(i), t.y + 0.1 * double(j)});
    }
    const auto index = [g](std::int64_t i, std::int64_t j) { return std::uint32_t(i * g + j); };
    for (std::size_t tries = 0; in.segments.size() < s && tries < 100 * s; ++tries) {
        const std::int64_t i = d.between(0, g - 1), j = d.between(0, g - 1);
        const std::int64_t dx = d.between(-2, 2), dy = d.between(-2, 2);
        if (dx == 0 && dy == 0) continue;
        std::int64_t m = 0;  // the largest multiple that stays on the lattice
        while (i + (m + 1) * dx >= 0 && i + (m + 1) * dx < g && j + (m + 1) * dy >= 0 &&
               j + (m + 1) * dy < g)
            ++m;
        if (m < 2) continue;
        m = d.between(2, m);
        in.segments.push_back({index(i, j), index(i + m * dx, j + m * dy)});
    }
    return in;
}

/// A bundle of at most 10 segments within 8 ulps of the line y = a x + c (ends x0 in
/// [0, 0.5) and x1 in [1, 1.5)), crossing one another at tiny angles, the other segments
/// (at least 1) steep across it,
/// half the other points within 8 ulps of the line and half at random around it.
ConstrainedInput nearly_parallel(Draw& d, std::size_t n, std::size_t s) {
    ConstrainedInput in;
    constexpr double slopes[] = {0.0, 1.0 / 3.0, -2.5, 0.7, 7.0, 1e-9};
    const double a = slopes[d.below(std::size(slopes))];
    const double c = double(d.between(-1000, 1000)) / 7.0;
    const auto near = [&](double x) {
        return Point2{x, testing::nudge(a * x + c, d.between(-8, 8))};
    };
    // At most 10 in the bundle (larger bundles once ended in too_many_crossings with every
    // kernel, before cascades were snap-rounded; kept so that the table stays comparable).
    const std::size_t bundle = std::clamp<std::size_t>(s > 2 ? s - 2 : 2, 2, 10);
    const std::size_t across = std::max<std::size_t>(1, s > bundle ? s - bundle : 1);
    for (std::size_t i = 0; i < bundle; ++i)
        add_segment(in, near(d.uniform(0, 0.5)), near(d.uniform(1, 1.5)));
    for (std::size_t i = 0; i < across; ++i) {
        const double x = d.uniform(0.1, 1.4);
        const double x2 = x + d.uniform(-0.03, 0.03);
        add_segment(in, {x, a * x + c + 1}, {x2, a * x2 + c - 1});
    }
    const std::size_t on_line = n > in.points.size() ? (n - in.points.size()) / 2 : 0;
    for (std::size_t i = 0; i < on_line; ++i) add_point(in, near(d.uniform(0, 1.5)));
    while (in.points.size() < n) {
        const double x = d.uniform(-0.1, 1.6);
        add_point(in, {x, a * x + c + d.uniform(-1, 1)});
    }
    return in;
}

/// A closed ring of segments through `vertices`.
void add_ring(ConstrainedInput& in, const std::vector<Point2>& vertices) {
    const auto first = std::uint32_t(in.points.size());
    for (const Point2& p : vertices) add_point(in, p);
    const auto m = std::uint32_t(vertices.size());
    for (std::uint32_t i = 0; i < m; ++i) in.segments.push_back({first + i, first + (i + 1) % m});
}

/// A star polygon around a random centre (radius R = 1, vertex radii in [0.55, 1]) with a
/// star hole (radii in [0.15, 0.35]), about 5/8 of the segments on the outer ring; half
/// the other points within 4 ulps of a side (a rounded point of the side, moved), half at
/// random in the polygon's box.
ConstrainedInput polygon_with_holes(Draw& d, std::size_t n, std::size_t s) {
    ConstrainedInput in;
    const Point2 centre{d.uniform(-10, 10), d.uniform(-10, 10)};
    const std::size_t outer = std::max<std::size_t>(3, s * 5 / 8);
    const std::size_t hole = std::max<std::size_t>(3, s > outer ? s - outer : 3);
    const auto star = [&](std::size_t m, double r0, double r1) {
        std::vector<Point2> v;
        const double phase = d.unit();
        for (std::size_t i = 0; i < m; ++i) {
            const double angle =
                2 * std::numbers::pi * (double(i) + 0.8 * d.unit() + phase) / double(m);
            const double r = d.uniform(r0, r1);
            v.push_back({centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)});
        }
        return v;
    };
    add_ring(in, star(outer, 0.55, 1.0));
    add_ring(in, star(hole, 0.15, 0.35));
    const std::vector<Segment> sides = in.segments;
    const std::size_t near_sides = n > in.points.size() ? (n - in.points.size()) / 2 : 0;
    for (std::size_t i = 0; i < near_sides; ++i) {
        const Segment& side = sides[d.below(sides.size())];
        const Point2 a = in.points[side.a], b = in.points[side.b];
        const double t = d.unit();
        add_point(in, jitter(d, {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}, 4));
    }
    fill_random(d, in, n, centre.x - 1, centre.x + 1, centre.y - 1, centre.y + 1);
    return in;
}

/// Uniform points in [0, 1]^2 and segments between random pairs of distinct points.
ConstrainedInput random_segments(Draw& d, std::size_t n, std::size_t s) {
    ConstrainedInput in;
    fill_random(d, in, std::max<std::size_t>(n, 2), 0, 1, 0, 1);
    while (in.segments.size() < s) {
        const auto a = std::uint32_t(d.below(in.points.size()));
        const auto b = std::uint32_t(d.below(in.points.size()));
        if (a != b) in.segments.push_back({a, b});
    }
    return in;
}

/// A run of the study: one input (family, seed) and its size.
struct Job {
    ConstrainedFamily family;
    std::size_t seed_index = 0, points = 0, segments = 0;
};

std::string join_kinds(const std::vector<std::string>& kinds) {
    std::string s;
    for (const std::string& k : kinds) s += (s.empty() ? "" : "; ") + k;
    return s;
}

}  // namespace

std::string_view to_string(ConstrainedFamily f) noexcept {
    switch (f) {
        case ConstrainedFamily::crossing_grid: return "crossing_grid";
        case ConstrainedFamily::lattice_segments: return "lattice_segments";
        case ConstrainedFamily::nearly_parallel: return "nearly_parallel";
        case ConstrainedFamily::polygon_with_holes: return "polygon_with_holes";
        case ConstrainedFamily::random_segments: return "random_segments";
    }
    return "?";
}

std::string_view to_string(ConstrainedOutcome o) noexcept {
    switch (o) {
        case ConstrainedOutcome::certified: return "certified";
        case ConstrainedOutcome::wrong: return "wrong";
        case ConstrainedOutcome::failure: return "failure";
        case ConstrainedOutcome::too_many_crossings: return "too_many_crossings";
    }
    return "?";
}

std::string_view constrained_family_definition(ConstrainedFamily f) {
    switch (f) {
        case ConstrainedFamily::crossing_grid:
            return "k segments along a unit direction (p, q) / |(p, q)| (p, q in 1..7, rounded) "
                   "and k across it, h in [0.05, 0.2] apart: the crossings are a rotated lattice; "
                   "every segment end moved by up to 3 ulps per coordinate, half the other points "
                   "within 2 ulps of a rounded lattice crossing, the rest at random in the box.";
        case ConstrainedFamily::lattice_segments:
            return "the points (t + 0.1 i, t' + 0.1 j) of a G x G lattice (G^2 about n; t, t' "
                   "multiples of 0.1 in [-3, 3]), all rounded; each segment joins a lattice point "
                   "a to a + m (dx, dy), |dx|, |dy| <= 2, m >= 2, so in the reals it passes "
                   "through m - 1 lattice points, and in doubles within ulps of them.";
        case ConstrainedFamily::nearly_parallel:
            return "a bundle of at most 10 segments with ends within 8 ulps of one line "
                   "y = a x + c (a in {0, 1/3, -2.5, 0.7, 7, 1e-9}), x from [0, 0.5) to [1, 1.5), "
                   "crossing one another at tiny angles; the other segments (at least 1) steep "
                   "across the bundle; half the "
                   "other points within 8 ulps of the line, half at random within 1 of it.";
        case ConstrainedFamily::polygon_with_holes:
            return "a star polygon (vertex radii in [0.55, 1] around a random centre) with a "
                   "star hole (radii in [0.15, 0.35]) as two closed rings of segments; half the "
                   "other points a rounded point of a side moved by up to 4 ulps per coordinate, "
                   "half at random in the box.";
        case ConstrainedFamily::random_segments:
            return "uniform points in [0, 1]^2, segments between random pairs of them "
                   "(the control: nothing near-degenerate by construction).";
    }
    throw std::invalid_argument("constrained_family_definition: not a ConstrainedFamily value");
}

std::vector<ConstrainedFamily> parse_constrained_families(std::string_view list) {
    std::vector<ConstrainedFamily> out;
    const auto add = [&out](ConstrainedFamily f) {
        if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
    };
    while (!list.empty()) {
        const std::size_t comma = list.find(',');
        const std::string_view name = list.substr(0, comma);
        bool found = name == "all";
        for (ConstrainedFamily f : all_constrained_families) {
            if (found && name == "all") {
                add(f);
            } else if (to_string(f) == name) {
                add(f);
                found = true;
            }
        }
        if (!found) {
            std::string names;
            for (ConstrainedFamily f : all_constrained_families)
                names += std::string(to_string(f)) + ", ";
            throw std::invalid_argument("unknown constrained family '" + std::string(name) +
                                        "' (expected " + names + "or all)");
        }
        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    }
    if (out.empty()) throw std::invalid_argument("empty constrained family list");
    return out;
}

ConstrainedInput draw_constrained_input(ConstrainedFamily family, std::uint64_t seed,
                                        std::size_t points, std::size_t segments) {
    Draw d{{seed}};
    switch (family) {
        case ConstrainedFamily::crossing_grid: return crossing_grid(d, points, segments);
        case ConstrainedFamily::lattice_segments: return lattice_segments(d, points, segments);
        case ConstrainedFamily::nearly_parallel: return nearly_parallel(d, points, segments);
        case ConstrainedFamily::polygon_with_holes: return polygon_with_holes(d, points, segments);
        case ConstrainedFamily::random_segments: return random_segments(d, points, segments);
    }
    throw std::invalid_argument("draw_constrained_input: not a ConstrainedFamily value");
}

ConstrainedClassification classify_constrained(const ConstrainedInput& input,
                                               const Kernel& kernel) {
    delaunay::ConstrainedResult result;
    try {
        result = std::visit(
            [&](const auto& k) {
                return delaunay::constrained_delaunay(std::span<const Point2>(input.points),
                                                      std::span<const Segment>(input.segments), k);
            },
            kernel);
    } catch (const std::exception& e) {
        // Not a typed Failure: a bug of the library, never an outcome. Say where.
        throw std::runtime_error("constrained_delaunay threw with kernel " + kernel_name(kernel) +
                                 " on " + std::to_string(input.points.size()) + " points and " +
                                 std::to_string(input.segments.size()) + " segments: " + e.what());
    }
    ConstrainedClassification c;
    if (result.failure) {
        c.outcome = result.failure->kind == delaunay::FailureKind::too_many_crossings
                        ? ConstrainedOutcome::too_many_crossings
                        : ConstrainedOutcome::failure;
        c.kinds.emplace_back(delaunay::to_string(result.failure->kind));
        return c;
    }
    c.added_points = result.cdt.added_count();
    const delaunay::Certificate cert =
        delaunay::certify_constrained(input.points, input.segments, result.cdt);
    if (cert.ok()) return c;
    c.outcome = ConstrainedOutcome::wrong;
    std::set<std::string> kinds;
    for (const delaunay::Finding& f : cert.findings) kinds.emplace(delaunay::to_string(f.kind));
    c.kinds.assign(kinds.begin(), kinds.end());
    return c;
}

ConstrainedStudy run_constrained_study(const ConstrainedStudyOptions& options,
                                       const RunOptions& run) {
    ConstrainedStudy study;
    study.kernels = options.kernels;
    if (study.kernels.empty())
        study.kernels = {"double", "long-double", "mpfr:53", "mpfr:106", "adaptive", "exact"};
    std::vector<Kernel> kernels;
    for (const std::string& k : study.kernels) kernels.push_back(parse_kernel(k));
    for (std::size_t k = 0; k < kernels.size(); ++k) study.kernels[k] = kernel_name(kernels[k]);
    study.families = options.families.empty()
                         ? std::vector<ConstrainedFamily>(all_constrained_families.begin(),
                                                          all_constrained_families.end())
                         : options.families;
    const std::size_t seeds = options.seeds ? options.seeds : (run.quick ? 3 : 40);
    // Sizes cycled over the seeds: (points, segments).
    const std::vector<std::pair<std::size_t, std::size_t>> sizes =
        run.quick ? std::vector<std::pair<std::size_t, std::size_t>>{{40, 12}, {60, 16}}
                  : std::vector<std::pair<std::size_t, std::size_t>>{
                        {60, 16}, {120, 24}, {200, 32}, {300, 40}};
    std::vector<Job> jobs;
    for (ConstrainedFamily f : study.families) {
        for (std::size_t s = 0; s < seeds; ++s)
            jobs.push_back({f, s, sizes[s % sizes.size()].first, sizes[s % sizes.size()].second});
    }

    // Every job in its own slot: the results do not depend on --jobs.
    std::vector<std::vector<ConstrainedRun>> results(jobs.size());
    {
        Progress progress("constrained", jobs.size(), run.progress);
        for_each_chunk(jobs.size(), run.jobs, &progress, [&](std::size_t i) {
            const Job& job = jobs[i];
            const ConstrainedInput input = draw_constrained_input(
                job.family,
                derive_seed(run.seed,
                            {constrained_study_id, std::uint64_t(job.family), job.seed_index}),
                job.points, job.segments);
            for (std::size_t k = 0; k < kernels.size(); ++k) {
                ConstrainedClassification c;
                try {
                    c = classify_constrained(input, kernels[k]);
                } catch (const std::runtime_error& e) {
                    throw std::runtime_error(std::string(e.what()) + " (family " +
                                             std::string(to_string(job.family)) + ", seed index " +
                                             std::to_string(job.seed_index) + ")");
                }
                results[i].push_back({job.family, job.seed_index, input.points.size(),
                                      input.segments.size(), study.kernels[k], std::move(c)});
            }
        });
    }

    // Counts per kernel and family, and the kinds seen per kernel (and family).
    study.counts.assign(kernels.size() * study.families.size(), ConstrainedCounts{});
    // (kernel, "outcome: kind") -> runs per family
    std::map<std::pair<std::size_t, std::string>, std::vector<std::uint64_t>> kinds;
    for (const std::vector<ConstrainedRun>& job_runs : results) {
        for (std::size_t k = 0; k < job_runs.size(); ++k) {
            const ConstrainedRun& r = job_runs[k];
            const auto f =
                std::size_t(std::find(study.families.begin(), study.families.end(), r.family) -
                            study.families.begin());
            ++study.counts[k * study.families.size() + f][std::size_t(r.result.outcome)];
            for (const std::string& kind : r.result.kinds) {
                auto& row =
                    kinds[{k, r.result.outcome == ConstrainedOutcome::too_many_crossings
                                  ? kind
                                  : std::string(to_string(r.result.outcome)) + ": " + kind}];
                row.resize(study.families.size());
                ++row[f];
            }
            study.runs.push_back(r);
        }
    }

    // The main table: kernel x family, cells certified/wrong/failure (+ too_many_crossings).
    Table& table = study.table;
    table.header = {"kernel"};
    for (ConstrainedFamily f : study.families) table.header.emplace_back(to_string(f));
    table.header.emplace_back("all families");
    const auto cell = [](const ConstrainedCounts& c) {
        std::string s =
            std::to_string(c[0]) + "/" + std::to_string(c[1]) + "/" + std::to_string(c[2]);
        if (c[3] != 0) s += " +" + std::to_string(c[3]);
        return s;
    };
    for (std::size_t k = 0; k < kernels.size(); ++k) {
        std::vector<std::string> row{study.kernels[k]};
        ConstrainedCounts total{};
        for (std::size_t f = 0; f < study.families.size(); ++f) {
            row.push_back(cell(study.at(k, f)));
            for (std::size_t o = 0; o < total.size(); ++o) total[o] += study.at(k, f)[o];
        }
        row.push_back(cell(total));
        table.rows.push_back(std::move(row));
    }

    Table kinds_table;
    kinds_table.header = {"kernel", "outcome: kind"};
    for (ConstrainedFamily f : study.families) kinds_table.header.emplace_back(to_string(f));
    kinds_table.header.emplace_back("all families");
    for (const auto& [key, per_family] : kinds) {
        std::vector<std::string> row{study.kernels[key.first], key.second};
        std::uint64_t total = 0;
        for (std::uint64_t v : per_family) {
            row.push_back(std::to_string(v));
            total += v;
        }
        row.push_back(std::to_string(total));
        kinds_table.rows.push_back(std::move(row));
    }

    Table runs_table;
    runs_table.header = {"family", "seed index", "points", "segments",
                         "kernel", "outcome",    "kinds",  "added points"};
    for (const ConstrainedRun& r : study.runs) {
        runs_table.rows.push_back({std::string(to_string(r.family)), std::to_string(r.seed_index),
                                   std::to_string(r.points), std::to_string(r.segments), r.kernel,
                                   std::string(to_string(r.result.outcome)),
                                   join_kinds(r.result.kinds),
                                   std::to_string(r.result.added_points)});
    }
    write_text_file(run.out / "constrained.csv", runs_table.csv());
    write_text_file(run.out / "constrained_kinds.csv", kinds_table.csv());

    std::string sizes_text;
    for (const auto& [n, s] : sizes) {
        sizes_text += (sizes_text.empty() ? "" : ", ") + std::to_string(n) + " points / " +
                      std::to_string(s) + " segments";
    }
    study.report = Report("Constrained Delaunay outcomes per kernel");
    study.report.paragraph(
        std::to_string(seeds) + " inputs per family (sizes " + sizes_text +
        ", cycled over the seeds; seed " + std::to_string(run.seed) +
        "); every kernel runs constrained_delaunay (the default options) on the same inputs. "
        "Outcomes, decided by the exact certifier certify_constrained: **certified**; **wrong** (a "
        "result whose certificate has findings); **failure** (the construction detected the "
        "inconsistency and stopped with a typed Failure); **too_many_crossings** (more crossing "
        "points than max_added_points allows: a limit the user sets, counted apart because it "
        "is not a kernel error; none with the default options). Cells: certified/wrong/failure, "
        "then +N too_many_crossings when "
        "there were any.");
    std::string definitions = "Families (src/constrained.cpp):";
    for (ConstrainedFamily f : study.families) {
        definitions += "\n- `" + std::string(to_string(f)) +
                       "`: " + std::string(constrained_family_definition(f));
    }
    study.report.paragraph(std::move(definitions));
    study.report.table(table);
    study.report.heading("Failure and finding kinds");
    study.report.paragraph(
        "Runs per kind: the FailureKind of each failure and too_many_crossings, and for each "
        "wrong result every distinct FindingKind of its certificate (a run may count under "
        "several).");
    if (kinds_table.rows.empty()) {
        study.report.paragraph("(none: every run was certified)");
    } else {
        study.report.table(kinds_table);
    }
    study.report.link("constrained.csv", "constrained.csv");
    study.report.link("constrained_kinds.csv", "constrained_kinds.csv");
    char summary[160];
    std::uint64_t certified = 0;
    for (const ConstrainedRun& r : study.runs)
        certified += r.result.outcome == ConstrainedOutcome::certified;
    std::snprintf(summary, sizeof summary, "constrained: %zu runs, %llu certified",
                  study.runs.size(), static_cast<unsigned long long>(certified));
    log_line(run, summary);
    return study;
}

}  // namespace exidel::research
