"""exidel.Voronoi: the Voronoi diagram with scipy.spatial.Voronoi's names, exact topology
and correctly rounded vertices."""

from __future__ import annotations

import gc

import numpy as np

from . import _core
from ._delaunay import (TriangulationError, default_threads, incremental_points,
                        parse_qhull_options)


class ClippedVoronoi:
    """The diagram intersected with a box (Voronoi.clip): every cell a convex polygon.

    vertices       (V, 2) float64: the Voronoi vertices inside the box or on it, then the
                   points the box adds (edge crossings, corners), each the correctly
                   rounded value of an exact point
    voronoi_vertex_count  how many of them are Voronoi vertices
    regions        per input point, the vertex indices of its clipped cell,
                   counter-clockwise (empty when the cell misses the box); lists of ints
    vertex_sites   per vertex, the sites whose cells have it as a corner; lists of ints
    """

    def __init__(self, d):
        self.vertices = d["vertices"]
        self.voronoi_vertex_count = int(d["voronoi_vertex_count"])
        self.regions = _core.split_lists(d["cell_offsets"], d["cell_vertices"])
        self.vertex_sites = _core.split_lists(d["site_offsets"], d["sites"])
        self.unbounded = d["unbounded"]


class Voronoi:
    """The Voronoi diagram of 2D points.

    Voronoi(points, kernel="adaptive", algorithm="external", threads=None, *,
            furthest_site=False, incremental=False, qhull_options=None)

    Every vertex is the centre of a maximal set of exactly cocircular Delaunay triangles
    (decided by the kernel's in-circle test, never by a tolerance) and its coordinates are
    the doubles nearest to the exact centre. Duplicate points share their twin's cell. A
    centre beyond the largest double raises ValueError; an inexact kernel's failed
    triangulation raises exidel.TriangulationError.

    furthest_site=True (or qhull_options "Qu") is scipy's furthest-site diagram, exact:
    the dual of Delaunay(points, furthest_site=True), each vertex the correctly rounded
    centre of its (merged, exactly cocircular) triangles; only the convex hull's corners
    have regions, each unbounded (regions[i] is [] for every other point, a point inside a
    hull edge included), entered along -entry_ray and left along exit_ray, the inward
    normals of the hull edges at the point. `algorithm` does not apply.

    incremental and qhull_options are scipy's, as for exidel.Delaunay: the options that
    cannot change an exact diagram (Qbb, Qc, Qz, Qt, QJ, Qx, Q11, Q12, Pp) are accepted,
    any other raises ValueError naming it; with incremental=True, add_points(points,
    restart=False) computes the diagram of all points again, exactly (a call costs as much
    as the first), and close() ends incremental mode.

    scipy's names and meaning:
      points, vertices (V, 2), regions (one list of vertex indices per input point,
      counter-clockwise, with -1 where an unbounded cell goes to infinity),
      point_region (input point -> its entry of regions: here the identity),
      ridge_points (r, 2), ridge_vertices (list of [v, w], -1 for a point at infinity),
      ridge_dict ({(p, q): [v, w]} over the rows of ridge_points, the values the lists of
      ridge_vertices), add_points, close
    exidel's own:
      vertex_sites   per vertex, every site exactly equidistant, counter-clockwise (a
                     list of lists of ints, as regions)
      unbounded      (n,) bool
      entry_ray, exit_ray  (n, 2): an unbounded cell comes in from infinity along
                     -entry_ray into its first vertex and leaves along exit_ray from its
                     last (outward hull-edge normals, exact in sign); (0, 0) if bounded
      collinear      no vertices (all sites on one line); `chain` orders them
      triangulation  the exidel.Delaunay arrays it is the dual of (simplices, halfedges)
      vertex_of_triangle  the vertex of every Delaunay triangle
      stats          how many centres each stage of the construction decided, and the
                     cocircularity tests
    """

    ndim = 2

    def __init__(self, points, kernel="adaptive", algorithm="external", threads=None, *,
                 furthest_site=False, incremental=False, qhull_options=None):
        self._qhull_options = parse_qhull_options(qhull_options, incremental, "Qbb Qc Qz", "Qc",
                                                  furthest=True)
        self.furthest_site = bool(furthest_site) or "Qu" in self._qhull_options
        self._settings = (kernel, algorithm, threads)
        self._incremental = bool(incremental)
        self._build(np.ascontiguousarray(points, dtype=np.float64))

    def _build(self, points):
        kernel, algorithm, threads = self._settings
        threads = default_threads() if threads is None else threads
        data = _core.VoronoiData(points, kernel, algorithm, threads, self.furthest_site)
        failure = data.failure()
        if failure is not None:
            raise TriangulationError(*failure)
        d = data.arrays()
        self.points = points
        self._data = data
        self._arrays = d
        self.vertices = d["vertices"]
        self.unbounded = d["unbounded"]
        self.entry_ray = d["entry_ray"]
        self.exit_ray = d["exit_ray"]
        self.vertex_of_triangle = d["vertex_of_triangle"]
        self.collinear = bool(d["collinear"])
        self.chain = d["chain"]
        self.simplices = d["triangles"]
        self.halfedges = d["halfedges"]
        self.stats = d["stats"]
        self.point_region = np.arange(self.points.shape[0], dtype=np.int32)
        # The list-of-lists attributes (regions, vertex_sites, ridge_vertices) are built on
        # first use: Python lists of 10^5 cells cost more than the diagram itself.
        self._lists = {}

    def _cached(self, name, build):
        if name not in self._lists:
            # Millions of new lists and ints would run the cyclic collector over and over
            # (half the time of building them); none of them can form a cycle.
            enabled = gc.isenabled()
            gc.disable()
            try:
                self._lists[name] = build()
            finally:
                if enabled:
                    gc.enable()
        return self._lists[name]

    @property
    def regions(self):
        d = self._arrays
        return self._cached("regions", lambda: _core.split_lists(
            d["cell_offsets"], d["cell_vertices"], self.unbounded))

    @property
    def vertex_sites(self):
        d = self._arrays
        return self._cached("vertex_sites", lambda: _core.split_lists(d["site_offsets"], d["sites"]))

    @property
    def ridge_points(self):
        return self._cached("ridges", self._ridges)[0]

    @property
    def ridge_vertices(self):
        return self._cached("ridges", self._ridges)[1]

    def _ridges(self):
        if self.collinear:
            # Consecutive sites along the line are separated by a whole bisector line.
            points = np.stack([self.chain[:-1], self.chain[1:]], axis=1).astype(np.int32)
            return points, [[-1, -1] for _ in range(len(points))]
        flat = self.simplices.reshape(-1)
        e = np.arange(flat.size)
        nxt = np.where(e % 3 == 2, e - 2, e + 1)
        twin = self.halfedges
        # Each Delaunay edge once (the half-edge with the larger twin, or a boundary one),
        # except those inside a cocircular group: both sides have the same vertex, and
        # their sites' cells meet in that point only.
        keep = (twin < e)
        keep &= (twin < 0) | (self.vertex_of_triangle[e // 3] != self.vertex_of_triangle[np.maximum(twin, 0) // 3])
        e = e[keep]
        points = np.stack([flat[e], flat[nxt[e]]], axis=1).astype(np.int32)
        v = self.vertex_of_triangle[e // 3].astype(np.int64)
        w = np.where(twin[e] < 0, -1, self.vertex_of_triangle[np.maximum(twin[e], 0) // 3])
        return points, np.stack([w, v], axis=1).tolist()

    @property
    def ridge_dict(self):
        """scipy's {(p, q): [v, w]}: for each row (p, q) of ridge_points, its entry of
        ridge_vertices (the same list objects)."""
        return self._cached("ridge_dict", lambda: dict(zip(
            map(tuple, self.ridge_points.tolist()), self.ridge_vertices)))

    def add_points(self, points, restart=False):
        """Adds points (an (k, 2) array) to a diagram made with incremental=True, with
        scipy's semantics and errors (RuntimeError when not incremental or closed,
        ValueError for a shape other than (k, 2)). Each call computes the diagram of all
        points again, exactly; `restart` changes nothing."""
        points = incremental_points(self, points)
        if points is not None:
            self._build(points)

    def close(self):
        """Ends incremental mode (scipy's close): add_points raises RuntimeError afterwards."""
        self._incremental = False

    @property
    def npoints(self):
        return int(self.points.shape[0])

    def clip(self, xmin, ymin, xmax, ymax):
        """The diagram inside the box [xmin, xmax] x [ymin, ymax] (exact rationals, every
        new point correctly rounded): a ClippedVoronoi. Not for the furthest-site diagram
        (ValueError)."""
        if self.furthest_site:
            raise ValueError("clip: the clipped diagram is the nearest-site one; this is the "
                             "furthest-site diagram")
        try:
            return ClippedVoronoi(self._data.clip(float(xmin), float(ymin), float(xmax), float(ymax)))
        except RuntimeError as error:  # std::invalid_argument: the box
            raise ValueError(str(error)) from None

    def __repr__(self):
        kind = "furthest-site " if self.furthest_site else ""
        return (f"<exidel.Voronoi: {kind}{self.npoints} sites, {len(self.vertices)} vertices, "
                f"{sum(map(bool, self.unbounded))} unbounded cells>")


