// exidel: input validation, lexicographic sort and duplicate removal.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "exidel/delaunay/detail/memory.hpp"
#include "exidel/delaunay/detail/radix.hpp"
#include "exidel/delaunay/parallel.hpp"
#include "exidel/delaunay/result.hpp"

namespace exidel::delaunay {

std::string_view to_string(FailureKind kind) noexcept {
    switch (kind) {
        case FailureKind::non_finite_input: return "non_finite_input";
        case FailureKind::too_many_points: return "too_many_points";
        case FailureKind::no_visible_edge: return "no_visible_edge";
        case FailureKind::hull_walk_exceeded: return "hull_walk_exceeded";
        case FailureKind::erosion_inconsistent: return "erosion_inconsistent";
        case FailureKind::erosion_exceeded: return "erosion_exceeded";
        case FailureKind::point_inside_hull: return "point_inside_hull";
        case FailureKind::merge_inconsistent: return "merge_inconsistent";
        case FailureKind::result_inconsistent: return "result_inconsistent";
        case FailureKind::unknown_algorithm: return "unknown_algorithm";
        case FailureKind::location_exceeded: return "location_exceeded";
        case FailureKind::cavity_inconsistent: return "cavity_inconsistent";
        case FailureKind::flips_exceeded: return "flips_exceeded";
        case FailureKind::location_inconsistent: return "location_inconsistent";
        case FailureKind::update_inconsistent: return "update_inconsistent";
        case FailureKind::invalid_segment: return "invalid_segment";
        case FailureKind::too_many_crossings: return "too_many_crossings";
        case FailureKind::constraint_inconsistent: return "constraint_inconsistent";
    }
    return "unknown";
}

std::string_view to_string(Strategy strategy) noexcept {
    switch (strategy) {
        case Strategy::automatic: return "automatic";
        case Strategy::lexicographic: return "lexicographic";
        case Strategy::radial: return "radial";
        case Strategy::strips: return "strips";
    }
    return "unknown";
}

Counters& Counters::operator+=(const Counters& o) noexcept {
#define EXIDEL_DELAUNAY_COUNTER_ADD(name) name += o.name;
    EXIDEL_DELAUNAY_COUNTERS(EXIDEL_DELAUNAY_COUNTER_ADD)
#undef EXIDEL_DELAUNAY_COUNTER_ADD
    return *this;
}

namespace detail {

namespace {

// Decided on the bits, so the answer does not depend on the caller's -ffinite-math-only.
bool finite(double v) noexcept {
    constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
    return (std::bit_cast<std::uint64_t>(v) & exponent) != exponent;
}

constexpr std::uint32_t none = 0xffffffffu;

// One point in the sort: its x as an order key, its input index, and its bucket (a
// monotone function of x, below) or, after the sort, whether it is kept (not a repeat).
struct Record {
    std::uint64_t key;
    std::uint32_t index;
    std::uint32_t bucket;
};

// A non-decreasing map from x to [0, count): each operation rounds monotonically in every
// rounding mode, so x <= x' gives bucket(x) <= bucket(x'), and records sorted by bucket,
// then by x inside each bucket, are sorted by x. The halves keep hi - lo finite for any
// finite data; equal x (signed zeros included) get one bucket. Balance only matters for
// speed: skewed data (one far outlier) fills few buckets, and the sort of a bucket is
// O(m log m) whatever its size.
struct Buckets {
    double lo = 0, scale = 0;
    std::uint32_t count = 1;

    Buckets(double x_lo, double x_hi, std::uint32_t buckets) : lo(x_lo / 2), count(buckets) {
        const double s = count / (x_hi / 2 - lo);
        if (finite(s) && s > 0) scale = s;
    }
    std::uint32_t operator()(double x) const {
        const double t = (x / 2 - lo) * scale;
        if (!(t > 0)) return 0;  // also NaN: 0 * inf cannot occur, scale is finite
        return t >= count - 1 ? count - 1 : static_cast<std::uint32_t>(t);
    }
};

constexpr unsigned digit_bits = 11;
constexpr std::size_t digits = std::size_t{1} << digit_bits;

// One stable pass of an LSD radix sort on the bucket's bits [shift, shift + 11), from
// `from` into `to`, over fixed chunks in parallel: each chunk's records of one digit go
// after those of the earlier chunks, so the pass is stable whatever thread runs which
// chunk. Returns false, writing nothing, when every record has the same digit.
bool radix_pass(std::span<const Record> from, std::span<Record> to, unsigned shift,
                std::size_t chunk, unsigned threads) {
    const std::size_t chunks = (from.size() + chunk - 1) / chunk;
    auto digit = [&](const Record& r) { return (r.bucket >> shift) & (digits - 1); };
    std::vector<std::array<std::uint32_t, digits>> start(chunks);
    parallel_for(chunks, threads, [&](std::size_t c) {
        auto& count = start[c];
        count.fill(0);
        const std::size_t end = std::min(from.size(), (c + 1) * chunk);
        for (std::size_t j = c * chunk; j < end; ++j) ++count[digit(from[j])];
    });
    // One digit everywhere: the pass would copy the records unchanged.
    const std::size_t only = digit(from[0]);
    std::size_t with_only = 0;
    for (std::size_t c = 0; c < chunks; ++c) with_only += start[c][only];
    if (with_only == from.size()) return false;
    std::uint32_t sum = 0;  // digit-major, chunk-minor: the stable positions
    for (std::size_t d = 0; d < digits; ++d) {
        for (std::size_t c = 0; c < chunks; ++c) sum += std::exchange(start[c][d], sum);
    }
    parallel_for(chunks, threads, [&](std::size_t c) {
        auto& next = start[c];
        const std::size_t end = std::min(from.size(), (c + 1) * chunk);
        for (std::size_t j = c * chunk; j < end; ++j) to[next[digit(from[j])]++] = from[j];
    });
    return true;
}

// Sorts one run of records of equal bucket, in input order, by (x, y, input index): a
// strict total order, so the result is the one a stable sort by (x, y) gives. Short runs
// (the usual case, about eight records) by insertion; y is read only for equal x.
void sort_run(std::span<Record> run, std::span<const Point2> input) {
    auto less = [&](const Record& a, const Record& b) {
        if (a.key != b.key) return a.key < b.key;
        const double ya = input[a.index].y, yb = input[b.index].y;
        return ya != yb ? ya < yb : a.index < b.index;
    };
    if (run.size() > 32) {
        std::sort(run.begin(), run.end(), less);
        return;
    }
    for (std::size_t j = 1; j < run.size(); ++j) {
        const Record r = run[j];
        std::size_t k = j;
        for (; k > 0 && less(r, run[k - 1]); --k) run[k] = run[k - 1];
        run[k] = r;
    }
}

}  // namespace

std::optional<Failure> sort_and_dedupe(std::span<const Point2> input, SortedInput& out,
                                       unsigned threads, std::size_t chunk) {
    const std::size_t n = input.size();
    chunk = std::max<std::size_t>(chunk, 1);
    const std::size_t chunks = (n + chunk - 1) / chunk;
    auto chunk_end = [&](std::size_t c) { return std::min(n, (c + 1) * chunk); };

    // Pass 1: the first non-finite coordinate of each chunk, and the range of x.
    struct Scan {
        std::size_t bad;
        double lo, hi;
    };
    std::vector<Scan> scans(chunks);
    parallel_for(chunks, threads, [&](std::size_t c) {
        Scan s{no_index, input[c * chunk].x, input[c * chunk].x};
        for (std::size_t i = c * chunk; i < chunk_end(c); ++i) {
            if (!finite(input[i].x) || !finite(input[i].y)) {
                s.bad = i;
                break;
            }
            s.lo = std::min(s.lo, input[i].x);
            s.hi = std::max(s.hi, input[i].x);
        }
        scans[c] = s;
    });
    double lo = 0, hi = 0;
    for (std::size_t c = 0; c < chunks; ++c) {
        if (scans[c].bad != no_index) {
            const std::size_t i = scans[c].bad;
            return Failure{FailureKind::non_finite_input, i, no_index,
                           "input point " + std::to_string(i) + " has a non-finite coordinate"};
        }
        lo = c == 0 ? scans[c].lo : std::min(lo, scans[c].lo);
        hi = c == 0 ? scans[c].hi : std::max(hi, scans[c].hi);
    }
    if (n > max_points) {
        return Failure{FailureKind::too_many_points, no_index, no_index,
                       std::to_string(n) + " points, at most " + std::to_string(max_points) +
                           " are supported"};
    }

    // Pass 2: records in input order, then a stable LSD radix sort by bucket (about eight
    // points per bucket, at most 2^22 buckets: two passes), then each bucket's run sorted
    // by (x, y, index). Together: the lexicographic order, ties by input index, so the
    // first occurrence of a repeated point comes first.
    const auto buckets = static_cast<std::uint32_t>(std::clamp<std::size_t>(
        std::bit_ceil(std::max<std::size_t>(n / 8, 1)), 1, std::size_t{1} << (2 * digit_bits)));
    const Buckets bucket_of(lo, hi, buckets);
    FreshBuffer<Record> memory(n), spare;
    std::span<Record> records(memory.get(), n);
    parallel_for(chunks, threads, [&](std::size_t c) {
        for (std::size_t i = c * chunk; i < chunk_end(c); ++i) {
            records[i] = {order_key(input[i].x), static_cast<std::uint32_t>(i),
                          bucket_of(input[i].x)};
        }
    });
    if (buckets > 1) {
        spare = FreshBuffer<Record>(n);
        std::span<Record> to(spare.get(), n);
        for (unsigned shift = 0; (std::size_t{1} << shift) < buckets; shift += digit_bits) {
            if (radix_pass(records, to, shift, chunk, threads)) std::swap(records, to);
        }
    }
    // A run belongs to the chunk where it starts; a chunk skips the tail of a run begun
    // in the one before.
    parallel_for(chunks, threads, [&](std::size_t c) {
        std::size_t j = c * chunk;
        while (j > 0 && j < chunk_end(c) && records[j].bucket == records[j - 1].bucket) ++j;
        while (j < chunk_end(c)) {
            std::size_t k = j + 1;
            while (k < n && records[k].bucket == records[j].bucket) ++k;
            sort_run(records.subspan(j, k - j), input);
            j = k;
        }
    });

    // Pass 3: a record is kept unless it repeats the point before it (== treats -0.0 and
    // +0.0 as the same point, as every predicate does). Per chunk: the kept count and the
    // input index of its last kept point, which the next chunks' repeats refer to.
    struct Kept {
        std::size_t count;
        std::uint32_t last;
    };
    std::vector<Kept> kept(chunks);
    parallel_for(chunks, threads, [&](std::size_t c) {
        Kept k{0, none};
        for (std::size_t j = c * chunk; j < chunk_end(c); ++j) {
            // Equal keys are equal x (signed zeros included): only then are the points read.
            const bool keep = j == 0 || records[j].key != records[j - 1].key ||
                              !(input[records[j].index] == input[records[j - 1].index]);
            records[j].bucket = keep;
            if (keep) ++k.count, k.last = records[j].index;
        }
        kept[c] = k;
    });
    std::vector<std::size_t> first_position(chunks + 1, 0);
    std::vector<std::uint32_t> kept_before(chunks, none);
    for (std::size_t c = 0; c < chunks; ++c) {
        first_position[c + 1] = first_position[c] + kept[c].count;
        if (c > 0) kept_before[c] = kept[c - 1].count > 0 ? kept[c - 1].last : kept_before[c - 1];
    }
    const std::size_t distinct = first_position[chunks];
    resize_fresh(out.points, distinct);
    resize_fresh(out.input_of, distinct);
    resize_fresh(out.vertex_of_input, n);
    std::vector<std::vector<std::uint32_t>> repeats(chunks);
    parallel_for(chunks, threads, [&](std::size_t c) {
        std::size_t k = first_position[c];
        std::uint32_t last = kept_before[c];
        for (std::size_t j = c * chunk; j < chunk_end(c); ++j) {
            const std::uint32_t i = records[j].index;
            if (records[j].bucket) {
                out.points[k] = input[i];
                out.input_of[k++] = i;
                out.vertex_of_input[i] = last = i;
            } else {
                out.vertex_of_input[i] = last;
                repeats[c].push_back(i);
            }
        }
    });
    out.duplicates.clear();
    for (const auto& r : repeats) out.duplicates.insert(out.duplicates.end(), r.begin(), r.end());
    std::sort(out.duplicates.begin(), out.duplicates.end());
    return std::nullopt;
}

}  // namespace detail

}  // namespace exidel::delaunay
