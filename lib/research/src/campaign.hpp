// exidel::research (internal): the engine under every fuzzing campaign (fuzz.hpp). A
// campaign is N units (queries, triangulations) in blocks of a fixed size, each block a
// pure function of the seed and its number; the engine groups blocks into stripes, hands
// stripes to MPI ranks in turn and a stripe's blocks to threads, keeps a checkpoint of
// finished stripes, and brings the counts and the first findings to rank 0. What a block
// computes and what its counts mean is the campaign's business.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "exidel/research/fuzz.hpp"

namespace exidel::research::campaign {

/// SplitMix64 (Steele, Lea and Flood 2014): a fast stream of 64-bit words from one seed.
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, n) for n >= 1, by rejection (no modulo bias).
    std::uint64_t below(std::uint64_t n) {
        const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
        for (;;) {
            const std::uint64_t r = next();
            if (r < limit) return r % n;
        }
    }
};

/// Which units a block holds and which blocks a stripe: fixed by N and the block size.
struct Layout {
    std::uint64_t units = 0, block_units = 1, blocks = 0, stripes = 0, stripe_blocks = 0;

    Layout(std::uint64_t units, std::uint64_t block_units, std::uint64_t units_per_stripe);
    std::uint64_t block_begin(std::uint64_t stripe) const { return stripe * stripe_blocks; }
    std::uint64_t block_end(std::uint64_t stripe) const;
    std::uint64_t units_in_block(std::uint64_t block) const;
    std::uint64_t units_in_stripe(std::uint64_t stripe) const;
};

/// A unit that went wrong: its number and two campaign-defined integers (the kernel's
/// and the reference's sign, an outcome).
struct Finding {
    std::uint64_t index;
    std::int32_t a, b;
};

/// What some blocks found: counts (campaign-defined, summed) and their first findings
/// in unit order.
struct Partial {
    std::vector<std::uint64_t> counts;
    std::vector<Finding> findings;

    /// Adds `other`'s counts and keeps the first `max_findings` findings of both.
    void add(const Partial& other, std::size_t max_findings);
};

struct Spec {
    std::string label;     ///< the progress bar's
    std::string identity;  ///< what the checkpoint must match to be resumed (options, build)
    Layout layout{0, 1, 1};
    std::size_t counts = 0;        ///< the size of every Partial::counts
    std::size_t max_findings = 0;  ///< findings kept
    std::filesystem::path checkpoint;
    bool resume = false;
    unsigned jobs = 1;
    bool progress = true;
    /// Block b's counts and findings (called on several threads at once).
    std::function<Partial(std::uint64_t block)> run_block;
};

/// A Spec with what every campaign's options carry (max_reports, checkpoint, resume, jobs,
/// progress); the campaign adds its label, identity, layout, counts and block.
template <class Options>
Spec spec_from(const Options& o) {
    Spec s;
    s.max_findings = o.max_reports;
    s.checkpoint = o.checkpoint;
    s.resume = o.resume;
    s.jobs = o.jobs;
    s.progress = o.progress;
    return s;
}

/// The members that close every campaign's JSON summary: the report limit, the build, the
/// time and how the run was split. `unit` names what the campaign counts ("queries",
/// "triangulations"); the rate leaves out the units read back from a checkpoint.
template <class Json>
void close_summary(Json& j, std::size_t max_reports, const std::string& commit, double seconds,
                   int ranks, unsigned jobs, const std::string& unit, std::uint64_t units,
                   std::uint64_t resumed) {
    j["max_reports"] = max_reports;
    j["exidel"] = commit;
    j["seconds"] = seconds;
    j["run"] = Json{{"ranks", ranks},
                    {"threads_per_rank", jobs},
                    {unit + "_per_second", seconds > 0 ? double(units - resumed) / seconds : 0.0},
                    {"resumed_" + unit, resumed}};
}

struct Outcome {
    Partial all;                ///< rank 0: every rank's; other ranks: empty
    std::uint64_t resumed = 0;  ///< units read back from the checkpoint
    double seconds = 0;         ///< wall time of the slowest rank
};

/// Runs the campaign (every rank of `team` with the same spec). Throws
/// std::invalid_argument when the checkpoint cannot serve it (on every rank alike).
Outcome run(const Spec& spec, Team& team);

}  // namespace exidel::research::campaign
