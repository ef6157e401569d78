"""exidel.Delaunay, exidel.certify: the triangulation with scipy.spatial.Delaunay's names."""

from __future__ import annotations

import os
import re
from dataclasses import dataclass

import numpy as np

from . import _core


def default_threads():
    """The thread count the exidel command uses by default: the hardware's."""
    return max(1, os.cpu_count() or 1)


# qhull's options (scipy's qhull_options=). exidel computes the exact Delaunay triangulation
# of every point, so the options that steer qhull's floating-point construction (scaling for
# precision, joggling, merging, keeping coplanar points, triangulating merged facets) have
# nothing to act on and are accepted silently; Qbb and Qz keep one visible effect, the scale
# of the lifted coordinate (paraboloid_scale, paraboloid_shift). Every other option would
# change the answer (QbB scales the input, QGn/QVn select facets) or
# concerns qhull's output files and tracing: it raises ValueError naming it.
_QHULL_SILENT = ("Qbb", "Qc", "Qz", "Qt", "QJ", "Qx", "Q11", "Q12", "Pp")
_QHULL_JOGGLE = re.compile(r"QJ(\d+(\.\d*)?|\.\d+)?([eE][-+]?\d+)?$")
# scipy refuses these with incremental=True (they rescale or add a point once, at the start).
_QHULL_NOT_INCREMENTAL = ("Qbb", "Qbk", "QBk", "QbB", "Qz")
_QHULL_WHY = {
    "QbB": "it scales the input to the unit cube, which changes its Delaunay triangulation",
    "Qbk": "it scales a coordinate of the input, which changes its Delaunay triangulation",
    "QBk": "it scales a coordinate of the input, which changes its Delaunay triangulation",
    "QG": "it selects 'good' facets (scipy's .good)",
    "QV": "it selects 'good' facets (scipy's .good)",
}


def parse_qhull_options(options, incremental, default, default_incremental, furthest=False):
    """The set of qhull option tokens of `options` (scipy's qhull_options= string; None: the
    class's scipy default), after scipy's incremental-mode check. Raises ValueError naming an
    option that exidel does not accept; "Qu" (furthest-site) is accepted when `furthest`."""
    if options is None:
        options = default_incremental if incremental else default
    if not isinstance(options, str):
        raise TypeError(f"qhull_options: expected a str, got {type(options).__name__}")
    tokens = options.split()
    if incremental:
        bad = [t for t in _QHULL_NOT_INCREMENTAL if t in tokens]
        if bad:
            raise ValueError(f"Qhull options {bad!r} are incompatible with incremental mode")
    for t in tokens:
        if t in _QHULL_SILENT or _QHULL_JOGGLE.match(t) or (furthest and t == "Qu"):
            continue
        why = next((w for k, w in _QHULL_WHY.items() if t.startswith(k)), None)
        raise ValueError(
            f"qhull_options: exidel does not accept {t!r}"
            + (f" ({why})" if why else "")
            + "; exidel computes the exact Delaunay triangulation and accepts only the options "
            "that cannot change it: " + ", ".join(_QHULL_SILENT) + " (QJ with or without an "
            "amount)")
    return frozenset("QJ" if _QHULL_JOGGLE.match(t) else t for t in tokens)


def incremental_points(obj, points):
    """add_points' checks, with scipy's errors: all the points afterwards (float64), or None
    when `points` is empty. `obj` has ._incremental, .ndim and .points."""
    if not obj._incremental:
        raise RuntimeError("incremental mode not enabled or already closed")
    points = np.asarray(points)
    if points.ndim != 2 or points.shape[1] != obj.ndim:
        raise ValueError("invalid size for new points array")
    if points.size == 0:
        return None
    return np.concatenate([obj.points, points.astype(np.float64)])


def _split(x):
    """Veltkamp's split of |x| <= 1: x == hi + lo exactly, each with at most 26 bits."""
    c = 134217729.0 * x
    hi = c - (c - x)
    return hi, x - hi


def _det2(a, b, c, d):
    """a d - b c for |a|, |b|, |c|, |d| <= 1 within a few ulps of the exact value, where the
    plain formula can lose every digit: both products and their difference are split into
    exact sums of doubles (Dekker's product, Knuth's sum) and the parts added smallest
    last."""
    def product(x, y):
        p = x * y
        xh, xl = _split(x)
        yh, yl = _split(y)
        return p, xl * yl - (((p - xh * yh) - xl * yh) - xh * yl)

    def total(x, y):
        s = x + y
        z = s - x
        return s, (x - (s - z)) + (y - z)
    p, ep = product(a, d)
    q, eq = product(b, c)
    d1, e1 = total(p, -q)
    d2, e2 = total(ep, -eq)
    return (d1 + d2) + (e1 + e2)


def _scale_rows(v):
    """v (rows of vectors) divided by a power of two per row, exactly, so that the largest
    entry of each row is in [0.5, 1); the direction of each row is unchanged."""
    _, e = np.frexp(np.max(np.abs(v), axis=-1))
    return np.ldexp(v, -e[..., None]), e


class TriangulationError(RuntimeError):
    """The algorithm stopped with a typed failure: an inexact kernel contradicted itself
    (never with an exact kernel), or, for ConstrainedDelaunay, a segment names no point
    ("invalid_segment") or the crossings exceed max_added_points ("too_many_crossings"). Carries the C++ library's typed failure:

    kind         the FailureKind name ("no_visible_edge", "erosion_inconsistent", ...)
    input_index  the input point being inserted, or None
    insertion    its position in the insertion order, or None (merges, the final check)
    message      where it happened, in words
    """

    def __init__(self, kind, input_index, insertion, message):
        super().__init__(f"{kind}: {message}")
        self.kind = kind
        self.input_index = input_index
        self.insertion = insertion
        self.message = message


@dataclass(frozen=True)
class Location:
    """Where queries lie (Delaunay.locate): arrays of the queries' shape.

    kind     int8: 0 inside, 1 on an edge, 2 on a vertex, 3 outside (exidel.location_kinds)
    simplex  int32: a triangle holding the query, or outside the triangle of a hull edge
             that sees it; -1 without triangles
    edge     int32: the half-edge the query is on (on_edge), or a hull half-edge that sees
             it (outside); -1 otherwise
    vertex   int32: the vertex the query is on (on_vertex); -1 otherwise
    """

    kind: np.ndarray
    simplex: np.ndarray
    edge: np.ndarray
    vertex: np.ndarray

    def kind_names(self):
        """The kinds as strings ("inside", "on_edge", "on_vertex", "outside")."""
        return np.asarray(_core.location_kinds)[self.kind]


class _TriangleArrays:
    """What Delaunay and ConstrainedDelaunay derive alike from their arrays (points,
    simplices, halfedges, hull, collinear; _neighbors caches the neighbours)."""

    @property
    def npoints(self):
        return int(self.points.shape[0])

    @property
    def nsimplex(self):
        return int(self.simplices.shape[0])

    @property
    def neighbors(self):
        """(t, 3) int32: neighbors[i, j] is the triangle opposite vertex j of triangle i,
        -1 on the hull."""
        if self._neighbors is None:
            m = self.nsimplex
            # The edge opposite vertex j of triangle t is half-edge 3t + (j + 1) % 3.
            e = 3 * np.arange(m, dtype=np.int64)[:, None] + np.array([1, 2, 0])
            twin = self.halfedges[e]
            self._neighbors = np.where(twin >= 0, twin // 3, -1).astype(np.int32)
        return self._neighbors

    @property
    def convex_hull(self):
        """(h, 2) int32: the hull edges, counter-clockwise; (0, 2) without triangles."""
        if self.collinear:
            return np.empty((0, 2), dtype=np.int32)
        return np.stack([self.hull, np.roll(self.hull, -1)], axis=1)


class Delaunay(_TriangleArrays):
    """The Delaunay triangulation of 2D points, exact with an exact kernel.

    Delaunay(points, kernel="adaptive", algorithm="external", incircle="determinant",
             order="auto", threads=None, counters=False, *, incremental=False,
             qhull_options=None)

    points     array of shape (n, 2), float64 (other dtypes are converted once). Every
               finite input is accepted: duplicates (kept out of the triangulation and
               listed in .duplicates), collinear sets (no triangles: .collinear is True
               and .hull is the chain of distinct points), fewer than three points.
               A NaN or infinite coordinate raises ValueError naming the row.
    kernel     any kernel spelling of the exidel command (exidel.kernel_spellings):
               "adaptive" (exact, the fastest), "exact", "exact-cpp", "double",
               "long-double", "mpfr:<bits>". With an inexact kernel the result may be wrong
               (exidel.certify says so), or the run raises TriangulationError.
    algorithm  one of exidel.algorithms ("external", "bowyer-watson", "randomized",
               "lawson", "sweep-hull", "divide-and-conquer", "dwyer").
    incircle   "determinant" or "cosine" (the paper's cosine test).
    order      the external algorithm's insertion order: "auto", "lexicographic",
               "radial", "strips".
    threads    worker threads of the strips order (the result does not depend on it);
               None (the default): the hardware's thread count, as the exidel command.
    counters   record predicate calls, flips, ... in .stats["counters"].
    furthest_site  scipy's: the furthest-site Delaunay triangulation instead, exact: the
               triangulation of the extreme points (the hull's corners; every other point
               is in no triangle) whose every circumcircle holds every point (Chew's
               algorithm with the in-circle test reversed). Also qhull_options "Qu".
               algorithm, incircle, order and counters do not apply to it.
    incremental  scipy's: allow add_points (below).
    qhull_options  scipy's qhull option string, for code written for scipy. exidel always
               answers the exact, unjoggled Delaunay triangulation of every point, so the
               options that only steer qhull's floating-point construction are accepted
               and change nothing in the triangulation: Qbb, Qc, Qz, Qt, QJ (joggling:
               exidel never needs to perturb the input, and does not), Qx, Q11, Q12, Pp.
               Qbb and Qz keep their one visible effect, the scale of the lifted
               coordinate (paraboloid_scale, paraboloid_shift). Any other option raises
               ValueError naming it (QbB would triangulate scaled points, QGn selects
               facets). None (the default) is
               scipy's default: "Qbb Qc Qz Q12", and "Qc" when incremental.

    Attributes with scipy's names and meaning:
      points      (n, 2) float64, the input
      simplices   (m, 3) int32, the triangles' vertices (input indices), counter-clockwise
      neighbors   (m, 3) int32, neighbors[i, j] the triangle opposite vertex j of
                  triangle i, -1 on the boundary
      convex_hull (h, 2) int32, the boundary edges, counter-clockwise
      vertex_neighbor_vertices  (indptr, indices) as in scipy
      vertex_to_simplex  (n,) int32, a triangle holding each point
      transform   (m, 3, 2) float64, the barycentric transforms
      equations, paraboloid_scale, paraboloid_shift, lift_points(x), plane_distance(xi):
                  the triangles as facets of the lifted points, with qhull's scaling
      nsimplex, npoints, ndim
      add_points(points, restart=False), close()
      find_simplex(xi, bruteforce=False, tol=None)  exact: a triangle holding each query
    exidel's own:
      locate(xi, order="hilbert", threads=None)  exact classification: inside, on an edge
                  (which), on a vertex (which), outside (with the hull edge that sees it)
      nearest(xi, threads=None)  the exactly nearest point to each query
      hull        (h,) int32, the boundary cycle counter-clockwise from the
                  lexicographically smallest point, collinear boundary points included
      halfedges   (3m,) int32, twin of half-edge e (from simplices.flat[e] to the next
                  vertex of its triangle), -1 on the boundary (delaunator's layout)
      duplicates  input indices that repeat an earlier point exactly
      vertex_of_input  (n,) int32, the first occurrence of each input point
      collinear   True when there are no triangles (fewer than three distinct points or
                  all on one line)
      stats       algorithm, order, strips, cavity_pieces, sizes (and counters when asked)
    Unlike scipy, no point is ever left out (.coplanar is always empty except for the
    duplicates, which scipy also reports there) and nothing is joggled. The arrays computed
    from the triangles (neighbors, transform, equations, vertex_to_simplex, ...) are built
    on first use and kept until add_points changes the triangulation.
    """

    ndim = 2

    def __init__(self, points, kernel="adaptive", algorithm="external", incircle="determinant",
                 order="auto", threads=None, counters=False, *, furthest_site=False,
                 incremental=False, qhull_options=None):
        self._qhull_options = parse_qhull_options(qhull_options, incremental,
                                                  "Qbb Qc Qz Q12", "Qc", furthest=True)
        self.furthest_site = bool(furthest_site) or "Qu" in self._qhull_options
        self._settings = (kernel, algorithm, incircle, order, threads, counters)
        self._incremental = bool(incremental)
        self._triangulate(np.ascontiguousarray(points, dtype=np.float64))

    def _triangulate(self, points):
        kernel, algorithm, incircle, order, threads, counters = self._settings
        threads = default_threads() if threads is None else threads
        if self.furthest_site:
            r = _core.furthest_site(points, kernel)
        else:
            r = _core.triangulate(points, kernel, algorithm, incircle, order, threads, counters)
        failure = r.get("failure")
        if failure is not None:
            raise TriangulationError(failure["kind"], failure["input_index"],
                                     failure["insertion"], failure["message"])
        self.kernel = _core.kernel_name(kernel)
        self._mutable = None  # add_points' triangulation, made on first use
        self._adopt(points, r)
        self.stats.update(algorithm=r["algorithm"], order=r["strategy"], strips=r["strips"],
                          cavity_pieces=r.get("cavity_pieces", 0))
        if counters and "counters" in r:
            self.stats["counters"] = r["counters"]

    @classmethod
    def _from_arrays(cls, points, r, kernel):
        """A Delaunay of `points` with triangulate()'s (or a snapshot's) arrays r, not
        recomputed (MutableTriangulation.delaunay)."""
        self = cls.__new__(cls)
        self._qhull_options = parse_qhull_options(None, False, "Qbb Qc Qz Q12", "Qc")
        self.furthest_site = False
        self._settings = (kernel, "external", "determinant", "auto", None, False)
        self._incremental = False
        self.kernel = _core.kernel_name(kernel)
        self._mutable = None
        self._adopt(points, r)
        return self

    def _adopt(self, points, r):
        """points and the arrays of r (triangulate's or a snapshot's) as the attributes."""
        self.points = points
        self.simplices = r["triangles"]
        self.halfedges = r["halfedges"]
        self.hull = r["hull"]
        self.vertex_of_input = r["vertex_of_input"]
        self.duplicates = r["duplicates"]
        self.collinear = bool(r["collinear"])
        self.stats = dict(getattr(self, "stats", {}))
        self.stats.pop("counters", None)
        self.stats.update({
            "kernel": self.kernel,
            "points": int(self.points.shape[0]),
            "vertices": int(self.points.shape[0] - self.duplicates.size),
            "triangles": int(self.simplices.shape[0]),
            "duplicates": int(self.duplicates.size),
        })
        # Built on first use, from the arrays above.
        self._neighbors = None
        self._transform = None
        self._equations = None
        self._paraboloid = None
        self._vertex_to_simplex = None
        self._locator = None

    def _query(self, xi, call):
        """xi as (n, 2) rows given to call(locator, rows), and the shape of the answer."""
        xi = np.asarray(xi, dtype=np.float64)
        if xi.ndim == 0 or xi.shape[-1] != self.ndim:
            raise ValueError(f"xi: expected shape (..., 2), got {xi.shape}")
        shape = xi.shape[:-1]
        rows = np.ascontiguousarray(xi.reshape(-1, self.ndim))
        if self._locator is None:
            self._locator = _core.Locator(self.points, self.simplices, self.halfedges,
                                          self.hull, self.collinear, self.kernel)
        try:
            return shape, call(self._locator, rows)
        except RuntimeError as e:  # "location_exceeded: ..." from an inexact kernel
            kind_name, _, message = str(e).partition(": ")
            raise TriangulationError(kind_name, None, None, message) from None

    def _located(self, xi, order, threads):
        """The shape of the answer and the C++ Locator's four arrays."""
        threads = default_threads() if threads is None else threads
        shape, arrays = self._query(xi, lambda loc, rows: loc.locate(rows, order, threads))
        return (shape, *arrays)

    def nearest(self, xi, k=None, threads=None):
        """The index of the point nearest to each query (int32, the queries' shape), decided
        exactly (the kernel's compare_distance): no point is strictly nearer. Among equally
        near points one is chosen (a repeated point by its first occurrence); -1 when there
        are no points. A NaN or infinite query raises ValueError naming the row.

        With k (an int >= 0): the k nearest points of each query, shape (..., k), nearest
        first, found by walking the triangulation from the nearest point; ties in distance
        are ordered by index; a repeated point counts once (its first occurrence); -1 past
        the number of distinct points."""
        threads = default_threads() if threads is None else threads
        if k is None:
            shape, out = self._query(xi, lambda loc, rows: loc.nearest(rows, threads))
            return out.reshape(shape)
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 0:
            raise ValueError(f"k must be an integer >= 0, got {k!r}")
        shape, out = self._query(xi, lambda loc, rows: loc.nearest_k(rows, int(k), threads))
        return out.reshape(shape + (int(k),))

    def within_radius(self, xi, r, threads=None):
        """The points p with |p - x| <= r, decided exactly, for each query x of xi flattened
        to (q, 2), nearest first (ties by index; a repeated point once, by its first
        occurrence), as compressed rows: the points of query i are
        indices[indptr[i]:indptr[i + 1]]. Returns (indptr int64, indices int32). (scipy's
        cKDTree.query_ball_point answers lists, unsorted unless return_sorted.)"""
        threads = default_threads() if threads is None else threads
        r = float(r)
        _, arrays = self._query(xi, lambda loc, rows: loc.within_radius(rows, r, threads))
        return arrays

    def natural_neighbors(self, xi, exact=False, threads=None):
        """Sibson's natural neighbour coordinates of each query, as compressed rows (the
        layout of scipy's vertex_neighbor_vertices): for the i-th query of xi flattened to
        (q, 2), the points indices[indptr[i]:indptr[i + 1]] with weights
        weights[indptr[i]:indptr[i + 1]] (summing to 1). A query on a point has that point
        alone (weight 1); on a hull edge, the edge's two ends (linear along it); outside
        the convex hull, none. The neighbours are decided exactly (the kernel's incircle);
        the weights are areas of Voronoi polygons computed in doubles, or with exact=True
        in exact rationals, each weight then the double nearest the exact one. Returns
        (indptr int64, indices int32, weights float64)."""
        if self.furthest_site:
            raise ValueError("natural_neighbors: the coordinates are those of the Delaunay "
                             "triangulation, not the furthest-site one")
        threads = default_threads() if threads is None else threads
        _, arrays = self._query(
            xi, lambda loc, rows: loc.natural_coordinates(rows, bool(exact), threads))
        return arrays

    def locate(self, xi, order="hilbert", threads=None):
        """Where each query lies, decided exactly (the kernel's orient2d, no tolerance).

        xi       array of shape (..., 2)
        order    "hilbert" (default: the queries sorted along a Hilbert curve, each walk
                 from the previous answer), "given" (their own order), "jump" (each from
                 the nearest of a sample of vertices); the answers' kinds and vertices do
                 not depend on it
        threads  worker threads (None: the hardware's); the answers do not depend on it
        Returns a Location with arrays of shape (...):
          kind     int8: 0 inside a triangle, 1 on an edge, 2 on a vertex, 3 outside the
                   convex hull (exidel.location_kinds names them)
          simplex  int32: a triangle holding the query (inside, on_edge, on_vertex), or,
                   outside, the triangle of a hull edge that sees it; -1 when there are no
                   triangles (collinear points)
          edge     int32: on an edge, the half-edge (an index into .halfedges: it runs from
                   simplices.flat[edge] to the next corner of its triangle); outside, a
                   hull half-edge with the query strictly on its outer side; -1 otherwise.
                   Collinear points: on_edge's edge is the position i of the segment
                   hull[i], hull[i + 1]
          vertex   int32: on a vertex, its index (a repeated point's first occurrence);
                   -1 otherwise
        A NaN or infinite query raises ValueError naming the row. With an inexact kernel
        a walk whose answers contradict each other raises TriangulationError."""
        shape, kind, simplex, edge, vertex = self._located(xi, order, threads)
        return Location(kind.reshape(shape), simplex.reshape(shape), edge.reshape(shape),
                        vertex.reshape(shape))

    def find_simplex(self, xi, bruteforce=False, tol=None):
        """scipy's find_simplex: the index of a triangle holding each query, -1 outside the
        convex hull. Decided exactly, so `bruteforce` and `tol` are accepted for scipy's
        sake and change nothing: a query on an edge or a vertex is always found (in one of
        the triangles holding it), however thin the triangles, where scipy's eps test may
        answer -1. A NaN or infinite query raises ValueError (scipy answers -1)."""
        del bruteforce, tol
        shape, kind, simplex, _, _ = self._located(xi, "hilbert", None)
        out = np.where(kind == 3, -1, simplex).astype(np.intc)
        return out.reshape(shape)

    def add_points(self, points, restart=False):
        """Adds points (an (k, 2) array) to a triangulation made with incremental=True, with
        scipy's semantics: the new points get the indices npoints, npoints + 1, ..., and
        every attribute describes the triangulation of all points afterwards. Raises
        RuntimeError when the triangulation was not made incremental or close() was called,
        ValueError when `points` is not (k, 2).

        The points are inserted one by one into the existing triangulation (exidel's
        MutableTriangulation: located by a walk, then Lawson's flips), exactly with an
        exact kernel; the arrays are then read out of it again, which costs O(n) per call.
        With furthest_site=True every call triangulates all the points again. `restart` is
        accepted for scipy's sake and changes nothing: the result is the exact
        triangulation either way."""
        all_points = incremental_points(self, points)
        if all_points is None:
            return
        if self.furthest_site:
            self._triangulate(all_points)
            return
        new = all_points[self.points.shape[0]:]
        try:
            if self._mutable is None:
                self._mutable = _core.MutableTriangulation(self.points, self.kernel)
            self._mutable.insert(new)
            r = self._mutable.snapshot()
        except RuntimeError as e:  # "flips_exceeded: ..." from an inexact kernel
            self._mutable = None
            kind_name, _, message = str(e).partition(": ")
            raise TriangulationError(kind_name, None, None, message) from None
        self._adopt(all_points, r)

    def close(self):
        """Ends incremental mode (scipy's close): add_points raises RuntimeError afterwards.
        The triangulation and its attributes stay."""
        self._incremental = False
        self._mutable = None

    @property
    def vertex_to_simplex(self):
        """(n,) int32: for each point, a triangle that has it as a vertex; -1 for a point
        that is no vertex (a duplicate: its first occurrence is the vertex, see
        vertex_of_input) and for every point when there are no triangles. Which of the
        point's triangles is given is arbitrary, as in scipy. (scipy writes the nearest
        vertex's index, .coplanar[:, 2], for a point it left out; exidel writes -1.)"""
        if self._vertex_to_simplex is None:
            v = np.full(self.npoints, -1, dtype=np.int32)
            v[self.simplices.reshape(-1)] = np.repeat(np.arange(self.nsimplex, dtype=np.int32), 3)
            self._vertex_to_simplex = v
        return self._vertex_to_simplex

    @property
    def transform(self):
        """(m, 3, 2) float64, scipy's barycentric transforms: for triangle i with vertices
        (p0, p1, p2), transform[i, :2] is the inverse of T = [p0 - p2, p1 - p2] (as columns)
        and transform[i, 2] is r = p2, so the barycentric coordinates of x are
        c = transform[i, :2] @ (x - r) and 1 - c.sum(). T is formed from the rounded
        differences as in scipy; its inverse is the adjugate over a determinant computed
        with error-free products and sums (after exact power-of-two scaling), so every
        triangle gets a finite inverse within a few ulps of that of T, including the very
        thin triangles for which scipy writes NaN (every exidel triangle has positive
        area). (0, 3, 2)
        without triangles."""
        if self._transform is None:
            s = self.simplices
            r = self.points[s[:, 2]]
            # d[i, j] = p_j - r: the columns of T.
            d = self.points[s[:, :2]] - r[:, None, :]
            t = np.stack([d[:, 0, 0], d[:, 1, 0], d[:, 0, 1], d[:, 1, 1]], axis=1)
            t, e = _scale_rows(t)
            a, b, c, dd = t.T
            det = _det2(a, b, c, dd)
            inverse = np.stack([dd, -b, -c, a], axis=1) / det[:, None]
            out = np.empty((self.nsimplex, 3, 2), dtype=np.float64)
            out[:, :2, :] = np.ldexp(inverse, -e[:, None]).reshape(-1, 2, 2)
            out[:, 2, :] = r
            self._transform = out
        return self._transform

    def _scale_shift(self):
        """qhull's scaling of the lifted coordinate under options Qbb (and Qz), the numbers
        scipy reports."""
        if self._paraboloid is None:
            scale, shift = 1.0, 0.0
            p = self.points
            if "Qbb" in self._qhull_options and p.shape[0] > 0:
                lifted = p[:, 0] * p[:, 0] + p[:, 1] * p[:, 1]
                low, high = lifted.min(), lifted.max()
                newhigh = np.abs(p).max()
                if "Qz" in self._qhull_options:
                    # qhull's point at infinity: above the centroid (inside the coordinate
                    # range), at 1.1 times the highest lifted point.
                    high = high * 1.1
                if high > low:
                    scale = float(newhigh / (high - low))
                    shift = float(-low * scale)
                if not (np.isfinite(scale) and np.isfinite(shift)):
                    scale, shift = 1.0, 0.0
            self._paraboloid = (scale, shift)
        return self._paraboloid

    @property
    def paraboloid_scale(self):
        """scipy's scale of the lifted coordinate: with qhull option Qbb (in the default),
        qhull maps x^2 + y^2 from [low, high] (the lowest lifted input point; the highest,
        times 1.1 with Qz for its point at infinity) onto [0, m], m the largest absolute
        coordinate: the scale is m / (high - low). 1.0 without Qbb (incremental mode) and
        when every point lifts to the same height (where qhull stops with an error)."""
        return self._scale_shift()[0]

    @property
    def paraboloid_shift(self):
        """scipy's shift of the lifted coordinate: -low * paraboloid_scale (0.0 without
        Qbb)."""
        return self._scale_shift()[1]

    def lift_points(self, x):
        """Lifts points (shape (..., 2)) onto qhull's paraboloid: (..., 3) with the last
        coordinate (x^2 + y^2) * paraboloid_scale + paraboloid_shift, as scipy."""
        x = np.asarray(x, dtype=np.float64)
        if x.shape[-1:] != (self.ndim,):
            raise ValueError(f"lift_points: expected points of shape (..., 2), got {x.shape}")
        scale, shift = self._scale_shift()
        z = np.empty(x.shape[:-1] + (self.ndim + 1,), dtype=np.float64)
        z[..., :-1] = x
        z[..., -1] = (x ** 2).sum(axis=-1) * scale + shift
        return z

    @property
    def equations(self):
        """(m, 4) float64, scipy's [normal, offset] of each triangle's plane through its
        lifted vertices (lift_points): unit normal pointing down (out of the lower hull),
        normal . z + offset = 0 on the plane; the lifted input points lie on or above every
        plane, at distance <= 0 (plane_distance). The lifted differences are formed as
        (x1 - x0)(x1 + x0) + (y1 - y0)(y1 + y0), not as differences of lifted values.
        (0, 4) without triangles."""
        if self._equations is None:
            scale, _ = self._scale_shift()
            s = self.simplices
            p0 = self.points[s[:, 0]]
            def edge(k):
                p = self.points[s[:, k]]
                d = p - p0
                dz = (d[:, 0] * (p[:, 0] + p0[:, 0]) + d[:, 1] * (p[:, 1] + p0[:, 1])) * scale
                return _scale_rows(np.stack([d[:, 0], d[:, 1], dz], axis=1))[0]
            u, v = edge(1), edge(2)
            # The counter-clockwise triangle's u x v points up; qhull's lower facets down.
            n = -np.cross(u, v)
            n /= np.sqrt((n * n).sum(axis=1))[:, None]
            z0 = self.lift_points(p0)
            out = np.empty((self.nsimplex, 4), dtype=np.float64)
            out[:, :3] = n
            out[:, 3] = -(n * z0).sum(axis=1)
            self._equations = out
        return self._equations

    def plane_distance(self, xi):
        """Signed distances from the lifted points xi (shape (..., 2)) to every triangle's
        plane (equations): shape (..., nsimplex), as scipy's. Negative above a plane."""
        xi = np.asarray(xi, dtype=np.float64)
        if xi.shape[-1:] != (self.ndim,):
            raise ValueError("xi has different dimensionality than triangulation")
        z = self.lift_points(xi.reshape(-1, self.ndim))
        eq = self.equations
        out = z @ eq[:, :3].T + eq[:, 3]
        return out.reshape(xi.shape[:-1] + (self.nsimplex,))

    @property
    def coplanar(self):
        """scipy's (k, 3) array of points left out: [point, a simplex, nearest vertex]. Only
        exact duplicates are ever left out; each is listed with a triangle of its twin."""
        if self.duplicates.size == 0 or self.collinear:
            return np.empty((0, 3), dtype=np.int32)
        twin = self.vertex_of_input[self.duplicates]
        flat = self.simplices.reshape(-1)
        first_corner = np.full(self.npoints, -1, dtype=np.int64)
        first_corner[flat[::-1]] = np.arange(flat.size - 1, -1, -1)
        return np.stack([self.duplicates, first_corner[twin] // 3, twin], axis=1).astype(np.int32)

    @property
    def vertex_neighbor_vertices(self):
        """(indptr, indices): the neighbours of vertex k are indices[indptr[k]:indptr[k+1]]."""
        s = self.simplices.astype(np.int64)
        a = np.concatenate([s[:, 0], s[:, 1], s[:, 2], s[:, 1], s[:, 2], s[:, 0]])
        b = np.concatenate([s[:, 1], s[:, 2], s[:, 0], s[:, 0], s[:, 1], s[:, 2]])
        if self.collinear and self.hull.size > 1:
            a = np.concatenate([self.hull[:-1], self.hull[1:]]).astype(np.int64)
            b = np.concatenate([self.hull[1:], self.hull[:-1]]).astype(np.int64)
        pairs = np.unique(np.stack([a, b], axis=1), axis=0) if a.size else np.empty((0, 2), np.int64)
        indptr = np.zeros(self.npoints + 1, dtype=np.int32)
        np.add.at(indptr, pairs[:, 0] + 1, 1)
        return np.cumsum(indptr).astype(np.int32), pairs[:, 1].astype(np.int32)

    def certify(self):
        """The exact certificate of this result (exidel.certify)."""
        return certify(self.points, self)

    def __repr__(self):
        return (f"<exidel.Delaunay: {self.npoints} points, {self.nsimplex} triangles, "
                f"kernel {self.kernel}, algorithm {self.stats['algorithm']}>")


@dataclass(frozen=True)
class Finding:
    """One defect the certifier found, located.

    kind      the FindingKind name: "not_ccw", "not_delaunay", "missing_point", ...
    message   what and where in words, naming triangles and points by index:
              "triangle 18 (4, 9, 2) is clockwise"
    triangle  the triangle concerned, its row in the simplices given (-1 when none)
    points    the input points concerned, in the message's order (a repeated point by its
              first occurrence); for not_delaunay (a, b, c, d): edge (a, b) of triangle
              (a, b, c), and d, strictly inside its circumcircle
    index, other  the C++ Finding's raw indices (half-edge, hull position, ...)
    """

    kind: str
    message: str
    triangle: int = -1
    points: tuple = ()
    index: int = -1
    other: int = -1

    def __str__(self):
        return f"{self.kind}: {self.message}"


class Certificate:
    """What exidel.certify found.

    ok              True when the triangulation is the Delaunay triangulation
    findings        list of Finding (the first 64 unless certify(..., all=True))
    total_findings  how many there are in all
    kinds           the set of finding kinds among .findings
    notes           what was normalised before certifying (clockwise triangles turned,
                    later copies of repeated points renamed, the hull reversed or
                    rotated), one sentence each
    """

    def __init__(self, d):
        self.ok = bool(d["ok"])
        self.total_findings = int(d["total_findings"])
        self.findings = [Finding(f["kind"], f["message"], int(f["triangle"]),
                                 tuple(int(p) for p in f["points"]), int(f["index"]),
                                 int(f["other"])) for f in d["findings"]]
        self.kinds = {f.kind for f in self.findings}
        self.notes = list(d["notes"])

    def __bool__(self):
        return self.ok

    def __repr__(self):
        if self.ok:
            return "<exidel.Certificate: ok>"
        return (f"<exidel.Certificate: {self.total_findings} findings, first "
                f"{self.findings[0]}>")


def certify(points, triangulation, reorient=True, all=False):
    """Decides exactly whether `triangulation` is the Delaunay triangulation of `points`,
    with the same reader conventions and findings as `exidel certify`.

    triangulation  any of:
                   - an exidel.Delaunay;
                   - a scipy.spatial.Delaunay, or anything with a .simplices array;
                   - an (m, 3) integer array of triangles (scipy's simplices, a mesher's);
                   - delaunator's arrays: a dict or object with "triangles" (flat) and
                     optionally "halfedges" and "hull".
                   What is not given is derived: twins from shared edges, the hull from
                   the boundary, duplicates from the points. An empty array claims that
                   the points are collinear.
    reorient       True (default): normalise the producers' conventions first (a later
                   copy of a repeated point stands for its first occurrence, clockwise
                   triangles are turned with their twins, a clockwise or rotated hull is
                   put in order; Certificate.notes says what changed). False: hold the
                   triangulation to exidel's own layout, as `exidel certify --strict`.
    all            keep every finding (default: the first 64; all are counted).
    Checks: shape, topology, every triangle counter-clockwise, the boundary is the convex
    hull, every distinct point is a vertex, Euler's count, every edge locally Delaunay
    (exact predicates throughout). A finding's triangle is a row of what was given.
    Returns a Certificate.
    """
    pts = np.ascontiguousarray(points, dtype=np.float64)
    limit = -1 if all else 64
    arrays = {}
    if isinstance(triangulation, Delaunay):
        t = triangulation
        triangles = t.simplices
        arrays = dict(halfedges=t.halfedges, hull=t.hull, duplicates=t.duplicates)
    elif isinstance(triangulation, dict) or hasattr(triangulation, "triangles"):
        get = (triangulation.get if isinstance(triangulation, dict)
               else lambda k: getattr(triangulation, k, None))
        triangles = np.asarray(get("triangles"))
        for key in ("halfedges", "hull", "duplicates"):
            if get(key) is not None:
                arrays[key] = np.asarray(get(key))
    else:
        triangles = np.asarray(getattr(triangulation, "simplices", triangulation))
    if triangles.size == 0:
        triangles = np.empty((0, 3), dtype=np.int64)
    if not np.issubdtype(triangles.dtype, np.integer):
        raise ValueError("triangles: expected integers (an (m, 3) simplices array or a flat "
                         "delaunator triangles array)")
    if triangles.ndim == 2 and triangles.shape[1] != 3 or triangles.ndim > 2 or \
            triangles.size % 3 != 0:
        raise ValueError(f"triangles: expected shape (m, 3) or (3m,), got {triangles.shape}")
    return Certificate(_core.certify(pts, triangles.reshape(-1), strict=not reorient,
                                     max_findings=limit, **arrays))
