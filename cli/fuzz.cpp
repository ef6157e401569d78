// exidel CLI: `exidel fuzz`, campaigns of a kernel against a reference on the
// exidel::testing families (lib/research/fuzz.hpp), on threads and MPI ranks (team.hpp).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <algorithm>
#include <filesystem>
#include <memory>
#include <thread>
#include <string>
#include <tuple>
#include <vector>

#include "commands.hpp"
#include "exidel/research/fuzz.hpp"
#include "exidel/research/studies.hpp"
#include "options.hpp"
#include "team.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view fuzz_help_text =
    R"(usage: exidel fuzz predicates [options]       a kernel against a reference, query by query
       exidel fuzz triangulations [options]   every algorithm on point sets, certified exactly
       mpirun -np R exidel fuzz ...           the same campaign over R MPI ranks

Campaigns on the exidel::testing families (exact and near degeneracies, wide exponents,
duplicates): the same seed and size give the same inputs, the same counts and the same
report however the work is split over threads (--jobs) and MPI ranks.
See exidel fuzz predicates --help and exidel fuzz triangulations --help.
)";

constexpr std::string_view predicates_help_head =
    R"(usage: exidel fuzz predicates [--kernel K] [--reference R] [--families LIST|all]
                              [--predicates LIST|all] [--queries N] [--seed S] [--jobs N]
                              [--summary FILE] [--reports N] [--checkpoint DIR] [--resume]
       mpirun -np R exidel fuzz predicates ...

Checks a kernel against a reference kernel on queries drawn from the exidel::testing
families: the same seed and N give the same queries, the same counts and the same report
however the work is split over threads (--jobs) and MPI ranks. Queries are drawn 256 at
a time from one set of 16 points of a family (families in turn), each query a predicate
(in turn) of distinct points of the set; the adaptive kernel runs through its batched
path.

Output (standard output) is input for `exidel predicate`: every reported disagreement is
a query line, shrunk to the simplest query that still disagrees (RapidCheck's shrinks of
the point set, toward the exact degenerate configuration), after a comment line with the
query as drawn and both signs; the counts per family follow as comment lines. Replay:
  exidel predicate --kernel K FILE

Options:
  -k, --kernel K       the kernel checked (default adaptive)
  -r, --reference R    the kernel it is checked against (default exact)
  --predicates LIST    orient2d, incircle, incircle_cosine, compare_distance, or 'all'
                       (default all)
  -n, --queries N      how many queries (default 1000000); 1e9 and 2.5e8 are accepted
  --reports N          disagreements shrunk and reported, the first in query order
                       (default 100; all are counted)
  --summary FILE       write the summary as JSON: queries, disagreements, seconds, the
                       counts per family and predicate, the reported disagreements
)";

constexpr std::string_view triangulations_help_head =
    R"(usage: exidel fuzz triangulations [--kernel K] [--algorithms LIST|all]
                   [--orders LIST|all] [--incircle LIST|all] [--families LIST|all]
                   [--sizes MIN-MAX] [--sets N] [--seed S] [--jobs N] [--out DIR]
                   [--summary FILE] [--reports N] [--checkpoint DIR] [--resume]
       mpirun -np R exidel fuzz triangulations ...

Triangulates point sets drawn from the exidel::testing families (families in turn, a
size drawn from MIN-MAX) with every method asked for (an algorithm of the registry; the
external one in each insertion order) under each in-circle policy, with one kernel, and
certifies every result exactly. Outcomes: delaunay (certified), not_delaunay, invalid,
failure (the algorithm stopped itself), guard (more than 64 n^2 + 10^6 predicate calls:
a hang). With an exact kernel anything but delaunay is a bug; with an inexact one the
wrong outcomes are expected, but a guard is a bug. The first wrong outcomes are shrunk
by delta debugging to sets from which no point can be removed and written as fixtures
(hex-float point files whose header says how to replay them with exidel triangulate).

Options:
  -k, --kernel K       the kernel (default adaptive)
  -a, --algorithms LIST  registry names separated by commas, or 'all' (default all)
  --orders LIST        the external algorithm's insertion orders: lexicographic,
                       radial, strips, or 'all' (default all)
  --incircle LIST      determinant, cosine, or 'all' (default all)
  --sizes MIN-MAX      points per set (default 3-100; at most 100000)
  -n, --sets N         how many point sets (default 10000); 1e5 is accepted
  --out DIR            where the fixtures go (default exidel-fuzz-fixtures; created only
                       when there is one)
  --reports N          wrong outcomes shrunk into fixtures, the first in unit order
                       (default 20; all are counted)
  --summary FILE       write the summary as JSON: triangulations, wrong, problems, the
                       outcomes per family, method and policy, the fixtures
)";

constexpr std::string_view common_help_head =
    R"(  --families LIST      family names separated by commas, 'degenerate' (every family
                       but uniform, uniform_scaled and wide_exponents) or 'all'
                       (default all):
                       )";

constexpr std::string_view common_help_tail = R"(
  --seed S             the campaign is a function of it (default 20250704)
  -j, --jobs N         threads per process (default: the processor count; 1 under MPI)
  --checkpoint DIR     where finished stripes (a few seconds of work each) are kept
                       (default exidel-fuzz-checkpoint); removed when the campaign ends
  --resume             continue the campaign whose checkpoint is in DIR (same options)
  --keep-checkpoint    keep DIR after the campaign ends
  --no-checkpoint      keep no checkpoint
  --no-progress        no progress bar (drawn only on a terminal anyway)
  -h, --help           show this help

MPI: under mpirun (Open MPI), ranks take stripes in turn and rank 0 prints the output and
writes the one summary, identical to a single process's but for "seconds" and "run".
DIR must then be on a file system every rank sees.
)";

std::string common_help() {
    std::string families;
    for (const testing::FamilyInfo& f : testing::all_families()) {
        if (!families.empty()) families += ", ";
        if (families.size() - families.rfind('\n') + f.name.size() > 56)
            families += "\n                       ";
        families += f.name;
    }
    return std::string(common_help_head) + families + std::string(common_help_tail);
}

std::string predicates_help() {
    return std::string(predicates_help_head) + common_help() +
           "\nExit status: 0 no disagreement, 1 disagreements (or an I/O error), 2 bad "
           "options.\n\nKernels:\n" +
           kernel_help();
}

std::string triangulations_help() {
    return std::string(triangulations_help_head) + common_help() +
           "\nExit status: 0 nothing wrong (an exact kernel certified everything, no guard), 1 a\n"
           "problem (or an I/O error), 2 bad options.\n\nAlgorithms:\n" +
           delaunay::algorithm_help() + "\nKernels:\n" + kernel_help();
}

/// A count given as an integer or in exponent form ("1e9", "2.5e8"): a whole number in
/// [1, 2^62].
std::uint64_t parse_count(const std::string& text, const std::string& name) {
    constexpr std::uint64_t limit = std::uint64_t{1} << 62;
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    if (auto [p, ec] = std::from_chars(text.data(), end, v); ec == std::errc() && p == end) {
        if (v >= 1 && v <= limit) return v;
    } else {
        double d = 0;
        if (auto [q, ec2] = std::from_chars(text.data(), end, d);
            ec2 == std::errc() && q == end && d >= 1 && d <= double(limit) && d == std::floor(d)) {
            return std::uint64_t(d);
        }
    }
    throw std::invalid_argument(name + " takes a whole number from 1 to 2^62 (1000, 1e9), got '" +
                                text + "'");
}

std::vector<std::string> split_list(const std::string& s) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= s.size(); ++i) {
        if (i == s.size() || s[i] == ',') {
            if (i > start) out.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    }
    return out;
}

std::vector<Predicate> parse_predicates(const std::string& list) {
    if (list == "all") return {};
    std::vector<Predicate> out;
    for (const std::string& name : split_list(list)) {
        const std::optional<Predicate> p = predicate_from_name(name);
        if (!p) {
            throw std::invalid_argument(
                "--predicates: unknown predicate '" + name +
                "' (orient2d, incircle, incircle_cosine, compare_distance or all)");
        }
        if (std::find(out.begin(), out.end(), *p) == out.end()) out.push_back(*p);
    }
    if (out.empty()) throw std::invalid_argument("--predicates needs at least one predicate");
    return out;
}

std::string sign_text(Sign s) { return std::to_string(to_int(s)); }

/// The report on standard output: the disagreements as `exidel predicate` input, then the
/// counts as comment lines.
void print_report(std::ostream& out, const research::PredicateFuzzResult& r) {
    const research::PredicateFuzzOptions& o = r.options;
    for (const research::Disagreement& d : r.reported) {
        const std::size_t n = point_count(d.predicate);
        out << "# query " << d.index << " (" << testing::family_name(d.family) << "): " << o.kernel
            << ' ' << sign_text(d.kernel_sign) << ", " << o.reference << ' '
            << sign_text(d.reference_sign)
            << "; as drawn: " << research::query_line(d.predicate, std::span(d.query.data(), n))
            << '\n'
            << research::query_line(d.predicate, std::span(d.shrunk.data(), n)) << "  # "
            << o.kernel << ' ' << sign_text(d.shrunk_kernel_sign) << ", " << o.reference << ' '
            << sign_text(d.shrunk_reference_sign) << " (" << d.shrink_steps << " shrinks)\n";
    }
    // One line per family: its queries and disagreements, then the disagreements per
    // predicate (the predicates share a family's queries in turn).
    std::string head = "# family                  queries  disagreements";
    for (Predicate p : o.predicates) head += "  " + std::string(predicate_name(p));
    out << head << '\n';
    for (std::size_t f = 0; f < o.families.size(); ++f) {
        research::FuzzCount sum;
        std::string per_predicate;
        for (std::size_t p = 0; p < o.predicates.size(); ++p) {
            const research::FuzzCount& n = r.counts[f * o.predicates.size() + p];
            sum.queries += n.queries;
            sum.disagreements += n.disagreements;
            const std::string count = std::to_string(n.disagreements);
            const std::size_t width = predicate_name(o.predicates[p]).size();
            per_predicate +=
                "  " + std::string(width > count.size() ? width - count.size() : 0, ' ') + count;
        }
        char line[120];
        std::snprintf(line, sizeof line, "# %-20s %12llu %14llu",
                      std::string(testing::family_name(o.families[f])).c_str(),
                      static_cast<unsigned long long>(sum.queries),
                      static_cast<unsigned long long>(sum.disagreements));
        out << line << per_predicate << '\n';
    }
    const double rate = r.seconds > 0 ? double(r.total.queries - r.resumed_queries) / r.seconds : 0;
    char line[240];
    std::snprintf(
        line, sizeof line,
        "# %llu queries, %llu disagreements (%s against %s), %.1f s, %.3g queries/s on %d rank%s x "
        "%u "
        "thread%s%s\n",
        static_cast<unsigned long long>(r.total.queries),
        static_cast<unsigned long long>(r.total.disagreements), o.kernel.c_str(),
        o.reference.c_str(), r.seconds, rate, r.ranks, r.ranks == 1 ? "" : "s", o.jobs,
        o.jobs == 1 ? "" : "s",
        r.resumed_queries ? (", " + std::to_string(r.resumed_queries) + " resumed").c_str() : "");
    out << line;
}

/// The options every campaign takes, as given.
struct Common {
    std::string kernel = "adaptive";
    std::vector<testing::Family> families;
    std::uint64_t seed = 20250704;
    std::optional<unsigned> jobs;
    std::optional<std::size_t> reports;
    std::optional<std::string> summary;
    std::filesystem::path checkpoint = "exidel-fuzz-checkpoint";
    bool resume = false, keep_checkpoint = false, no_checkpoint = false, progress = true;

    void declare(CLI::App& app) {
        app.add_option("-k,--kernel", kernel);
        app.add_option_function<std::string>("--families,--family", [this](const std::string& v) {
            families = v == "all" ? std::vector<testing::Family>{} : research::parse_families(v);
        });
        app.add_option_function<std::string>("--seed", [this](const std::string& v) {
            const char* end = v.data() + v.size();
            if (auto [p, ec] = std::from_chars(v.data(), end, seed);
                ec != std::errc() || p != end) {
                throw std::invalid_argument(
                    "--seed takes a whole number from 0 to 2^64 - 1, got '" + v + "'");
            }
        });
        app.add_option_function<std::string>("-j,--jobs", [this](const std::string& v) {
            const std::uint64_t n = parse_count(v, "--jobs");
            if (n > 1024) throw std::invalid_argument("--jobs takes at most 1024, got '" + v + "'");
            jobs = unsigned(n);
        });
        app.add_option_function<std::string>("--reports", [this](const std::string& v) {
            reports = v == "0" ? 0 : std::size_t(parse_count(v, "--reports"));
        });
        app.add_option("--summary", summary);
        app.add_option_function<std::string>("--checkpoint",
                                             [this](const std::string& v) { checkpoint = v; });
        app.add_flag("--resume", resume);
        app.add_flag("--keep-checkpoint", keep_checkpoint);
        app.add_flag("--no-checkpoint", no_checkpoint);
        app.add_flag_callback("--no-progress", [this] { progress = false; });
    }

    /// After parsing: the usage error, if any.
    std::optional<std::string> check(Team& team) {
        if (no_checkpoint && (resume || keep_checkpoint))
            return "--no-checkpoint with --resume or --keep-checkpoint";
        if (no_checkpoint) checkpoint.clear();
        std::string error;
        if (!parse_kernel(kernel, error)) return error;
        if (!jobs) jobs = team.size() > 1 ? 1u : std::max(1u, std::thread::hardware_concurrency());
        return std::nullopt;
    }

    /// Copies the options into a campaign's (after check()).
    template <class Options>
    void apply(Options& o) const {
        o.kernel = kernel;
        o.families = families;
        o.seed = seed;
        o.jobs = *jobs;
        if (reports) o.max_reports = *reports;
        o.checkpoint = checkpoint;
        o.resume = resume;
        o.progress = progress;
    }

    /// Writes the summary (rank 0) and removes the finished campaign's checkpoint.
    int finish(const std::string& command, const std::string& json, bool found) const {
        if (summary) {
            std::ofstream file(*summary, std::ios::binary | std::ios::trunc);
            file << json;
            file.flush();
            if (!file) {
                std::cerr << "exidel " << command << ": cannot write '" << *summary << "'\n";
                return exit_failure;
            }
        }
        if (!checkpoint.empty() && !keep_checkpoint) {
            std::error_code ec;
            std::filesystem::remove_all(checkpoint, ec);
        }
        return found ? exit_failure : exit_ok;
    }
};

/// Runs a campaign, turning its errors into exit statuses: bad options and checkpoints
/// (the same on every rank) are usage errors; anything else ends the whole MPI job.
template <class Run>
std::optional<int> guarded(const CommandLine& cli, const std::string& command, Team& team,
                           Run run) {
    try {
        run();
    } catch (const std::invalid_argument& e) {
        return cli.usage_error(e.what());
    } catch (const std::exception& e) {
        std::cerr << "exidel " << command << ": " << e.what() << '\n';
        team.fail();  // under MPI: the other ranks stop too
        return exit_failure;
    }
    return std::nullopt;
}

int fuzz_predicates_command(std::span<const std::string_view> args, Team& team) {
    CommandLine cli("fuzz predicates", predicates_help());
    Common common;
    research::PredicateFuzzOptions o;
    common.declare(cli.app);
    cli.app.add_option("-r,--reference", o.reference);
    cli.app.add_option_function<std::string>(
        "--predicates,--predicate",
        [&o](const std::string& v) { o.predicates = parse_predicates(v); });
    cli.app.add_option_function<std::string>(
        "-n,--queries", [&o](const std::string& v) { o.queries = parse_count(v, "--queries"); });
    if (const std::optional<int> status = cli.parse(args)) return *status;
    if (const auto error = common.check(team)) return cli.usage_error(*error);
    std::string error;
    if (!parse_kernel(o.reference, error)) return cli.usage_error(error);
    common.apply(o);

    research::PredicateFuzzResult r;
    if (auto status = guarded(cli, "fuzz predicates", team,
                              [&] { r = research::fuzz_predicates(o, team); })) {
        return *status;
    }
    if (team.rank() != 0) return exit_ok;  // rank 0 reports and decides the status
    print_report(std::cout, r);
    std::cout.flush();
    return common.finish("fuzz predicates", research::summary_json(r), r.total.disagreements > 0);
}

/// --sizes MIN-MAX (or N alone).
std::pair<std::size_t, std::size_t> parse_sizes(const std::string& v) {
    const std::size_t dash = v.find('-');
    const auto number = [&v](std::string_view t) {
        std::size_t n = 0;
        if (auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), n);
            ec != std::errc() || p != t.data() + t.size()) {
            throw std::invalid_argument("--sizes takes MIN-MAX (3-100) or N, got '" + v + "'");
        }
        return n;
    };
    const std::string_view text(v);
    if (dash == std::string::npos) return {number(text), number(text)};
    return {number(text.substr(0, dash)), number(text.substr(dash + 1))};
}

std::vector<delaunay::InCirclePolicy> parse_policies(const std::string& list) {
    if (list == "all") return {};
    std::vector<delaunay::InCirclePolicy> out;
    for (const std::string& name : split_list(list)) {
        delaunay::InCirclePolicy p{};
        if (name == "determinant") {
            p = delaunay::InCirclePolicy::determinant;
        } else if (name == "cosine") {
            p = delaunay::InCirclePolicy::cosine;
        } else {
            throw std::invalid_argument("--incircle takes determinant, cosine or all, got '" +
                                        name + "'");
        }
        if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
    }
    if (out.empty()) throw std::invalid_argument("--incircle needs at least one policy");
    return out;
}

void print_report(std::ostream& out, const research::TriangulationFuzzResult& r) {
    const research::TriangulationFuzzOptions& o = r.options;
    const auto describe = [](const research::Classification& c) {
        return std::string(research::to_string(c.outcome)) +
               (c.detail.empty() ? "" : " (" + c.detail + ")");
    };
    for (const research::TriangulationFinding& f : r.reported) {
        out << "# unit " << f.index << " (" << testing::family_name(f.family) << ", "
            << research::method_label(f.method) << ", " << research::policy_name(f.policy)
            << "): " << describe(f.outcome) << ", " << f.points << " points shrunk to "
            << f.shrunk.size() << " (" << describe(f.shrunk_outcome) << ")"
            << (f.file.empty() ? "" : ": " + (o.out / f.file).string()) << '\n';
    }
    const std::size_t outcomes = research::all_outcomes.size(),
                      runs = r.methods.size() * o.policies.size();
    std::string head = "# family                triangulations";
    for (research::Outcome oc : research::all_outcomes)
        head += "  " + std::string(research::to_string(oc));
    out << head << '\n';
    for (std::size_t f = 0; f < o.families.size(); ++f) {
        std::vector<std::uint64_t> sum(outcomes);
        for (std::size_t i = f * runs * outcomes; i < (f + 1) * runs * outcomes; ++i)
            sum[i % outcomes] += r.counts[i];
        char line[120];
        std::uint64_t total = 0;
        for (std::uint64_t n : sum) total += n;
        std::snprintf(line, sizeof line, "# %-20s %15llu",
                      std::string(testing::family_name(o.families[f])).c_str(),
                      static_cast<unsigned long long>(total));
        out << line;
        for (std::size_t k = 0; k < outcomes; ++k) {
            const std::string count = std::to_string(sum[k]);
            const std::size_t width = research::to_string(research::all_outcomes[k]).size();
            out << "  " << std::string(width > count.size() ? width - count.size() : 0, ' ')
                << count;
        }
        out << '\n';
    }
    const double rate = r.seconds > 0 ? double(r.triangulations - r.resumed) / r.seconds : 0;
    char line[260];
    std::snprintf(
        line, sizeof line,
        "# %llu triangulations (%llu sets x %zu methods x %zu policies, %zu-%zu points, kernel "
        "%s): %llu "
        "wrong, %llu problems, %.1f s, %.3g triangulations/s on %d rank%s x %u thread%s\n",
        static_cast<unsigned long long>(r.triangulations), static_cast<unsigned long long>(o.sets),
        r.methods.size(), o.policies.size(), o.min_points, o.max_points, o.kernel.c_str(),
        static_cast<unsigned long long>(r.wrong), static_cast<unsigned long long>(r.problems),
        r.seconds, rate, r.ranks, r.ranks == 1 ? "" : "s", o.jobs, o.jobs == 1 ? "" : "s");
    out << line;
}

int fuzz_triangulations_command(std::span<const std::string_view> args, Team& team) {
    CommandLine cli("fuzz triangulations", triangulations_help());
    Common common;
    research::TriangulationFuzzOptions o;
    o.out = "exidel-fuzz-fixtures";
    common.declare(cli.app);
    cli.app.add_option_function<std::string>(
        "-a,--algorithms,--algorithm", [&o](const std::string& v) {
            o.algorithms =
                v == "all" ? std::vector<delaunay::Algorithm>{} : research::parse_algorithms(v);
        });
    cli.app.add_option_function<std::string>(
        "--orders,--order", [&o](const std::string& v) { o.orders = research::parse_orders(v); });
    cli.app.add_option_function<std::string>(
        "--incircle", [&o](const std::string& v) { o.policies = parse_policies(v); });
    cli.app.add_option_function<std::string>("--sizes", [&o](const std::string& v) {
        std::tie(o.min_points, o.max_points) = parse_sizes(v);
    });
    cli.app.add_option_function<std::string>(
        "-n,--sets", [&o](const std::string& v) { o.sets = parse_count(v, "--sets"); });
    cli.app.add_option_function<std::string>("--out", [&o](const std::string& v) { o.out = v; });
    if (const std::optional<int> status = cli.parse(args)) return *status;
    if (const auto error = common.check(team)) return cli.usage_error(*error);
    common.apply(o);

    research::TriangulationFuzzResult r;
    if (auto status = guarded(cli, "fuzz triangulations", team,
                              [&] { r = research::fuzz_triangulations(o, team); })) {
        return *status;
    }
    if (team.rank() != 0) return exit_ok;
    print_report(std::cout, r);
    std::cout.flush();
    return common.finish("fuzz triangulations", research::summary_json(r), r.problems > 0);
}

}  // namespace

int fuzz_command(std::span<const std::string_view> args) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        (args.empty() ? std::cerr : std::cout) << fuzz_help_text;
        return args.empty() ? exit_usage : exit_ok;
    }
    const auto run = args[0] == "predicates"       ? &fuzz_predicates_command
                     : args[0] == "triangulations" ? &fuzz_triangulations_command
                                                   : nullptr;
    if (!run) {
        std::cerr << "exidel fuzz: unknown campaign '" << args[0]
                  << "' (predicates or triangulations)\n";
        return exit_usage;
    }
    Membership membership = join_team();
    return run(args.subspan(1), membership.team());
}

}  // namespace exidel::cli
