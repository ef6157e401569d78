// exidel CLI: `exidel study`, the research instruments of lib/research. Thin: parse the
// options, call one study, print its table and where the report is.
#include <array>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "exidel/delaunay/algorithms.hpp"
#include "exidel/io/number.hpp"
#include "exidel/research/studies.hpp"
#include "options.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view study_help_head =
    R"(usage: exidel study <study> [--out DIR] [--seed N] [--jobs N] [--quick] [options]

Studies (each writes report.md, CSVs and pictures into DIR and prints its main table;
report.md starts with the command that writes the same files again):
  failure-map    one predicate while one point moves over a grid of ulp steps
                 (Kettner et al. 2008): a PNG per preset and kernel, sign counts
  precision      wrong-sign rate of MPFR at p bits vs the exact kernel, per
                 formulation and near-degenerate family: threshold table, and
                 precision.svg and precision.png, one panel per formulation with
                 one line per family
  triangulation  every kernel x in-circle policy x family: certified Delaunay, valid
                 but not Delaunay, invalid, or failure; minimal failing fixtures; the
                 work (flips, predicate calls) of each algorithm and insertion order;
                 the failure rate against MPFR precision, one line per algorithm
  stages         which stage of the adaptive kernel decides, on query streams and
                 inside triangulations
  constrained    every kernel x family of constrained inputs (crossing grids, segments
                 through lattice points, nearly parallel segments, polygons with holes,
                 random segments): constrained_delaunay certified, wrong, failure
                 detected, or too_many_crossings, with the failure and finding kinds
  all            failure-map, precision, triangulation and stages into DIR/<study>/
                 and DIR/report.md, each with its defaults (so `all` takes only the
                 common options below)
  replay         classify one point file as the triangulation study would:
                 exidel study replay -i FILE --kernel K [--incircle determinant|cosine]
                                     [--algorithm NAME] [--order lexicographic|radial|strips]
                 (default: the external algorithm in the paper's lexicographic order;
                 strips use 64-point strips)

Common options:
  --out DIR       output folder (default: exidel-study/<study>, or exidel-study for all)
  --seed N        every random input is a function of N (default 20250704)
  --jobs N        threads (default 1); results are identical for every N
  --quick         the short preset (what `study all --quick` runs)
  --no-progress   never draw the progress bar (it is drawn on stderr only when stderr
                  is a terminal and the work takes more than a second)

failure-map:
  --preset LIST   comma-separated preset names, or 'all' (default: all presets;
                  --quick: kettner1-3, incircle-s2, cosine-s2, orient3d-tilted,
                  insphere-s2); --list-presets
  --kernel LIST   comma-separated kernel names (listed at the end)
                  (default: double,long-double,mpfr:106,adaptive,exact)
  --width W, --height H   window in cells (default 256 x 256)
  a custom configuration instead of presets:
  --predicate P   orient2d|incircle|incircle_cosine|orient3d|insphere
  --points "x,y;x,y;x,y[;x,y]"   decimal or hex floats (x,y,z triples in space)
  --move I        index of the point that moves (default 0)
  --axes AB       space maps: the moving point's coordinates on the map's x and y
                  axes, two of x, y, z (default xy)
  --order LIST    argument order, e.g. 1,2,0 evaluates orient2d(q, r, p): the
                  floating formulas subtract their first argument (orient2d) or the
                  last (the others) (default: 0,1,2[,3[,4]])
  --step S        ulps per cell (default 1)
  --centered      the window around the moving point: offsets [-W/2, W/2) x
                  [-H/2, H/2), the point at the centre cell (the default)
  --corner        the moving point at the window's bottom-left corner instead:
                  offsets [0, W) x [0, H) (presets keep their own window)

precision:
  --bits LIST     precisions (default 24..128 every 8, 53, 106, then 160..512)
  --families LIST family names, 'near' (default) or 'all'
  --samples N     queries per formulation and family (default 10000; --quick 500)

triangulation:
  --kernel LIST   (default double,long-double,mpfr:53,mpfr:106,adaptive,exact)
  --families LIST (default all)   --seeds N point sets per family (default 16; quick 4)
  --sizes LIST    point counts, cycled over seeds (default 50,100,200,500)
  --shrink N      fixtures per order, kernel, policy and outcome (default 2)
  --order LIST    insertion orders of the outcome tables and fixtures, comma-separated:
                  lexicographic|radial|strips, or 'all' (default lexicographic, the
                  paper's algorithm; strips use 64-point strips so merges run). The
                  "Work per insertion order" table always compares all three
  --algorithm LIST  algorithms (listed at the end), comma-separated, or 'all'
                  (default all). Each runs in the orders above if it takes an
                  order; with several, every table gets an "algorithm" column
  --bits LIST     MPFR precisions of the failure rate against precision (one line per
                  algorithm in precision.svg; default 12,16,20,24,32,40,48,53,64,80,106)

stages:
  --families LIST (default all)  --samples N queries per family and predicate
                  (default 10000; quick 2000)
  --seeds N triangulations per family and context (default 4; quick 2); contexts:
                  lexicographic with each in-circle policy, radial with the determinant
  --size N        points per triangulation (default 1000; quick 200)

constrained:
  --kernel LIST   (default double,long-double,mpfr:53,mpfr:106,adaptive,exact)
  --families LIST crossing_grid, lattice_segments, nearly_parallel,
                  polygon_with_holes, random_segments, or 'all' (default all)
  --seeds N       inputs per family (default 40, sizes 60-300 points and 16-40
                  segments, cycled; quick 3, sizes 40-60 points and 12-16 segments)

Exit status: 0 success, 1 a study failed (I/O), 2 bad options.

Algorithms:
)";

std::string study_help() {
    return std::string(study_help_head) + delaunay::algorithm_help() + "\nKernels:\n" +
           kernel_help();
}

std::vector<std::string> split(std::string_view s, char sep) {
    std::vector<std::string> out;
    while (!s.empty()) {
        const std::size_t i = s.find(sep);
        out.emplace_back(s.substr(0, i));
        s = i == std::string_view::npos ? std::string_view{} : s.substr(i + 1);
    }
    return out;
}

std::uint64_t parse_unsigned(std::string_view text, std::string_view what, std::uint64_t max) {
    std::uint64_t v = 0;
    if (text.empty()) throw std::invalid_argument(std::string(what) + " needs a number");
    for (char c : text) {
        if (c < '0' || c > '9' || v > (max - std::uint64_t(c - '0')) / 10) {
            throw std::invalid_argument(std::string(what) + " must be an integer in [0, " +
                                        std::to_string(max) + "], got '" + std::string(text) + "'");
        }
        v = v * 10 + std::uint64_t(c - '0');
    }
    return v;
}

std::vector<std::size_t> parse_list(std::string_view text, std::string_view what,
                                    std::uint64_t max) {
    std::vector<std::size_t> out;
    for (const std::string& s : split(text, ',')) out.push_back(parse_unsigned(s, what, max));
    if (out.empty()) throw std::invalid_argument(std::string(what) + " needs at least one value");
    return out;
}

/// "x,y;x,y;..." (dimension 2) or "x,y,z;x,y,z;..." (dimension 3) as coordinate tuples.
std::vector<std::vector<double>> parse_points(std::string_view text, std::size_t dimension) {
    std::vector<std::vector<double>> out;
    for (const std::string& p : split(text, ';')) {
        const std::vector<std::string> coordinates = split(p, ',');
        if (coordinates.size() != dimension) {
            throw std::invalid_argument(dimension == 2
                                            ? "--points: expected x,y pairs separated by ';'"
                                            : "--points: expected x,y,z triples separated by ';'");
        }
        std::vector<double>& point = out.emplace_back();
        for (const std::string& c : coordinates) {
            const io::ParsedNumber v = io::parse_double(c);
            if (!v.value) throw std::invalid_argument("--points: " + v.error);
            point.push_back(*v.value);
        }
    }
    return out;
}

/// "xy", "xz", "zy", ...: two different coordinate axes.
std::array<int, 2> parse_axes(std::string_view text) {
    const auto axis = [](char c) { return c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1; };
    if (text.size() != 2 || axis(text[0]) < 0 || axis(text[1]) < 0 || text[0] == text[1]) {
        throw std::invalid_argument(
            "--axes must be two different letters of x, y, z (e.g. xz), got '" + std::string(text) +
            "'");
    }
    return {axis(text[0]), axis(text[1])};
}

delaunay::InCirclePolicy parse_policy(std::string_view s) {
    if (s == "determinant") return delaunay::InCirclePolicy::determinant;
    if (s == "cosine") return delaunay::InCirclePolicy::cosine;
    throw std::invalid_argument("--incircle must be determinant or cosine");
}

/// The options of every study, as given (validated by the study itself).
struct Parsed {
    std::string study;
    research::RunOptions run;
    bool out_given = false;
    std::optional<std::string> presets, kernels, predicate, points, move, axes, order, families,
        bits, sizes, input, incircle, algorithms;
    std::optional<std::uint64_t> width, height, step, samples, seeds, size, shrink;
    bool centered = false, corner = false, list_presets = false;
};

// Declares the options of every study; they fill `p` as given.
void add_options(CLI::App& app, Parsed& p) {
    const auto number = [&app](const std::string& name, std::optional<std::uint64_t>& target,
                               std::uint64_t max) {
        app.add_option_function<std::string>(name, [name, &target, max](const std::string& v) {
            target = parse_unsigned(v, name, max);
        });
    };
    app.add_option_function<std::string>("-o,--out", [&p](const std::string& v) {
        p.run.out = v;
        p.out_given = true;
    });
    app.add_option_function<std::string>("--seed", [&p](const std::string& v) {
        p.run.seed = parse_unsigned(v, "--seed", UINT64_MAX);
    });
    app.add_option_function<std::string>("-j,--jobs", [&p](const std::string& v) {
        p.run.jobs = unsigned(parse_unsigned(v, "--jobs", 256));
        if (p.run.jobs == 0) throw std::invalid_argument("--jobs must be at least 1");
    });
    app.add_flag("--quick", p.run.quick);
    app.add_flag_callback("--no-progress", [&p] { p.run.progress = false; });
    // Text options, passed on as given (each study validates its own).
    for (auto [names, target] : {std::pair{"--preset", &p.presets},
                                 {"-k,--kernel,--kernels", &p.kernels},
                                 {"--predicate", &p.predicate},
                                 {"--points", &p.points},
                                 {"--move", &p.move},
                                 {"--axes", &p.axes},
                                 {"--order", &p.order},
                                 {"-a,--algorithm,--algorithms", &p.algorithms},
                                 {"--families,--family", &p.families},
                                 {"--bits", &p.bits},
                                 {"--sizes", &p.sizes},
                                 {"-i,--input", &p.input},
                                 {"--incircle", &p.incircle}}) {
        app.add_option(names, *target);
    }
    // Whole-number options and their largest values.
    for (auto [name, target, max] : {std::tuple{"--width", &p.width, std::uint64_t{4096}},
                                     {"--height", &p.height, std::uint64_t{4096}},
                                     {"--step", &p.step, std::uint64_t{1} << 40},
                                     {"--samples", &p.samples, std::uint64_t{100'000'000}},
                                     {"--seeds", &p.seeds, std::uint64_t{1'000'000}},
                                     {"--size", &p.size, std::uint64_t{1'000'000}},
                                     {"--shrink", &p.shrink, std::uint64_t{1000}}}) {
        number(name, *target, max);
    }
    app.add_flag("--centered", p.centered);
    app.add_flag("--corner", p.corner);
    app.add_flag("--list-presets", p.list_presets);
}

research::FailureMapOptions failure_map_options(const Parsed& p) {
    research::FailureMapOptions o;
    if (p.predicate || p.points) {
        if (!p.predicate || !p.points)
            throw std::invalid_argument("a custom map needs --predicate and --points");
        research::FailureMapSpec s;
        s.name = "custom";
        s.space = space_predicate_from_name(*p.predicate);
        if (s.space) {
            for (const std::vector<double>& c : parse_points(*p.points, 3))
                s.points3.push_back({c[0], c[1], c[2]});
            if (p.axes) s.axes = parse_axes(*p.axes);
        } else {
            if (p.axes) throw std::invalid_argument("--axes is for orient3d and insphere maps");
            try {
                s.formulation = research::formulation_from_name(*p.predicate);
            } catch (const std::invalid_argument&) {  // its message names the plane's three only
                throw std::invalid_argument(
                    "--predicate must be orient2d|incircle|incircle_cosine|orient3d|insphere, got "
                    "'" +
                    *p.predicate + "'");
            }
            for (const std::vector<double>& c : parse_points(*p.points, 2))
                s.points.push_back({c[0], c[1]});
        }
        const std::size_t last = s.arity() - 1;
        s.pivot = p.move ? parse_unsigned(*p.move, "--move", last) : 0;
        s.order.resize(s.arity());
        for (std::size_t i = 0; i < s.order.size(); ++i) s.order[i] = i;
        if (p.order) s.order = parse_list(*p.order, "--order", last);
        if (p.step) s.step = std::int64_t(*p.step);
        if (p.centered && p.corner)
            throw std::invalid_argument("--centered and --corner choose different windows");
        s.centered = !p.corner;
        s.description =
            "custom " + std::string(s.predicate()) + " map, point " + std::to_string(s.pivot) +
            " moved" +
            (s.space ? std::string(" in ") + "xyz"[s.axes[0]] + " and " + "xyz"[s.axes[1]] : "") +
            (s.centered ? ", the window centred on it" : ", from the window's corner");
        research::validate(s);  // before any work: bad specs are usage errors
        o.specs.push_back(std::move(s));
    } else if (p.corner) {
        throw std::invalid_argument(
            "--corner sets the window of a custom map (--predicate, --points); presets keep "
            "their own");
    } else if (p.presets && *p.presets != "all") {
        for (const std::string& name : split(*p.presets, ','))
            o.specs.push_back(research::failure_map_preset(name));
    } else if (p.presets) {
        o.specs = research::failure_map_presets();
    }
    if (p.kernels) o.kernels = split(*p.kernels, ',');
    for (const std::string& k : o.kernels) (void)research::parse_kernel(k);
    if (p.width) o.width = int(*p.width);
    if (p.height) o.height = int(*p.height);
    return o;
}

/// The command line that reproduces a study's files: the study, then every option given
/// that changes a result, in one fixed order, with --seed always (its default may change)
/// and --out. A custom failure map names its window always (--centered or --corner, for the
/// same reason). --jobs, --no-progress and --list-presets change no file and are left out,
/// and so is --centered without a custom map (presets keep their own window).
std::string rerun_command(const Parsed& p) {
    using research::shell_quote;
    std::string c = "exidel study " + p.study;
    if (p.run.quick) c += " --quick";
    c += " --seed " + std::to_string(p.run.seed);
    const auto text = [&c](std::string_view name, const std::optional<std::string>& v) {
        if (v) c += " " + std::string(name) + " " + shell_quote(*v);
    };
    const auto number = [&c](std::string_view name, const std::optional<std::uint64_t>& v) {
        if (v) c += " " + std::string(name) + " " + std::to_string(*v);
    };
    text("--preset", p.presets);
    text("--kernel", p.kernels);
    text("--predicate", p.predicate);
    text("--points", p.points);
    text("--move", p.move);
    text("--axes", p.axes);
    text("--order", p.order);
    number("--step", p.step);
    if (p.study == "failure-map" && (p.predicate || p.points))
        c += p.corner ? " --corner" : " --centered";
    number("--width", p.width);
    number("--height", p.height);
    text("--algorithm", p.algorithms);
    text("--families", p.families);
    text("--bits", p.bits);
    number("--samples", p.samples);
    number("--seeds", p.seeds);
    text("--sizes", p.sizes);
    number("--shrink", p.shrink);
    number("--size", p.size);
    return c + " --out " + shell_quote(p.run.out.string());
}

// Announces the study, runs it, writes its report (headed by the command that reproduces
// it, what built and ran it, and the run's timing) and prints its main table and where
// the report is.
template <class StudyOptions, class Run, class Seconds>
void run_and_report(const Parsed& p, const StudyOptions& o, Run run, Seconds seconds) {
    std::cout << p.study << ": seed " << p.run.seed << ", output " << p.run.out.string() << '\n';
    auto r = run(o, p.run);
    research::Report header = research::run_header(p.run);
    header.paragraph(research::timing_line(seconds(), p.run));
    r.report.prepend(header);
    research::write_text_file(p.run.out / "report.md", r.report.render());
    std::cout << r.table.text();
    std::printf("\nreport: %s  (%.1f s)\n", (p.run.out / "report.md").c_str(), seconds());
}

}  // namespace

int study_command(std::span<const std::string_view> args) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        (args.empty() ? std::cerr : std::cout) << study_help();
        return args.empty() ? exit_usage : exit_ok;
    }
    CommandLine cli("study", study_help(), false);
    Parsed p;
    p.study = std::string(args[0]);
    add_options(cli.app, p);
    if (const std::optional<int> status = cli.parse(args.subspan(1))) return *status;
    if (!p.out_given) p.run.out = p.study == "all" ? "exidel-study" : "exidel-study/" + p.study;
    p.run.log = &std::cout;
    p.run.command = rerun_command(p);
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    using namespace research;
    try {
        if (p.study == "failure-map") {
            if (p.list_presets) {
                for (const FailureMapSpec& s : failure_map_presets())
                    std::cout << s.name << "  " << s.description << '\n';
                return exit_ok;
            }
            const FailureMapOptions o = failure_map_options(p);
            run_and_report(p, o, run_failure_map_study, seconds);
        } else if (p.study == "precision") {
            PrecisionOptions o;
            if (p.bits) {
                for (std::size_t b : parse_list(*p.bits, "--bits", MpfrKernel::max_bits))
                    o.bits.push_back(unsigned(b));
            }
            if (p.families) o.families = parse_families(*p.families);
            if (p.samples) o.samples = *p.samples;
            run_and_report(p, o, run_precision_study, seconds);
        } else if (p.study == "triangulation") {
            TriangulationOptions o;
            if (p.kernels) o.kernels = split(*p.kernels, ',');
            for (const std::string& k : o.kernels) (void)research::parse_kernel(k);
            if (p.families) o.families = parse_families(*p.families);
            if (p.seeds) o.seeds = *p.seeds;
            if (p.sizes) o.sizes = parse_list(*p.sizes, "--sizes", 100000);
            if (p.shrink) o.shrink_per_class = *p.shrink;
            if (p.order) o.orders = parse_orders(*p.order);
            if (p.algorithms) o.algorithms = parse_algorithms(*p.algorithms);
            if (p.bits) {
                for (std::size_t b : parse_list(*p.bits, "--bits", MpfrKernel::max_bits)) {
                    o.precision_bits.push_back(unsigned(b));
                    (void)research::parse_kernel("mpfr:" + std::to_string(b));  // in range?
                }
            }
            run_and_report(p, o, run_triangulation_study, seconds);
        } else if (p.study == "constrained") {
            ConstrainedStudyOptions o;
            if (p.kernels) o.kernels = split(*p.kernels, ',');
            for (const std::string& k : o.kernels) (void)research::parse_kernel(k);
            if (p.families) o.families = parse_constrained_families(*p.families);
            if (p.seeds) o.seeds = *p.seeds;
            run_and_report(p, o, run_constrained_study, seconds);
        } else if (p.study == "stages") {
            StagesOptions o;
            if (p.families) o.families = parse_families(*p.families);
            if (p.samples) o.samples = *p.samples;
            if (p.seeds) o.seeds = *p.seeds;
            if (p.size) o.size = *p.size;
            run_and_report(p, o, run_stages_study, seconds);
        } else if (p.study == "all") {
            // `all` runs every study with its defaults: an option of one study would be
            // silently ignored, and its report's rerun line would not show it.
            if (p.presets || p.kernels || p.predicate || p.points || p.move || p.axes || p.order ||
                p.families || p.bits || p.sizes || p.input || p.incircle || p.algorithms ||
                p.width || p.height || p.step || p.samples || p.seeds || p.size || p.shrink ||
                p.centered || p.corner || p.list_presets) {
                return cli.usage_error(
                    "study all takes only --out, --seed, --jobs, --quick and "
                    "--no-progress; give a study's own options to that study");
            }
            run_all_studies(p.run);
            std::printf("\nall studies done in %.1f s; report: %s\n", seconds(),
                        (p.run.out / "report.md").c_str());
        } else if (p.study == "replay") {
            if (!p.input || !p.kernels)
                return cli.usage_error("replay needs -i FILE and --kernel K");
            const Kernel k = research::parse_kernel(*p.kernels);
            const auto policy = parse_policy(p.incircle.value_or("determinant"));
            const std::vector<delaunay::Strategy> orders =
                parse_orders(p.order.value_or("lexicographic"));
            if (orders.size() != 1)
                return cli.usage_error("replay runs one --order: lexicographic, radial or strips");
            const std::vector<delaunay::Algorithm> algorithms =
                parse_algorithms(p.algorithms.value_or("external"));
            if (algorithms.size() != 1) return cli.usage_error("replay runs one --algorithm");
            const Classification c =
                replay_fixture(*p.input, k, policy, Method(algorithms.front(), orders.front()));
            std::cout << to_string(c.outcome) << (c.detail.empty() ? "" : " (" + c.detail + ")")
                      << '\n';
        } else {
            return cli.usage_error("unknown study '" + p.study + "'");
        }
    } catch (const std::invalid_argument& e) {
        return cli.usage_error(e.what());
    } catch (const std::exception& e) {
        std::cerr << "exidel study: " << e.what() << '\n';
        return exit_failure;
    }
    return exit_ok;
}

}  // namespace exidel::cli
