// libFuzzer harness: sequences of insertions and removals on a MutableTriangulation,
// decoded from arbitrary bytes.
//   - The adaptive kernel (exact): no operation fails; a non-finite point is refused with
//     non_finite_input and changes nothing; halfway and at the end the live points'
//     triangulation is certified Delaunay.
//   - The double kernel (inexact): the same operations; a FailureError (then a
//     std::logic_error for every later change) is allowed, a crash, a sanitizer report or
//     a hang is not.
// Decoding: the first byte's low two bits choose the points, as in triangulate.cpp: 0 raw
// float64 pairs (16 bytes per point; NaN and infinities included); 1 pairs of signed bytes,
// a small grid full of collinear, cocircular and repeated points; 2 that grid scaled by
// 2^k (k from the second byte); 3 the grid nudged by an ulp per coordinate (bits of the
// third byte). Then operations, each one byte: an even byte inserts the next point, an odd
// byte b removes the live id at position (b >> 1) modulo their count.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "exidel/delaunay/certify.hpp"
#include "exidel/delaunay/mutable_triangulation.hpp"
#include "exidel/predicates/all.hpp"

#include "decode.hpp"

namespace {

using exidel::Point2;
namespace delaunay = exidel::delaunay;

// The kernels as types of the harness's own, so that triangulate() (the constructor from
// points, unused here) and everything else is instantiated here for them only.
struct Adaptive : exidel::AdaptiveKernel {};
struct Double : exidel::DoubleKernel {};

struct Operation {
    bool insert = true;
    Point2 point{};
    unsigned which = 0;  // removal: position among the live ids
};

std::vector<Operation> decode(const std::uint8_t* data, std::size_t size) {
    std::vector<Operation> ops;
    if (size == 0) return ops;
    const exidel::fuzz::Header h = exidel::fuzz::read_header(data, size);
    std::size_t i = 0;
    unsigned bit = 0;
    while (i < size) {
        const std::uint8_t op = data[i++];
        if (op & 1u) {
            ops.push_back({false, {}, unsigned(op >> 1)});
            continue;
        }
        Point2 p;
        if (h.mode == 0) {
            if (i + 16 > size) break;
            p = exidel::fuzz::raw_point(data + i);
            i += 16;
        } else {
            if (i + 2 > size) break;
            p = exidel::fuzz::grid_point(h, data[i], data[i + 1], bit);
            i += 2;
            if (h.mode == 3) bit = (bit + 1) % 8;
        }
        ops.push_back({true, p, 0});
    }
    return ops;
}

[[noreturn]] void finding(const char* what, std::size_t step) {
    std::fprintf(stderr, "%s (operation %zu)\n", what, step);
    std::abort();
}

template <class K>
void run(const std::vector<Operation>& ops, bool exact) {
    delaunay::MutableTriangulation<K> m;
    std::vector<std::uint32_t> live;
    for (std::size_t step = 0; step < ops.size(); ++step) {
        const Operation& op = ops[step];
        try {
            if (op.insert) {
                const bool finite = std::isfinite(op.point.x) && std::isfinite(op.point.y);
                try {
                    live.push_back(m.insert(op.point));
                    if (!finite) finding("a non-finite point was inserted", step);
                } catch (const delaunay::FailureError& e) {
                    if (finite && exact) finding("an exact insertion failed", step);
                    if (!finite && e.failure.kind != delaunay::FailureKind::non_finite_input) {
                        finding("a non-finite point failed otherwise", step);
                    }
                    if (finite) return;  // the double kernel's inconsistency: done
                }
            } else if (!live.empty()) {
                const std::size_t i = op.which % live.size();
                m.remove(live[i]);
                live[i] = live.back();
                live.pop_back();
            }
        } catch (const delaunay::FailureError&) {
            if (exact) finding("an exact removal failed", step);
            return;
        }
        if (m.size() != live.size()) finding("the live count is wrong", step);
        if (exact && (step == ops.size() / 2 || step + 1 == ops.size())) {
            const auto s = m.snapshot();
            if (!delaunay::certify(s.points, s.triangulation).ok()) {
                finding("the state does not certify", step);
            }
        }
    }
    if (!exact) {
        try {
            (void)m.snapshot();
        } catch (const delaunay::FailureError&) {}
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<Operation> ops = decode(data, size);
    run<Adaptive>(ops, true);
    run<Double>(ops, false);
    return 0;
}
