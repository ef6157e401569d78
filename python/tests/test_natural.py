"""exidel.NaturalNeighborInterpolator, griddata(method="natural") and
Delaunay.natural_neighbors: Sibson's coordinates sum to 1, reproduce the query (linear
precision; exactly with exact=True on dyadic data), equal a point's value on it and the
linear interpolation on hull edges; threads, complex and vector values, bad input. (The
coordinates themselves are checked against CGAL's in the C++ tests.)"""

import numpy as np
import pytest

import exidel


def data(seed=3, n=1500, q=2000):
    rng = np.random.default_rng(seed)
    pts = rng.random((n, 2))
    values = np.sin(5 * pts[:, 0]) * np.cos(3 * pts[:, 1])
    xi = rng.random((q, 2)) * 1.2 - 0.1
    return pts, values, xi


def test_coordinates_sum_to_one_and_reproduce_the_query():
    pts, _, xi = data()
    tri = exidel.Delaunay(pts)
    indptr, indices, weights = tri.natural_neighbors(xi)
    assert indptr.shape == (len(xi) + 1,) and indptr[0] == 0
    assert indices.dtype == np.int32 and weights.dtype == np.float64
    inside = tri.find_simplex(xi) >= 0
    counts = np.diff(indptr)
    assert np.all((counts > 0) == inside)
    assert np.all(weights >= 0)
    rows = np.repeat(np.arange(len(xi)), counts)
    sums = np.bincount(rows, weights, minlength=len(xi))
    np.testing.assert_allclose(sums[inside], 1, atol=1e-12)
    centre = np.stack([np.bincount(rows, weights * pts[indices, k], minlength=len(xi))
                       for k in range(2)], axis=1)
    np.testing.assert_allclose(centre[inside], xi[inside], atol=1e-12)
    # Every natural neighbour is a corner of a triangle whose circumcircle holds the query.
    exact = tri.natural_neighbors(xi, exact=True)
    np.testing.assert_array_equal(exact[0], indptr)
    np.testing.assert_array_equal(exact[1], indices)
    np.testing.assert_allclose(exact[2], weights, atol=1e-12)


def test_linear_functions_are_reproduced_exactly():
    rng = np.random.default_rng(9)
    lattice = np.stack(np.meshgrid(np.arange(11.0), np.arange(11.0)), -1).reshape(-1, 2)
    pts = np.concatenate([lattice, rng.integers(0, 11 * 64, (300, 2)) / 64.0, lattice[:40]])
    values = 3 * pts[:, 0] - 2 * pts[:, 1] + 7
    xi = rng.integers(0, 10 * 32, (3000, 2)) / 32.0
    want = 3 * xi[:, 0] - 2 * xi[:, 1] + 7
    got = exidel.NaturalNeighborInterpolator(pts, values, exact=True)(xi)
    np.testing.assert_array_equal(got, want)
    rounded = exidel.NaturalNeighborInterpolator(pts, values)(xi)
    np.testing.assert_allclose(rounded, want, atol=1e-10)


def test_values_on_points_hull_edges_and_outside():
    pts = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [1, 1]], dtype=float)
    values = pts.sum(axis=1)
    ip = exidel.NaturalNeighborInterpolator(pts, values, fill_value=-7)
    got = ip([[1, 1], [1, 0], [4, 3], [5, 5], [0, 4]])
    np.testing.assert_array_equal(got, [2, 1, 7, -7, 4])
    # Collinear points: linear along their chain, fill elsewhere.
    line = np.array([[0, 0], [2, 2], [1, 1]], dtype=float)
    ip = exidel.NaturalNeighborInterpolator(line, [0.0, 20.0, 10.0])
    got = ip([[1.5, 1.5], [1, 2]])
    assert got[0] == 15 and np.isnan(got[1])


def test_vector_complex_values_threads_and_griddata():
    pts, values, xi = data(seed=5, n=600, q=900)
    vec = np.stack([values, 2 * values, values + 1j * values], axis=1)
    tri = exidel.Delaunay(pts)
    ip = exidel.NaturalNeighborInterpolator(tri, vec)
    got = ip(xi[:, 0], xi[:, 1])
    assert got.shape == (len(xi), 3) and got.dtype == np.complex128
    one = exidel.NaturalNeighborInterpolator(pts, values)(xi)
    np.testing.assert_allclose(got[:, 0].real, one, rtol=0, atol=1e-15, equal_nan=True)
    inside = ~np.isnan(one)  # outside: nan + 0j, as LinearNDInterpolator's fill
    np.testing.assert_allclose(got[inside, 2].imag, one[inside], rtol=0, atol=1e-15)
    assert np.all(got[~inside, 2].imag == 0)
    np.testing.assert_array_equal(ip(xi, threads=1), ip(xi, threads=2))
    np.testing.assert_array_equal(exidel.griddata(pts, values, xi, method="natural"), one)
    gx, gy = np.mgrid[0:1:20j, 0:1:30j]
    assert exidel.griddata(pts, values, (gx, gy), method="natural").shape == (20, 30)
    # Smoother than the linear interpolant on a smooth function.
    f = lambda p: np.sin(5 * p[:, 0]) * np.cos(3 * p[:, 1])  # noqa: E731
    inside = tri.find_simplex(xi) >= 0
    linear = exidel.LinearNDInterpolator(tri, values)(xi)
    assert np.abs(one - f(xi))[inside].max() < 2 * np.abs(linear - f(xi))[inside].max()


def test_bad_input():
    pts, values, _ = data(n=50, q=5)
    ip = exidel.NaturalNeighborInterpolator(pts, values)
    with pytest.raises(ValueError, match="row 1"):
        ip([[0.5, 0.5], [np.nan, 0.5]])
    with pytest.raises(ValueError, match="different number"):
        exidel.NaturalNeighborInterpolator(pts, values[:-1])
    with pytest.raises(ValueError, match="furthest"):
        exidel.NaturalNeighborInterpolator(exidel.Delaunay(pts, furthest_site=True), values)
    with pytest.raises(ValueError, match="threads"):
        exidel.Delaunay(pts).natural_neighbors([[0.5, 0.5]], threads=0)
