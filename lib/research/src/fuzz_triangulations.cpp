// exidel::research: `exidel fuzz triangulations`, every method on point sets of every
// family, certified exactly (fuzz.hpp says how the sets are defined).
#include <algorithm>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "exidel/delaunay/parallel.hpp"
#include "exidel/predicates/build_info.hpp"
#include "exidel/research/common.hpp"
#include "exidel/research/fuzz.hpp"

#include "campaign.hpp"

namespace exidel::research {

namespace {

using campaign::Finding;
using campaign::Partial;

/// The first element of the seed paths of this campaign (fuzz predicates uses 101).
constexpr std::uint64_t fuzz_triangulations_id = 102;

constexpr std::size_t outcome_count = all_outcomes.size();

std::size_t outcome_position(Outcome o) {
    return std::size_t(std::find(all_outcomes.begin(), all_outcomes.end(), o) -
                       all_outcomes.begin());
}

struct Campaign {
    TriangulationFuzzOptions options;
    Kernel kernel;
    std::vector<Method> methods;
    campaign::Layout layout;

    explicit Campaign(TriangulationFuzzOptions o)
        : options(complete(std::move(o))),
          kernel(parse_kernel(options.kernel)),
          methods(methods_of(options.algorithms, options.orders)),
          // About 2^16 triangulations (of 50 points on average, a few seconds) a stripe.
          layout(options.sets * methods.size() * options.policies.size(),
                 methods.size() * options.policies.size(), std::uint64_t{1} << 16) {}

    static TriangulationFuzzOptions complete(TriangulationFuzzOptions o) {
        if (o.families.empty()) {
            for (const testing::FamilyInfo& f : testing::all_families())
                o.families.push_back(f.family);
        }
        if (o.algorithms.empty()) {
            for (const delaunay::AlgorithmInfo& a : delaunay::algorithms())
                o.algorithms.push_back(a.id);
        }
        if (o.orders.empty()) o.orders.assign(all_orders.begin(), all_orders.end());
        if (o.policies.empty())
            o.policies = {delaunay::InCirclePolicy::determinant, delaunay::InCirclePolicy::cosine};
        if (o.min_points < 1 || o.min_points > o.max_points) {
            throw std::invalid_argument("the sizes must satisfy 1 <= MIN <= MAX, got " +
                                        std::to_string(o.min_points) + "-" +
                                        std::to_string(o.max_points));
        }
        if (o.max_points > 100'000) throw std::invalid_argument("the sizes go up to 100000 points");
        if (o.jobs == 0) o.jobs = 1;
        return o;
    }

    std::size_t runs_per_set() const { return methods.size() * options.policies.size(); }
    std::size_t family_position(std::uint64_t set) const {
        return std::size_t(set % options.families.size());
    }

    /// Set s as drawn (under the RapidCheck lock: common.hpp says why).
    std::vector<Point2> draw(std::uint64_t set) const {
        campaign::SplitMix64 sizes{derive_seed(options.seed, {fuzz_triangulations_id, set, 1})};
        const std::size_t n =
            options.min_points + sizes.below(options.max_points - options.min_points + 1);
        const rc::Random random(derive_seed(options.seed, {fuzz_triangulations_id, set}));
        const std::lock_guard lock(rapidcheck_mutex());
        return testing::gen_points(options.families[family_position(set)], n)(random).value();
    }

    Method method_of(std::uint64_t unit) const {
        return methods[(unit % runs_per_set()) / options.policies.size()];
    }
    delaunay::InCirclePolicy policy_of(std::uint64_t unit) const {
        return options.policies[unit % options.policies.size()];
    }
    bool wrong_is_a_problem() const { return kernel_is_exact(kernel); }
};

/// Every run of set s. Counts: runs per (family, method, policy, outcome); a finding's a
/// is the outcome's position in all_outcomes.
Partial run_block(const Campaign& c, std::uint64_t set) {
    const std::vector<Point2> points = c.draw(set);
    Partial result;
    result.counts.resize(c.options.families.size() * c.runs_per_set() * outcome_count);
    const std::uint64_t first = set * c.runs_per_set();
    for (std::uint64_t unit = first; unit < first + c.runs_per_set(); ++unit) {
        const Classification r =
            classify_triangulation(points, c.kernel, c.policy_of(unit), c.method_of(unit));
        const std::size_t o = outcome_position(r.outcome);
        const std::size_t category = c.family_position(set) * c.runs_per_set() + (unit - first);
        ++result.counts[category * outcome_count + o];
        if (r.outcome != Outcome::delaunay) result.findings.push_back({unit, std::int32_t(o), 0});
    }
    result.add({}, c.options.max_reports);
    return result;
}

std::string campaign_text(const Campaign& c) {
    std::ostringstream out;
    const TriangulationFuzzOptions& o = c.options;
    out << "exidel fuzz triangulations checkpoint 1\nkernel " << kernel_name(c.kernel)
        << "\nfamilies";
    for (testing::Family f : o.families) out << ' ' << testing::family_name(f);
    out << "\nmethods";
    for (const Method& m : c.methods)
        out << ' ' << delaunay::to_string(m.algorithm) << '/' << delaunay::to_string(m.order);
    out << "\npolicies";
    for (delaunay::InCirclePolicy p : o.policies) out << ' ' << policy_name(p);
    out << "\nsizes " << o.min_points << '-' << o.max_points << "\nsets " << o.sets << "\nseed "
        << o.seed << "\nreports " << o.max_reports << "\nexidel " << build_info().commit << '\n';
    return out.str();
}

/// The finding shrunk, and its fixture written when options.out is set.
TriangulationFinding report(const Campaign& c, const Finding& f) {
    const std::uint64_t set = f.index / c.runs_per_set();
    TriangulationFinding r;
    r.index = f.index;
    r.family = c.options.families[c.family_position(set)];
    r.method = c.method_of(f.index);
    r.policy = c.policy_of(f.index);
    const std::vector<Point2> points = c.draw(set);
    r.points = points.size();
    r.outcome = classify_triangulation(points, c.kernel, r.policy, r.method);
    r.shrunk = shrink_failing_input(points, c.kernel, r.policy, r.outcome, r.method);
    r.shrunk_outcome = classify_triangulation(r.shrunk, c.kernel, r.policy, r.method);
    if (c.options.out.empty()) return r;
    const std::string kname = kernel_name(c.kernel);
    std::string kfile = kname;
    std::erase(kfile, ':');
    r.file = std::string(to_string(r.outcome.outcome)) + "-" + kfile + "-" +
             std::string(policy_name(r.policy)) + "-" + method_label(r.method) + "-" +
             std::string(testing::family_name(r.family)) + "-u" + std::to_string(f.index) + ".xy";
    const auto describe = [](const Classification& k) {
        return std::string(to_string(k.outcome)) + (k.detail.empty() ? "" : " (" + k.detail + ")");
    };
    const std::string flags = "--kernel " + kname + " --incircle " +
                              std::string(policy_name(r.policy)) +
                              triangulate_order_flags(r.method);
    const std::vector<std::string> header{
        "exidel fuzz triangulations fixture: " + describe(r.shrunk_outcome),
        "family " + std::string(testing::family_name(r.family)) + ", unit " +
            std::to_string(f.index) + " of seed " + std::to_string(c.options.seed) + ", " +
            std::to_string(r.points) + " points (" + describe(r.outcome) + ") shrunk to " +
            std::to_string(r.shrunk.size()),
        "reproduce: exidel triangulate -i FILE " + flags + " --certify",
    };
    write_text_file(c.options.out / r.file, fixture_text(r.shrunk, header));
    return r;
}

}  // namespace

std::string method_label(const Method& m) {
    return m.algorithm == delaunay::Algorithm::external
               ? std::string(delaunay::to_string(m.algorithm)) + "-" +
                     std::string(delaunay::to_string(m.order))
               : std::string(delaunay::to_string(m.algorithm));
}

TriangulationFuzzResult fuzz_triangulations(const TriangulationFuzzOptions& options, Team& team) {
    const Campaign c(options);
    campaign::Spec spec = campaign::spec_from(c.options);
    spec.label = "fuzz triangulations";
    spec.identity = campaign_text(c);
    spec.layout = c.layout;
    spec.counts = c.options.families.size() * c.runs_per_set() * outcome_count;
    spec.run_block = [&c](std::uint64_t set) { return run_block(c, set); };
    const campaign::Outcome outcome = campaign::run(spec, team);

    TriangulationFuzzResult result;
    result.options = c.options;
    result.methods = c.methods;
    result.ranks = team.size();
    result.commit = std::string(build_info().commit);
    result.seconds = outcome.seconds;
    result.resumed = outcome.resumed;
    if (team.rank() != 0) return result;
    result.counts = outcome.all.counts;
    for (std::size_t i = 0; i < result.counts.size(); ++i) {
        const Outcome o = all_outcomes[i % outcome_count];
        result.triangulations += result.counts[i];
        if (o != Outcome::delaunay) result.wrong += result.counts[i];
        if (o == Outcome::guard || (o != Outcome::delaunay && c.wrong_is_a_problem())) {
            result.problems += result.counts[i];
        }
    }
    if (result.triangulations != c.layout.units) {
        throw std::runtime_error("fuzz: " + std::to_string(result.triangulations) +
                                 " triangulations were counted, " + std::to_string(c.layout.units) +
                                 " asked for");
    }
    if (!c.options.out.empty() && !outcome.all.findings.empty())
        std::filesystem::create_directories(c.options.out);
    result.reported.resize(outcome.all.findings.size());
    parallel_for(result.reported.size(), c.options.jobs,
                 [&](std::size_t i) { result.reported[i] = report(c, outcome.all.findings[i]); });
    return result;
}

std::string summary_json(const TriangulationFuzzResult& r) {
    using Json = nlohmann::ordered_json;
    const TriangulationFuzzOptions& o = r.options;
    const std::size_t M = r.methods.size(), P = o.policies.size();
    // Outcome counts summed over everything but one dimension.
    const auto outcomes = [&](auto keep) {
        Json j = Json::object();
        std::vector<std::uint64_t> sum(outcome_count);
        std::uint64_t runs = 0;
        for (std::size_t i = 0; i < r.counts.size(); ++i) {
            const std::size_t cat = i / outcome_count;
            if (!keep(cat / (M * P), (cat / P) % M, cat % P)) continue;
            sum[i % outcome_count] += r.counts[i];
            runs += r.counts[i];
        }
        j["triangulations"] = runs;
        for (std::size_t k = 0; k < outcome_count; ++k)
            j[std::string(to_string(all_outcomes[k]))] = sum[k];
        return j;
    };
    Json j;
    j["campaign"] = "triangulations";
    j["kernel"] = o.kernel;
    j["seed"] = o.seed;
    j["sets"] = o.sets;
    j["sizes"] = {o.min_points, o.max_points};
    j["triangulations"] = r.triangulations;
    j["wrong"] = r.wrong;
    j["problems"] = r.problems;
    j["outcomes"] = outcomes([](std::size_t, std::size_t, std::size_t) { return true; });
    Json families = Json::object(), methods = Json::object(), policies = Json::object();
    for (std::size_t f = 0; f < o.families.size(); ++f) {
        families[std::string(testing::family_name(o.families[f]))] =
            outcomes([f](std::size_t ff, std::size_t, std::size_t) { return ff == f; });
    }
    for (std::size_t m = 0; m < M; ++m) {
        methods[method_label(r.methods[m])] =
            outcomes([m](std::size_t, std::size_t mm, std::size_t) { return mm == m; });
    }
    for (std::size_t p = 0; p < P; ++p) {
        policies[std::string(policy_name(o.policies[p]))] =
            outcomes([p](std::size_t, std::size_t, std::size_t pp) { return pp == p; });
    }
    j["families"] = std::move(families);
    j["methods"] = std::move(methods);
    j["policies"] = std::move(policies);
    Json reported = Json::array();
    for (const TriangulationFinding& f : r.reported) {
        reported.push_back({{"unit", f.index},
                            {"family", testing::family_name(f.family)},
                            {"method", method_label(f.method)},
                            {"incircle", policy_name(f.policy)},
                            {"outcome", to_string(f.outcome.outcome)},
                            {"detail", f.outcome.detail},
                            {"points", f.points},
                            {"shrunk_points", f.shrunk.size()},
                            {"shrunk_outcome", to_string(f.shrunk_outcome.outcome)},
                            {"file", f.file}});
    }
    j["reported"] = std::move(reported);
    campaign::close_summary(j, o.max_reports, r.commit, r.seconds, r.ranks, o.jobs,
                            "triangulations", r.triangulations, r.resumed);
    return j.dump(2) + "\n";
}

}  // namespace exidel::research
