// exidel::research: fuzzing campaigns of a kernel against a reference (fuzz.hpp says how
// the queries are defined and split).
#include "exidel/research/fuzz.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <variant>

#include <nlohmann/json.hpp>

#include "exidel/predicates/batch.hpp"
#include "exidel/predicates/build_info.hpp"
#include "exidel/predicates/registry.hpp"
#include "exidel/research/common.hpp"

#include "campaign.hpp"

namespace exidel::research {

namespace {

using campaign::Finding;
using campaign::Partial;
using campaign::SplitMix64;

/// The first element of every seed path of the fuzz campaigns (the studies use 1 to 4).
constexpr std::uint64_t fuzz_predicates_id = 101;

/// A query before its points are known: the predicate and which points of the set.
struct QueryPlan {
    Predicate predicate;
    std::array<std::uint8_t, 4> index{};
};

/// Everything a campaign's workers share, fixed before the first block.
struct Campaign {
    PredicateFuzzOptions options;
    Kernel kernel, reference;
    campaign::Layout layout;

    explicit Campaign(PredicateFuzzOptions o)
        : options(complete(std::move(o))),
          kernel(parse_kernel(options.kernel)),
          reference(parse_kernel(options.reference)),
          // About 10^6 queries per stripe: a few seconds of work lost at an interruption.
          layout(options.queries, fuzz_block_queries, std::uint64_t{1} << 20) {}

    static PredicateFuzzOptions complete(PredicateFuzzOptions o) {
        if (o.families.empty()) {
            for (const testing::FamilyInfo& f : testing::all_families())
                o.families.push_back(f.family);
        }
        if (o.predicates.empty()) o.predicates.assign(all_predicates.begin(), all_predicates.end());
        if (o.jobs == 0) o.jobs = 1;
        return o;
    }

    std::size_t family_count() const { return options.families.size(); }
    std::size_t predicate_count() const { return options.predicates.size(); }
    std::size_t family_position(std::uint64_t block) const {
        return std::size_t(block % family_count());
    }

    /// The point set of block b: drawn under the RapidCheck lock (common.hpp says why).
    rc::Shrinkable<std::vector<Point2>> draw_set(std::uint64_t block) const {
        const rc::Random random(derive_seed(options.seed, {fuzz_predicates_id, block}));
        return testing::gen_points(options.families[family_position(block)],
                                   fuzz_set_points)(random);
    }

    /// Query j of block b: its predicate, and distinct points chosen by its own stream.
    QueryPlan plan(std::uint64_t block, std::uint64_t j) const {
        QueryPlan q{options.predicates[j % predicate_count()]};
        SplitMix64 random{derive_seed(options.seed, {fuzz_predicates_id, block, j})};
        const std::size_t k = point_count(q.predicate);
        for (std::size_t i = 0; i < k; ++i) {
            bool fresh = false;
            while (!fresh) {
                q.index[i] = std::uint8_t(random.below(fuzz_set_points));  // < 16
                fresh = std::find(q.index.begin(), q.index.begin() + std::ptrdiff_t(i),
                                  q.index[i]) == q.index.begin() + std::ptrdiff_t(i);
            }
        }
        return q;
    }
};

/// The points of a planned query, from its block's set.
std::array<Point2, 4> make_query(const std::vector<Point2>& set, const QueryPlan& plan) {
    std::array<Point2, 4> q{};
    for (std::size_t i = 0; i < point_count(plan.predicate); ++i) q[i] = set[plan.index[i]];
    // The adaptive kernel's orient2d is exact, and the cosine comparison below does not
    // depend on it: a wrong arrangement would only change which query is asked.
    if (plan.predicate == Predicate::incircle_cosine)
        q = testing::arrange_for_cosine(q, AdaptiveKernel{});
    return q;
}

/// Queries of one predicate, as the batched kernels take them: one array per argument.
struct Columns {
    std::array<std::vector<Point2>, 4> arg;
    std::vector<std::uint32_t> j;  ///< each query's number within its block

    void push(const std::array<Point2, 4>& q, std::size_t points, std::uint32_t number) {
        for (std::size_t i = 0; i < points; ++i) arg[i].push_back(q[i]);
        j.push_back(number);
    }
};

/// out[i] = the sign `kernel` gives query i of `c`: the adaptive kernel through its
/// batched path (exidel/predicates/batch.hpp), every other one query by query.
void evaluate_columns(const Kernel& kernel, Predicate p, const Columns& c, std::span<Sign> out) {
    const auto& a = c.arg;
    if (std::holds_alternative<AdaptiveKernel>(kernel)) {
        switch (p) {
            case Predicate::orient2d: return batch::orient2d(a[0], a[1], a[2], out);
            case Predicate::incircle: return batch::incircle(a[0], a[1], a[2], a[3], out);
            case Predicate::incircle_cosine:
                return batch::incircle_cosine(a[0], a[1], a[2], a[3], out);
            case Predicate::compare_distance: return batch::compare_distance(a[0], a[1], a[2], out);
        }
    }
    std::visit(
        [&](const auto& k) {
            std::array<Point2, 4> q{};
            for (std::size_t i = 0; i < out.size(); ++i) {
                for (std::size_t m = 0; m < point_count(p); ++m) q[m] = a[m][i];
                out[i] = exidel::evaluate(k, p, std::span(q.data(), point_count(p)));
            }
        },
        kernel);
}

/// One query through one kernel.
Sign evaluate_one(const Kernel& kernel, Predicate p, const std::array<Point2, 4>& q) {
    return std::visit(
        [&](const auto& k) { return exidel::evaluate(k, p, std::span(q.data(), point_count(p))); },
        kernel);
}

/// Every query of block b. Counts: (queries, disagreements) per (family, predicate); a
/// finding's a and b are the kernel's and the reference's signs.
Partial run_block(const Campaign& c, std::uint64_t block) {
    std::vector<Point2> set;
    {
        const std::lock_guard lock(rapidcheck_mutex());
        set = c.draw_set(block).value();
    }
    const std::size_t P = c.predicate_count();
    std::vector<Columns> columns(P);
    const std::uint64_t count = c.layout.units_in_block(block);
    for (std::uint64_t j = 0; j < count; ++j) {
        const QueryPlan plan = c.plan(block, j);
        columns[j % P].push(make_query(set, plan), point_count(plan.predicate), std::uint32_t(j));
    }
    Partial result;
    result.counts.resize(c.family_count() * P * 2);
    const std::size_t row = c.family_position(block) * P;
    std::vector<Sign> mine, theirs;
    for (std::size_t p = 0; p < P; ++p) {
        const Columns& col = columns[p];
        mine.resize(col.j.size());
        theirs.resize(col.j.size());
        evaluate_columns(c.kernel, c.options.predicates[p], col, mine);
        evaluate_columns(c.reference, c.options.predicates[p], col, theirs);
        std::uint64_t* n = &result.counts[(row + p) * 2];
        n[0] += col.j.size();
        for (std::size_t i = 0; i < col.j.size(); ++i) {
            if (mine[i] == theirs[i]) continue;
            ++n[1];
            result.findings.push_back(
                {block * fuzz_block_queries + col.j[i], to_int(mine[i]), to_int(theirs[i])});
        }
    }
    // The first ones in query order (the columns are per predicate).
    result.add({}, c.options.max_reports);
    return result;
}

// ---------------------------------------------------------------------------------
// Shrinking.

/// At most this many candidate sets are tried per disagreement: a shrink costs one draw
/// of the set (about 100 us), so a report never takes more than a second or so.
constexpr std::size_t shrink_budget = 10000;

Sign to_sign(int v) { return v < 0 ? Sign::negative : v > 0 ? Sign::positive : Sign::zero; }

Disagreement shrink(const Campaign& c, const Finding& raw) {
    const std::uint64_t block = raw.index / fuzz_block_queries, j = raw.index % fuzz_block_queries;
    const QueryPlan plan = c.plan(block, j);
    Disagreement d;
    d.index = raw.index;
    d.family = c.options.families[c.family_position(block)];
    d.predicate = plan.predicate;
    d.kernel_sign = to_sign(raw.a);
    d.reference_sign = to_sign(raw.b);

    const std::lock_guard lock(rapidcheck_mutex());
    rc::Shrinkable<std::vector<Point2>> set = c.draw_set(block);
    d.query = d.shrunk = make_query(set.value(), plan);
    d.shrunk_kernel_sign = d.kernel_sign;
    d.shrunk_reference_sign = d.reference_sign;
    std::size_t tries = 0;
    for (bool smaller = true; smaller && tries < shrink_budget;) {
        smaller = false;
        rc::Seq<rc::Shrinkable<std::vector<Point2>>> candidates = set.shrinks();
        while (auto candidate = candidates.next()) {
            if (++tries > shrink_budget) break;
            std::array<Point2, 4> q;
            try {
                q = make_query(candidate->value(), plan);
            } catch (const std::exception&) {
                continue;  // a shrink the generator rejects (RapidCheck's GenerationFailure)
            }
            const Sign k = evaluate_one(c.kernel, plan.predicate, q);
            const Sign r = evaluate_one(c.reference, plan.predicate, q);
            if (k == r) continue;
            set = std::move(*candidate);
            d.shrunk = q;
            d.shrunk_kernel_sign = k;
            d.shrunk_reference_sign = r;
            ++d.shrink_steps;
            smaller = true;
            break;
        }
    }
    return d;
}

/// What identifies a campaign in its checkpoint: everything the queries and the counts
/// depend on, and the build (another build may draw or evaluate differently).
std::string campaign_text(const Campaign& c) {
    std::ostringstream out;
    const PredicateFuzzOptions& o = c.options;
    out << "exidel fuzz predicates checkpoint 1\nkernel " << kernel_name(c.kernel) << "\nreference "
        << kernel_name(c.reference) << "\nfamilies";
    for (testing::Family f : o.families) out << ' ' << testing::family_name(f);
    out << "\npredicates";
    for (Predicate p : o.predicates) out << ' ' << predicate_name(p);
    out << "\nqueries " << o.queries << "\nseed " << o.seed << "\nreports " << o.max_reports
        << "\nexidel " << build_info().commit << '\n';
    return out.str();
}

}  // namespace

PredicateFuzzResult fuzz_predicates(const PredicateFuzzOptions& options, Team& team) {
    const Campaign c(options);
    campaign::Spec spec = campaign::spec_from(c.options);
    spec.label = "fuzz predicates";
    spec.identity = campaign_text(c);
    spec.layout = c.layout;
    spec.counts = c.family_count() * c.predicate_count() * 2;
    spec.run_block = [&c](std::uint64_t block) { return run_block(c, block); };
    const campaign::Outcome outcome = campaign::run(spec, team);

    PredicateFuzzResult result;
    result.options = c.options;
    result.ranks = team.size();
    result.commit = std::string(build_info().commit);
    result.seconds = outcome.seconds;
    result.resumed_queries = outcome.resumed;
    if (team.rank() != 0) return result;
    for (std::size_t i = 0; i < outcome.all.counts.size(); i += 2) {
        result.counts.push_back({outcome.all.counts[i], outcome.all.counts[i + 1]});
        result.total.queries += outcome.all.counts[i];
        result.total.disagreements += outcome.all.counts[i + 1];
    }
    if (result.total.queries != c.options.queries) {
        throw std::runtime_error("fuzz: " + std::to_string(result.total.queries) +
                                 " queries were counted, " + std::to_string(c.options.queries) +
                                 " asked for");
    }
    for (const Finding& f : outcome.all.findings) result.reported.push_back(shrink(c, f));
    return result;
}
std::string summary_json(const PredicateFuzzResult& r) {
    using Json = nlohmann::ordered_json;
    const PredicateFuzzOptions& o = r.options;
    Json j;
    j["campaign"] = "predicates";
    j["kernel"] = o.kernel;
    j["reference"] = o.reference;
    j["seed"] = o.seed;
    j["queries"] = r.total.queries;
    j["disagreements"] = r.total.disagreements;
    Json families = Json::object();
    for (std::size_t f = 0; f < o.families.size(); ++f) {
        Json fam, preds = Json::object();
        FuzzCount sum;
        for (std::size_t p = 0; p < o.predicates.size(); ++p) {
            const FuzzCount& n = r.counts[f * o.predicates.size() + p];
            preds[std::string(predicate_name(o.predicates[p]))] = {
                {"queries", n.queries}, {"disagreements", n.disagreements}};
            sum.queries += n.queries;
            sum.disagreements += n.disagreements;
        }
        fam["queries"] = sum.queries;
        fam["disagreements"] = sum.disagreements;
        fam["predicates"] = std::move(preds);
        families[std::string(testing::family_name(o.families[f]))] = std::move(fam);
    }
    j["families"] = std::move(families);
    Json reported = Json::array();
    for (const Disagreement& d : r.reported) {
        const std::size_t n = point_count(d.predicate);
        reported.push_back({{"query", d.index},
                            {"family", testing::family_name(d.family)},
                            {"predicate", predicate_name(d.predicate)},
                            {"line", query_line(d.predicate, std::span(d.query.data(), n))},
                            {"kernel_sign", to_int(d.kernel_sign)},
                            {"reference_sign", to_int(d.reference_sign)},
                            {"shrunk", query_line(d.predicate, std::span(d.shrunk.data(), n))},
                            {"shrunk_kernel_sign", to_int(d.shrunk_kernel_sign)},
                            {"shrunk_reference_sign", to_int(d.shrunk_reference_sign)},
                            {"shrink_steps", d.shrink_steps}});
    }
    j["reported"] = std::move(reported);
    campaign::close_summary(j, o.max_reports, r.commit, r.seconds, r.ranks, o.jobs, "queries",
                            r.total.queries, r.resumed_queries);
    return j.dump(2) + "\n";
}

std::string query_line(Predicate p, std::span<const Point2> points) {
    std::string s(predicate_name(p));
    char buf[64];
    for (std::size_t i = 0; i < point_count(p) && i < points.size(); ++i) {
        std::snprintf(buf, sizeof buf, " %a %a", points[i].x, points[i].y);
        s += buf;
    }
    return s;
}

}  // namespace exidel::research
