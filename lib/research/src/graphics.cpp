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
    if (!(xmin < xmax)) { xmin = 0; xmax = 1; }
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
      << "<text x=\"" << number(left + pw / 2) << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
      << escape_xml(plot.title) << "</text>\n";
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
