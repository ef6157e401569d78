// exidel I/O (internal): small pieces shared by the readers and writers.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string_view>

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

/// The opening of an SVG picture of `width` x `height` units with `margin` around it
/// (the viewBox starts at -margin, -margin), up to and including the closing '>' of the
/// <svg> tag and a newline; the caller writes the content and "</svg>".
inline void svg_header(NumberWriter& w, double width, double height, double margin) {
    w.text(
         "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"")
        .fixed(-margin, 0)
        .text(" ")
        .fixed(-margin, 0)
        .text(" ")
        .fixed(width + 2 * margin, 3)
        .text(" ")
        .fixed(height + 2 * margin, 3)
        .text("\">\n");
}

/// The radius of a point's dot in a picture `size` units wide with n points: smaller as
/// the points get denser, between 0.5 and 4 units.
inline double svg_dot_radius(double size, std::size_t n) {
    return std::clamp(size / (4 * std::sqrt(static_cast<double>(n) + 1)), 0.5, 4.0);
}

}  // namespace exidel::io::detail
