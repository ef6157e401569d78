"""exidel.testing: the point families of exidel's own tests, as Hypothesis strategies.

    points(family, n)    n points of one family: an (n, 2) float64 numpy array
    query3(family)       an orient2d / compare_distance query: a (3, 2) array
    query4(family)       an incircle query: a (4, 2) array
    FAMILIES, families() the 13 families in exidel's order, with their near_degenerate flag

The families are those of the C++ generators (lib/testing, RapidCheck), drawn the same way:
integers first, then an exact construction (integer translation, scaling by 2^k, Gaussian
integers, steps of one ulp), so a structure holds exactly, not up to rounding (the near_
families then leave it on purpose, by a few ulps):

    uniform              points uniform in [-1, 1]^2 on the grid 2^-53: the easy case
    uniform_scaled       the same in one box [-2^k, 2^k]^2, k from -1074 (subnormals) to 1023
    wide_exponents       every coordinate any finite double, at its own exponent
    integer_grid         points of a small integer grid (|x|, |y| <= 8), moved and scaled by 2^k
    lattice_circle       integer points of one circle (radius 5 up to 48612265): all cocircular
    dyadic_line          points of one line of slope p / 2^q (or its mirror): all collinear
    near_integer_grid    integer_grid with every coordinate moved by up to 4 ulps
    near_lattice_circle  lattice_circle with every coordinate moved by up to 4 ulps
    near_dyadic_line     dyadic_line with every coordinate moved by up to 4 ulps
    near_rounded_line    points p + t (q - p) rounded once (fma), then moved by up to 4 ulps
    near_rounded_circle  points c + R (cos, sin) rounded once, moved by up to 4 ulps, scaled
    kettner              the three configurations of Kettner et al., p over their ulp window
    duplicates           points of another family, some of them repeated

Every choice shrinks toward the degenerate configuration: ulp offsets toward none, scales
toward 2^0, translations toward 0, lattice points toward the axis points (r, 0), (0, r), ...,
repeats toward copies of the first point. A failing property therefore shrinks to an exactly
degenerate input, or to the fewest ulps away from one that still fails. Wide integer ranges
(significands, translations) are drawn uniformly, as RapidCheck does at full size, rather
than with Hypothesis's preference for small integers.

A test of your own orientation function against exidel's exact one:

    import numpy as np, exidel
    from hypothesis import given
    from exidel.testing import query3

    def my_orient2d(a, b, c):
        return np.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))

    @given(query3("near_rounded_line"))
    def test_my_orient2d(q):
        a, b, c = q
        assert my_orient2d(a, b, c) == exidel.orient2d(a, b, c, kernel="exact")

Hypothesis finds a counterexample within a few dozen examples and shrinks it to a query a
few ulps from a degenerate one, e.g. (0, 0), (0, 5e-324), (5e-324, 0), where the products
underflow to 0 but the orientation is negative. Requires hypothesis (`import exidel` alone
does not).
"""

from __future__ import annotations

import math
import struct
from fractions import Fraction
from typing import NamedTuple

import numpy as np
from hypothesis import strategies as st

__all__ = ["FAMILIES", "Family", "families", "points", "query3", "query4", "nudge", "dyadic",
           "lattice_circle_radius", "lattice_circle_point", "KETTNER_CONFIGURATIONS"]


class Family(NamedTuple):
    name: str
    #: True for the families built to sit within a few ulps of a degeneracy (but not on it):
    #: where a non-robust kernel is expected to fail.
    near_degenerate: bool


#: Every family, in the order of the C++ all_families() (names are stable).
FAMILIES = (
    Family("uniform", False),
    Family("uniform_scaled", False),
    Family("wide_exponents", False),
    Family("integer_grid", False),
    Family("lattice_circle", False),
    Family("dyadic_line", False),
    Family("near_integer_grid", True),
    Family("near_lattice_circle", True),
    Family("near_dyadic_line", True),
    Family("near_rounded_line", True),
    Family("near_rounded_circle", True),
    Family("kettner", True),
    Family("duplicates", False),
)


def families(near_degenerate=None):
    """The families (FAMILIES), or only those whose near_degenerate flag is the given one."""
    return [f for f in FAMILIES if near_degenerate is None or f.near_degenerate == near_degenerate]


# ---------------------------------------------------------------------------------------
# Exact moves on the double grid (ulp.hpp, lattice.hpp).

from ._ulp import KETTNER_CONFIGURATIONS, _key, nudge  # noqa: E402,F401  (public here too)


def dyadic(m, k):
    """The integer m times 2^k, rounded once (exact when |m| <= 2^53 and no bit falls below
    the subnormal grid 2^-1074)."""
    return math.ldexp(float(m), k)


def _fma_exact(a, b, c):
    exact = Fraction(a) * Fraction(b) + Fraction(c)
    if exact:
        return float(exact)  # int / int: correctly rounded, subnormals included
    if (a == 0 or b == 0) and c == 0:  # IEEE 754: -0 only for (-0) + (-0)
        product_negative = (math.copysign(1.0, a) < 0) != (math.copysign(1.0, b) < 0)
        return -0.0 if product_negative and math.copysign(1.0, c) < 0 else 0.0
    return 0.0


#: a * b + c rounded once (std::fma; math.fma exists from Python 3.13).
_fma = getattr(math, "fma", _fma_exact)

# The Gaussian primes of lattice.hpp: p = a^2 + b^2, the first primes p = 1 mod 4.
_GAUSSIAN_PRIMES = ((5, 1, 2), (13, 2, 3), (17, 1, 4), (29, 2, 5), (37, 1, 6), (41, 4, 5))


def lattice_circle_radius(primes):
    """The radius of the lattice circle of the first `primes` primes (1..6): 5, 65, 1105,
    32045, 1185665, 48612265. Its circle holds 4 * 3^primes integer points."""
    if not 1 <= primes <= len(_GAUSSIAN_PRIMES):
        raise ValueError("lattice_circle_radius: primes must be in [1, 6]")
    return math.prod(p for p, _, _ in _GAUSSIAN_PRIMES[:primes])


def lattice_circle_point(choices, unit):
    """The integer point (x, y) on the circle of radius lattice_circle_radius(len(choices)):
    the Gaussian integer i^unit times, per prime, p (choice 0), pi^2 (1) or conj(pi)^2 (2).
    All choices 0 give the axis points (r, 0), (0, r), (-r, 0), (0, -r)."""
    if not 1 <= len(choices) <= len(_GAUSSIAN_PRIMES):
        raise ValueError("lattice_circle_point: between 1 and 6 choices")
    x, y = 1, 0
    for choice, (p, a, b) in zip(choices, _GAUSSIAN_PRIMES):
        if choice not in (0, 1, 2):
            raise ValueError("lattice_circle_point: choice not in {0, 1, 2}")
        re, im = (p, 0) if choice == 0 else (a * a - b * b, 2 * a * b * (1 if choice == 1 else -1))
        x, y = x * re - y * im, x * im + y * re
    for _ in range(unit % 4):
        x, y = -y, x
    return x, y


# ---------------------------------------------------------------------------------------
# Drawing integers. Each helper takes Hypothesis's `draw` (of st.composite) and shrinks
# toward its lower bound (toward 0 for _toward_zero), like RapidCheck's inRange.


def _in_range(draw, lo, hi):
    """An integer in [lo, hi], uniform, shrinking toward lo (RapidCheck's inRange(lo, hi + 1)).
    Hypothesis draws wide ranges mostly from their low 8 to 32 bits; here ranges beyond 2^24
    are drawn 24 bits at a time, most significant first, so they stay uniform (but for the
    few percent of draws that Hypothesis forces onto a bound)."""
    span = hi - lo
    if span < 1 << 24:
        return lo + draw(st.integers(0, span))
    low_bits = span.bit_length() - 24
    high = draw(st.integers(0, span >> low_bits))
    low = _in_range(draw, 0, (1 << low_bits) - 1)
    return lo + min((high << low_bits) | low, span)


def _toward_zero(draw, lo, hi):
    """An integer in [lo, hi] (lo <= 0 <= hi) shrinking toward 0 from either side:
    a sign (shrinking toward +), then a magnitude (toward 0), as gen_toward_zero."""
    negative = lo < 0 and (hi == 0 or draw(st.booleans()))
    return -_in_range(draw, 0, -lo) if negative else _in_range(draw, 0, hi)


_ONE = 1 << 53
_MIN_EXACT_SCALE = -1074  # n * 2^k is exact for every integer n when k >= this


def _max_scale_for_bits(bits):
    """Largest k for which n * 2^k is finite for every |n| < 2^bits."""
    return 1024 - bits


def _point_in_box(draw, k):
    """A point uniform in [-2^k, 2^k]^2 on the grid 2^(k-53) (rounded once below 2^-1074)."""
    mx = _toward_zero(draw, -_ONE, _ONE)
    my = _toward_zero(draw, -_ONE, _ONE)
    return dyadic(mx, k - 53), dyadic(my, k - 53)


def _any_finite_double(draw):
    """A 53-bit significand at any exponent: from 2^-1074 up to 2^1024 - 2^971."""
    m = _toward_zero(draw, -(_ONE - 1), _ONE - 1)
    k = _toward_zero(draw, -1074, 1023)
    return dyadic(m, k - 52)


def _nudged(draw, pts, max_steps=4):
    """Each coordinate of each point moved by up to max_steps ulps, shrinking toward none."""
    out = []
    for x, y in pts:
        dx = _toward_zero(draw, -max_steps, max_steps)
        dy = _toward_zero(draw, -max_steps, max_steps)
        out.append((nudge(x, dx), nudge(y, dy)))
    return out


def _place(ints, t, k):
    """Integer points translated by the integer vector t and scaled by 2^k, exactly."""
    return [(dyadic(x + t[0], k), dyadic(y + t[1], k)) for x, y in ints]


# ---------------------------------------------------------------------------------------
# The families: each takes `draw` and n and returns a list of n (x, y) floats.


def _uniform(draw, n):
    return [_point_in_box(draw, 0) for _ in range(n)]


def _uniform_scaled(draw, n):
    k = _toward_zero(draw, -1074, 1023)
    return [_point_in_box(draw, k) for _ in range(n)]


def _wide_exponents(draw, n):
    return [(_any_finite_double(draw), _any_finite_double(draw)) for _ in range(n)]


def _integer_grid(draw, n):
    g = _in_range(draw, 1, 8)
    ints = [(_toward_zero(draw, -g, g), _toward_zero(draw, -g, g)) for _ in range(n)]
    t = (_toward_zero(draw, -(1 << 30), 1 << 30), _toward_zero(draw, -(1 << 30), 1 << 30))
    k = _toward_zero(draw, _MIN_EXACT_SCALE, _max_scale_for_bits(32))
    return _place(ints, t, k)


def _lattice_circle(draw, n):
    primes = _in_range(draw, 1, len(_GAUSSIAN_PRIMES))
    ints = []
    for _ in range(n):
        choices = [_in_range(draw, 0, 2) for _ in range(primes)]
        ints.append(lattice_circle_point(choices, _in_range(draw, 0, 3)))
    t = (_toward_zero(draw, -(1 << 26), 1 << 26), _toward_zero(draw, -(1 << 26), 1 << 26))
    k = _toward_zero(draw, _MIN_EXACT_SCALE, _max_scale_for_bits(28))
    return _place(ints, t, k)


def _dyadic_line(draw, n):
    bx = _toward_zero(draw, -(1 << 30), 1 << 30)
    by = _toward_zero(draw, -(1 << 30), 1 << 30)
    run = 1 << _in_range(draw, 0, 20)
    rise = _toward_zero(draw, -(1 << 20), 1 << 20)
    mirrored = draw(st.booleans())
    ints = []
    for _ in range(n):
        t = _toward_zero(draw, -(1 << 10), 1 << 10)
        x, y = bx + t * run, by + t * rise  # |.| <= 2^31
        ints.append((y, x) if mirrored else (x, y))
    k = _toward_zero(draw, _MIN_EXACT_SCALE, _max_scale_for_bits(33))
    return _place(ints, (0, 0), k)


def _near_integer_grid(draw, n):
    return _nudged(draw, _integer_grid(draw, n))


def _near_lattice_circle(draw, n):
    return _nudged(draw, _lattice_circle(draw, n))


def _near_dyadic_line(draw, n):
    return _nudged(draw, _dyadic_line(draw, n))


def _near_rounded_line(draw, n):
    k = _toward_zero(draw, -900, 900)
    (px, py), (qx, qy) = _point_in_box(draw, k), _point_in_box(draw, k)
    pts = []
    for _ in range(n):
        t = dyadic(_toward_zero(draw, -(1 << 21), 1 << 22), -20)  # in [-2, 4]
        pts.append((_fma(t, qx - px, px), _fma(t, qy - py, py)))
    return _nudged(draw, pts)


def _near_rounded_circle(draw, n):
    cx, cy = _point_in_box(draw, _in_range(draw, 0, 30))
    r = dyadic(_in_range(draw, 1 << 50, 1 << 53), -53)  # in [1/8, 1]
    pts = []
    for _ in range(n):
        theta = dyadic(_in_range(draw, 0, (13 << 40) - 1), -41)  # dyadic, in [0, 6.5)
        pts.append((_fma(r, math.cos(theta), cx), _fma(r, math.sin(theta), cy)))
    k = _toward_zero(draw, -900, 900)
    return [(math.ldexp(x, k), math.ldexp(y, k)) for x, y in _nudged(draw, pts)]


#: The configurations of Kettner, Mehlhorn, Pion, Schirra and Yap (CGTA 2008), as literals.
def _kettner(draw, n):
    """One configuration with p moved over the 256 x 256 window of ulp steps (shrinking
    toward p itself); points beyond the third on the diagonal y = x at k 2^-47 in [0.5, 16)."""
    (px, py), q, r = KETTNER_CONFIGURATIONS[_in_range(draw, 0, 2)]
    i, j = _in_range(draw, 0, 255), _in_range(draw, 0, 255)
    pts = [(nudge(px, i), nudge(py, j)), q, r]
    while len(pts) < n:
        v = dyadic(_in_range(draw, 1 << 46, (1 << 51) - 1), -47)
        pts.append((v, v))
    return pts[:n]


def _duplicates(draw, n):
    """Points of another family (shrinking toward uniform) in which some points repeat: one
    pair forced equal, and each later point may copy an earlier one (shrinking toward copying
    the first)."""
    base = FAMILIES[_in_range(draw, 0, len(FAMILIES) - 2)].name
    pts = _BUILDERS[base](draw, n)
    if n < 2:
        return pts
    for i in range(1, n):
        if not draw(st.booleans()):  # shrinks toward copying
            pts[i] = pts[_in_range(draw, 0, i - 1)]
    later = _in_range(draw, 1, n - 1)
    pts[later] = pts[_in_range(draw, 0, later - 1)]
    return pts


_BUILDERS = {
    "uniform": _uniform,
    "uniform_scaled": _uniform_scaled,
    "wide_exponents": _wide_exponents,
    "integer_grid": _integer_grid,
    "lattice_circle": _lattice_circle,
    "dyadic_line": _dyadic_line,
    "near_integer_grid": _near_integer_grid,
    "near_lattice_circle": _near_lattice_circle,
    "near_dyadic_line": _near_dyadic_line,
    "near_rounded_line": _near_rounded_line,
    "near_rounded_circle": _near_rounded_circle,
    "kettner": _kettner,
    "duplicates": _duplicates,
}
assert list(_BUILDERS) == [f.name for f in FAMILIES]


def _builder(family):
    try:
        return _BUILDERS[family]
    except (KeyError, TypeError):
        raise ValueError(f"unknown point family {family!r}; the families are: "
                         + ", ".join(f.name for f in FAMILIES)) from None


def _as_array(pts, n):
    return np.array(pts, dtype=np.float64).reshape(n, 2)


# ---------------------------------------------------------------------------------------
# The strategies.


def points(family, n):
    """A strategy of n points of the given family (a name of FAMILIES), sharing the family's
    structure (one circle, one line, ...): an (n, 2) float64 array, C contiguous. Raises
    ValueError for an unknown family or a negative n.

    Hypothesis 6 records at most 8 KiB of choices per example, which bounds n: about 140
    points for wide_exponents, 180 for duplicates, 200 for uniform and uniform_scaled,
    340 to 680 for the near_ families and kettner, 1000 and more for the exact structures.
    Beyond that its health check reports a large base example."""
    build = _builder(family)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 0:
        raise ValueError(f"points: n must be a non-negative integer, not {n!r}")
    n = int(n)

    @st.composite
    def family_points(draw):
        return _as_array(build(draw, n), n)

    return family_points()


def query3(family):
    """A strategy of orient2d (or compare_distance) queries of the family: the 3 points of
    points(family, 3) as a (3, 2) float64 array; unpack with `a, b, c = q`."""
    return points(family, 3)


def query4(family):
    """A strategy of incircle queries of the family: the 4 points of points(family, 4) as a
    (4, 2) float64 array; unpack with `a, b, c, d = q`."""
    return points(family, 4)
