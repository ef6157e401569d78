// exidel::research: PNG via libpng's simplified API (no setjmp in our code), and the
// line plot as SVG and as an image.
#include "exidel/research/graphics.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace exidel::research {

void write_png(const std::filesystem::path& file, const Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height)) {
        throw std::invalid_argument("write_png: image size does not match its pixels");
    }
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGB;
    static_assert(sizeof(Rgb) == 3, "Rgb must be three packed bytes for libpng");
    const int ok = png_image_write_to_file(&png, file.c_str(), 0, image.pixels.data(), 0, nullptr);
    const std::string message = png.message;
    png_image_free(&png);
    if (!ok) throw std::runtime_error("cannot write PNG " + file.string() + ": " + message);
}

Image read_png(const std::filesystem::path& file) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, file.c_str())) {
        const std::string message = png.message;
        png_image_free(&png);
        throw std::runtime_error("not a readable PNG " + file.string() + ": " + message);
    }
    png.format = PNG_FORMAT_RGB;
    Image image(static_cast<int>(png.width), static_cast<int>(png.height), Rgb{0, 0, 0});
    if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
        const std::string message = png.message;
        png_image_free(&png);
        throw std::runtime_error("corrupt PNG " + file.string() + ": " + message);
    }
    return image;
}

// ---------------------------------------------------------------------------------
// Text in PNGs: a 5 x 8 bitmap font, so that the pictures carry their own title, axis
// labels and legend without a font library. Columns of bits, least significant bit on
// top; the eighth row holds the descenders (g, j, p, q, y, comma).

namespace {

constexpr std::uint8_t font[95][5] = {
    {0x00, 0x00, 0x00, 0x00, 0x00},  // ' '
    {0x00, 0x00, 0x5F, 0x00, 0x00},  // '!'
    {0x00, 0x07, 0x00, 0x07, 0x00},  // '"'
    {0x14, 0x7F, 0x14, 0x7F, 0x14},  // '#'
    {0x24, 0x2A, 0x7F, 0x2A, 0x12},  // '$'
    {0x23, 0x13, 0x08, 0x64, 0x62},  // '%'
    {0x36, 0x49, 0x56, 0x20, 0x50},  // '&'
    {0x00, 0x08, 0x07, 0x03, 0x00},  // '\''
    {0x00, 0x1C, 0x22, 0x41, 0x00},  // '('
    {0x00, 0x41, 0x22, 0x1C, 0x00},  // ')'
    {0x2A, 0x1C, 0x7F, 0x1C, 0x2A},  // '*'
    {0x08, 0x08, 0x3E, 0x08, 0x08},  // '+'
    {0x00, 0x80, 0x70, 0x30, 0x00},  // ','
    {0x08, 0x08, 0x08, 0x08, 0x08},  // '-'
    {0x00, 0x00, 0x60, 0x60, 0x00},  // '.'
    {0x20, 0x10, 0x08, 0x04, 0x02},  // '/'
    {0x3E, 0x51, 0x49, 0x45, 0x3E},  // '0'
    {0x00, 0x42, 0x7F, 0x40, 0x00},  // '1'
    {0x72, 0x49, 0x49, 0x49, 0x46},  // '2'
    {0x21, 0x41, 0x49, 0x4D, 0x33},  // '3'
    {0x18, 0x14, 0x12, 0x7F, 0x10},  // '4'
    {0x27, 0x45, 0x45, 0x45, 0x39},  // '5'
    {0x3C, 0x4A, 0x49, 0x49, 0x31},  // '6'
    {0x41, 0x21, 0x11, 0x09, 0x07},  // '7'
    {0x36, 0x49, 0x49, 0x49, 0x36},  // '8'
    {0x46, 0x49, 0x49, 0x29, 0x1E},  // '9'
    {0x00, 0x00, 0x14, 0x00, 0x00},  // ':'
    {0x00, 0x40, 0x34, 0x00, 0x00},  // ';'
    {0x00, 0x08, 0x14, 0x22, 0x41},  // '<'
    {0x14, 0x14, 0x14, 0x14, 0x14},  // '='
    {0x00, 0x41, 0x22, 0x14, 0x08},  // '>'
    {0x02, 0x01, 0x59, 0x09, 0x06},  // '?'
    {0x3E, 0x41, 0x5D, 0x59, 0x4E},  // '@'
    {0x7C, 0x12, 0x11, 0x12, 0x7C},  // 'A'
    {0x7F, 0x49, 0x49, 0x49, 0x36},  // 'B'
    {0x3E, 0x41, 0x41, 0x41, 0x22},  // 'C'
    {0x7F, 0x41, 0x41, 0x41, 0x3E},  // 'D'
    {0x7F, 0x49, 0x49, 0x49, 0x41},  // 'E'
    {0x7F, 0x09, 0x09, 0x09, 0x01},  // 'F'
    {0x3E, 0x41, 0x41, 0x51, 0x73},  // 'G'
    {0x7F, 0x08, 0x08, 0x08, 0x7F},  // 'H'
    {0x00, 0x41, 0x7F, 0x41, 0x00},  // 'I'
    {0x20, 0x40, 0x41, 0x3F, 0x01},  // 'J'
    {0x7F, 0x08, 0x14, 0x22, 0x41},  // 'K'
    {0x7F, 0x40, 0x40, 0x40, 0x40},  // 'L'
    {0x7F, 0x02, 0x1C, 0x02, 0x7F},  // 'M'
    {0x7F, 0x04, 0x08, 0x10, 0x7F},  // 'N'
    {0x3E, 0x41, 0x41, 0x41, 0x3E},  // 'O'
    {0x7F, 0x09, 0x09, 0x09, 0x06},  // 'P'
    {0x3E, 0x41, 0x51, 0x21, 0x5E},  // 'Q'
    {0x7F, 0x09, 0x19, 0x29, 0x46},  // 'R'
    {0x26, 0x49, 0x49, 0x49, 0x32},  // 'S'
    {0x03, 0x01, 0x7F, 0x01, 0x03},  // 'T'
    {0x3F, 0x40, 0x40, 0x40, 0x3F},  // 'U'
    {0x1F, 0x20, 0x40, 0x20, 0x1F},  // 'V'
    {0x3F, 0x40, 0x38, 0x40, 0x3F},  // 'W'
    {0x63, 0x14, 0x08, 0x14, 0x63},  // 'X'
    {0x03, 0x04, 0x78, 0x04, 0x03},  // 'Y'
    {0x61, 0x59, 0x49, 0x4D, 0x43},  // 'Z'
    {0x00, 0x7F, 0x41, 0x41, 0x41},  // '['
    {0x02, 0x04, 0x08, 0x10, 0x20},  // '\\'
    {0x00, 0x41, 0x41, 0x41, 0x7F},  // ']'
    {0x04, 0x02, 0x01, 0x02, 0x04},  // '^'
    {0x40, 0x40, 0x40, 0x40, 0x40},  // '_'
    {0x00, 0x03, 0x07, 0x08, 0x00},  // '`'
    {0x20, 0x54, 0x54, 0x78, 0x40},  // 'a'
    {0x7F, 0x28, 0x44, 0x44, 0x38},  // 'b'
    {0x38, 0x44, 0x44, 0x44, 0x28},  // 'c'
    {0x38, 0x44, 0x44, 0x28, 0x7F},  // 'd'
    {0x38, 0x54, 0x54, 0x54, 0x18},  // 'e'
    {0x00, 0x08, 0x7E, 0x09, 0x02},  // 'f'
    {0x18, 0xA4, 0xA4, 0x9C, 0x78},  // 'g'
    {0x7F, 0x08, 0x04, 0x04, 0x78},  // 'h'
    {0x00, 0x44, 0x7D, 0x40, 0x00},  // 'i'
    {0x20, 0x40, 0x40, 0x3D, 0x00},  // 'j'
    {0x7F, 0x10, 0x28, 0x44, 0x00},  // 'k'
    {0x00, 0x41, 0x7F, 0x40, 0x00},  // 'l'
    {0x7C, 0x04, 0x78, 0x04, 0x78},  // 'm'
    {0x7C, 0x08, 0x04, 0x04, 0x78},  // 'n'
    {0x38, 0x44, 0x44, 0x44, 0x38},  // 'o'
    {0xFC, 0x18, 0x24, 0x24, 0x18},  // 'p'
    {0x18, 0x24, 0x24, 0x18, 0xFC},  // 'q'
    {0x7C, 0x08, 0x04, 0x04, 0x08},  // 'r'
    {0x48, 0x54, 0x54, 0x54, 0x24},  // 's'
    {0x04, 0x04, 0x3F, 0x44, 0x24},  // 't'
    {0x3C, 0x40, 0x40, 0x20, 0x7C},  // 'u'
    {0x1C, 0x20, 0x40, 0x20, 0x1C},  // 'v'
    {0x3C, 0x40, 0x30, 0x40, 0x3C},  // 'w'
    {0x44, 0x28, 0x10, 0x28, 0x44},  // 'x'
    {0x4C, 0x90, 0x90, 0x90, 0x7C},  // 'y'
    {0x44, 0x64, 0x54, 0x4C, 0x44},  // 'z'
    {0x00, 0x08, 0x36, 0x41, 0x00},  // '{'
    {0x00, 0x00, 0x77, 0x00, 0x00},  // '|'
    {0x00, 0x41, 0x36, 0x08, 0x00},  // '}'
    {0x02, 0x01, 0x02, 0x04, 0x02},  // '~'
};

void put(Image& image, int x, int y, Rgb colour) {
    if (x >= 0 && y >= 0 && x < image.width && y < image.height) image.at(x, y) = colour;
}

const std::uint8_t* glyph(char c) {
    const int i = static_cast<unsigned char>(c) - 0x20;
    return font[i >= 0 && i < 95 ? i : '?' - 0x20];
}

}  // namespace

int text_width(std::string_view text, int scale) {
    return text.empty() ? 0 : (int(text.size()) * glyph_advance - 1) * scale;
}

void draw_text(Image& image, int x, int y, std::string_view text, Rgb colour, int scale) {
    for (char c : text) {
        const std::uint8_t* g = glyph(c);
        for (int col = 0; col < glyph_width; ++col) {
            for (int row = 0; row < glyph_height; ++row) {
                if (!((g[col] >> row) & 1)) continue;
                fill_rect(image, x + col * scale, y + row * scale, scale, scale, colour);
            }
        }
        x += glyph_advance * scale;
    }
}

void draw_text_vertical(Image& image, int x, int y, std::string_view text, Rgb colour, int scale) {
    // Turned a quarter left: the baseline runs upward from (x, y), glyph tops face left.
    for (char c : text) {
        const std::uint8_t* g = glyph(c);
        for (int col = 0; col < glyph_width; ++col) {
            for (int row = 0; row < glyph_height; ++row) {
                if (!((g[col] >> row) & 1)) continue;
                fill_rect(image, x + row * scale, y - (col + 1) * scale, scale, scale, colour);
            }
        }
        y -= glyph_advance * scale;
    }
}

void fill_rect(Image& image, int x, int y, int w, int h, Rgb colour) {
    for (int j = y; j < y + h; ++j) {
        for (int i = x; i < x + w; ++i) put(image, i, j, colour);
    }
}

// ---------------------------------------------------------------------------------
// The line plot. One drawing routine (draw_plot) describes the picture to a Canvas; the
// SVG canvas writes elements, the raster canvas sets pixels, so the two files show the
// same plot by construction.

namespace {

std::string escape_xml(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

// Colour-blind-safe palette (Okabe-Ito); after seven curves the colours repeat dashed,
// then dotted.
constexpr Rgb palette[] = {{0x00, 0x72, 0xB2}, {0xD5, 0x5E, 0x00}, {0x00, 0x9E, 0x73},
                           {0xCC, 0x79, 0xA7}, {0xE6, 0x9F, 0x00}, {0x56, 0xB4, 0xE9},
                           {0x00, 0x00, 0x00}};
constexpr Rgb black{0, 0, 0}, white{255, 255, 255}, grid_grey{0xdd, 0xdd, 0xdd},
    zero_grey{0x99, 0x99, 0x99};

enum class Dash { solid, dashed, dotted };
enum class Anchor { start, middle, end };

std::string hex(Rgb c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02X%02X%02X", c.r, c.g, c.b);
    return buf;
}

/// What draw_plot draws with, in SVG user units (pixels of the SVG).
class Canvas {
public:
    virtual ~Canvas() = default;
    virtual void begin_group(const char* kind, const std::string& title) = 0;
    virtual void end_group() = 0;
    virtual void frame(double x, double y, double w, double h) = 0;  ///< black outline
    virtual void polyline(const std::vector<std::pair<double, double>>& points, Rgb colour,
                          double width, Dash dash) = 0;
    virtual void disc(double cx, double cy, double r, Rgb colour) = 0;
    /// Baseline at y; vertical: turned a quarter left around (x, y).
    virtual void text(double x, double y, const std::string& text, double size, Anchor anchor,
                      bool vertical = false) = 0;
    void line(double x1, double y1, double x2, double y2, Rgb colour, double width,
              Dash dash = Dash::solid) {
        polyline({{x1, y1}, {x2, y2}}, colour, width, dash);
    }
};

class SvgCanvas final : public Canvas {
public:
    std::ostringstream out;
    void begin_group(const char* kind, const std::string& title) override {
        out << "<g class=\"" << kind << "\"><title>" << escape_xml(title) << "</title>\n";
    }
    void end_group() override { out << "</g>\n"; }
    void frame(double x, double y, double w, double h) override {
        out << "<rect x=\"" << number(x) << "\" y=\"" << number(y) << "\" width=\"" << number(w)
            << "\" height=\"" << number(h) << "\" fill=\"none\" stroke=\"black\"/>\n";
    }
    void polyline(const std::vector<std::pair<double, double>>& points, Rgb colour, double width,
                  Dash dash) override {
        out << "<polyline fill=\"none\" stroke=\"" << hex(colour) << "\" stroke-width=\""
            << number(width) << "\"";
        if (dash == Dash::dashed) out << " stroke-dasharray=\"6 3\"";
        if (dash == Dash::dotted) out << " stroke-dasharray=\"2 2\"";
        out << " points=\"";
        for (const auto& [x, y] : points) out << number(x) << ',' << number(y) << ' ';
        out << "\"/>\n";
    }
    void disc(double cx, double cy, double r, Rgb colour) override {
        out << "<circle cx=\"" << number(cx) << "\" cy=\"" << number(cy) << "\" r=\"" << number(r)
            << "\" fill=\"" << hex(colour) << "\"/>\n";
    }
    void text(double x, double y, const std::string& text, double size, Anchor anchor,
              bool vertical) override {
        const char* a = anchor == Anchor::start    ? "start"
                        : anchor == Anchor::middle ? "middle"
                                                   : "end";
        out << "<text";
        if (vertical) {
            out << " transform=\"translate(" << number(x) << ',' << number(y) << ") rotate(-90)\"";
        } else {
            out << " x=\"" << number(x) << "\" y=\"" << number(y) << "\"";
        }
        out << " text-anchor=\"" << a << "\" font-size=\"" << number(size) << "\">"
            << escape_xml(text) << "</text>\n";
    }
};

/// Pixels at `zoom` times the SVG's units; text in the bitmap font, about as tall as the
/// SVG's sans-serif at that zoom.
class RasterCanvas final : public Canvas {
public:
    RasterCanvas(double width, double height, int zoom)
        : image(int(std::lround(width * zoom)), int(std::lround(height * zoom)), white),
          zoom_(zoom) {}
    Image image;
    void begin_group(const char*, const std::string&) override {}
    void end_group() override {}
    void frame(double x, double y, double w, double h) override {
        const int x0 = px(x), y0 = px(y), x1 = px(x + w), y1 = px(y + h);
        fill_rect(image, x0, y0, x1 - x0 + 1, zoom_, black);
        fill_rect(image, x0, y1 - zoom_ + 1, x1 - x0 + 1, zoom_, black);
        fill_rect(image, x0, y0, zoom_, y1 - y0 + 1, black);
        fill_rect(image, x1 - zoom_ + 1, y0, zoom_, y1 - y0 + 1, black);
    }
    void polyline(const std::vector<std::pair<double, double>>& points, Rgb colour, double width,
                  Dash dash) override {
        // Discs of the line's width stamped every half pixel along it; a dash pattern runs
        // on across the vertices.
        const double on = dash == Dash::dashed ? 6 * zoom_ : 2 * zoom_;
        const double period = dash == Dash::dashed ? 9 * zoom_ : 4 * zoom_;
        const double r = std::max(0.5, width * zoom_ / 2);
        double travelled = 0;
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            const double x0 = points[i].first * zoom_, y0 = points[i].second * zoom_;
            const double dx = points[i + 1].first * zoom_ - x0,
                         dy = points[i + 1].second * zoom_ - y0;
            const double length = std::hypot(dx, dy);
            const int steps = std::max(1, int(std::ceil(length * 2)));
            for (int k = 0; k <= steps; ++k) {
                const double t = double(k) / steps;
                if (dash != Dash::solid && std::fmod(travelled + t * length, period) >= on)
                    continue;
                stamp(x0 + t * dx, y0 + t * dy, r, colour);
            }
            travelled += length;
        }
    }
    void disc(double cx, double cy, double r, Rgb colour) override {
        stamp(cx * zoom_, cy * zoom_, r * zoom_, colour);
    }
    void text(double x, double y, const std::string& text, double size, Anchor anchor,
              bool vertical) override {
        // Font pixels of zoom * size / 12 px (12 px text at zoom 2: capitals 14 px tall,
        // as a 24 px sans-serif's), smaller where the text would not fit the image.
        int scale = std::max(1, int(std::lround(zoom_ * size / 12.0)));
        while (scale > 1 && text_width(text, scale) > image.width) --scale;
        const int w = text_width(text, scale);
        const int shift = anchor == Anchor::start ? 0 : anchor == Anchor::middle ? w / 2 : w;
        const int baseline = 7 * scale;  // the glyphs' eighth row holds the descenders
        if (vertical) {
            draw_text_vertical(image, px(x) - baseline, px(y) + shift, text, black, scale);
        } else {
            draw_text(image, px(x) - shift, px(y) - baseline, text, black, scale);
        }
    }

private:
    int zoom_;
    int px(double v) const { return int(std::lround(v * zoom_)); }
    void stamp(double cx, double cy, double r, Rgb colour) {
        // Pixel (i, j) covers [i, i + 1) x [j, j + 1); it is set when its centre is inside.
        for (int j = int(std::floor(cy - r)); j <= int(std::ceil(cy + r)); ++j) {
            for (int i = int(std::floor(cx - r)); i <= int(std::ceil(cx + r)); ++i) {
                const double ex = i + 0.5 - cx, ey = j + 0.5 - cy;
                if (ex * ex + ey * ey <= r * r && i >= 0 && j >= 0 && i < image.width &&
                    j < image.height)
                    image.at(i, j) = colour;
            }
        }
    }
};

struct PlotSize {
    double W, H, left, top, pw, ph, gap;
};

PlotSize plot_size(const LinePlot& plot) {
    const std::size_t n = std::max<std::size_t>(1, plot.panels.size());
    const bool captions = std::any_of(plot.panels.begin(), plot.panels.end(),
                                      [](const Panel& p) { return !p.title.empty(); });
    PlotSize s{};
    s.left = 80;
    s.top = captions ? 60 : 40;
    s.gap = 20;
    s.pw = n == 1 ? 450 : 260;
    s.ph = 320;
    s.W = s.left + double(n) * s.pw + double(n - 1) * s.gap + 190;
    s.H = s.top + s.ph + 60;
    return s;
}

void draw_plot(const LinePlot& plot, Canvas& c) {
    const PlotSize size = plot_size(plot);
    const double left = size.left, top = size.top, pw = size.pw, ph = size.ph, H = size.H;

    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
    double ymin_pos = std::numeric_limits<double>::infinity(), ymax = 0;
    double ymin = std::numeric_limits<double>::infinity();
    std::vector<std::string> names;  // legend: every series name once, in order of appearance
    for (const Panel& panel : plot.panels) {
        for (const Series& s : panel.series) {
            if (std::find(names.begin(), names.end(), s.name) == names.end())
                names.push_back(s.name);
            for (std::size_t i = 0; i < s.x.size(); ++i) {
                xmin = std::min(xmin, s.x[i]);
                xmax = std::max(xmax, s.x[i]);
                ymax = std::max(ymax, s.y[i]);
                ymin = std::min(ymin, s.y[i]);
                if (s.y[i] > 0) ymin_pos = std::min(ymin_pos, s.y[i]);
            }
        }
    }
    if (!(xmin < xmax)) {
        xmin = 0;
        xmax = 1;
    }
    // y mapping. Log: decades from floor(log10 min positive) to ceil(log10 max); zeros
    // go one band below the lowest decade, labelled "0" and separated by a dashed line.
    int dlo = 0, dhi = 0;
    double zero_band = 0;
    if (plot.log_y) {
        if (!(ymin_pos < std::numeric_limits<double>::infinity())) ymin_pos = 1e-6;
        if (!(ymax > 0)) ymax = 1;
        dlo = static_cast<int>(std::floor(std::log10(ymin_pos)));
        dhi = static_cast<int>(std::ceil(std::log10(ymax)));
        if (dhi <= dlo) dhi = dlo + 1;
        zero_band = ph * 0.1;
    } else {
        ymin = std::min(0.0, ymin);
        if (!(ymax > ymin)) ymax = ymin + 1;
    }
    auto Y = [&](double y) {
        if (plot.log_y) {
            if (y <= 0) return top + ph;
            const double f = (std::log10(y) - dlo) / double(dhi - dlo);
            return top + (ph - zero_band) * (1 - f);
        }
        return top + ph * (1 - (y - ymin) / (ymax - ymin));
    };
    const double xstep = [&] {
        const double span = xmax - xmin;
        for (double st : {1.0, 2.0, 5.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0, 512.0}) {
            if (span / st <= 10) return st;
        }
        return span / 8;
    }();
    const auto colour = [&](std::size_t k) { return palette[k % std::size(palette)]; };
    const auto dash = [&](std::size_t k) {
        const std::size_t d = k / std::size(palette) % 3;
        return d == 0 ? Dash::solid : d == 1 ? Dash::dashed : Dash::dotted;
    };
    const double right_edge = left + double(std::max<std::size_t>(1, plot.panels.size())) * pw +
                              double(std::max<std::size_t>(1, plot.panels.size()) - 1) * size.gap;

    c.text((left + right_edge) / 2, 22, plot.title, 15, Anchor::middle);
    for (std::size_t p = 0; p < plot.panels.size(); ++p) {
        const Panel& panel = plot.panels[p];
        const double x0 = left + double(p) * (pw + size.gap);
        auto X = [&](double x) { return x0 + (x - xmin) / (xmax - xmin) * pw; };
        c.begin_group("panel", panel.title);
        // Grid and ticks; the y labels left of the first panel only (the scales are shared).
        for (double x = std::ceil(xmin / xstep) * xstep; x <= xmax + 1e-9; x += xstep) {
            c.line(X(x), top, X(x), top + ph, grid_grey, 1);
            std::ostringstream label;
            label << x;
            c.text(X(x), top + ph + 18, label.str(), 12, Anchor::middle);
        }
        if (plot.log_y) {
            for (int d = dlo; d <= dhi; ++d) {
                const double y = Y(std::pow(10.0, d));
                c.line(x0, y, x0 + pw, y, grid_grey, 1);
                if (p == 0) c.text(left - 6, y + 4, "1e" + std::to_string(d), 12, Anchor::end);
            }
            const double yz = top + ph - zero_band / 2;
            c.line(x0, yz, x0 + pw, yz, zero_grey, 1, Dash::dashed);
            if (p == 0) c.text(left - 6, top + ph + 4, "0", 12, Anchor::end);
        } else {
            for (int i = 0; i <= 5; ++i) {
                const double v = ymin + (ymax - ymin) * i / 5;
                c.line(x0, Y(v), x0 + pw, Y(v), grid_grey, 1);
                std::ostringstream label;
                label << v;
                if (p == 0) c.text(left - 6, Y(v) + 4, label.str(), 12, Anchor::end);
            }
        }
        c.frame(x0, top, pw, ph);
        if (!panel.title.empty()) c.text(x0 + pw / 2, top - 8, panel.title, 13, Anchor::middle);
        for (const Series& se : panel.series) {
            const auto k =
                std::size_t(std::find(names.begin(), names.end(), se.name) - names.begin());
            c.begin_group("series", se.name);
            std::vector<std::pair<double, double>> points;
            for (std::size_t i = 0; i < se.x.size(); ++i)
                points.emplace_back(X(se.x[i]), Y(se.y[i]));
            c.polyline(points, colour(k), 2, dash(k));
            for (const auto& [x, y] : points) c.disc(x, y, 2.5, colour(k));
            c.end_group();
        }
        c.end_group();
    }
    c.text((left + right_edge) / 2, H - 15, plot.x_label, 12, Anchor::middle);
    c.text(18, top + ph / 2, plot.y_label, 12, Anchor::middle, true);
    c.begin_group("legend", "legend");
    for (std::size_t k = 0; k < names.size(); ++k) {
        const double ly = top + 10 + 20 * double(k);
        c.line(right_edge + 15, ly, right_edge + 40, ly, colour(k), 2, dash(k));
        c.text(right_edge + 46, ly + 4, names[k], 12, Anchor::start);
    }
    c.end_group();
}

}  // namespace

std::string render_svg(const LinePlot& plot) {
    const PlotSize size = plot_size(plot);
    SvgCanvas svg;
    svg.out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size.W << "\" height=\""
            << size.H << "\" viewBox=\"0 0 " << size.W << ' ' << size.H
            << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
            << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    draw_plot(plot, svg);
    svg.out << "</svg>\n";
    return svg.out.str();
}

Image render_plot_image(const LinePlot& plot) {
    const PlotSize size = plot_size(plot);
    RasterCanvas raster(size.W, size.H, 2);
    draw_plot(plot, raster);
    return std::move(raster.image);
}

}  // namespace exidel::research
