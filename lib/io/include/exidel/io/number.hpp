// exidel I/O: text to double, correctly rounded. The one number parser of the project:
// the point readers and the `exidel predicate` query format both use it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace exidel::io {

/// The result of reading one coordinate: a finite double, or why the text is not one.
struct ParsedNumber {
    std::optional<double> value;
    std::string error;  // empty iff value holds
};

/// Reads the whole of `text` as one finite double: optional sign, then decimal or
/// 0x/0X-prefixed hexadecimal (C99 "%a" syntax), rounded to the nearest double, ties to
/// even. Rejects empty text, trailing characters, "nan"/"inf" in any spelling, and values
/// beyond the largest finite double (which would round to infinity). A nonzero value
/// below the smallest subnormal rounds to zero, as the IEEE rounding of the text
/// prescribes; that is not an error.
ParsedNumber parse_double(std::string_view text);

/// Short, quoted excerpt of `s` for error messages (long garbage is cut at 40 characters
/// so a message stays on one line).
std::string quoted(std::string_view s);

}  // namespace exidel::io
