// exidel::research: the engine under the fuzzing campaigns (campaign.hpp).
#include "campaign.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "exidel/delaunay/parallel.hpp"
#include "exidel/research/common.hpp"

namespace exidel::research {

namespace {

class SoloTeam final : public Team {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    std::vector<std::string> gather(const std::string& mine) override { return {mine}; }
    double max(double value) override { return value; }
};

}  // namespace

Team& Team::solo() {
    static SoloTeam team;
    return team;
}

namespace campaign {

Layout::Layout(std::uint64_t n, std::uint64_t per_block, std::uint64_t units_per_stripe)
    : units(n), block_units(std::max<std::uint64_t>(per_block, 1)) {
    blocks = (units + block_units - 1) / block_units;
    // Long campaigns get stripes of about units_per_stripe units (what an interruption
    // loses per thread); short ones at least 16 stripes when there are enough blocks, so
    // that small runs still spread over a few MPI ranks.
    const std::uint64_t most = std::max<std::uint64_t>(units_per_stripe / block_units, 1);
    stripe_blocks = std::clamp<std::uint64_t>((blocks + 15) / 16, 1, most);
    stripes = (blocks + stripe_blocks - 1) / stripe_blocks;
}

std::uint64_t Layout::block_end(std::uint64_t stripe) const {
    return std::min(blocks, (stripe + 1) * stripe_blocks);
}

std::uint64_t Layout::units_in_block(std::uint64_t b) const {
    return std::min(block_units, units - b * block_units);
}

std::uint64_t Layout::units_in_stripe(std::uint64_t s) const {
    return std::min(units, block_end(s) * block_units) - block_begin(s) * block_units;
}

void Partial::add(const Partial& other, std::size_t max_findings) {
    if (counts.size() < other.counts.size()) counts.resize(other.counts.size());
    for (std::size_t i = 0; i < other.counts.size(); ++i) counts[i] += other.counts[i];
    findings.insert(findings.end(), other.findings.begin(), other.findings.end());
    std::sort(findings.begin(), findings.end(),
              [](const Finding& x, const Finding& y) { return x.index < y.index; });
    if (findings.size() > max_findings) findings.resize(max_findings);
}

namespace {

// ---------------------------------------------------------------------------------
// Partial results as text: the files of a checkpoint and the messages between ranks.

std::string serialize(const Partial& p, std::uint64_t resumed) {
    std::ostringstream out;
    out << "resumed " << resumed << "\ncounts " << p.counts.size() << '\n';
    for (std::uint64_t n : p.counts) out << n << '\n';
    out << "findings " << p.findings.size() << '\n';
    for (const Finding& f : p.findings) out << f.index << ' ' << f.a << ' ' << f.b << '\n';
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
    if (!(in >> word >> resumed) || word != "resumed" || !(in >> word >> n) || word != "counts" ||
        n != counts) {
        return std::nullopt;
    }
    p.counts.resize(n);
    for (std::uint64_t& c : p.counts) {
        if (!(in >> c)) return std::nullopt;
    }
    if (!(in >> word >> n) || word != "findings") return std::nullopt;
    p.findings.resize(n);
    for (Finding& f : p.findings) {
        if (!(in >> f.index >> f.a >> f.b)) return std::nullopt;
    }
    if (!(in >> word) || word != "end") return std::nullopt;
    return std::pair{std::move(p), resumed};
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
std::string checkpoint_problem(const Spec& spec) {
    const std::filesystem::path& dir = spec.checkpoint;
    const std::filesystem::path campaign = dir / "campaign";
    std::error_code ec;
    const bool exists = std::filesystem::exists(campaign, ec);
    if (!spec.resume) {
        if (exists) {
            return "the checkpoint directory '" + dir.string() +
                   "' holds an unfinished campaign: --resume continues it; remove the directory to "
                   "start afresh";
        }
        return {};
    }
    if (!exists) return "--resume: no campaign to resume in '" + dir.string() + "'";
    const std::string theirs = read_file(campaign);
    if (theirs == spec.identity) return {};
    // Name the first line that differs.
    std::istringstream a(theirs), b(spec.identity);
    std::string la, lb;
    while (std::getline(a, la) && std::getline(b, lb) && la == lb) {}
    return "--resume: the checkpoint in '" + dir.string() + "' is of another campaign (it has '" +
           la + "', this run has '" + lb + "')";
}

// ---------------------------------------------------------------------------------
// Running the stripes.

Partial run_stripe(const Spec& spec, std::uint64_t stripe, Progress& progress) {
    const std::uint64_t first = spec.layout.block_begin(stripe);
    std::vector<Partial> blocks(spec.layout.block_end(stripe) - first);
    parallel_for(blocks.size(), spec.jobs, [&](std::size_t i) {
        blocks[i] = spec.run_block(first + i);
        progress.advance(spec.layout.units_in_block(first + i));
    });
    Partial p;
    p.counts.resize(spec.counts);
    for (const Partial& b : blocks) p.add(b, spec.max_findings);
    return p;
}

/// This rank's stripes, each run or (with --resume) read back from the checkpoint.
std::pair<Partial, std::uint64_t> run_rank(const Spec& spec, Team& team) {
    Partial mine;
    mine.counts.resize(spec.counts);
    std::uint64_t resumed = 0;
    std::vector<std::uint64_t> pending;
    const Layout& layout = spec.layout;
    for (std::uint64_t s = std::uint64_t(team.rank()); s < layout.stripes;
         s += std::uint64_t(team.size())) {
        if (spec.resume) {
            std::ifstream in(stripe_path(spec.checkpoint, s), std::ios::binary);
            if (in) {
                if (auto done = deserialize(in, spec.counts)) {
                    mine.add(done->first, spec.max_findings);
                    resumed += layout.units_in_stripe(s);
                    continue;
                }
            }
        }
        pending.push_back(s);
    }
    std::uint64_t work = 0;
    for (std::uint64_t s : pending) work += layout.units_in_stripe(s);
    Progress progress(spec.label, work, spec.progress && team.rank() == 0);
    for (std::uint64_t s : pending) {
        const Partial p = run_stripe(spec, s, progress);
        if (!spec.checkpoint.empty())
            write_atomically(stripe_path(spec.checkpoint, s), serialize(p, 0));
        mine.add(p, spec.max_findings);
    }
    return {std::move(mine), resumed};
}

}  // namespace

Outcome run(const Spec& spec, Team& team) {
    const auto start = std::chrono::steady_clock::now();
    // Every rank checks the checkpoint before anyone writes to it, and all stop if one
    // rank cannot go on (the others would otherwise wait for it forever).
    const std::string problem = spec.checkpoint.empty() ? std::string() : checkpoint_problem(spec);
    if (team.max(problem.empty() ? 0.0 : 1.0) != 0.0) {
        throw std::invalid_argument(problem.empty() ? "another rank refused the checkpoint"
                                                    : problem);
    }
    if (!spec.checkpoint.empty()) {
        if (team.rank() == 0 && !spec.resume) {
            std::filesystem::create_directories(spec.checkpoint);
            write_atomically(spec.checkpoint / "campaign", spec.identity);
        }
        (void)team.max(0.0);  // the directory exists for every rank from here on
    }

    auto [mine, resumed] = run_rank(spec, team);
    const std::vector<std::string> parts = team.gather(serialize(mine, resumed));
    Outcome outcome;
    outcome.seconds =
        team.max(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (team.rank() != 0) return outcome;
    outcome.all.counts.resize(spec.counts);
    for (const std::string& part : parts) {
        std::istringstream in(part);
        auto p = deserialize(in, spec.counts);
        if (!p) throw std::runtime_error("fuzz: a rank's result did not arrive whole");
        outcome.all.add(p->first, spec.max_findings);
        outcome.resumed += p->second;
    }
    return outcome;
}

}  // namespace campaign

}  // namespace exidel::research
