"""exidel: exact geometric predicates and Delaunay triangulation.

    import numpy as np, exidel
    pts = np.random.default_rng(1).random((1000, 2))
    exidel.orient2d(pts[:-2], pts[1:-1], pts[2:])        # int8 signs, exact
    exidel.orient3d(*np.random.default_rng(2).random((4, 9, 3)))  # in space: (n, 3) arrays
    tri = exidel.Delaunay(pts)                            # scipy.spatial.Delaunay's names
    exidel.certify(pts, tri).ok                           # True, decided exactly
    vor = exidel.Voronoi(pts)                             # correctly rounded vertices
    cdt = exidel.ConstrainedDelaunay(pts, [[0, 1], [2, 3]])  # segments as edges; .certify()

Submodules imported on demand: exidel.research (the studies of `exidel study`),
exidel.plot (matplotlib), exidel.testing (Hypothesis strategies).
"""

from ._core import (__version__, algorithms, build_info, compare_distance, incircle,
                    incircle_cosine, insphere, kernel_spellings, orient2d, orient3d)
from ._core import location_kinds
from ._delaunay import Certificate, Delaunay, Finding, Location, TriangulationError, certify
from ._constrained import ConstrainedDelaunay
from ._interpolate import (LinearNDInterpolator, NaturalNeighborInterpolator,
                           NearestNDInterpolator, griddata)
from ._voronoi import ClippedVoronoi, Voronoi
from ._mutable import MutableTriangulation
from ._core import circumcenter, circumcenter_statuses

__all__ = ["__version__", "algorithms", "build_info", "kernel_spellings", "orient2d",
           "incircle", "incircle_cosine", "compare_distance", "orient3d", "insphere", "Delaunay", "ConstrainedDelaunay", "TriangulationError",
           "certify", "Certificate", "Finding", "Location", "location_kinds", "LinearNDInterpolator",
           "NearestNDInterpolator", "NaturalNeighborInterpolator", "griddata", "MutableTriangulation", "Voronoi", "ClippedVoronoi", "circumcenter",
           "circumcenter_statuses"]
