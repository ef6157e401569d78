// exidel::research: `exidel study all`, and the family-list parser shared by the studies.
#include <chrono>
#include <cstdio>

#include "exidel/research/studies.hpp"

namespace exidel::research {

std::vector<testing::Family> parse_families(std::string_view list) {
    std::vector<testing::Family> out;
    while (!list.empty()) {
        const std::size_t comma = list.find(',');
        const std::string_view name = list.substr(0, comma);
        if (name == "all" || name == "near") {
            for (const auto& info : testing::all_families()) {
                if (name == "all" || info.near_degenerate) out.push_back(info.family);
            }
        } else {
            out.push_back(testing::family_from_name(name));
        }
        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    }
    if (out.empty()) throw std::invalid_argument("empty family list");
    return out;
}

void run_all_studies(const RunOptions& run) {
    using Clock = std::chrono::steady_clock;
    Report all("exidel studies" + std::string(run.quick ? " (quick)" : ""));
    all.paragraph("Four studies of predicate precision, each in its own folder with its CSVs "
                  "and pictures; seed " + std::to_string(run.seed) +
                  ". Rerun any one of them with `exidel study <name> --out DIR --seed " +
                  std::to_string(run.seed) + "`.");
    std::string rendered;
    const auto one = [&](const char* name, auto&& body) {
        RunOptions sub = run;
        sub.out = run.out / name;
        const auto start = Clock::now();
        log_line(run, std::string("== study ") + name);
        const StudyResult result = body(sub);
        write_text_file(sub.out / "report.md", result.report.render());
        rendered += result.report.render(std::string(name) + "/", 2);
        char buf[96];
        std::snprintf(buf, sizeof buf, "   %s done in %.1f s: %s", name,
                      std::chrono::duration<double>(Clock::now() - start).count(),
                      (sub.out / "report.md").c_str());
        log_line(run, buf);
    };
    one("failure-map", [](const RunOptions& r) -> StudyResult { return run_failure_map_study({}, r); });
    one("precision", [](const RunOptions& r) -> StudyResult { return run_precision_study({}, r); });
    one("triangulation", [](const RunOptions& r) -> StudyResult { return run_triangulation_study({}, r); });
    one("stages", [](const RunOptions& r) -> StudyResult { return run_stages_study({}, r); });
    write_text_file(run.out / "report.md", all.render() + rendered);
}

}  // namespace exidel::research
