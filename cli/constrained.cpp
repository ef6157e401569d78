// exidel CLI: exidel triangulate's constrained mode (constrained.hpp). The same steps as a
// plain run (triangulate.cpp): read the whole input, triangulate (the one timed call),
// optionally certify, write into the pending output renamed on success.
#include "constrained.hpp"

#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/constrained.hpp"
#include "exidel/io/constrained.hpp"

namespace exidel::cli {

namespace {

struct Constrained {
    delaunay::ConstrainedResult result;
    std::string kernel_name;
    bool exact_kernel = false;
    double ms = 0;
};

void print_stats(std::ostream& err, const io::ConstraintFile& input, const Constrained& c,
                 const delaunay::Regions* regions, delaunay::FillRule rule, const PointCommand& o,
                 const StepTimes& times, double certify_ms) {
    const delaunay::ConstrainedTriangulation& cdt = c.result.cdt;
    const bool ok = c.result.ok();
    nlohmann::ordered_json failure;  // null when the run succeeded
    if (!ok) {
        failure = {{"kind", delaunay::to_string(c.result.failure->kind)},
                   {"message", c.result.failure->message}};
    }
    const std::size_t inside = regions ? regions->inside_triangles().size() : 0;
    nlohmann::ordered_json stats{
        {"points", input.points.size()},
        {"segments", input.segments.size()},
        {"holes", input.holes.size()},
        {"added_points", ok ? cdt.added_count() : 0},
        {"constraints", ok ? cdt.constraints.size() : 0},
        {"duplicates", ok ? cdt.triangulation.duplicates.size() : 0},
        {"triangles", inside},
        {"hull_triangles", ok ? cdt.triangulation.triangle_count() : 0},
        {"regions", regions ? regions->region_count : 0},
        {"closed", regions ? regions->closed : true},
        {"unplaced_holes", regions ? regions->unplaced_holes.size() : 0},
        {"fill", fill_rule_name(rule)},
        {"kernel", c.kernel_name},
        {"algorithm", delaunay::to_string(o.algorithm)},
        {"failure", failure},
    };
    err << stats_line(with_times(stats, times, certify_ms));
}

}  // namespace

std::string_view fill_rule_name(delaunay::FillRule rule) {
    switch (rule) {
        case delaunay::FillRule::even_odd: return "even-odd";
        case delaunay::FillRule::non_zero: return "non-zero";
        case delaunay::FillRule::enclosed: return "enclosed";
        case delaunay::FillRule::all: return "all";
    }
    return "?";
}

std::optional<delaunay::FillRule> fill_rule_from_name(const std::string& name) {
    for (const delaunay::FillRule r : {delaunay::FillRule::even_odd, delaunay::FillRule::non_zero,
                                       delaunay::FillRule::enclosed, delaunay::FillRule::all}) {
        if (name == fill_rule_name(r)) return r;
    }
    return std::nullopt;
}

int run_constrained(const PointCommand& o, const ConstrainedSettings& settings,
                    const AnyKernel& kernel, Clock::time_point start,
                    std::optional<PendingFile>& output, std::optional<PendingFile>& node_output) {
    PointRun steps(o, start);
    const delaunay::FillRule rule = settings.fill.value_or(
        o.input.resolved_format() == io::PointFormat::poly ? delaunay::FillRule::enclosed
                                                           : delaunay::FillRule::even_odd);
    const Clock::time_point read_start = Clock::now();
    const std::optional<io::ConstraintFile> input = o.input.read_constraints(steps.progress);
    if (!input) return exit_failure;
    steps.times.read = ms_since(read_start);
    std::vector<delaunay::Segment> segments;
    segments.reserve(input->segments.size());
    for (const auto& [a, b] : input->segments) segments.push_back({a, b});

    steps.progress.phase("triangulating " + std::to_string(input->points.size()) + " points and " +
                         std::to_string(segments.size()) + " segments");
    Constrained c;
    std::visit(
        [&](const auto& k) {
            c.kernel_name = k.name();
            c.exact_kernel = std::decay_t<decltype(k)>::is_exact;
            const Clock::time_point t0 = Clock::now();
            c.result =
                delaunay::constrained_delaunay(input->points, segments, k, {settings.delaunay, 0});
            c.ms = ms_since(t0);
        },
        kernel);
    steps.times.triangulate = c.ms;
    std::optional<delaunay::Regions> regions;
    double certify_ms = 0;
    const auto finish = [&](int status) {
        return steps.finish(status, [&] {
            print_stats(std::cerr, *input, c, regions ? &*regions : nullptr, rule, o, steps.times,
                        certify_ms);
        });
    };
    if (!c.result.ok()) {
        steps.progress.stop();
        Triangulated failed;
        failed.result.failure = c.result.failure;
        failed.kernel_name = c.kernel_name;
        failed.exact_kernel = c.exact_kernel;
        print_triangulation_failure(std::cerr, failed);
        return finish(exit_failure);
    }
    const delaunay::ConstrainedTriangulation& cdt = c.result.cdt;
    delaunay::RegionOptions region_options{rule, input->holes, {}};
    for (const io::ConstraintFile::Region& g : input->regions)
        region_options.attributes.push_back({g.seed, g.attribute});
    regions = delaunay::classify_regions(cdt, region_options);

    if (settings.certify) {
        steps.progress.phase("certifying " + std::to_string(cdt.triangulation.triangle_count()) +
                             " triangles");
        const Clock::time_point t0 = Clock::now();
        const delaunay::Certificate certificate =
            delaunay::certify_constrained(input->points, segments, cdt);
        certify_ms = ms_since(t0);
        if (!certificate.ok()) {
            steps.progress.stop();
            std::cerr << "exidel: the result is not the constrained Delaunay triangulation of "
                         "the input ("
                      << certificate.total_findings << " findings; nothing written):\n";
            print_findings(std::cerr, certificate);
            return finish(exit_failure);
        }
    }

    const std::vector<double> z = io::constrained_z(cdt, input->z);
    const io::ConstrainedWriteOptions write_options{
        input->index_base, o.threads, z, input->segment_markers, input->holes, input->regions};
    std::vector<BesideFile> beside;
    if (node_output) {
        beside.push_back({*node_output, [&](std::ostream& out) {
                              io::write_points(out, cdt.points, io::PointFormat::node,
                                               input->index_base, o.threads);
                          }});
    }
    const bool written = steps.write(
        output,
        [&](std::ostream& out) {
            io::write_constrained(out, cdt, *regions, settings.format, write_options);
        },
        beside);
    if (!written) return finish(exit_failure);
    if (!o.quiet) {
        for (const std::size_t h : regions->unplaced_holes) {
            std::cerr << "exidel: note: hole " << h + input->index_base
                      << " is outside the triangulation or exactly on a segment or point; it "
                         "removes nothing\n";
        }
        for (const std::size_t h : regions->unplaced_attributes) {
            std::cerr << "exidel: note: region " << h + input->index_base
                      << " is outside the triangulation or exactly on a segment or point; it "
                         "labels nothing\n";
        }
        if (!regions->closed && rule == delaunay::FillRule::non_zero) {
            std::cerr << "exidel: note: the segments do not form closed rings, so winding "
                         "numbers depend on the path; even-odd or enclosed may suit better\n";
        }
        if (cdt.added_count() > 0) {
            std::cerr << "exidel: note: " << cdt.added_count()
                      << " crossing points added (each coordinate rounded to the nearest "
                         "double), numbered from "
                      << cdt.input_count + input->index_base << '\n';
        }
        if (settings.certify) {
            std::cerr << "exidel: certified: the constrained Delaunay triangulation of the "
                         "input (exact checks)\n";
        }
    }
    return finish(exit_ok);
}

}  // namespace exidel::cli
