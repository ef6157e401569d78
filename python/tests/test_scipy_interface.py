"""The rest of scipy.spatial.Delaunay's and Voronoi's interface for the plane, against
scipy's own answers: transform, equations, paraboloid_scale/shift, lift_points,
plane_distance, vertex_to_simplex, ridge_dict, qhull_options, incremental mode."""

from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial

import exidel


def sets(rng):
    """General-position inputs: the unit square, a box away from the origin, a wide one."""
    yield rng.random((400, 2))
    yield rng.random((300, 2)) * [3.0, 7.0] + [40.0, -20.0]
    yield (rng.random((200, 2)) - 0.5) * 1e6


def row_map(ours, theirs):
    """For each of our triangles, the row of scipy's with the same three vertices."""
    index = {tuple(sorted(t)): i for i, t in enumerate(theirs.simplices.tolist())}
    rows = [index.get(tuple(sorted(t)), -1) for t in ours.simplices.tolist()]
    assert -1 not in rows and len(rows) == theirs.nsimplex
    return np.array(rows)


def barycentric_by_vertex(tri, x):
    """The barycentric coordinates of x[i] in triangle i, through tri.transform, ordered by
    vertex index (so that they compare across vertex orders)."""
    t = tri.transform
    c = np.einsum("mij,mj->mi", t[:, :2], x - t[:, 2])
    full = np.concatenate([c, 1 - c.sum(axis=1, keepdims=True)], axis=1)
    return np.take_along_axis(full, np.argsort(tri.simplices, axis=1), axis=1)


def test_paraboloid_scale_and_shift_are_scipys(rng):
    for pts in sets(rng):
        ours, theirs = exidel.Delaunay(pts), scipy.spatial.Delaunay(pts)
        assert ours.paraboloid_scale == pytest.approx(theirs.paraboloid_scale, rel=1e-15)
        assert ours.paraboloid_shift == pytest.approx(theirs.paraboloid_shift, rel=1e-15)
        assert ours.paraboloid_scale != 1.0
        # Without Qz qhull adds no point at infinity; without Qbb nothing is scaled.
        for options in ("Qbb Qc Q12", "Qc Qz", "Qbb Qz Qt"):
            ours = exidel.Delaunay(pts, qhull_options=options)
            theirs = scipy.spatial.Delaunay(pts, qhull_options=options)
            assert ours.paraboloid_scale == pytest.approx(theirs.paraboloid_scale, rel=1e-15)
            assert ours.paraboloid_shift == pytest.approx(theirs.paraboloid_shift, rel=1e-15,
                                                          abs=0.0)


def test_lift_points_is_scipys(rng):
    for pts in sets(rng):
        ours, theirs = exidel.Delaunay(pts), scipy.spatial.Delaunay(pts)
        x = pts[:7] * 1.5
        np.testing.assert_allclose(ours.lift_points(x), theirs.lift_points(x), rtol=1e-15)
        grid = np.stack(np.meshgrid(np.arange(3.0), np.arange(4.0)), axis=-1)
        assert ours.lift_points(grid).shape == (4, 3, 3)
        np.testing.assert_allclose(ours.lift_points(grid), theirs.lift_points(grid), rtol=1e-15)
    with pytest.raises(ValueError, match="shape"):
        ours.lift_points(np.zeros((3, 3)))


def test_transform_is_scipys(rng):
    for pts in sets(rng):
        ours, theirs = exidel.Delaunay(pts), scipy.spatial.Delaunay(pts)
        t = ours.transform
        assert t.shape == (ours.nsimplex, 3, 2) and t.dtype == np.float64
        assert ours.transform is t  # built once
        # The definition: r is the last vertex, and T^-1 (p_j - r) = e_j.
        np.testing.assert_array_equal(t[:, 2], pts[ours.simplices[:, 2]])
        for j, e in ((0, [1, 0]), (1, [0, 1])):
            c = np.einsum("mij,mj->mi", t[:, :2], pts[ours.simplices[:, j]] - t[:, 2])
            np.testing.assert_allclose(c, np.broadcast_to(e, c.shape), atol=1e-9)
        # scipy's coordinates of the same points in the same triangles.
        rows = row_map(ours, theirs)
        x = pts[ours.simplices].mean(axis=1) + (rng.random((ours.nsimplex, 2)) - 0.5) * 1e-3
        x_theirs = np.empty_like(x)
        x_theirs[rows] = x
        np.testing.assert_allclose(barycentric_by_vertex(ours, x),
                                   barycentric_by_vertex(theirs, x_theirs)[rows], atol=1e-9)


def test_transform_of_a_thin_triangle_is_accurate():
    # One ulp off a line: a d - b c of the (exact) differences cancels completely in
    # doubles, where the error-free products keep every digit.
    pts = np.array([[0.6401116518525249, 0.09341157025565983],
                    [0.9758270244710884, 0.5184671299080237],
                    [1.330092837949231, 0.9670097523060226]])
    tri = exidel.Delaunay(pts)
    assert tri.nsimplex == 1
    t = tri.transform[0]
    assert np.isfinite(t).all()
    s = tri.simplices[0]
    r = [Fraction(v) for v in pts[s[2]]]
    cols = [[Fraction(v) - w for v, w in zip(pts[s[j]], r)] for j in (0, 1)]
    a, b, c, d = cols[0][0], cols[1][0], cols[0][1], cols[1][1]
    det = a * d - b * c
    exact = [[d / det, -b / det], [-c / det, a / det]]
    for i in range(2):
        for j in range(2):
            assert abs(Fraction(t[i, j]) - exact[i][j]) <= abs(exact[i][j]) * 2.0 ** -50


def test_transform_and_equations_scale_with_the_input(rng):
    # Scaling by a power of two is exact: the transforms scale exactly, even where the
    # determinant itself would overflow (2^500) or underflow (2^-900) in doubles.
    # (The lexicographic order gives the same triangles in the same order at every scale.)
    pts = rng.random((60, 2))
    base = exidel.Delaunay(pts, order="lexicographic")
    for k in (500, -900):
        tri = exidel.Delaunay(np.ldexp(pts, k), order="lexicographic")
        np.testing.assert_array_equal(tri.simplices, base.simplices)
        np.testing.assert_array_equal(tri.transform[:, :2], np.ldexp(base.transform[:, :2], -k))
        np.testing.assert_array_equal(tri.transform[:, 2], np.ldexp(base.transform[:, 2], k))
    # With Qbb the lifted points scale by 2^k too: the same normals, offsets times 2^k,
    # where the plain cross product overflows (2^500) or underflows (2^-500).
    for k in (500, -500):
        tri = exidel.Delaunay(np.ldexp(pts, k), order="lexicographic")
        assert np.isfinite(tri.equations).all()
        np.testing.assert_allclose(tri.equations[:, :3], base.equations[:, :3], rtol=1e-14)
        np.testing.assert_allclose(tri.equations[:, 3], np.ldexp(base.equations[:, 3], k),
                                   rtol=1e-14)


def test_equations_and_plane_distance_are_scipys(rng):
    for pts in sets(rng):
        ours, theirs = exidel.Delaunay(pts), scipy.spatial.Delaunay(pts)
        rows = row_map(ours, theirs)
        eq = ours.equations
        assert eq.shape == (ours.nsimplex, 4) and ours.equations is eq
        scale = np.abs(theirs.equations).max()
        np.testing.assert_allclose(eq, theirs.equations[rows], rtol=0, atol=1e-10 * scale)
        np.testing.assert_allclose(np.linalg.norm(eq[:, :3], axis=1), 1.0, rtol=1e-14)
        assert (eq[:, 2] < 0).all()
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        xi = lo + (hi - lo) * rng.random((5, 4, 2))
        d = ours.plane_distance(xi)
        assert d.shape == (5, 4, ours.nsimplex)
        expected = theirs.plane_distance(xi)[..., rows]
        np.testing.assert_allclose(d, expected, rtol=0, atol=1e-10 * np.abs(expected).max())
        # Delaunay: every lifted input point lies on or above every triangle's plane, and
        # on the planes of its own triangles.
        own = ours.plane_distance(pts)
        assert own.max() <= 1e-12 * np.abs(own).max()
        corners = own[ours.simplices, np.arange(ours.nsimplex)[:, None]]
        assert np.abs(corners).max() <= 1e-12 * np.abs(own).max()
    with pytest.raises(ValueError, match="dimensionality"):
        ours.plane_distance(np.zeros((2, 3)))


def test_vertex_to_simplex_holds_the_vertex(rng):
    for pts in sets(rng):
        ours, theirs = exidel.Delaunay(pts), scipy.spatial.Delaunay(pts)
        v = ours.vertex_to_simplex
        assert v.shape == (ours.npoints,) and v.dtype == np.int32
        assert ours.vertex_to_simplex is v
        assert (v >= 0).all() and (theirs.vertex_to_simplex >= 0).all()
        assert (ours.simplices[v] == np.arange(ours.npoints)[:, None]).any(axis=1).all()


def test_duplicates_collinear_and_three_points(rng):
    pts = np.concatenate([rng.random((50, 2)), [[0.5, 0.5]], [[0.5, 0.5]]])
    pts = np.concatenate([pts, pts[:5]])
    tri = exidel.Delaunay(pts)
    v = tri.vertex_to_simplex
    assert set(np.flatnonzero(v < 0)) == set(tri.duplicates.tolist()) == {51, 52, 53, 54, 55, 56}
    ok = v >= 0
    assert (tri.simplices[v[ok]] == np.flatnonzero(ok)[:, None]).any(axis=1).all()

    line = np.stack([np.arange(10.0), 2 * np.arange(10.0) + 1], axis=1)
    for pts in (line, line[:2], line[:1]):
        tri = exidel.Delaunay(pts)
        assert tri.collinear and tri.nsimplex == 0
        assert tri.transform.shape == (0, 3, 2) and tri.transform.dtype == np.float64
        assert tri.equations.shape == (0, 4)
        np.testing.assert_array_equal(tri.vertex_to_simplex, np.full(len(pts), -1))
        assert tri.plane_distance(np.zeros((4, 2))).shape == (4, 0)
        assert tri.lift_points(pts).shape == (len(pts), 3)
        assert np.isfinite([tri.paraboloid_scale, tri.paraboloid_shift]).all()

    three = np.array([[0.0, 0.0], [2.0, 0.5], [0.7, 1.9]])
    ours, theirs = exidel.Delaunay(three), scipy.spatial.Delaunay(three)
    assert ours.paraboloid_scale == pytest.approx(theirs.paraboloid_scale, rel=1e-15)
    np.testing.assert_allclose(ours.equations, theirs.equations, atol=1e-14)
    x = np.array([[0.9, 0.8]])
    np.testing.assert_allclose(barycentric_by_vertex(ours, x), barycentric_by_vertex(theirs, x),
                               atol=1e-14)
    np.testing.assert_allclose(ours.plane_distance(x), theirs.plane_distance(x), atol=1e-14)

    # All points at the origin lift to one height: qhull cannot scale; exidel does not.
    origin = exidel.Delaunay(np.zeros((3, 2)))
    assert (origin.paraboloid_scale, origin.paraboloid_shift) == (1.0, 0.0)


def test_ridge_dict_is_scipys(rng):
    for pts in sets(rng):
        ours, theirs = exidel.Voronoi(pts), scipy.spatial.Voronoi(pts)
        rd = ours.ridge_dict
        assert ours.ridge_dict is rd
        assert len(rd) == len(ours.ridge_points)
        for (p, q), value in zip(ours.ridge_points.tolist(), ours.ridge_vertices):
            assert rd[(p, q)] is value
        # The vertex numbering may differ from scipy's: compare through the geometry.
        dist, nearest = scipy.spatial.cKDTree(theirs.vertices).query(ours.vertices)
        assert dist.max() <= 1e-9 * max(1.0, np.abs(theirs.vertices).max())
        ours_geo = {frozenset(k): frozenset(-1 if v < 0 else int(nearest[v]) for v in value)
                    for k, value in rd.items()}
        theirs_geo = {frozenset(k): frozenset(value) for k, value in theirs.ridge_dict.items()}
        assert ours_geo == theirs_geo
    line = np.stack([np.arange(5.0), np.zeros(5)], axis=1)
    assert exidel.Voronoi(line).ridge_dict == {(i, i + 1): [-1, -1] for i in range(4)}


SILENT = ["Qbb", "Qc", "Qz", "Qt", "QJ", "QJ0.001", "Qx", "Q11", "Q12", "Pp",
          "Qbb Qc Qz Q12", "Qbb Qc Qz Qx Q12 Qt QJ Pp"]


@pytest.mark.parametrize("options", SILENT)
def test_qhull_options_that_change_nothing_are_accepted(rng, options):
    pts = rng.random((100, 2))
    plain = exidel.Delaunay(pts)
    tri = exidel.Delaunay(pts, qhull_options=options)
    np.testing.assert_array_equal(tri.simplices, plain.simplices)
    vor = exidel.Voronoi(pts, qhull_options=options)
    np.testing.assert_array_equal(vor.vertices, exidel.Voronoi(pts).vertices)
    scipy.spatial.Delaunay(pts, qhull_options=options)  # real qhull options, all of them


@pytest.mark.parametrize("option", ["QbB", "Qbk:0Bk:0", "QG4", "QV0", "Qfoo", "Fx", "TO"])
def test_other_qhull_options_raise_naming_the_option(rng, option):
    pts = rng.random((20, 2))
    # Both take Qu as furthest_site=True (test_locate.py, test_voronoi.py).
    for cls in (exidel.Delaunay, exidel.Voronoi):
        with pytest.raises(ValueError, match=f"'{option}'"):
            cls(pts, qhull_options=f"Qbb {option} Qc")
    with pytest.raises(TypeError, match="str"):
        exidel.Delaunay(pts, qhull_options=b"Qbb")


def scipy_error(call):
    try:
        call()
    except Exception as error:  # noqa: BLE001 - the type and message are what is compared
        return type(error), str(error)
    raise AssertionError("scipy raised nothing")


def test_incremental_errors_are_scipys(rng):
    pts, more = rng.random((30, 2)), rng.random((5, 2))
    for cls, scipy_cls in ((exidel.Delaunay, scipy.spatial.Delaunay),
                           (exidel.Voronoi, scipy.spatial.Voronoi)):
        kind, message = scipy_error(lambda: scipy_cls(pts).add_points(more))
        assert kind is RuntimeError
        with pytest.raises(kind, match=message):
            cls(pts).add_points(more)
        closed = cls(pts, incremental=True)
        closed.close()
        closed.close()
        with pytest.raises(RuntimeError, match=message):
            closed.add_points(more)
        for bad in (more[0], np.zeros((2, 3))):
            kind, message = scipy_error(
                lambda: scipy_cls(pts, incremental=True).add_points(bad))
            with pytest.raises(kind, match=message):
                cls(pts, incremental=True).add_points(bad)
        for options in ("Qbb", "Qz Qc", "QbB"):
            kind, message = scipy_error(
                lambda: scipy_cls(pts, incremental=True, qhull_options=options))
            assert kind is ValueError and "incompatible with incremental mode" in message
            with pytest.raises(ValueError, match="incompatible with incremental mode"):
                cls(pts, incremental=True, qhull_options=options)


def test_incremental_delaunay_is_the_triangulation_of_all_points(rng):
    pts, more, last = rng.random((200, 2)), rng.random((40, 2)), rng.random((7, 2)) + 0.5
    tri = exidel.Delaunay(pts, incremental=True)
    theirs = scipy.spatial.Delaunay(pts, incremental=True)
    # Fill every cache, so that a stale one would show.
    before = (tri.neighbors, tri.transform, tri.equations, tri.vertex_to_simplex,
              tri.convex_hull, tri.paraboloid_scale)
    tri.add_points(more)
    theirs.add_points(more)
    tri.add_points(last, restart=True)
    theirs.add_points(last, restart=True)
    tri.add_points(np.empty((0, 2)))
    everything = np.concatenate([pts, more, last])
    fresh = exidel.Delaunay(everything)
    np.testing.assert_array_equal(tri.points, everything)
    assert tri.npoints == len(everything) == theirs.npoints
    # The same triangles as a fresh triangulation (points are inserted into the existing
    # one, so the rows come in another order), and every cache rebuilt from them.
    rows = row_map(tri, fresh)
    assert row_map(tri, theirs).size == theirs.nsimplex
    assert tri.nsimplex > len(before[0])
    for t, j in zip(*np.nonzero(tri.neighbors >= 0)):  # each neighbour, by the vertex it faces
        k = tri.neighbors[t, j]
        v = tri.simplices[t, j]
        fj = list(fresh.simplices[rows[t]]).index(v)
        assert fresh.neighbors[rows[t], fj] == rows[k]
    assert (tri.neighbors < 0).sum() == (fresh.neighbors < 0).sum()  # the hull edges
    x = np.repeat(everything[:1], tri.nsimplex, axis=0) * 0.5 + 0.25
    np.testing.assert_allclose(barycentric_by_vertex(tri, x),
                               barycentric_by_vertex(fresh, x)[rows], atol=1e-9)
    assert {tuple(sorted(e)) for e in tri.convex_hull.tolist()} == \
        {tuple(sorted(e)) for e in fresh.convex_hull.tolist()}
    for v, t in enumerate(tri.vertex_to_simplex):
        assert v in tri.simplices[t]
    assert tri.stats["points"] == len(everything)
    # incremental mode has no Qbb: the lift is not scaled, in scipy as here.
    assert (tri.paraboloid_scale, tri.paraboloid_shift) == (1.0, 0.0)
    assert (theirs.paraboloid_scale, theirs.paraboloid_shift) == (1.0, 0.0)
    rows = row_map(tri, theirs)
    np.testing.assert_allclose(tri.equations, theirs.equations[rows], atol=1e-10)
    assert exidel.certify(everything, tri).ok
    # A bad point raises and leaves the triangulation as it was.
    with pytest.raises(ValueError):
        tri.add_points([[np.nan, 0.0]])
    assert tri.npoints == len(everything) and tri.nsimplex == fresh.nsimplex


def test_incremental_voronoi_is_the_diagram_of_all_points(rng):
    pts, more = rng.random((100, 2)), rng.random((30, 2))
    vor = exidel.Voronoi(pts, incremental=True)
    before = (vor.ridge_dict, vor.regions, vor.ridge_points)
    vor.add_points(more)
    fresh = exidel.Voronoi(np.concatenate([pts, more]))
    assert vor.npoints == 130 and len(vor.point_region) == 130
    np.testing.assert_array_equal(vor.vertices, fresh.vertices)
    assert vor.regions == fresh.regions and len(vor.regions) > len(before[1])
    assert vor.ridge_dict == fresh.ridge_dict and len(vor.ridge_dict) > len(before[0])
    vor.add_points(rng.random((3, 2)), restart=True)
    assert vor.npoints == 133 and len(vor.regions) == 133
