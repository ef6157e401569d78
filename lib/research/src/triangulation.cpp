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
struct GuardedKernel {
    static constexpr bool is_exact = K::is_exact;
    K kernel;
    std::uint64_t budget;
    mutable std::uint64_t calls = 0;  // mutable: the kernel interface is const

    std::string name() const { return kernel.name(); }
    void spend() const {
        if (++calls > budget) throw GuardExceeded{};
    }
    Sign orient2d(Point2 a, Point2 b, Point2 c) const {
        spend();
        return kernel.orient2d(a, b, c);
    }
    Sign incircle(Point2 a, Point2 b, Point2 c, Point2 d) const {
        spend();
        return kernel.incircle(a, b, c, d);
    }
    Sign incircle_cosine(Point2 a, Point2 b, Point2 c, Point2 d) const {
        spend();
        return kernel.incircle_cosine(a, b, c, d);
    }
    Sign compare_distance(Point2 c, Point2 p, Point2 q) const {
        spend();
        return kernel.compare_distance(c, p, q);
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
                return delaunay::triangulate(points, guarded, options);
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

TriangulationStudy run_triangulation_study(const TriangulationOptions& options,
                                           const RunOptions& run) {
    std::vector<std::string> kernel_names = options.kernels;
    if (kernel_names.empty()) {
        kernel_names = {"double", "long-double", "mpfr:53", "mpfr:106", "adaptive", "exact"};
    }
    std::vector<Kernel> kernels;
    for (const std::string& k : kernel_names) kernels.push_back(parse_kernel(k));
    std::vector<testing::Family> families = options.families;
    if (families.empty()) {
        for (const auto& info : testing::all_families()) families.push_back(info.family);
    }
    const std::vector<delaunay::Strategy> orders =
        options.orders.empty() ? std::vector<delaunay::Strategy>{delaunay::Strategy::lexicographic}
                               : options.orders;
    for (delaunay::Strategy o : orders) {
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
    // What the outcome tables run, and what the work table runs (every order).
    const std::vector<Method> methods = methods_of(algorithms, orders);
    const std::vector<Method> work_methods = methods_of(algorithms, all_orders);
    // One algorithm: the tables keep the columns they had before the registry.
    const bool algorithm_column = algorithms.size() > 1;
    const std::size_t seeds = options.seeds ? options.seeds : (run.quick ? 4 : 16);
    const std::vector<std::size_t> sizes =
        options.sizes.empty() ? std::vector<std::size_t>{50, 100, 200, 500} : options.sizes;
    for (std::size_t n : sizes) {
        if (n < 1 || n > 100000)
            throw std::invalid_argument("triangulation sizes must be in [1, 100000]");
    }
    const std::size_t per_method = kernels.size() * std::size(both_policies);
    const std::vector<unsigned> bits =
        options.precision_bits.empty()
            ? std::vector<unsigned>{12, 16, 20, 24, 32, 40, 48, 53, 64, 80, 106}
            : options.precision_bits;
    std::vector<Kernel> mpfr_kernels;
    for (unsigned b : bits) mpfr_kernels.push_back(parse_kernel("mpfr:" + std::to_string(b)));

    // One chunk per (family, seed): one point set, every method, kernel and policy on it
    // (runs in that nesting), and the work of every work method with the adaptive kernel.
    struct Chunk {
        testing::Family family;
        std::size_t seed_index;
        std::vector<Point2> points;
        std::vector<TriangulationRun> runs;
        std::vector<WorkSample> work;
        std::vector<std::uint8_t> wrong_at;  // per method, then precision: 1 if not Delaunay
    };
    std::vector<Chunk> chunks;
    for (testing::Family f : families) {
        for (std::size_t s = 0; s < seeds; ++s) chunks.push_back({f, s, {}, {}, {}, {}});
    }
    Progress progress("triangulation", chunks.size(), run.progress);
    for_each_chunk(chunks.size(), run.jobs, &progress, [&](std::size_t i) {
        Chunk& c = chunks[i];
        const std::size_t n = sizes[c.seed_index % sizes.size()];
        {
            const std::lock_guard lock(rapidcheck_mutex());
            const rc::Random random(derive_seed(
                run.seed, {triangulation_study_id, std::uint64_t(c.family), c.seed_index}));
            c.points = testing::gen_points(c.family, n)(random).value();
        }
        for (const Method& m : methods) {
            for (const Kernel& k : kernels) {
                for (delaunay::InCirclePolicy p : both_policies) {
                    c.runs.push_back({c.family, c.seed_index, n, kernel_name(k), p,
                                      classify_triangulation(c.points, k, p, m), m.order,
                                      m.algorithm});
                }
            }
        }
        for (const Method& m : work_methods) c.work.push_back(measure_work(c.points, m));
        for (const Method& m : methods) {
            for (const Kernel& k : mpfr_kernels) {
                const Classification r =
                    classify_triangulation(c.points, k, delaunay::InCirclePolicy::determinant, m);
                c.wrong_at.push_back(is_wrong(r.outcome) ? 1 : 0);
            }
        }
    });

    TriangulationStudy study;
    // Counts per (family, method, kernel, policy) and per (method, kernel, policy), by positions.
    using Key = std::tuple<std::size_t, std::size_t, std::size_t, int>;
    using Cell = std::tuple<std::size_t, std::size_t, int>;
    std::map<Key, std::array<std::uint64_t, all_outcomes.size()>> counts;
    std::map<Cell, std::array<std::uint64_t, all_outcomes.size()>> totals;
    std::map<Cell, std::map<std::string, std::uint64_t>> details;
    struct Candidate {
        const Chunk* chunk;
        std::size_t kernel;
        TriangulationRun run;
    };
    std::vector<Candidate> to_shrink;
    std::map<std::tuple<std::size_t, std::size_t, int, int>, std::size_t> shrink_count;
    for (std::size_t ci = 0; ci < chunks.size(); ++ci) {
        const Chunk& c = chunks[ci];
        const auto fpos =
            std::size_t(std::find(families.begin(), families.end(), c.family) - families.begin());
        for (std::size_t r = 0; r < c.runs.size(); ++r) {
            const TriangulationRun& tr = c.runs[r];
            const std::size_t opos = r / per_method;
            const std::size_t kpos = r % per_method / std::size(both_policies);
            const int pol = int(tr.policy);
            const auto o = std::size_t(tr.result.outcome);
            ++counts[{fpos, opos, kpos, pol}][o];
            ++totals[{opos, kpos, pol}][o];
            if (is_wrong(tr.result.outcome)) {
                // Edge counts of not_delaunay outcomes would make one entry per run.
                ++details[{opos, kpos, pol}][tr.result.outcome == Outcome::not_delaunay
                                                 ? std::string(to_string(tr.result.outcome))
                                                 : describe(tr.result)];
                std::size_t& taken = shrink_count[{opos, kpos, pol, int(o)}];
                if (taken < options.shrink_per_class && tr.result.outcome != Outcome::guard) {
                    ++taken;
                    to_shrink.push_back({&c, kpos, tr});
                }
            }
            study.runs.push_back(tr);
        }
    }

    for (std::size_t op = 0; op < methods.size(); ++op) {
        for (std::size_t b = 0; b < bits.size(); ++b) {
            PrecisionRate rate{methods[op], bits[b], 0, 0};
            for (const Chunk& c : chunks) {
                rate.wrong += c.wrong_at[op * bits.size() + b];
                ++rate.runs;
            }
            study.precision.push_back(rate);
        }
    }

    // The method's cells: "algorithm" (only when several run) and "order".
    const auto method_cells = [&](const Method& m) {
        std::vector<std::string> cells;
        if (algorithm_column) cells.emplace_back(delaunay::to_string(m.algorithm));
        cells.push_back(order_name(m));
        return cells;
    };
    const auto method_header = [&](std::vector<std::string> before,
                                   std::vector<std::string> after) {
        if (algorithm_column) before.emplace_back("algorithm");
        before.emplace_back("order");
        before.insert(before.end(), after.begin(), after.end());
        return before;
    };
    const auto join = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    study.table.header = method_header({"family"}, {"kernel", "incircle"});
    for (Outcome o : all_outcomes) study.table.header.emplace_back(to_string(o));
    for (std::size_t f = 0; f < families.size(); ++f) {
        for (std::size_t op = 0; op < methods.size(); ++op) {
            for (std::size_t k = 0; k < kernels.size(); ++k) {
                for (delaunay::InCirclePolicy p : both_policies) {
                    const auto& row_counts = counts[{f, op, k, int(p)}];
                    std::vector<std::string> row =
                        join(join({std::string(testing::family_name(families[f]))},
                                  method_cells(methods[op])),
                             {kernel_name(kernels[k]), std::string(policy_name(p))});
                    for (std::uint64_t v : row_counts) row.push_back(std::to_string(v));
                    study.table.rows.push_back(std::move(row));
                }
            }
        }
    }
    Table summary;
    summary.header = method_header({}, {"kernel", "incircle", "runs"});
    for (Outcome o : all_outcomes) summary.header.emplace_back(to_string(o));
    summary.header.emplace_back("wrong outcomes by kind");
    for (std::size_t op = 0; op < methods.size(); ++op) {
        for (std::size_t k = 0; k < kernels.size(); ++k) {
            for (delaunay::InCirclePolicy p : both_policies) {
                const auto& t = totals[{op, k, int(p)}];
                std::uint64_t runs = 0;
                for (std::uint64_t v : t) runs += v;
                std::vector<std::string> row = join(
                    method_cells(methods[op]),
                    {kernel_name(kernels[k]), std::string(policy_name(p)), std::to_string(runs)});
                for (std::uint64_t v : t) row.push_back(std::to_string(v));
                std::string kinds;
                for (const auto& [what, n] : details[{op, k, int(p)}]) {
                    kinds += (kinds.empty() ? "" : "; ") + what + ": " + std::to_string(n);
                }
                row.push_back(kinds.empty() ? "-" : kinds);
                summary.rows.push_back(std::move(row));
            }
        }
    }

    // The work of each method, per family and over all families (chunk order: the sums
    // do not depend on which thread measured what).
    std::vector<OrderWork> overall;
    for (const Method& m : work_methods) {
        overall.push_back({families.front(), m.order, m.algorithm, 0, 0, {}, 0, 0, 0});
    }
    for (testing::Family f : families) {
        for (std::size_t o = 0; o < work_methods.size(); ++o) {
            OrderWork w{f, work_methods[o].order, work_methods[o].algorithm, 0, 0, {}, 0, 0, 0};
            for (const Chunk& c : chunks) {
                if (c.family != f) continue;
                const WorkSample& s = c.work[o];
                ++w.sets;
                w.points += c.points.size();
                w.counters += s.counters;
                w.distance_comparisons += s.distance_comparisons;
                w.merges += s.strips - 1;
                w.certified += s.certified;
            }
            OrderWork& all = overall[o];
            all.sets += w.sets;
            all.points += w.points;
            all.counters += w.counters;
            all.distance_comparisons += w.distance_comparisons;
            all.merges += w.merges;
            all.certified += w.certified;
            study.work.push_back(w);
        }
    }
    Table work_table;
    work_table.header = method_header(
        {"family"}, {"point sets", "points", "flips/point", "in-circle tests/point",
                     "orientations/point", "distance comparisons/point", "location steps/point",
                     "triangles created/point", "merges", "certified"});
    const auto work_row = [&](std::string family, const OrderWork& w) {
        work_table.rows.push_back(
            join(join({std::move(family)}, method_cells(Method(w.algorithm, w.order))),
                 {std::to_string(w.sets), std::to_string(w.points),
                  per_point(w.counters.flips(), w.points),
                  per_point(incircle_tests(w.counters), w.points),
                  per_point(orientations(w.counters), w.points),
                  per_point(w.distance_comparisons, w.points),
                  per_point(w.counters.location_steps, w.points),
                  per_point(w.counters.triangles_created, w.points), std::to_string(w.merges),
                  std::to_string(w.certified) + "/" + std::to_string(w.sets)}));
    };
    for (const OrderWork& w : study.work) work_row(std::string(testing::family_name(w.family)), w);
    for (const OrderWork& w : overall) work_row("all families", w);

    // Shrink the chosen wrong outcomes (in parallel; each is a pure function of its input).
    std::vector<std::vector<Point2>> shrunk(to_shrink.size());
    {
        Progress shrink_progress("shrinking", to_shrink.size(), run.progress);
        for_each_chunk(to_shrink.size(), run.jobs, &shrink_progress, [&](std::size_t i) {
            const Candidate& c = to_shrink[i];
            shrunk[i] = shrink_failing_input(c.chunk->points, kernels[c.kernel], c.run.policy,
                                             c.run.result, Method(c.run.algorithm, c.run.order));
        });
    }
    Table fixtures_table;
    fixtures_table.header = method_header(
        {"fixture"}, {"kernel", "incircle", "outcome", "points (original)", "replays"});
    for (std::size_t i = 0; i < to_shrink.size(); ++i) {
        const Candidate& c = to_shrink[i];
        const Kernel& k = kernels[c.kernel];
        const std::string kname = kernel_name(k);
        const Method method(c.run.algorithm, c.run.order);
        const std::string oname = is_external(method)
                                      ? order_name(method)
                                      : std::string(delaunay::to_string(method.algorithm));
        // The paper's order keeps the names fixtures had before orders existed; another
        // algorithm's fixtures carry its name instead of an order.
        const std::string file = "fixtures/" + std::string(to_string(c.run.result.outcome)) + "-" +
                                 kernel_file_name(k) + "-" +
                                 std::string(policy_name(c.run.policy)) +
                                 (is_paper_order(method) ? "" : "-" + oname) + "-" +
                                 std::string(testing::family_name(c.run.family)) + "-s" +
                                 std::to_string(c.run.seed_index) + ".xy";
        // The shrunk set's own classification (its detail may differ from the original's
        // for invalid and not_delaunay outcomes, which shrink by outcome only).
        const Classification now = classify_triangulation(shrunk[i], k, c.run.policy, method);
        const std::string cmd_flags =
            "--kernel " + kname + " --incircle " + std::string(policy_name(c.run.policy));
        const std::vector<std::string> header{
            "exidel study triangulation fixture: " + describe(now),
            "kernel " + kname + ", incircle policy " + std::string(policy_name(c.run.policy)) +
                (is_external(method) ? ", order " : ", algorithm ") + oname,
            "family " + std::string(testing::family_name(c.run.family)) + ", seed index " +
                std::to_string(c.run.seed_index) + " of study seed " + std::to_string(run.seed) +
                ", " + std::to_string(c.chunk->points.size()) + " points shrunk to " +
                std::to_string(shrunk[i].size()),
            "reproduce: exidel study replay -i FILE " + cmd_flags + replay_order_flags(method),
            "      and: exidel triangulate -i FILE " + cmd_flags + triangulate_order_flags(method) +
                (now.outcome == Outcome::failure ? "   (exit status 1: triangulation failed)"
                                                 : "   (output differs from --kernel exact)"),
        };
        write_text_file(run.out / file, fixture_text(shrunk[i], header));
        study.fixtures.push_back({file, kname, c.run.policy, now, c.chunk->points.size(),
                                  shrunk[i].size(), c.run.order, c.run.algorithm});
        fixtures_table.rows.push_back(join(
            join({"`" + file + "`"}, method_cells(method)),
            {kname, std::string(policy_name(c.run.policy)), describe(now),
             std::to_string(shrunk[i].size()) + " (" + std::to_string(c.chunk->points.size()) + ")",
             now.outcome == c.run.result.outcome ? "yes" : "NO"}));
    }

    write_text_file(run.out / "triangulation.csv", study.table.csv());
    write_text_file(run.out / "triangulation_summary.csv", summary.csv());
    write_text_file(run.out / "triangulation_work.csv", work_table.csv());

    std::string sizes_text;
    for (std::size_t n : sizes) sizes_text += (sizes_text.empty() ? "" : ", ") + std::to_string(n);
    std::string orders_text;
    for (delaunay::Strategy o : orders)
        orders_text += (orders_text.empty() ? "" : ", ") + std::string(delaunay::to_string(o));
    std::string others_text;
    for (const Method& m : methods) {
        if (!is_external(m))
            others_text +=
                ", and by the " + std::string(delaunay::to_string(m.algorithm)) + " algorithm";
    }
    study.report = Report("Triangulation outcomes per kernel and in-circle policy");
    std::string families_text;
    for (testing::Family f : families) {
        families_text += (families_text.empty() ? "" : ", ") + std::string(testing::family_name(f));
    }
    if (families.size() == testing::all_families().size())
        families_text = "Every family of lib/testing";
    study.report.paragraph(
        families_text + ", " + std::to_string(seeds) + " point sets each (sizes " + sizes_text +
        ", cycled; seed " + std::to_string(run.seed) +
        "); every kernel and both in-circle "
        "policies triangulate the same point sets, in insertion order " +
        orders_text +
        (orders.size() == 1 && orders.front() == delaunay::Strategy::lexicographic
             ? " (the paper's algorithm)"
             : "") +
        others_text +
        ". Outcomes, decided by the exact certifier: "
        "**delaunay** (certified), **not_delaunay** (a valid triangulation with some edge not "
        "locally Delaunay), **invalid** (not a triangulation of the points; the certifier's first "
        "finding in the last column), **failure** (the algorithm detected the inconsistency and "
        "stopped), **guard** (the predicate-call budget of 64 n^2 + 10^6 ran out; never "
        "expected).");
    study.report.append(family_definitions(families));
    study.report.table(summary);
    study.report.paragraph(
        "Minimal failing inputs (delta debugging until no single point can be removed), "
        "written as fixtures in hex floats:");
    if (fixtures_table.rows.empty()) {
        study.report.paragraph("(no wrong outcome, nothing to shrink)");
    } else {
        study.report.table(fixtures_table);
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
    study.report.table(work_table);
    // Failure rate against MPFR precision: one line per method.
    Table precision_table;
    precision_table.header = method_header({}, {});
    for (unsigned b : bits) precision_table.header.push_back("p = " + std::to_string(b));
    LinePlot plot;
    plot.title =
        "Triangulations not certified Delaunay, MPFR kernel at p bits (determinant policy)";
    plot.x_label = "significand bits p";
    plot.y_label = "share of point sets with a wrong outcome";
    for (std::size_t op = 0; op < methods.size(); ++op) {
        std::vector<std::string> row = method_cells(methods[op]);
        Series series;
        series.name =
            algorithm_column ? std::string(delaunay::to_string(methods[op].algorithm)) : "";
        if (is_external(methods[op])) {
            series.name +=
                (series.name.empty() ? "" : " ") + std::string("(") + order_name(methods[op]) + ")";
        }
        for (std::size_t b = 0; b < bits.size(); ++b) {
            const PrecisionRate& r = study.precision[op * bits.size() + b];
            row.push_back(std::to_string(r.wrong) + "/" + std::to_string(r.runs));
            series.x.push_back(double(r.bits));
            series.y.push_back(r.runs ? double(r.wrong) / double(r.runs) : 0.0);
        }
        precision_table.rows.push_back(std::move(row));
        plot.series.push_back(std::move(series));
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
    return study;
}

}  // namespace exidel::research
