"""exidel.orient2d, incircle, incircle_cosine, compare_distance, and in space orient3d and
insphere: exactness against rational arithmetic, agreement with the exidel command,
broadcasting and bad input."""

import math
import threading

import numpy as np
import pytest

import exidel
from conftest import (compare_distance_exact, incircle_exact, insphere_exact, orient2d_exact,
                      orient3d_exact, run_cli)

EXACT = ["adaptive", "exact", "exact-cpp"]


def near_collinear(rng, n):
    """Triples on a line through far-apart points, rounded, then moved by a few ulps: most
    exact orientations are far below the plain formula's rounding error."""
    p = rng.random((n, 2)) * 2 - 1
    q = rng.random((n, 2)) * 2 - 1
    t = rng.integers(-8, 16, size=(n, 1)) / 4
    c = p + t * (q - p)
    c = np.nextafter(c, np.where(rng.random((n, 2)) < 0.5, -np.inf, np.inf))
    return p, q, c


def near_cocircular(rng, n):
    """Four points of a circle of radius ~1 around (1e3, 1e3), rounded, then moved by an ulp."""
    theta = rng.random((n, 4)) * 2 * np.pi
    pts = 1e3 + np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    pts = np.nextafter(pts, np.where(rng.random(pts.shape) < 0.5, -np.inf, np.inf))
    order = np.argsort(theta, axis=1)  # counter-clockwise a, b, c
    pts = np.take_along_axis(pts, order[..., None], axis=1)
    return pts[:, 0], pts[:, 1], pts[:, 2], pts[:, 3]


@pytest.mark.parametrize("kernel", EXACT)
def test_orient2d_exact_on_near_collinear(rng, kernel):
    a, b, c = near_collinear(rng, 400)
    got = exidel.orient2d(a, b, c, kernel=kernel)
    want = [orient2d_exact(*q) for q in zip(a, b, c)]
    assert got.dtype == np.int8 and got.shape == (400,)
    assert got.tolist() == want


@pytest.mark.parametrize("kernel", EXACT)
def test_incircle_and_cosine_exact_on_near_cocircular(rng, kernel):
    a, b, c, d = near_cocircular(rng, 300)
    got = exidel.incircle(a, b, c, d, kernel=kernel)
    want = [incircle_exact(*q) for q in zip(a, b, c, d)]
    assert got.tolist() == want
    # The cosine test equals orient2d(a, b, c) * incircle(a, b, c, d) when c and d are
    # strictly on opposite sides of ab (its precondition, kernel.hpp): in counter-clockwise
    # order a, b, c, d, the diagonal ac separates b and d.
    ok = exidel.orient2d(a, c, b) * exidel.orient2d(a, c, d) < 0
    cos = exidel.incircle_cosine(a, c, b, d, kernel=kernel)
    want = exidel.orient2d(a, c, b) * exidel.incircle(a, c, b, d)
    assert ok.sum() > 250
    assert (cos[ok] == want[ok]).all()


@pytest.mark.parametrize("kernel", EXACT)
def test_compare_distance_exact_on_ties(rng, kernel):
    c = rng.random((300, 2))
    p = rng.random((300, 2))
    # q: p reflected through c's x line, so |p - c| = |q - c| exactly where no rounding
    # happened, nearly otherwise.
    q = np.stack([p[:, 0], 2 * c[:, 1] - p[:, 1]], axis=1)
    got = exidel.compare_distance(c, p, q, kernel=kernel)
    assert got.tolist() == [compare_distance_exact(*x) for x in zip(c, p, q)]
    assert (got == 0).any() and (got != 0).any()


def test_double_kernel_is_wrong_near_degeneracy_and_exact_kernels_agree(rng):
    a, b, c = near_collinear(rng, 2000)
    exact = exidel.orient2d(a, b, c, kernel="exact")
    assert (exidel.orient2d(a, b, c, kernel="adaptive") == exact).all()
    assert (exidel.orient2d(a, b, c, kernel="double") != exact).sum() > 0


@pytest.mark.parametrize("kernel", ["double", "long-double", "adaptive", "exact", "mpfr:64"])
def test_agrees_with_the_exidel_command(rng, exidel_cli, kernel):
    a, b, c = near_collinear(rng, 100)
    d = near_cocircular(rng, 100)
    lines, expected = [], []
    h = lambda *ps: " ".join(float(v).hex() for p in ps for v in p)  # noqa: E731
    for q in zip(a, b, c):
        lines.append("orient2d " + h(*q))
    for q in zip(*d):
        lines.append("incircle " + h(*q))
        lines.append("incircle_cosine " + h(*q))
    for q in zip(c, a, b):
        lines.append("compare_distance " + h(*q))
    expected = np.concatenate([
        exidel.orient2d(a, b, c, kernel=kernel),
        np.stack([exidel.incircle(*d, kernel=kernel),
                  exidel.incircle_cosine(*d, kernel=kernel)], axis=1).reshape(-1),
        exidel.compare_distance(c, a, b, kernel=kernel)])
    out = run_cli(exidel_cli, "predicate", "--kernel", kernel, stdin="\n".join(lines) + "\n")
    assert [int(s) for s in out.split()] == expected.tolist()


def test_every_kernel_spelling_works():
    a, b, c = [0.0, 0.0], [1.0, 0.0], [0.0, 1.0]
    for name in ["double", "long-double", "adaptive", "exact", "exact-cpp", "mpfr:24", "mpfr:113"]:
        assert exidel.orient2d(a, b, c, kernel=name) == 1
    assert exidel.kernel_spellings[-1] == "mpfr:<bits>"


def test_broadcasting_and_shapes():
    a = np.array([[0.0, 0.0], [0.0, 0.0], [2.0, 2.0]])
    s = exidel.orient2d(a, [1.0, 0.0], [[0.0, 1.0]])
    assert s.shape == (3,) and s.tolist() == [1, 1, -1]
    one = exidel.orient2d([0, 0], [1, 0], [0, 1])  # integers are converted
    assert one.shape == () and int(one) == 1
    empty = exidel.incircle(np.empty((0, 2)), [0, 0], [1, 0], [0, 1])
    assert empty.shape == (0,) and empty.dtype == np.int8
    # float32, Fortran order and strided views are converted once.
    f = np.asfortranarray(np.array([[0, 0], [3, 3]], dtype=np.float32))
    assert exidel.orient2d(f, [1, 0], [0, 1]).tolist() == [1, -1]
    big = np.arange(20.0).reshape(10, 2)[::2]
    assert exidel.orient2d(big, big + [1, 0], big + [0, 1]).tolist() == [1] * 5


def test_bad_input_raises_value_error_naming_the_row():
    a = np.zeros((5, 2))
    a[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"a: row 3 is not finite \(0.0, nan\)"):
        exidel.orient2d(a, [1, 0], [0, 1])
    c = np.ones((4, 2))
    c[2, 0] = -np.inf
    with pytest.raises(ValueError, match="q: row 2 is not finite"):
        exidel.compare_distance([0, 0], [1, 1], c)
    with pytest.raises(ValueError, match=r"expected shape \(n, 2\) or \(2,\), got \(3, 3\)"):
        exidel.orient2d(np.zeros((3, 3)), [1, 0], [0, 1])
    with pytest.raises(ValueError, match="rows"):
        exidel.orient2d(np.zeros((3, 2)), np.zeros((4, 2)), [0, 1])
    with pytest.raises(ValueError, match="adaptive"):
        exidel.orient2d([0, 0], [1, 0], [0, 1], kernel="fast")
    with pytest.raises(ValueError, match="mpfr"):
        exidel.orient2d([0, 0], [1, 0], [0, 1], kernel="mpfr:0")
    with pytest.raises(ValueError, match="float64"):
        exidel.orient2d([["x", "y"]], [1, 0], [0, 1])


def test_extreme_magnitudes_stay_exact():
    tiny = math.ulp(0.0)  # the smallest subnormal
    a, b, c = [0.0, 0.0], [3 * tiny, tiny], [6 * tiny, 2 * tiny]
    assert exidel.orient2d(a, b, c) == 0
    assert exidel.orient2d(a, b, [6 * tiny, 3 * tiny]) == 1
    huge = 2.0 ** 1000
    # Products overflow double here; the exact kernels do not care.
    assert exidel.orient2d([-huge, -huge], [huge, huge], [huge, huge * (1 - 2 ** -52)]) == -1
    assert exidel.incircle([-huge, 0], [0, -huge], [huge, 0], [0, huge]) == 0


def test_threads_can_call_concurrently(rng):
    # The loop releases the GIL; results from several threads equal the sequential ones.
    a, b, c = near_collinear(rng, 20000)
    want = exidel.orient2d(a, b, c)
    results = [None] * 4

    def work(k):
        results[k] = exidel.orient2d(a, b, c)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all((r == want).all() for r in results)


# --- the predicates of space ------------------------------------------------------------

def near_coplanar(rng, n):
    """Four points: three far apart, the fourth an affine combination of them with dyadic
    weights, rounded, then moved by an ulp in each coordinate at random."""
    a, b, c = (rng.random((n, 3)) * 2 - 1 for _ in range(3))
    s, t = (rng.integers(-8, 16, size=(n, 1)) / 4 for _ in range(2))
    d = a + s * (b - a) + t * (c - a)
    d = np.nextafter(d, np.where(rng.random((n, 3)) < 0.5, -np.inf, np.inf))
    return a, b, c, d


def near_cospherical(rng, n):
    """Five points of a unit sphere around (100, 100, 100), rounded, then moved by an ulp."""
    v = rng.normal(size=(n, 5, 3))
    pts = 100 + v / np.linalg.norm(v, axis=-1, keepdims=True)
    pts = np.nextafter(pts, np.where(rng.random(pts.shape) < 0.5, -np.inf, np.inf))
    return tuple(pts[:, k] for k in range(5))


@pytest.mark.parametrize("kernel", EXACT + ["mpfr:2000"])
def test_orient3d_and_insphere_exact_near_degeneracy(rng, kernel):
    q = near_coplanar(rng, 300)
    got = exidel.orient3d(*q, kernel=kernel)
    assert got.dtype == np.int8 and got.shape == (300,)
    assert got.tolist() == [orient3d_exact(*r) for r in zip(*q)]
    s = near_cospherical(rng, 150)
    assert exidel.insphere(*s, kernel=kernel).tolist() == [insphere_exact(*r) for r in zip(*s)]


def test_double_kernel_is_wrong_in_space_and_exact_kernels_agree(rng):
    q = near_coplanar(rng, 2000)
    exact = exidel.orient3d(*q, kernel="exact")
    assert (exidel.orient3d(*q, kernel="double") != exact).any()
    assert (exidel.orient3d(*q, kernel="exact-cpp") == exact).all()
    s = near_cospherical(rng, 2000)
    exact = exidel.insphere(*s, kernel="exact")
    assert (exidel.insphere(*s, kernel="double") != exact).any()
    assert (exidel.insphere(*s) == exact).all()


def test_space_predicates_signs_conventions_and_broadcasting():
    o, x, y, z = [0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]
    # Shewchuk's convention: d below the plane of a counter-clockwise a, b, c is positive.
    assert exidel.orient3d(o, x, y, [0, 0, -1]) == 1 and exidel.orient3d(o, x, y, z) == -1
    assert exidel.orient3d(o, x, y, [5, -3, 0]) == 0
    a, b, c, d = o, x, y, [0, 0, -1]  # orient3d(a, b, c, d) > 0
    assert exidel.insphere(a, b, c, d, [0.3, 0.3, -0.3]) == 1
    assert exidel.insphere(a, b, c, d, [3, 3, 3]) == -1
    assert exidel.insphere(a, b, c, d, [1, 1, -1]) == 0  # a corner of the cube: on the sphere
    assert exidel.insphere(b, a, c, d, [0.3, 0.3, -0.3]) == -1  # flips with orient3d
    e = np.array([[0.3, 0.3, -0.3], [3, 3, 3], [1, 1, -1]])
    got = exidel.insphere(a, b, c, [[0, 0, -1]], e, kernel="double")
    assert got.shape == (3,) and got.tolist() == [1, -1, 0]
    empty = exidel.orient3d(np.empty((0, 3)), o, x, y)
    assert empty.shape == (0,) and empty.dtype == np.int8
    for kernel in ["double", "long-double", "adaptive", "exact", "exact-cpp", "mpfr:24"]:
        assert exidel.orient3d(o, x, y, [0, 0, -1], kernel=kernel) == 1


def test_space_predicates_bad_input():
    a = np.zeros((4, 3))
    a[2, 2] = np.inf
    with pytest.raises(ValueError, match=r"a: row 2 is not finite \(0.0, 0.0, inf\)"):
        exidel.orient3d(a, [1, 0, 0], [0, 1, 0], [0, 0, 1])
    with pytest.raises(ValueError, match=r"e: expected shape \(n, 3\) or \(3,\), got \(2, 2\)"):
        exidel.insphere([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], np.zeros((2, 2)))
    with pytest.raises(ValueError, match="rows"):
        exidel.orient3d(np.zeros((3, 3)), np.zeros((2, 3)), [0, 1, 0], [0, 0, 1])
    with pytest.raises(ValueError, match="adaptive"):
        exidel.orient3d([0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], kernel="fast")


def test_space_predicates_agree_with_the_exidel_command(rng, exidel_cli):
    q = near_coplanar(rng, 60)
    s = near_cospherical(rng, 60)
    h = lambda *ps: " ".join(float(v).hex() for p in ps for v in p)  # noqa: E731
    lines = ["orient3d " + h(*r) for r in zip(*q)] + ["insphere " + h(*r) for r in zip(*s)]
    for kernel in ["double", "adaptive", "mpfr:64"]:
        expected = np.concatenate([exidel.orient3d(*q, kernel=kernel), exidel.insphere(*s, kernel=kernel)])
        out = run_cli(exidel_cli, "predicate", "--kernel", kernel, stdin="\n".join(lines) + "\n")
        assert [int(v) for v in out.split()] == expected.tolist()
