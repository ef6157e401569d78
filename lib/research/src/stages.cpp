// exidel::research: where the adaptive kernel decides. The share of calls decided by
// each stage, per predicate and family, on raw query streams and inside triangulations.
#include <map>

#include "exidel/delaunay/triangulate.hpp"
#include "exidel/research/studies.hpp"

namespace exidel::research {

Sign StageCountingKernel::orient2d(Point2 a, Point2 b, Point2 c) const {
    AdaptiveStage stage{};
    const Sign s = orient2d_staged(a, b, c, stage);
    ++counts[0][std::size_t(stage)];
    return s;
}

Sign StageCountingKernel::incircle(Point2 a, Point2 b, Point2 c, Point2 d) const {
    AdaptiveStage stage{};
    const Sign s = incircle_staged(a, b, c, d, stage);
    ++counts[1][std::size_t(stage)];
    return s;
}

Sign StageCountingKernel::incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) const {
    AdaptiveStage stage{};
    const Sign s = incircle_cosine_staged(a, b, c, d, stage);
    ++counts[2][std::size_t(stage)];
    return s;
}

namespace {

constexpr std::uint64_t stages_study_id = 4;
constexpr std::size_t queries_per_chunk = 1000;

constexpr const char* stage_names[adaptive_stage_count] = {"filter", "stage_b", "stage_c", "exact", "gmp"};
constexpr const char* contexts[] = {"stream", "triangulation/determinant", "triangulation/cosine"};

void add(StageCounts& into, const StageCounts& from) {
    for (std::size_t p = 0; p < into.size(); ++p) {
        for (std::size_t s = 0; s < into[p].size(); ++s) into[p][s] += from[p][s];
    }
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
    // triangulated with both policies.
    struct Chunk {
        testing::Family family;
        int context;      // 0 stream, 1 triangulation (both policies)
        Formulation formulation = Formulation::orient2d;  // stream only
        std::size_t index = 0;
        StageCounts counts[2]{};  // stream: [0]; triangulation: per policy
    };
    std::vector<Chunk> chunks;
    const std::size_t blocks = (samples + queries_per_chunk - 1) / queries_per_chunk;
    for (testing::Family f : families) {
        for (Formulation form : all_formulations) {
            for (std::size_t b = 0; b < blocks; ++b) chunks.push_back({f, 0, form, b, {}});
        }
        for (std::size_t s = 0; s < seeds; ++s) chunks.push_back({f, 1, Formulation::orient2d, s, {}});
    }
    Progress progress("stages", chunks.size(), run.progress);
    for_each_chunk(chunks.size(), run.jobs, &progress, [&](std::size_t i) {
        Chunk& c = chunks[i];
        const StageCountingKernel kernel;
        if (c.context == 0) {
            const std::size_t count = std::min(queries_per_chunk, samples - c.index * queries_per_chunk);
            std::vector<std::array<Point2, 4>> queries(count);
            {
                const std::lock_guard lock(rapidcheck_mutex());
                rc::Random random(derive_seed(run.seed, {stages_study_id, std::uint64_t(c.family), 0,
                                                         std::uint64_t(c.formulation), c.index}));
                for (auto& q : queries) {
                    const rc::Random r = random.split();
                    if (c.formulation == Formulation::orient2d) {
                        const auto q3 = testing::gen_query3(c.family)(r).value();
                        std::copy(q3.begin(), q3.end(), q.begin());
                    } else if (c.formulation == Formulation::incircle) {
                        q = testing::gen_query4(c.family)(r).value();
                    } else {
                        q = testing::gen_cosine_query(c.family)(r).value();
                    }
                }
            }
            for (const auto& q : queries) evaluate(kernel, c.formulation, std::span(q.data(), arity(c.formulation)));
            c.counts[0] = kernel.counts;
        } else {
            std::vector<Point2> points;
            {
                const std::lock_guard lock(rapidcheck_mutex());
                const rc::Random random(derive_seed(run.seed, {stages_study_id, std::uint64_t(c.family), 1, c.index}));
                points = testing::gen_points(c.family, size)(random).value();
            }
            for (int p = 0; p < 2; ++p) {
                const StageCountingKernel counting;
                const auto policy = p == 0 ? delaunay::InCirclePolicy::determinant : delaunay::InCirclePolicy::cosine;
                (void)delaunay::triangulate(points, counting, delaunay::Options{policy});
                c.counts[p] = counting.counts;
            }
        }
    });

    StagesStudy study;
    std::map<std::pair<std::size_t, int>, StageCounts> combined;  // (family position, context)
    for (const Chunk& c : chunks) {
        const auto f = std::size_t(std::find(families.begin(), families.end(), c.family) - families.begin());
        if (c.context == 0) {
            add(combined[{f, 0}], c.counts[0]);
        } else {
            add(combined[{f, 1}], c.counts[0]);
            add(combined[{f, 2}], c.counts[1]);
        }
    }
    study.table.header = {"family", "context", "predicate", "calls"};
    for (const char* s : stage_names) study.table.header.emplace_back(s);
    StageCounts overall[3]{};
    for (std::size_t f = 0; f < families.size(); ++f) {
        for (int ctx = 0; ctx < 3; ++ctx) {
            const StageCounts& counts = combined[{f, ctx}];
            study.rows.push_back({families[f], contexts[ctx], counts});
            add(overall[ctx], counts);
            for (Formulation form : all_formulations) {
                const auto& per = counts[std::size_t(form)];
                std::uint64_t calls = 0;
                for (std::uint64_t v : per) calls += v;
                if (calls == 0) continue;  // e.g. incircle_cosine in a determinant triangulation
                std::vector<std::string> row{std::string(testing::family_name(families[f])), contexts[ctx],
                                             std::string(to_string(form)), std::to_string(calls)};
                for (std::uint64_t v : per) row.push_back(format_fraction(double(v) / double(calls)));
                study.table.rows.push_back(std::move(row));
            }
        }
    }
    Table summary;
    summary.header = study.table.header;
    summary.header.erase(summary.header.begin());
    for (int ctx = 0; ctx < 3; ++ctx) {
        for (Formulation form : all_formulations) {
            const auto& per = overall[ctx][std::size_t(form)];
            std::uint64_t calls = 0;
            for (std::uint64_t v : per) calls += v;
            if (calls == 0) continue;
            std::vector<std::string> row{contexts[ctx], std::string(to_string(form)), std::to_string(calls)};
            for (std::uint64_t v : per) row.push_back(format_fraction(double(v) / double(calls)));
            summary.rows.push_back(std::move(row));
        }
    }
    write_text_file(run.out / "stages.csv", study.table.csv());
    write_text_file(run.out / "stages_summary.csv", summary.csv());

    study.report = Report("Adaptive kernel: which stage decides");
    study.report.paragraph(
        "Fraction of calls decided by each stage of the adaptive kernel (filter: the "
        "floating-point filter; stage_b: exact value of the rounded differences, or for "
        "incircle_cosine the exact signs of the two dot products; stage_c: first-order tail "
        "correction; exact: expansion arithmetic / cpp_int; gmp: magnitudes outside the "
        "expansion range). 'stream': " + std::to_string(samples) + " queries per family and "
        "predicate; 'triangulation/...': the calls made while triangulating " + std::to_string(seeds) +
        " point sets of " + std::to_string(size) + " points per family with each in-circle policy. "
        "Seed " + std::to_string(run.seed) + ".");
    study.report.paragraph("All families together:");
    study.report.table(summary);
    study.report.heading("Per family");
    study.report.table(study.table);
    study.report.link("stages.csv", "stages.csv");
    study.report.link("stages_summary.csv", "stages_summary.csv");
    return study;
}

}  // namespace exidel::research
