"""exidel.LinearNDInterpolator, NearestNDInterpolator, griddata and Delaunay.nearest:
against scipy.interpolate on general-position input, and exact on vertices, edges and
equidistant queries."""

import numpy as np
import pytest
import scipy.interpolate
import scipy.spatial

import exidel


def general_position(seed=2, n=2000, q=3000):
    rng = np.random.default_rng(seed)
    pts = rng.random((n, 2))
    values = np.sin(6 * pts[:, 0]) + pts[:, 1] ** 2
    xi = rng.random((q, 2)) * 1.2 - 0.1
    return pts, values, xi


def test_linear_matches_scipy():
    pts, values, xi = general_position()
    ours = exidel.LinearNDInterpolator(pts, values)(xi)
    theirs = scipy.interpolate.LinearNDInterpolator(pts, values)(xi)
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
    np.testing.assert_allclose(ours, theirs, rtol=1e-12, atol=1e-12, equal_nan=True)
    # fill_value, vector values, x and y given apart, a Delaunay object reused.
    tri = exidel.Delaunay(pts)
    vec = np.stack([values, 2 * values, values + 1j], axis=1)
    ip = exidel.LinearNDInterpolator(tri, vec, fill_value=-7)
    got = ip(xi[:, 0], xi[:, 1])
    want = scipy.interpolate.LinearNDInterpolator(pts, vec, fill_value=-7)(xi)
    assert got.shape == (len(xi), 3) and got.dtype == np.complex128
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12)
    assert ip.tri is tri


def test_rescale_matches_scipy():
    rng = np.random.default_rng(4)
    pts = rng.random((500, 2)) * np.array([1e6, 1.0])
    values = pts[:, 0] * 1e-6 + pts[:, 1]
    xi = rng.random((800, 2)) * np.array([1e6, 1.0])
    ours = exidel.LinearNDInterpolator(pts, values, rescale=True)(xi)
    theirs = scipy.interpolate.LinearNDInterpolator(pts, values, rescale=True)(xi)
    np.testing.assert_allclose(ours, theirs, rtol=1e-10, atol=1e-12, equal_nan=True)


def test_linear_is_exact_on_vertices_and_edges():
    g = np.arange(6, dtype=np.float64)
    pts = np.stack(np.meshgrid(g, g), axis=-1).reshape(-1, 2)
    values = 3 * pts[:, 0] - 2 * pts[:, 1] + 0.1 * pts[:, 0] * pts[:, 1]
    ip = exidel.LinearNDInterpolator(pts, values)
    np.testing.assert_array_equal(ip(pts), values)  # every vertex, exactly
    # Midpoints of axis edges: the mean of the two ends, whatever the triangles.
    a = np.flatnonzero(pts[:, 0] < 5)  # pts[a + 1] is pts[a] + (1, 0)
    np.testing.assert_array_equal(pts[a + 1] - pts[a], np.tile([1.0, 0.0], (len(a), 1)))
    mid = pts[a] + np.array([0.5, 0.0])
    np.testing.assert_allclose(ip(mid), (values[a] + values[a + 1]) / 2, rtol=0, atol=1e-14)
    assert np.isnan(ip([[6.0, 6.0]])).all()


def test_linear_on_collinear_points():
    pts = np.array([[0, 0], [1, 1], [3, 3]], dtype=float)
    ip = exidel.LinearNDInterpolator(pts, np.array([0.0, 1.0, 5.0]))
    np.testing.assert_allclose(ip([[0.5, 0.5], [2, 2], [1, 1]]), [0.5, 3.0, 1.0])
    assert np.isnan(ip([[0, 1]])).all()


def test_nearest_is_exact():
    pts, values, xi = general_position(seed=6)
    tri = exidel.Delaunay(pts)
    nearest = tri.nearest(xi)
    d_ours = ((pts[nearest] - xi) ** 2).sum(axis=1)
    d_best, _ = scipy.spatial.cKDTree(pts).query(xi)
    np.testing.assert_allclose(d_ours, d_best ** 2, rtol=1e-12)
    # Equidistant queries on a lattice: the cell centres are equally near four points.
    g = np.arange(4, dtype=np.float64)
    lattice = np.stack(np.meshgrid(g, g), axis=-1).reshape(-1, 2)
    centres = lattice[lattice.max(axis=1) < 3] + 0.5
    n = exidel.Delaunay(lattice).nearest(centres)
    np.testing.assert_array_equal(((lattice[n] - centres) ** 2).sum(axis=1), 0.5)
    np.testing.assert_array_equal(exidel.Delaunay(lattice).nearest(lattice),
                                  np.arange(len(lattice)))


def test_griddata_matches_scipy():
    pts, values, xi = general_position(seed=8, n=500, q=700)
    for method in ("linear", "nearest"):
        ours = exidel.griddata(pts, values, xi, method=method)
        theirs = scipy.interpolate.griddata(pts, values, xi, method=method)
        np.testing.assert_allclose(ours, theirs, rtol=1e-12, atol=1e-12, equal_nan=True)
    gx, gy = np.mgrid[0:1:20j, 0:1:30j]
    assert exidel.griddata(pts, values, (gx, gy)).shape == (20, 30)
    with pytest.raises(NotImplementedError, match="cubic"):
        exidel.griddata(pts, values, xi, method="cubic")
    with pytest.raises(ValueError, match="Unknown"):
        exidel.griddata(pts, values, xi, method="spline")


def test_bad_input():
    pts, values, xi = general_position(n=50, q=5)
    with pytest.raises(ValueError, match="different number"):
        exidel.LinearNDInterpolator(pts, values[:-1])
    ip = exidel.LinearNDInterpolator(pts, values)
    with pytest.raises(ValueError, match="row 0"):
        ip([[np.nan, 0.5]])
    with pytest.raises(ValueError, match="rescale"):
        exidel.LinearNDInterpolator(exidel.Delaunay(pts), values, rescale=True)
