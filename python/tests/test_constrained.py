"""exidel.ConstrainedDelaunay: exact domain areas under the fill rules and hole seeds
(rational arithmetic), correctly rounded crossing points, constraints as edges, the
certificate on random degenerate input (Hypothesis), agreement with Delaunay and scipy
without segments, the certifier catching tampered output, bad input."""

import math
from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial

import exidel

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import given, settings, strategies as st  # noqa: E402

from exidel.testing import FAMILIES  # noqa: E402  (imports hypothesis)
from exidel.testing import points as family_points  # noqa: E402


def fixed(max_examples):
    """Reproducible and fast: the same examples on every run, nothing stored."""
    P = hypothesis.Phase
    return settings(derandomize=True, max_examples=max_examples, deadline=None, database=None,
                    suppress_health_check=list(hypothesis.HealthCheck),
                    phases=[P.explicit, P.generate, P.shrink])


def twice_area(pts, triangles):
    """Twice the total signed area of the triangles, exactly (rationals of the doubles)."""
    total = Fraction(0)
    for a, b, c in np.asarray(triangles).tolist():
        (ax, ay), (bx, by), (cx, cy) = [(Fraction(float(p[0])), Fraction(float(p[1])))
                                        for p in (pts[a], pts[b], pts[c])]
        total += (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return total


def twice_polygon_area(ring):
    """Twice the signed area of a polygon (shoelace), exactly: positive counter-clockwise."""
    r = [(Fraction(float(x)), Fraction(float(y))) for x, y in ring]
    return sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(r, r[1:] + r[:1]))


def ring_segments(start, count):
    return [[start + i, start + (i + 1) % count] for i in range(count)]


def edge_set(simplices):
    s = np.asarray(simplices)
    e = np.concatenate([s[:, [0, 1]], s[:, [1, 2]], s[:, [2, 0]]])
    return {(min(a, b), max(a, b)) for a, b in e.tolist()}


def triangle_set(simplices):
    return {tuple(sorted(t)) for t in np.asarray(simplices).tolist()}


def same_bits(a, b):
    a, b = np.ascontiguousarray(a, dtype=np.float64), np.ascontiguousarray(b, dtype=np.float64)
    return a.shape == b.shape and (a.view(np.uint64) == b.view(np.uint64)).all()


def exact_crossing(a, b, c, d):
    """The exact crossing of lines ab and cd (rationals of the doubles)."""
    (ax, ay), (bx, by), (cx, cy), (dx, dy) = [(Fraction(float(p[0])), Fraction(float(p[1])))
                                              for p in (a, b, c, d)]
    den = (bx - ax) * (dy - cy) - (by - ay) * (dx - cx)
    t = ((cx - ax) * (dy - cy) - (cy - ay) * (dx - cx)) / den
    return ax + t * (bx - ax), ay + t * (by - ay)


def orient_exact(a, b, c):
    (ax, ay), (bx, by), (cx, cy) = [(Fraction(float(p[0])), Fraction(float(p[1])))
                                    for p in (a, b, c)]
    v = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (v > 0) - (v < 0)


def check_structure(cdt, pts, segs):
    """What the result promises, checked directly (certify() checks it too)."""
    n = len(pts)
    assert cdt.input_count == n and same_bits(cdt.points[:n], pts)
    assert cdt.added_points.shape == (cdt.added_count, 2)
    assert cdt.simplices.dtype == np.int32 and cdt.simplices.shape == (cdt.nsimplex, 3)
    if cdt.nsimplex:
        p = cdt.points
        s = cdt.simplices
        assert (exidel.orient2d(p[s[:, 0]], p[s[:, 1]], p[s[:, 2]]) == 1).all()
    # Every constraint piece is an edge (of the line's chain when there are no triangles).
    if cdt.collinear:
        edges = {(min(a, b), max(a, b)) for a, b in zip(cdt.hull[:-1].tolist(),
                                                        cdt.hull[1:].tolist())}
    else:
        edges = edge_set(cdt.simplices)
    constraints = [tuple(c) for c in cdt.constraints.tolist()]
    assert constraints == sorted(set(constraints)) and all(u < v for u, v in constraints)
    assert set(constraints) <= edges
    # The chains run between the vertices of the segment's ends; their pieces are the list.
    chains = cdt.chains
    assert len(chains) == len(segs)
    pieces = set()
    for (a, b), chain in zip(np.asarray(segs).reshape(-1, 2).tolist(), chains):
        assert chain[0] == cdt.vertex_of_input[a] and chain[-1] == cdt.vertex_of_input[b]
        assert len(set(chain.tolist())) == len(chain)
        pieces |= {(min(u, v), max(u, v)) for u, v in zip(chain[:-1].tolist(), chain[1:].tolist())}
    assert pieces == set(constraints)
    assert cdt.crossings.shape == (cdt.added_count, 2)
    assert cdt.crossing_lines.shape == (cdt.added_count, 4)
    for arr in (cdt.regions, cdt.depth, cdt.winding, cdt.inside):
        assert arr.shape == (cdt.nsimplex,)
    assert cdt.inside.dtype == bool
    assert (cdt.inside == (cdt.depth % 2 == 1)).all()  # the default rule, even_odd
    assert cdt.inside_simplices.shape == (int(cdt.inside.sum()), 3)
    assert cdt.region_count == (int(cdt.regions.max()) + 1 if cdt.nsimplex else 0)


# ---- the square with a square hole ------------------------------------------------------

OUTER = [(0.1, 0.1), (3.3, 0.1), (3.3, 2.9), (0.1, 2.9)]  # counter-clockwise
HOLE = [(1.1, 0.7), (1.1, 2.3), (2.2, 2.3), (2.2, 0.7)]  # clockwise


def square_with_hole(rng, hole=HOLE, outside=True):
    """The two rings (points 0-3 and 4-7, segments around each), 40 points inside the outer
    square (some in the hole) and, with `outside`, three points beyond it so that the hull
    has triangles outside the rings."""
    inner = rng.random((40, 2)) * [3.2, 2.8] + [0.1, 0.1]
    extra = [(5.0, 1.5), (1.7, -1.5), (-2.0, 2.0)] if outside else []
    pts = np.array(OUTER + list(hole) + inner.tolist() + extra)
    return pts, ring_segments(0, 4) + ring_segments(4, 4)


@pytest.mark.parametrize("rule", ["even_odd", "non_zero"])
def test_square_with_a_hole_by_rings(rule, rng):
    pts, segs = square_with_hole(rng)
    cdt = exidel.ConstrainedDelaunay(pts, segs, rule=rule)
    assert cdt.certify().ok
    if rule == "even_odd":
        check_structure(cdt, pts, segs)
    assert cdt.rule == rule and cdt.closed and cdt.added_count == 0
    expected = twice_polygon_area(OUTER) + twice_polygon_area(HOLE)  # the hole is clockwise
    assert expected == 2 * (Fraction(3.3) - Fraction(0.1)) * (Fraction(2.9) - Fraction(0.1)) \
        - 2 * (Fraction(2.2) - Fraction(1.1)) * (Fraction(2.3) - Fraction(0.7))
    assert twice_area(cdt.points, cdt.inside_simplices) == expected
    # Winding 1 in the domain, 0 in the hole and outside; depth 1, 2 and 0.
    assert set(cdt.winding[cdt.inside].tolist()) == {1}
    assert set(cdt.winding[~cdt.inside].tolist()) == {0}
    assert set(cdt.depth[cdt.inside].tolist()) == {1} and set(cdt.depth.tolist()) == {0, 1, 2}
    # The pieces cut the hull into three regions: outside the rings, between, in the hole.
    assert cdt.region_count == 3
    assert len(set(cdt.regions[cdt.inside].tolist())) == 1
    # Every triangle of the hull once: their area is the hull's.
    hull = cdt.points[cdt.hull]
    assert twice_area(cdt.points, cdt.simplices) == twice_polygon_area(hull.tolist())
    assert np.array_equal(cdt.inside_simplices, cdt.simplices[cdt.inside])


def test_same_orientation_rings_differ_between_the_rules(rng):
    pts, segs = square_with_hole(rng, hole=HOLE[::-1])  # both rings counter-clockwise
    even = exidel.ConstrainedDelaunay(pts, segs, rule="even_odd")
    nonzero = exidel.ConstrainedDelaunay(pts, segs, rule="non_zero")
    outer, hole = twice_polygon_area(OUTER), twice_polygon_area(HOLE[::-1])
    assert twice_area(even.points, even.inside_simplices) == outer - hole
    assert twice_area(nonzero.points, nonzero.inside_simplices) == outer  # winding 2 inside
    assert set(nonzero.winding.tolist()) == {0, 1, 2}
    assert np.array_equal(even.simplices, nonzero.simplices)
    # enclosed (Triangle's convention): everything the segments close off from outside,
    # here the outer ring's inside whatever the inner ring's orientation; a seed removes
    # the hole.
    enclosed = exidel.ConstrainedDelaunay(pts, segs, rule="enclosed")
    assert twice_area(enclosed.points, enclosed.inside_simplices) == outer
    assert (enclosed.inside == (enclosed.depth > 0)).all()
    seeded = exidel.ConstrainedDelaunay(pts, segs, rule="enclosed", holes=[(1.5, 1.5)])
    assert twice_area(seeded.points, seeded.inside_simplices) == outer - hole


def test_hole_seeds_under_rule_all(rng):
    pts, segs = square_with_hole(rng, hole=HOLE[::-1])  # the orientation does not matter
    seeds = [(1.5, 1.5),    # in the hole
             (3.5, 1.5),    # between the outer ring and the hull
             (10.0, 10.0),  # outside the hull
             (0.1, 0.1),    # on a vertex
             (1.7, 0.7)]    # on a piece of the hole's ring
    cdt = exidel.ConstrainedDelaunay(pts, segs, holes=seeds, rule="all")
    assert cdt.unplaced_holes.tolist() == [2, 3, 4]
    assert twice_area(cdt.points, cdt.inside_simplices) == \
        twice_polygon_area(OUTER) - twice_polygon_area(HOLE[::-1])
    assert cdt.holes.shape == (5, 2) and cdt.rule == "all"
    # Without seeds, rule all keeps the whole hull; one seed as a (2,) point.
    everything = exidel.ConstrainedDelaunay(pts, segs, rule="all")
    assert everything.inside.all() and everything.unplaced_holes.size == 0
    one = exidel.ConstrainedDelaunay(pts, segs, holes=[1.5, 1.5], rule="all")
    assert twice_area(one.points, one.inside_simplices) == \
        twice_area(one.points, one.simplices) + twice_polygon_area(HOLE)
    # Seeds act under the other rules too: a seed in the ring removes the domain.
    emptied = exidel.ConstrainedDelaunay(pts, segs, holes=[(0.5, 0.5)])
    assert not emptied.inside.any() and emptied.unplaced_holes.size == 0


def test_open_polyline_is_not_closed():
    pts = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 3], [2, 1]], dtype=float)
    cdt = exidel.ConstrainedDelaunay(pts, [[4, 6], [6, 5]])
    assert not cdt.closed and cdt.certify().ok
    assert exidel.ConstrainedDelaunay(pts, [[0, 1], [1, 2], [2, 3], [3, 0]]).closed


# ---- crossings ----------------------------------------------------------------------------

def test_two_crossing_segments_meet_at_the_rounded_crossing():
    # (0,0)-(3,1) and (0,0.5)-(3,0.2) cross at x = 1.5 / 1.3, which no double holds.
    pts = np.array([[0, 0], [3, 1], [0, 0.5], [3, 0.2]])
    cdt = exidel.ConstrainedDelaunay(pts, [[0, 1], [2, 3]])
    assert cdt.added_count == 1 and cdt.npoints == 5
    x, y = exact_crossing(*pts)
    p = cdt.points[4]
    assert (p[0], p[1]) == (float(x), float(y))  # int / int: the nearest double, ties to even
    assert (Fraction(float(p[0])), Fraction(float(p[1]))) != (x, y)  # it was rounded
    assert cdt.crossings.tolist() == [[0, 1]]
    assert sorted(map(sorted, cdt.crossing_lines.reshape(2, 2).tolist())) == [[0, 1], [2, 3]]
    assert [c.tolist() for c in cdt.chains] == [[0, 4, 1], [2, 4, 3]]
    assert cdt.constraints.tolist() == [[0, 4], [1, 4], [2, 4], [3, 4]]
    assert set(map(tuple, cdt.constraints.tolist())) <= edge_set(cdt.simplices)
    assert cdt.certify().ok


def test_random_crossings_are_correctly_rounded(rng):
    done = 0
    while done < 150:
        scale = 2.0 ** int(rng.integers(-60, 60))
        q = (rng.random((4, 2)) - 0.5) * scale + rng.random(2) * scale * 8
        a, b, c, d = q
        if not (orient_exact(a, b, c) * orient_exact(a, b, d) < 0
                and orient_exact(c, d, a) * orient_exact(c, d, b) < 0):
            continue
        cdt = exidel.ConstrainedDelaunay(q, [[0, 1], [2, 3]])
        assert cdt.added_count == 1
        x, y = exact_crossing(a, b, c, d)
        assert tuple(cdt.points[4].tolist()) == (float(x), float(y))
        assert cdt.certify().ok
        done += 1


def test_three_segments_through_one_point_make_one_vertex():
    pts = np.array([[0, 0], [1, 1], [1, 0], [0, 0.5], [0, 1], [0.5, 0]])
    cdt = exidel.ConstrainedDelaunay(pts, [[0, 1], [2, 3], [4, 5]])
    assert cdt.added_count == 1 and cdt.constraints.shape == (6, 2)
    assert all(c.tolist()[1] == 6 for c in cdt.chains)
    assert cdt.certify().ok


def test_grid_of_crossings_and_the_limit():
    pts, segs = [], []
    for i in range(5):
        k = len(pts)
        pts += [(0, i + 0.5), (5, i + 0.5), (i + 0.5, 0), (i + 0.5, 5)]
        segs += [[k, k + 1], [k + 2, k + 3]]
    cdt = exidel.ConstrainedDelaunay(pts, segs)
    assert cdt.added_count == 25 and cdt.certify().ok
    assert sorted(map(tuple, cdt.added_points.tolist())) == \
        sorted((i + 0.5, j + 0.5) for i in range(5) for j in range(5))
    with pytest.raises(exidel.TriangulationError) as info:
        exidel.ConstrainedDelaunay(pts, segs, max_added_points=10)
    assert info.value.kind == "too_many_crossings"
    assert exidel.ConstrainedDelaunay(pts, segs, max_added_points=25).added_count == 25


# ---- degenerate input -------------------------------------------------------------------

def test_points_on_segments_split_them_and_overlaps_merge():
    pts = np.array([[0, 0], [1, 0], [3, 0], [4, 0], [2, 0], [6, 0], [2, 3], [2, -3]])
    cdt = exidel.ConstrainedDelaunay(pts, [[0, 3], [4, 5]])
    assert [c.tolist() for c in cdt.chains] == [[0, 1, 4, 2, 3], [4, 2, 3, 5]]
    assert cdt.constraints.tolist() == [[0, 1], [1, 4], [2, 3], [2, 4], [3, 5]]
    assert cdt.added_count == 0 and cdt.certify().ok


def test_non_delaunay_diagonal_is_kept():
    pts = np.array([[0, 0], [4, -1], [8, 0], [4, 1]], dtype=float)
    cdt = exidel.ConstrainedDelaunay(pts, [[0, 2]])
    assert cdt.constraints.tolist() == [[0, 2]] and cdt.nsimplex == 2
    assert cdt.certify().ok
    plain = exidel.certify(pts, cdt.simplices)
    assert not plain.ok and "not_delaunay" in plain.kinds


def test_duplicates_and_degenerate_segments():
    pts = np.array([[0, 0], [2, 0], [1, 2], [2, 0], [1, 0.5]])
    cdt = exidel.ConstrainedDelaunay(pts, [[3, 0], [4, 4], [1, 2]])
    assert cdt.duplicates.tolist() == [3]
    assert [c.tolist() for c in cdt.chains] == [[1, 0], [4], [1, 2]]
    assert cdt.certify().ok
    check_structure(cdt, pts, [[3, 0], [4, 4], [1, 2]])


def test_collinear_points_have_chains_and_no_triangles():
    pts = np.array([[0, 0], [2, 2], [1, 1], [3, 3], [1, 1]])
    cdt = exidel.ConstrainedDelaunay(pts, [[3, 0], [4, 1]], holes=[[1, 1]])
    assert cdt.collinear and cdt.nsimplex == 0 and cdt.convex_hull.shape == (0, 2)
    assert [c.tolist() for c in cdt.chains] == [[3, 1, 2, 0], [2, 1]]
    assert cdt.regions.shape == (0,) and cdt.region_count == 0
    assert cdt.unplaced_holes.tolist() == [0] and cdt.inside_simplices.shape == (0, 3)
    assert cdt.certify().ok
    for n in range(3):
        tiny = exidel.ConstrainedDelaunay(pts[:n], [[0, n - 1]] if n else [])
        assert tiny.nsimplex == 0 and tiny.certify().ok


# ---- agreement with Delaunay and scipy ----------------------------------------------------

def test_without_segments_the_delaunay_triangulation(rng):
    pts = rng.random((500, 2))
    cdt = exidel.ConstrainedDelaunay(pts, [])
    tri = exidel.Delaunay(pts)
    assert triangle_set(cdt.simplices) == triangle_set(tri.simplices)
    assert triangle_set(cdt.simplices) == triangle_set(scipy.spatial.Delaunay(pts).simplices)
    assert np.array_equal(cdt.hull, tri.hull) and np.array_equal(cdt.neighbors.shape,
                                                                 tri.neighbors.shape)
    assert cdt.chains == [] and cdt.constraints.shape == (0, 2) and cdt.npoints == 500
    assert cdt.region_count == 1 and not cdt.inside.any() and cdt.closed
    assert {frozenset(e) for e in cdt.convex_hull.tolist()} == \
        {frozenset(e) for e in tri.convex_hull.tolist()}
    assert exidel.certify(pts, cdt.simplices).ok and cdt.certify().ok
    assert exidel.ConstrainedDelaunay(pts, None).nsimplex == cdt.nsimplex


def test_neighbors_are_opposite_vertices(rng):
    pts, segs = square_with_hole(rng)
    cdt = exidel.ConstrainedDelaunay(pts, segs)
    for i in range(cdt.nsimplex):
        for j in range(3):
            n = cdt.neighbors[i, j]
            edge = set(cdt.simplices[i].tolist()) - {int(cdt.simplices[i, j])}
            if n >= 0:
                assert edge <= set(cdt.simplices[n].tolist())
            else:
                assert any(set(e) == edge for e in cdt.convex_hull.tolist())


@pytest.mark.parametrize("algorithm", exidel.algorithms)
def test_every_algorithm_and_exact_kernel_give_the_same_result(algorithm, rng):
    pts, segs = square_with_hole(rng)
    pts = np.concatenate([pts, [[0.0, 1.0], [3.4, 2.0]]])
    segs = segs + [[len(pts) - 2, len(pts) - 1]]  # crosses both rings
    ref = exidel.ConstrainedDelaunay(pts, segs)
    assert ref.added_count == 4 and ref.certify().ok
    for kernel in ["adaptive", "exact", "exact-cpp"]:
        cdt = exidel.ConstrainedDelaunay(pts, segs, kernel=kernel, algorithm=algorithm)
        assert cdt.kernel == exidel._core.kernel_name(kernel)
        assert same_bits(cdt.points, ref.points)
        assert np.array_equal(cdt.constraints, ref.constraints)
        assert triangle_set(cdt.simplices) == triangle_set(ref.simplices)
        assert cdt.certify().ok


def test_inexact_kernels(rng):
    pts, segs = square_with_hole(rng)
    ref = exidel.ConstrainedDelaunay(pts, segs)
    for kernel in ["double", "long-double", "mpfr:113"]:
        cdt = exidel.ConstrainedDelaunay(pts, segs, kernel=kernel)
        assert cdt.kernel == exidel._core.kernel_name(kernel) and cdt.certify().ok
        assert np.array_equal(cdt.simplices, ref.simplices)
        assert np.array_equal(cdt.inside, ref.inside)
    # Two-bit arithmetic: a result (certified or not) or a typed failure, never a crash.
    for seed in range(5):
        q = np.random.default_rng(seed).random((60, 2))
        s = np.random.default_rng(seed).integers(0, 60, size=(8, 2))
        try:
            cdt = exidel.ConstrainedDelaunay(q, s, kernel="mpfr:2")
        except exidel.TriangulationError as e:
            assert e.kind and e.message and str(e).startswith(e.kind)
            continue
        cdt.certify()


# ---- the certificate ----------------------------------------------------------------------

def test_certify_finds_tampering(rng):
    pts, segs = square_with_hole(rng)
    pts = np.concatenate([pts, [[0.0, 1.0], [3.4, 2.0]]])
    segs = segs + [[len(pts) - 2, len(pts) - 1]]

    def tampered(change):
        cdt = exidel.ConstrainedDelaunay(pts, segs)
        change(cdt)
        cert = cdt.certify()
        assert not cert.ok
        return cert.kinds

    def move_added_point(c):
        c.points = c.points.copy()
        c.points[-1, 0] = math.nextafter(c.points[-1, 0], math.inf)
    assert "added_point_wrong" in tampered(move_added_point)
    assert "constraints_mismatch" in tampered(
        lambda c: setattr(c, "constraints", c.constraints[1:]))

    def cut_chain(c):
        c.chain_vertices = np.delete(c.chain_vertices, 1)
        c.chain_offsets = np.concatenate([c.chain_offsets[:1], c.chain_offsets[1:] - 1])
    assert "chain_broken" in tampered(cut_chain)

    def flip_a_constraint(c):
        # Flip the triangles across a constraint: the piece is no longer an edge.
        s = c.simplices.copy()
        for u, v in c.constraints.tolist():  # the first piece with a triangle on each side
            t = [i for i in range(c.nsimplex) if {u, v} <= set(s[i].tolist())]
            if len(t) == 2:
                break
        a = next(x for x in s[t[0]].tolist() if x not in (u, v))
        b = next(x for x in s[t[1]].tolist() if x not in (u, v))
        s[t[0]], s[t[1]] = [a, b, u], [b, a, v]
        c.simplices = s
    assert "chain_broken" in tampered(flip_a_constraint)
    # Other input than the triangulated one.
    cdt = exidel.ConstrainedDelaunay(pts, segs)
    cdt._input = pts[::-1].copy()
    assert "input_mismatch" in cdt.certify().kinds
    # Garbage arrays: findings, never a crash.
    for seed in range(10):
        g = np.random.default_rng(seed)
        cdt = exidel.ConstrainedDelaunay(pts, segs)
        for name in ("simplices", "halfedges", "chain_vertices", "chain_offsets", "crossings",
                     "crossing_lines", "constraints"):
            a = getattr(cdt, name)
            setattr(cdt, name, g.integers(-3, a.size + 5, size=a.shape).astype(a.dtype))
        assert not cdt.certify().ok
        assert len(cdt.certify(all=True).findings) == cdt.certify(all=True).total_findings


# ---- random input (Hypothesis) -------------------------------------------------------------

SCALES = [1.0, 0.1, 2.0 ** -1060, 2.0 ** 1000, 3.0 ** 20]


@st.composite
def constrained_input(draw):
    """Points and segments: small integer grids scaled (points on segments, overlapping
    collinear segments, duplicates, exact and rounded collinearity), the same with uniform
    points mixed in, points all on one line, or a family of exidel.testing; up to 8
    segments between any two points (a point to itself included)."""
    kind = draw(st.sampled_from(["grid", "grid_and_uniform", "line", "family"]))
    near = False
    if kind in ("grid", "grid_and_uniform"):
        n = draw(st.integers(1, 14))
        cells = draw(st.lists(st.tuples(st.integers(0, 4), st.integers(0, 4)),
                              min_size=n, max_size=n))
        pts = np.array(cells, dtype=float) * draw(st.sampled_from(SCALES))
        if kind == "grid_and_uniform":
            extra = draw(st.lists(st.tuples(st.floats(0, 4), st.floats(0, 4)), max_size=6))
            pts = np.concatenate([pts, np.array(extra, dtype=float).reshape(-1, 2)])
    elif kind == "line":
        xs = draw(st.lists(st.integers(-20, 20), min_size=1, max_size=10))
        pts = np.array([[x, 3 * x + 1] for x in xs], dtype=float)
    else:
        family = draw(st.sampled_from(FAMILIES))
        near = family.near_degenerate
        pts = draw(family_points(family.name, draw(st.integers(3, 12))))
    n = len(pts)
    segs = draw(st.lists(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)), max_size=8))
    return np.ascontiguousarray(pts), np.array(segs, dtype=np.int64).reshape(-1, 2), near


@fixed(300)
@given(constrained_input())
def test_random_input_certifies(case):
    pts, segs, _ = case
    # Rounded crossings among segments within a few ulps of each other that do not settle
    # are snap-rounded: every run gives a certified result.
    cdt = exidel.ConstrainedDelaunay(pts, segs)
    cert = cdt.certify()
    assert cert.ok, cert.findings
    check_structure(cdt, pts, segs)
    if cdt.collinear:
        assert cdt.nsimplex == 0 and cdt.added_count == 0
    # The exact kernels agree bit for bit; the double kernel gives a result or a typed
    # failure.
    exact = exidel.ConstrainedDelaunay(pts, segs, kernel="exact")
    assert same_bits(exact.points, cdt.points) and np.array_equal(exact.simplices, cdt.simplices)
    assert np.array_equal(exact.chain_vertices, cdt.chain_vertices)
    try:
        exidel.ConstrainedDelaunay(pts, segs, kernel="double").certify()
    except exidel.TriangulationError:
        pass


# ---- bad input ------------------------------------------------------------------------------

def test_bad_input():
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    with pytest.raises(ValueError, match=r"points: row 2 is not finite \(nan, 1.0\)"):
        exidel.ConstrainedDelaunay([[0, 0], [1, 0], [np.nan, 1]], [[0, 1]])
    with pytest.raises(ValueError, match="points: expected shape"):
        exidel.ConstrainedDelaunay(np.zeros((4, 3)), [])
    with pytest.raises(ValueError, match=r"got \(2,\)"):
        exidel.ConstrainedDelaunay([0.0, 1.0], [])
    with pytest.raises(ValueError, match="segments: expected shape"):
        exidel.ConstrainedDelaunay(sq, [[0, 1, 2]])
    with pytest.raises(ValueError, match="segments: expected shape"):
        exidel.ConstrainedDelaunay(sq, [0, 1])
    with pytest.raises(ValueError, match="integer"):
        exidel.ConstrainedDelaunay(sq, [[0.0, 1.0]])
    for bad, row, named in (([[0, 1], [2, 4]], 1, 4), ([[0, -1]], 0, -1),
                            (np.array([[0, 2 ** 63 + 5]], dtype=np.uint64), 0, 2 ** 63 - 1),
                            ([[2 ** 40, 0]], 0, 2 ** 40)):
        with pytest.raises(exidel.TriangulationError) as info:
            exidel.ConstrainedDelaunay(sq, bad)
        e = info.value
        assert (e.kind, e.input_index, e.insertion) == ("invalid_segment", row, None)
        assert e.message == f"segment {row} names point {named} of 4"
    with pytest.raises(ValueError, match="unknown rule 'evenodd'; expected even_odd"):
        exidel.ConstrainedDelaunay(sq, [], rule="evenodd")
    with pytest.raises(ValueError, match="unknown rule"):
        exidel.ConstrainedDelaunay(sq, [], rule=None)
    with pytest.raises(ValueError, match="kernel"):
        exidel.ConstrainedDelaunay(sq, [], kernel="float")
    with pytest.raises(ValueError, match="unknown algorithm 'qhull'"):
        exidel.ConstrainedDelaunay(sq, [], algorithm="qhull")
    with pytest.raises(ValueError, match=r"holes: row 1 is not finite"):
        exidel.ConstrainedDelaunay(sq, [], holes=[[0.5, 0.5], [np.inf, 0]])
    with pytest.raises(ValueError, match="holes: expected shape"):
        exidel.ConstrainedDelaunay(sq, [], holes=[[0.5, 0.5, 0.5]])
    for limit in (0, -1, 2.5, True):
        with pytest.raises(ValueError, match="max_added_points"):
            exidel.ConstrainedDelaunay(sq, [], max_added_points=limit)


def test_repr_and_stats(rng):
    pts, segs = square_with_hole(rng)
    cdt = exidel.ConstrainedDelaunay(pts, segs)
    assert cdt.stats["triangles"] == cdt.nsimplex and cdt.stats["segments"] == 8
    assert cdt.stats["inside_triangles"] == len(cdt.inside_simplices)
    assert cdt.stats["constraints"] == len(cdt.constraints) and cdt.stats["regions"] == 3
    assert repr(cdt).startswith("<exidel.ConstrainedDelaunay: 51 points (+0 crossings), "
                                "8 segments")
    assert repr(cdt.certify()) == "<exidel.Certificate: ok>"
    assert "ConstrainedDelaunay" in exidel.__all__


def test_regional_attributes_label_their_regions(rng):
    pts, segs = square_with_hole(rng, hole=HOLE[::-1])
    cdt = exidel.ConstrainedDelaunay(pts, segs, rule="all",
                                     attributes=[(1.5, 1.5, 7.0), (10.0, 10.0, 9.0),
                                                 (3.2, 2.8, 2.0)])
    assert cdt.attribute.shape == (cdt.nsimplex,)
    assert cdt.unplaced_attributes.tolist() == [1]
    inside_hole = cdt.attribute == 7.0
    assert inside_hole.any() and (cdt.attribute[~inside_hole] != 7.0).all()
    # The hole's triangles are exactly one region, the one labelled 7; the ring between
    # the outer square and the hole is labelled 2.
    assert len(set(cdt.regions[inside_hole].tolist())) == 1
    assert (cdt.attribute == 2.0).any()
    assert exidel.ConstrainedDelaunay(pts, segs).attribute is None
    with pytest.raises(ValueError):
        exidel.ConstrainedDelaunay(pts, segs, attributes=[(0.0, 0.0)])
    with pytest.raises(ValueError):
        exidel.ConstrainedDelaunay(pts, segs, attributes=[(0.0, 0.0, float("nan"))])
