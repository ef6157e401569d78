"""exidel.MutableTriangulation: a Delaunay triangulation that points are inserted into and
removed from one at a time (the C++ delaunay::MutableTriangulation)."""

from __future__ import annotations

import numpy as np

from . import _core
from ._delaunay import Delaunay, TriangulationError


def _failure(error):
    """A C++ FailureError ("kind: message") as exidel.TriangulationError."""
    kind, _, message = str(error).partition(": ")
    return TriangulationError(kind, None, None, message)


class MutableTriangulation:
    """A Delaunay triangulation that changes: points inserted and removed one at a time,
    exactly with an exact kernel (the default, "adaptive"), in every degenerate case
    (duplicates, collinear points, cocircular stars).

    MutableTriangulation(points=None, kernel="adaptive")

    Every inserted point gets an id, the next integer (the initial points 0 ... n - 1); a
    point equal to a live one is a copy of it (it leaves the triangulation with its last
    id). Each insert is located by a walk from the previous one (or a sample of vertices),
    then made Delaunay by Lawson's flips; a removal re-triangulates the hole (ears, then
    flips). Cost: about as CGAL's insert and remove (docs/benchmarks.md).

      insert(points)   (k, 2) rows, or one (2,) point: their ids (int32 array, or an int)
      remove(ids)      an id or ids; IndexError for an id never issued or already removed
                       (those before it are removed)
      len(t)           live ids
      ids, points      the live ids (increasing) and their points, (m,) and (m, 2)
      delaunay()       an exidel.Delaunay of the live points (rows in the order of ids;
                       every query of Delaunay: locate, nearest, natural_neighbors, ...)

    A NaN or infinite point raises ValueError and changes nothing. With an inexact kernel
    an inconsistency raises exidel.TriangulationError, after which the triangulation
    refuses changes (RuntimeError).
    """

    def __init__(self, points=None, kernel="adaptive"):
        points = np.zeros((0, 2)) if points is None else points
        self.kernel = _core.kernel_name(kernel)
        try:
            self._core = _core.MutableTriangulation(
                np.ascontiguousarray(points, dtype=np.float64), kernel)
        except RuntimeError as e:
            raise _failure(e) from None
        self._snapshot = None

    def insert(self, points):
        rows = np.asarray(points, dtype=np.float64)
        single = rows.shape == (2,)
        try:
            ids = self._core.insert(np.ascontiguousarray(rows.reshape(-1, 2) if single else rows))
        except RuntimeError as e:
            raise _failure(e) from None
        finally:
            self._snapshot = None
        return int(ids[0]) if single else ids

    def remove(self, ids):
        ids = np.atleast_1d(np.asarray(ids))
        if ids.size and not np.issubdtype(ids.dtype, np.integer):
            raise TypeError(f"remove: ids must be integers, got {ids.dtype}")
        try:
            self._core.remove(np.ascontiguousarray(ids, dtype=np.int64))
        except RuntimeError as e:
            raise _failure(e) from None
        finally:
            self._snapshot = None

    def _state(self):
        if self._snapshot is None:
            try:
                self._snapshot = self._core.snapshot()
            except RuntimeError as e:
                raise _failure(e) from None
        return self._snapshot

    def __len__(self):
        return len(self._core)

    @property
    def ids(self):
        return self._state()["ids"]

    @property
    def points(self):
        return self._state()["points"]

    def delaunay(self):
        r = self._state()
        return Delaunay._from_arrays(r["points"], r, self.kernel)

    def __repr__(self):
        return f"<exidel.MutableTriangulation: {len(self)} live points, kernel {self.kernel}>"
