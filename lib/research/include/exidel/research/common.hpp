// exidel::research: what every study shares. The kernels a study can run, the three
// formulations, reproducible seeds, deterministic work splitting over threads, the
// progress bar, and the tables and reports a study writes.
//
// Determinism: a study splits its work into a fixed list of chunks whose contents and
// seeds depend only on the study's options and --seed, never on --jobs; threads take
// chunks in any order and write each result into the chunk's own slot, and the results
// are combined in chunk order. The same seed therefore gives byte-identical output files
// for every --jobs.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "exidel/delaunay/parallel.hpp"
#include "exidel/predicates/all.hpp"

namespace exidel::research {

// ---------------------------------------------------------------------------------
// Kernels and formulations.

/// The kernels a study can evaluate: every kernel of the registry
/// (exidel/predicates/registry.hpp). GmpExactKernel is the reference of every study.
using Kernel = AnyKernel;
using exidel::kernel_name;

/// parse_kernel of the registry, throwing std::invalid_argument with its message.
Kernel parse_kernel(std::string_view name);
/// kernel_name with characters unsafe in file names replaced ("mpfr:64" -> "mpfr64").
std::string kernel_file_name(const Kernel& k);

/// The formulations the studies compare: the predicates of exidel/predicates/predicate.hpp
/// whose formulas fail in floating point in different ways (compare_distance, the radial
/// order's key, is counted by the stages study only).
using Formulation = Predicate;
inline constexpr Formulation all_formulations[] = {Predicate::orient2d, Predicate::incircle,
                                                   Predicate::incircle_cosine};
/// Throws std::invalid_argument for anything but the three names.
Formulation formulation_from_name(std::string_view name);

// ---------------------------------------------------------------------------------
// Seeds.

/// A 64-bit seed derived from `seed` and a path of integers (study, family, chunk, ...)
/// with SplitMix64 steps: distinct paths give unrelated streams.
std::uint64_t derive_seed(std::uint64_t seed, std::initializer_list<std::uint64_t> path);

/// RapidCheck keeps the generation context of rc::gen::exec in process-wide stacks, so
/// generators must never run on two threads at once. Chunks hold this lock while they
/// draw their inputs (from their own seed, so the order of drawing does not matter) and
/// release it for the evaluation.
std::mutex& rapidcheck_mutex();

// ---------------------------------------------------------------------------------
// Options every study accepts.

struct RunOptions {
    std::uint64_t seed = 20250704;  ///< printed in every report; the run is a function of it
    std::filesystem::path out = "exidel-study";
    unsigned jobs = 1;            ///< threads; results do not depend on it
    bool quick = false;           ///< the short preset (study all --quick, the tests)
    bool progress = true;         ///< allow the progress bar (still only on a terminal)
    std::ostream* log = nullptr;  ///< summary lines (stdout in the CLI); null: silent
    /// The command line that reproduces this run's files, printed at the top of its report
    /// (run_header). The CLI sets it from the options given; run_all_studies composes its
    /// own. Empty: the report says the run was made through the library API.
    std::string command;
};

/// `exidel study <study> [--quick] --seed N --out DIR`: the command of a study run with
/// no options but the common ones, which is what run_all_studies runs.
std::string default_command(std::string_view study, const RunOptions& run);

/// `s` quoted for a POSIX shell when it holds anything but [A-Za-z0-9_./:,=+@%^-].
std::string shell_quote(std::string_view s);

// ---------------------------------------------------------------------------------
// Progress bar.

/// A one-line progress bar on stderr: done/total, the rate so far and the time left at it. Drawn
/// only when stderr is a terminal, progress is allowed, and the work has already taken a second
/// (short runs stay silent). advance() is thread-safe and cheap: redraws are limited to ten per
/// second.
class Progress {
public:
    Progress(std::string label, std::size_t total, bool allowed);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void advance(std::size_t n = 1);

private:
    void draw(std::size_t done);

    std::string label_;
    std::size_t total_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    std::atomic<std::size_t> done_{0};
    std::atomic<std::int64_t> last_draw_ms_{-1};
    std::mutex draw_mutex_;
    bool drawn_ = false;
};

/// Runs body(i) for every chunk i in [0, chunks) on `jobs` threads (jobs >= 1; the
/// calling thread is one of them). body must only write to chunk i's own result slot.
/// Advances `progress` by one per finished chunk. The first exception thrown by any
/// body is rethrown here after every thread has stopped.
template <class Body>
void for_each_chunk(std::size_t chunks, unsigned jobs, Progress* progress, Body&& body) {
    parallel_for(chunks, jobs, [&](std::size_t i) {
        body(i);
        if (progress) progress->advance();
    });
}

// ---------------------------------------------------------------------------------
// Tables and reports.

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    std::string markdown() const;
    std::string csv() const;   ///< RFC 4180 quoting where a cell needs it
    std::string text() const;  ///< aligned columns for a terminal
};

/// A report.md under construction: headings, paragraphs, tables, images, code blocks.
/// Image paths are relative to the report's folder; render(prefix) prefixes them, so a
/// study's report can be embedded in the report of `study all` one folder up.
class Report {
public:
    explicit Report(std::string title) : title_(std::move(title)) {}
    void heading(std::string text) { blocks_.push_back({Kind::heading, std::move(text), ""}); }
    void paragraph(std::string text) { blocks_.push_back({Kind::paragraph, std::move(text), ""}); }
    void code(std::string text) { blocks_.push_back({Kind::code, std::move(text), ""}); }
    void table(const Table& t) { blocks_.push_back({Kind::table, t.markdown(), ""}); }
    void image(std::string alt, std::string path) {
        blocks_.push_back({Kind::image, std::move(alt), std::move(path)});
    }
    void link(std::string text, std::string path) {
        blocks_.push_back({Kind::link, std::move(text), std::move(path)});
    }
    /// A paragraph shown only when the report is rendered on its own, not when it is
    /// embedded in the report of `study all` (which says it once at the top).
    void standalone_paragraph(std::string text) {
        blocks_.push_back({Kind::paragraph, std::move(text), "", true});
    }
    void standalone_table(const Table& t) {
        blocks_.push_back({Kind::table, t.markdown(), "", true});
    }
    /// Appends the blocks (not the title) of another report.
    void append(const Report& other) {
        blocks_.insert(blocks_.end(), other.blocks_.begin(), other.blocks_.end());
    }
    /// Puts the blocks (not the title) of another report before this one's.
    void prepend(const Report& other) {
        blocks_.insert(blocks_.begin(), other.blocks_.begin(), other.blocks_.end());
    }
    const std::string& title() const noexcept { return title_; }

    /// The Markdown; `prefix` (e.g. "precision/") is put before every image and link
    /// path, and `level` is the heading level of the title (sections get level + 1).
    /// `embedded`: leave out the standalone blocks.
    std::string render(std::string_view prefix = "", int level = 1, bool embedded = false) const;

private:
    enum class Kind { heading, paragraph, code, table, image, link };
    struct Block {
        Kind kind;
        std::string text;
        std::string path;
        bool standalone = false;
    };
    std::string title_;
    std::vector<Block> blocks_;
};

/// The first line of every report's provenance: "Rerun: `<command>` ...". Tools (and the
/// reproducibility test) find the command between the first pair of backquotes of the
/// line that starts with this prefix.
inline constexpr std::string_view rerun_prefix = "Rerun: `";
/// The one line of a report that differs between reruns of its command on the same
/// machine and build (wall-clock time, date, threads) starts with this prefix.
inline constexpr std::string_view timing_prefix = "Timing (differs between reruns): ";

/// The provenance blocks of a report: the rerun line, then (standalone only) what built
/// and ran it: exidel version and commit, compiler and flags, GMP / MPFR / Boost, CPU, the
/// long-double format.
Report run_header(const RunOptions& run);
/// "Timing (differs between reruns): 11.2 s wall-clock with 1 thread, finished
/// 2026-12-02 12:31 UTC."
std::string timing_line(double seconds, const RunOptions& run);

/// Writes `text` to `file` (creating its folder); throws std::runtime_error on failure.
void write_text_file(const std::filesystem::path& file, std::string_view text);

/// "12.34%"-style and scientific formatting used in every table.
std::string format_rate(std::uint64_t wrong, std::uint64_t total);
std::string format_fraction(double value);

/// Prints `text` to the run's log, if any.
void log_line(const RunOptions& run, std::string_view text);

}  // namespace exidel::research
