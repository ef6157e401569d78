"""exidel._core.MutableTriangulation (the C++ MutableTriangulation under
Delaunay.add_points): points inserted and removed, every state certified exactly and
compared with scipy in general position; copies of a point; bad ids and points."""

import numpy as np
import pytest
import scipy.spatial

import exidel
from exidel import _core


def triangle_set(simplices, ids=None):
    rows = simplices if ids is None else ids[simplices]
    return {tuple(sorted(t)) for t in rows.tolist()}


def certified(snapshot):
    c = exidel.certify(snapshot["points"], {"triangles": snapshot["triangles"].reshape(-1),
                                            "halfedges": snapshot["halfedges"],
                                            "hull": snapshot["hull"]}, reorient=False)
    return c.ok


def test_insert_and_remove_match_scipy_in_general_position():
    rng = np.random.default_rng(11)
    pts = rng.random((400, 2))
    m = _core.MutableTriangulation(pts[:100])
    ids = list(range(100)) + list(m.insert(pts[100:]))
    assert ids == list(range(400)) and len(m) == 400
    removed = rng.choice(400, size=150, replace=False)
    m.remove(removed)
    s = m.snapshot()
    keep = np.setdiff1d(np.arange(400), removed)
    np.testing.assert_array_equal(s["ids"], keep)
    np.testing.assert_array_equal(s["points"], pts[keep])
    assert certified(s)
    theirs = scipy.spatial.Delaunay(pts[keep])
    assert triangle_set(s["triangles"], s["ids"]) == triangle_set(theirs.simplices, keep)


def test_degenerate_sets_stay_delaunay():
    # A lattice (every cell cocircular) and a circle with its centre, changed at random.
    rng = np.random.default_rng(2)
    grid = np.stack(np.meshgrid(np.arange(12.0), np.arange(12.0)), axis=-1).reshape(-1, 2)
    angles = [(3, 4), (4, 3), (5, 0), (0, 5)]
    circle = np.array([(sx * a, sy * b) for a, b in angles for sx in (1, -1)
                       for sy in (1, -1)], dtype=np.float64)
    for pts in (grid, np.concatenate([[[0.0, 0.0]], np.unique(circle, axis=0)])):
        m = _core.MutableTriangulation(np.empty((0, 2)))
        ids = m.insert(pts)
        for _ in range(3):
            gone = rng.choice(ids, size=len(ids) // 3, replace=False)
            m.remove(gone)
            assert certified(m.snapshot())
            ids = np.concatenate([np.setdiff1d(ids, gone), m.insert(pts[gone % len(pts)])])
            assert certified(m.snapshot())


def test_copies_of_a_point_and_bad_ids():
    m = _core.MutableTriangulation([[0, 0], [1, 0], [0, 1], [1, 1]])
    a, b = m.insert([[1, 1], [1, 1]])
    assert (a, b) == (4, 5) and len(m) == 6
    s = m.snapshot()
    assert len(s["duplicates"]) == 2 and len(s["triangles"]) == 2
    m.remove([3, 4])
    s = m.snapshot()
    assert list(s["ids"]) == [0, 1, 2, 5] and len(s["triangles"]) == 2  # 5 keeps the point
    with pytest.raises(IndexError, match="was removed"):
        m.remove([3])
    with pytest.raises(IndexError, match="never issued"):
        m.remove([99])
    with pytest.raises(ValueError, match="not finite"):
        m.insert([[np.nan, 0.0]])
    assert len(m) == 4


def test_public_class_inserts_removes_and_answers_queries():
    rng = np.random.default_rng(21)
    pts = rng.random((300, 2))
    m = exidel.MutableTriangulation(pts[:100])
    assert len(m) == 100 and "100 live points" in repr(m)
    assert m.insert(pts[100]) == 100  # one point: an int
    np.testing.assert_array_equal(m.insert(pts[101:]), np.arange(101, 300))
    m.remove([5, 7])
    m.remove(9)
    keep = np.setdiff1d(np.arange(300), [5, 7, 9])
    np.testing.assert_array_equal(m.ids, keep)
    np.testing.assert_array_equal(m.points, pts[keep])
    tri = m.delaunay()
    assert isinstance(tri, exidel.Delaunay) and tri.npoints == len(keep)
    assert exidel.certify(tri.points, tri).ok
    theirs = scipy.spatial.Delaunay(pts[keep])
    assert triangle_set(tri.simplices) == triangle_set(theirs.simplices)
    xi = rng.random((50, 2))
    np.testing.assert_array_equal(tri.find_simplex(xi) >= 0, theirs.find_simplex(xi) >= 0)
    np.testing.assert_array_equal(keep[tri.nearest(xi)],
                                  keep[scipy.spatial.cKDTree(pts[keep]).query(xi)[1]])
    with pytest.raises(IndexError):
        m.remove(5)
    with pytest.raises(ValueError):
        m.insert([np.nan, 0.5])
    with pytest.raises(TypeError):
        m.remove([1.5])
    assert len(exidel.MutableTriangulation()) == 0
