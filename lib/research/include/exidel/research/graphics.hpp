// exidel::research: pictures. PNG through libpng (images of failure maps) and a small
// SVG line plot (the precision curves), both written by the studies into their folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace exidel::research {

struct Rgb {
    std::uint8_t r, g, b;
    friend constexpr bool operator==(const Rgb&, const Rgb&) = default;
};

/// An 8-bit RGB image, rows top to bottom.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<Rgb> pixels;  ///< width * height, row-major

    Image() = default;
    Image(int w, int h, Rgb fill) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), fill) {}
    Rgb& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const Rgb& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

/// Writes `image` as an 8-bit RGB PNG. Throws std::runtime_error with libpng's message.
void write_png(const std::filesystem::path& file, const Image& image);

/// Reads a PNG back (any colour type, converted to 8-bit RGB). Throws
/// std::runtime_error if the file is not a valid PNG. Used by tests and tools.
Image read_png(const std::filesystem::path& file);

/// One curve of a line plot.
struct Series {
    std::string name;
    std::vector<double> x, y;
};

struct LinePlot {
    std::string title, x_label, y_label;
    bool log_y = false;  ///< y values of 0 are drawn on a separate "0" line below the decades
    std::vector<Series> series;
};

/// The plot as a standalone SVG document (about 720 x 420 px, axes, ticks, legend).
std::string render_svg(const LinePlot& plot);

}  // namespace exidel::research
