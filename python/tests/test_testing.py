"""exidel.testing: the point families as Hypothesis strategies. Shapes and finiteness, the
exact structure of each family (decided by exidel's exact kernel), the exact building blocks
(nudge against a loop of nextafter, fma, lattice circles), shrinking toward the degenerate
configuration, and the searches a user runs: the double kernel and a naive orientation are
caught on near-degenerate families."""

import itertools
import math
import os
import re
import subprocess
import sys
import textwrap
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import find, given, settings, strategies as st  # noqa: E402

import exidel  # noqa: E402
from exidel import testing as T  # noqa: E402
from exidel.testing import FAMILIES, nudge, points, query3, query4  # noqa: E402


def fixed(max_examples, shrink=True):
    """Reproducible and fast: the same examples on every run, nothing stored; without
    shrinking when only the existence of an example matters."""
    P = hypothesis.Phase
    phases = [P.explicit, P.generate] + ([P.shrink] if shrink else [])  # no slow explain phase
    return settings(derandomize=True, max_examples=max_examples, deadline=None, database=None,
                    suppress_health_check=list(hypothesis.HealthCheck), phases=phases)


NAMES = [f.name for f in FAMILIES]
TOP = sys.float_info.max
TINY = math.ulp(0.0)


def bits(v):
    return np.float64(v).view(np.uint64).item()


def ulps_apart(a, b):
    return abs(T._key(a) - T._key(b))


def rows(p):
    return [tuple(r) for r in np.asarray(p).tolist()]


def all_quadruples_incircle(p):
    q = np.array(list(itertools.combinations(range(len(p)), 4)))
    return exidel.incircle(p[q[:, 0]], p[q[:, 1]], p[q[:, 2]], p[q[:, 3]], kernel="exact")


def all_triples_orient(p):
    q = np.array(list(itertools.combinations(range(len(p)), 3)))
    return exidel.orient2d(p[q[:, 0]], p[q[:, 1]], p[q[:, 2]], kernel="exact")


def valuation(x):
    """The 2-adic valuation of a non-zero dyadic rational."""
    f = Fraction(x)
    num, den = f.numerator, f.denominator
    return (abs(num) & -abs(num)).bit_length() - 1 - (den.bit_length() - 1)


def in_range(q, lo=2.0 ** -500, hi=2.0 ** 500):
    """No coordinate where a product of two could underflow or overflow."""
    a = np.abs(np.asarray(q))
    return bool(np.all((a == 0) | ((a > lo) & (a < hi))))


# ---------------------------------------------------------------------------------------
# The names.


def test_families_match_the_cpp_all_families():
    header = (Path(__file__).resolve().parents[2]
              / "lib/testing/include/exidel/testing/families.hpp")
    if not header.exists():
        pytest.skip("the C++ sources are not next to this test")
    body = header.read_text().split("all_families()", 1)[1]
    # {Family::f, "name", near_degenerate, degenerate}; the module keeps the first flag.
    cpp = re.findall(r'\{Family::(\w+), "(\w+)", (true|false), (?:true|false)\}', body)
    assert [(name, flag == "true") for _, name, flag in cpp] == [tuple(f) for f in FAMILIES]
    assert len(FAMILIES) == 13 and T.families() == list(FAMILIES)
    assert [f.name for f in T.families(near_degenerate=True)] == [
        "near_integer_grid", "near_lattice_circle", "near_dyadic_line", "near_rounded_line",
        "near_rounded_circle", "kettner"]


@pytest.mark.parametrize("make", [lambda f: points(f, 3), query3, query4])
def test_unknown_family_raises_listing_the_names(make):
    with pytest.raises(ValueError) as e:
        make("lattice-circle")
    assert "'lattice-circle'" in str(e.value)
    assert all(name in str(e.value) for name in NAMES)


@pytest.mark.parametrize("n", [-1, 2.0, True, "3"])
def test_bad_counts_raise(n):
    with pytest.raises(ValueError):
        points("uniform", n)


def test_import_exidel_does_not_import_hypothesis():
    code = "import sys, exidel; print('hypothesis' in sys.modules)"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=env, check=True).stdout
    assert out.strip() == "False"


# ---------------------------------------------------------------------------------------
# The exact building blocks.


def nudge_by_nextafter(v, steps):
    """ulp.hpp's nudge, literally."""
    while steps > 0 and v < TOP:
        v, steps = math.nextafter(v, TOP), steps - 1
    while steps < 0 and v > -TOP:
        v, steps = math.nextafter(v, -TOP), steps + 1
    return v


def test_nudge_is_the_cpp_loop_of_nextafter():
    values = [0.0, -0.0, TINY, -TINY, 2 * TINY, -3 * TINY, sys.float_info.min, 1.0, -1.0, 0.5,
              1.5, 2.0 ** 52, TOP, -TOP, math.nextafter(TOP, 0), -math.nextafter(TOP, 0),
              math.inf, -math.inf, 24.00000000000005, -1e-310]
    for v in values:
        for steps in list(range(-7, 8)) + [-300, 255, 1000]:
            want = nudge_by_nextafter(v, steps)
            assert bits(nudge(v, steps)) == bits(want), (v, steps)
    assert math.isnan(nudge(math.nan, 3))


def test_nudge_at_zero_and_at_the_top():
    assert nudge(0.0, 1) == TINY and nudge(0.0, -1) == -TINY
    assert bits(nudge(-TINY, 1)) == bits(-0.0) and bits(nudge(TINY, -1)) == bits(0.0)
    assert nudge(-TINY, 2) == TINY  # zero is one step
    assert nudge(TOP, 4) == TOP and nudge(-TOP, -4) == -TOP
    assert nudge(TOP, -1) == math.nextafter(TOP, 0)
    assert nudge(1.0, -1) == 1 - 2.0 ** -53 and nudge(1.0, 1) == 1 + 2.0 ** -52


def test_dyadic_and_fma_round_once():
    assert T.dyadic(3, -1) == 1.5 and T.dyadic(-(2 ** 53), -53) == -1.0
    assert T.dyadic(3, -1075) == 2 * TINY  # 1.5 * 2^-1074: ties to even
    assert T.dyadic(1, -1075) == 0.0
    f = T._fma_exact
    assert f(0.1, 10.0, -1.0) == 5.551115123125783e-17  # the fused value, not 0
    assert f(2.0 ** -600, 2.0 ** -500, 0.0) == 0.0  # 2^-1100: below half the smallest
    assert f(1.5, TINY, 0.0) == 2 * TINY and f(2.5, TINY, 0.0) == 2 * TINY  # ties to even
    assert f(1.25, TINY, 0.0) == TINY and f(1.75, TINY, -TINY) == TINY
    assert bits(f(-0.0, 1.0, -0.0)) == bits(-0.0) and bits(f(0.0, 1.0, -0.0)) == bits(0.0)
    assert bits(f(1.0, 1.0, -1.0)) == bits(0.0)
    assert f(TOP, 0.5, 0.0) == TOP / 2 and f(1.0 + 2 ** -52, 1.0 - 2 ** -53, 0.0) == 1.0


@pytest.mark.parametrize("primes", range(1, 7))
def test_lattice_circle_points_are_every_integer_point(primes):
    r = T.lattice_circle_radius(primes)
    assert r == [5, 65, 1105, 32045, 1185665, 48612265][primes - 1]
    pts = {T.lattice_circle_point(c, u)
           for c in itertools.product(range(3), repeat=primes) for u in range(4)}
    assert all(x * x + y * y == r * r for x, y in pts)
    assert len(pts) == 4 * 3 ** primes
    assert T.lattice_circle_point([0] * primes, 0) == (r, 0)
    assert T.lattice_circle_point([0] * primes, 1) == (0, r)


def test_lattice_circle_rejects_bad_choices():
    with pytest.raises(ValueError):
        T.lattice_circle_radius(7)
    with pytest.raises(ValueError):
        T.lattice_circle_point([], 0)
    with pytest.raises(ValueError):
        T.lattice_circle_point([3], 0)


# ---------------------------------------------------------------------------------------
# Every family: shape, dtype, finiteness.


COUNTS = (0, 1, 2, 3, 4, 50)


@pytest.mark.parametrize("family", NAMES)
def test_points_are_finite_n_by_2_doubles(family):
    @fixed(15)
    @given(st.tuples(*(points(family, n) for n in COUNTS)))
    def check(sets):
        for n, p in zip(COUNTS, sets):
            assert isinstance(p, np.ndarray) and p.dtype == np.float64 and p.shape == (n, 2)
            assert p.flags.c_contiguous and np.all(np.isfinite(p))

    check()


@pytest.mark.parametrize("family", NAMES)
def test_queries_are_the_points_of_three_and_four(family):
    @fixed(20)
    @given(query3(family), query4(family))
    def check(q3, q4):
        assert q3.shape == (3, 2) and q4.shape == (4, 2)
        a, b, c = q3
        assert exidel.orient2d(a, b, c, kernel="exact").shape == ()

    check()


# ---------------------------------------------------------------------------------------
# Structure, exactly.


@fixed(60)
@given(points("lattice_circle", 7))
def test_lattice_circle_every_four_points_cocircular(p):
    assert np.all(all_quadruples_incircle(p) == 0)


@fixed(60)
@given(points("dyadic_line", 7))
def test_dyadic_line_every_three_points_collinear(p):
    assert np.all(all_triples_orient(p) == 0)


@fixed(100)
@given(points("integer_grid", 8))
def test_integer_grid_is_a_small_grid(p):
    # (x + t) 2^k with |x| <= 8: every coordinate difference is a multiple of 2^k of at
    # most 16 of them, so at most 16 times its smallest power of two.
    diffs = [Fraction(float(a)) - Fraction(float(b))
             for col in p.T for a, b in itertools.combinations(col, 2) if a != b]
    if diffs:
        v = min(valuation(d) for d in diffs)
        assert max(abs(d) for d in diffs) <= 16 * Fraction(2) ** v


@fixed(100)
@given(points("uniform", 6))
def test_uniform_is_on_the_grid_2_to_minus_53_in_the_unit_box(p):
    assert np.all(np.abs(p) <= 1)
    assert all((Fraction(float(v)) * 2 ** 53).denominator == 1 for v in p.ravel())


@fixed(100)
@given(points("uniform_scaled", 6))
def test_uniform_scaled_is_one_box_of_53_bits(p):
    nonzero = [Fraction(float(v)) for v in p.ravel() if v != 0]
    if nonzero:  # m 2^(k-53) with |m| <= 2^53 (or rounded onto the subnormal grid)
        assert max(map(abs, nonzero)) <= Fraction(2) ** (min(map(valuation, nonzero)) + 53)


def test_uniform_scaled_and_wide_exponents_cover_the_range():
    seen = {"huge box": False, "subnormal box": False, "unit box": False, "spread": 0}

    @fixed(300)
    @given(points("uniform_scaled", 4), points("wide_exponents", 4))
    def observe(box, wide):
        top = np.abs(box).max()
        seen["huge box"] |= bool(top > 2.0 ** 1000)
        seen["subnormal box"] |= bool(0 < top < sys.float_info.min)
        seen["unit box"] |= bool(2.0 ** -8 < top <= 1)
        e = [math.frexp(v)[1] for v in wide.ravel() if v != 0]
        seen["spread"] = max(seen["spread"], max(e) - min(e) if e else 0)

    observe()
    assert seen["huge box"] and seen["subnormal box"] and seen["unit box"]
    assert seen["spread"] > 1800  # one query spans most of the ~2100 exponents


@st.composite
def base_and_near(draw, base, n):
    """A structured set and the same set moved as the near_* families move it."""
    pts = base(draw, n)
    return np.array(pts), np.array(T._nudged(draw, pts))


@pytest.mark.parametrize("base, structured", [
    (T._lattice_circle, lambda p: np.all(all_quadruples_incircle(p) == 0)),
    (T._dyadic_line, lambda p: np.all(all_triples_orient(p) == 0)),
    (T._integer_grid, lambda p: True),
])
def test_near_families_are_the_structure_moved_by_at_most_4_ulps(base, structured):
    moved_any = []

    @fixed(60)
    @given(base_and_near(base, 5))
    def check(pair):
        exact, near = pair
        assert structured(exact)
        d = [ulps_apart(a, b) for a, b in zip(exact.ravel(), near.ravel())]
        assert max(d) <= 4
        moved_any.append(max(d) > 0)

    check()
    assert sum(moved_any) > len(moved_any) // 2


@fixed(100)
@given(points("near_rounded_line", 5))
def test_near_rounded_line_is_within_a_few_ulps_of_a_line(p):
    # Rounded points of one exact line, each coordinate off by at most 4.5 ulps (of the
    # largest coordinate): |orient2d| <= some small multiple of ulp * length.
    ulp = math.ulp(float(np.abs(p).max()))
    length = max(abs(Fraction(float(v))) for v in (p[:, None, :] - p[None, :, :]).ravel()) * 2
    for a, b, c in itertools.combinations(rows(p), 3):
        (ax, ay), (bx, by), (cx, cy) = [(Fraction(x), Fraction(y)) for x, y in (a, b, c)]
        det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        assert abs(det) <= 64 * Fraction(ulp) * (length + Fraction(ulp))


@fixed(200)
@given(points("kettner", 6))
def test_kettner_configurations_and_the_diagonal(p):
    pts = rows(p)
    config = next(c for c in T.KETTNER_CONFIGURATIONS if tuple(c[1:]) == tuple(pts[1:3]))
    (px, py), (x, y) = config[0], pts[0]
    assert 0 <= T._key(x) - T._key(px) < 256 and 0 <= T._key(y) - T._key(py) < 256
    for x, y in pts[3:]:
        assert x == y and 0.5 <= x < 16 and (Fraction(x) * 2 ** 47).denominator == 1
    if config is not T.KETTNER_CONFIGURATIONS[1]:  # q and r on the diagonal too
        assert np.all(all_triples_orient(p[1:]) == 0)


@fixed(200)
@given(points("duplicates", 5))
def test_duplicates_repeat_a_point(p):
    assert len(set(rows(p))) < 5


# ---------------------------------------------------------------------------------------
# Shrinking goes to the degenerate configuration.


def separated(p):
    """Distinct far beyond their ulps: a property of the coarse shape only."""
    d = [math.dist(a, b) for a, b in itertools.combinations(rows(p), 2)]
    return min(d) > 2.0 ** 20 * math.ulp(float(np.abs(p).max()))


def test_minimal_examples_are_the_degenerate_configurations():
    s = fixed(200)
    # Nothing asked: every choice at its simplest, exactly degenerate.
    assert rows(find(points("near_lattice_circle", 4), lambda p: True, settings=s)) == [(5, 0)] * 4
    assert rows(find(points("kettner", 3), lambda p: True, settings=s)) == [
        (0.5, 0.5), (12, 12), (24, 24)]
    assert rows(find(points("duplicates", 5), lambda p: True, settings=s)) == [(0, 0)] * 5
    assert rows(find(points("uniform_scaled", 2), lambda p: True, settings=s)) == [(0, 0)] * 2


@pytest.mark.parametrize("family, n, degenerate", [
    ("near_lattice_circle", 4, lambda p: np.all(all_quadruples_incircle(p) == 0)),
    ("near_dyadic_line", 3, lambda p: np.all(all_triples_orient(p) == 0)),
    ("near_integer_grid", 3, lambda p: np.all(p == np.round(p))),
])
def test_a_property_of_the_coarse_shape_shrinks_to_no_ulps(family, n, degenerate):
    # Any property that does not depend on the ulps shrinks them away: the axis points of
    # the circle of radius 5, points of the x axis, points of the unit grid.
    p = find(points(family, n), separated, settings=fixed(300))
    assert degenerate(p) and len(set(rows(p))) == n, p


def test_duplicates_shrink_toward_copies_of_the_first_point():
    p = find(points("duplicates", 4), lambda p: len(set(rows(p))) >= 2, settings=fixed(300))
    r = rows(p)
    assert len(set(r)) == 2 and r.count(r[0]) == 3


# ---------------------------------------------------------------------------------------
# What a user's search finds.


def test_find_a_query_where_the_double_incircle_is_wrong():
    def wrong(q):
        return exidel.incircle(*q, kernel="double") != exidel.incircle(*q, kernel="exact")

    q = find(query4("near_lattice_circle"), wrong, settings=fixed(300))
    assert wrong(q)
    # Also away from underflow and overflow (the minimal case above may be subnormal).
    q = find(query4("near_lattice_circle"), lambda q: in_range(q) and wrong(q),
             settings=fixed(300, shrink=False))
    assert wrong(q) and in_range(q) and exidel.incircle(*q, kernel="exact") != 0


def naive_orient2d(a, b, c):
    with np.errstate(all="ignore"):
        return np.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


@pytest.mark.parametrize("family", ["near_rounded_line", "near_dyadic_line"])
def test_a_naive_orientation_is_caught(family):
    def wrong(q):
        return in_range(q) and naive_orient2d(*q) != exidel.orient2d(*q, kernel="exact")

    q = find(query3(family), wrong, settings=fixed(300))
    assert wrong(q)


def test_the_docstring_example_fails_as_it_says():
    example = T.__doc__.split("A test of your own orientation function", 1)[1]
    code = textwrap.dedent(example.split("\n\n", 1)[1].split("\n\nHypothesis finds", 1)[0])
    namespace = {}
    exec(compile(code, "exidel.testing example", "exec"), namespace)
    test = fixed(200, shrink=False)(namespace["test_my_orient2d"])
    with np.errstate(all="ignore"), pytest.raises(AssertionError):
        test()
