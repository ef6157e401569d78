// libFuzzer harness: the constraint readers (exidel/io/constraints.hpp: Triangle's .poly,
// GeoJSON, JSON {"points", "segments", "holes"}) on the same arbitrary bytes. Each reader
// either returns a file whose coordinates are all finite, whose segments name its
// points and whose markers, when present, number one per segment, or throws io::ReadError
// naming the line; anything else (a crash, another exception, a sanitizer report, a hang)
// is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "exidel/io/points.hpp"
#include "exidel/io/constraints.hpp"

namespace {
[[noreturn]] void finding(const char* what) {
    std::fprintf(stderr, "constraint reader: %s\n", what);
    std::abort();
}
bool finite(exidel::Point2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void check(const exidel::io::ConstraintFile& p) {
    for (const exidel::Point2& q : p.points)
        if (!finite(q)) finding("a non-finite point");
    for (const auto& [a, b] : p.segments)
        if (a >= p.points.size() || b >= p.points.size()) finding("a segment names no point");
    if (!p.segment_markers.empty() && p.segment_markers.size() != p.segments.size())
        finding("markers do not number one per segment");
    if (!p.z.empty() && p.z.size() != p.points.size()) finding("z does not number one per point");
    for (const double z : p.z)
        if (!std::isfinite(z)) finding("a non-finite z");
    for (const exidel::Point2& q : p.holes)
        if (!finite(q)) finding("a non-finite hole");
    for (const auto& r : p.regions)
        if (!finite(r.seed) || !std::isfinite(r.attribute) ||
            (r.max_area && !(*r.max_area > 0 && std::isfinite(*r.max_area))))
            finding("a region that is not finite");
    if (p.index_base > 1) finding("an index base other than 0 or 1");
}

template <class Parse>
void run(Parse parse, std::string_view bytes) {
    try {
        check(parse(bytes));
    } catch (const exidel::io::ReadError& e) {
        if (std::string(e.what()).find("line ") == std::string::npos)
            finding("a ReadError that names no line");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    run(exidel::io::parse_poly, bytes);
    run(exidel::io::parse_geojson_constraints, bytes);
    run(exidel::io::parse_json_constraints, bytes);
    return 0;
}
