// exidel CLI (internal): what exidel triangulate and exidel voronoi share (common.hpp).
#include "common.hpp"

#include <charconv>
#include <cstring>
#include <cmath>
#include <system_error>
#include <type_traits>
#include <variant>

#include "exidel/delaunay/triangulate.hpp"
#include "memory.hpp"

namespace exidel::cli {

const std::string_view point_input_help =
    R"(Input (-i FILE or FILE, or standard input when no file or '-' is given). The format
is --input-format, else the file's extension (.json json, .node node, .f64 f64,
.geojson geojson, .poly poly), else xy:
  xy    one point per line, "x y" or "x,y" (.txt .xy .csv); '#' starts a comment;
        the first line may be a header of names ("x,y"), which is skipped; fields
        may be quoted ("x","y"); a UTF-8 byte order mark is skipped. Wider CSV:
        --columns X,Y picks the two fields by number (from 1) or header name;
        --columns X,Y,Z also reads a third as z (a finite number; triangulate
        writes it, voronoi ignores it)
  json  [[x, y], [x, y], ...]
  node  Triangle's .node: "n 2 attributes markers", then "index x y [...]" lines
        (0- or 1-based); attributes and markers are checked and ignored
  f64   raw little-endian float64 pairs x0 y0 x1 y1 ...
  geojson  RFC 7946 FeatureCollection, Feature or geometry of Point and MultiPoint
        (GeometryCollections of them too); a feature with a null geometry is
        skipped, other geometry types are an error naming the feature; z is the
        positions' third coordinate (all or none), or with triangulate's
        --z-property NAME that property's value
  poly  Triangle's .poly: its vertices (as .node); triangulate reads its segments,
        holes and regions too (constrained mode)
Text coordinates are decimal or C99 hex floats (0x1.8p-3; json: decimal only),
)";

std::string point_command_help(std::string_view head, std::string_view tail) {
    return std::string(head) + std::string(point_input_help) + std::string(tail) +
           delaunay::algorithm_help() + "\nKernels:\n" + kernel_help();
}

void add_algorithm_option(CLI::App& app, delaunay::Algorithm& target) {
    app.add_option_function<std::string>("-a,--algorithm", [&target](const std::string& name) {
        const std::optional<delaunay::Algorithm> a = delaunay::algorithm_from_name(name);
        if (!a) {
            throw std::invalid_argument("unknown algorithm '" + name + "' (expected " +
                                        delaunay::algorithm_spellings() + ")");
        }
        target = *a;
    });
}

std::optional<std::size_t> whole_number(const std::string& text, std::size_t limit) {
    std::size_t n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc{} || end != text.data() + text.size() || n == 0 || n > limit) return {};
    return n;
}

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void PointInput::add_file_options(CLI::App& app) {
    input_option_ = app.add_option("-i,--input", path);
    app.add_option("FILE", files_);
}

void PointInput::add_format_options(CLI::App& app) {
    add_point_format_option(app, format);
    add_columns_option(app, columns);
}

void PointInput::add_z_property_option(CLI::App& app) {
    app.add_option_function<std::string>("--z-property", [this](const std::string& name) {
        if (name.empty()) throw std::invalid_argument("--z-property needs a property name");
        z_property = name;
    });
}

std::optional<std::string> PointInput::take_files() {
    if (input_option_->count() + files_.size() > 1) return "more than one input file given";
    if (!files_.empty()) path = files_.front();
    return std::nullopt;
}

io::PointFormat PointInput::resolved_format() const {
    if (format) return *format;
    return from_stdin() ? io::PointFormat::xy : io::point_format_from_path(*path);
}

std::optional<std::string> PointInput::columns_error() const {
    if (z_property && resolved_format() != io::PointFormat::geojson) {
        return "--z-property applies to geojson input, not to " +
               std::string(io::to_string(resolved_format()));
    }
    return cli::columns_error(columns, resolved_format());
}

std::optional<io::PointFile> PointInput::read(unsigned threads, Progress& progress) const {
    progress.phase(from_stdin() ? "reading standard input" : "reading '" + *path + "'");
    try {
        const io::ReadOptions options{columns, threads, z_property};
        if (from_stdin()) return io::read_point_file(std::cin, resolved_format(), options);
        const io::FileBytes bytes(*path);
        return io::parse_point_file(bytes.view(), resolved_format(), options);
    } catch (const std::runtime_error& e) {  // io::ReadError included
        progress.stop();
        std::cerr << "exidel: " << e.what() << '\n';
        return std::nullopt;
    }
}

std::optional<io::ConstraintFile> PointInput::read_constraints(Progress& progress) const {
    progress.phase(from_stdin() ? "reading standard input" : "reading '" + *path + "'");
    try {
        if (from_stdin()) {
            std::string data;
            char chunk[1 << 16];
            while (std::cin.read(chunk, sizeof chunk) || std::cin.gcount() > 0) {
                data.append(chunk, static_cast<std::size_t>(std::cin.gcount()));
            }
            if (std::cin.bad()) throw std::runtime_error("error while reading the input");
            return io::parse_constraint_file(data, resolved_format());
        }
        const io::FileBytes bytes(*path);
        return io::parse_constraint_file(bytes.view(), resolved_format());
    } catch (const std::runtime_error& e) {  // io::ReadError included
        progress.stop();
        std::cerr << "exidel: " << e.what() << '\n';
        return std::nullopt;
    }
}

void PointCommand::add_input_output_options(CLI::App& app) {
    input.add_file_options(app);
    output_option_ = app.add_option("-o,--output", output);
    app.add_option("-k,--kernel", kernel);
    add_algorithm_option(app, algorithm);
}

void PointCommand::add_threads_option(CLI::App& app) {
    add_parsed(app, "--threads", "a whole number from 1 to 1024", threads,
               [](const std::string& v) { return whole_number(v, 1024); });
}

void PointCommand::add_report_options(CLI::App& app) {
    app.add_flag("--stats", stats);
    app.add_flag("-q,--quiet", quiet);
}

std::optional<int> PointCommand::parse(CommandLine& cli, std::span<const std::string_view> args) {
    if (const std::optional<int> status = cli.parse(args)) return *status;
    if (const std::optional<std::string> e = input.take_files()) return cli.usage_error(*e);
    if (output_option_->count() > 1) return cli.usage_error("more than one output file given");
    return std::nullopt;
}

std::optional<AnyKernel> PointCommand::checked_kernel(std::string& error) const {
    std::optional<AnyKernel> k = parse_kernel(kernel, error);
    if (!k) return std::nullopt;
    if (std::optional<std::string> e = input.columns_error()) {
        error = std::move(*e);
        return std::nullopt;
    }
    return k;
}

bool PointCommand::open_output(std::optional<PendingFile>& file) const {
    return reported([&] {
        if (!to_stdout()) file.emplace(*output);
    });
}

Triangulated triangulate_points(const AnyKernel& kernel, std::span<const Point2> points,
                                const delaunay::Options& options, bool counters) {
    return timed_triangulation(kernel, [&](const auto& k) {
        return counters
                   ? delaunay::triangulate<delaunay::Instrumentation::counters>(points, k, options)
                   : delaunay::triangulate<delaunay::Instrumentation::off>(points, k, options);
    });
}

namespace {

// What each failure means, completing the algorithm's message (which says where).
std::string_view failure_meaning(delaunay::FailureKind kind) {
    using delaunay::FailureKind;
    switch (kind) {
        case FailureKind::non_finite_input: return "a coordinate is NaN or infinite";
        case FailureKind::too_many_points:
            return "more points than 32-bit half-edge indices can address";
        case FailureKind::unknown_algorithm: return "no such algorithm";
        case FailureKind::result_inconsistent:
            return "the finished triangulation does not close up";
        case FailureKind::invalid_segment: return "a segment names a point that does not exist";
        case FailureKind::too_many_crossings:
            return "more crossing points than the limit allows (max_added_points)";
        default: return "the kernel's signs contradict each other";
    }
}

}  // namespace

void print_triangulation_failure(std::ostream& err, const Triangulated& t) {
    const delaunay::Failure& f = *t.result.failure;
    err << "exidel: triangulation failed: " << f.message << ": " << failure_meaning(f.kind) << " ("
        << delaunay::to_string(f.kind) << ").";
    if (!t.exact_kernel) {
        err << " The " << t.kernel_name << " kernel is not exact; an exact kernel "
            << "(adaptive, the default) triangulates every finite input.";
    }
    err << '\n';
}

std::string write_error(const std::string& what, int error) {
    return error == 0 ? what : what + ": " + std::strerror(error);
}

void print_findings(std::ostream& err, const delaunay::Certificate& c) {
    for (const delaunay::Finding& f : c.findings) {
        err << "exidel: certificate: " << delaunay::to_string(f.kind) << ": " << f.message << '\n';
    }
    if (c.total_findings > c.findings.size()) {
        err << "exidel: certificate: ... and " << c.total_findings - c.findings.size()
            << " more findings\n";
    }
}

PointRun::PointRun(const PointCommand& command, Clock::time_point start)
    : progress(!command.quiet), command_(command), start_(start) {}

std::optional<io::PointFile> PointRun::read() {
    note_memory_need("reading the input", 0, 0);
    const Clock::time_point start = Clock::now();
    std::optional<io::PointFile> points = command_.input.read(command_.threads, progress);
    if (points) times.read = ms_since(start);
    return points;
}

Triangulated PointRun::triangulate(const AnyKernel& kernel, std::span<const Point2> points,
                                   const delaunay::Options& options, bool counters) {
    start_triangulating(points.size(), "");
    return recorded(triangulate_points(kernel, points, options, counters));
}

void PointRun::start_triangulating(std::size_t points, std::string_view what) {
    progress.phase("triangulating " + std::to_string(points) + " points" + std::string(what));
    note_memory_need("triangulating", points,
                     static_cast<double>(points) * triangulate_bytes_per_point);
}

Triangulated PointRun::recorded(Triangulated t) {
    times.triangulate = t.ms;
    if (!t.result.ok()) {
        progress.stop();
        print_triangulation_failure(std::cerr, t);
    }
    return t;
}

bool PointRun::write(std::optional<PendingFile>& output, const Writer& write,
                     std::span<const BesideFile> beside) {
    progress.phase("writing");
    const Clock::time_point start = Clock::now();
    const bool ok = reported(
        [&] {
            if (!output) {
                write_stdout(write);
                return;
            }
            write_into(*output, write);
            for (const BesideFile& f : beside) write_into(f.file, f.write);
            output->commit();
            for (const BesideFile& f : beside) f.file.commit();
        },
        &progress);
    if (!ok) return false;
    times.write = ms_since(start);
    progress.stop();
    return true;
}

nlohmann::ordered_json& with_times(nlohmann::ordered_json& stats, const StepTimes& times,
                                   double certify_ms) {
    stats["read_ms"] = stats_ms(times.read);
    stats["triangulate_ms"] = stats_ms(times.triangulate);
    stats["certify_ms"] = stats_ms(certify_ms);
    stats["write_ms"] = stats_ms(times.write);
    stats["total_ms"] = stats_ms(times.total);
    return stats;
}

double stats_ms(double ms) { return std::round(ms * 1e6) / 1e6; }

std::string stats_line(const nlohmann::ordered_json& stats) {
    // dump(0) puts each item on its own line with ": " (a string's own newlines are
    // escaped, so every '\n' is layout).
    std::string line;
    for (const char c : stats.dump(0)) {
        if (c != '\n') {
            line += c;
        } else if (!line.empty() && line.back() == ',') {
            line += ' ';
        }
    }
    return line + '\n';
}

}  // namespace exidel::cli
