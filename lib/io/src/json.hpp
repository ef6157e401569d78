// exidel I/O (internal): a strict cursor over JSON text, enough for the two shapes exidel
// reads (an array of [x, y] pairs; the triangulation object it writes). Tracks the line
// for error messages. Not a general JSON parser: no strings with escapes, no nesting
// beyond what the callers walk themselves.
//
// Why not nlohmann-json (which writes `--stats`): its DOM costs tens of bytes per number
// on files of millions of points, and its SAX events carry no position, so the line of a
// shape error ("a third coordinate") had to be recovered by counting the lexer's reads.
// That version was written and measured (docs/measurements.md): 3.2 times slower on 10^6
// points and more than twice the code of this cursor.
#pragma once

#include <cctype>
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "exidel/io/number.hpp"
#include "exidel/io/points.hpp"

namespace exidel::io::detail {

class JsonCursor {
public:
    explicit JsonCursor(std::string_view text) : s_(text) {}

    void skip_space() {
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == '\n') {
                ++line_;
            } else if (c != ' ' && c != '\t' && c != '\r') {
                break;
            }
            ++i_;
        }
    }
    bool at_end() {
        skip_space();
        return i_ >= s_.size();
    }
    /// The next non-space character, or '\0' at the end.
    char peek() {
        skip_space();
        return i_ < s_.size() ? s_[i_] : '\0';
    }
    void expect(char c, std::string_view context) {
        if (peek() != c)
            fail("expected '" + std::string(1, c) + "' " + std::string(context) + ", found " +
                 found());
        ++i_;
    }
    /// Consumes `c` if it is next.
    bool accept(char c) {
        if (peek() != c) return false;
        ++i_;
        return true;
    }
    /// A JSON number (RFC 8259 grammar), correctly rounded, finite.
    double number(std::string_view what) {
        skip_space();
        const std::size_t start = i_;
        std::size_t j = i_;
        const auto digits = [&] {
            const std::size_t d = j;
            while (j < s_.size() && s_[j] >= '0' && s_[j] <= '9') ++j;
            return j - d;
        };
        if (j < s_.size() && s_[j] == '-') ++j;
        if (j < s_.size() && s_[j] == '0') {
            ++j;
        } else if (digits() == 0) {
            const std::string_view rest = s_.substr(start, 12);
            if (rest.starts_with("NaN") || rest.starts_with("Infinity") ||
                rest.starts_with("-Infinity") || rest.starts_with("nan") ||
                rest.starts_with("inf") || rest.starts_with("-inf")) {
                fail(std::string(what) + ": not a finite number (JSON has no NaN or Infinity)");
            }
            fail("expected a number for " + std::string(what) + ", found " + found());
        }
        if (j < s_.size() && s_[j] == '.') {
            ++j;
            if (digits() == 0) fail(std::string(what) + ": digits must follow '.'");
        }
        if (j < s_.size() && (s_[j] == 'e' || s_[j] == 'E')) {
            ++j;
            if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
            if (digits() == 0) fail(std::string(what) + ": digits must follow the exponent");
        }
        // Letters or digits glued to the number ("1x", "0123") are not JSON.
        if (j < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[j])) || s_[j] == '.')) {
            std::size_t k = j;
            while (k < s_.size() && !std::isspace(static_cast<unsigned char>(s_[k])) &&
                   s_[k] != ',' && s_[k] != ']' && s_[k] != '}')
                ++k;
            fail(std::string(what) + ": " + quoted(s_.substr(start, k - start)) +
                 " is not a JSON number");
        }
        const ParsedNumber n = parse_double(s_.substr(start, j - start));
        if (!n.value) fail(std::string(what) + ": " + n.error);
        i_ = j;
        return *n.value;
    }
    /// A JSON integer in [lo, hi].
    std::int64_t integer(std::string_view what, std::int64_t lo, std::int64_t hi) {
        skip_space();
        const std::size_t start = i_;
        std::size_t j = i_;
        if (j < s_.size() && s_[j] == '-') ++j;
        const std::size_t d = j;
        while (j < s_.size() && s_[j] >= '0' && s_[j] <= '9') ++j;
        if (j == d) fail("expected an integer for " + std::string(what) + ", found " + found());
        std::int64_t v = 0;
        const auto r = std::from_chars(s_.data() + start, s_.data() + j, v);
        if (r.ec != std::errc{} || v < lo || v > hi) {
            fail(std::string(what) + ": " + quoted(s_.substr(start, j - start)) +
                 " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        }
        i_ = j;
        return v;
    }
    /// A JSON string without escapes (enough for the keys exidel writes).
    std::string_view key() {
        expect('"', "to start a key");
        const std::size_t start = i_;
        while (i_ < s_.size() && s_[i_] != '"' && s_[i_] != '\\' && s_[i_] != '\n') ++i_;
        if (i_ >= s_.size() || s_[i_] != '"') fail("unterminated or escaped key");
        return s_.substr(start, i_++ - start);
    }

    /// The line of the cursor (after skipping blanks), counted from 1.
    std::size_t line() {
        skip_space();
        return line_;
    }

    [[noreturn]] void fail(const std::string& reason) const {
        throw ReadError::at_line(line_, reason);
    }
    /// What is at the cursor, for messages.
    std::string found() {
        skip_space();
        if (i_ >= s_.size()) return "the end of the input";
        std::size_t k = i_ + 1;
        while (k < s_.size() && k < i_ + 12 && !std::isspace(static_cast<unsigned char>(s_[k])))
            ++k;
        return quoted(s_.substr(i_, k - i_));
    }

private:
    std::string_view s_;
    std::size_t i_ = 0;
    std::size_t line_ = 1;
};

/// "[[x, y], ...]" appended to `out`; `what` names the array in messages ("points").
inline void point_array(JsonCursor& j, std::vector<Point2>& out, std::string_view what) {
    j.expect('[', "to open the array of " + std::string(what));
    if (j.accept(']')) return;
    do {
        j.expect('[', "to open a point [x, y]");
        const double x = j.number("x");
        if (j.peek() == ']') j.fail("a point is [x, y]: y is missing");
        j.expect(',', "between x and y");
        const double y = j.number("y");
        if (j.peek() == ',') j.fail("a point is [x, y]: found a third coordinate");
        j.expect(']', "to close the point");
        out.push_back({x, y});
    } while (j.accept(','));
    j.expect(']', "or ',' after a point");
}

/// "[i, j, ...]" of integers in [lo, hi], the array named `key` in messages.
template <class T>
std::vector<T> integer_array(JsonCursor& j, std::string_view key, std::int64_t lo,
                             std::int64_t hi) {
    std::vector<T> v;
    j.expect('[', "to open the array \"" + std::string(key) + "\"");
    if (j.accept(']')) return v;
    do {
        v.push_back(static_cast<T>(j.integer(key, lo, hi)));
    } while (j.accept(','));
    j.expect(']', "or ',' in the array \"" + std::string(key) + "\"");
    return v;
}

}  // namespace exidel::io::detail
