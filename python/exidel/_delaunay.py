"""exidel.Delaunay, exidel.certify: the triangulation with scipy.spatial.Delaunay's names."""

from __future__ import annotations

import os
from dataclasses import dataclass

import numpy as np

from . import _core


def default_threads():
    """The thread count the exidel command uses by default: the hardware's."""
    return max(1, os.cpu_count() or 1)


class TriangulationError(RuntimeError):
    """An inexact kernel contradicted itself and the algorithm stopped (never raised with an
    exact kernel). Carries the C++ library's typed failure:

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


class Delaunay:
    """The Delaunay triangulation of 2D points, exact with an exact kernel.

    Delaunay(points, kernel="adaptive", algorithm="external", incircle="determinant",
             order="auto", threads=None, counters=False)

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

    Attributes with scipy's names and meaning:
      points      (n, 2) float64, the input
      simplices   (m, 3) int32, the triangles' vertices (input indices), counter-clockwise
      neighbors   (m, 3) int32, neighbors[i, j] the triangle opposite vertex j of
                  triangle i, -1 on the boundary
      convex_hull (h, 2) int32, the boundary edges, counter-clockwise
      vertex_neighbor_vertices  (indptr, indices) as in scipy
      nsimplex, npoints, ndim
    exidel's own:
      hull        (h,) int32, the boundary cycle counter-clockwise from the
                  lexicographically smallest point, collinear boundary points included
      halfedges   (3m,) int32, twin of half-edge e (from simplices.flat[e] to the next
                  vertex of its triangle), -1 on the boundary (delaunator's layout)
      duplicates  input indices that repeat an earlier point exactly
      vertex_of_input  (n,) int32, the first occurrence of each input point
      collinear   True when there are no triangles (fewer than three distinct points or
                  all on one line)
      stats       algorithm, order, strips, sizes (and counters when asked)
    Unlike scipy, no point is ever left out (.coplanar is always empty except for the
    duplicates, which scipy also reports there) and nothing is joggled.
    """

    ndim = 2

    def __init__(self, points, kernel="adaptive", algorithm="external", incircle="determinant",
                 order="auto", threads=None, counters=False):
        self.points = np.ascontiguousarray(points, dtype=np.float64)
        threads = default_threads() if threads is None else threads
        r = _core.triangulate(self.points, kernel, algorithm, incircle, order, threads, counters)
        failure = r.get("failure")
        if failure is not None:
            raise TriangulationError(failure["kind"], failure["input_index"],
                                     failure["insertion"], failure["message"])
        self.kernel = _core.kernel_name(kernel)
        self.simplices = r["triangles"]
        self.halfedges = r["halfedges"]
        self.hull = r["hull"]
        self.vertex_of_input = r["vertex_of_input"]
        self.duplicates = r["duplicates"]
        self.collinear = bool(r["collinear"])
        self.stats = {
            "algorithm": r["algorithm"],
            "order": r["strategy"],
            "strips": r["strips"],
            "kernel": self.kernel,
            "points": int(self.points.shape[0]),
            "vertices": int(self.points.shape[0] - self.duplicates.size),
            "triangles": int(self.simplices.shape[0]),
            "duplicates": int(self.duplicates.size),
        }
        if counters:
            self.stats["counters"] = r["counters"]
        self._neighbors = None

    @property
    def npoints(self):
        return int(self.points.shape[0])

    @property
    def nsimplex(self):
        return int(self.simplices.shape[0])

    @property
    def neighbors(self):
        if self._neighbors is None:
            m = self.nsimplex
            # The edge opposite vertex j of triangle t is half-edge 3t + (j + 1) % 3.
            e = 3 * np.arange(m, dtype=np.int64)[:, None] + np.array([1, 2, 0])
            twin = self.halfedges[e]
            self._neighbors = np.where(twin >= 0, twin // 3, -1).astype(np.int32)
        return self._neighbors

    @property
    def convex_hull(self):
        if self.collinear:
            return np.empty((0, 2), dtype=np.int32)
        return np.stack([self.hull, np.roll(self.hull, -1)], axis=1)

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
            return "<exidel.Certificate: Delaunay>"
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
