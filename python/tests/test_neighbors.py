"""Delaunay.nearest(xi, k) and Delaunay.within_radius: against scipy's cKDTree on general
position, exact on lattice circles and ties."""

import numpy as np
import pytest
import scipy.spatial

import exidel


def test_k_nearest_matches_ckdtree():
    rng = np.random.default_rng(12)
    pts = rng.random((3000, 2))
    xi = rng.random((500, 2)) * 1.4 - 0.2
    tri = exidel.Delaunay(pts)
    got = tri.nearest(xi, k=8)
    assert got.shape == (500, 8) and got.dtype == np.int32
    _, want = scipy.spatial.cKDTree(pts).query(xi, k=8)
    np.testing.assert_array_equal(got, want)
    np.testing.assert_array_equal(tri.nearest(xi, k=1)[:, 0], tri.nearest(xi))
    assert tri.nearest(xi.reshape(10, 50, 2), k=3).shape == (10, 50, 3)
    assert tri.nearest(xi, k=0).shape == (500, 0)
    # More than the distinct points: -1 after them.
    small = exidel.Delaunay(np.array([[0, 0], [1, 0], [0, 1], [0, 1]], dtype=float))
    np.testing.assert_array_equal(small.nearest([[0.1, 0.9]], k=5), [[2, 0, 1, -1, -1]])


def test_within_radius_matches_ckdtree():
    rng = np.random.default_rng(13)
    pts = rng.random((3000, 2))
    xi = rng.random((400, 2))
    tri = exidel.Delaunay(pts)
    indptr, indices = tri.within_radius(xi, 0.05, threads=2)
    want = scipy.spatial.cKDTree(pts).query_ball_point(xi, 0.05)
    for i in range(len(xi)):
        row = indices[indptr[i]:indptr[i + 1]]
        assert sorted(row) == sorted(want[i])
        d = np.hypot(*(pts[row] - xi[i]).T)
        assert np.all(np.diff(d) >= 0)


def test_lattice_circle_is_exact():
    g = np.stack(np.meshgrid(np.arange(-8.0, 9), np.arange(-8.0, 9)), -1).reshape(-1, 2)
    tri = exidel.Delaunay(g)
    indptr, indices = tri.within_radius([[0, 0]], 5)
    d2 = (g[indices] ** 2).sum(axis=1)
    assert len(indices) == 81 and np.sum(d2 == 25) == 12 and d2.max() == 25
    # The four corners of a cell tie as nearest to its centre: ordered by index.
    four = tri.nearest([[0.5, 0.5]], k=4)[0]
    assert list(four) == sorted(four)
    assert set(map(tuple, g[four])) == {(0, 0), (1, 0), (0, 1), (1, 1)}


def test_bad_input():
    tri = exidel.Delaunay(np.random.default_rng(1).random((30, 2)))
    for r in (-1, np.nan, np.inf):
        with pytest.raises(ValueError, match="r must be"):
            tri.within_radius([[0.5, 0.5]], r)
    for k in (-1, 2.5, True):
        with pytest.raises(ValueError, match="k must be"):
            tri.nearest([[0.5, 0.5]], k=k)
    with pytest.raises(ValueError, match="row 0"):
        tri.nearest([[np.nan, 0.5]], k=2)
