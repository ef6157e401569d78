"""exidel.Voronoi and exidel.circumcenter: correctly rounded vertices (checked in rational
arithmetic), exact cocircular groups, scipy's names, clipping, bad input."""

import math
from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial

import exidel


def exact_centre(a, b, c):
    (ax, ay), (bx, by), (cx, cy) = [(Fraction(float(p[0])), Fraction(float(p[1]))) for p in (a, b, c)]
    bx, by, cx, cy = bx - ax, by - ay, cx - ax, cy - ay
    d = 2 * (bx * cy - by * cx)
    ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d
    uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d
    return ax + ux, ay + uy


def nearest(x, exact):
    """Whether the double x is a nearest double to the rational `exact`."""
    err = abs(Fraction(x) - exact)
    return all(err <= abs(Fraction(n) - exact)
               for n in (math.nextafter(x, math.inf), math.nextafter(x, -math.inf)))


def test_vertices_are_correctly_rounded_and_match_scipy(rng):
    pts = rng.random((300, 2)) * 1e3 + 1e6  # far from the origin: rounding matters
    v = exidel.Voronoi(pts)
    s = scipy.spatial.Voronoi(pts)
    for t in range(0, len(v.simplices), 7):
        a, b, c = pts[v.simplices[t]]
        x, y = exact_centre(a, b, c)
        vx, vy = v.vertices[v.vertex_of_triangle[t]]
        assert nearest(vx, x) and nearest(vy, y)
    # The same ridges as scipy (no four cocircular points here), and vertices within
    # scipy's rounding error.
    ours = {frozenset(r) for r in v.ridge_points.tolist()}
    assert ours == {frozenset(r) for r in s.ridge_points.tolist()}
    assert len(v.vertices) == len(s.vertices)
    assert np.allclose(np.sort(v.vertices, axis=0), np.sort(s.vertices, axis=0), rtol=0, atol=1e-6)
    # regions: the same cells (as sets of vertex coordinates) for bounded regions.
    for i in range(0, 300, 13):
        mine = v.regions[v.point_region[i]]
        theirs = s.regions[s.point_region[i]]
        assert (-1 in mine) == (-1 in theirs)
        if -1 not in mine:
            assert np.allclose(np.sort(v.vertices[mine], axis=0),
                               np.sort(s.vertices[theirs], axis=0), rtol=0, atol=1e-6)


def test_cocircular_points_give_one_vertex():
    g = np.array([[i, j] for i in range(5) for j in range(5)], dtype=float)
    v = exidel.Voronoi(g)
    # The 4x4 grid cells' centres: each one vertex with exactly four sites.
    assert len(v.vertices) == 16
    assert all(len(s) == 4 for s in v.vertex_sites)
    assert v.stats["cocircular_merges"] == 16
    # Every ridge has positive length (the diagonals inside a square are not ridges).
    assert all(a != b for a, b in v.ridge_vertices)
    # A lattice circle: one vertex, its centre, with every point as a site.
    r = 65
    circle = np.array([(x, y) for x in range(-r, r + 1) for y in range(-r, r + 1)
                       if x * x + y * y == r * r], dtype=float) + [2.0 ** 40, 3.0]
    c = exidel.Voronoi(circle)
    assert c.vertices.tolist() == [[2.0 ** 40, 3.0]]
    assert len(c.vertex_sites[0]) == len(circle) and all(c.unbounded)


def test_unbounded_cells_and_rays(rng):
    pts = rng.random((100, 2))
    v = exidel.Voronoi(pts)
    hull = set(exidel.Delaunay(pts).hull.tolist())
    assert set(np.nonzero(v.unbounded)[0].tolist()) == hull
    for i in hull:
        assert v.regions[i][-1] == -1
        assert np.any(v.entry_ray[i] != 0) and np.any(v.exit_ray[i] != 0)
    inner = [i for i in range(100) if i not in hull]
    assert all((v.entry_ray[i] == 0).all() for i in inner)


def test_clip_to_a_box(rng):
    pts = rng.random((200, 2))
    v = exidel.Voronoi(pts)
    c = v.clip(0, 0, 1, 1)
    assert len(c.regions) == 200 and all(len(r) >= 3 for r in c.regions)
    assert (c.vertices >= 0).all() and (c.vertices <= 1).all()
    # The clipped cells tile the box: their areas sum to 1 (up to rounding of the shoelace).
    area = 0.0
    for r in c.regions:
        x, y = c.vertices[r, 0], c.vertices[r, 1]
        area += 0.5 * (np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    assert abs(area - 1) < 1e-12
    with pytest.raises(ValueError):
        v.clip(1, 0, 0, 1)
    with pytest.raises(ValueError):
        v.clip(0, 0, np.nan, 1)


def test_collinear_and_duplicates():
    line = np.array([[0.0, 0.0], [1.0, 1.0], [3.0, 3.0], [1.0, 1.0]])
    v = exidel.Voronoi(line)
    assert v.collinear and len(v.vertices) == 0
    assert v.chain.tolist() == [0, 1, 2]
    assert v.ridge_points.tolist() == [[0, 1], [1, 2]] and v.ridge_vertices == [[-1, -1]] * 2
    g = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 0.0]])
    d = exidel.Voronoi(g)
    assert d.regions[3] == d.regions[1]


def test_errors():
    with pytest.raises(ValueError, match="row 1"):
        exidel.Voronoi([[0, 0], [np.nan, 1], [1, 1]])
    # A nearly flat triangle of huge points: its centre is beyond the largest double.
    big = 2.0 ** 1020
    with pytest.raises(ValueError):
        exidel.Voronoi([[-big, 0.0], [big, 0.0], [0.0, 2.0 ** -1000]])
    with pytest.raises(exidel.TriangulationError):
        exidel.Voronoi(np.random.default_rng(3).random((1000, 2)), kernel="mpfr:2")
    with pytest.raises(ValueError, match="unknown algorithm 'fortune'"):
        exidel.Voronoi([[0, 0], [1, 0], [0, 1]], algorithm="fortune")
    with pytest.raises(ValueError, match="threads"):
        exidel.Voronoi([[0, 0], [1, 0], [0, 1]], threads=0)


@pytest.mark.parametrize("algorithm", exidel.algorithms)
def test_every_algorithm_gives_the_same_diagram(algorithm):
    g = np.array([[i, j] for i in range(6) for j in range(6)], dtype=float)
    pts = np.vstack([g, np.random.default_rng(4).random((50, 2)) * 5])
    reference = exidel.Voronoi(pts)
    v = exidel.Voronoi(pts, algorithm=algorithm, threads=2)
    # The same diagram up to the numbering of the vertices (by first triangle, and the
    # algorithms number triangles differently): each vertex with its sites, each cell.
    def canonical(d):
        vertices = {tuple(d.vertices[k]): tuple(sorted(d.vertex_sites[k]))
                    for k in range(len(d.vertices))}
        cells = [frozenset(tuple(d.vertices[k]) if k >= 0 else None for k in r) for r in d.regions]
        return vertices, cells
    assert len(v.vertices) == len(reference.vertices)
    assert canonical(v) == canonical(reference)


def test_circumcenter_rows(rng):
    a, b, c = rng.random((3, 200, 2)) * 1e-300
    centres, status = exidel.circumcenter(a, b, c)
    assert centres.shape == (200, 2) and (status == 0).all()
    for i in range(0, 200, 17):
        x, y = exact_centre(a[i], b[i], c[i])
        assert nearest(centres[i, 0], x) and nearest(centres[i, 1], y)
    one, st = exidel.circumcenter([0, 0], [2, 0], [0, 2])
    assert one.tolist() == [1.0, 1.0] and int(st) == 0
    _, st = exidel.circumcenter([[0, 0]], [1, 1], [2, 2])
    assert exidel.circumcenter_statuses[st[0]] == "collinear"


def test_list_attributes_are_lists_of_ints_built_once():
    pts = np.random.default_rng(8).random((300, 2))
    v = exidel.Voronoi(pts)
    assert v.regions is v.regions and v.ridge_vertices is v.ridge_vertices
    assert all(type(i) is int for r in v.regions for i in r)
    assert all(type(i) is int for s in v.vertex_sites for i in s)
    assert [r[-1] == -1 for r in v.regions] == [bool(u) for u in v.unbounded]
    assert all(len(s) >= 3 for s in v.vertex_sites)
    c = v.clip(0, 0, 1, 1)
    assert all(type(i) is int for r in c.regions for i in r)


def same_cycle(a, b):
    """Whether the lists are the same cycle (a rotation of each other)."""
    return len(a) == len(b) and any(a == b[k:] + b[:k] for k in range(len(b)))


def test_furthest_site_matches_scipy(rng):
    pts = rng.random((200, 2))
    ours = exidel.Voronoi(pts, furthest_site=True)
    theirs = scipy.spatial.Voronoi(pts, furthest_site=True)
    assert ours.furthest_site and "furthest-site" in repr(ours)
    assert len(ours.vertices) == len(theirs.vertices)
    # The same vertices (matched by nearest), each the correctly rounded centre of its
    # furthest-site triangles.
    match = [int(np.argmin(np.hypot(*(theirs.vertices - v).T))) for v in ours.vertices]
    assert sorted(match) == list(range(len(match)))
    np.testing.assert_allclose(ours.vertices, theirs.vertices[match], rtol=0, atol=1e-9)
    for t in range(len(ours.simplices)):
        x, y = exact_centre(*pts[ours.simplices[t]])
        vx, vy = ours.vertices[ours.vertex_of_triangle[t]]
        assert nearest(vx, x) and nearest(vy, y)
    ridge = lambda r: frozenset(r)  # noqa: E731
    assert {ridge(r) for r in ours.ridge_points.tolist()} == \
        {ridge(r) for r in theirs.ridge_points.tolist()}
    theirs_ridges = {ridge(p): sorted(v) for p, v in zip(theirs.ridge_points.tolist(),
                                                          theirs.ridge_vertices)}
    for p, v in zip(ours.ridge_points.tolist(), ours.ridge_vertices):
        assert sorted(-1 if w < 0 else match[w] for w in v) == theirs_ridges[ridge(p)]
    # Regions: the hull's corners only, unbounded, the same cycle of vertices (exidel's
    # counter-clockwise with -1 last; qhull's in its own direction).
    hull = set(scipy.spatial.ConvexHull(pts).vertices.tolist())
    for i in range(len(pts)):
        mine = ours.regions[ours.point_region[i]]
        other = theirs.regions[theirs.point_region[i]]
        assert bool(mine) == (i in hull) == bool(other)
        assert ours.unbounded[i] == (i in hull)
        if mine:
            assert mine[-1] == -1
            mapped = [-1 if w < 0 else match[w] for w in mine]
            assert same_cycle(mapped, other) or same_cycle(mapped[::-1], other)


def test_furthest_site_degenerate_inputs():
    # The corners of a rectangle (cocircular): one vertex, four regions; an interior point
    # and a point inside an edge have none. Qu means furthest_site=True.
    pts = np.array([[0, 0], [4, 0], [4, 3], [0, 3], [1, 1], [2, 0], [4, 3]], dtype=float)
    v = exidel.Voronoi(pts, qhull_options="Qu")
    assert v.furthest_site
    np.testing.assert_array_equal(v.vertices, [[2, 1.5]])
    assert v.regions == [[0, -1], [0, -1], [0, -1], [0, -1], [], [], [0, -1]]
    assert sorted(map(sorted, v.ridge_points.tolist())) == [[0, 1], [0, 3], [1, 2], [2, 3]]
    with pytest.raises(ValueError, match="furthest"):
        v.clip(0, 0, 1, 1)
    # Collinear points: no vertices; the two ends have regions.
    line = exidel.Voronoi(np.array([[0, 0], [1, 1], [3, 3]], dtype=float), furthest_site=True)
    assert line.collinear and len(line.vertices) == 0
    assert line.regions == [[-1], [], [-1]]
