// exidel::research: what wrong signs do to the triangulation. Every kernel and in-circle
// policy (and, on request, insertion order) on the same point sets; each outcome
// classified by the exact certifier; the first wrong outcomes of each kind shrunk to
// minimal fixtures. And what each insertion order costs with the adaptive kernel, so the
// price of the paper's lexicographic order is on the page next to its outcomes.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/triangulate.hpp"
#include "exidel/predicates/dynamic.hpp"
#include "exidel/predicates/wrapper.hpp"
#include "exidel/io/points.hpp"
#include "exidel/research/graphics.hpp"
#include "exidel/research/studies.hpp"

namespace exidel::research {

namespace {

constexpr std::uint64_t triangulation_study_id = 3;

struct GuardExceeded {};

/// Any kernel, with a budget of predicate calls: the run is abandoned (by an exception,
/// which the triangulation's vectors survive) when the budget is spent. The algorithm
/// has its own guards and never loops; this one makes "never a hang" independent of
/// that claim.
template <PredicateKernel K>
struct GuardedKernel : KernelWrapper<GuardedKernel<K>> {
    static constexpr bool is_exact = K::is_exact;
    K kernel;
    std::uint64_t budget;
    mutable std::uint64_t calls = 0;  // mutable: the kernel interface is const

    GuardedKernel(const K& k, std::uint64_t b) : kernel(k), budget(b) {}
    std::string name() const { return kernel.name(); }
    /// Every predicate of the list (KernelWrapper): one call of the budget, then K's.
    template <class Points>
    Sign answer(Predicate which, const Points& points) const {
        if (++calls > budget) throw GuardExceeded{};
        return evaluate(kernel, which, points);
    }
};
static_assert(PredicateKernel<GuardedKernel<DoubleKernel>>);

constexpr delaunay::InCirclePolicy both_policies[] = {delaunay::InCirclePolicy::determinant,
                                                      delaunay::InCirclePolicy::cosine};

bool is_wrong(Outcome o) { return o != Outcome::delaunay; }

bool is_external(const Method& m) { return m.algorithm == delaunay::Algorithm::external; }
bool is_paper_order(const Method& m) {
    return is_external(m) && m.order == delaunay::Strategy::lexicographic;
}

/// What the "order" column shows: the insertion order of the external algorithm; other
/// algorithms take none.
std::string order_name(const Method& m) {
    return is_external(m) ? std::string(delaunay::to_string(m.order)) : "-";
}

/// The flags that make `exidel study replay` and `exidel triangulate` run `method` as the
/// study did. replay's default is the paper's order, triangulate's is auto, so only the
/// triangulate line always names it.
std::string algorithm_flag(const Method& m) {
    return is_external(m) ? "" : " --algorithm " + std::string(delaunay::to_string(m.algorithm));
}
std::string replay_order_flags(const Method& m) {
    if (!is_external(m)) return algorithm_flag(m);
    return is_paper_order(m) ? "" : " --order " + std::string(delaunay::to_string(m.order));
}

/// value / points with two decimals ("-" for no points).
std::string per_point(std::uint64_t value, std::size_t points) {
    if (points == 0) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", double(value) / double(points));
    return buf;
}

std::uint64_t orientations(const delaunay::Counters& c) {
    return c.seed_orientations + c.tangent_orientations + c.visible_search_orientations +
           c.merge_orientations + c.location_orientations + c.cavity_orientations;
}
std::uint64_t incircle_tests(const delaunay::Counters& c) {
    return c.incircle_tests + c.merge_incircle_tests;
}

/// One point set's work under one order (the work table's unit).
struct WorkSample {
    delaunay::Counters counters;
    std::uint64_t distance_comparisons = 0;
    std::size_t strips = 1;
    bool certified = false;
};

/// Triangulates with the adaptive predicates, instrumented. StageCountingKernel is the
/// adaptive kernel plus per-predicate call counts: the algorithm's Counters do not count
/// the radial order's sort, the kernel does.
WorkSample measure_work(std::span<const Point2> points, const Method& method) {
    const StageCountingKernel kernel;
    const delaunay::Result r = delaunay::triangulate<delaunay::Instrumentation::counters>(
        points, kernel, study_options(delaunay::InCirclePolicy::determinant, method));
    WorkSample w;
    w.counters = r.counters;
    for (std::uint64_t v : kernel.counts[compare_distance_row]) w.distance_comparisons += v;
    w.strips = r.strips;
    w.certified = r.ok() && delaunay::certify(points, r.triangulation).ok();
    return w;
}

/// The items a comma-separated list of names and "all" (every item of `all`) spells, in
/// the order given, repeats dropped; `lookup` maps a name to an item. Throws
/// std::invalid_argument naming the `expected` spellings.
template <class T, class Lookup>
std::vector<T> parse_names(std::string_view list, std::span<const T> all, Lookup lookup,
                           const std::string& what, const std::string& expected) {
    std::vector<T> out;
    const auto add = [&](T item) {
        if (std::find(out.begin(), out.end(), item) == out.end()) out.push_back(item);
    };
    while (!list.empty()) {
        const std::size_t comma = list.find(',');
        const std::string_view name = list.substr(0, comma);
        if (name == "all") {
            for (T item : all) add(item);
        } else if (const std::optional<T> item = lookup(name)) {
            add(*item);
        } else {
            throw std::invalid_argument("unknown " + what + " '" + std::string(name) +
                                        "' (expected " + expected + ")");
        }
        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    }
    if (out.empty()) throw std::invalid_argument("empty " + what + " list");
    return out;
}

std::string describe(const Classification& c) {
    return std::string(to_string(c.outcome)) + (c.detail.empty() ? "" : " (" + c.detail + ")");
}

}  // namespace

std::string_view policy_name(delaunay::InCirclePolicy p) {
    return p == delaunay::InCirclePolicy::cosine ? "cosine" : "determinant";
}

std::string triangulate_order_flags(const Method& m) {
    if (!is_external(m)) return algorithm_flag(m);
    std::string flags = " --order " + std::string(delaunay::to_string(m.order));
    if (m.order == delaunay::Strategy::strips)
        flags += " --strip-points " + std::to_string(study_strip_points);
    return flags;
}

std::string_view to_string(Outcome o) noexcept {
    switch (o) {
        case Outcome::delaunay: return "delaunay";
        case Outcome::not_delaunay: return "not_delaunay";
        case Outcome::invalid: return "invalid";
        case Outcome::failure: return "failure";
        case Outcome::guard: return "guard";
    }
    return "?";
}

delaunay::Options study_options(delaunay::InCirclePolicy policy, Method method) {
    return delaunay::Options{}
        .with_algorithm(method.algorithm)
        .with_incircle(policy)
        .with_strategy(method.order)
        .with_threads(1)
        .with_strip_points(study_strip_points);
}

std::vector<Method> methods_of(std::span<const delaunay::Algorithm> algorithms,
                               std::span<const delaunay::Strategy> orders) {
    std::vector<Method> out;
    for (const delaunay::AlgorithmInfo& info : delaunay::algorithms()) {
        if (std::find(algorithms.begin(), algorithms.end(), info.id) == algorithms.end()) continue;
        if (!info.takes_order) {
            out.emplace_back(info.id, delaunay::Strategy::automatic);
            continue;
        }
        for (delaunay::Strategy o : orders) out.emplace_back(info.id, o);
    }
    return out;
}

std::vector<delaunay::Strategy> parse_orders(std::string_view list) {
    return parse_names<delaunay::Strategy>(
        list, all_orders,
        [](std::string_view name) -> std::optional<delaunay::Strategy> {
            for (delaunay::Strategy s : all_orders) {
                if (delaunay::to_string(s) == name) return s;
            }
            return std::nullopt;
        },
        "order", "lexicographic, radial, strips or all");
}

std::vector<delaunay::Algorithm> parse_algorithms(std::string_view list) {
    std::vector<delaunay::Algorithm> every;
    for (const delaunay::AlgorithmInfo& info : delaunay::algorithms()) every.push_back(info.id);
    return parse_names<delaunay::Algorithm>(list, every, delaunay::algorithm_from_name, "algorithm",
                                            delaunay::algorithm_spellings() + " or all");
}

Classification classify_triangulation(std::span<const Point2> points, const Kernel& kernel,
                                      delaunay::InCirclePolicy policy, Method method,
                                      std::uint64_t call_budget) {
    const std::uint64_t n = points.size();
    const std::uint64_t budget = call_budget ? call_budget : 64 * n * n + 1'000'000;
    const delaunay::Options options = study_options(policy, method);
    std::optional<delaunay::Result> result;
    try {
        result = std::visit(
            [&](const auto& k) {
                const GuardedKernel<std::decay_t<decltype(k)>> guarded{k, budget};
                // Through DynamicKernel: the library's compiled algorithms serve every
                // kernel, and this file compiles none (an indirect call per predicate).
                return delaunay::triangulate(points, DynamicKernel(guarded), options);
            },
            kernel);
    } catch (const GuardExceeded&) {
        return {Outcome::guard, "more than " + std::to_string(budget) + " predicate calls"};
    }
    if (result->failure)
        return {Outcome::failure, std::string(delaunay::to_string(result->failure->kind))};
    const delaunay::Certificate cert = delaunay::certify(points, result->triangulation);
    if (cert.ok()) return {Outcome::delaunay, ""};
    // The Delaunay check runs last and only when every earlier check passed, so a first
    // finding of not_delaunay means all of them are (the list is capped at 64).
    if (cert.findings.front().kind == delaunay::FindingKind::not_delaunay) {
        return {Outcome::not_delaunay, std::to_string(cert.total_findings) + " edges"};
    }
    return {Outcome::invalid, std::string(delaunay::to_string(cert.findings.front().kind))};
}

std::vector<Point2> shrink_failing_input(std::vector<Point2> points, const Kernel& kernel,
                                         delaunay::InCirclePolicy policy,
                                         const Classification& target, Method method) {
    const auto still_fails = [&](const std::vector<Point2>& candidate) {
        const Classification c = classify_triangulation(candidate, kernel, policy, method);
        return c.outcome == target.outcome &&
               (target.outcome != Outcome::failure || c.detail == target.detail);
    };
    // Delta debugging: remove chunks of halving size while the outcome persists; at size
    // one, sweep until no single point can go (the result is 1-minimal). The attempt
    // budget bounds the time on large inputs; what it returns always still fails.
    std::size_t attempts = 0;
    constexpr std::size_t max_attempts = 20000;
    std::size_t chunk = std::max<std::size_t>(points.size() / 2, 1);
    for (;;) {
        bool removed = false;
        for (std::size_t start = 0; start < points.size() && attempts < max_attempts;) {
            const std::size_t end = std::min(points.size(), start + chunk);
            std::vector<Point2> candidate;
            candidate.reserve(points.size());
            candidate.insert(candidate.end(), points.begin(),
                             points.begin() + std::ptrdiff_t(start));
            candidate.insert(candidate.end(), points.begin() + std::ptrdiff_t(end), points.end());
            ++attempts;
            if (still_fails(candidate)) {
                points = std::move(candidate);
                removed = true;
            } else {
                start = end;
            }
        }
        if (attempts >= max_attempts) break;
        if (chunk > 1) {
            chunk = std::max<std::size_t>(chunk / 2, 1);
        } else if (!removed) {
            break;
        }
    }
    return points;
}

std::string fixture_text(std::span<const Point2> points, std::span<const std::string> header) {
    std::string s;
    for (const std::string& line : header) s += "# " + line + "\n";
    char buf[80];
    for (const Point2& p : points) {
        std::snprintf(buf, sizeof buf, "%a %a\n", p.x, p.y);
        s += buf;
    }
    return s;
}

Classification replay_fixture(const std::filesystem::path& file, const Kernel& kernel,
                              delaunay::InCirclePolicy policy, Method method) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + file.string());
    const std::vector<Point2> points =
        io::read_points(in, io::point_format_from_path(file.string()));
    return classify_triangulation(points, kernel, policy, method);
}

namespace {

// =================================================================================
// The study in four steps: plan (what runs, from the options), run (every point set,
// in parallel), aggregate (counts, fixtures, work, rates) and report (the files).

/// One point set of the work list: its family, seed and size.
struct PointSet {
    testing::Family family;
    std::size_t seed_index = 0;
    std::size_t size = 0;
};

/// What a triangulation study runs, decided from its options before anything runs.
struct StudyPlan {
    std::vector<Kernel> kernels;
    std::vector<testing::Family> families;
    std::vector<delaunay::Strategy> orders;
    std::vector<Method> methods;       ///< the outcome tables' (and fixtures') methods
    std::vector<Method> work_methods;  ///< the work table's: every order
    /// More than one algorithm: every table gets an "algorithm" column (with one, the
    /// tables keep the columns they had before the registry).
    bool algorithm_column = false;
    std::size_t seeds = 0;
    std::vector<std::size_t> sizes;
    std::vector<unsigned> bits;        ///< the MPFR precisions of the failure rates
    std::vector<Kernel> mpfr_kernels;  ///< one per entry of bits
    std::size_t shrink_per_class = 0;
    /// The work list: one point set per (family, seed), families outermost. Its contents
    /// depend only on the options, never on --jobs.
    std::vector<PointSet> sets;

    /// Runs per method on one point set: every kernel with both policies.
    std::size_t runs_per_method() const { return kernels.size() * std::size(both_policies); }
};

/// What one point set gave: the points, every method x kernel x policy classified (in
/// that nesting), the work of every work method with the adaptive kernel, and per method,
/// then precision, whether the MPFR kernel's outcome was wrong (1) or not (0).
struct SetResult {
    std::vector<Point2> points;
    std::vector<TriangulationRun> runs;
    std::vector<WorkSample> work;
    std::vector<std::uint8_t> wrong_at;
};

using OutcomeCounts = std::array<std::uint64_t, all_outcomes.size()>;
/// Positions in the plan's lists: (family, method, kernel, policy) and (method, kernel,
/// policy).
using FamilyCell = std::tuple<std::size_t, std::size_t, std::size_t, int>;
using Cell = std::tuple<std::size_t, std::size_t, int>;

/// m[key], or an empty value when no run counted there.
template <class Map>
const typename Map::mapped_type& count_at(const Map& m, const typename Map::key_type& key) {
    static const typename Map::mapped_type none{};
    const auto it = m.find(key);
    return it == m.end() ? none : it->second;
}

/// A wrong outcome shrunk to a fixture: its record (the file's name included), the
/// outcome of the run it came from (the fixture replays when its own outcome is the
/// same), and the file's text.
struct ShrunkFixture {
    Fixture fixture;
    Outcome original;
    std::string text;
};

/// The study's results put together: the runs, work and precision rates of the study
/// (its tables and report are the report step's), the outcome counts, and the fixtures.
struct StudyTotals {
    TriangulationStudy study;
    std::map<FamilyCell, OutcomeCounts> counts;
    std::map<Cell, OutcomeCounts> totals;
    /// Wrong outcomes by kind ("failure (no_visible_edge)", "not_delaunay", ...).
    std::map<Cell, std::map<std::string, std::uint64_t>> details;
    std::vector<OrderWork> overall;  ///< the work of each work method over all families
    std::vector<ShrunkFixture> fixtures;
};

StudyPlan plan_study(const TriangulationOptions& options, const RunOptions& run) {
    StudyPlan plan;
    std::vector<std::string> kernel_names = options.kernels;
    if (kernel_names.empty()) {
        kernel_names = {"double", "long-double", "mpfr:53", "mpfr:106", "adaptive", "exact"};
    }
    for (const std::string& k : kernel_names) plan.kernels.push_back(parse_kernel(k));
    plan.families = options.families;
    if (plan.families.empty()) {
        for (const auto& info : testing::all_families()) plan.families.push_back(info.family);
    }
    plan.orders = options.orders.empty()
                      ? std::vector<delaunay::Strategy>{delaunay::Strategy::lexicographic}
                      : options.orders;
    for (delaunay::Strategy o : plan.orders) {
        if (std::find(all_orders.begin(), all_orders.end(), o) == all_orders.end()) {
            throw std::invalid_argument(
                "the triangulation study runs lexicographic, radial or strips, not " +
                std::string(delaunay::to_string(o)));
        }
    }
    std::vector<delaunay::Algorithm> algorithms = options.algorithms;
    if (algorithms.empty()) {
        for (const delaunay::AlgorithmInfo& info : delaunay::algorithms())
            algorithms.push_back(info.id);
    }
    plan.methods = methods_of(algorithms, plan.orders);
    plan.work_methods = methods_of(algorithms, all_orders);
    plan.algorithm_column = algorithms.size() > 1;
    plan.seeds = options.seeds ? options.seeds : (run.quick ? 4 : 16);
    plan.sizes =
        options.sizes.empty() ? std::vector<std::size_t>{50, 100, 200, 500} : options.sizes;
    for (std::size_t n : plan.sizes) {
        if (n < 1 || n > 100000)
            throw std::invalid_argument("triangulation sizes must be in [1, 100000]");
    }
    plan.bits = options.precision_bits.empty()
                    ? std::vector<unsigned>{12, 16, 20, 24, 32, 40, 48, 53, 64, 80, 106}
                    : options.precision_bits;
    for (unsigned b : plan.bits)
        plan.mpfr_kernels.push_back(parse_kernel("mpfr:" + std::to_string(b)));
    plan.shrink_per_class = options.shrink_per_class;
    for (testing::Family f : plan.families) {
        for (std::size_t s = 0; s < plan.seeds; ++s)
            plan.sets.push_back({f, s, plan.sizes[s % plan.sizes.size()]});
    }
    return plan;
}

/// Draws every point set of the plan and runs everything on it, on run.jobs threads
/// (each set's result in its own slot: the results do not depend on the thread count).
std::vector<SetResult> run_study(const StudyPlan& plan, const RunOptions& run) {
    std::vector<SetResult> results(plan.sets.size());
    Progress progress("triangulation", plan.sets.size(), run.progress);
    for_each_chunk(plan.sets.size(), run.jobs, &progress, [&](std::size_t i) {
        const PointSet& set = plan.sets[i];
        SetResult& r = results[i];
        {
            const std::lock_guard lock(rapidcheck_mutex());
            const rc::Random random(derive_seed(
                run.seed, {triangulation_study_id, std::uint64_t(set.family), set.seed_index}));
            r.points = testing::gen_points(set.family, set.size)(random).value();
        }
        for (const Method& m : plan.methods) {
            for (const Kernel& k : plan.kernels) {
                for (delaunay::InCirclePolicy p : both_policies) {
                    r.runs.push_back({set.family, set.seed_index, set.size, kernel_name(k), p,
                                      classify_triangulation(r.points, k, p, m), m.order,
                                      m.algorithm});
                }
            }
        }
        for (const Method& m : plan.work_methods) r.work.push_back(measure_work(r.points, m));
        for (const Method& m : plan.methods) {
            for (const Kernel& k : plan.mpfr_kernels) {
                const Classification c =
                    classify_triangulation(r.points, k, delaunay::InCirclePolicy::determinant, m);
                r.wrong_at.push_back(is_wrong(c.outcome) ? 1 : 0);
            }
        }
    });
    return results;
}

/// The name of a fixture's file inside run.out, and its text: a header saying where it
/// comes from and how to replay it, then the points.
ShrunkFixture make_fixture(const TriangulationRun& from, const Kernel& k, std::size_t original_size,
                           std::vector<Point2> points, const RunOptions& run) {
    const std::string kname = kernel_name(k);
    const Method method(from.algorithm, from.order);
    const std::string oname = is_external(method)
                                  ? order_name(method)
                                  : std::string(delaunay::to_string(method.algorithm));
    // The paper's order keeps the names fixtures had before orders existed; another
    // algorithm's fixtures carry its name instead of an order.
    const std::string file = "fixtures/" + std::string(to_string(from.result.outcome)) + "-" +
                             kernel_file_name(k) + "-" + std::string(policy_name(from.policy)) +
                             (is_paper_order(method) ? "" : "-" + oname) + "-" +
                             std::string(testing::family_name(from.family)) + "-s" +
                             std::to_string(from.seed_index) + ".xy";
    // The shrunk set's own classification (its detail may differ from the original's
    // for invalid and not_delaunay outcomes, which shrink by outcome only).
    const Classification now = classify_triangulation(points, k, from.policy, method);
    const std::string cmd_flags =
        "--kernel " + kname + " --incircle " + std::string(policy_name(from.policy));
    const std::vector<std::string> header{
        "exidel study triangulation fixture: " + describe(now),
        "kernel " + kname + ", incircle policy " + std::string(policy_name(from.policy)) +
            (is_external(method) ? ", order " : ", algorithm ") + oname,
        "family " + std::string(testing::family_name(from.family)) + ", seed index " +
            std::to_string(from.seed_index) + " of study seed " + std::to_string(run.seed) + ", " +
            std::to_string(original_size) + " points shrunk to " + std::to_string(points.size()),
        "reproduce: exidel study replay -i FILE " + cmd_flags + replay_order_flags(method),
        "      and: exidel triangulate -i FILE " + cmd_flags + triangulate_order_flags(method) +
            (now.outcome == Outcome::failure ? "   (exit status 1: triangulation failed)"
                                             : "   (output differs from --kernel exact)"),
    };
    return {
        {file, kname, from.policy, now, original_size, points.size(), from.order, from.algorithm},
        from.result.outcome,
        fixture_text(points, header)};
}

/// Counts the outcomes per cell, shrinks the first wrong outcomes of each kind (in
/// parallel) into fixtures, sums the work per family and over all of them, and the
/// failure rates per method and precision. Everything in the order of the work list, so
/// nothing depends on which thread ran what.
StudyTotals aggregate_study(const StudyPlan& plan, const std::vector<SetResult>& results,
                            const RunOptions& run) {
    StudyTotals t;
    // The wrong outcomes to shrink: at most shrink_per_class per (method, kernel, policy,
    // outcome), the first ones in the work list.
    struct Candidate {
        std::size_t set, kernel;
        TriangulationRun run;
    };
    std::vector<Candidate> to_shrink;
    std::map<std::tuple<std::size_t, std::size_t, int, int>, std::size_t> shrink_count;
    const std::size_t per_method = plan.runs_per_method();
    for (std::size_t si = 0; si < results.size(); ++si) {
        const auto fpos = std::size_t(
            std::find(plan.families.begin(), plan.families.end(), plan.sets[si].family) -
            plan.families.begin());
        const std::vector<TriangulationRun>& runs = results[si].runs;
        for (std::size_t r = 0; r < runs.size(); ++r) {
            const TriangulationRun& tr = runs[r];
            const std::size_t opos = r / per_method;
            const std::size_t kpos = r % per_method / std::size(both_policies);
            const int pol = int(tr.policy);
            const auto o = std::size_t(tr.result.outcome);
            ++t.counts[{fpos, opos, kpos, pol}][o];
            ++t.totals[{opos, kpos, pol}][o];
            if (is_wrong(tr.result.outcome)) {
                // Edge counts of not_delaunay outcomes would make one entry per run.
                ++t.details[{opos, kpos, pol}][tr.result.outcome == Outcome::not_delaunay
                                                   ? std::string(to_string(tr.result.outcome))
                                                   : describe(tr.result)];
                std::size_t& taken = shrink_count[{opos, kpos, pol, int(o)}];
                if (taken < plan.shrink_per_class && tr.result.outcome != Outcome::guard) {
                    ++taken;
                    to_shrink.push_back({si, kpos, tr});
                }
            }
            t.study.runs.push_back(tr);
        }
    }

    for (std::size_t op = 0; op < plan.methods.size(); ++op) {
        for (std::size_t b = 0; b < plan.bits.size(); ++b) {
            PrecisionRate rate{plan.methods[op], plan.bits[b], 0, 0};
            for (const SetResult& r : results) {
                rate.wrong += r.wrong_at[op * plan.bits.size() + b];
                ++rate.runs;
            }
            t.study.precision.push_back(rate);
        }
    }

    // The work of each method, per family and over all families.
    for (const Method& m : plan.work_methods) {
        t.overall.push_back({plan.families.front(), m.order, m.algorithm, 0, 0, {}, 0, 0, 0});
    }
    for (testing::Family f : plan.families) {
        for (std::size_t o = 0; o < plan.work_methods.size(); ++o) {
            const Method& m = plan.work_methods[o];
            OrderWork w{f, m.order, m.algorithm, 0, 0, {}, 0, 0, 0};
            for (std::size_t si = 0; si < results.size(); ++si) {
                if (plan.sets[si].family != f) continue;
                const WorkSample& s = results[si].work[o];
                ++w.sets;
                w.points += results[si].points.size();
                w.counters += s.counters;
                w.distance_comparisons += s.distance_comparisons;
                w.merges += s.strips - 1;
                w.certified += s.certified;
            }
            OrderWork& all = t.overall[o];
            all.sets += w.sets;
            all.points += w.points;
            all.counters += w.counters;
            all.distance_comparisons += w.distance_comparisons;
            all.merges += w.merges;
            all.certified += w.certified;
            t.study.work.push_back(w);
        }
    }

    // Shrink the chosen wrong outcomes (in parallel; each is a pure function of its input).
    std::vector<std::vector<Point2>> shrunk(to_shrink.size());
    {
        Progress shrink_progress("shrinking", to_shrink.size(), run.progress);
        for_each_chunk(to_shrink.size(), run.jobs, &shrink_progress, [&](std::size_t i) {
            const Candidate& c = to_shrink[i];
            shrunk[i] =
                shrink_failing_input(results[c.set].points, plan.kernels[c.kernel], c.run.policy,
                                     c.run.result, Method(c.run.algorithm, c.run.order));
        });
    }
    for (std::size_t i = 0; i < to_shrink.size(); ++i) {
        const Candidate& c = to_shrink[i];
        t.fixtures.push_back(make_fixture(c.run, plan.kernels[c.kernel],
                                          results[c.set].points.size(), std::move(shrunk[i]), run));
        t.study.fixtures.push_back(t.fixtures.back().fixture);
    }
    return t;
}

std::vector<std::string> join(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

/// The columns that name a method in the report's tables: "algorithm" (only when several
/// run) and "order".
struct MethodColumns {
    bool algorithm_column = false;

    std::vector<std::string> cells(const Method& m) const {
        std::vector<std::string> cells;
        if (algorithm_column) cells.emplace_back(delaunay::to_string(m.algorithm));
        cells.push_back(order_name(m));
        return cells;
    }
    std::vector<std::string> header(std::vector<std::string> before,
                                    const std::vector<std::string>& after) const {
        if (algorithm_column) before.emplace_back("algorithm");
        before.emplace_back("order");
        return join(std::move(before), after);
    }
};

/// The outcome counts per family, method, kernel and policy (the study's main table).
Table outcome_table(const StudyPlan& plan, const StudyTotals& t, const MethodColumns& columns) {
    Table table;
    table.header = columns.header({"family"}, {"kernel", "incircle"});
    for (Outcome o : all_outcomes) table.header.emplace_back(to_string(o));
    for (std::size_t f = 0; f < plan.families.size(); ++f) {
        for (std::size_t op = 0; op < plan.methods.size(); ++op) {
            for (std::size_t k = 0; k < plan.kernels.size(); ++k) {
                for (delaunay::InCirclePolicy p : both_policies) {
                    const OutcomeCounts& row_counts = count_at(t.counts, {f, op, k, int(p)});
                    std::vector<std::string> row =
                        join(join({std::string(testing::family_name(plan.families[f]))},
                                  columns.cells(plan.methods[op])),
                             {kernel_name(plan.kernels[k]), std::string(policy_name(p))});
                    for (std::uint64_t v : row_counts) row.push_back(std::to_string(v));
                    table.rows.push_back(std::move(row));
                }
            }
        }
    }
    return table;
}

/// The outcome counts per method, kernel and policy over every family, with the wrong
/// outcomes by kind.
Table summary_table(const StudyPlan& plan, const StudyTotals& t, const MethodColumns& columns) {
    Table summary;
    summary.header = columns.header({}, {"kernel", "incircle", "runs"});
    for (Outcome o : all_outcomes) summary.header.emplace_back(to_string(o));
    summary.header.emplace_back("wrong outcomes by kind");
    for (std::size_t op = 0; op < plan.methods.size(); ++op) {
        for (std::size_t k = 0; k < plan.kernels.size(); ++k) {
            for (delaunay::InCirclePolicy p : both_policies) {
                const OutcomeCounts& counts = count_at(t.totals, {op, k, int(p)});
                std::uint64_t runs = 0;
                for (std::uint64_t v : counts) runs += v;
                std::vector<std::string> row =
                    join(columns.cells(plan.methods[op]),
                         {kernel_name(plan.kernels[k]), std::string(policy_name(p)),
                          std::to_string(runs)});
                for (std::uint64_t v : counts) row.push_back(std::to_string(v));
                std::string kinds;
                for (const auto& [what, n] : count_at(t.details, {op, k, int(p)})) {
                    kinds += (kinds.empty() ? "" : "; ") + what + ": " + std::to_string(n);
                }
                row.push_back(kinds.empty() ? "-" : kinds);
                summary.rows.push_back(std::move(row));
            }
        }
    }
    return summary;
}

/// The work per point of each method, per family, then over all families.
Table work_table(const StudyTotals& t, const MethodColumns& columns) {
    Table table;
    table.header = columns.header(
        {"family"}, {"point sets", "points", "flips/point", "in-circle tests/point",
                     "orientations/point", "distance comparisons/point", "location steps/point",
                     "triangles created/point", "merges", "certified"});
    const auto row = [&](std::string family, const OrderWork& w) {
        table.rows.push_back(
            join(join({std::move(family)}, columns.cells(Method(w.algorithm, w.order))),
                 {std::to_string(w.sets), std::to_string(w.points),
                  per_point(w.counters.flips(), w.points),
                  per_point(incircle_tests(w.counters), w.points),
                  per_point(orientations(w.counters), w.points),
                  per_point(w.distance_comparisons, w.points),
                  per_point(w.counters.location_steps, w.points),
                  per_point(w.counters.triangles_created, w.points), std::to_string(w.merges),
                  std::to_string(w.certified) + "/" + std::to_string(w.sets)}));
    };
    for (const OrderWork& w : t.study.work) row(std::string(testing::family_name(w.family)), w);
    for (const OrderWork& w : t.overall) row("all families", w);
    return table;
}

/// The fixtures: file, method, kernel, policy, outcome, size, and whether they replay.
Table fixtures_table(const StudyTotals& t, const MethodColumns& columns) {
    Table table;
    table.header = columns.header(
        {"fixture"}, {"kernel", "incircle", "outcome", "points (original)", "replays"});
    for (const ShrunkFixture& s : t.fixtures) {
        const Fixture& f = s.fixture;
        table.rows.push_back(
            join(join({"`" + f.file + "`"}, columns.cells(Method(f.algorithm, f.order))),
                 {f.kernel, std::string(policy_name(f.policy)), describe(f.result),
                  std::to_string(f.size) + " (" + std::to_string(f.original_size) + ")",
                  f.result.outcome == s.original ? "yes" : "NO"}));
    }
    return table;
}

/// Writes the fixtures, the tables as CSV and the failure-rate plot into run.out, and
/// returns the study with its main table and report.
TriangulationStudy report_study(const StudyPlan& plan, StudyTotals t, const RunOptions& run) {
    const MethodColumns columns{plan.algorithm_column};
    TriangulationStudy& study = t.study;
    study.table = outcome_table(plan, t, columns);
    const Table summary = summary_table(plan, t, columns);
    const Table work = work_table(t, columns);
    const Table fixtures = fixtures_table(t, columns);
    for (const ShrunkFixture& s : t.fixtures) write_text_file(run.out / s.fixture.file, s.text);

    write_text_file(run.out / "triangulation.csv", study.table.csv());
    write_text_file(run.out / "triangulation_summary.csv", summary.csv());
    write_text_file(run.out / "triangulation_work.csv", work.csv());

    std::string sizes_text;
    for (std::size_t n : plan.sizes)
        sizes_text += (sizes_text.empty() ? "" : ", ") + std::to_string(n);
    std::string orders_text;
    for (delaunay::Strategy o : plan.orders)
        orders_text += (orders_text.empty() ? "" : ", ") + std::string(delaunay::to_string(o));
    std::string others_text;
    for (const Method& m : plan.methods) {
        if (!is_external(m))
            others_text +=
                ", and by the " + std::string(delaunay::to_string(m.algorithm)) + " algorithm";
    }
    study.report = Report("Triangulation outcomes per kernel and in-circle policy");
    std::string families_text;
    for (testing::Family f : plan.families) {
        families_text += (families_text.empty() ? "" : ", ") + std::string(testing::family_name(f));
    }
    if (plan.families.size() == testing::all_families().size())
        families_text = "Every family of lib/testing";
    study.report.paragraph(
        families_text + ", " + std::to_string(plan.seeds) + " point sets each (sizes " +
        sizes_text + ", cycled; seed " + std::to_string(run.seed) +
        "); every kernel and both in-circle "
        "policies triangulate the same point sets, in insertion order " +
        orders_text +
        (plan.orders.size() == 1 && plan.orders.front() == delaunay::Strategy::lexicographic
             ? " (the paper's algorithm)"
             : "") +
        others_text +
        ". Outcomes, decided by the exact certifier: "
        "**delaunay** (certified), **not_delaunay** (a valid triangulation with some edge not "
        "locally Delaunay), **invalid** (not a triangulation of the points; the certifier's first "
        "finding in the last column), **failure** (the algorithm detected the inconsistency and "
        "stopped), **guard** (the predicate-call budget of 64 n^2 + 10^6 ran out; never "
        "expected).");
    study.report.append(family_definitions(plan.families));
    study.report.table(summary);
    study.report.paragraph(
        "Minimal failing inputs (delta debugging until no single point can be removed), "
        "written as fixtures in hex floats:");
    if (fixtures.rows.empty()) {
        study.report.paragraph("(no wrong outcome, nothing to shrink)");
    } else {
        study.report.table(fixtures);
    }
    study.report.heading("Work per insertion order");
    study.report.paragraph(
        "The same point sets triangulated with the adaptive kernel (exact signs) and the "
        "determinant "
        "policy in each insertion order: **lexicographic** (the paper's order), **radial** "
        "(ascending "
        "exact distance from the bounding-box centre) and **strips** (strips of " +
        std::to_string(study_strip_points) +
        " points, each radial, merged by the Guibas-Stolfi zipper). "
        "Per input point: flips (edges eroded by insertions plus edges deleted by merges), "
        "in-circle "
        "tests and orientations of the algorithm (insertions and merges), and distance "
        "comparisons: the "
        "compare_distance calls of the radial sort, made only where its floating-point key cannot "
        "separate two points (counted by the kernel; the floating-point sort itself is not "
        "counted). "
        "Algorithms that locate their points (bowyer-watson: a walk; randomized: a history DAG) "
        "add "
        "location steps (triangles the walk entered, DAG nodes the descent passed) and their "
        "orientations "
        "count among the orientations; triangles created counts finite triangles, de Berg et al.'s "
        "quantity (at most 9n + 1 in expectation for the randomized algorithm, de Berg et al. 3rd "
        "ed., Section 9.4). "
        "For bowyer-watson, flips are the edges inside each cavity (what a split and Lawson's "
        "flips "
        "would have removed); for randomized, Lawson's flips. "
        "merges: strips merged over all sets; certified: results the exact certifier accepted.");
    study.report.table(work);
    // Failure rate against MPFR precision: one line per method.
    Table precision_table;
    precision_table.header = columns.header({}, {});
    for (unsigned b : plan.bits) precision_table.header.push_back("p = " + std::to_string(b));
    LinePlot plot;
    plot.title =
        "Triangulations not certified Delaunay, MPFR kernel at p bits (determinant policy)";
    plot.x_label = "significand bits p";
    plot.y_label = "share of point sets with a wrong outcome";
    Panel& panel = plot.panels.emplace_back();
    for (std::size_t op = 0; op < plan.methods.size(); ++op) {
        std::vector<std::string> row = columns.cells(plan.methods[op]);
        Series series;
        series.name = plan.algorithm_column
                          ? std::string(delaunay::to_string(plan.methods[op].algorithm))
                          : "";
        if (is_external(plan.methods[op])) {
            series.name += (series.name.empty() ? "" : " ") + std::string("(") +
                           order_name(plan.methods[op]) + ")";
        }
        for (std::size_t b = 0; b < plan.bits.size(); ++b) {
            const PrecisionRate& r = study.precision[op * plan.bits.size() + b];
            row.push_back(std::to_string(r.wrong) + "/" + std::to_string(r.runs));
            series.x.push_back(double(r.bits));
            series.y.push_back(r.runs ? double(r.wrong) / double(r.runs) : 0.0);
        }
        precision_table.rows.push_back(std::move(row));
        panel.series.push_back(std::move(series));
    }
    write_text_file(run.out / "triangulation_precision.csv", precision_table.csv());
    write_text_file(run.out / "precision.svg", render_svg(plot));
    study.report.heading("Failure rate against precision");
    study.report.paragraph(
        "The same point sets triangulated by each method with the MPFR kernel at p significand "
        "bits "
        "(the input coordinates rounded to p bits as the kernel reads them, every operation "
        "rounded "
        "to p bits) and the determinant policy; a run counts as wrong when its outcome is anything "
        "but certified Delaunay (not Delaunay, invalid, failure detected). Cells: wrong runs / "
        "point "
        "sets.");
    study.report.image("failure rate vs precision", "precision.svg");
    study.report.table(precision_table);
    study.report.heading("Per family");
    study.report.table(study.table);
    study.report.link("triangulation.csv", "triangulation.csv");
    study.report.link("triangulation_summary.csv", "triangulation_summary.csv");
    study.report.link("triangulation_work.csv", "triangulation_work.csv");
    study.report.link("triangulation_precision.csv", "triangulation_precision.csv");
    return std::move(t.study);
}

}  // namespace

TriangulationStudy run_triangulation_study(const TriangulationOptions& options,
                                           const RunOptions& run) {
    const StudyPlan plan = plan_study(options, run);
    const std::vector<SetResult> results = run_study(plan, run);
    return report_study(plan, aggregate_study(plan, results, run), run);
}

}  // namespace exidel::research
