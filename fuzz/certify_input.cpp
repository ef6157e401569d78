// libFuzzer harness: `exidel certify` on arbitrary bytes. The first byte picks the format
// (json, ele, off, simplices: its value mod 4); the rest is the file. The points are a
// fixed 4 x 4 grid with repeats, so every format can name real vertices. Reading either
// gives a ProducedTriangulation or throws io::ReadError naming a line; normalize and
// certify then run on anything read, with every index however wrong, and must return a
// certificate: a crash, another exception, a sanitizer report or a hang is a finding, and
// so is a certificate that is ok() with findings or not ok() without.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "exidel/delaunay/certify.hpp"
#include "exidel/io/triangulation_input.hpp"

namespace {

std::vector<exidel::Point2> grid_with_repeats() {
    std::vector<exidel::Point2> p;
    for (int x = 0; x < 4; ++x) {
        for (int y = 0; y < 4; ++y) p.push_back({double(x), double(y)});
    }
    p.push_back(p[5]);
    p.push_back(p[0]);
    return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace exidel;
    if (size == 0) return 0;
    static const std::vector<Point2> points = grid_with_repeats();
    constexpr io::ProducedFormat formats[] = {io::ProducedFormat::json, io::ProducedFormat::ele,
                                              io::ProducedFormat::off,
                                              io::ProducedFormat::simplices};
    const io::ProducedFormat format = formats[data[0] % 4];
    const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
    delaunay::ProducedTriangulation produced;
    try {
        produced = io::read_produced(text, format, points);
    } catch (const io::ReadError& e) {
        if (std::string(e.what()).find("line ") == std::string::npos) {
            std::fprintf(stderr, "a ReadError that names no line: %s\n", e.what());
            std::abort();
        }
        return 0;
    }
    for (const bool strict : {false, true}) {
        const delaunay::Triangulation t = delaunay::normalize(points, produced, nullptr, strict);
        const delaunay::Certificate c = delaunay::certify(
            points, t, delaunay::CertifyOptions{std::numeric_limits<std::size_t>::max()});
        if (c.ok() != c.findings.empty() || c.findings.size() != c.total_findings) {
            std::fprintf(stderr, "certificate: ok %d with %zu of %zu findings\n", int(c.ok()),
                         c.findings.size(), c.total_findings);
            std::abort();
        }
    }
    return 0;
}
