// exidel::research: the studies measure what they claim, deterministically, and what
// they write (PNG, report, fixtures) can be read back and reproduces.
#include <sys/wait.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "exidel/predicates/build_info.hpp"
#include "exidel/research/studies.hpp"
#include "exidel/testing/ulp.hpp"

namespace exidel::research {
namespace {

namespace fs = std::filesystem;
using delaunay::InCirclePolicy;
using delaunay::Strategy;

// A fresh folder per test: ctest may run the tests of this file in parallel.
fs::path work_dir(const std::string& name) {
    const fs::path dir = fs::path(EXIDEL_RESEARCH_WORK) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Every regular file below dir, by relative path, with its bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = read_file(e.path());
    }
    return files;
}

RunOptions quiet_run(const fs::path& out, unsigned jobs = 1) {
    RunOptions run;
    run.out = out;
    run.jobs = jobs;
    run.progress = false;
    run.quick = true;
    return run;
}

// --- failure maps ------------------------------------------------------------------

/// Some wrong cell where the exact sign is positive, and some where it is negative.
bool wrong_on_both_sides(const FailureMap& m) {
    bool where_positive = false, where_negative = false;
    for (std::size_t c = 0; c < m.signs.size(); ++c) {
        if (m.signs[c] == m.exact[c]) continue;
        where_positive |= m.exact[c] == Sign::positive;
        where_negative |= m.exact[c] == Sign::negative;
    }
    return where_positive && where_negative;
}

TEST(FailureMap, Kettner1BreaksDoubleOnBothSidesOfTheLineAndNeverAdaptiveOrExact) {
    const FailureMapSpec spec = failure_map_preset("kettner1");
    const FailureMap dbl = compute_failure_map(spec, DoubleKernel{}, 2);
    EXPECT_GT(dbl.wrong, 0u);
    // The published picture: wrong signs on both sides of the line, not just on it.
    EXPECT_TRUE(wrong_on_both_sides(dbl));
    EXPECT_EQ(dbl.exact_counts.zero, 256u);  // p on the line y = x: the diagonal cells

    EXPECT_EQ(compute_failure_map(spec, AdaptiveKernel{}, 2).wrong, 0u);
    EXPECT_EQ(compute_failure_map(spec, GmpExactKernel{}, 2).wrong, 0u);
}

TEST(FailureMap, EveryPresetIsExactWithTheAdaptiveKernel) {
    for (FailureMapSpec spec : failure_map_presets()) {
        spec.width = spec.height = 48;
        const FailureMap m = compute_failure_map(spec, AdaptiveKernel{}, 2);
        EXPECT_EQ(m.wrong, 0u) << spec.name;
        EXPECT_EQ(m.signs.size(), 48u * 48u) << spec.name;
    }
}

TEST(FailureMap, PivotOrderIsACyclicPermutationWithTheSameExactSigns) {
    FailureMapSpec p = failure_map_preset("kettner1"), q = failure_map_preset("kettner1-pivot-q");
    p.width = p.height = q.width = q.height = 32;
    EXPECT_EQ(compute_failure_map(p, GmpExactKernel{}, 1).exact,
              compute_failure_map(q, GmpExactKernel{}, 1).exact);
}

TEST(FailureMap, RejectsBadSpecs) {
    FailureMapSpec s = failure_map_preset("kettner1");
    s.pivot = 3;
    EXPECT_THROW(validate(s), std::invalid_argument);
    s = failure_map_preset("kettner1");
    s.order = {0, 0, 1};
    EXPECT_THROW(validate(s), std::invalid_argument);
    s = failure_map_preset("kettner1");
    s.points.pop_back();
    EXPECT_THROW(validate(s), std::invalid_argument);
    EXPECT_THROW(failure_map_preset("no-such-preset"), std::invalid_argument);
    EXPECT_THROW(parse_kernel("mpfr:1"), std::invalid_argument);
    EXPECT_THROW(parse_kernel("float"), std::invalid_argument);
    EXPECT_EQ(kernel_name(parse_kernel("mpfr:64")), "mpfr:64");
}

// The maps of space: the exact signs draw the plane or sphere the points were built on,
// the double kernel errs next to it on both sides, and the moving point's axes are those
// the spec names.
TEST(FailureMap, SpaceMapsDrawTheExactPlaneAndBreakTheDoubleKernel) {
    // Exact zeros counted by hand. diagonal: d = (1/2, 1/2, 1/2) on the plane x = y, the
    // cells where the offsets of d.x and d.y are equal (one binade on each side of 1/2,
    // the same ulp for x and y): all 256 diagonal cells. tilted: d = (3/4, 3/4, 0) on
    // x + y + z = 3/2, one ulp (2^-53) over the window: offsets kx + ky = 0 with ky < 128,
    // 255 cells. tilted-move-a: a = (12, -4.5, -6), ulps 2^-49 in x and 2^-50 in y:
    // 2 kx + ky = 0 with ky in [-128, 127], 128 cells. The spheres pass through a window
    // cell only at the lattice point itself.
    const std::pair<const char*, std::uint64_t> zeros[] = {
        {"orient3d-diagonal", 256}, {"orient3d-tilted", 255}, {"orient3d-tilted-move-a", 128},
        {"insphere-s2", 1},         {"insphere-s12", 1},      {"insphere-s24", 1},
        {"insphere-s12-move-a", 1}};
    for (const auto& [name, expected_zeros] : zeros) {
        const FailureMapSpec spec = failure_map_preset(name);
        ASSERT_TRUE(spec.space) << name;
        const FailureMap dbl = compute_failure_map(spec, DoubleKernel{}, 2);
        EXPECT_EQ(dbl.exact_counts.zero, expected_zeros) << name;
        // The centre cell is the unmoved, exactly degenerate configuration.
        EXPECT_EQ(dbl.exact[128 * 256 + 128], Sign::zero) << name;
        EXPECT_GT(dbl.wrong, 0u) << name;
        EXPECT_EQ(compute_failure_map(spec, GmpExactKernel{}, 2).wrong, 0u) << name;
        EXPECT_EQ(compute_failure_map(spec, CppIntExactKernel{}, 2).wrong, 0u) << name;
    }
    // Kettner's picture in space: wrong signs on both sides of the plane, not just on it.
    EXPECT_TRUE(wrong_on_both_sides(
        compute_failure_map(failure_map_preset("orient3d-tilted"), DoubleKernel{}, 2)));
}

TEST(FailureMap, SpaceMapAxesSwapTransposesTheMap) {
    FailureMapSpec xy = failure_map_preset("orient3d-tilted");
    xy.width = xy.height = 40;
    FailureMapSpec yx = xy;
    yx.axes = {1, 0};
    const FailureMap a = compute_failure_map(xy, DoubleKernel{}, 1),
                     b = compute_failure_map(yx, DoubleKernel{}, 2);
    for (std::size_t j = 0; j < 40; ++j) {
        for (std::size_t i = 0; i < 40; ++i) {
            ASSERT_EQ(a.signs[j * 40 + i], b.signs[i * 40 + j]) << i << ", " << j;
            ASSERT_EQ(a.exact[j * 40 + i], b.exact[i * 40 + j]) << i << ", " << j;
        }
    }
    // Moving z instead of y: z = 0 steps through the subnormals (k 2^-1074), x in steps of
    // 2^-53, so x decides the side wherever it moved (every column but the middle one is
    // constant), and z only on the middle column, zero at its own offset 0 alone.
    FailureMapSpec xz = xy;
    xz.axes = {0, 2};
    const FailureMap z = compute_failure_map(xz, GmpExactKernel{}, 2);
    for (std::size_t j = 0; j < 40; ++j) {
        for (std::size_t i = 0; i < 40; ++i) {
            if (i != 20) {
                ASSERT_EQ(z.exact[j * 40 + i], z.exact[i]) << i << ", " << j;
            }
        }
    }
    EXPECT_EQ(z.exact_counts.zero, 1u);
    EXPECT_EQ(z.exact[20 * 40 + 20], Sign::zero);
    EXPECT_NE(z.exact[19 * 40 + 20], Sign::zero);
    EXPECT_EQ(z.exact[19 * 40 + 20], -z.exact[21 * 40 + 20]);
    EXPECT_EQ(z.exact[19 * 40 + 20], z.exact[19]);  // moving z down is moving x down
}

TEST(FailureMap, RejectsBadSpaceSpecs) {
    FailureMapSpec s = failure_map_preset("insphere-s2");
    s.points3.pop_back();
    EXPECT_THROW(validate(s), std::invalid_argument);
    s = failure_map_preset("insphere-s2");
    s.pivot = 5;
    EXPECT_THROW(validate(s), std::invalid_argument);
    s = failure_map_preset("orient3d-tilted");
    s.axes = {1, 1};
    EXPECT_THROW(validate(s), std::invalid_argument);
    s.axes = {0, 3};
    EXPECT_THROW(validate(s), std::invalid_argument);
    s = failure_map_preset("orient3d-tilted");
    s.points3[1].z = std::numeric_limits<double>::infinity();
    EXPECT_THROW(validate(s), std::invalid_argument);
    s = failure_map_preset("orient3d-tilted");
    s.order = {0, 1, 2, 2};
    EXPECT_THROW(validate(s), std::invalid_argument);
}

TEST(FailureMap, StudyWritesAValidPngAndAReportThatReferencesIt) {
    const fs::path out = work_dir("failure_map_png");
    FailureMapOptions o;
    o.specs = {failure_map_preset("kettner1")};
    o.kernels = {"double"};
    o.width = o.height = 64;
    const FailureMapStudy study = run_failure_map_study(o, quiet_run(out));
    write_text_file(out / "report.md", study.report.render());
    ASSERT_EQ(study.rows.size(), 1u);
    const Image img = read_png(out / study.rows[0].png);
    const FailureMapLayout layout = failure_map_layout(64, 64);
    EXPECT_EQ(img.width, layout.width);
    EXPECT_EQ(img.height, layout.height);
    EXPECT_EQ(layout.panel_width, 64 * 2);
    // The wrong cells of the double kernel are drawn in red in the third panel, and only
    // there (the legend's red square is below the panels).
    const Rgb red{215, 25, 28};
    std::size_t red_in_third = 0, red_in_first = 0;
    for (int y = layout.panel_y; y < layout.panel_y + layout.panel_height; ++y) {
        for (int x = 0; x < layout.panel_width; ++x) {
            red_in_third += img.at(layout.panel_x[2] + x, y) == red;
            red_in_first += img.at(layout.panel_x[0] + x, y) == red;
        }
    }
    EXPECT_EQ(red_in_third, study.rows[0].wrong * 4);  // 2 x 2 pixels per cell
    EXPECT_EQ(red_in_first, 0u);
    // Title, axis labels and legend are drawn: dark text pixels above, left of and below
    // the panels.
    const auto dark_pixels = [&](int x0, int y0, int x1, int y1) {
        std::size_t n = 0;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) n += img.at(x, y) == Rgb{0, 0, 0};
        }
        return n;
    };
    EXPECT_GT(dark_pixels(0, 0, img.width, layout.panel_y), 100u);  // title, captions
    EXPECT_GT(dark_pixels(0, layout.panel_y, layout.panel_x[0] - 1, img.height), 20u);  // y label
    EXPECT_GT(dark_pixels(0, layout.panel_y + layout.panel_height + 1, img.width, img.height),
              200u);
    const std::string report = read_file(out / "report.md");
    EXPECT_NE(report.find("](" + study.rows[0].png + ")"), std::string::npos);
    EXPECT_NE(report.find("failure_map.csv"), std::string::npos);
    EXPECT_TRUE(fs::exists(out / "failure_map.csv"));
    // Not a PNG: a clear error, not a crash.
    EXPECT_THROW(read_png(out / "failure_map.csv"), std::runtime_error);
}

// --- determinism -------------------------------------------------------------------

TEST(Determinism, EveryStudyWritesTheSameFilesForOneAndTwoJobs) {
    const auto run_all = [](unsigned jobs) {
        const fs::path out = work_dir("determinism_jobs" + std::to_string(jobs));
        RunOptions run = quiet_run(out, jobs);
        run.seed = 4242;
        FailureMapOptions fm;
        fm.specs = {failure_map_preset("kettner2"), failure_map_preset("cosine-s12")};
        fm.kernels = {"double", "mpfr:60"};
        fm.width = fm.height = 40;
        run.out = out / "failure-map";
        write_text_file(run.out / "report.md", run_failure_map_study(fm, run).report.render());
        PrecisionOptions pr;
        pr.families = {testing::Family::near_rounded_line, testing::Family::kettner};
        pr.bits = {40, 53, 64, 120};
        pr.samples = 600;
        run.out = out / "precision";
        write_text_file(run.out / "report.md", run_precision_study(pr, run).report.render());
        TriangulationOptions tr;
        tr.kernels = {"double", "adaptive"};
        tr.families = {testing::Family::near_lattice_circle, testing::Family::uniform_scaled};
        tr.seeds = 3;
        tr.sizes = {30, 60};
        tr.orders = parse_orders("all");  // fixture names and headers per order, and the work table
        run.out = out / "triangulation";
        write_text_file(run.out / "report.md", run_triangulation_study(tr, run).report.render());
        StagesOptions st;
        st.families = {testing::Family::near_rounded_circle, testing::Family::integer_grid};
        st.samples = 1500;
        st.seeds = 2;
        st.size = 80;
        run.out = out / "stages";
        write_text_file(run.out / "report.md", run_stages_study(st, run).report.render());
        return snapshot(out);
    };
    const auto one = run_all(1), two = run_all(2);
    ASSERT_EQ(one.size(), two.size());
    for (const auto& [name, bytes] : one) {
        ASSERT_TRUE(two.count(name)) << name;
        EXPECT_EQ(bytes, two.at(name)) << name << " differs between --jobs 1 and --jobs 2";
    }
    EXPECT_TRUE(one.count("precision/precision.svg"));
    EXPECT_TRUE(one.count("precision/precision.png"));
    EXPECT_TRUE(one.count("triangulation/triangulation_work.csv"));
    EXPECT_NE(one.at("triangulation/report.md").find("## Work per insertion order"),
              std::string::npos);
    EXPECT_NE(one.at("precision/report.md").find("](precision.svg)"), std::string::npos);
}

TEST(Determinism, AnotherSeedDrawsOtherInputs) {
    PrecisionOptions pr;
    pr.families = {testing::Family::near_rounded_line};
    pr.bits = {53};
    pr.samples = 300;
    RunOptions a = quiet_run(work_dir("seed_a")), b = quiet_run(work_dir("seed_b"));
    b.seed = a.seed + 1;
    (void)run_precision_study(pr, a);
    (void)run_precision_study(pr, b);
    EXPECT_NE(read_file(a.out / "precision_thresholds.csv"),
              read_file(b.out / "precision_thresholds.csv"));
}

// --- precision ---------------------------------------------------------------------

TEST(Precision, EnoughBitsMakeNoErrorAndDoublePrecisionDoes) {
    PrecisionOptions pr;
    pr.families = {testing::Family::kettner};
    pr.bits = {53, 512};
    pr.samples = 500;
    const PrecisionStudy s = run_precision_study(pr, quiet_run(work_dir("precision_bounds")));
    std::uint64_t wrong53 = 0;
    for (const PrecisionCell& c : s.cells) {
        // Kettner queries have b = 58 (proofs/bitcounts.md): 512 >= 8 b + 12 for every formulation.
        if (c.bits == 512) {
            EXPECT_EQ(c.wrong, 0u) << predicate_name(c.formulation);
        }
        if (c.bits == 53) wrong53 += c.wrong;
        EXPECT_EQ(c.total, 500u);
    }
    EXPECT_GT(wrong53, 0u);
}

/// The text between `open` and the next `close` after position `from` ("" if none).
std::string between(const std::string& text, const std::string& open, const std::string& close,
                    std::size_t from = 0) {
    const std::size_t a = text.find(open, from);
    if (a == std::string::npos) return "";
    const std::size_t b = text.find(close, a + open.size());
    return b == std::string::npos ? "" : text.substr(a + open.size(), b - a - open.size());
}

/// Every piece of `text` that starts with `marker`, up to the next one (or the end).
std::vector<std::string> pieces(const std::string& text, const std::string& marker) {
    std::vector<std::string> out;
    for (std::size_t a = text.find(marker); a != std::string::npos;) {
        const std::size_t b = text.find(marker, a + marker.size());
        out.push_back(text.substr(a, b == std::string::npos ? std::string::npos : b - a));
        a = b;
    }
    return out;
}

/// CRC-32 of PNG (ISO 3309, polynomial 0xEDB88320 reflected), bit by bit.
std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
}

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
}

/// Checks a PNG file's structure without libpng: the signature, every chunk's length and
/// CRC, IHDR first (returns its width and height), some IDAT, IEND last.
std::pair<std::uint32_t, std::uint32_t> check_png_chunks(const std::string& png) {
    const std::string signature = "\x89PNG\r\n\x1a\n";
    EXPECT_EQ(png.substr(0, 8), signature);
    std::vector<std::string> types;
    std::pair<std::uint32_t, std::uint32_t> size{0, 0};
    std::size_t at = 8;
    while (at + 12 <= png.size()) {
        const std::uint32_t length = big_endian(png, at);
        if (at + 12 + length > png.size()) break;
        const std::string type_and_data = png.substr(at + 4, 4 + length);
        types.push_back(type_and_data.substr(0, 4));
        EXPECT_EQ(crc32(type_and_data), big_endian(png, at + 8 + length))
            << "CRC of chunk " << types.back();
        if (types.back() == "IHDR") {
            EXPECT_EQ(length, 13u);
            size = {big_endian(type_and_data, 4), big_endian(type_and_data, 8)};
            EXPECT_EQ(type_and_data[12], 8);  // bit depth
            EXPECT_EQ(type_and_data[13], 2);  // colour type: RGB
        }
        at += 12 + length;
    }
    EXPECT_EQ(at, png.size()) << "bytes after the last whole chunk";
    EXPECT_FALSE(types.empty());
    if (types.empty()) return size;
    EXPECT_EQ(types.front(), "IHDR");
    EXPECT_EQ(types.back(), "IEND");
    EXPECT_NE(std::find(types.begin(), types.end(), "IDAT"), types.end());
    return size;
}

// The precision plot: one panel per formulation, one line per family in each (the same
// colour in every panel, one legend entry), with a point per precision; and the same plot
// as a valid PNG of twice the SVG's size, every family's colour drawn.
TEST(Precision, ThePlotHasOneLinePerFamilyAndAValidPng) {
    PrecisionOptions pr;
    pr.families = {testing::Family::near_rounded_line, testing::Family::kettner,
                   testing::Family::near_integer_grid};
    pr.bits = {24, 53, 128};
    pr.samples = 50;
    const fs::path out = work_dir("precision_plot");
    const PrecisionStudy study = run_precision_study(pr, quiet_run(out));
    const std::string svg = read_file(out / "precision.svg");
    const std::vector<std::string> panels = pieces(svg, "<g class=\"panel\">");
    ASSERT_EQ(panels.size(), std::size(all_formulations));
    std::vector<std::string> first_colours;
    for (std::size_t f = 0; f < panels.size(); ++f) {
        EXPECT_EQ(between(panels[f], "<title>", "</title>"), predicate_name(all_formulations[f]));
        std::vector<std::string> series = pieces(panels[f], "<g class=\"series\">");
        ASSERT_EQ(series.size(), pr.families.size());
        for (std::string& g : series) g = g.substr(0, g.find("</g>"));
        std::vector<std::string> colours;
        for (std::size_t k = 0; k < series.size(); ++k) {
            EXPECT_EQ(between(series[k], "<title>", "</title>"),
                      testing::family_name(pr.families[k]));
            EXPECT_EQ(pieces(series[k], "<polyline").size(), 1u);
            std::istringstream points(between(series[k], "points=\"", "\""));
            std::size_t n = 0;
            for (std::string xy; points >> xy;) ++n;
            EXPECT_EQ(n, pr.bits.size());
            EXPECT_EQ(pieces(series[k], "<circle").size(), pr.bits.size());
            colours.push_back(between(series[k], "stroke=\"", "\""));
        }
        EXPECT_EQ(std::set<std::string>(colours.begin(), colours.end()).size(), colours.size());
        if (f == 0) first_colours = colours;
        EXPECT_EQ(colours, first_colours);  // a family keeps its colour in every panel
    }
    const std::string legend = between(svg, "<g class=\"legend\">", "</g>");
    for (testing::Family fam : pr.families) {
        EXPECT_NE(legend.find(">" + std::string(testing::family_name(fam)) + "</text>"),
                  std::string::npos);
    }
    EXPECT_EQ(pieces(legend, "<text").size(), pr.families.size());

    const std::string png = read_file(out / "precision.png");
    const auto [width, height] = check_png_chunks(png);
    EXPECT_EQ(double(width), 2 * std::stod(between(svg, "width=\"", "\"")));
    EXPECT_EQ(double(height), 2 * std::stod(between(svg, "height=\"", "\"")));
    const Image image = read_png(out / "precision.png");
    ASSERT_EQ(image.width, int(width));
    ASSERT_EQ(image.height, int(height));
    for (const std::string& c : first_colours) {
        const Rgb want{std::uint8_t(std::stoi(c.substr(1, 2), nullptr, 16)),
                       std::uint8_t(std::stoi(c.substr(3, 2), nullptr, 16)),
                       std::uint8_t(std::stoi(c.substr(5, 2), nullptr, 16))};
        EXPECT_GT(std::count(image.pixels.begin(), image.pixels.end(), want), 1000) << c;
    }
    EXPECT_NE(study.report.render().find("](precision.png)"), std::string::npos);
    // The checker's CRC: the standard check value, and a flipped bit in the chunk after
    // IHDR (at byte 33: its length, then type and data) no longer matches the stored CRC.
    EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
    std::string damaged = png;
    const std::uint32_t length = big_endian(png, 33);
    damaged[41] = char(damaged[41] ^ 1);
    EXPECT_EQ(crc32(png.substr(37, 4 + length)), big_endian(png, 41 + length));
    EXPECT_NE(crc32(damaged.substr(37, 4 + length)), big_endian(damaged, 41 + length));
}

// --- triangulation -----------------------------------------------------------------

int run_cli(const std::string& args) {
#ifdef EXIDEL_CLI_PATH
    const std::string cmd = std::string(EXIDEL_CLI_PATH) + " " + args + " >/dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
#else
    (void)args;
    return -2;
#endif
}

/// The standard output of `exidel ARGS` (empty when the binary was not built).
std::string cli_output(const std::string& args) {
    std::string out;
#ifdef EXIDEL_CLI_PATH
    const std::string cmd = std::string(EXIDEL_CLI_PATH) + " " + args + " 2>/dev/null";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return out;
    char buf[256];
    while (std::fgets(buf, sizeof buf, pipe)) out += buf;
    pclose(pipe);
#else
    (void)args;
#endif
    return out;
}

/// The text after `prefix` on the first line of `text` that starts with it ("" if none).
std::string line_after(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
    }
    return "";
}

TEST(Triangulation, ShrunkFixturesReplayTheirOutcome) {
    const fs::path out = work_dir("triangulation_fixtures");
    TriangulationOptions tr;
    tr.kernels = {"double", "exact"};
    tr.families = {testing::Family::uniform_scaled, testing::Family::near_lattice_circle};
    tr.seeds = 4;
    tr.sizes = {40, 80};
    tr.shrink_per_class = 1;
    tr.orders = parse_orders("all");
    tr.algorithms = {delaunay::Algorithm::external};  // the orders are the subject
    const TriangulationStudy s = run_triangulation_study(tr, quiet_run(out));
    std::map<Strategy, std::size_t> runs_per_order;
    for (const TriangulationRun& r : s.runs) {
        ++runs_per_order[r.order];
        if (r.kernel == "exact") {
            EXPECT_EQ(r.result.outcome, Outcome::delaunay) << r.result.detail;
        }
    }
    for (Strategy o : all_orders)
        EXPECT_EQ(runs_per_order[o], 2u * 4u * 2u * 2u) << delaunay::to_string(o);
    ASSERT_FALSE(s.fixtures.empty()) << "the double kernel found nothing to shrink";
    bool saw_failure = false;
    std::map<Strategy, std::size_t> fixtures_per_order;
    for (const Fixture& f : s.fixtures) {
        ++fixtures_per_order[f.order];
        EXPECT_LE(f.size, f.original_size);
        const Classification again =
            replay_fixture(out / f.file, parse_kernel(f.kernel), f.policy, f.order);
        EXPECT_EQ(again.outcome, f.result.outcome) << f.file;
        EXPECT_EQ(again.detail, f.result.detail) << f.file;
        EXPECT_EQ(replay_fixture(out / f.file, AdaptiveKernel{}, f.policy, f.order).outcome,
                  Outcome::delaunay)
            << f.file;
        // The paper's order keeps the old names; the others say which order they need.
        const std::string order_part = "-" + std::string(delaunay::to_string(f.order)) + "-";
        EXPECT_EQ(f.file.find(order_part) != std::string::npos, f.order != Strategy::lexicographic)
            << f.file;
        const std::string text = read_file(out / f.file);
        const std::string replay = line_after(text, "# reproduce: exidel study replay -i FILE ");
        const std::string triangulate =
            line_after(text, "#       and: exidel triangulate -i FILE ");
        ASSERT_FALSE(replay.empty()) << f.file;
        ASSERT_FALSE(triangulate.empty()) << f.file;
        EXPECT_NE(triangulate.find("--order " + std::string(delaunay::to_string(f.order))),
                  std::string::npos)
            << f.file;
#ifdef EXIDEL_CLI_PATH
        // The header's own command lines reproduce the outcome.
        const std::string described = std::string(to_string(f.result.outcome)) +
                                      (f.result.detail.empty() ? "" : " (" + f.result.detail + ")");
        EXPECT_EQ(cli_output("study replay -i " + (out / f.file).string() + " " + replay),
                  described + "\n")
            << f.file << ": " << replay;
        if (f.result.outcome == Outcome::failure) {
            const std::string flags = triangulate.substr(0, triangulate.find("   ("));
            EXPECT_EQ(run_cli("triangulate -i " + (out / f.file).string() + " " + flags), 1)
                << f.file;
            EXPECT_EQ(run_cli("triangulate -i " + (out / f.file).string() + " --kernel exact"), 0)
                << f.file;
        }
#endif
        saw_failure = saw_failure || f.result.outcome == Outcome::failure;
    }
    EXPECT_TRUE(saw_failure);
    for (Strategy o : all_orders) EXPECT_GT(fixtures_per_order[o], 0u) << delaunay::to_string(o);
}

TEST(Triangulation, WorkPerOrderHasOneRowPerFamilyAndOrderAndTheAdaptiveKernelCertifiesEveryOrder) {
    const fs::path out = work_dir("triangulation_work");
    TriangulationOptions tr;
    tr.kernels = {"adaptive"};
    tr.families = {testing::Family::uniform, testing::Family::wide_exponents,
                   testing::Family::near_lattice_circle, testing::Family::duplicates};
    tr.seeds = 2;
    tr.sizes = {300};
    tr.algorithms = {delaunay::Algorithm::external};  // the orders are the subject
    const TriangulationStudy s = run_triangulation_study(tr, quiet_run(out));
    // The outcome tables keep their default order: the paper's only.
    for (const TriangulationRun& r : s.runs) EXPECT_EQ(r.order, Strategy::lexicographic);
    ASSERT_EQ(s.work.size(), tr.families.size() * all_orders.size());
    for (std::size_t i = 0; i < s.work.size(); ++i) {
        const OrderWork& w = s.work[i];
        const std::string where = std::string(testing::family_name(w.family)) + "/" +
                                  std::string(delaunay::to_string(w.order));
        EXPECT_EQ(w.family, tr.families[i / all_orders.size()]) << where;
        EXPECT_EQ(w.order, all_orders[i % all_orders.size()]) << where;
        EXPECT_EQ(w.sets, 2u) << where;
        EXPECT_EQ(w.points, 600u) << where;
        EXPECT_EQ(w.certified, w.sets) << where;
        EXPECT_EQ(w.counters.flips(), w.counters.eroded_edges + w.counters.merge_deleted_edges)
            << where;
        // Only strips merge, and only the radial sort (radial, and strips' radial strips)
        // compares distances; 300 points in 64-point strips always merge.
        if (w.order == Strategy::strips) {
            EXPECT_GT(w.merges, 0u) << where;
            EXPECT_GT(w.counters.merge_incircle_tests + w.counters.merge_orientations, 0u) << where;
        } else {
            EXPECT_EQ(w.merges, 0u) << where;
            EXPECT_EQ(w.counters.merge_incircle_tests + w.counters.merge_orientations +
                          w.counters.merge_deleted_edges + w.counters.merge_cross_edges,
                      0u)
                << where;
        }
        if (w.order == Strategy::lexicographic) {
            EXPECT_EQ(w.distance_comparisons, 0u) << where;
            EXPECT_EQ(w.counters.visible_search_orientations, 0u) << where;
        }
        EXPECT_GT(w.counters.incircle_tests, 0u) << where;
    }
    const std::string report = s.report.render();
    EXPECT_NE(report.find("## Work per insertion order"), std::string::npos);
    // triangulation_work.csv: a header, a row per family and order, and a total per order.
    const std::string csv = read_file(out / "triangulation_work.csv");
    std::istringstream lines(csv);
    std::vector<std::string> rows;
    for (std::string line; std::getline(lines, line);) rows.push_back(line);
    ASSERT_EQ(rows.size(), 1 + s.work.size() + all_orders.size());
    EXPECT_EQ(rows[0].rfind("family,order,point sets,points,flips/point", 0), 0u) << rows[0];
    for (std::size_t i = 0; i < s.work.size(); ++i) {
        const std::string prefix = std::string(testing::family_name(s.work[i].family)) + "," +
                                   std::string(delaunay::to_string(s.work[i].order)) + ",2,600,";
        EXPECT_EQ(rows[1 + i].rfind(prefix, 0), 0u) << rows[1 + i];
        EXPECT_NE(rows[1 + i].find(",2/2"), std::string::npos) << rows[1 + i];
        EXPECT_NE(report.find("| " + std::string(testing::family_name(s.work[i].family)) + " | " +
                              std::string(delaunay::to_string(s.work[i].order)) + " | 2 | 600 |"),
                  std::string::npos)
            << rows[1 + i];
    }
    for (std::size_t o = 0; o < all_orders.size(); ++o) {
        EXPECT_EQ(
            rows[1 + s.work.size() + o].rfind(
                "all families," + std::string(delaunay::to_string(all_orders[o])) + ",8,2400,", 0),
            0u)
            << rows[1 + s.work.size() + o];
    }
}

TEST(Triangulation, OrdersParseAndTheStudyRejectsAutomatic) {
    EXPECT_EQ(parse_orders("all"), std::vector<Strategy>(all_orders.begin(), all_orders.end()));
    EXPECT_EQ(parse_orders("radial,lexicographic,radial"),
              (std::vector<Strategy>{Strategy::radial, Strategy::lexicographic}));
    EXPECT_EQ(parse_orders("strips"), std::vector<Strategy>{Strategy::strips});
    EXPECT_THROW(parse_orders(""), std::invalid_argument);
    EXPECT_THROW(parse_orders("auto"), std::invalid_argument);
    EXPECT_THROW(parse_orders("automatic"), std::invalid_argument);
    EXPECT_THROW(parse_orders("radial,,strips"), std::invalid_argument);
    TriangulationOptions tr;
    tr.kernels = {"adaptive"};
    tr.families = {testing::Family::uniform};
    tr.seeds = 1;
    tr.sizes = {10};
    tr.orders = {Strategy::automatic};
    EXPECT_THROW(run_triangulation_study(tr, quiet_run(work_dir("triangulation_automatic"))),
                 std::invalid_argument);
    const delaunay::Options o = study_options(InCirclePolicy::cosine, Strategy::strips);
    EXPECT_EQ(o.incircle, InCirclePolicy::cosine);
    EXPECT_EQ(o.strategy, Strategy::strips);
    EXPECT_EQ(o.strip_points, study_strip_points);
#ifdef EXIDEL_CLI_PATH
    const std::string fixture =
        (fs::path(EXIDEL_RESEARCH_FIXTURES) / "double_overflow_no_visible_edge.xy").string();
    EXPECT_EQ(run_cli("study replay -i " + fixture + " --kernel double --order all"), 2);
    EXPECT_EQ(run_cli("study replay -i " + fixture + " --kernel double --order auto"), 2);
    EXPECT_EQ(run_cli("study triangulation --order sideways --out " +
                      work_dir("triangulation_bad_order").string()),
              2);
#endif
}

// A custom map of space from the command line: the moving point's axes, and clear usage
// errors for points of the wrong dimension and bad axes.
TEST(FailureMap, CommandLineDrawsACustomSpaceMap) {
#ifdef EXIDEL_CLI_PATH
    const fs::path out = work_dir("failure_map_space_cli");
    const std::string points = "'12,-4.5,-6;-9,20.5,-10;-7,-8,16.5;0.75,0.75,0'";
    const std::string map = "study failure-map --predicate orient3d --points " + points +
                            " --move 3 --centered --width 24 --height 24 --kernel double --out ";
    EXPECT_EQ(run_cli(map + out.string() + " --axes yx"), 0);
    const std::string report = read_file(out / "report.md");
    EXPECT_NE(report.find("--axes yx"), std::string::npos);  // the rerun line
    EXPECT_NE(report.find("custom orient3d map, point 3 moved in y and x"), std::string::npos);
    EXPECT_NE(report.find("(0.75, 0.75, 0)"), std::string::npos);
    EXPECT_EQ(run_cli(map + out.string() + " --axes xx"), 2);
    EXPECT_EQ(run_cli(map + out.string() + " --axes xw"), 2);
    EXPECT_EQ(run_cli(map + out.string() + " --move 4"), 2);
    EXPECT_EQ(run_cli("study failure-map --predicate orient3d --points '1,2;3,4;5,6;7,8' --out " +
                      out.string()),
              2);
    EXPECT_EQ(
        run_cli("study failure-map --predicate orient2d --points '1,2;3,4;5,6' --axes xz --out " +
                out.string()),
        2);
    EXPECT_EQ(run_cli("study failure-map --predicate insphere3 --points '1,2;3,4;5,6' --out " +
                      out.string()),
              2);
#else
    GTEST_SKIP() << "the exidel binary is not built";
#endif
}

// A custom map's window is centred on the moving point unless it asks for the corner:
// the centred map is the corner map of the point moved back by half the window, its
// centre cell the unmoved (exactly degenerate) configuration. The presets keep their own
// windows: Kettner's at the corner (as the paper draws them), the others centred.
TEST(FailureMap, ACustomMapIsCentredByDefaultAndTheCornerIsTheShiftedWindow) {
    FailureMapSpec centred;
    EXPECT_TRUE(centred.centered);
    centred.name = "custom";
    centred.points = {{0.5, 0.5}, {12, 12}, {24, 24}};  // exactly collinear
    centred.order = {0, 1, 2};
    centred.width = 24;
    centred.height = 15;
    FailureMapSpec corner = centred;
    corner.centered = false;
    corner.points[0] = {testing::nudge(0.5, -12), testing::nudge(0.5, -7)};
    const FailureMap a = compute_failure_map(centred, DoubleKernel{}, 2);
    const FailureMap b = compute_failure_map(corner, DoubleKernel{}, 2);
    EXPECT_EQ(a.signs, b.signs);
    EXPECT_EQ(a.exact, b.exact);
    EXPECT_EQ(a.exact[7 * 24 + 12], Sign::zero);  // the centre cell: p itself
    EXPECT_NE(a.exact[0], Sign::zero);
    // The same points with the corner window: p at cell (0, 0).
    corner.points = centred.points;
    const FailureMap c = compute_failure_map(corner, DoubleKernel{}, 2);
    EXPECT_EQ(c.exact[0], Sign::zero);
    EXPECT_NE(c.exact, a.exact);

    for (const FailureMapSpec& s : failure_map_presets())
        EXPECT_EQ(s.centered, !s.name.starts_with("kettner")) << s.name;
}

// From the command line: no flag and --centered draw the centred window, --corner the
// moving point at the corner, each picture the library's for that window, and the report's
// rerun line names the window and writes the same picture again.
TEST(FailureMap, CommandLineCentresACustomMapAndCornerKeepsTheCornerWindow) {
#ifdef EXIDEL_CLI_PATH
    const std::string map =
        "study failure-map --predicate orient2d --points '0.5,0.5;12,12;24,24' --width 24 "
        "--height 16 --kernel adaptive --no-progress --out ";
    FailureMapSpec spec;
    spec.name = "custom";
    spec.points = {{0.5, 0.5}, {12, 12}, {24, 24}};
    spec.order = {0, 1, 2};
    spec.width = 24;
    spec.height = 16;
    const auto picture = [](bool centered, FailureMapSpec s) {
        s.centered = centered;
        return render_failure_map(compute_failure_map(s, AdaptiveKernel{}, 1)).pixels;
    };
    const std::string png = "custom-adaptive.png";
    for (const auto& [flag, centered] :
         {std::pair<std::string, bool>{"", true}, {" --centered", true}, {" --corner", false}}) {
        const fs::path out = work_dir("failure_map_window" + (flag.empty() ? "" : flag.substr(3)));
        ASSERT_EQ(run_cli(map + out.string() + flag), 0) << flag;
        EXPECT_EQ(read_png(out / png).pixels, picture(centered, spec)) << flag;
        EXPECT_NE(read_png(out / png).pixels, picture(!centered, spec)) << flag;
        const std::string report = read_file(out / "report.md");
        const std::string rerun = line_after(report, std::string(rerun_prefix));
        const std::string command = rerun.substr(0, rerun.find('`'));
        EXPECT_NE(command.find(centered ? " --centered" : " --corner"), std::string::npos)
            << command;
        EXPECT_NE(report.find(centered ? "the window centred on it" : "from the window's corner"),
                  std::string::npos);
        const std::string first = read_file(out / png);
        fs::remove(out / png);
        ASSERT_EQ(run_cli(command.substr(std::string("exidel ").size())), 0) << command;
        EXPECT_EQ(read_file(out / png), first) << command;
    }
    const std::string out = work_dir("failure_map_window_errors").string();
    EXPECT_EQ(run_cli(map + out + " --centered --corner"), 2);
    EXPECT_EQ(run_cli("study failure-map --preset kettner1 --corner --out " + out), 2);
    EXPECT_EQ(run_cli("study all --corner --out " + out), 2);
    EXPECT_NE(cli_output("study --help").find("--corner"), std::string::npos);
#else
    GTEST_SKIP() << "the exidel binary is not built";
#endif
}

// The study runs the algorithms of the registry by name: "all" is every one, in registry
// order; an algorithm with insertion orders runs once per order, any other once; every
// run of the study names its algorithm.
TEST(Triangulation, AlgorithmsComeFromTheRegistry) {
    std::vector<delaunay::Algorithm> every;
    for (const delaunay::AlgorithmInfo& a : delaunay::algorithms()) every.push_back(a.id);
    EXPECT_EQ(parse_algorithms("all"), every);
    EXPECT_EQ(parse_algorithms("external,external"),
              std::vector<delaunay::Algorithm>{delaunay::Algorithm::external});
    EXPECT_THROW(parse_algorithms(""), std::invalid_argument);
    EXPECT_THROW(parse_algorithms("sideways"), std::invalid_argument);
    const std::vector<Method> methods = methods_of(every, all_orders);
    std::size_t expected = 0;
    for (const delaunay::AlgorithmInfo& a : delaunay::algorithms())
        expected += a.takes_order ? all_orders.size() : 1;
    EXPECT_EQ(methods.size(), expected);
    for (const Method& m : methods) {
        const delaunay::Options o = study_options(InCirclePolicy::determinant, m);
        EXPECT_EQ(o.algorithm, m.algorithm);
        EXPECT_EQ(o.strategy, m.order);
    }
    TriangulationOptions tr;
    tr.kernels = {"adaptive"};
    tr.families = {testing::Family::uniform};
    tr.seeds = 1;
    tr.sizes = {30};  // no algorithms given: every one of the registry
    const TriangulationStudy s =
        run_triangulation_study(tr, quiet_run(work_dir("triangulation_algorithms")));
    std::set<delaunay::Algorithm> seen;
    for (const TriangulationRun& r : s.runs) {
        seen.insert(r.algorithm);
        EXPECT_EQ(r.result.outcome, Outcome::delaunay) << delaunay::to_string(r.algorithm);
    }
    EXPECT_EQ(seen.size(), every.size());
#ifdef EXIDEL_CLI_PATH
    EXPECT_EQ(run_cli("study triangulation --algorithm sideways --out " +
                      work_dir("triangulation_bad_algorithm").string()),
              2);
#endif
}

// The failure rate against precision: one rate per algorithm and precision, over every
// point set; at 1024 bits the MPFR kernel's determinant is exact on these inputs
// (proofs/bitcounts.md: 4b + 8 bits, b = 53 + the exponent spread), so nothing is wrong.
TEST(Triangulation, FailureRateAgainstPrecisionHasOneLinePerAlgorithm) {
    TriangulationOptions tr;
    tr.kernels = {"adaptive"};
    tr.families = {testing::Family::uniform};
    tr.seeds = 2;
    tr.sizes = {30};
    tr.precision_bits = {24, 1024};
    const fs::path out = work_dir("triangulation_precision");
    const TriangulationStudy s = run_triangulation_study(tr, quiet_run(out));
    ASSERT_EQ(s.precision.size(), delaunay::algorithms().size() * 2);
    for (std::size_t i = 0; i < s.precision.size(); ++i) {
        const PrecisionRate& r = s.precision[i];
        EXPECT_EQ(r.method.algorithm, delaunay::algorithms()[i / 2].id);
        EXPECT_EQ(r.bits, i % 2 == 0 ? 24u : 1024u);
        EXPECT_EQ(r.runs, 2u);
        EXPECT_LE(r.wrong, r.runs);
        if (r.bits == 1024) {
            EXPECT_EQ(r.wrong, 0u) << delaunay::to_string(r.method.algorithm);
        }
    }
    EXPECT_TRUE(fs::exists(out / "precision.svg"));
    EXPECT_TRUE(fs::exists(out / "triangulation_precision.csv"));
#ifdef EXIDEL_CLI_PATH
    EXPECT_EQ(run_cli("study triangulation --bits 1 --out " +
                      work_dir("triangulation_bad_bits").string()),
              2);
#endif
}

TEST(Triangulation, ShrinkingKeepsTheOutcomeAndRemovesEveryRemovablePoint) {
    const fs::path file = fs::path(EXIDEL_RESEARCH_FIXTURES) / "double_overflow_no_visible_edge.xy";
    const Kernel dbl = DoubleKernel{};
    const Classification c = replay_fixture(file, dbl, InCirclePolicy::determinant);
    ASSERT_EQ(c.outcome, Outcome::failure);
    // Pad the fixture with harmless points; shrinking must find the fixture again.
    std::ifstream in(file);
    std::vector<Point2> points;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        std::string x, y;
        s >> x >> y;
        points.push_back({std::strtod(x.c_str(), nullptr), std::strtod(y.c_str(), nullptr)});
    }
    ASSERT_EQ(points.size(), 4u);
    std::vector<Point2> padded = points;
    for (int i = 0; i < 12; ++i)
        padded.insert(padded.begin() + i, Point2{0x1p600 * i, -0x1p600 * i});
    ASSERT_EQ(classify_triangulation(padded, dbl, InCirclePolicy::determinant).outcome,
              Outcome::failure);
    const std::vector<Point2> shrunk =
        shrink_failing_input(padded, dbl, InCirclePolicy::determinant, c);
    EXPECT_EQ(classify_triangulation(shrunk, dbl, InCirclePolicy::determinant).outcome,
              Outcome::failure);
    EXPECT_LE(shrunk.size(), 4u);
    for (std::size_t i = 0; i < shrunk.size(); ++i) {
        std::vector<Point2> less = shrunk;
        less.erase(less.begin() + std::ptrdiff_t(i));
        EXPECT_NE(classify_triangulation(less, dbl, InCirclePolicy::determinant).outcome,
                  Outcome::failure);
    }
}

// Named regression fixtures: minimal failing inputs the triangulation study shrank
// (seed 20250704, `exidel study triangulation --quick`).

TEST(Regression, DoubleOverflowNoVisibleEdge) {
    // Four points near 2^673: the double kernel's products overflow to infinity.
    const fs::path file = fs::path(EXIDEL_RESEARCH_FIXTURES) / "double_overflow_no_visible_edge.xy";
    const Classification c = replay_fixture(file, DoubleKernel{}, InCirclePolicy::determinant);
    EXPECT_EQ(c.outcome, Outcome::failure);
    EXPECT_EQ(c.detail, "no_visible_edge");
    EXPECT_EQ(replay_fixture(file, AdaptiveKernel{}, InCirclePolicy::determinant).outcome,
              Outcome::delaunay);
#ifdef EXIDEL_CLI_PATH
    EXPECT_EQ(run_cli("triangulate -i " + file.string() + " --kernel double --order lexicographic"),
              1);
    EXPECT_EQ(
        run_cli("triangulate -i " + file.string() + " --kernel adaptive --order lexicographic"), 0);
#endif
}

TEST(Regression, DoubleOverflowRadialOrderFailsInsideTheHull) {
    // The same four points in the radial order: the double kernel's overflowed answers
    // now contradict the radial invariant (every new point outside the current hull)
    // instead of the lexicographic one. The order option reaches the triangulation.
    const fs::path file = fs::path(EXIDEL_RESEARCH_FIXTURES) / "double_overflow_no_visible_edge.xy";
    for (Strategy order : {Strategy::radial, Strategy::strips}) {
        const Classification c =
            replay_fixture(file, DoubleKernel{}, InCirclePolicy::determinant, order);
        EXPECT_EQ(c.outcome, Outcome::failure) << delaunay::to_string(order);
        EXPECT_EQ(c.detail, "point_inside_hull") << delaunay::to_string(order);
        EXPECT_EQ(
            replay_fixture(file, AdaptiveKernel{}, InCirclePolicy::determinant, order).outcome,
            Outcome::delaunay);
    }
    EXPECT_EQ(
        replay_fixture(file, DoubleKernel{}, InCirclePolicy::determinant, Strategy::lexicographic)
            .detail,
        "no_visible_edge");
#ifdef EXIDEL_CLI_PATH
    EXPECT_EQ(cli_output("study replay -i " + file.string() + " --kernel double --order radial"),
              "failure (point_inside_hull)\n");
    EXPECT_EQ(cli_output("study replay -i " + file.string() + " --kernel double"),
              "failure (no_visible_edge)\n");
#endif
}

TEST(Regression, LongDoubleCosineKettnerNotCcw) {
    // Kettner configuration 1 with p moved, and a fourth point on the diagonal: long
    // double's wrong orientation leaves a clockwise triangle.
    const fs::path file =
        fs::path(EXIDEL_RESEARCH_FIXTURES) / "long_double_cosine_kettner_not_ccw.xy";
    const Classification c = replay_fixture(file, LongDoubleKernel{}, InCirclePolicy::cosine);
    EXPECT_EQ(c.outcome, Outcome::invalid);
    EXPECT_EQ(c.detail, "not_ccw");
    EXPECT_EQ(replay_fixture(file, GmpExactKernel{}, InCirclePolicy::cosine).outcome,
              Outcome::delaunay);
}

TEST(Regression, Mpfr106CosineNearLineNotDelaunay) {
    // 106 bits decide the degree-4 determinant here but not the cosine test's degree-8
    // comparison: the precision study's "cosine needs about 120 bits" inside a triangulation.
    const fs::path file =
        fs::path(EXIDEL_RESEARCH_FIXTURES) / "mpfr106_cosine_near_line_not_delaunay.xy";
    EXPECT_EQ(replay_fixture(file, MpfrKernel(106), InCirclePolicy::cosine).outcome,
              Outcome::not_delaunay);
    EXPECT_EQ(replay_fixture(file, MpfrKernel(106), InCirclePolicy::determinant).outcome,
              Outcome::delaunay);
    EXPECT_EQ(replay_fixture(file, MpfrKernel(120), InCirclePolicy::cosine).outcome,
              Outcome::delaunay);
}

// --- constrained -------------------------------------------------------------------

// The quick study: the exact-sign kernels certify every run (crossing cascades that do not
// settle are snap-rounded), the report names every family, and
// with the default seed the double kernel gets crossing_grid wrong or stops on it (in
// every quick run: 0 certified of 3; other families vary with the seed).
TEST(Constrained, ExactSignKernelsAreCertifiedAndDoubleBreaksOnTheCrossingGrid) {
    const RunOptions run = quiet_run(work_dir("constrained"));
    const ConstrainedStudy study = run_constrained_study({}, run);
    ASSERT_EQ(study.kernels.size(), 6u);
    ASSERT_EQ(study.families.size(), all_constrained_families.size());
    ASSERT_EQ(study.runs.size(), 6u * all_constrained_families.size() * 3);
    const auto certified = std::size_t(ConstrainedOutcome::certified);
    const auto wrong = std::size_t(ConstrainedOutcome::wrong);
    const auto failure = std::size_t(ConstrainedOutcome::failure);
    for (std::size_t k = 0; k < study.kernels.size(); ++k) {
        if (study.kernels[k] != "adaptive" && study.kernels[k] != "exact") continue;
        for (std::size_t f = 0; f < study.families.size(); ++f) {
            EXPECT_EQ(study.at(k, f)[wrong], 0u) << study.kernels[k] << " " << f;
            EXPECT_EQ(study.at(k, f)[failure], 0u) << study.kernels[k] << " " << f;
            EXPECT_EQ(study.at(k, f)[std::size_t(ConstrainedOutcome::too_many_crossings)], 0u)
                << study.kernels[k] << " " << f;
            EXPECT_GT(study.at(k, f)[certified], 0u) << study.kernels[k] << " " << f;
        }
    }
    const auto grid = std::size_t(
        std::find(study.families.begin(), study.families.end(), ConstrainedFamily::crossing_grid) -
        study.families.begin());
    const auto dbl = std::size_t(std::find(study.kernels.begin(), study.kernels.end(), "double") -
                                 study.kernels.begin());
    ASSERT_LT(dbl, study.kernels.size());
    EXPECT_GT(study.at(dbl, grid)[wrong] + study.at(dbl, grid)[failure], 0u);
    write_text_file(run.out / "report.md", study.report.render());  // as the CLI does
    const std::string report = read_file(run.out / "report.md");
    ASSERT_FALSE(report.empty()) << "no report.md";
    for (ConstrainedFamily f : all_constrained_families)
        EXPECT_NE(report.find(std::string(to_string(f))), std::string::npos) << to_string(f);
    EXPECT_TRUE(fs::exists(run.out / "constrained.csv"));
    // The inputs are a function of the seed: the same seed draws the same input.
    const ConstrainedInput a = draw_constrained_input(ConstrainedFamily::polygon_with_holes, 7, 40,
                                                      12),
                           b = draw_constrained_input(ConstrainedFamily::polygon_with_holes, 7, 40,
                                                      12);
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.segments, b.segments);
    EXPECT_EQ(a.points.size(), 40u);
    EXPECT_EQ(a.segments.size(), 12u);
}

// --- stages ------------------------------------------------------------------------

TEST(Stages, CountsEveryCallAndUniformInputStaysInTheFilter) {
    StagesOptions st;
    st.families = {testing::Family::uniform, testing::Family::near_rounded_line};
    st.samples = 1000;
    st.seeds = 1;
    st.size = 100;
    const StagesStudy s = run_stages_study(st, quiet_run(work_dir("stages")));
    bool radial_compared = false;
    for (const StagesRow& r : s.rows) {
        std::uint64_t distance_calls = 0;
        for (std::uint64_t v : r.counts[compare_distance_row]) distance_calls += v;
        // Only the radial order sorts by distance; the paper's order never does.
        if (r.context == "triangulation/determinant" || r.context == "triangulation/cosine") {
            EXPECT_EQ(distance_calls, 0u) << r.context;
        }
        if (r.context == "triangulation/radial")
            radial_compared = radial_compared || distance_calls > 0;
        if (r.context != "stream") continue;
        for (const auto& per : r.counts) {
            std::uint64_t calls = 0;
            for (std::uint64_t v : per) calls += v;
            EXPECT_EQ(calls, 1000u);
        }
        const auto filter = std::size_t(AdaptiveStage::filter);
        if (r.family == testing::Family::uniform) {
            for (const auto& per : r.counts) EXPECT_EQ(per[filter], 1000u);
        } else {
            EXPECT_LT(r.counts[0][filter], 1000u);  // near-collinear: the filter often fails
        }
    }
    EXPECT_TRUE(radial_compared);
    EXPECT_NE(s.report.render().find("| triangulation/radial | compare_distance |"),
              std::string::npos);
}

TEST(Stages, CountingKernelAgreesWithTheAdaptiveKernel) {
    const StageCountingKernel k;
    const Point2 a{0.5, 0.5}, b{12, 12}, c{24, 24}, d{0.5, 0.75};
    EXPECT_EQ(k.orient2d(a, b, c), AdaptiveKernel::orient2d(a, b, c));
    EXPECT_EQ(k.incircle(a, b, d, c), AdaptiveKernel::incircle(a, b, d, c));
    EXPECT_EQ(k.compare_distance(a, b, c), AdaptiveKernel::compare_distance(a, b, c));
    EXPECT_EQ(k.compare_distance(Point2{0, 0}, Point2{3, 4}, Point2{5, 0}), Sign::zero);
    std::uint64_t total = 0;
    for (const auto& per : k.counts) {
        for (std::uint64_t v : per) total += v;
    }
    EXPECT_EQ(total, 4u);
    std::uint64_t distance_calls = 0;
    for (std::uint64_t v : k.counts[compare_distance_row]) distance_calls += v;
    EXPECT_EQ(distance_calls, 2u);
}

// --- reproducibility --------------------------------------------------------------

/// Runs `command` through the shell in `dir`; its exit status.
int run_in(const fs::path& dir, const std::string& command) {
    const std::string cmd = "cd '" + dir.string() + "' && " + command + " >/dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The text without its lines that start with `prefix`, and how many there were.
std::pair<std::string, int> without_lines(const std::string& text, std::string_view prefix) {
    std::istringstream in(text);
    std::string kept;
    int dropped = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with(prefix)) {
            ++dropped;
        } else {
            kept += line + '\n';
        }
    }
    return {kept, dropped};
}

/// Every file of `a` and `b` is in both and the same, reports but for their one timing
/// line; counts the reports.
void expect_same_files(const std::map<std::string, std::string>& a,
                       const std::map<std::string, std::string>& b, std::size_t& reports) {
    for (const auto& [name, bytes] : b)
        EXPECT_TRUE(a.count(name)) << name << " appeared in the rerun only";
    for (const auto& [name, bytes] : a) {
        ASSERT_TRUE(b.count(name)) << name << " is missing from the rerun";
        if (fs::path(name).filename() == "report.md") {
            ++reports;
            const auto [kept_a, timing_a] = without_lines(bytes, timing_prefix);
            const auto [kept_b, timing_b] = without_lines(b.at(name), timing_prefix);
            EXPECT_EQ(timing_a, 1) << name << ": one timing line, the only one that may differ";
            EXPECT_EQ(timing_b, 1) << name;
            EXPECT_EQ(kept_a, kept_b) << name << " differs from its rerun beyond the timing line";
            EXPECT_NE(bytes.find("commit `"), std::string::npos) << name << ": no build facts";
        } else {
            EXPECT_EQ(bytes, b.at(name)) << name << " differs from its rerun";
        }
    }
}

// The promise of every report: the command on its rerun line writes the same files again.
// The quick study runs once (two threads), then its own rerun line runs verbatim from
// another folder (one thread: --jobs is not on the line, and must not matter): every file
// must match byte for byte, except each report's one timing line. And no two pictures of
// the run may show the same thing.
TEST(Reproducibility, TheReportsRerunLineWritesTheSameFilesAgain) {
#ifndef EXIDEL_CLI_PATH
    GTEST_SKIP() << "the exidel command was not built";
#else
    const fs::path first = work_dir("rerun_first"), second = work_dir("rerun_second");
    const std::string exidel = EXIDEL_CLI_PATH;
    ASSERT_EQ(run_in(first, exidel + " study all --quick --jobs 2 --no-progress --out out"), 0);
    const std::string report = read_file(first / "out" / "report.md");
    const std::string rest = line_after(report, std::string(rerun_prefix));
    const std::size_t close = rest.find('`');
    ASSERT_NE(close, std::string::npos) << "no rerun line in report.md";
    const std::string command = rest.substr(0, close);
    EXPECT_EQ(command, "exidel study all --quick --seed 20250704 --out out");
    ASSERT_TRUE(command.starts_with("exidel "));
    ASSERT_EQ(run_in(second, exidel + command.substr(6)), 0) << command;

    const auto a = snapshot(first / "out"), b = snapshot(second / "out");
    ASSERT_FALSE(a.empty());
    std::size_t reports = 0, pictures = 0;
    expect_same_files(a, b, reports);
    for (const auto& [name, bytes] : a) pictures += name.ends_with(".png");
    EXPECT_EQ(reports, 5u);
    EXPECT_GT(pictures, 1u);

    // Each study's own report names the command that writes its folder alone: the study
    // with the defaults `all` ran it with. Run for the two quick ones.
    const fs::path third = work_dir("rerun_third");
    for (const std::string study : {"failure-map", "precision", "triangulation", "stages"}) {
        const std::string line =
            line_after(read_file(first / "out" / study / "report.md"), std::string(rerun_prefix));
        const std::string own = line.substr(0, line.find('`'));
        EXPECT_EQ(own, "exidel study " + study + " --quick --seed 20250704 --out out/" + study);
        if (study != "failure-map" && study != "precision") continue;
        ASSERT_EQ(run_in(third, exidel + own.substr(6)), 0) << own;
        std::size_t one = 0;
        expect_same_files(snapshot(first / "out" / study), snapshot(third / "out" / study), one);
        EXPECT_EQ(one, 1u);
    }

    // No failure map twice: neither the same file bytes, nor (titles aside) the same panels.
    const FailureMapLayout layout = failure_map_layout(256, 256);
    std::map<std::string, std::string> by_bytes, by_panels;
    for (const auto& [name, bytes] : a) {
        if (!name.ends_with(".png") || !name.starts_with("failure-map/")) continue;
        const auto [it, fresh] = by_bytes.emplace(bytes, name);
        EXPECT_TRUE(fresh) << name << " and " << it->second << " are byte-identical";
        const Image img = read_png(first / "out" / name);
        ASSERT_EQ(img.width, layout.width) << name;
        ASSERT_EQ(img.height, layout.height) << name;
        std::string panels;
        for (int p = 0; p < 3; ++p) {
            for (int y = layout.panel_y; y < layout.panel_y + layout.panel_height; ++y) {
                for (int x = layout.panel_x[p]; x < layout.panel_x[p] + layout.panel_width; ++x) {
                    const Rgb c = img.at(x, y);
                    panels += {char(c.r), char(c.g), char(c.b)};
                }
            }
        }
        const auto [same, new_panels] = by_panels.emplace(panels, name);
        EXPECT_TRUE(new_panels) << name << " shows the same map as " << same->second;
    }
#endif
}

TEST(Reproducibility, StudyAllRefusesTheOptionsOfOneStudy) {
#ifndef EXIDEL_CLI_PATH
    GTEST_SKIP() << "the exidel command was not built";
#else
    // They would be ignored, and the rerun line would not show them.
    const fs::path out = work_dir("all_refuses");
    EXPECT_EQ(run_cli("study all --quick --kernel double --out " + out.string()), 2);
    EXPECT_EQ(run_cli("study all --samples 10 --out " + out.string()), 2);
    EXPECT_FALSE(fs::exists(out / "report.md"));
#endif
}

TEST(Reproducibility, OneStudysRerunLineHasEveryOptionThatChangesAResult) {
#ifndef EXIDEL_CLI_PATH
    GTEST_SKIP() << "the exidel command was not built";
#else
    const fs::path dir = work_dir("rerun_one");
    ASSERT_EQ(
        run_in(dir, std::string(EXIDEL_CLI_PATH) +
                        " study failure-map --predicate orient2d --points '0.5,0.5;12,12;24,24'"
                        " --width 16 --height 8 --kernel double --jobs 2 --out 'my maps'"),
        0);
    const std::string report = read_file(dir / "my maps" / "report.md");
    EXPECT_EQ(line_after(report, std::string(rerun_prefix))
                  .substr(0, line_after(report, std::string(rerun_prefix)).find('`')),
              "exidel study failure-map --seed 20250704 --kernel double --predicate orient2d "
              "--points '0.5,0.5;12,12;24,24' --centered --width 16 --height 8 --out 'my maps'");
    EXPECT_EQ(without_lines(report, timing_prefix).second, 1);
#endif
}

// --- build facts -------------------------------------------------------------------

TEST(BuildInfo, SaysWhichExidelCompilerAndLibrariesBuiltIt) {
    const BuildInfo& b = build_info();
    EXPECT_EQ(b.version, EXIDEL_TEST_VERSION);
    EXPECT_NE(b.compiler.find(EXIDEL_TEST_COMPILER_VERSION), std::string_view::npos) << b.compiler;
    // The library's own options are part of its flags, not only the global ones.
    EXPECT_NE(b.cxx_flags.find("-ffp-contract=off"), std::string_view::npos) << b.cxx_flags;
    EXPECT_EQ(b.cxx_flags.find("  "), std::string_view::npos) << b.cxx_flags;
    EXPECT_FALSE(b.gmp.empty());
    EXPECT_FALSE(b.mpfr.empty());
    EXPECT_NE(b.boost.find('.'), std::string_view::npos) << b.boost;
    // Every kernel of the registry, each spelled as the command line accepts it.
    ASSERT_FALSE(b.kernels.empty());
    for (std::string_view k : b.kernels) {
        const std::string name = k == "mpfr:<bits>" ? "mpfr:64" : std::string(k);
        EXPECT_NO_THROW((void)parse_kernel(name)) << k;
    }
    if (std::numeric_limits<long double>::digits == 64) {
        EXPECT_TRUE(b.long_double.starts_with("x87 80-bit")) << b.long_double;
    }
    EXPECT_FALSE(cpu_model().empty());
}

// The commit is refreshed at every build: when the sources are a git checkout, it is
// the checkout's HEAD (as of the last build, which ctest runs after).
TEST(BuildInfo, TheCommitIsTheCheckoutsHead) {
    const std::string commit(build_info().commit);
    const std::string source = EXIDEL_TEST_SOURCE_DIR;
    const std::string head = [&] {
        std::string out;
        FILE* pipe = popen(("git -C '" + source + "' rev-parse HEAD 2>/dev/null").c_str(), "r");
        if (!pipe) return out;
        char buf[128];
        while (std::fgets(buf, sizeof buf, pipe)) out += buf;
        pclose(pipe);
        return out;
    }();
    if (!fs::exists(fs::path(source) / ".git") || head.empty()) {
        EXPECT_EQ(commit, "unknown");
        return;
    }
    // describe prints "<tag>-<n>-g<hash>" after a tag, else the abbreviated hash.
    std::string hash = commit;
    if (hash.ends_with("-dirty")) hash.resize(hash.size() - 6);
    if (const std::size_t g = hash.rfind("-g"); g != std::string::npos) hash = hash.substr(g + 2);
    EXPECT_GE(hash.size(), 12u) << commit;
    EXPECT_TRUE(head.starts_with(hash))
        << "build_info().commit " << commit << ", HEAD " << head << " (rebuild after committing)";
}

}  // namespace
}  // namespace exidel::research
