// exidel::research: `exidel study all`, and the family-list parser shared by the studies.
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "exidel/research/studies.hpp"

namespace exidel::research {

std::vector<testing::Family> parse_families(std::string_view list) {
    std::vector<testing::Family> out;
    while (!list.empty()) {
        const std::size_t comma = list.find(',');
        const std::string_view name = list.substr(0, comma);
        if (name == "all" || name == "near" || name == "degenerate") {
            for (const auto& info : testing::all_families()) {
                if (name == "all" || (name == "near" && info.near_degenerate) ||
                    (name == "degenerate" && info.degenerate)) {
                    out.push_back(info.family);
                }
            }
        } else {
            out.push_back(testing::family_from_name(name));
        }
        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    }
    if (out.empty()) throw std::invalid_argument("empty family list");
    return out;
}

std::string_view family_definition(testing::Family f) {
    // Read off the generators of lib/testing (generators.hpp, families.hpp). Every random
    // choice there is drawn at RapidCheck's nominal size, so the ranges below are the full
    // ranges of the generators. "Scaled by 2^k" is exact: integers times a power of two.
    using F = testing::Family;
    switch (f) {
        case F::uniform:
            return "coordinates uniform on the grid of step 2^-53 in [-1, 1]; no scaling, so every "
                   "coordinate is below 1 in magnitude.";
        case F::uniform_scaled:
            return "each point set uniform in one box [-2^k, 2^k]^2 with k drawn once in [-1074, "
                   "1023] "
                   "(negative half the time): from boxes of subnormals to magnitudes near 1e308.";
        case F::wide_exponents:
            return "every coordinate a random 53-bit significand at its own exponent in [-1074, "
                   "1023]: "
                   "one query spreads over up to ~2100 bits.";
        case F::integer_grid:
            return "integer points of [-G, G]^2 with G in 1..8 (many exactly collinear and "
                   "cocircular "
                   "subsets), translated by an integer vector of up to 2^30, scaled by 2^k, k in "
                   "[-1074, 992].";
        case F::lattice_circle:
            return "points exactly on one lattice circle of radius 5 to 48612265 (products of the "
                   "first "
                   "1 to 6 primes = 1 mod 4), translated by up to 2^26, scaled by 2^k, k in "
                   "[-1074, 996]: "
                   "every four points exactly cocircular.";
        case F::dyadic_line:
            return "points exactly on one line of slope p / 2^q (|p| <= 2^20, q <= 20, or the "
                   "mirror "
                   "slope), integer base up to 2^30, steps |t| <= 2^10, scaled by 2^k, k in "
                   "[-1074, 991]: "
                   "every three points exactly collinear.";
        case F::near_integer_grid:
            return "integer_grid with every coordinate then moved by an independent offset of -4 "
                   "to +4 ulps.";
        case F::near_lattice_circle:
            return "lattice_circle with every coordinate then moved by an independent offset of -4 "
                   "to +4 ulps.";
        case F::near_dyadic_line:
            return "dyadic_line with every coordinate then moved by an independent offset of -4 to "
                   "+4 ulps.";
        case F::near_rounded_line:
            return "p and q uniform in a box of scale 2^k, k in [-900, 900]; points fma(t, q - p, "
                   "p) for "
                   "dyadic t in [-2, 4] (steps 2^-20), rounded once, then moved by -4 to +4 ulps "
                   "per "
                   "coordinate.";
        case F::near_rounded_circle:
            return "centre uniform in a box of scale 2^c (c in 0..30), radius R in [1/8, 1]; "
                   "points "
                   "c + R (cos t, sin t) rounded once, moved by -4 to +4 ulps per coordinate, then "
                   "scaled "
                   "by 2^k, k in [-900, 900].";
        case F::kettner:
            return "one of the three configurations of Kettner et al. (coordinates in [0.5, 24]) "
                   "with p "
                   "moved by 0 to 255 ulps in x and in y; further points on the diagonal y = x at "
                   "dyadic "
                   "positions in [0.5, 16); no scaling.";
        case F::duplicates:
            return "a point set of one of the other twelve families (chosen uniformly) in which "
                   "points "
                   "repeat: at least one pair is equal and each later point copies an earlier one "
                   "about "
                   "half the time.";
    }
    throw std::invalid_argument("family_definition: not a Family value");
}

Report family_definitions(std::span<const testing::Family> families, bool standalone) {
    std::string text =
        "Families of point sets (lib/testing; a query takes the first 3 or 4 points of a set):";
    for (testing::Family f : families) {
        text += "\n- `" + std::string(testing::family_name(f)) +
                "`: " + std::string(family_definition(f));
    }
    Report r("");
    if (standalone) {
        r.standalone_paragraph(std::move(text));
    } else {
        r.paragraph(std::move(text));
    }
    return r;
}

void run_all_studies(const RunOptions& run) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto seconds_since = [](Clock::time_point t) {
        return std::chrono::duration<double>(Clock::now() - t).count();
    };
    Report all("exidel studies" + std::string(run.quick ? " (quick)" : ""));
    RunOptions top = run;
    // `study all` takes only the common options, so its command is always this one.
    top.command = default_command("all", run);
    all.append(run_header(top));
    std::string rendered;
    const auto one = [&](const char* name, auto&& body) {
        RunOptions sub = run;
        sub.out = run.out / name;
        // Each study of `all` runs with its default options: the same files as this command.
        sub.command = default_command(name, sub);
        const auto study_start = Clock::now();
        log_line(run, std::string("== study ") + name);
        StudyResult result = body(sub);
        Report header = run_header(sub);
        const double seconds = seconds_since(study_start);
        header.standalone_paragraph(timing_line(seconds, sub));
        result.report.prepend(header);
        // Embedded: without the build table, timing and family definitions, said once at
        // the top.
        rendered += result.report.render(std::string(name) + "/", 2, true);
        write_text_file(sub.out / "report.md", result.report.render());
        char buf[96];
        std::snprintf(buf, sizeof buf, "   %s done in %.1f s: %s", name, seconds,
                      (sub.out / "report.md").c_str());
        log_line(run, buf);
    };
    one("failure-map",
        [](const RunOptions& r) -> StudyResult { return run_failure_map_study({}, r); });
    one("precision", [](const RunOptions& r) -> StudyResult { return run_precision_study({}, r); });
    one("triangulation",
        [](const RunOptions& r) -> StudyResult { return run_triangulation_study({}, r); });
    one("stages", [](const RunOptions& r) -> StudyResult { return run_stages_study({}, r); });
    all.paragraph(timing_line(seconds_since(start), run));
    all.paragraph(
        "Four studies of predicate precision, each in its own folder with its CSVs "
        "and pictures; each section below says how to rerun that study alone.");
    all.append(family_definitions(parse_families("all"), false));
    write_text_file(run.out / "report.md", all.render() + rendered);
}

}  // namespace exidel::research
