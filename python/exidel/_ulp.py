"""Exact steps on the double grid and the Kettner et al. configurations, shared by
exidel.testing (the Hypothesis families) and exidel.research (failure maps): the Python
side of lib/testing's ulp.hpp and generators.hpp."""

import math
import struct

_TOP = 1.7976931348623157e308  # the largest finite double
_SIGN = 1 << 63


def _key(v):
    """The ordered-integer view of a double: consecutive doubles differ by 1; -0.0 and 0.0 are 0."""
    bits = struct.unpack("<Q", struct.pack("<d", v))[0]
    return bits if bits < _SIGN else -(bits - _SIGN)


def _from_key(k):
    return struct.unpack("<d", struct.pack("<Q", k if k >= 0 else _SIGN - k))[0]


_TOP_KEY = _key(_TOP)


def nudge(v, steps):
    """v moved by |steps| representable doubles, up if steps > 0, down if steps < 0, crossing
    zero and the subnormals like any other step and stopping at the largest finite magnitude:
    the C++ testing::nudge (a loop of std::nextafter toward +-DBL_MAX), in one step. As there,
    zero is one step (reached from below it is -0.0, from above 0.0), an infinity moves only
    toward the finite doubles, and NaN stays NaN."""
    v, steps = float(v), int(steps)
    if math.isnan(v) or steps == 0:
        return v
    if math.isinf(v):
        if (v > 0) == (steps > 0):
            return v
        v, steps = math.copysign(_TOP, v), steps - (1 if steps > 0 else -1)
        if steps == 0:
            return v
    k = max(-_TOP_KEY, min(_TOP_KEY, _key(v) + steps))
    if k == 0:
        return -0.0 if steps > 0 else 0.0
    return _from_key(k)


# The three configurations of Kettner, Mehlhorn, Pion, Schirra and Yap (CGTA 2008), as in
# lib/testing/include/exidel/testing/generators.hpp (kettner_configurations).
KETTNER_CONFIGURATIONS = (
    ((0.5, 0.5), (12.0, 12.0), (24.0, 24.0)),
    ((0.50000000000002531, 0.5000000000000171), (17.300000000000001, 17.300000000000001),
     (24.00000000000005, 24.0000000000000517765)),
    ((0.5, 0.5), (8.8000000000000007, 8.8000000000000007), (12.1, 12.1)),
)
