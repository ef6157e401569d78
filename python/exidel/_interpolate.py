"""exidel.LinearNDInterpolator, NearestNDInterpolator and griddata: scipy.interpolate's
interface for the plane, over exidel's exact point location."""

from __future__ import annotations

import numpy as np

from ._delaunay import Delaunay, default_threads


def _coords(args, what):
    """scipy's calling conventions: one array of shape (..., 2), or x and y arrays that
    broadcast (or a tuple of them)."""
    if len(args) == 1 and isinstance(args[0], tuple):
        args = args[0]
    if len(args) == 1:
        xi = np.asarray(args[0], dtype=np.float64)
    elif len(args) == 2:
        x, y = np.broadcast_arrays(*(np.asarray(a, dtype=np.float64) for a in args))
        xi = np.stack([x, y], axis=-1)
    else:
        raise ValueError(f"{what}: expected one (..., 2) array or x and y arrays, got "
                         f"{len(args)} arrays")
    if xi.ndim == 0 or xi.shape[-1] != 2:
        raise ValueError(f"{what}: expected shape (..., 2), got {xi.shape}")
    return xi


def _rescaling(points):
    """scipy's rescale=True: the points centred on their mean and divided, per axis, by
    their extent (1 where it is 0)."""
    offset = points.mean(axis=0)
    scale = np.ptp(points - offset, axis=0)
    scale[~(scale > 0)] = 1.0
    return offset, scale


class _Interpolator:
    def __init__(self, points, values, rescale):
        if isinstance(points, Delaunay):
            if rescale:
                raise ValueError("rescale=True needs the points, not a Delaunay object "
                                 "(the triangulation of the rescaled points differs)")
            self.tri = points
            self.offset, self.scale = None, None
        else:
            points = _coords((points,), "points")
            if points.ndim != 2:
                raise ValueError(f"points: expected shape (n, 2), got {points.shape}")
            self.offset, self.scale = _rescaling(points) if rescale else (None, None)
            if rescale:
                points = (points - self.offset) / self.scale
            self.tri = Delaunay(points)
        self.points = self.tri.points
        values = np.asarray(values)
        if values.ndim == 0 or values.shape[0] != self.tri.npoints:
            raise ValueError("different number of values and points")
        if not (np.issubdtype(values.dtype, np.floating) or
                np.issubdtype(values.dtype, np.complexfloating)):
            values = values.astype(np.float64)
        self.values = values

    def _queries(self, args):
        xi = _coords(args, "xi")
        if self.offset is not None:
            xi = (xi - self.offset) / self.scale
        return xi


class LinearNDInterpolator(_Interpolator):
    """Piecewise linear interpolation over the Delaunay triangulation, with
    scipy.interpolate.LinearNDInterpolator's interface for the plane.

    LinearNDInterpolator(points, values, fill_value=np.nan, rescale=False)

    points      (n, 2) array, or an exidel.Delaunay (reused, not recomputed)
    values      (n, ...) array of float or complex values at the points
    fill_value  the value outside the convex hull (default NaN)
    rescale     scipy's: triangulate the points centred on their mean and scaled per axis
                by their extent, and the queries the same way (the triangulation of the
                rescaled points is the exact one of those points)
    Called as ip(xi) with xi of shape (..., 2), or ip(x, y): values of shape
    xi.shape[:-1] + values.shape[1:].

    The arithmetic: where each query lies is decided exactly (Delaunay.locate). A query on
    a vertex gets that vertex's value exactly; on an edge, the linear interpolation along
    the edge between its two ends (the third corner's weight is exactly zero, so the value
    is the same from both triangles); inside a triangle, the barycentric weights of
    scipy's formula (Delaunay.transform), rounded to doubles, so the values agree with
    scipy's to rounding wherever the triangulations agree. The weights are not exact:
    each is a rounded floating-point quantity, with an error relative to the triangle's
    size that grows as the triangle gets thinner. Collinear points (no triangles, where
    scipy raises) interpolate along their chain and fill elsewhere.
    """

    def __init__(self, points, values, fill_value=np.nan, rescale=False):
        super().__init__(points, values, rescale)
        self.fill_value = fill_value

    def __call__(self, *args):
        xi = self._queries(args)
        shape = xi.shape[:-1]
        q = np.ascontiguousarray(xi.reshape(-1, 2))
        where = self.tri.locate(q)
        out = np.empty((q.shape[0],) + self.values.shape[1:],
                       dtype=np.result_type(self.values.dtype, np.float64))
        out[...] = self.fill_value
        kind = where.kind
        vert = kind == 2
        out[vert] = self.values[where.vertex[vert]]
        pts = self.tri.points
        edge = kind == 1
        if edge.any():
            if self.tri.collinear:
                e = where.edge[edge]
                a, b = self.tri.hull[e], self.tri.hull[e + 1]
            else:
                e = where.edge[edge]
                flat = self.tri.simplices.reshape(-1)
                a = flat[e]
                b = flat[3 * (e // 3) + (e % 3 + 1) % 3]
            d = pts[b] - pts[a]
            t = np.einsum("ij,ij->i", q[edge] - pts[a], d) / np.einsum("ij,ij->i", d, d)
            t = t.reshape((-1,) + (1,) * (self.values.ndim - 1))
            out[edge] = (1 - t) * self.values[a] + t * self.values[b]
        inside = kind == 0
        if inside.any():
            s = where.simplex[inside]
            T = self.tri.transform[s]
            c = np.einsum("ijk,ik->ij", T[:, :2], q[inside] - T[:, 2])
            w = np.concatenate([c, 1 - c.sum(axis=1, keepdims=True)], axis=1)
            corners = self.tri.simplices[s]
            v = self.values[corners]  # (k, 3, ...)
            w = w.reshape(w.shape + (1,) * (self.values.ndim - 1))
            out[inside] = (w * v).sum(axis=1)
        return out.reshape(shape + self.values.shape[1:])


class NearestNDInterpolator(_Interpolator):
    """Nearest-neighbour interpolation with scipy.interpolate.NearestNDInterpolator's
    interface for the plane: the value of the point nearest to each query, decided exactly
    (Delaunay.nearest: no point is strictly nearer; among equally near points one is
    chosen). NearestNDInterpolator(points, values, rescale=False, tree_options=None);
    tree_options (scipy's cKDTree options) is accepted and changes nothing."""

    def __init__(self, x, y, rescale=False, tree_options=None):
        del tree_options
        super().__init__(x, y, rescale)

    def __call__(self, *args, **query_options):
        del query_options  # scipy passes them to cKDTree.query
        xi = self._queries(args)
        nearest = self.tri.nearest(xi)
        return self.values[nearest]


class NaturalNeighborInterpolator(_Interpolator):
    """Sibson's natural neighbour interpolation, with the interface of
    scipy.interpolate.LinearNDInterpolator (scipy has no natural neighbour interpolant;
    CGAL's natural_neighbor_coordinates_2 and MetPy's natural_neighbor_to_points have).

    NaturalNeighborInterpolator(points, values, fill_value=np.nan, rescale=False,
                                exact=False)

    points      (n, 2) array, or an exidel.Delaunay (reused, not recomputed)
    values      (n, ...) array of float or complex values at the points
    fill_value  the value outside the convex hull (default NaN)
    rescale     scipy's (see LinearNDInterpolator)
    exact       compute the areas in exact rationals: every value is then the double
                nearest to the exact interpolant of the given values (complex values: each
                part)
    Called as ip(xi) with xi of shape (..., 2), or ip(x, y). Threads: ip(xi, threads=k).

    The interpolant is C1 except at the data points, reproduces linear functions (exactly
    with exact=True), and equals a point's value on it. The natural neighbours are decided
    exactly; on a hull edge the value is the linear interpolation along the edge (the limit
    from inside); outside the hull, fill_value. Without exact=True the Voronoi areas are
    computed in doubles, relative to the query, with no proven bound (the circumcentre of a
    thin triangle is far away and its rounding error large); exidel falls back to exact
    arithmetic for a query where a rounded determinant is not positive or an area negative,
    so rounded weights are never negative. Delaunay.natural_neighbors gives the
    coordinates themselves.
    """

    def __init__(self, points, values, fill_value=np.nan, rescale=False, exact=False):
        super().__init__(points, values, rescale)
        if self.tri.furthest_site:
            raise ValueError("NaturalNeighborInterpolator needs a Delaunay triangulation, not "
                             "a furthest-site one")
        self.fill_value = fill_value
        self.exact = bool(exact)

    def __call__(self, *args, threads=None):
        xi = self._queries(args)
        shape = xi.shape[:-1]
        q = np.ascontiguousarray(xi.reshape(-1, 2))
        values = self.values.reshape(self.values.shape[0], -1)
        complex_values = np.iscomplexobj(values)
        parts = [values.real, values.imag] if complex_values else [values]
        fill = complex(self.fill_value) if complex_values else self.fill_value
        fills = [fill.real, fill.imag] if complex_values else [float(fill)]
        threads = default_threads() if threads is None else threads
        outs = []
        for part, part_fill in zip(parts, fills):
            part = np.ascontiguousarray(part, dtype=np.float64)
            _, out = self.tri._query(
                q, lambda loc, rows, part=part, part_fill=part_fill: loc.natural(
                    rows, part, part_fill, self.exact, threads))
            outs.append(out)
        out = outs[0] + 1j * outs[1] if complex_values else outs[0]
        return out.reshape(shape + self.values.shape[1:])


def griddata(points, values, xi, method="linear", fill_value=np.nan, rescale=False):
    """scipy.interpolate.griddata for points of the plane: `method` "linear"
    (LinearNDInterpolator), "nearest" (NearestNDInterpolator, which ignores fill_value as
    scipy does) or exidel's "natural" (NaturalNeighborInterpolator; not in scipy). "cubic" (scipy's Clough-Tocher interpolant) is not in exidel and raises
    NotImplementedError; any other method raises ValueError, as in scipy. `xi` is an array
    of shape (..., 2) or a tuple of x and y arrays."""
    if method == "linear":
        ip = LinearNDInterpolator(points, values, fill_value=fill_value, rescale=rescale)
    elif method == "nearest":
        ip = NearestNDInterpolator(points, values, rescale=rescale)
    elif method == "natural":
        ip = NaturalNeighborInterpolator(points, values, fill_value=fill_value, rescale=rescale)
    elif method == "cubic":
        raise NotImplementedError("griddata: method='cubic' (the Clough-Tocher interpolant) "
                                  "is not in exidel; 'linear', 'nearest' and 'natural' are")
    else:
        raise ValueError(f"Unknown interpolation method {method!r} for 2 dimensional data")
    return ip(xi)
