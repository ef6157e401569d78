// exidel CLI (internal): what a command was doing when memory ran out, so that main()
// can say "not enough memory for N points (needs about M MB)" instead of
// "std::bad_alloc". The commands record their step and its size as they go; main()
// reads it when a std::bad_alloc reaches it (the pending output files are removed on the
// way, by their destructors).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace exidel::cli {

/// Peak resident memory of `exidel triangulate` per input point, in bytes: the estimate
/// of the message, not a limit. Measured: 118 MB at 10^6 and 441 MB at 4 * 10^6 uniform
/// points (f64 input, OFF output, 1 or 2 threads alike; `/usr/bin/time -f %M exidel
/// triangulate u.f64 -o out.off`), 108 bytes a point beyond 10 MB, rounded up.
inline constexpr double triangulate_bytes_per_point = 110;

/// Records the current step: `what` (e.g. "triangulating"), on `points` points, needing
/// about `bytes` in all. Called from the main thread only.
void note_memory_need(std::string_view what, std::size_t points, double bytes);

/// "not enough memory for triangulating 1000000 points (needs about 110 MB)", or "not
/// enough memory" before any step was recorded.
std::string out_of_memory_message();

}  // namespace exidel::cli
