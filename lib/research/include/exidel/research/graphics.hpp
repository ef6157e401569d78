// exidel::research: pictures. PNG through libpng (images of failure maps) and a small
// line plot (the precision curves) drawn as SVG and as an image for PNG, all written by the
// studies into their folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
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
    Image(int w, int h, Rgb fill)
        : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), fill) {}
    Rgb& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const Rgb& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

/// Text for pictures, in a built-in 5 x 8 bitmap font (printable ASCII; other characters
/// are drawn as '?'), every font pixel a scale x scale square. Pixels outside the image
/// are clipped.
inline constexpr int glyph_width = 5, glyph_height = 8, glyph_advance = 6;
/// Width in pixels of `text` drawn at `scale`.
int text_width(std::string_view text, int scale);
/// Draws `text` left to right with the top-left corner of its first glyph at (x, y).
void draw_text(Image& image, int x, int y, std::string_view text, Rgb colour, int scale);
/// Draws `text` bottom to top (turned a quarter left, for y-axis labels), starting at
/// (x, y), the bottom-left corner of the turned text.
void draw_text_vertical(Image& image, int x, int y, std::string_view text, Rgb colour, int scale);
/// Fills a w x h rectangle whose top-left corner is (x, y).
void fill_rect(Image& image, int x, int y, int w, int h, Rgb colour);

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

/// One chart of a line plot: its caption (may be empty) and its curves.
struct Panel {
    std::string title;
    std::vector<Series> series;
};

/// Charts side by side with the same x and y scales and one legend: a series name keeps
/// its colour (and dash, after the seven colours) in every panel, listed once in the legend.
struct LinePlot {
    std::string title, x_label, y_label;
    bool log_y = false;  ///< y values of 0 are drawn on a separate "0" line below the decades
    std::vector<Panel> panels;
};

/// The plot as a standalone SVG document (about 720 x 420 px for one panel, 280 px wider
/// for each further one): title, axes, ticks, a panel caption above each chart, legend.
/// Every panel is a <g class="panel"> and every curve a <g class="series">, each starting
/// with a <title> naming it.
std::string render_svg(const LinePlot& plot);

/// The same drawing as render_svg, rasterised at twice its size (text in the bitmap font),
/// for write_png.
Image render_plot_image(const LinePlot& plot);

}  // namespace exidel::research
