// exidel CLI (internal): the text format of `exidel predicate`, parsed without I/O.
//
// One query per line:
//   orient2d        ax ay bx by cx cy
//   incircle        ax ay bx by cx cy dx dy
//   incircle_cosine ax ay bx by cx cy dx dy
//   compare_distance cx cy px py qx qy     (sign of |p - c|^2 - |q - c|^2)
//   orient3d        ax ay az bx by bz cx cy cz dx dy dz
//   insphere        ax ay az bx by bz cx cy cz dx dy dz ex ey ez
// Tokens are separated by blanks (space, tab, CR, VT, FF). Everything from the first '#'
// to the end of the line is a comment; a line that is blank after removing the comment
// holds no query. Coordinates are decimal ("0.1", "-1e-300") or C99 hexadecimal floats
// ("0x1.8p-3", "-0X1P+4"), rounded to the nearest double (ties to even).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "exidel/io/number.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/predicate.hpp"
#include "exidel/predicates/types.hpp"

namespace exidel::cli {

struct Query {
    Predicate predicate = Predicate::orient2d;
    std::array<Point2, 4> points{};       // only the first point_count(predicate) are used
    std::optional<SpacePredicate> space;  // set for orient3d and insphere, which use:
    std::array<Point3, 5> points3{};      // the first 4 (orient3d) or all 5 (insphere)
};

// The coordinate parser lives in lib/io (one implementation for every reader of numbers).
using io::ParsedNumber;
using io::parse_double;

/// What one line of input holds.
struct ParsedLine {
    enum class Kind { blank, query, error };
    Kind kind = Kind::blank;
    Query query;
    std::string error;  // set iff kind == error; does not include the line number
};

ParsedLine parse_query_line(std::string_view line);

/// Evaluates a parsed query with kernel `k` (every shipped kernel has the 3D predicates).
template <PredicateKernel3D K>
Sign evaluate(const K& k, const Query& q) {
    if (q.space) {
        return exidel::evaluate(k, *q.space, q.points3);
    }
    return exidel::evaluate(k, q.predicate, q.points);
}

}  // namespace exidel::cli
