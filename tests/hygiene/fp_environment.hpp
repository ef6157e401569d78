// exidel hygiene tests: reading and setting the floating-point environment, including the
// x86 SSE control bits that <cfenv> does not reach: flush-to-zero (FTZ: subnormal results
// become 0) and denormals-are-zero (DAZ: subnormal operands are read as 0). Linking with
// -ffast-math turns both on before main() (GCC's crtfastmath.o).
#pragma once

#include <cfenv>

#if defined(__SSE2__) || defined(_M_X64)
#include <xmmintrin.h>
#define EXIDEL_HYGIENE_HAVE_MXCSR 1
#else
#define EXIDEL_HYGIENE_HAVE_MXCSR 0
#endif

namespace exidel::hygiene {

inline constexpr unsigned mxcsr_ftz = 0x8000;
inline constexpr unsigned mxcsr_daz = 0x0040;
inline constexpr unsigned mxcsr_rounding = 0x6000;
// Everything but the six sticky exception flags: what a kernel must leave as it found it.
inline constexpr unsigned mxcsr_controls = 0xffc0;

inline unsigned read_mxcsr() {
#if EXIDEL_HYGIENE_HAVE_MXCSR
    return _mm_getcsr();
#else
    return 0;
#endif
}

inline void write_mxcsr(unsigned value) {
#if EXIDEL_HYGIENE_HAVE_MXCSR
    _mm_setcsr(value);
#else
    (void)value;
#endif
}

inline bool ftz_or_daz_on() { return (read_mxcsr() & (mxcsr_ftz | mxcsr_daz)) != 0; }

/// The controls a kernel call could disturb: the C rounding mode and the SSE control bits.
struct FpControls {
    int rounding;
    unsigned mxcsr;
    friend bool operator==(const FpControls&, const FpControls&) = default;
};

inline FpControls current_controls() { return {std::fegetround(), read_mxcsr() & mxcsr_controls}; }

/// Sets a rounding mode and, on x86, the FTZ/DAZ bits given in `ftz_daz` (others cleared).
inline void set_controls(int rounding, unsigned ftz_daz) {
    std::fesetround(rounding);  // also sets the MXCSR rounding bits
    write_mxcsr((read_mxcsr() & ~(mxcsr_ftz | mxcsr_daz)) | ftz_daz);
}

/// A non-default environment a caller can leave behind: a rounding mode and, on x86, the
/// FTZ/DAZ bits (for set_controls).
struct Environment {
    const char* name;
    int rounding;
    unsigned ftz_daz;
};

/// Every one the hygiene tests try.
inline constexpr Environment environments[] = {
    {"upward", FE_UPWARD, 0},
    {"downward", FE_DOWNWARD, 0},
    {"toward-zero", FE_TOWARDZERO, 0},
#if EXIDEL_HYGIENE_HAVE_MXCSR
    {"ftz+daz", FE_TONEAREST, mxcsr_ftz | mxcsr_daz},
    {"ftz", FE_TONEAREST, mxcsr_ftz},
    {"daz", FE_TONEAREST, mxcsr_daz},
    {"ftz+daz+upward", FE_UPWARD, mxcsr_ftz | mxcsr_daz},
    {"ftz+daz+toward-zero", FE_TOWARDZERO, mxcsr_ftz | mxcsr_daz},
#endif
};

/// Runs f() in the IEEE default environment (round to nearest, no FTZ/DAZ) and restores
/// whatever was set before: the reference answers are computed here.
template <class F>
auto in_default_environment(F f) {
    const FpControls saved = current_controls();
    set_controls(FE_TONEAREST, 0);
    auto result = f();
    std::fesetround(saved.rounding);
    write_mxcsr((read_mxcsr() & ~mxcsr_controls) | saved.mxcsr);
    return result;
}

}  // namespace exidel::hygiene
