// exidel I/O: the correctly rounded number parser.
#include "exidel/io/number.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <system_error>

namespace exidel::io {

namespace {

bool starts_with_ci(std::string_view s, std::string_view prefix) {
    if (s.size() < prefix.size()) return false;
    return std::equal(prefix.begin(), prefix.end(), s.begin(), [](char p, char c) {
        return p == std::tolower(static_cast<unsigned char>(c));
    });
}

}  // namespace

std::string quoted(std::string_view s) {
    constexpr std::size_t limit = 40;
    std::string q = "'";
    q += s.substr(0, limit);
    if (s.size() > limit) q += "...";
    q += "'";
    return q;
}

ParsedNumber parse_double(std::string_view text) {
    if (text.empty()) return {std::nullopt, "empty coordinate"};
    // std::from_chars takes neither a '+' sign nor a "0x" prefix (and with chars_format::hex
    // it would parse "0x1p3" as 0), so both are stripped here and the sign reapplied.
    std::string_view s = text;
    bool negative = false;
    if (s.front() == '+' || s.front() == '-') {
        negative = s.front() == '-';
        s.remove_prefix(1);
    }
    const bool hex = s.size() >= 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    if (hex) s.remove_prefix(2);
    const char first = s.empty() ? '\0' : static_cast<char>(s.front() | 0x20);  // lower case
    if ((first == 'n' || first == 'i') && (starts_with_ci(s, "nan") || starts_with_ci(s, "inf"))) {
        return {std::nullopt, quoted(text) + " is not a finite number"};
    }
    // After sign and prefix a number starts with a digit or a point; this also refuses a
    // second sign, which from_chars would otherwise accept ("--1", "0x-1").
    const auto digit = [hex](unsigned char c) { return hex ? std::isxdigit(c) : std::isdigit(c); };
    if (s.empty() || !(digit(static_cast<unsigned char>(s.front())) || s.front() == '.')) {
        return {std::nullopt, quoted(text) + " is not a number"};
    }
    double v = 0;
    const auto [end, ec] =
        std::from_chars(s.data(), s.data() + s.size(), v,
                        hex ? std::chars_format::hex : std::chars_format::general);
    if (ec == std::errc::invalid_argument) return {std::nullopt, quoted(text) + " is not a number"};
    if (end != s.data() + s.size()) {
        return {std::nullopt, quoted(text) + " is not a number (trailing characters " +
                                  quoted(std::string_view(end, s.data() + s.size() - end)) + ")"};
    }
    if (ec == std::errc::result_out_of_range) {
        // libstdc++ reports both overflow and underflow this way and leaves v unset.
        // strtod (correctly rounded in glibc, "C" locale since exidel never calls
        // setlocale) tells them apart: infinity for overflow, the rounded value otherwise.
        const std::string copy(text);
        const double r = std::strtod(copy.c_str(), nullptr);
        if (std::isinf(r)) {
            return {std::nullopt, quoted(text) + " is outside the range of finite doubles"};
        }
        return {r, {}};
    }
    return {negative ? -v : v, {}};
}

}  // namespace exidel::io
