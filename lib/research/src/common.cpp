// exidel::research: kernels by name, seeds, progress bar, tables and reports.
#include "exidel/research/common.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "exidel/predicates/build_info.hpp"

namespace exidel::research {

Kernel parse_kernel(std::string_view name) {
    std::string error;
    if (auto k = exidel::parse_kernel(name, error)) return std::move(*k);
    throw std::invalid_argument(error);
}

std::string kernel_file_name(const Kernel& k) {
    std::string s = kernel_name(k);
    std::erase(s, ':');
    return s;
}

Formulation formulation_from_name(std::string_view name) {
    for (Formulation f : all_formulations) {
        if (predicate_name(f) == name) return f;
    }
    throw std::invalid_argument("unknown formulation '" + std::string(name) +
                                "' (expected orient2d|incircle|incircle_cosine)");
}

std::uint64_t derive_seed(std::uint64_t seed, std::initializer_list<std::uint64_t> path) {
    // SplitMix64's finaliser, once per path element: a bijective mix, so different
    // (seed, path) prefixes never collide by construction at any single step.
    auto mix = [](std::uint64_t z) {
        z += 0x9e3779b97f4a7c15ULL;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    };
    std::uint64_t h = mix(seed);
    for (std::uint64_t p : path) h = mix(h ^ mix(p + 0x632be59bd9b4e019ULL));
    return h;
}

std::mutex& rapidcheck_mutex() {
    static std::mutex m;
    return m;
}

// ---------------------------------------------------------------------------------

Progress::Progress(std::string label, std::size_t total, bool allowed)
    : label_(std::move(label)),
      total_(total),
      enabled_(allowed && total > 0 && isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
    if (!drawn_) return;
    draw(done_.load());
    std::fputs("\n", stderr);
    std::fflush(stderr);
}

void Progress::advance(std::size_t n) {
    const std::size_t done = done_.fetch_add(n) + n;
    if (!enabled_) return;
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                        std::chrono::steady_clock::now() - start_)
                        .count();
    // Silent for the first second; then at most one redraw per 100 ms.
    if (ms < 1000) return;
    std::int64_t last = last_draw_ms_.load();
    if (last >= 0 && ms - last < 100) return;
    if (!last_draw_ms_.compare_exchange_strong(last, ms)) return;
    const std::unique_lock lock(draw_mutex_, std::try_to_lock);
    if (lock.owns_lock()) draw(done);
}

void Progress::draw(std::size_t done) {
    constexpr int width = 30;
    done = std::min(done, total_);
    const double f = total_ == 0 ? 1.0 : double(done) / double(total_);
    const int filled = static_cast<int>(f * width);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(width, '.');
    // The rate so far, and the time left at that rate (a campaign of 10^9 queries runs
    // for most of an hour).
    const double rate = elapsed > 0 ? double(done) / elapsed : 0;
    char eta[32] = "?";
    if (rate > 0) {
        const auto left = static_cast<long long>(double(total_ - done) / rate);
        if (left >= 3600) {
            std::snprintf(eta, sizeof eta, "%lldh%02lldm", left / 3600, left / 60 % 60);
        } else if (left >= 60) {
            std::snprintf(eta, sizeof eta, "%lldm%02llds", left / 60, left % 60);
        } else {
            std::snprintf(eta, sizeof eta, "%llds", left);
        }
    }
    std::fprintf(stderr, "\r%s [%s] %zu/%zu  %.3g/s  %.0f s, %s left   ", label_.c_str(),
                 bar.c_str(), done, total_, rate, elapsed, eta);
    std::fflush(stderr);
    drawn_ = true;
}

// ---------------------------------------------------------------------------------

std::string Table::markdown() const {
    std::ostringstream s;
    auto row = [&](const std::vector<std::string>& cells) {
        s << '|';
        for (const std::string& c : cells) s << ' ' << c << " |";
        s << '\n';
    };
    row(header);
    s << '|';
    for (std::size_t i = 0; i < header.size(); ++i) s << "---|";
    s << '\n';
    for (const auto& r : rows) row(r);
    return s.str();
}

std::string Table::csv() const {
    std::ostringstream s;
    auto cell = [&](const std::string& c) {
        if (c.find_first_of(",\"\n") == std::string::npos) {
            s << c;
            return;
        }
        s << '"';
        for (char ch : c) s << (ch == '"' ? "\"\"" : std::string(1, ch));
        s << '"';
    };
    auto row = [&](const std::vector<std::string>& cells) {
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i) s << ',';
            cell(cells[i]);
        }
        s << '\n';
    };
    row(header);
    for (const auto& r : rows) row(r);
    return s.str();
}

std::string Table::text() const {
    std::vector<std::size_t> width(header.size(), 0);
    auto measure = [&](const std::vector<std::string>& cells) {
        for (std::size_t i = 0; i < cells.size() && i < width.size(); ++i) {
            width[i] = std::max(width[i], cells[i].size());
        }
    };
    measure(header);
    for (const auto& r : rows) measure(r);
    std::ostringstream s;
    auto row = [&](const std::vector<std::string>& cells) {
        for (std::size_t i = 0; i < cells.size(); ++i) {
            s << cells[i];
            if (i + 1 < cells.size() && i < width.size()) {
                s << std::string(width[i] - cells[i].size() + 2, ' ');
            }
        }
        s << '\n';
    };
    row(header);
    for (const auto& r : rows) row(r);
    return s.str();
}

std::string Report::render(std::string_view prefix, int level, bool embedded) const {
    std::ostringstream s;
    s << std::string(static_cast<std::size_t>(level), '#') << ' ' << title_ << "\n\n";
    for (const Block& b : blocks_) {
        if (embedded && b.standalone) continue;
        switch (b.kind) {
            case Kind::heading:
                s << std::string(static_cast<std::size_t>(level + 1), '#') << ' ' << b.text
                  << "\n\n";
                break;
            case Kind::paragraph: s << b.text << "\n\n"; break;
            case Kind::code:
                s << "```\n" << b.text << (b.text.ends_with('\n') ? "" : "\n") << "```\n\n";
                break;
            case Kind::table: s << b.text << '\n'; break;
            case Kind::image: s << "![" << b.text << "](" << prefix << b.path << ")\n\n"; break;
            case Kind::link: s << "[" << b.text << "](" << prefix << b.path << ")\n\n"; break;
        }
    }
    return s.str();
}

std::string shell_quote(std::string_view s) {
    const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               std::string_view("_./:,=+@%^-").find(c) != std::string_view::npos;
    });
    if (plain) return std::string(s);
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string default_command(std::string_view study, const RunOptions& run) {
    return "exidel study " + std::string(study) + (run.quick ? " --quick" : "") + " --seed " +
           std::to_string(run.seed) + " --out " + shell_quote(run.out.string());
}

Report run_header(const RunOptions& run) {
    Report r("");
    if (run.command.empty()) {
        r.paragraph(std::string(rerun_prefix.substr(0, rerun_prefix.size() - 1)) +
                    "this report was produced through the library API (exidel::research), "
                    "not by the exidel command; seed " +
                    std::to_string(run.seed) + ".");
    } else {
        r.paragraph(std::string(rerun_prefix) + run.command + "`");
        r.standalone_paragraph(
            "This command carries every option that changes a result (--jobs changes none). "
            "Run with the build and on the machine below, it writes these files again byte for "
            "byte, all but the timing line. Another build or machine may compute other results, "
            "the long-double kernel's above all: they depend on the long-double format below.");
    }
    const BuildInfo& b = build_info();
    std::string kernels;
    for (std::string_view k : b.kernels) kernels += (kernels.empty() ? "" : ", ") + std::string(k);
    Table t;
    t.header = {"built and run with", ""};
    // Appends rather than "`" + s + "`": GCC 12 warns falsely (-Wrestrict) on the latter.
    const auto code = [](std::string_view v) {
        std::string out(1, '`');
        out.append(v);
        out += '`';
        return out;
    };
    t.rows = {
        {"exidel", std::string(b.version) + ", commit " + code(b.commit)},
        {"compiler", std::string(b.compiler) +
                         (b.build_type.empty() ? "" : ", " + std::string(b.build_type) + " build")},
        {"library flags", code(b.cxx_flags)},
        {"GMP / MPFR / Boost",
         std::string(b.gmp) + " / " + std::string(b.mpfr) + " / " + std::string(b.boost)},
        {"CPU", cpu_model()},
        {"long double",
         std::string(b.long_double) + ": the long-double kernel's results depend on it"},
        {"kernels", kernels},
    };
    r.standalone_table(t);
    return r;
}

std::string timing_line(double seconds, const RunOptions& run) {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &utc);
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.1f s wall-clock with %u thread%s, finished %s.", seconds,
                  run.jobs, run.jobs == 1 ? "" : "s", date);
    return std::string(timing_prefix) + buf;
}

void write_text_file(const std::filesystem::path& file, std::string_view text) {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

std::string format_rate(std::uint64_t wrong, std::uint64_t total) {
    if (total == 0) return "-";
    char buf[32];
    const double r = double(wrong) / double(total);
    if (wrong == 0) return "0";
    std::snprintf(buf, sizeof buf, r >= 1e-3 ? "%.4f" : "%.2e", r);
    return buf;
}

std::string format_fraction(double value) {
    char buf[32];
    if (value == 0) return "0";
    std::snprintf(buf, sizeof buf, value >= 1e-3 ? "%.4f" : "%.2e", value);
    return buf;
}

void log_line(const RunOptions& run, std::string_view text) {
    if (!run.log) return;
    *run.log << text;
    if (!text.ends_with('\n')) *run.log << '\n';
    run.log->flush();
}

}  // namespace exidel::research
