// exidel::research: where the adaptive kernel decides. The share of calls decided by
// each stage, per predicate and family, on raw query streams and inside triangulations
// (the paper's lexicographic order with each in-circle policy, and the radial order,
// whose sort is the only user of compare_distance).
#include <cstdio>
#include <map>

#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/dynamic.hpp"
#include "exidel/research/studies.hpp"

namespace exidel::research {

Sign StageCountingKernel::count(Predicate which, std::span<const Point2> points) const {
    AdaptiveStage stage{};
    const Sign s = staged(which, points, stage);
    ++counts[std::size_t(which)][std::size_t(stage)];
    return s;
}

namespace {

constexpr std::uint64_t stages_study_id = 4;
constexpr std::size_t queries_per_chunk = 1000;

constexpr const char* stage_names[adaptive_stage_count] = {
    "filter", "small_integer", "double_word", "stage_b", "stage_c", "exact", "gmp"};
constexpr const char* contexts[] = {"stream", "triangulation/determinant", "triangulation/cosine",
                                    "triangulation/radial"};
constexpr std::size_t context_count = std::size(contexts);

/// The triangulations of a triangulation chunk, one per context after "stream".
struct TriangulationContext {
    delaunay::InCirclePolicy policy;
    delaunay::Strategy order;
};
constexpr TriangulationContext triangulation_contexts[] = {
    {delaunay::InCirclePolicy::determinant, delaunay::Strategy::lexicographic},
    {delaunay::InCirclePolicy::cosine, delaunay::Strategy::lexicographic},
    {delaunay::InCirclePolicy::determinant, delaunay::Strategy::radial},
};
static_assert(std::size(triangulation_contexts) + 1 == context_count);

void add(StageCounts& into, const StageCounts& from) {
    for (std::size_t p = 0; p < into.size(); ++p) {
        for (std::size_t s = 0; s < into[p].size(); ++s) into[p][s] += from[p][s];
    }
}

}  // namespace

namespace {

/// What the exponent range of a family does to the stages, with the measured shares of
/// this run. The mechanism is the code's (predicates/src/adaptive.cpp): a filter that
/// cannot decide, with some coordinate outside the range where expansions are error-free,
/// hands the call to GMP at once.
std::string exponent_spread_text(const std::vector<testing::Family>& families,
                                 std::map<std::pair<std::size_t, int>, StageCounts>& combined) {
    const auto share = [](const std::array<std::uint64_t, adaptive_stage_count>& per,
                          AdaptiveStage st) {
        std::uint64_t calls = 0;
        for (std::uint64_t v : per) calls += v;
        return calls == 0 ? 0.0 : double(per[std::size_t(st)]) / double(calls);
    };
    const auto percent = [](double v) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "%.0f%%", 100 * v);
        return std::string(buf);
    };
    std::string without_gmp;
    struct Range {
        double lo = 2, hi = -1;
        std::string lo_family, hi_family;
        void add(double v, std::string_view f) {
            if (v < lo) lo = v, lo_family = f;
            if (v > hi) hi = v, hi_family = f;
        }
    } orient, incircle;
    for (std::size_t f = 0; f < families.size(); ++f) {
        const StageCounts& c = combined[{f, 0}];
        const std::string_view name = testing::family_name(families[f]);
        bool gmp = false;
        for (const auto& per : c) gmp = gmp || per[std::size_t(AdaptiveStage::gmp)] > 0;
        if (!gmp) {
            without_gmp += (without_gmp.empty() ? "" : ", ") + std::string(name);
            continue;
        }
        orient.add(share(c[std::size_t(Predicate::orient2d)], AdaptiveStage::gmp), name);
        incircle.add(share(c[std::size_t(Predicate::incircle)], AdaptiveStage::gmp), name);
    }
    std::string text =
        "**What the exponent spread does.** In most families it is the exponent range, not "
        "near-degeneracy, that sends calls past the filter. Every family but uniform and kettner "
        "(and duplicates when it copies those) scales its points by 2^k with k drawn over most of "
        "the double range, and wide_exponents puts every coordinate at its own exponent. The "
        "filters' error bounds hold only away from overflow and underflow: an "
        "orient2d product above 2^1024 is infinite and never passes the filter's strict test "
        "(coordinates above about 2^511), and far in the subnormals the bound's absolute "
        "underflow term (2^-1070) exceeds the value (coordinates below about 2^-535); incircle's "
        "semi-static bound is used only while its largest difference lies in [2^-240, 2^250], and "
        "beyond that Shewchuk's stage A, relative to the permanent plus an underflow term, fails "
        "the same way at about half those exponents (degree 4). A call the filter cannot decide, "
        "with some coordinate outside the range where expansion arithmetic is error-free "
        "(orient2d and compare_distance: exponents at most 500 and ulps no finer than 2^-537, so "
        "magnitudes from about 2^-485; incircle: at most 250 and ulps no finer than 2^-268), goes "
        "to GMP at once, without the expansion "
        "stages: the gmp column measures the exponent range a family draws from (incircle first "
        "tries its small-integer stage, which has no range limit, and its double-word stage, "
        "proven for differences in [2^-220, 2^220], so fewer of its calls get there). "
        "incircle_cosine "
        "never reaches GMP: its last stage is cpp_int, which has no range limit (its exact "
        "column). ";
    if (const std::size_t last = without_gmp.rfind(", "); last != std::string::npos) {
        without_gmp.replace(last, 2, " and ");
    }
    if (!without_gmp.empty())
        text += "In this run no stream call of " + without_gmp + " reached GMP";
    if (orient.hi >= 0) {
        text += std::string(without_gmp.empty() ? "In this run" : ";") + " GMP decided " +
                percent(orient.lo) + " (" + orient.lo_family + ") to " + percent(orient.hi) + " (" +
                orient.hi_family + ") of the orient2d stream calls and " + percent(incircle.lo) +
                " (" + incircle.lo_family + ") to " + percent(incircle.hi) + " (" +
                incircle.hi_family + ") of the incircle stream calls of the other families";
    }
    if (!without_gmp.empty() || orient.hi >= 0) text += ".";
    return text;
}

}  // namespace

StagesStudy run_stages_study(const StagesOptions& options, const RunOptions& run) {
    std::vector<testing::Family> families = options.families;
    if (families.empty()) {
        for (const auto& info : testing::all_families()) families.push_back(info.family);
    }
    const std::size_t samples = options.samples ? options.samples : (run.quick ? 2000 : 10000);
    const std::size_t seeds = options.seeds ? options.seeds : (run.quick ? 2 : 4);
    const std::size_t size = options.size ? options.size : (run.quick ? 200 : 1000);

    // Chunks: query blocks per (family, predicate), then one chunk per (family, seed)
    // triangulated once per triangulation context.
    struct Chunk {
        testing::Family family;
        int context;                // 0 stream, 1 triangulation (every triangulation context)
        std::size_t predicate = 0;  // stream only: the row of StageCounts
        std::size_t index = 0;
        StageCounts counts[context_count - 1]{};  // stream: [0]; triangulation: per context
    };
    std::vector<Chunk> chunks;
    const std::size_t blocks = (samples + queries_per_chunk - 1) / queries_per_chunk;
    for (testing::Family f : families) {
        for (std::size_t pred = 0; pred < stage_predicates.size(); ++pred) {
            for (std::size_t b = 0; b < blocks; ++b) chunks.push_back({f, 0, pred, b, {}});
        }
        for (std::size_t s = 0; s < seeds; ++s) chunks.push_back({f, 1, 0, s, {}});
    }
    Progress progress("stages", chunks.size(), run.progress);
    for_each_chunk(chunks.size(), run.jobs, &progress, [&](std::size_t i) {
        Chunk& c = chunks[i];
        const StageCountingKernel kernel;
        if (c.context == 0) {
            const std::size_t count =
                std::min(queries_per_chunk, samples - c.index * queries_per_chunk);
            std::vector<std::array<Point2, 4>> queries(count);
            // compare_distance(c, p, q) takes three points of the family, like orient2d;
            // rows 0-2 are the Formulation values, so their streams keep their seeds.
            const bool three_points = point_count(stage_predicates[c.predicate]) == 3;
            {
                const std::lock_guard lock(rapidcheck_mutex());
                rc::Random random(derive_seed(run.seed, {stages_study_id, std::uint64_t(c.family),
                                                         0, std::uint64_t(c.predicate), c.index}));
                for (auto& q : queries) {
                    const rc::Random r = random.split();
                    if (three_points) {
                        const auto q3 = testing::gen_query3(c.family)(r).value();
                        std::copy(q3.begin(), q3.end(), q.begin());
                    } else if (stage_predicates[c.predicate] == Predicate::incircle) {
                        q = testing::gen_query4(c.family)(r).value();
                    } else {
                        q = testing::gen_cosine_query(c.family)(r).value();
                    }
                }
            }
            for (const auto& q : queries) {
                const Predicate p = stage_predicates[c.predicate];
                (void)evaluate(kernel, p, std::span(q.data(), point_count(p)));
            }
            c.counts[0] = kernel.counts;
        } else {
            std::vector<Point2> points;
            {
                const std::lock_guard lock(rapidcheck_mutex());
                const rc::Random random(
                    derive_seed(run.seed, {stages_study_id, std::uint64_t(c.family), 1, c.index}));
                points = testing::gen_points(c.family, size)(random).value();
            }
            for (std::size_t t = 0; t < std::size(triangulation_contexts); ++t) {
                const StageCountingKernel counting;
                // Through DynamicKernel: the library's compiled algorithms, none here.
                (void)delaunay::triangulate(points, DynamicKernel(counting),
                                            study_options(triangulation_contexts[t].policy,
                                                          triangulation_contexts[t].order));
                c.counts[t] = counting.counts;
            }
        }
    });

    StagesStudy study;
    std::map<std::pair<std::size_t, int>, StageCounts> combined;  // (family position, context)
    for (const Chunk& c : chunks) {
        const auto f =
            std::size_t(std::find(families.begin(), families.end(), c.family) - families.begin());
        if (c.context == 0) {
            add(combined[{f, 0}], c.counts[0]);
        } else {
            for (std::size_t t = 0; t + 1 < context_count; ++t)
                add(combined[{f, int(t + 1)}], c.counts[t]);
        }
    }
    study.table.header = {"family", "context", "predicate", "calls"};
    for (const char* s : stage_names) study.table.header.emplace_back(s);
    StageCounts overall[context_count]{};
    for (std::size_t f = 0; f < families.size(); ++f) {
        for (int ctx = 0; ctx < int(context_count); ++ctx) {
            const StageCounts& counts = combined[{f, ctx}];
            study.rows.push_back({families[f], contexts[ctx], counts});
            add(overall[ctx], counts);
            for (std::size_t pred = 0; pred < stage_predicates.size(); ++pred) {
                const auto& per = counts[pred];
                std::uint64_t calls = 0;
                for (std::uint64_t v : per) calls += v;
                if (calls == 0) continue;  // e.g. incircle_cosine in a determinant triangulation
                std::vector<std::string> row{
                    std::string(testing::family_name(families[f])), contexts[ctx],
                    std::string(predicate_name(stage_predicates[pred])), std::to_string(calls)};
                for (std::uint64_t v : per)
                    row.push_back(format_fraction(double(v) / double(calls)));
                study.table.rows.push_back(std::move(row));
            }
        }
    }
    Table summary;
    summary.header = study.table.header;
    summary.header.erase(summary.header.begin());
    for (std::size_t ctx = 0; ctx < context_count; ++ctx) {
        for (std::size_t pred = 0; pred < stage_predicates.size(); ++pred) {
            const auto& per = overall[ctx][pred];
            std::uint64_t calls = 0;
            for (std::uint64_t v : per) calls += v;
            if (calls == 0) continue;
            std::vector<std::string> row{contexts[ctx],
                                         std::string(predicate_name(stage_predicates[pred])),
                                         std::to_string(calls)};
            for (std::uint64_t v : per) row.push_back(format_fraction(double(v) / double(calls)));
            summary.rows.push_back(std::move(row));
        }
    }
    write_text_file(run.out / "stages.csv", study.table.csv());
    write_text_file(run.out / "stages_summary.csv", summary.csv());

    // The report's tables: per family, streams and triangulations apart (the pooled
    // summary mixes families whose exponent ranges differ, which is what decides the stage).
    Table streams, inside;
    streams.header = inside.header = study.table.header;
    for (const auto& row : study.table.rows)
        (row[1] == contexts[0] ? streams : inside).rows.push_back(row);
    streams.header.erase(streams.header.begin() + 1);
    for (auto& row : streams.rows) row.erase(row.begin() + 1);

    study.report = Report("Adaptive kernel: which stage decides");
    study.report.paragraph(
        "Fraction of calls decided by each stage of the adaptive kernel (filter: the "
        "floating-point filter; small_integer: two equal points (orient2d, incircle, "
        "compare_distance), or exact differences that all fit one window of 30 bits (incircle, "
        "and the cosine form's final comparison) or 62 bits (orient2d, compare_distance, and "
        "incircle's second try), evaluated in 64/128/256-bit integers; "
        "double_word: the same value from the exact differences in double-word arithmetic with "
        "a proven bound; stage_b: exact value of the rounded differences, or for "
        "incircle_cosine the exact signs of the two dot products, and for compare_distance only "
        "when its differences were exact, e.g. exact ties on grids; stage_c: first-order tail "
        "correction; exact: expansion arithmetic / cpp_int; gmp: magnitudes outside the "
        "expansion range). "
        "'stream': " +
        std::to_string(samples) +
        " queries per family and "
        "predicate (compare_distance(c, p, q) on three points of the family); 'triangulation/...': "
        "the "
        "calls made while triangulating " +
        std::to_string(seeds) + " point sets of " + std::to_string(size) +
        " points per family: in the paper's lexicographic "
        "order with each in-circle policy (determinant, cosine), and in the radial order with the "
        "determinant (radial: its sort is the only user of compare_distance). "
        "Seed " +
        std::to_string(run.seed) + ".");
    study.report.append(family_definitions(families));
    study.report.paragraph(exponent_spread_text(families, combined));
    study.report.heading("Per family: query streams");
    study.report.table(streams);
    study.report.heading("Per family: inside triangulations");
    study.report.table(inside);
    study.report.link("stages.csv", "stages.csv");
    study.report.paragraph(
        "All families pooled (the stage shares of a pool depend on which "
        "families it mixes; read the tables above):");
    study.report.link("stages_summary.csv", "stages_summary.csv");
    return study;
}

}  // namespace exidel::research
