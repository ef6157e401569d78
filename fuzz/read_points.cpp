// libFuzzer harness: a point reader of lib/io on arbitrary bytes. Built once per format
// (EXIDEL_FUZZ_FORMAT: xy, json, node, f64, geojson). The reader either returns points, every one
// finite, or throws io::ReadError naming where the input went wrong; anything else (a
// crash, another exception, a sanitizer report, a hang) is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "exidel/io/points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    std::istringstream in(bytes);
    try {
        const std::vector<exidel::Point2> points =
            exidel::io::read_points(in, exidel::io::PointFormat::EXIDEL_FUZZ_FORMAT);
        for (const exidel::Point2& p : points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
                std::fprintf(stderr, "read_points returned a non-finite point\n");
                std::abort();
            }
        }
    } catch (const exidel::io::ReadError& e) {
        // Expected for malformed input; the message must say where.
        const std::string what = e.what();
        if (what.find("line ") == std::string::npos &&
            what.find("byte offset ") == std::string::npos) {
            std::fprintf(stderr, "a ReadError that names no line or offset: %s\n", e.what());
            std::abort();
        }
    }
    return 0;
}
