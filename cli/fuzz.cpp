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
#include <vector>

#include "commands.hpp"
#include "exidel/research/fuzz.hpp"
#include "exidel/research/studies.hpp"
#include "options.hpp"
#include "team.hpp"

namespace exidel::cli {

namespace {

constexpr std::string_view fuzz_help_head =
    R"(usage: exidel fuzz predicates [--kernel K] [--reference R] [--families LIST|all]
                              [--predicates LIST|all] [--queries N] [--seed S] [--jobs N]
                              [--summary FILE] [--reports N] [--checkpoint DIR] [--resume]
       mpirun -np R exidel fuzz predicates ...

Checks a kernel against a reference kernel on queries drawn from the exidel::testing
families (exact and near degeneracies, wide exponents, duplicates): the same seed and N
give the same queries, the same counts and the same report however the work is split
over threads (--jobs) and MPI ranks. Queries are drawn 256 at a time from one set of 16
points of a family (families in turn), each query a predicate (in turn) of distinct
points of the set; the adaptive kernel runs through its batched path.

Output (standard output) is input for `exidel predicate`: every reported disagreement is
a query line, shrunk to the simplest query that still disagrees (RapidCheck's shrinks of
the point set, toward the exact degenerate configuration), after a comment line with the
query as drawn and both signs; the counts per family follow as comment lines. Replay:
  exidel predicate --kernel K FILE

Options:
  -k, --kernel K       the kernel checked (default adaptive)
  -r, --reference R    the kernel it is checked against (default exact)
  --families LIST      family names separated by commas, 'degenerate' (every family
                       but uniform, uniform_scaled and wide_exponents) or 'all'
                       (default all):
                       )";

constexpr std::string_view fuzz_help_tail = R"(
  --predicates LIST    orient2d, incircle, incircle_cosine, compare_distance, or 'all'
                       (default all)
  -n, --queries N      how many queries (default 1000000); 1e9 and 2.5e8 are accepted
  --seed S             the campaign is a function of it (default 20250704)
  -j, --jobs N         threads per process (default: the processor count; 1 under MPI)
  --summary FILE       write the summary as JSON: queries, disagreements, seconds, the
                       counts per family and predicate, the reported disagreements
  --reports N          disagreements shrunk and reported, the first in query order
                       (default 100; all are counted)
  --checkpoint DIR     where finished stripes (about 10^6 queries each) are kept
                       (default exidel-fuzz-checkpoint); removed when the campaign ends
  --resume             continue the campaign whose checkpoint is in DIR (same options)
  --keep-checkpoint    keep DIR after the campaign ends
  --no-checkpoint      keep no checkpoint
  --no-progress        no progress bar (drawn only on a terminal anyway)
  -h, --help           show this help

MPI: under mpirun (Open MPI), ranks take stripes in turn and rank 0 prints the output and
writes the one summary, identical to a single process's but for "seconds" and "run".
DIR must then be on a file system every rank sees.

Exit status: 0 no disagreement, 1 disagreements (or an I/O error), 2 bad options.

Kernels:
)";

std::string fuzz_help() {
    std::string families;
    for (const testing::FamilyInfo& f : testing::all_families()) {
        if (!families.empty()) families += ", ";
        if (families.size() - families.rfind('\n') + f.name.size() > 56) families += "\n                       ";
        families += f.name;
    }
    return std::string(fuzz_help_head) + families + std::string(fuzz_help_tail) + kernel_help();
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
        if (auto [q, ec2] = std::from_chars(text.data(), end, d); ec2 == std::errc() && q == end &&
                                                                   d >= 1 && d <= double(limit) &&
                                                                   d == std::floor(d)) {
            return std::uint64_t(d);
        }
    }
    throw std::invalid_argument(name + " takes a whole number from 1 to 2^62 (1000, 1e9), got '" + text + "'");
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
            throw std::invalid_argument("--predicates: unknown predicate '" + name +
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
        out << "# query " << d.index << " (" << testing::family_name(d.family) << "): " << o.kernel << ' '
            << sign_text(d.kernel_sign) << ", " << o.reference << ' ' << sign_text(d.reference_sign)
            << "; as drawn: " << research::query_line(d.predicate, std::span(d.query.data(), n)) << '\n'
            << research::query_line(d.predicate, std::span(d.shrunk.data(), n)) << "  # " << o.kernel << ' '
            << sign_text(d.shrunk_kernel_sign) << ", " << o.reference << ' ' << sign_text(d.shrunk_reference_sign)
            << " (" << d.shrink_steps << " shrinks)\n";
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
            per_predicate += "  " + std::string(width > count.size() ? width - count.size() : 0, ' ') + count;
        }
        char line[120];
        std::snprintf(line, sizeof line, "# %-20s %12llu %14llu", std::string(testing::family_name(o.families[f])).c_str(),
                      static_cast<unsigned long long>(sum.queries), static_cast<unsigned long long>(sum.disagreements));
        out << line << per_predicate << '\n';
    }
    const double rate = r.seconds > 0 ? double(r.total.queries - r.resumed_queries) / r.seconds : 0;
    char line[240];
    std::snprintf(line, sizeof line,
                  "# %llu queries, %llu disagreements (%s against %s), %.1f s, %.3g queries/s on %d rank%s x %u "
                  "thread%s%s\n",
                  static_cast<unsigned long long>(r.total.queries),
                  static_cast<unsigned long long>(r.total.disagreements), o.kernel.c_str(), o.reference.c_str(),
                  r.seconds, rate, r.ranks, r.ranks == 1 ? "" : "s", o.jobs, o.jobs == 1 ? "" : "s",
                  r.resumed_queries ? (", " + std::to_string(r.resumed_queries) + " resumed").c_str() : "");
    out << line;
}

int fuzz_predicates_command(std::span<const std::string_view> args, Team& team) {
    CommandLine cli("fuzz predicates", fuzz_help());
    research::PredicateFuzzOptions o;
    o.checkpoint = "exidel-fuzz-checkpoint";
    std::optional<std::string> summary;
    std::optional<unsigned> jobs;
    bool keep_checkpoint = false, no_checkpoint = false;
    cli.app.add_option("-k,--kernel", o.kernel);
    cli.app.add_option("-r,--reference", o.reference);
    cli.app.add_option_function<std::string>("--families,--family", [&o](const std::string& v) {
        o.families = v == "all" ? std::vector<testing::Family>{} : research::parse_families(v);
    });
    cli.app.add_option_function<std::string>("--predicates,--predicate",
                                             [&o](const std::string& v) { o.predicates = parse_predicates(v); });
    cli.app.add_option_function<std::string>("-n,--queries",
                                             [&o](const std::string& v) { o.queries = parse_count(v, "--queries"); });
    cli.app.add_option_function<std::string>("--seed", [&o](const std::string& v) {
        std::uint64_t s = 0;
        const char* end = v.data() + v.size();
        if (auto [p, ec] = std::from_chars(v.data(), end, s); ec != std::errc() || p != end) {
            throw std::invalid_argument("--seed takes a whole number from 0 to 2^64 - 1, got '" + v + "'");
        }
        o.seed = s;
    });
    cli.app.add_option_function<std::string>("-j,--jobs", [&jobs](const std::string& v) {
        const std::uint64_t n = parse_count(v, "--jobs");
        if (n > 1024) throw std::invalid_argument("--jobs takes at most 1024, got '" + v + "'");
        jobs = unsigned(n);
    });
    cli.app.add_option_function<std::string>("--reports", [&o](const std::string& v) {
        o.max_reports = v == "0" ? 0 : std::size_t(parse_count(v, "--reports"));
    });
    cli.app.add_option("--summary", summary);
    cli.app.add_option_function<std::string>("--checkpoint", [&o](const std::string& v) { o.checkpoint = v; });
    cli.app.add_flag("--resume", o.resume);
    cli.app.add_flag("--keep-checkpoint", keep_checkpoint);
    cli.app.add_flag("--no-checkpoint", no_checkpoint);
    cli.app.add_flag_callback("--no-progress", [&o] { o.progress = false; });
    if (const std::optional<int> status = cli.parse(args)) return *status;
    if (no_checkpoint && (o.resume || keep_checkpoint)) {
        return cli.usage_error("--no-checkpoint with --resume or --keep-checkpoint");
    }
    if (no_checkpoint) o.checkpoint.clear();
    for (const std::string& k : {o.kernel, o.reference}) {
        std::string error;
        if (!parse_kernel(k, error)) return cli.usage_error(error);
    }
    o.jobs = jobs ? *jobs : team.size() > 1 ? 1u : std::max(1u, std::thread::hardware_concurrency());

    research::PredicateFuzzResult r;
    try {
        r = research::fuzz_predicates(o, team);
    } catch (const std::invalid_argument& e) {
        return cli.usage_error(e.what());
    } catch (const std::exception& e) {
        std::cerr << "exidel fuzz predicates: " << e.what() << '\n';
        team.fail();  // under MPI: the other ranks stop too
        return exit_failure;
    }
    if (team.rank() != 0) return exit_ok;  // rank 0 reports and decides the status
    print_report(std::cout, r);
    std::cout.flush();
    if (summary) {
        std::ofstream file(*summary, std::ios::binary | std::ios::trunc);
        file << research::summary_json(r);
        file.flush();
        if (!file) {
            std::cerr << "exidel fuzz predicates: cannot write '" << *summary << "'\n";
            return exit_failure;
        }
    }
    if (!o.checkpoint.empty() && !keep_checkpoint) {
        std::error_code ec;
        std::filesystem::remove_all(o.checkpoint, ec);
    }
    return r.total.disagreements == 0 ? exit_ok : exit_failure;
}

}  // namespace

int fuzz_command(std::span<const std::string_view> args) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        (args.empty() ? std::cerr : std::cout) << fuzz_help();
        return args.empty() ? exit_usage : exit_ok;
    }
    if (args[0] != "predicates") {
        std::cerr << "exidel fuzz: unknown campaign '" << args[0] << "' (predicates)\n";
        return exit_usage;
    }
    std::unique_ptr<Team> team = join_team();
    return fuzz_predicates_command(args.subspan(1), *team);
}

}  // namespace exidel::cli
