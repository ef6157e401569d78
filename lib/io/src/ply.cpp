// exidel I/O: the PLY writer of triangulations (format: exidel/io/triangulation.hpp).
#include <bit>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <span>
#include <utility>
#include <vector>

#include "text.hpp"
#include "writers.hpp"

namespace exidel::io::detail {

namespace {

// Appends the little-endian bytes of `v` to `bytes`.
template <class T>
void put_le(std::vector<char>& bytes, T v) {
    char raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) {
        for (std::size_t k = 0; k < sizeof(T) / 2; ++k) std::swap(raw[k], raw[sizeof(T) - 1 - k]);
    }
    bytes.insert(bytes.end(), raw, raw + sizeof(T));
}

}  // namespace

void write_triangulation_ply(std::ostream& out, std::span<const Point2> points,
                             const delaunay::Triangulation& tri, std::span<const double> z,
                             bool binary) {
    const std::size_t n = tri.triangle_count();
    {
        NumberWriter w(out);
        w.text("ply\nformat ")
            .text(binary ? "binary_little_endian" : "ascii")
            .text(
                " 1.0\ncomment exidel triangulation: vertices are the input points in input "
                "order\nelement vertex ")
            .number(static_cast<std::uint64_t>(points.size()))
            .text("\nproperty double x\nproperty double y\nproperty double z\nelement face ")
            .number(static_cast<std::uint64_t>(n))
            .text("\nproperty list uchar int vertex_indices\nend_header\n");
        if (!binary) {
            for (std::size_t i = 0; i < points.size(); ++i) {
                w.number(points[i].x).text(" ").number(points[i].y).text(" ");
                w.number(z.empty() ? 0.0 : z[i]).text("\n");
            }
            for (std::size_t t = 0; t < n; ++t) {
                w.text("3");
                for (std::size_t k = 0; k < 3; ++k) {
                    w.text(" ").number(static_cast<std::uint64_t>(tri.triangles[3 * t + k]));
                }
                w.text("\n");
            }
            return;
        }
    }
    // Binary: in blocks of about 1 MB.
    std::vector<char> bytes;
    constexpr std::size_t block = 1 << 20;
    bytes.reserve(block + 64);
    const auto flush = [&](bool always) {
        if (always || bytes.size() >= block) {
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
            bytes.clear();
        }
    };
    for (std::size_t i = 0; i < points.size(); ++i) {
        put_le(bytes, points[i].x);
        put_le(bytes, points[i].y);
        put_le(bytes, z.empty() ? 0.0 : z[i]);
        flush(false);
    }
    for (std::size_t t = 0; t < n; ++t) {
        bytes.push_back(3);
        for (std::size_t k = 0; k < 3; ++k) {
            put_le(bytes, static_cast<std::int32_t>(tri.triangles[3 * t + k]));
        }
        flush(false);
    }
    flush(true);
}

}  // namespace exidel::io::detail
