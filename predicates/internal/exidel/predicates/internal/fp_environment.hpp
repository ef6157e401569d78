// exidel (private): run exact code in the floating-point environment it was proven for.
#pragma once

#if defined(__SSE2__)
#include <xmmintrin.h>
#else
#include <cfenv>
#endif

#include "exidel/predicates/types.hpp"

namespace exidel::detail {

// ---- The floating-point environment -----------------------------------------------------
// Every bound assumes round to nearest with gradual underflow. A caller may have changed
// the rounding mode, or linked with -ffast-math, which on x86-64 starts the process with
// flush-to-zero and denormals-are-zero set. Reading MXCSR costs one instruction; when the
// environment is not the standard one, the predicate runs in a standard environment and
// restores the caller's afterwards.
#if defined(__SSE2__)
constexpr unsigned mxcsr_rounding = 0x6000u, mxcsr_ftz = 0x8000u, mxcsr_daz = 0x0040u;
constexpr unsigned mxcsr_nonstandard = mxcsr_rounding | mxcsr_ftz | mxcsr_daz;

inline bool environment_is_standard() { return (_mm_getcsr() & mxcsr_nonstandard) == 0; }

class StandardEnvironment {
public:
    StandardEnvironment() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ & ~mxcsr_nonstandard); }
    ~StandardEnvironment() { _mm_setcsr(saved_); }
    StandardEnvironment(const StandardEnvironment&) = delete;
    StandardEnvironment& operator=(const StandardEnvironment&) = delete;

private:
    unsigned saved_;
};
#else
inline bool environment_is_standard() { return std::fegetround() == FE_TONEAREST; }

class StandardEnvironment {
public:
    StandardEnvironment() : saved_(std::fegetround()) { std::fesetround(FE_TONEAREST); }
    ~StandardEnvironment() { std::fesetround(saved_); }
    StandardEnvironment(const StandardEnvironment&) = delete;
    StandardEnvironment& operator=(const StandardEnvironment&) = delete;

private:
    int saved_;
};
#endif

// Calls `impl` in the standard environment. The call goes through a function that is never
// inlined, so the compiler cannot move its floating-point work across the MXCSR writes.
template <auto Impl, class... Args>
[[gnu::noinline]] Sign call_opaque(Args... args) {
    return Impl(args...);
}

// The arguments are forwarded by reference: by value, the compiler copied the fifteen
// coordinates of insphere's points from the caller's argument area to a frame of its own
// before the filter read them.
template <auto Impl, class... Args>
inline Sign in_standard_environment(const Args&... args) {
    if (environment_is_standard()) [[likely]]
        return Impl(args...);
    const StandardEnvironment guard;
    return call_opaque<Impl>(args...);
}

}  // namespace exidel::detail
