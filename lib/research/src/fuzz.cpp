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

namespace exidel::research {

namespace {

/// The first element of every seed path of the fuzz campaigns (the studies use 1 to 4).
constexpr std::uint64_t fuzz_predicates_id = 101;

class SoloTeam final : public Team {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    std::vector<std::string> gather(const std::string& mine) override { return {mine}; }
    double max(double value) override { return value; }
};

/// SplitMix64 (Steele, Lea and Flood 2014): a fast stream of 64-bit words from one seed.
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, n) by rejection (n small; no modulo bias).
    std::uint32_t below(std::uint32_t n) {
        const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
        for (;;) {
            const std::uint64_t r = next();
            if (r < limit) return std::uint32_t(r % n);
        }
    }
};

/// The campaign's fixed layout: which block holds which queries, which stripe which blocks.
struct Layout {
    std::uint64_t queries = 0, blocks = 0, stripes = 0, stripe_blocks = 0;

    explicit Layout(std::uint64_t n) : queries(n) {
        blocks = (n + fuzz_block_queries - 1) / fuzz_block_queries;
        // About 10^6 queries per stripe for long campaigns (a few seconds of work lost at
        // an interruption); at least 16 stripes when there are enough blocks, so that
        // small runs still spread over a few MPI ranks.
        stripe_blocks = std::clamp<std::uint64_t>((blocks + 15) / 16, 1, 4096);
        stripes = (blocks + stripe_blocks - 1) / stripe_blocks;
    }
    std::uint64_t block_begin(std::uint64_t stripe) const { return stripe * stripe_blocks; }
    std::uint64_t block_end(std::uint64_t stripe) const {
        return std::min(blocks, (stripe + 1) * stripe_blocks);
    }
    std::uint64_t queries_in_block(std::uint64_t b) const {
        return std::min<std::uint64_t>(fuzz_block_queries, queries - b * fuzz_block_queries);
    }
    std::uint64_t queries_in_stripe(std::uint64_t s) const {
        const std::uint64_t first = block_begin(s) * fuzz_block_queries;
        return std::min(queries, block_end(s) * fuzz_block_queries) - first;
    }
};

/// A disagreement before shrinking: the query's number and both signs.
struct RawDisagreement {
    std::uint64_t index;
    Sign kernel, reference;
};

/// What a stripe (or any set of blocks) found: counts per (family, predicate) and its
/// first max_reports disagreements in query order.
struct Partial {
    std::vector<FuzzCount> counts;
    std::vector<RawDisagreement> disagreements;

    void add(const Partial& other, std::size_t max_reports) {
        if (counts.size() < other.counts.size()) counts.resize(other.counts.size());
        for (std::size_t i = 0; i < other.counts.size(); ++i) {
            counts[i].queries += other.counts[i].queries;
            counts[i].disagreements += other.counts[i].disagreements;
        }
        disagreements.insert(disagreements.end(), other.disagreements.begin(), other.disagreements.end());
        std::sort(disagreements.begin(), disagreements.end(),
                  [](const RawDisagreement& a, const RawDisagreement& b) { return a.index < b.index; });
        if (disagreements.size() > max_reports) disagreements.resize(max_reports);
    }
};

/// A query before its points are known: the predicate and which points of the set.
struct QueryPlan {
    Predicate predicate;
    std::array<std::uint8_t, 4> index{};
};

/// Everything a campaign's workers share, fixed before the first block.
struct Campaign {
    PredicateFuzzOptions options;
    Kernel kernel, reference;
    Layout layout;

    explicit Campaign(PredicateFuzzOptions o)
        : options(complete(std::move(o))),
          kernel(parse_kernel(options.kernel)),
          reference(parse_kernel(options.reference)),
          layout(options.queries) {}

    static PredicateFuzzOptions complete(PredicateFuzzOptions o) {
        if (o.families.empty()) {
            for (const testing::FamilyInfo& f : testing::all_families()) o.families.push_back(f.family);
        }
        if (o.predicates.empty()) o.predicates.assign(all_predicates.begin(), all_predicates.end());
        if (o.jobs == 0) o.jobs = 1;
        return o;
    }

    std::size_t family_count() const { return options.families.size(); }
    std::size_t predicate_count() const { return options.predicates.size(); }
    std::size_t family_position(std::uint64_t block) const { return std::size_t(block % family_count()); }

    /// The point set of block b: drawn under the RapidCheck lock (common.hpp says why).
    rc::Shrinkable<std::vector<Point2>> draw_set(std::uint64_t block) const {
        const rc::Random random(derive_seed(options.seed, {fuzz_predicates_id, block}));
        return testing::gen_points(options.families[family_position(block)], fuzz_set_points)(random);
    }

    /// Query j of block b: its predicate, and distinct points chosen by its own stream.
    QueryPlan plan(std::uint64_t block, std::uint64_t j) const {
        QueryPlan q{options.predicates[j % predicate_count()]};
        SplitMix64 random{derive_seed(options.seed, {fuzz_predicates_id, block, j})};
        const std::size_t k = point_count(q.predicate);
        for (std::size_t i = 0; i < k; ++i) {
            bool fresh = false;
            while (!fresh) {
                q.index[i] = std::uint8_t(random.below(fuzz_set_points));
                fresh = std::find(q.index.begin(), q.index.begin() + std::ptrdiff_t(i), q.index[i]) ==
                        q.index.begin() + std::ptrdiff_t(i);
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
    if (plan.predicate == Predicate::incircle_cosine) q = testing::arrange_for_cosine(q, AdaptiveKernel{});
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
            case Predicate::incircle_cosine: return batch::incircle_cosine(a[0], a[1], a[2], a[3], out);
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
    return std::visit([&](const auto& k) { return exidel::evaluate(k, p, std::span(q.data(), point_count(p))); },
                      kernel);
}

/// Every query of block b.
Partial run_block(const Campaign& c, std::uint64_t block) {
    std::vector<Point2> set;
    {
        const std::lock_guard lock(rapidcheck_mutex());
        set = c.draw_set(block).value();
    }
    const std::size_t P = c.predicate_count();
    std::vector<Columns> columns(P);
    const std::uint64_t count = c.layout.queries_in_block(block);
    for (std::uint64_t j = 0; j < count; ++j) {
        const QueryPlan plan = c.plan(block, j);
        columns[j % P].push(make_query(set, plan), point_count(plan.predicate), std::uint32_t(j));
    }
    Partial result;
    result.counts.resize(c.family_count() * P);
    const std::size_t row = c.family_position(block) * P;
    std::vector<Sign> mine, theirs;
    for (std::size_t p = 0; p < P; ++p) {
        const Columns& col = columns[p];
        mine.resize(col.j.size());
        theirs.resize(col.j.size());
        evaluate_columns(c.kernel, c.options.predicates[p], col, mine);
        evaluate_columns(c.reference, c.options.predicates[p], col, theirs);
        FuzzCount& n = result.counts[row + p];
        n.queries += col.j.size();
        for (std::size_t i = 0; i < col.j.size(); ++i) {
            if (mine[i] == theirs[i]) continue;
            ++n.disagreements;
            result.disagreements.push_back({block * fuzz_block_queries + col.j[i], mine[i], theirs[i]});
        }
    }
    // The first ones in query order (the columns are per predicate).
    result.add({}, c.options.max_reports);
    return result;
}

// ---------------------------------------------------------------------------------
// Partial results as text: the files of a checkpoint and the messages between ranks.

std::string serialize(const Partial& p, std::uint64_t resumed) {
    std::ostringstream out;
    out << "resumed " << resumed << "\ncounts " << p.counts.size() << '\n';
    for (const FuzzCount& n : p.counts) out << n.queries << ' ' << n.disagreements << '\n';
    out << "disagreements " << p.disagreements.size() << '\n';
    for (const RawDisagreement& d : p.disagreements) {
        out << d.index << ' ' << to_int(d.kernel) << ' ' << to_int(d.reference) << '\n';
    }
    out << "end\n";
    return out.str();
}

/// The inverse of serialize; nothing when the text is not a whole partial result (a file
/// cut short by an interruption, say).
std::optional<std::pair<Partial, std::uint64_t>> deserialize(std::istream& in, std::size_t counts) {
    Partial p;
    std::string word;
    std::uint64_t resumed = 0;
    std::size_t n = 0;
    if (!(in >> word >> resumed) || word != "resumed" || !(in >> word >> n) || word != "counts" || n != counts) {
        return std::nullopt;
    }
    p.counts.resize(n);
    for (FuzzCount& c : p.counts) {
        if (!(in >> c.queries >> c.disagreements)) return std::nullopt;
    }
    if (!(in >> word >> n) || word != "disagreements") return std::nullopt;
    auto sign = [](int v) { return v < 0 ? Sign::negative : v > 0 ? Sign::positive : Sign::zero; };
    for (std::size_t i = 0; i < n; ++i) {
        RawDisagreement d{};
        int k = 0, r = 0;
        if (!(in >> d.index >> k >> r)) return std::nullopt;
        d.kernel = sign(k);
        d.reference = sign(r);
        p.disagreements.push_back(d);
    }
    if (!(in >> word) || word != "end") return std::nullopt;
    return std::pair{std::move(p), resumed};
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

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::filesystem::path stripe_path(const std::filesystem::path& dir, std::uint64_t stripe) {
    char name[40];
    std::snprintf(name, sizeof name, "stripe-%08llu", static_cast<unsigned long long>(stripe));
    return dir / name;
}

/// Written to a temporary name and renamed: a stripe file is whole or absent.
void write_atomically(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::path tmp = path;
    tmp += ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << text;
        out.flush();
        if (!out) throw std::runtime_error("cannot write the checkpoint file " + tmp.string());
    }
    std::filesystem::rename(tmp, path);
}

/// The reason the checkpoint directory cannot serve this campaign; empty when it can.
std::string checkpoint_problem(const Campaign& c) {
    const std::filesystem::path& dir = c.options.checkpoint;
    const std::filesystem::path campaign = dir / "campaign";
    std::error_code ec;
    const bool exists = std::filesystem::exists(campaign, ec);
    if (!c.options.resume) {
        if (exists) {
            return "the checkpoint directory '" + dir.string() +
                   "' holds an unfinished campaign: --resume continues it; remove the directory to start afresh";
        }
        return {};
    }
    if (!exists) return "--resume: no campaign to resume in '" + dir.string() + "'";
    const std::string theirs = read_file(campaign), ours = campaign_text(c);
    if (theirs == ours) return {};
    // Name the first line that differs.
    std::istringstream a(theirs), b(ours);
    std::string la, lb;
    while (std::getline(a, la) && std::getline(b, lb) && la == lb) {
    }
    return "--resume: the checkpoint in '" + dir.string() + "' is of another campaign (it has '" + la +
           "', this run has '" + lb + "')";
}

// ---------------------------------------------------------------------------------
// Shrinking.

/// At most this many candidate sets are tried per disagreement: a shrink costs one draw
/// of the set (about 100 us), so a report never takes more than a second or so.
constexpr std::size_t shrink_budget = 10000;

Disagreement shrink(const Campaign& c, const RawDisagreement& raw) {
    const std::uint64_t block = raw.index / fuzz_block_queries, j = raw.index % fuzz_block_queries;
    const QueryPlan plan = c.plan(block, j);
    Disagreement d;
    d.index = raw.index;
    d.family = c.options.families[c.family_position(block)];
    d.predicate = plan.predicate;
    d.kernel_sign = raw.kernel;
    d.reference_sign = raw.reference;

    const std::lock_guard lock(rapidcheck_mutex());
    rc::Shrinkable<std::vector<Point2>> set = c.draw_set(block);
    d.query = d.shrunk = make_query(set.value(), plan);
    d.shrunk_kernel_sign = raw.kernel;
    d.shrunk_reference_sign = raw.reference;
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

// ---------------------------------------------------------------------------------
// Running the stripes.

Partial run_stripe(const Campaign& c, std::uint64_t stripe, Progress& progress) {
    const std::uint64_t first = c.layout.block_begin(stripe);
    std::vector<Partial> blocks(c.layout.block_end(stripe) - first);
    parallel_for(blocks.size(), c.options.jobs, [&](std::size_t i) {
        blocks[i] = run_block(c, first + i);
        progress.advance(c.layout.queries_in_block(first + i));
    });
    Partial p;
    p.counts.resize(c.family_count() * c.predicate_count());
    for (const Partial& b : blocks) p.add(b, c.options.max_reports);
    return p;
}

/// This rank's stripes, each run or (with --resume) read back from the checkpoint.
std::pair<Partial, std::uint64_t> run_rank(const Campaign& c, Team& team) {
    const std::size_t counts = c.family_count() * c.predicate_count();
    Partial mine;
    mine.counts.resize(counts);
    std::uint64_t resumed = 0;
    std::vector<std::uint64_t> todo;
    for (std::uint64_t s = std::uint64_t(team.rank()); s < c.layout.stripes; s += std::uint64_t(team.size())) {
        if (c.options.resume) {
            std::ifstream in(stripe_path(c.options.checkpoint, s), std::ios::binary);
            if (in) {
                if (auto done = deserialize(in, counts)) {
                    mine.add(done->first, c.options.max_reports);
                    resumed += c.layout.queries_in_stripe(s);
                    continue;
                }
            }
        }
        todo.push_back(s);
    }
    std::uint64_t work = 0;
    for (std::uint64_t s : todo) work += c.layout.queries_in_stripe(s);
    Progress progress("fuzz predicates", work, c.options.progress && team.rank() == 0);
    for (std::uint64_t s : todo) {
        const Partial p = run_stripe(c, s, progress);
        if (!c.options.checkpoint.empty()) {
            write_atomically(stripe_path(c.options.checkpoint, s), serialize(p, 0));
        }
        mine.add(p, c.options.max_reports);
    }
    return {std::move(mine), resumed};
}

}  // namespace

PredicateFuzzResult fuzz_predicates(const PredicateFuzzOptions& options, Team& team) {
    const auto start = std::chrono::steady_clock::now();
    const Campaign c(options);
    PredicateFuzzResult result;
    result.options = c.options;
    result.ranks = team.size();
    result.commit = std::string(build_info().commit);

    // Every rank checks the checkpoint before anyone writes to it, and all stop if one
    // rank cannot go on (the others would otherwise wait for it forever).
    const std::string problem = c.options.checkpoint.empty() ? std::string() : checkpoint_problem(c);
    if (team.max(problem.empty() ? 0.0 : 1.0) != 0.0) {
        throw std::invalid_argument(problem.empty() ? "another rank refused the checkpoint" : problem);
    }
    if (!c.options.checkpoint.empty()) {
        if (team.rank() == 0 && !c.options.resume) {
            std::filesystem::create_directories(c.options.checkpoint);
            write_atomically(c.options.checkpoint / "campaign", campaign_text(c));
        }
        (void)team.max(0.0);  // the directory exists for every rank from here on
    }

    auto [mine, resumed] = run_rank(c, team);
    const std::vector<std::string> parts = team.gather(serialize(mine, resumed));
    result.seconds = team.max(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (team.rank() != 0) return result;

    Partial all;
    all.counts.resize(c.family_count() * c.predicate_count());
    for (const std::string& part : parts) {
        std::istringstream in(part);
        auto p = deserialize(in, all.counts.size());
        if (!p) throw std::runtime_error("fuzz: a rank's result did not arrive whole");
        all.add(p->first, c.options.max_reports);
        result.resumed_queries += p->second;
    }
    result.counts = all.counts;
    for (const FuzzCount& n : all.counts) {
        result.total.queries += n.queries;
        result.total.disagreements += n.disagreements;
    }
    if (result.total.queries != c.options.queries) {
        throw std::runtime_error("fuzz: " + std::to_string(result.total.queries) + " queries were counted, " +
                                 std::to_string(c.options.queries) + " asked for");
    }
    for (const RawDisagreement& raw : all.disagreements) result.reported.push_back(shrink(c, raw));
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
            preds[std::string(predicate_name(o.predicates[p]))] = {{"queries", n.queries},
                                                                   {"disagreements", n.disagreements}};
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
    j["max_reports"] = o.max_reports;
    j["exidel"] = r.commit;
    j["seconds"] = r.seconds;
    j["run"] = {{"ranks", r.ranks},
                {"threads_per_rank", o.jobs},
                {"queries_per_second", r.seconds > 0 ? double(r.total.queries - r.resumed_queries) / r.seconds : 0.0},
                {"resumed_queries", r.resumed_queries}};
    return j.dump(2) + "\n";
}

Team& Team::solo() {
    static SoloTeam team;
    return team;
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
