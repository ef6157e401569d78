"""exidel.Delaunay and exidel.certify: scipy's names and meaning, every algorithm and exact
kernel certified on degenerate input, typed failures, bad input."""

import math

import numpy as np
import pytest
import scipy.spatial

import exidel

EXACT = ["adaptive", "exact", "exact-cpp"]


def triangle_set(simplices):
    return {tuple(sorted(t)) for t in np.asarray(simplices).tolist()}


def grid(k, scale=1.0, offset=0.0):
    return np.array([[i, j] for i in range(k) for j in range(k)], dtype=float) * scale + offset


def lattice_circle(r):
    """Every integer point of x^2 + y^2 = r^2 (r = 65: 36 points, all cocircular)."""
    pts = {(x, y) for x in range(-r, r + 1) for y in (math.isqrt(r * r - x * x),)
           if x * x + y * y == r * r}
    pts |= {(x, -y) for x, y in pts}
    return np.array(sorted(pts), dtype=float)


DEGENERATE = {
    "grid 12x12": grid(12),
    "grid, huge (2^1000)": grid(8, 2.0 ** 1000),
    "grid, subnormal (2^-1074)": grid(8, math.ulp(0.0)),
    "lattice circle r=65": lattice_circle(65),
    "lattice circle r=1105, centre 2^30": lattice_circle(1105) + 2.0 ** 30,
    "grid with duplicates": np.concatenate([grid(6), grid(6)[::3]]),
    "collinear": np.stack([np.arange(30.0), 3 * np.arange(30.0) + 1], axis=1),
    "square and centre": np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]]),
}


def test_same_triangles_neighbors_and_hull_as_scipy(rng):
    pts = rng.random((2000, 2))
    ours = exidel.Delaunay(pts)
    theirs = scipy.spatial.Delaunay(pts)
    assert triangle_set(ours.simplices) == triangle_set(theirs.simplices)
    assert ours.simplices.dtype == np.int32 and ours.simplices.shape == theirs.simplices.shape
    # neighbors: the same adjacency, through each triangle's vertex set.
    def adjacency(d):
        key = [tuple(sorted(t)) for t in d.simplices.tolist()]
        return {(key[i], frozenset(key[n] for n in d.neighbors[i] if n >= 0))
                for i in range(len(key))}
    assert adjacency(ours) == adjacency(theirs)
    # neighbors[i, j] is opposite vertex j: the shared edge is the other two vertices.
    for i in range(0, ours.nsimplex, 97):
        for j in range(3):
            n = ours.neighbors[i, j]
            if n >= 0:
                edge = set(ours.simplices[i]) - {ours.simplices[i, j]}
                assert edge <= set(ours.simplices[n])
    assert {frozenset(e) for e in ours.convex_hull.tolist()} == \
        {frozenset(e) for e in theirs.convex_hull.tolist()}
    # vertex_neighbor_vertices in scipy's layout.
    ip, ix = ours.vertex_neighbor_vertices
    sp, sx = theirs.vertex_neighbor_vertices
    for k in range(0, 2000, 101):
        assert set(ix[ip[k]:ip[k + 1]]) == set(sx[sp[k]:sp[k + 1]])
    assert ours.npoints == 2000 and ours.ndim == 2


def test_triangles_are_counter_clockwise(rng):
    pts = rng.random((500, 2))
    t = exidel.Delaunay(pts).simplices
    assert (exidel.orient2d(pts[t[:, 0]], pts[t[:, 1]], pts[t[:, 2]]) == 1).all()


@pytest.mark.parametrize("algorithm", exidel.algorithms)
@pytest.mark.parametrize("name", sorted(DEGENERATE))
def test_every_algorithm_certifies_on_degenerate_input(algorithm, name):
    pts = DEGENERATE[name]
    for kernel in EXACT:
        tri = exidel.Delaunay(pts, kernel=kernel, algorithm=algorithm)
        cert = exidel.certify(pts, tri)
        assert cert.ok, (kernel, cert)
        # The same certificate from the bare simplices (how one certifies scipy's output).
        assert exidel.certify(pts, tri.simplices).ok


@pytest.mark.parametrize("incircle", ["determinant", "cosine"])
@pytest.mark.parametrize("order", ["auto", "lexicographic", "radial", "strips"])
def test_policies_and_orders(incircle, order, rng):
    pts = np.concatenate([rng.random((300, 2)), grid(5)])
    tri = exidel.Delaunay(pts, incircle=incircle, order=order, threads=2)
    assert tri.certify().ok
    if order != "auto":
        assert tri.stats["order"] == order


def test_degenerate_details():
    c = exidel.Delaunay(DEGENERATE["collinear"])
    assert c.collinear and c.nsimplex == 0 and c.hull.tolist() == list(range(30))
    assert c.convex_hull.shape == (0, 2)
    d = exidel.Delaunay(DEGENERATE["grid with duplicates"])
    assert d.duplicates.tolist() == list(range(36, 48))
    assert (d.vertex_of_input[36:] == np.arange(0, 36, 3)).all()
    assert d.coplanar.shape == (12, 3) and (d.coplanar[:, 2] == d.vertex_of_input[36:]).all()
    for row in d.coplanar:  # the listed triangle has the twin as a vertex
        assert row[2] in d.simplices[row[1]]
    g = exidel.Delaunay(grid(4))
    # Collinear boundary points are hull vertices: all 12 boundary points of the 4x4 grid.
    assert len(g.hull) == 12 and g.hull[0] == 0
    assert g.nsimplex == 2 * 16 - 2 - 12


@pytest.mark.parametrize("n", [0, 1, 2, 3])
def test_tiny_inputs(n):
    pts = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])[:n]
    tri = exidel.Delaunay(pts)
    assert tri.nsimplex == (1 if n == 3 else 0)
    assert tri.certify().ok


def test_bad_input():
    with pytest.raises(ValueError, match=r"points: row 2 is not finite \(inf, 0.0\)"):
        exidel.Delaunay([[0, 0], [1, 0], [np.inf, 0]])
    with pytest.raises(ValueError, match="shape"):
        exidel.Delaunay(np.zeros((4, 3)))
    with pytest.raises(ValueError, match="got \\(2,\\)"):
        exidel.Delaunay([0.0, 1.0])
    with pytest.raises(ValueError, match="unknown algorithm 'qhull'"):
        exidel.Delaunay(np.zeros((3, 2)), algorithm="qhull")
    with pytest.raises(ValueError, match="determinant"):
        exidel.Delaunay(np.zeros((3, 2)), incircle="sphere")
    with pytest.raises(ValueError, match="lexicographic"):
        exidel.Delaunay(np.zeros((3, 2)), order="random")
    with pytest.raises(ValueError, match="kernel"):
        exidel.Delaunay(np.zeros((3, 2)), kernel="float")


def test_inexact_kernel_failure_is_typed(rng):
    # Two-bit MPFR arithmetic cannot keep uniform points consistent: the run stops itself.
    pts = rng.random((1000, 2))
    with pytest.raises(exidel.TriangulationError) as info:
        exidel.Delaunay(pts, kernel="mpfr:2")
    e = info.value
    assert e.kind in {"point_inside_hull", "no_visible_edge", "hull_walk_exceeded",
                      "erosion_inconsistent", "erosion_exceeded", "merge_inconsistent",
                      "result_inconsistent"}
    assert e.message and str(e).startswith(e.kind)
    assert e.input_index is None or 0 <= e.input_index < 1000
    # Either a typed failure or a result: never a crash, whatever the algorithm.
    for algorithm in exidel.algorithms:
        try:
            tri = exidel.Delaunay(pts[:200], kernel="mpfr:4", algorithm=algorithm)
        except exidel.TriangulationError:
            continue
        tri.certify()  # certifying a wrong result is fine, it just finds something


def test_stats_and_counters(rng):
    tri = exidel.Delaunay(rng.random((500, 2)), counters=True)
    assert tri.stats["triangles"] == tri.nsimplex and tri.stats["kernel"] == "adaptive"
    assert tri.stats["counters"]["incircle_tests"] > 500
    assert "counters" not in exidel.Delaunay(rng.random((10, 2))).stats
    # Uniform points never make auto give a radial run up to cavity insertion (the C++
    # test DelaunayAutomatic.RunsThatErodeTooMuchAreInsertedByCavities shows one that does).
    assert tri.stats["cavity_pieces"] == 0


def test_certify_finds_what_is_wrong(rng):
    pts = rng.random((300, 2))
    tri = exidel.Delaunay(pts)
    s = tri.simplices.copy()
    # Flip one interior edge: a valid triangulation that is not Delaunay.
    e = int(np.nonzero(tri.halfedges >= 0)[0][0])
    t, u = e // 3, int(tri.halfedges[e]) // 3
    a, b = s.reshape(-1)[e], s.reshape(-1)[3 * t + (e + 1) % 3]
    c = next(v for v in s[t] if v not in (a, b))
    d = next(v for v in s[u] if v not in (a, b))
    s[t], s[u] = [c, d, b], [d, c, a]
    cert = exidel.certify(pts, s)
    assert not cert.ok and "not_delaunay" in cert.kinds, cert
    # Orientation is checked when not repaired.
    cw = tri.simplices[:, ::-1]
    assert exidel.certify(pts, cw).ok
    assert "not_ccw" in exidel.certify(pts, cw, reorient=False).kinds
    # A missing triangle, an index out of range, garbage: findings, never a crash.
    assert not exidel.certify(pts, tri.simplices[1:]).ok
    bad = tri.simplices.copy()
    bad[0, 0] = 300
    assert "index_out_of_range" in exidel.certify(pts, bad).kinds
    for seed in range(20):
        junk = np.random.default_rng(seed).integers(-2, 302, size=(50, 3))
        assert not exidel.certify(pts, junk).ok
    # An empty array claims collinearity.
    assert not exidel.certify(pts, []).ok
    assert exidel.certify([[0, 0], [1, 1], [3, 3]], []).ok
    with pytest.raises(ValueError):
        exidel.certify(pts, np.zeros((3, 3)) + 0.5)


def test_scipy_output_can_be_certified(rng):
    pts = rng.random((1000, 2))
    assert exidel.certify(pts, scipy.spatial.Delaunay(pts).simplices).ok


def test_certify_takes_every_producers_layout_and_types_its_findings(rng):
    pts = rng.random((500, 2))
    pts = np.vstack([pts, pts[:20]])  # later copies of 20 points
    tri = exidel.Delaunay(pts)
    s = scipy.spatial.Delaunay(pts)
    # The scipy object itself, its simplices, delaunator's arrays (clockwise, a later copy,
    # the hull clockwise from elsewhere), exidel's own result: all certified.
    later = np.arange(len(pts))
    later[:20] = np.arange(500, 520)
    cw = later[tri.simplices[:, ::-1]]
    delaunator = {"triangles": cw.reshape(-1), "hull": np.roll(later[tri.hull[::-1]], 3)}
    for given in (s, s.simplices, delaunator, tri):
        cert = exidel.certify(pts, given)
        assert cert.ok, (type(given), cert)
    notes = exidel.certify(pts, delaunator).notes
    assert any("clockwise triangles turned" in n for n in notes), notes
    assert any("later copy" in n for n in notes), notes
    assert exidel.certify(pts, tri).notes == []
    # Typed, located findings: a clockwise triangle under reorient=False.
    bad = exidel.certify(pts, tri.simplices[:, ::-1], reorient=False)
    f = bad.findings[0]
    assert isinstance(f, exidel.Finding) and f.kind == "not_ccw"
    assert f.triangle == 0 and f.points == tuple(int(v) for v in tri.simplices[0, ::-1])
    assert f.message == f"triangle 0 ({', '.join(map(str, f.points))}) is clockwise"
    assert str(f).startswith("not_ccw: triangle 0 (")
    assert len(bad.findings) == 64 and bad.total_findings > 64
    every = exidel.certify(pts, tri.simplices[:, ::-1], reorient=False, all=True)
    assert len(every.findings) == every.total_findings == bad.total_findings
    # The plot accepts what certify accepts.
    pytest.importorskip("matplotlib")
    from exidel import plot
    plot.certificate(pts, s)
    plot.certificate(pts, delaunator)
