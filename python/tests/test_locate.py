"""exidel.Delaunay.locate and find_simplex: exact point location, against scipy on general
position and against exact orientation tests (exidel.orient2d) on degenerate queries."""

import numpy as np
import pytest
import scipy.spatial

import exidel


def triangle_sets(simplices, rows):
    return np.sort(simplices[rows], axis=1)


def test_find_simplex_matches_scipy_in_general_position():
    rng = np.random.default_rng(3)
    pts = rng.random((3000, 2))
    q = rng.random((5000, 2)) * 1.2 - 0.1
    ours = exidel.Delaunay(pts)
    theirs = scipy.spatial.Delaunay(pts)
    a, b = ours.find_simplex(q), theirs.find_simplex(q)
    assert a.dtype == b.dtype and a.shape == b.shape
    np.testing.assert_array_equal(a == -1, b == -1)
    inside = a >= 0
    np.testing.assert_array_equal(triangle_sets(ours.simplices, a[inside]),
                                  triangle_sets(theirs.simplices, b[inside]))
    # scipy's keywords are accepted and change nothing.
    np.testing.assert_array_equal(ours.find_simplex(q, bruteforce=True, tol=1e-3), a)


def exact_kind(points, tri, q):
    """The classification of q by brute force over every triangle, with exact orient2d."""
    s = tri.simplices
    a, b, c = points[s[:, 0]], points[s[:, 1]], points[s[:, 2]]
    qq = np.broadcast_to(q, a.shape)
    o = np.stack([exidel.orient2d(a, b, qq), exidel.orient2d(b, c, qq),
                  exidel.orient2d(c, a, qq)], axis=1)
    holding = (o >= 0).all(axis=1)
    if not holding.any():
        return 3, set()
    zeros = (o[holding] == 0).sum(axis=1)
    return {0: 0, 1: 1, 2: 2}[int(zeros.max())], set(np.flatnonzero(holding))


def test_locate_is_exact_on_a_lattice():
    # Every half-step query of a lattice is on a vertex, on an edge or outside: scipy's
    # eps test may call some of them outside or miss the edge; exidel decides exactly.
    g = np.arange(12, dtype=np.float64)
    pts = np.stack(np.meshgrid(g, g), axis=-1).reshape(-1, 2)
    tri = exidel.Delaunay(pts)
    h = np.arange(-1, 24) * 0.5
    q = np.stack(np.meshgrid(h, h), axis=-1).reshape(-1, 2)
    where = tri.locate(q)
    for i in range(len(q)):
        kind, holding = exact_kind(pts, tri, q[i])
        assert where.kind[i] == kind, (q[i], where.kind[i], kind)
        if kind != 3:
            assert where.simplex[i] in holding
        if kind == 2:
            assert (pts[where.vertex[i]] == q[i]).all()
        if kind == 1:
            e = where.edge[i]
            assert e // 3 == where.simplex[i]
            u = tri.simplices.flat[e]
            v = tri.simplices.flat[3 * (e // 3) + (e % 3 + 1) % 3]
            assert exidel.orient2d(pts[u], pts[v], q[i]) == 0
    counts = np.bincount(where.kind, minlength=4)
    assert counts[2] == 144
    assert counts[3] == 25 * 25 - 23 * 23  # the half steps beyond the hull
    # Axis edges' midpoints and the cells' centres (on the diagonal each cell got).
    assert counts[1] == 2 * 11 * 12 + 11 * 11 and counts[0] == 0
    assert set(where.kind_names()) == {"on_edge", "on_vertex", "outside"}
    # find_simplex finds every query of the hull, edges and vertices included.
    fs = tri.find_simplex(q)
    np.testing.assert_array_equal(fs == -1, where.kind == 3)


def test_locate_answers_do_not_depend_on_order_or_threads():
    rng = np.random.default_rng(5)
    pts = rng.random((20000, 2))
    q = np.concatenate([rng.random((20000, 2)), pts[:3000]])
    tri = exidel.Delaunay(pts)
    base = tri.locate(q, threads=1)
    for order, threads in [("hilbert", 2), ("given", 1), ("jump", 2)]:
        other = tri.locate(q, order=order, threads=threads)
        np.testing.assert_array_equal(other.kind, base.kind)
        np.testing.assert_array_equal(other.vertex, base.vertex)
    np.testing.assert_array_equal(tri.locate(q, threads=2).simplex, base.simplex)
    assert (base.kind[-3000:] == 2).all()
    np.testing.assert_array_equal(base.vertex[-3000:], np.arange(3000))


def test_shapes_duplicates_and_collinear_points():
    pts = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [1, 1]], dtype=float)
    tri = exidel.Delaunay(pts)
    q = np.array([[[0.5, 0.5], [1, 1]], [[2, 2], [0.25, 0.25]]])
    assert tri.find_simplex(q).shape == (2, 2)
    where = tri.locate(q)
    assert where.kind.shape == (2, 2)
    assert where.kind[0, 1] == 2 and where.vertex[0, 1] == 3  # the first of the two copies
    assert where.kind[1, 0] == 3
    assert tri.find_simplex([0.25, 0.25]).shape == ()

    line = exidel.Delaunay(np.array([[0, 0], [1, 1], [2, 2]], dtype=float))
    assert line.collinear
    w = line.locate(np.array([[0.5, 0.5], [1, 1], [3, 3], [0, 1]]))
    np.testing.assert_array_equal(w.kind, [1, 2, 3, 3])
    np.testing.assert_array_equal(w.simplex, [-1, -1, -1, -1])
    np.testing.assert_array_equal(line.find_simplex([[0.5, 0.5]]), [-1])


def test_bad_queries_are_clear_errors():
    tri = exidel.Delaunay(np.random.default_rng(1).random((50, 2)))
    with pytest.raises(ValueError, match="row 1"):
        tri.find_simplex(np.array([[0.5, 0.5], [np.nan, 0.5]]))
    with pytest.raises(ValueError, match="xi"):
        tri.find_simplex(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="order"):
        tri.locate([[0.5, 0.5]], order="random")


def test_locate_follows_add_points():
    rng = np.random.default_rng(9)
    tri = exidel.Delaunay(rng.random((100, 2)), incremental=True)
    far = np.array([[5.0, 5.0]])
    assert tri.find_simplex(far)[0] == -1
    tri.add_points(np.array([[6.0, 6.0], [6.0, 4.0], [4.0, 6.0]]))
    assert tri.find_simplex(far)[0] >= 0


def test_furthest_site_matches_scipy():
    rng = np.random.default_rng(12)
    pts = rng.random((400, 2))
    ours = exidel.Delaunay(pts, furthest_site=True)
    theirs = scipy.spatial.Delaunay(pts, furthest_site=True)
    assert ours.furthest_site
    as_set = lambda s: {tuple(sorted(row)) for row in s.tolist()}
    assert as_set(ours.simplices) == as_set(theirs.simplices)
    # Every point on or inside every triangle's circumcircle, decided exactly.
    s = ours.simplices
    for p in pts[::7]:
        q = np.broadcast_to(p, (len(s), 2))
        assert (exidel.incircle(pts[s[:, 0]], pts[s[:, 1]], pts[s[:, 2]], q) >= 0).all()
    # qhull's "Qu" asks for the same; locate works on it too.
    np.testing.assert_array_equal(exidel.Delaunay(pts, qhull_options="Qu").simplices,
                                  ours.simplices)
    assert (ours.find_simplex(pts[ours.hull]) >= 0).all()


def test_furthest_site_on_cocircular_and_collinear_points():
    angles = np.arange(12) * (np.pi / 6)
    circle = np.round(np.stack([np.cos(angles), np.sin(angles)], axis=1) * 5)
    square = np.array([[0, 0], [2, 0], [2, 2], [0, 2], [1, 1], [1, 0]], dtype=float)
    tri = exidel.Delaunay(square, furthest_site=True)
    assert tri.nsimplex == 2 and sorted(tri.hull.tolist()) == [0, 1, 2, 3]
    assert exidel.Delaunay(circle, furthest_site=True).nsimplex >= 1
    line = exidel.Delaunay(np.array([[0, 0], [1, 1], [2, 2]], dtype=float), furthest_site=True)
    assert line.collinear and line.nsimplex == 0
