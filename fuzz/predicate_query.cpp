// libFuzzer harness: the query parser of `exidel predicate` (cli/query.cpp) on arbitrary
// bytes, line by line. Every line is blank, a query or an error with a reason; every query
// is evaluated by the adaptive kernel and the GMP reference, which must agree.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "exidel/predicates/all.hpp"
#include "query.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        const exidel::cli::ParsedLine parsed = exidel::cli::parse_query_line(line);
        if (parsed.kind == exidel::cli::ParsedLine::Kind::error) {
            if (parsed.error.empty()) {
                std::fprintf(stderr, "a parse error without a reason\n");
                std::abort();
            }
            continue;
        }
        if (parsed.kind != exidel::cli::ParsedLine::Kind::query) continue;
        const exidel::Sign adaptive = exidel::cli::evaluate(exidel::AdaptiveKernel{}, parsed.query);
        const exidel::Sign exact = exidel::cli::evaluate(exidel::GmpExactKernel{}, parsed.query);
        if (adaptive != exact) {
            std::fprintf(stderr, "adaptive %d, exact %d on: %.*s\n", exidel::to_int(adaptive),
                         exidel::to_int(exact), int(line.size()), line.data());
            std::abort();
        }
    }
    return 0;
}
