// exidel I/O (internal): small pieces shared by the readers and writers.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <condition_variable>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <ostream>
#include <span>
#include <string_view>
#include <vector>

#include "exidel/delaunay/parallel.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::io::detail {

// Called for every character of a text file: comparisons, not blanks.find(c) (a memchr
// call per character was 40% of parsing an xy file).
inline bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Calls f(line_number, line) for every line of `data` (split at '\n', a trailing '\r'
/// removed, line numbers from 1). A final line without '\n' counts; an empty tail does not.
/// Returns the number of lines.
template <class F>
std::size_t for_each_line(std::string_view data, F&& f) {
    std::size_t number = 0;
    std::size_t start = 0;
    while (start < data.size()) {
        std::size_t end = data.find('\n', start);
        if (end == std::string_view::npos) end = data.size();
        std::string_view line = data.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        f(++number, line);
        start = end + 1;
    }
    return number;
}

/// ".json" -> "json": the part of the file name after its last '.'; empty when there is
/// none (a '.' in a directory name does not count).
inline std::string_view extension_of(std::string_view path) {
    const std::size_t dot = path.rfind('.'), slash = path.rfind('/');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
        return {};
    }
    return path.substr(dot + 1);
}

/// The smallest box holding `points`, {x0, y0, x1, y1}; all zero when empty (callers
/// decide what an empty set's box is).
struct Bounds {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
inline Bounds bounding_box(std::span<const Point2> points) {
    if (points.empty()) return {};
    Bounds b{points[0].x, points[0].y, points[0].x, points[0].y};
    for (const Point2& p : points) {
        b.x0 = std::min(b.x0, p.x);
        b.x1 = std::max(b.x1, p.x);
        b.y0 = std::min(b.y0, p.y);
        b.y1 = std::max(b.y1, p.y);
    }
    return b;
}

/// `line` without its '#' comment.
inline std::string_view strip_comment(std::string_view line) {
    const std::size_t hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// Buffered text output of numbers: std::to_chars into a local buffer, flushed in large
/// writes (an ostream<< per number costs several times more at 10^6 points).
class NumberWriter {
public:
    explicit NumberWriter(std::ostream& out) : out_(out) {}
    ~NumberWriter() { flush(); }
    NumberWriter(const NumberWriter&) = delete;
    NumberWriter& operator=(const NumberWriter&) = delete;

    NumberWriter& text(std::string_view s) {
        if (s.size() > capacity - used_) flush();
        if (s.size() > capacity) {
            out_.write(s.data(), static_cast<std::streamsize>(s.size()));
            return *this;
        }
        for (char c : s) buf_[used_++] = c;
        return *this;
    }
    /// The shortest decimal that reads back as exactly `v` (std::to_chars).
    NumberWriter& number(double v) { return put(v); }
    NumberWriter& number(std::uint64_t v) { return put(v); }
    /// `v` with `digits` digits after the point (for pictures, not for reading back).
    NumberWriter& fixed(double v, int digits) {
        if (capacity - used_ < 400) flush();  // room for any fixed-format double
        const auto r =
            std::to_chars(buf_ + used_, buf_ + capacity, v, std::chars_format::fixed, digits);
        used_ = static_cast<std::size_t>(r.ptr - buf_);
        return *this;
    }
    void flush() {
        out_.write(buf_, static_cast<std::streamsize>(used_));
        used_ = 0;
    }

private:
    template <class T>
    NumberWriter& put(T v) {
        if (capacity - used_ < 32) flush();
        const auto r = std::to_chars(buf_ + used_, buf_ + capacity, v);
        used_ = static_cast<std::size_t>(r.ptr - buf_);
        return *this;
    }
    static constexpr std::size_t capacity = 1 << 16;
    std::ostream& out_;
    char buf_[capacity];
    std::size_t used_ = 0;
};

/// Writes `v` as JSON: the shortest decimal that reads back as `v`, negative zero as
/// "-0.0" (to_chars writes "-0", which many JSON readers take for the integer 0).
inline void json_number(NumberWriter& w, double v) {
    if (v == 0 && std::signbit(v)) {
        w.text("-0.0");
    } else {
        w.number(v);
    }
}

/// Writers into memory reserved beforehand (TextBuffer::append): each returns the end of
/// what it wrote. A cursor in a local variable stays in a register; members of a buffer
/// written through a char pointer would be reloaded after every character.
inline char* put(char* p, std::string_view s) {
    std::memcpy(p, s.data(), s.size());
    return p + s.size();
}
/// The shortest decimal that reads back as exactly `v` (std::to_chars): at most 24 chars.
inline char* put(char* p, double v) { return std::to_chars(p, p + 32, v).ptr; }
inline char* put(char* p, std::uint64_t v) { return std::to_chars(p, p + 32, v).ptr; }
/// As json_number: negative zero as "-0.0".
inline char* put_json(char* p, double v) {
    return v == 0 && std::signbit(v) ? put(p, "-0.0") : put(p, v);
}

/// Text formatted into memory that grows as needed (by doubling; never zero-filled, as a
/// resized std::string would be): one slice of a file formatted on its own thread.
class TextBuffer {
public:
    /// Appends what write(char* p) puts at p, at most `most` characters; write returns
    /// the end of its text.
    template <class Write>
    void append(std::size_t most, Write&& write) {
        if (capacity_ - used_ < most) grow(used_ + most);
        char* const begin = buf_.get() + used_;
        used_ += static_cast<std::size_t>(write(begin) - begin);
    }
    void clear() { used_ = 0; }
    std::size_t size() const { return used_; }
    std::string_view view() const { return {buf_.get(), used_}; }

private:
    void grow(std::size_t least) {
        const std::size_t capacity = std::max(2 * capacity_, least + 4096);
        std::unique_ptr<char[]> bigger(new char[capacity]);
        if (used_) std::memcpy(bigger.get(), buf_.get(), used_);
        buf_ = std::move(bigger);
        capacity_ = capacity;
    }
    std::unique_ptr<char[]> buf_;
    std::size_t capacity_ = 0, used_ = 0;
};

/// Writes items 0 .. count - 1 to `out` in order, items [begin, end) formatted by
/// format(begin, end, buffer), in slices of `slice` items. The text does not depend on
/// `threads`.
///
/// With more than one thread, formatting and writing overlap: the threads take slices in
/// order from parallel_for's counter and format each into one of a ring of 2 x threads
/// buffers; whichever thread finishes the lowest slice not yet written becomes the writer
/// and writes every consecutive formatted slice, in order, while the others go on
/// formatting (writing a large file is mostly the kernel filling page-cache pages, which
/// formatting used to wait for). A thread about to format slice s first waits until slice
/// s - ring is written, so memory stays bounded by the ring. No wait can last: the lowest
/// unwritten slice was handed out before any slice that waits on it, and its own wait is
/// on slices already written. When a format call or the stream throws, every waiting
/// thread stops, and parallel_for rethrows the exception.
template <class FormatRange>
void write_slices(std::ostream& out, std::size_t count, unsigned threads, std::size_t slice,
                  FormatRange&& format) {
    const std::size_t slices = (count + slice - 1) / slice;
    const std::size_t workers = std::min<std::size_t>(std::max(threads, 1u), slices);
    const auto range = [&](std::size_t s, TextBuffer& b) {
        b.clear();
        format(s * slice, std::min(count, (s + 1) * slice), b);
    };
    if (workers <= 1) {
        TextBuffer b;
        for (std::size_t s = 0; s < slices; ++s) {
            range(s, b);
            out.write(b.view().data(), static_cast<std::streamsize>(b.size()));
        }
        return;
    }
    const std::size_t ring = 2 * workers;
    std::vector<TextBuffer> buffers(ring);
    std::vector<std::uint8_t> formatted(ring, 0);  // per buffer: holds an unwritten slice
    std::mutex m;
    std::condition_variable slot_free;
    std::size_t written = 0;  // slices 0 .. written - 1 are in `out`
    bool writing = false, failed = false;
    exidel::parallel_for(slices, static_cast<unsigned>(workers), [&](std::size_t s) {
        try {
            {
                std::unique_lock lock(m);
                slot_free.wait(lock, [&] { return failed || s < written + ring; });
                if (failed) return;
            }
            range(s, buffers[s % ring]);
            std::unique_lock lock(m);
            formatted[s % ring] = 1;
            if (writing) return;  // the writer sees this slice when it reaches it
            writing = true;
            while (!failed && written < slices && formatted[written % ring]) {
                const TextBuffer& b = buffers[written % ring];
                lock.unlock();
                out.write(b.view().data(), static_cast<std::streamsize>(b.size()));
                lock.lock();
                formatted[written % ring] = 0;
                ++written;
                slot_free.notify_all();
            }
            writing = false;
        } catch (...) {
            const std::lock_guard lock(m);
            failed = true;
            slot_free.notify_all();
            throw;
        }
    });
}

/// write_slices with item i formatted by format(i, buffer).
template <class Format>
void write_items(std::ostream& out, std::size_t count, unsigned threads, Format&& format,
                 std::size_t slice = std::size_t{1} << 14) {
    write_slices(out, count, threads, slice,
                 [&](std::size_t begin, std::size_t end, TextBuffer& b) {
                     for (std::size_t i = begin; i < end; ++i) format(i, b);
                 });
}

/// Every point's text formatted once, by format(i, buffer), `threads` slices at a time: for
/// writers that repeat a point in every item that uses it (a GeoJSON feature per
/// triangle writes each position about six times).
class FormattedPoints {
public:
    template <class Format>
    FormattedPoints(std::size_t count, unsigned threads, Format&& format) : start_(count) {
        const std::size_t slices = (count + slice - 1) / slice;
        slices_.resize(slices);
        exidel::parallel_for(slices, threads, [&](std::size_t s) {
            TextBuffer& b = slices_[s];
            const std::size_t begin = s * slice, end = std::min(count, begin + slice);
            for (std::size_t i = begin; i < end; ++i) {
                start_[i] = static_cast<std::uint32_t>(b.size());
                format(i, b);
            }
        });
    }
    std::string_view operator[](std::size_t i) const {
        const TextBuffer& b = slices_[i / slice];
        const std::size_t begin = start_[i];
        const std::size_t end =
            (i + 1) % slice == 0 || i + 1 == start_.size() ? b.size() : start_[i + 1];
        return b.view().substr(begin, end - begin);
    }

private:
    static constexpr std::size_t slice = std::size_t{1} << 16;  // points: at most a few MB
    std::vector<std::uint32_t> start_;                          // within its slice's buffer
    std::vector<TextBuffer> slices_;
};

/// The part of the plane a picture shows, in data units: [x0, x1] x [y0, y1], finite,
/// x0 < x1 and y0 < y1.
struct SvgBox {
    double x0 = -1, y0 = -1, x1 = 1, y1 = 1;
};

/// [lo - pad, hi + pad], each end moved by at least one representable step (a pad too
/// small to change a large coordinate still opens the interval) and kept finite.
inline void widen(double& lo, double& hi, double pad) {
    constexpr double max = std::numeric_limits<double>::max();
    const double a = lo - pad, b = hi + pad;
    lo = std::max(a < lo ? a : std::nextafter(lo, -max), -max);
    hi = std::min(b > hi ? b : std::nextafter(hi, max), max);
}

/// `v` if finite, else the largest double (a span of coordinates of opposite signs near
/// the largest double overflows).
inline double finite_span(double v) {
    return std::isfinite(v) ? v : std::numeric_limits<double>::max();
}

/// The picture of the box [xmin, xmax] x [ymin, ymax] (finite, min <= max) as it is, padded
/// only where a side is zero: a zero side becomes as long as the other one (centred); a
/// point gets one unit on every side (2^-20 of its largest coordinate when that is more).
inline SvgBox svg_box(double xmin, double ymin, double xmax, double ymax) {
    SvgBox b{xmin, ymin, xmax, ymax};
    const double w = finite_span(xmax - xmin), h = finite_span(ymax - ymin);
    if (w == 0 && h == 0) {
        const double pad = std::max({1.0, std::abs(xmin) * 0x1p-20, std::abs(ymin) * 0x1p-20});
        widen(b.x0, b.x1, pad);
        widen(b.y0, b.y1, pad);
    } else if (w == 0) {
        widen(b.x0, b.x1, h / 2);
    } else if (h == 0) {
        widen(b.y0, b.y1, w / 2);
    }
    return b;
}

/// The larger side of a picture on screen, in pixels (the width and height attributes).
inline constexpr double svg_screen_size = 1000;

/// The end of a path element.
inline constexpr std::string_view svg_path_end = "\"/>\n";

/// The size of one screen pixel in the data units of a picture of `box` shown at its width
/// and height attributes: stroke widths are written as pixels times this, so that lines
/// and dots have the same size on screen whatever the scale of the data (1e-6 degrees or
/// 1e6 metres). Not vector-effect="non-scaling-stroke": librsvg before 2.56 (Debian 12's
/// 2.54) ignores it, and its strokes then come out in data units, a thousand times too
/// wide or too thin.
inline double svg_pixel(const SvgBox& box) {
    return std::max(finite_span(box.x1 - box.x0), finite_span(box.y1 - box.y0)) / svg_screen_size;
}

/// stroke-width="W" for a width of `pixels` screen pixels in a picture of `box`.
inline NumberWriter& svg_stroke_width(NumberWriter& w, const SvgBox& box, double pixels) {
    return w.text("stroke-width=\"").number(pixels * svg_pixel(box)).text("\"");
}

/// The opening of an SVG picture of `box` in data coordinates: the viewBox is the box
/// (x = x0, y = -y1, since y is flipped), width and height put its larger side at
/// svg_screen_size pixels, and a group flips y (scale(1,-1)) so that the content is
/// written in the data's own coordinates, up being up. Written up to and including that
/// group's opening tag and a newline; the caller writes the content and svg_footer.
inline void svg_header(NumberWriter& w, const SvgBox& box) {
    const double width = finite_span(box.x1 - box.x0), height = finite_span(box.y1 - box.y0);
    const double larger = std::max(width, height);
    const auto pixels = [&](double side) {
        return std::max(1.0, std::round(side / larger * svg_screen_size * 10) / 10);
    };
    w.text(
         "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"")
        .fixed(pixels(width), 1)
        .text("\" height=\"")
        .fixed(pixels(height), 1)
        .text("\" viewBox=\"")
        .number(box.x0)
        .text(" ")
        .number(-box.y1)
        .text(" ")
        .number(width)
        .text(" ")
        .number(height)
        .text("\">\n<g transform=\"scale(1,-1)\">\n");
}

/// Closes what svg_header opened.
inline void svg_footer(NumberWriter& w) { w.text("</g>\n</svg>\n"); }

/// The radius of a point's dot, in screen pixels, with n points in a picture of
/// svg_screen_size pixels: smaller as the points get denser, between 0.5 and 4.
inline double svg_dot_radius(std::size_t n) {
    return std::clamp(svg_screen_size / (4 * std::sqrt(static_cast<double>(n) + 1)), 0.5, 4.0);
}

}  // namespace exidel::io::detail
