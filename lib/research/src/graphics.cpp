// exidel::research: PNG via libpng's simplified API (no setjmp in our code), and the
// SVG line plot.
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

// Colour-blind-safe palette (Okabe-Ito).
constexpr const char* palette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                   "#E69F00", "#56B4E9", "#000000"};

}  // namespace

std::string render_svg(const LinePlot& plot) {
    constexpr double W = 720, H = 420, left = 80, right = 190, top = 40, bottom = 60;
    const double pw = W - left - right, ph = H - top - bottom;

    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
    double ymin_pos = std::numeric_limits<double>::infinity(), ymax = 0;
    double ymin = std::numeric_limits<double>::infinity();
    for (const Series& s : plot.series) {
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            xmin = std::min(xmin, s.x[i]);
            xmax = std::max(xmax, s.x[i]);
            ymax = std::max(ymax, s.y[i]);
            ymin = std::min(ymin, s.y[i]);
            if (s.y[i] > 0) ymin_pos = std::min(ymin_pos, s.y[i]);
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
    auto X = [&](double x) { return left + (x - xmin) / (xmax - xmin) * pw; };
    auto Y = [&](double y) {
        if (plot.log_y) {
            if (y <= 0) return top + ph;
            const double f = (std::log10(y) - dlo) / double(dhi - dlo);
            return top + (ph - zero_band) * (1 - f);
        }
        return top + ph * (1 - (y - ymin) / (ymax - ymin));
    };

    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" viewBox=\"0 0 " << W << ' ' << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << number(left + pw / 2)
      << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << escape_xml(plot.title)
      << "</text>\n";
    // Grid and ticks.
    const double xstep = [&] {
        const double span = xmax - xmin;
        for (double st : {1.0, 2.0, 5.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0, 512.0}) {
            if (span / st <= 10) return st;
        }
        return span / 8;
    }();
    for (double x = std::ceil(xmin / xstep) * xstep; x <= xmax + 1e-9; x += xstep) {
        s << "<line x1=\"" << number(X(x)) << "\" y1=\"" << top << "\" x2=\"" << number(X(x))
          << "\" y2=\"" << top + ph << "\" stroke=\"#ddd\"/>\n"
          << "<text x=\"" << number(X(x)) << "\" y=\"" << top + ph + 18
          << "\" text-anchor=\"middle\">" << x << "</text>\n";
    }
    if (plot.log_y) {
        for (int d = dlo; d <= dhi; ++d) {
            const double y = Y(std::pow(10.0, d));
            s << "<line x1=\"" << left << "\" y1=\"" << number(y) << "\" x2=\"" << left + pw
              << "\" y2=\"" << number(y) << "\" stroke=\"#ddd\"/>\n"
              << "<text x=\"" << left - 6 << "\" y=\"" << number(y + 4)
              << "\" text-anchor=\"end\">1e" << d << "</text>\n";
        }
        const double yz = top + ph - zero_band / 2;
        s << "<line x1=\"" << left << "\" y1=\"" << number(yz) << "\" x2=\"" << left + pw
          << "\" y2=\"" << number(yz) << "\" stroke=\"#999\" stroke-dasharray=\"4 3\"/>\n"
          << "<text x=\"" << left - 6 << "\" y=\"" << number(top + ph + 4)
          << "\" text-anchor=\"end\">0</text>\n";
    } else {
        for (int i = 0; i <= 5; ++i) {
            const double v = ymin + (ymax - ymin) * i / 5;
            s << "<line x1=\"" << left << "\" y1=\"" << number(Y(v)) << "\" x2=\"" << left + pw
              << "\" y2=\"" << number(Y(v)) << "\" stroke=\"#ddd\"/>\n"
              << "<text x=\"" << left - 6 << "\" y=\"" << number(Y(v) + 4)
              << "\" text-anchor=\"end\">" << v << "</text>\n";
        }
    }
    s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"black\"/>\n"
      << "<text x=\"" << number(left + pw / 2) << "\" y=\"" << H - 15
      << "\" text-anchor=\"middle\">" << escape_xml(plot.x_label) << "</text>\n"
      << "<text transform=\"translate(18," << number(top + ph / 2)
      << ") rotate(-90)\" text-anchor=\"middle\">" << escape_xml(plot.y_label) << "</text>\n";
    // Curves and legend.
    for (std::size_t k = 0; k < plot.series.size(); ++k) {
        const Series& se = plot.series[k];
        const char* colour = palette[k % std::size(palette)];
        s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
        for (std::size_t i = 0; i < se.x.size(); ++i) {
            s << number(X(se.x[i])) << ',' << number(Y(se.y[i])) << ' ';
        }
        s << "\"/>\n";
        for (std::size_t i = 0; i < se.x.size(); ++i) {
            s << "<circle cx=\"" << number(X(se.x[i])) << "\" cy=\"" << number(Y(se.y[i]))
              << "\" r=\"2.5\" fill=\"" << colour << "\"/>\n";
        }
        const double ly = top + 10 + 20 * double(k);
        s << "<line x1=\"" << left + pw + 15 << "\" y1=\"" << ly << "\" x2=\"" << left + pw + 40
          << "\" y2=\"" << ly << "\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n"
          << "<text x=\"" << left + pw + 46 << "\" y=\"" << ly + 4 << "\">" << escape_xml(se.name)
          << "</text>\n";
    }
    s << "</svg>\n";
    return s.str();
}

}  // namespace exidel::research
