"""exidel.ConstrainedDelaunay: the constrained Delaunay triangulation of points and segments,
its regions (fill rule, hole seeds) and its exact certificate."""

from __future__ import annotations

import numpy as np

from . import _core
from ._delaunay import Certificate, TriangulationError, _TriangleArrays

RULES = ("even_odd", "non_zero", "enclosed", "all")


def _segment_array(segments):
    """segments as a C-contiguous (m, 2) int64 array; ValueError for another shape or a
    dtype that is not integer (indices are never rounded from floats)."""
    if segments is None:
        return np.empty((0, 2), dtype=np.int64)
    s = np.asarray(segments)
    if s.size == 0:
        return np.empty((0, 2), dtype=np.int64)
    if not np.issubdtype(s.dtype, np.integer):
        raise ValueError(f"segments: expected integer point indices, got dtype {s.dtype}")
    if s.ndim != 2 or s.shape[1] != 2:
        raise ValueError(f"segments: expected shape (m, 2), got {s.shape}")
    if np.issubdtype(s.dtype, np.unsignedinteger):
        # Past int64: still out of range, and still reported as such.
        s = np.minimum(s, np.iinfo(np.int64).max)
    return np.ascontiguousarray(s, dtype=np.int64)


class ConstrainedDelaunay(_TriangleArrays):
    """The constrained Delaunay triangulation of 2D points with segments as constraints,
    exact with an exact kernel, and the regions the segments cut it into.

    ConstrainedDelaunay(points, segments, holes=None, rule="even_odd", kernel="adaptive",
                        algorithm="external", max_added_points=None, attributes=None)

    points     array of shape (n, 2), float64 (other dtypes are converted once). Duplicates,
               collinear sets and fewer than three points are accepted as by Delaunay; a
               NaN or infinite coordinate raises ValueError naming the row.
    segments   array of shape (m, 2) of point indices (integers; None or empty: none). A
               segment whose two ends are the same point is allowed (a chain of one
               vertex). An index outside [0, n) raises TriangulationError of kind
               "invalid_segment" with input_index the segment's row.
    holes      hole seeds, shape (h, 2) or (2,) (None: none): each removes from the domain
               the region (the triangles reachable from it without crossing a constraint)
               that holds it, as Triangle's holes do.
    rule       the fill rule that decides the domain before the seeds: "even_odd" (the
               triangles reached from outside the hull by crossing an odd number of
               constraint pieces), "non_zero" (nonzero winding number of the chains),
               "enclosed" (every triangle a walk from outside reaches only by crossing a
               piece: Triangle's convention, holes given by seeds), "all" (every
               triangle). For rings (counter-clockwise outer rings, clockwise holes)
               even_odd and non_zero agree. ValueError for another name.
    attributes regional attributes (Triangle's -A), shape (a, 3) rows (x, y, value) or
               None: each labels the region holding its seed with its value (a later seed
               in the same region overrides); `attribute` gives each triangle's.
    kernel     any kernel spelling of the exidel command (exidel.kernel_spellings). With an
               inexact kernel ("double", ...) the result may be wrong (certify() says so) or
               the run raises TriangulationError.
    algorithm  the algorithm of the starting Delaunay triangulation (exidel.algorithms).
    max_added_points  None (no limit but the 32-bit indices') or an int >= 1: more crossing
               points stop the run with TriangulationError kind "too_many_crossings".

    What the output is. The segments become non-crossing pieces: a segment is split at every
    vertex exactly on it (an input point, an end of another segment), segments overlapping
    along a line share the pieces of their common part, and two segments that cross at a
    point interior to both get a new vertex there, each coordinate the double nearest to the
    exact crossing, computed once and shared by both. That rounded point need not lie exactly
    on either segment, so a crossed segment becomes a chain of straight pieces that may bend
    by less than an ulp at its crossings. Where rounding makes a piece meet another or pass
    through a vertex the exact segment missed (near-collinear segments within a few ulps),
    the chain is routed through that vertex, which lies within chain_tolerance (2^-44 of the
    segment's largest coordinate) of the segment; cascades that do not settle are
    snap-rounded instead (each segment passes through the vertices of the pixels, the reals
    that round to a vertex, that it meets; no vertex is made but the rounded crossings). Every
    piece is an edge, every other edge is locally Delaunay (no vertex strictly inside the
    circle of the triangle across it), and the triangles tile the convex hull of all
    vertices. With an exact kernel certify() is always ok.

    Attributes (the triangulation, with Delaunay's names and meaning):
      points       (N, 2) float64: the input points, then the added crossing points
      input_count  n, the number of input points; added_count = N - n
      added_points (N - n, 2) float64: points[input_count:]
      simplices    (t, 3) int32: the triangles of the whole convex hull, counter-clockwise,
                   by index into points (a repeated input point by its first occurrence)
      neighbors    (t, 3) int32: neighbors[i, j] the triangle opposite vertex j, -1 on the
                   hull
      convex_hull  (h, 2) int32: the hull edges, counter-clockwise
      hull, halfedges, vertex_of_input (one entry per point), duplicates, collinear
                   as in Delaunay (collinear: no triangles, and every chain runs along the
                   line)
      npoints, nsimplex, ndim
    the constraints:
      segments     (m, 2) int32: the input segments
      constraints  (c, 2) int32: every constraint piece once, as (u, v) with u < v, sorted;
                   each is an edge of simplices
      chains       list of m int32 arrays: segment s as its chain of vertices from the
                   vertex of its first end to that of its second; consecutive vertices are
                   a piece. chain_offsets (m + 1,) and chain_vertices hold the same as
                   compressed rows (chain s is chain_vertices[chain_offsets[s]:
                   chain_offsets[s + 1]])
      crossings    (N - n, 2) int32: for added point input_count + i, the two input
                   segments whose crossing it rounds (the first pair found; more segments
                   may pass through it)
      crossing_lines  (N - n, 4) int32: the points a, b, c, d of which added point i is the
                   rounded crossing of line ab with line cd (the segments' ends, or where
                   rounding has bent pieces, the ends of the pieces that crossed)
    the regions (under `rule` and `holes`), per triangle:
      regions      (t,) int32: which part of the hull, as cut by the pieces, the triangle is
                   in (0, 1, ... in order of first triangle); region_count of them
      depth        (t,) int32: the fewest pieces a walk from outside the hull crosses to reach
                   the triangle
      winding      (t,) int32: the winding number of the chains along that walk
      inside       (t,) bool: in the domain (fill rule, then hole seeds)
      inside_simplices  (d, 3) int32: simplices[inside]
      closed       True when the chains form closed curves (every walk gives the same
                   winding number); False for open polylines, whose depth and winding depend
                   on the walk
      unplaced_holes  int64 indices of the seeds that removed nothing: outside the hull, or
                   exactly on a piece or a vertex
      attribute    (t,) float64: the attribute of the triangle's region (0 where no seed
                   labels it), or None without attributes; unplaced_attributes as
                   unplaced_holes
      holes, rule, kernel (its canonical name), stats
    certify(all=False) decides all of this exactly (exidel.Certificate).

    TriangulationError carries kind, input_index (for invalid_segment the segment's row,
    for the inexact kernels' failures the input point concerned, or None), insertion and
    message.
    """

    ndim = 2

    def __init__(self, points, segments, holes=None, rule="even_odd", kernel="adaptive",
                 algorithm="external", max_added_points=None, attributes=None):
        if not isinstance(rule, str) or rule not in RULES:
            raise ValueError(f"unknown rule {rule!r}; expected even_odd|non_zero|enclosed|all")
        if max_added_points is None:
            limit = 0
        elif (isinstance(max_added_points, bool)
              or not isinstance(max_added_points, (int, np.integer)) or max_added_points < 1):
            raise ValueError(f"max_added_points must be None or an integer >= 1, got "
                             f"{max_added_points!r}")
        else:
            limit = int(max_added_points)
        pts = np.ascontiguousarray(points, dtype=np.float64)
        segs = _segment_array(segments)
        seeds = (np.empty((0, 2)) if holes is None
                 else np.ascontiguousarray(holes, dtype=np.float64))
        if seeds.size == 0:
            seeds = np.empty((0, 2))
        labels = (np.empty((0, 3)) if attributes is None
                  else np.ascontiguousarray(attributes, dtype=np.float64))
        if labels.size == 0:
            labels = np.empty((0, 3))
        if labels.ndim != 2 or labels.shape[1] != 3:
            raise ValueError(f"attributes: expected shape (a, 3) rows (x, y, value), got "
                             f"{labels.shape}")
        if not np.isfinite(labels).all():
            raise ValueError("attributes: a seed or value is NaN or infinite")
        r = _core.constrained_delaunay(pts, segs, kernel, algorithm, seeds, rule, limit,
                                       labels)
        failure = r.get("failure")
        if failure is not None:
            raise TriangulationError(failure["kind"], failure["input_index"],
                                     failure["insertion"], failure["message"])
        self.kernel = _core.kernel_name(kernel)
        self.rule = rule
        self.holes = seeds.reshape(-1, 2)
        self._input = pts  # what certify() holds the output to
        self.segments = segs.astype(np.int32)
        self.points = r["points"]
        self.input_count = int(r["input_count"])
        self.simplices = r["triangles"]
        self.halfedges = r["halfedges"]
        self.hull = r["hull"]
        self.vertex_of_input = r["vertex_of_input"]
        self.duplicates = r["duplicates"]
        self.collinear = bool(r["collinear"])
        self.chain_offsets = r["chain_offsets"]
        self.chain_vertices = r["chain_vertices"]
        self.crossings = r["crossings"]
        self.crossing_lines = r["crossing_lines"]
        self.constraints = r["constraints"]
        self.regions = r["region"]
        self.region_count = int(r["region_count"])
        self.depth = r["depth"]
        self.winding = r["winding"]
        self.inside = r["inside"]
        self.closed = bool(r["closed"])
        self.unplaced_holes = r["unplaced_holes"]
        self.attribute = r["attribute"] if attributes is not None else None
        self.unplaced_attributes = r["unplaced_attributes"]
        self.stats = {
            "kernel": self.kernel,
            "points": self.input_count,
            "added_points": self.added_count,
            "vertices": self.npoints - int(self.duplicates.size),
            "segments": int(self.segments.shape[0]),
            "constraints": int(self.constraints.shape[0]),
            "triangles": self.nsimplex,
            "inside_triangles": int(np.count_nonzero(self.inside)),
            "regions": self.region_count,
        }
        self._neighbors = None

    @property
    def added_count(self):
        """The number of added crossing points, npoints - input_count."""
        return self.npoints - self.input_count

    @property
    def added_points(self):
        """(added_count, 2) float64: the added crossing points, points[input_count:]."""
        return self.points[self.input_count:]

    @property
    def chains(self):
        """Each input segment as its chain of vertex indices (a list of int32 arrays)."""
        if self.segments.shape[0] == 0:
            return []
        return np.split(self.chain_vertices, self.chain_offsets[1:-1])

    @property
    def inside_simplices(self):
        """(d, 3) int32: the triangles of the domain (simplices[inside])."""
        return self.simplices[self.inside]

    def certify(self, all=False):
        """The exact certificate of this result (C++ certify_constrained, adaptive kernel):
        the points start with the input bit for bit and every added point is the correctly
        rounded crossing of its lines, which cross properly; the triangles tile the convex
        hull (certify()'s shape, topology, orientation, boundary, vertex and count checks);
        every chain runs from its segment's first end to its second without revisiting a
        vertex, each piece is an edge, each interior chain vertex is on the segment, a
        rounded crossing of it, or within chain_tolerance of it; constraints lists exactly
        the pieces; every other edge is locally Delaunay. Findings have certify()'s kinds
        plus input_mismatch, added_point_wrong, chain_broken, chain_off_segment and
        constraints_mismatch. all=True keeps every finding (default: the first 64)."""
        arrays = {
            "points": self.points, "input_count": self.input_count,
            "triangles": self.simplices, "halfedges": self.halfedges, "hull": self.hull,
            "vertex_of_input": self.vertex_of_input, "duplicates": self.duplicates,
            "collinear": self.collinear, "chain_offsets": self.chain_offsets,
            "chain_vertices": self.chain_vertices, "crossings": self.crossings,
            "crossing_lines": self.crossing_lines, "constraints": self.constraints,
        }
        return Certificate(_core.certify_constrained(self._input, self.segments, arrays,
                                                     max_findings=-1 if all else 64))

    def __repr__(self):
        return (f"<exidel.ConstrainedDelaunay: {self.input_count} points "
                f"(+{self.added_count} crossings), {self.segments.shape[0]} segments, "
                f"{self.nsimplex} triangles ({self.stats['inside_triangles']} inside), "
                f"kernel {self.kernel}>")
