"""exidel.plot on the Agg backend: each function draws what it says (counted through the
artists' gids), returns the Axes, and the figure saves as a PNG."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.image  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import exidel  # noqa: E402
from exidel import plot, research  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def artist(ax, gid):
    found = [a for a in (*ax.collections, *ax.lines, *ax.images) if a.get_gid() == gid]
    assert len(found) <= 1, gid
    return found[0] if found else None


def save(ax, path):
    ax.figure.savefig(path, dpi=60)
    img = matplotlib.image.imread(path)
    assert img.ndim == 3 and img.shape[0] > 50 and img.shape[1] > 50
    return img


def test_triangulation(rng, tmp_path):
    pts = rng.random((60, 2))
    pts = np.vstack([pts, pts[[3, 7, 7]]])  # three duplicates
    tri = exidel.Delaunay(pts)
    ax = plot.triangulation(tri, labels=True)
    assert isinstance(ax, matplotlib.axes.Axes)
    assert len(artist(ax, "triangles").get_paths()) == tri.nsimplex
    assert len(artist(ax, "hull").get_segments()) == len(tri.hull)
    assert len(artist(ax, "points").get_xdata()) == 63
    assert np.array_equal(artist(ax, "duplicates").get_xdata(), pts[tri.duplicates, 0])
    x0, x1 = ax.get_xlim()
    assert x0 <= pts[:, 0].min() and x1 >= pts[:, 0].max()
    save(ax, tmp_path / "tri.png")


def test_triangulation_of_scipy_and_of_collinear_points(rng, tmp_path):
    scipy_spatial = pytest.importorskip("scipy.spatial")
    pts = rng.random((30, 2))
    fig, (a, b) = plt.subplots(1, 2)
    s = scipy_spatial.Delaunay(pts)
    assert plot.triangulation(s, ax=a) is a
    assert len(artist(a, "triangles").get_paths()) == len(s.simplices)
    assert len(artist(a, "hull").get_segments()) == len(s.convex_hull)
    line = exidel.Delaunay([[0, 0], [1, 1], [2, 2], [3, 3], [1, 1]])
    assert line.collinear
    plot.triangulation(line, ax=b)
    assert len(artist(b, "triangles").get_paths()) == 0
    assert len(artist(b, "hull").get_segments()) == 3  # the chain of the 4 distinct points
    assert len(artist(b, "duplicates").get_xdata()) == 1
    fig.savefig(tmp_path / "two.png")


def test_failure_map_of_a_computed_map(tmp_path):
    m = research.compute_failure_map(**dict(research.failure_map_preset("kettner1"), width=48, height=32))
    assert m.wrong_count > 0
    ax = plot.failure_map(m)
    image = artist(ax, "signs")
    rgb = np.asarray(image.get_array())
    assert rgb.shape == (32, 48, 3) and image.origin == "lower"
    assert np.all(rgb[m.wrong_cells] == plot.WRONG_COLOUR)
    right = ~m.wrong_cells
    for s, colour in plot.SIGN_COLOURS.items():
        assert np.all(rgb[right & (m.signs == s)] == colour)
    assert list(image.get_extent()) == [-0.5, 47.5, -0.5, 31.5]
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["positive", "zero", "negative", "wrong"]
    assert str(m.wrong_count) in ax.get_title() and "ulps" in ax.get_xlabel()
    save(ax, tmp_path / "map.png")


def test_failure_map_of_arrays_centred_and_faded(tmp_path):
    m = research.compute_failure_map(**dict(research.failure_map_preset("incircle-s2"), width=40, height=20))
    fig, (a, b) = plt.subplots(1, 2)
    plot.failure_map(m.signs, ax=a, centered=True, step=2, legend=False)
    rgb = np.asarray(artist(a, "signs").get_array())
    assert not np.any(np.all(rgb == plot.WRONG_COLOUR, axis=-1))  # no exact: nothing red
    assert list(artist(a, "signs").get_extent()) == [-41.0, 39.0, -21.0, 19.0]
    assert a.get_legend() is None
    plot.failure_map(m.signs, m.exact, ax=b, offsets=(m.offsets_x, m.offsets_y), fade=True)
    rgb = np.asarray(artist(b, "signs").get_array())
    faded = (np.array(plot.SIGN_COLOURS[1]) + 3 * 255) // 4
    assert np.all(rgb[~m.wrong_cells & (m.exact == 1)] == faded)
    assert np.count_nonzero(np.all(rgb == plot.WRONG_COLOUR, axis=-1)) == m.wrong_count
    fig.savefig(tmp_path / "maps.png")
    with pytest.raises(ValueError):
        plot.failure_map(np.zeros(5, dtype=np.int8))


def test_certificate_marks_a_non_delaunay_edge(tmp_path):
    # A convex quadrilateral: one diagonal is Delaunay, the other is not.
    pts = np.array([[0.0, 0.0], [4.0, 0.0], [5.0, 3.0], [0.0, 1.0]])
    diagonals = ([[0, 1, 2], [0, 2, 3]], [[0, 1, 3], [1, 2, 3]])
    bad = next(np.array(s) for s in diagonals if not exidel.certify(pts, np.array(s)).ok)
    ax = plot.certificate(pts, bad)
    lines = artist(ax, "not_delaunay").get_segments()
    assert len(lines) == 1  # the shared diagonal, found from one side
    shared = set(bad[0].tolist()) & set(bad[1].tolist())
    assert {tuple(p) for p in lines[0].tolist()} == {tuple(pts[v]) for v in shared}
    assert len(artist(ax, "inside_circumcircle").get_xdata()) == 1
    assert "not_delaunay" in ax.get_title()
    save(ax, tmp_path / "bad.png")

    good = exidel.Delaunay(pts)
    ax = plot.certificate(pts, good, exidel.certify(pts, good))
    assert ax.get_title() == "certified Delaunay" and artist(ax, "not_delaunay") is None


def test_certificate_of_a_clockwise_triangle_and_of_scipy(tmp_path):
    pts = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    cw = np.array([[0, 2, 1]])
    cert = exidel.certify(pts, cw, reorient=False)
    ax = plot.certificate(pts, cw, cert, reorient=False)
    assert "not_ccw" in cert.kinds and len(artist(ax, "bad_triangles").get_paths()) == 1

    scipy_spatial = pytest.importorskip("scipy.spatial")
    # Points of an exactly cocircular lattice set moved by an ulp: qhull's result need not
    # be Delaunay; whatever it is, every not-Delaunay finding is one red edge.
    r, c = 65, 2.0 ** 13
    circle = [(x, y) for x in range(-r, r + 1) for y in range(-r, r + 1) if x * x + y * y == r * r]
    pts = np.array([(np.nextafter(c + x, np.inf), c + y) for x, y in circle])
    s = scipy_spatial.Delaunay(pts)
    cert = exidel.certify(pts, s.simplices)
    ax = plot.certificate(pts, s)
    n = sum(f.kind == "not_delaunay" for f in cert.findings)
    red = artist(ax, "not_delaunay")
    assert (len(red.get_segments()) if red is not None else 0) == n
    assert len(artist(ax, "triangles").get_paths()) == len(s.simplices)
    save(ax, tmp_path / "scipy.png")


def test_voronoi(rng, tmp_path):
    pts = rng.random((40, 2))
    vor = exidel.Voronoi(pts)
    ax = plot.voronoi(vor)
    finite = sum(all(v >= 0 for v in rv) for rv in vor.ridge_vertices)
    assert len(artist(ax, "ridges").get_segments()) == finite
    assert len(artist(ax, "rays").get_segments()) == len(vor.ridge_vertices) - finite
    assert len(artist(ax, "vertices").get_xdata()) == len(vor.vertices)
    save(ax, tmp_path / "vor.png")

    scipy_spatial = pytest.importorskip("scipy.spatial")
    s = scipy_spatial.Voronoi(pts)
    ax = plot.voronoi(s, vertices=False)
    assert len(artist(ax, "ridges").get_segments()) == sum(all(v >= 0 for v in rv) for rv in s.ridge_vertices)
    assert artist(ax, "vertices") is None

    line = exidel.Voronoi([[0.0, 0.0], [1.0, 0.0], [3.0, 0.0]])  # collinear: two bisector lines
    ax = plot.voronoi(line)
    assert artist(ax, "ridges") is None and len(artist(ax, "rays").get_segments()) == 2
    save(ax, tmp_path / "line.png")
