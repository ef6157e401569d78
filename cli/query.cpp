// exidel CLI (internal): parsing the `exidel predicate` query format.
#include "query.hpp"

#include <vector>

namespace exidel::cli {

namespace {

constexpr std::string_view blanks = " \t\r\v\f";

using io::quoted;

std::vector<std::string_view> split_blanks(std::string_view s) {
    std::vector<std::string_view> tokens;
    std::size_t i = s.find_first_not_of(blanks);
    while (i != std::string_view::npos) {
        const std::size_t end = s.find_first_of(blanks, i);
        tokens.push_back(s.substr(i, end == std::string_view::npos ? s.size() - i : end - i));
        i = s.find_first_not_of(blanks, end);
    }
    return tokens;
}

}  // namespace

ParsedLine parse_query_line(std::string_view line) {
    ParsedLine out;
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    const std::vector<std::string_view> tokens = split_blanks(line);
    if (tokens.empty()) return out;

    const auto fail = [&out](std::string message) {
        out.kind = ParsedLine::Kind::error;
        out.error = std::move(message);
        return out;
    };
    if (const std::optional<SpacePredicate> space = space_predicate_from_name(tokens[0])) {
        const std::size_t expected = 3 * point_count(*space);
        if (tokens.size() - 1 != expected) {
            return fail(std::string(tokens[0]) + " takes " + std::to_string(expected) +
                        " coordinates, got " + std::to_string(tokens.size() - 1));
        }
        out.query.space = *space;
        for (std::size_t i = 0; i < expected; ++i) {
            ParsedNumber n = parse_double(tokens[i + 1]);
            if (!n.value) return fail("coordinate " + std::to_string(i + 1) + ": " + n.error);
            Point3& p = out.query.points3[i / 3];
            (i % 3 == 0 ? p.x : i % 3 == 1 ? p.y : p.z) = *n.value;
        }
        out.kind = ParsedLine::Kind::query;
        return out;
    }
    const std::optional<Predicate> predicate = predicate_from_name(tokens[0]);
    if (!predicate) {
        return fail("unknown predicate " + quoted(tokens[0]) +
                    " (expected orient2d, incircle, incircle_cosine, compare_distance, "
                    "orient3d or insphere)");
    }
    const std::size_t expected = 2 * point_count(*predicate);
    if (tokens.size() - 1 != expected) {
        return fail(std::string(predicate_name(*predicate)) + " takes " + std::to_string(expected) +
                    " coordinates, got " + std::to_string(tokens.size() - 1));
    }
    out.query.predicate = *predicate;
    for (std::size_t i = 0; i < expected; ++i) {
        ParsedNumber n = parse_double(tokens[i + 1]);
        if (!n.value) return fail("coordinate " + std::to_string(i + 1) + ": " + n.error);
        Point2& p = out.query.points[i / 2];
        (i % 2 == 0 ? p.x : p.y) = *n.value;
    }
    out.kind = ParsedLine::Kind::query;
    return out;
}

}  // namespace exidel::cli
