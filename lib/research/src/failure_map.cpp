// exidel::research: failure maps (Kettner, Mehlhorn, Pion, Schirra, Yap, CGTA 2008).
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "exidel/research/studies.hpp"
#include "exidel/testing/generators.hpp"
#include "exidel/testing/ulp.hpp"

namespace exidel::research {

namespace {

// Four exactly cocircular points: a lattice circle of radius 5 (3-4-5 triangles) around
// (2, 2), scaled by 2^-s. a, b, c counter-clockwise; c and d strictly on opposite sides of
// ab (the cosine test's precondition), ab a chord that is not a diameter. Every
// coordinate is a dyadic rational near 2, so ulp steps are 2^-51 or 2^-52 and the window
// never touches zero or the subnormals.
std::vector<Point2> lattice_circle(int s) {
    const double r = testing::dyadic(1, -s);
    const auto at = [&](int x, int y) { return Point2{2 + x * r, 2 + y * r}; };  // exact
    return {at(-5, 0), at(4, 3), at(-3, 4), at(3, -4)};
}

FailureMapSpec kettner(int index, std::vector<std::size_t> order, std::string name) {
    const auto& c = testing::kettner_configurations[static_cast<std::size_t>(index)];
    FailureMapSpec s;
    s.name = std::move(name);
    s.formulation = Formulation::orient2d;
    s.points = {c[0], c[1], c[2]};
    s.pivot = 0;
    s.centered = false;  // the paper's window: p at its corner
    const char* letters = "pqr";
    std::string args;
    for (std::size_t i : order) args += letters[i];
    s.order = std::move(order);
    s.description = "Kettner et al. configuration " + std::to_string(index + 1) +
                    ": p moved over [0, 256)^2 ulp steps, orient2d(" + args[0] + ", " + args[1] +
                    ", " + args[2] + ") (the formula subtracts its first argument, " + args[0] +
                    ")";
    return s;
}

FailureMapSpec circle(Formulation f, int s, std::size_t pivot, std::string name) {
    FailureMapSpec spec;
    spec.name = std::move(name);
    spec.formulation = f;
    spec.points = lattice_circle(s);
    spec.pivot = pivot;
    spec.order = {0, 1, 2, 3};
    spec.centered = true;
    const char* letters = "abcd";
    spec.description = std::string(predicate_name(f)) +
                       "(a, b, c, d) for four exactly cocircular points " + "(radius 5 * 2^-" +
                       std::to_string(s) + " around (2, 2)); " + letters[pivot] +
                       " moved over [-128, 128)^2 ulp steps" +
                       (f == Formulation::incircle ? "; the formula subtracts d"
                                                   : "; the formula subtracts c and d");
    return spec;
}

// Four exactly coplanar points, the last one moved. "diagonal": the plane x = y, which holds
// Kettner's first line (1/2, 1/2), (12, 12), (24, 24) lifted to heights 1/2, 1 and 3, with
// a third point (1, 1, 12) off that line; the moving point (1/2, 1/2, 1/2) stays on the
// plane where its x and y are equal, the diagonal of the map. "tilted": the plane
// x + y + z = 3/2, through points of magnitude 4..24; the moving point (3/4, 3/4, 0) stays
// in one binade over the window, so the plane is the anti-diagonal. Every coordinate is a
// dyadic rational and the sums are exact, so the points are exactly coplanar; the
// differences the formula takes with the moving point round as soon as it moves (the
// others are 2^4..2^5 times larger).
std::vector<Point3> coplanar(bool tilted) {
    if (tilted) return {{12, -4.5, -6}, {-9, 20.5, -10}, {-7, -8, 16.5}, {0.75, 0.75, 0}};
    return {{12, 12, 1}, {24, 24, 3}, {1, 1, 12}, {0.5, 0.5, 0.5}};
}

// Five exactly cospherical points: points of norm 3 on the integer lattice, (3, 0, 0),
// (0, 3, 0), (0, 0, 3), (-1, -2, -2), (-2, 2, -1), around (2, 2, 2) and scaled by 2^-s (exact
// for the s used). orient3d(a, b, c, d) = det((4,2,2), (1,5,2), (1,2,5)) * 2^-3s > 0, so
// insphere is positive inside.
std::vector<Point3> lattice_sphere(int s) {
    const double r = testing::dyadic(1, -s);
    const auto at = [&](int x, int y, int z) { return Point3{2 + x * r, 2 + y * r, 2 + z * r}; };
    return {at(3, 0, 0), at(0, 3, 0), at(0, 0, 3), at(-1, -2, -2), at(-2, 2, -1)};
}

FailureMapSpec space_map(SpacePredicate p, std::vector<Point3> points, std::size_t pivot,
                         std::string name, std::string what) {
    FailureMapSpec spec;
    spec.name = std::move(name);
    spec.space = p;
    spec.points3 = std::move(points);
    spec.pivot = pivot;
    spec.order.resize(spec.points3.size());
    std::iota(spec.order.begin(), spec.order.end(), std::size_t{0});
    spec.centered = true;
    const std::string letters = "abcde";
    std::string args;
    for (std::size_t i = 0; i < spec.points3.size(); ++i)
        args += (i ? ", " : "") + letters.substr(i, 1);
    spec.description = std::string(predicate_name(p)) + "(" + args + ") for " + what + "; " +
                       letters[pivot] +
                       " moved in x and y over [-128, 128)^2 ulp steps; the formula subtracts " +
                       letters[spec.points3.size() - 1];
    return spec;
}

double& coordinate(Point3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

const Rgb colour_positive{66, 120, 200}, colour_zero{255, 255, 255}, colour_negative{245, 190, 60},
    colour_wrong{215, 25, 28};

Rgb colour(Sign s) {
    return s == Sign::positive ? colour_positive : s == Sign::zero ? colour_zero : colour_negative;
}

Rgb faded(Rgb c) {
    return {static_cast<std::uint8_t>((c.r + 3 * 255) / 4),
            static_cast<std::uint8_t>((c.g + 3 * 255) / 4),
            static_cast<std::uint8_t>((c.b + 3 * 255) / 4)};
}

std::string counts_text(const SignCounts& c) {
    return std::to_string(c.negative) + " / " + std::to_string(c.zero) + " / " +
           std::to_string(c.positive);
}

}  // namespace

std::vector<FailureMapSpec> failure_map_presets() {
    std::vector<FailureMapSpec> v{
        kettner(0, {0, 1, 2}, "kettner1"),         kettner(1, {0, 1, 2}, "kettner2"),
        kettner(2, {0, 1, 2}, "kettner3"),         kettner(0, {1, 2, 0}, "kettner1-pivot-q"),
        kettner(0, {2, 0, 1}, "kettner1-pivot-r"),
    };
    for (int s : {2, 12, 24}) {
        v.push_back(circle(Formulation::incircle, s, 3, "incircle-s" + std::to_string(s)));
    }
    v.push_back(circle(Formulation::incircle, 12, 0, "incircle-s12-move-a"));
    for (int s : {2, 12, 24}) {
        v.push_back(circle(Formulation::incircle_cosine, s, 3, "cosine-s" + std::to_string(s)));
    }
    const std::string
        diagonal = "four exactly coplanar points on the plane x = y (Kettner's first line lifted)",
        tilted = "four exactly coplanar points on the plane x + y + z = 3/2";
    v.push_back(
        space_map(SpacePredicate::orient3d, coplanar(false), 3, "orient3d-diagonal", diagonal));
    v.push_back(space_map(SpacePredicate::orient3d, coplanar(true), 3, "orient3d-tilted", tilted));
    v.push_back(
        space_map(SpacePredicate::orient3d, coplanar(true), 0, "orient3d-tilted-move-a", tilted));
    for (int s : {2, 12, 24}) {
        v.push_back(space_map(SpacePredicate::insphere, lattice_sphere(s), 4,
                              "insphere-s" + std::to_string(s),
                              "five exactly cospherical points (radius 3 * 2^-" +
                                  std::to_string(s) + " around (2, 2, 2))"));
    }
    v.push_back(space_map(SpacePredicate::insphere, lattice_sphere(12), 0, "insphere-s12-move-a",
                          "five exactly cospherical points (radius 3 * 2^-12 around (2, 2, 2))"));
    return v;
}

FailureMapSpec failure_map_preset(std::string_view name) {
    std::string names;
    for (FailureMapSpec& s : failure_map_presets()) {
        if (s.name == name) return s;
        names += (names.empty() ? "" : ", ") + s.name;
    }
    throw std::invalid_argument("unknown failure-map preset '" + std::string(name) +
                                "' (presets: " + names + ")");
}

void validate(const FailureMapSpec& s) {
    const std::size_t n = s.arity();
    const std::size_t given = s.space ? s.points3.size() : s.points.size();
    if (given != n) {
        throw std::invalid_argument(std::string(s.predicate()) + " needs " + std::to_string(n) +
                                    " points, got " + std::to_string(given));
    }
    for (const Point2& p : s.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw std::invalid_argument("failure map points must be finite");
    }
    for (const Point3& p : s.points3) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw std::invalid_argument("failure map points must be finite");
        }
    }
    if (s.space && (s.axes[0] < 0 || s.axes[0] > 2 || s.axes[1] < 0 || s.axes[1] > 2 ||
                    s.axes[0] == s.axes[1])) {
        throw std::invalid_argument(
            "the moving point's axes must be two different ones of x, y, z");
    }
    if (s.pivot >= n)
        throw std::invalid_argument("the moving point index must be below " + std::to_string(n));
    std::vector<std::size_t> sorted = s.order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> identity(n);
    std::iota(identity.begin(), identity.end(), std::size_t{0});
    if (sorted != identity) {
        throw std::invalid_argument("the argument order must be a permutation of the " +
                                    std::to_string(n) + " points");
    }
    if (s.width < 1 || s.height < 1 || s.width > 4096 || s.height > 4096) {
        throw std::invalid_argument("failure map width and height must be in [1, 4096]");
    }
    if (s.step < 1 || s.step > (std::int64_t{1} << 40)) {
        throw std::invalid_argument("failure map step must be in [1, 2^40] ulps");
    }
}

FailureMap compute_failure_map(const FailureMapSpec& spec, const Kernel& kernel, unsigned jobs,
                               Progress* progress) {
    validate(spec);
    FailureMap m;
    m.spec = spec;
    m.kernel = kernel_name(kernel);
    const std::size_t W = static_cast<std::size_t>(spec.width),
                      H = static_cast<std::size_t>(spec.height);
    // Coordinates of the moving point per column and per row, computed once (nudge walks
    // one ulp at a time). A plane map moves x and y; a space map its two axes.
    Point3 moved3 = spec.space ? spec.points3[spec.pivot] : Point3{};
    const double base_x = spec.space ? coordinate(moved3, spec.axes[0]) : spec.points[spec.pivot].x;
    const double base_y = spec.space ? coordinate(moved3, spec.axes[1]) : spec.points[spec.pivot].y;
    const auto offset = [&](std::size_t i, std::size_t size) {
        const auto k = static_cast<std::int64_t>(i) -
                       (spec.centered ? static_cast<std::int64_t>(size / 2) : 0);
        return k * spec.step;
    };
    std::vector<double> xs(W), ys(H);
    for (std::size_t i = 0; i < W; ++i) xs[i] = testing::nudge(base_x, offset(i, W));
    for (std::size_t j = 0; j < H; ++j) ys[j] = testing::nudge(base_y, offset(j, H));

    m.signs.resize(W * H);
    m.exact.resize(W * H);
    const std::size_t n = spec.arity();
    for_each_chunk(H, jobs, progress, [&](std::size_t j) {
        if (spec.space) {
            std::vector<Point3> pts = spec.points3;
            std::array<Point3, 5> args{};
            for (std::size_t i = 0; i < W; ++i) {
                coordinate(pts[spec.pivot], spec.axes[0]) = xs[i];
                coordinate(pts[spec.pivot], spec.axes[1]) = ys[j];
                for (std::size_t a = 0; a < n; ++a) args[a] = pts[spec.order[a]];
                const std::span<const Point3> q(args.data(), n);
                m.signs[j * W + i] =
                    std::visit([&](const auto& k) { return evaluate(k, *spec.space, q); }, kernel);
                m.exact[j * W + i] = evaluate(GmpExactKernel{}, *spec.space, q);
            }
            return;
        }
        std::vector<Point2> pts = spec.points;
        std::array<Point2, 4> args{};
        for (std::size_t i = 0; i < W; ++i) {
            pts[spec.pivot] = {xs[i], ys[j]};
            for (std::size_t a = 0; a < n; ++a) args[a] = pts[spec.order[a]];
            const std::span<const Point2> q(args.data(), n);
            m.signs[j * W + i] =
                std::visit([&](const auto& k) { return evaluate(k, spec.formulation, q); }, kernel);
            m.exact[j * W + i] = evaluate(GmpExactKernel{}, spec.formulation, q);
        }
    });
    for (std::size_t c = 0; c < W * H; ++c) {
        m.counts.add(m.signs[c]);
        m.exact_counts.add(m.exact[c]);
        m.wrong += m.signs[c] != m.exact[c];
    }
    return m;
}

FailureMapLayout failure_map_layout(int width, int height) {
    FailureMapLayout l;
    l.cell = width <= 256 && height <= 256 ? 2 : 1;
    l.panel_width = width * l.cell;
    l.panel_height = height * l.cell;
    constexpr int left = 96, gap = 24, right = 16, top = 62, below = 92;
    l.panel_y = top;
    for (int p = 0; p < 3; ++p) l.panel_x[p] = left + p * (l.panel_width + gap);
    l.width = l.panel_x[2] + l.panel_width + right;
    l.height = top + l.panel_height + below;
    return l;
}

Image render_failure_map(const FailureMap& m) {
    const int W = m.spec.width, H = m.spec.height;
    const FailureMapLayout l = failure_map_layout(W, H);
    const int scale = l.cell;
    const Rgb ink{0, 0, 0}, grey{90, 90, 90}, white{255, 255, 255};
    Image img(l.width, l.height, white);
    // Text at twice the font size where it fits, else at the font size.
    const auto fitting = [](std::string_view text, int room) {
        return text_width(text, 2) <= room ? 2 : 1;
    };
    const int line = glyph_height * 2;

    // Title: what is evaluated, which point moves, and the kernel's score.
    const bool kettner_letters = !m.spec.space && m.spec.formulation == Formulation::orient2d;
    const std::string letters = kettner_letters ? "pqr" : "abcde";
    const char moved = letters[m.spec.pivot];
    std::string args;
    for (std::size_t a = 0; a < m.spec.order.size(); ++a) {
        args += (a ? ", " : "") + std::string(1, letters[m.spec.order[a]]);
    }
    const std::string title = m.spec.name + ": " + std::string(m.spec.predicate()) + "(" + args +
                              ") as " + std::string(1, moved) + " moves, kernel " + m.kernel +
                              ": " + std::to_string(m.wrong) + " of " +
                              std::to_string(m.signs.size()) + " signs wrong";
    draw_text(img, 8, 8, title, ink, fitting(title, l.width - 16));

    // Panels, with a caption each and a frame.
    const std::string captions[3] = {"signs of " + m.kernel, "exact signs (GMP)",
                                     "errors of " + m.kernel + " (red)"};
    for (int p = 0; p < 3; ++p) {
        const int ts = fitting(captions[p], l.panel_width);
        draw_text(img, l.panel_x[p], l.panel_y - 8 - glyph_height * ts, captions[p], ink, ts);
        fill_rect(img, l.panel_x[p] - 1, l.panel_y - 1, l.panel_width + 2, l.panel_height + 2,
                  grey);
    }
    for (int j = 0; j < H; ++j) {
        for (int i = 0; i < W; ++i) {
            const std::size_t c = std::size_t(j) * std::size_t(W) + std::size_t(i);
            const Sign got = m.signs[c], want = m.exact[c];
            const Rgb panels[3] = {colour(got), colour(want),
                                   got == want ? faded(colour(want)) : colour_wrong};
            for (int p = 0; p < 3; ++p) {
                // y grows upward.
                fill_rect(img, l.panel_x[p] + i * scale, l.panel_y + (H - 1 - j) * scale, scale,
                          scale, panels[p]);
            }
        }
    }

    // Axes: the offsets of the moving point, in ulps, at the first and last cell (and 0
    // when the window is centred), under every panel and left of the first.
    const auto offset = [&](int k, int size) {
        return std::int64_t(k - (m.spec.centered ? size / 2 : 0)) * m.spec.step;
    };
    const int ts = 2;
    const int tick_y = l.panel_y + l.panel_height + 4;
    for (int p = 0; p < 3; ++p) {
        const std::string lo = std::to_string(offset(0, W)), hi = std::to_string(offset(W - 1, W));
        draw_text(img, l.panel_x[p], tick_y, lo, grey, ts);
        draw_text(img, l.panel_x[p] + l.panel_width - text_width(hi, ts), tick_y, hi, grey, ts);
        if (m.spec.centered) {
            const int x0 = l.panel_x[p] + (W / 2) * scale;
            draw_text(img, x0 - text_width("0", ts) / 2, tick_y, "0", grey, ts);
        }
    }
    const std::string unit =
        m.spec.step == 1 ? "ulps" : "ulps, steps of " + std::to_string(m.spec.step);
    // The coordinates that move: x and y, or a space map's two axes.
    const char x_axis = m.spec.space ? "xyz"[m.spec.axes[0]] : 'x',
               y_axis = m.spec.space ? "xyz"[m.spec.axes[1]] : 'y';
    const std::string x_label =
        "x: offset of " + std::string(1, moved) + "." + x_axis + " (" + unit + ")";
    draw_text(
        img,
        l.panel_x[0] + (l.panel_x[2] + l.panel_width - l.panel_x[0] - text_width(x_label, ts)) / 2,
        tick_y + line + 4, x_label, ink, ts);
    const std::string y_lo = std::to_string(offset(0, H)), y_hi = std::to_string(offset(H - 1, H));
    draw_text(img, l.panel_x[0] - 6 - text_width(y_hi, ts), l.panel_y, y_hi, grey, ts);
    draw_text(img, l.panel_x[0] - 6 - text_width(y_lo, ts), l.panel_y + l.panel_height - line, y_lo,
              grey, ts);
    if (m.spec.centered) {
        draw_text(img, l.panel_x[0] - 6 - text_width("0", ts),
                  l.panel_y + (H - 1 - H / 2) * scale - line / 2, "0", grey, ts);
    }
    const std::string y_label =
        "y: offset of " + std::string(1, moved) + "." + y_axis + " (" + unit + ")";
    draw_text_vertical(
        img, 8,
        l.panel_y + (l.panel_height + text_width(y_label, fitting(y_label, l.panel_height))) / 2,
        y_label, ink, fitting(y_label, l.panel_height));

    // Legend: what each colour means.
    struct Entry {
        Rgb colour;
        std::string text;
    };
    const Entry legend[] = {{colour_positive, "positive"},
                            {colour_zero, "zero"},
                            {colour_negative, "negative"},
                            {colour_wrong, "wrong sign"},
                            {faded(colour_positive), "right sign (faded exact)"}};
    int x = l.panel_x[0];
    const int legend_y = tick_y + 2 * line + 12;
    for (const Entry& e : legend) {
        const int room = l.width - x;
        const int es = text_width(e.text, 2) + 2 * line <= room ? 2 : 1;
        fill_rect(img, x - 1, legend_y - 1, glyph_height * es + 2, glyph_height * es + 2, grey);
        fill_rect(img, x, legend_y, glyph_height * es, glyph_height * es, e.colour);
        x += glyph_height * es + 6;
        draw_text(img, x, legend_y, e.text, ink, es);
        x += text_width(e.text, es) + 18;
    }
    return img;
}

FailureMapStudy run_failure_map_study(const FailureMapOptions& options, const RunOptions& run) {
    std::vector<FailureMapSpec> specs = options.specs;
    if (specs.empty()) {
        if (run.quick) {
            // The circle pair at s = 2, not 12: at s = 12 the double kernel gets the very
            // same cells wrong with both formulas (byte-identical maps, checked when this
            // list was chosen), so that pair showed nothing; at s = 2 they differ.
            for (const char* name : {"kettner1", "kettner2", "kettner3", "incircle-s2", "cosine-s2",
                                     "orient3d-tilted", "insphere-s2"}) {
                specs.push_back(failure_map_preset(name));
            }
        } else {
            specs = failure_map_presets();
        }
    }
    std::vector<std::string> kernel_names = options.kernels;
    if (kernel_names.empty()) {
        kernel_names = run.quick ? std::vector<std::string>{"double", "adaptive", "exact"}
                                 : std::vector<std::string>{"double", "long-double", "mpfr:106",
                                                            "adaptive", "exact"};
    }
    std::vector<Kernel> kernels;
    for (const std::string& k : kernel_names) kernels.push_back(parse_kernel(k));
    for (FailureMapSpec& s : specs) {
        if (options.width) s.width = *options.width;
        if (options.height) s.height = *options.height;
        validate(s);
    }

    FailureMapStudy study;
    study.table.header = {"preset", "kernel",           "predicate",
                          "cells",  "neg / zero / pos", "exact neg / zero / pos",
                          "wrong",  "wrong rate"};
    std::size_t rows_total = 0;
    for (const FailureMapSpec& s : specs) rows_total += std::size_t(s.height) * kernels.size();
    Progress progress("failure-map", rows_total, run.progress);

    Report pictures("");  // per preset: description and one picture per kernel
    for (const FailureMapSpec& spec : specs) {
        pictures.heading(spec.name);
        std::ostringstream pts;
        pts.precision(17);
        for (std::size_t i = 0; i < spec.points.size(); ++i) {
            pts << (i ? ", " : "") << '(' << spec.points[i].x << ", " << spec.points[i].y << ')';
        }
        for (std::size_t i = 0; i < spec.points3.size(); ++i) {
            const Point3& q = spec.points3[i];
            pts << (i ? ", " : "") << '(' << q.x << ", " << q.y << ", " << q.z << ')';
        }
        pictures.paragraph(spec.description + ". Points: " + pts.str() + ".");
        // One picture per distinct thing to see. A kernel with no wrong cell would draw the
        // exact map three times over, which is already the middle panel of every other
        // picture of the preset; a kernel whose signs equal a drawn kernel's would repeat
        // that picture. Such rows point to the picture that shows their map. (With no kernel
        // wrong anywhere in the preset, the first one is drawn, so the map is shown once.)
        std::vector<FailureMap> maps;
        for (const Kernel& kernel : kernels)
            maps.push_back(compute_failure_map(spec, kernel, run.jobs, &progress));
        const bool any_wrong =
            std::any_of(maps.begin(), maps.end(), [](const FailureMap& m) { return m.wrong > 0; });
        constexpr std::size_t none = std::size_t(-1);
        std::vector<std::string> png(maps.size());
        std::vector<std::size_t> shown_by(maps.size(),
                                          none);  // index of the kernel whose picture shows it
        for (std::size_t k = 0; k < maps.size(); ++k) {
            if (maps[k].wrong == 0 && any_wrong) continue;
            for (std::size_t d = 0; d < k && shown_by[k] == none; ++d) {
                if (shown_by[d] == d && maps[d].signs == maps[k].signs) shown_by[k] = d;
            }
            if (shown_by[k] != none) continue;
            shown_by[k] = k;
            png[k] = spec.name + "-" + kernel_file_name(kernels[k]) + ".png";
            write_png(run.out / png[k], render_failure_map(maps[k]));
        }
        // Kernels without errors, in a preset where some kernel errs: the first picture's
        // middle panel is their map.
        const auto first = std::size_t(
            std::find_if(png.begin(), png.end(), [](const std::string& f) { return !f.empty(); }) -
            png.begin());
        for (std::size_t& by : shown_by) by = by == none ? first : by;
        for (std::size_t k = 0; k < maps.size(); ++k) {
            const FailureMap& m = maps[k];
            FailureMapRow row;
            row.preset = spec.name;
            row.kernel = m.kernel;
            row.counts = m.counts;
            row.exact_counts = m.exact_counts;
            row.wrong = m.wrong;
            row.cells = m.signs.size();
            row.png = png[shown_by[k]];
            if (shown_by[k] == k) {
                pictures.image(
                    spec.name + ", " + m.kernel + ": " + std::to_string(m.wrong) + " wrong",
                    row.png);
            } else if (maps[shown_by[k]].signs == m.signs) {
                pictures.paragraph(m.kernel + ": every sign the same as " +
                                   maps[shown_by[k]].kernel + " (" + std::to_string(m.wrong) +
                                   " wrong), so the same picture: " + row.png + ".");
            } else {
                pictures.paragraph(
                    m.kernel + ": no wrong sign; its map is the exact one, the middle panel of " +
                    row.png + ".");
            }
            study.table.rows.push_back({spec.name, m.kernel, std::string(spec.predicate()),
                                        std::to_string(row.cells), counts_text(m.counts),
                                        counts_text(m.exact_counts), std::to_string(m.wrong),
                                        format_rate(m.wrong, row.cells)});
            study.rows.push_back(std::move(row));
        }
    }
    study.report = Report("Failure maps");
    study.report.paragraph(
        "Each map evaluates one predicate while one input point moves over a grid of ulp "
        "steps (Kettner, Mehlhorn, Pion, Schirra, Yap, CGTA 2008). Each picture has three "
        "panels: the kernel's signs, the exact signs (GMP), and the exact signs faded with "
        "every cell the kernel got wrong in **red**. Blue: positive, amber: negative, white: "
        "zero; x grows to the right, y upward; each picture has its title, axis offsets in "
        "ulps and this legend drawn in. A kernel without a wrong cell is not drawn (its map is "
        "the exact one, the middle panel of the other pictures), nor one whose signs are all "
        "those of a kernel already drawn for the same preset. Failure maps use no randomness "
        "(seed " +
        std::to_string(run.seed) + " is recorded for uniformity).");
    if (run.quick && options.specs.empty()) {
        study.report.paragraph(
            "The quick preset draws the two in-circle formulations on the circle scaled by 2^-2: "
            "on the circle scaled by 2^-12 (presets incircle-s12 and cosine-s12) the double kernel "
            "gets the very same cells wrong with both, so the pair would show one picture twice.");
    }
    study.report.paragraph(
        "Counts per sign (negative / zero / positive) for the kernel and for the exact "
        "reference; `wrong` cells have a sign different from the exact one.");
    study.report.table(study.table);
    study.report.link("failure_map.csv", "failure_map.csv");
    study.report.append(pictures);
    write_text_file(run.out / "failure_map.csv", study.table.csv());
    return study;
}

}  // namespace exidel::research
