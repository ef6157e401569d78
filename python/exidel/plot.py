"""exidel.plot: matplotlib pictures of triangulations, failure maps, certificates and
Voronoi diagrams. Every function draws onto `ax` (a new figure's Axes when None) and
returns the Axes; each artist it adds carries a gid ("triangles", "points", "hull",
"duplicates", "signs", "findings", ...) so that it can be found again.

    import exidel, exidel.plot
    ax = exidel.plot.triangulation(exidel.Delaunay(pts))
    ax.figure.savefig("tri.png")

matplotlib is imported by these functions, never by `import exidel`.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

__all__ = ["triangulation", "failure_map", "certificate", "voronoi", "SIGN_COLOURS",
           "WRONG_COLOUR"]

#: The failure-map colours of the C++ pictures (lib/research/src/failure_map.cpp), RGB 0-255.
SIGN_COLOURS = {1: (66, 120, 200), 0: (255, 255, 255), -1: (245, 190, 60)}
WRONG_COLOUR = (215, 25, 28)
_RED = tuple(c / 255 for c in WRONG_COLOUR)


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt
        _, ax = plt.subplots()
    return ax


def _boundary_edges(simplices):
    """The edges of exactly one triangle (either direction): the boundary of a triangle set."""
    if not len(simplices):
        return np.empty((0, 2), dtype=np.int64)
    e = np.concatenate([simplices[:, [0, 1]], simplices[:, [1, 2]], simplices[:, [2, 0]]])
    key = np.sort(e, axis=1)
    _, inverse, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    return e[counts[inverse.reshape(-1)] == 1]


def _triangle_data(tri):
    """(points, simplices, hull segments (k, 2, 2), duplicates) of an exidel.Delaunay, a
    scipy.spatial.Delaunay or anything with .points and .simplices."""
    points = np.asarray(tri.points, dtype=np.float64)
    simplices = np.asarray(tri.simplices, dtype=np.int64).reshape(-1, 3)
    hull = getattr(tri, "hull", None)
    if hull is not None:  # exidel's cycle (or, collinear, the chain of distinct points)
        hull = np.asarray(hull, dtype=np.int64)
        if not getattr(tri, "collinear", False) and hull.size > 1:
            hull = np.append(hull, hull[0])
        edges = np.stack([hull[:-1], hull[1:]], axis=1) if hull.size > 1 else np.empty((0, 2), np.int64)
    elif getattr(tri, "convex_hull", None) is not None:  # scipy's edges
        edges = np.asarray(tri.convex_hull, dtype=np.int64).reshape(-1, 2)
    else:
        edges = _boundary_edges(simplices)
    duplicates = getattr(tri, "duplicates", None)
    if duplicates is None:  # scipy lists repeated points in coplanar
        duplicates = np.asarray(getattr(tri, "coplanar", np.empty((0, 3))), dtype=np.int64).reshape(-1, 3)[:, 0]
    return points, simplices, points[edges], np.asarray(duplicates, dtype=np.int64)


def triangulation(tri, ax=None, *, points=True, hull=True, duplicates=True, edgecolor="0.35",
                  facecolor="none", linewidth=0.6, hull_color="tab:green", point_size=6,
                  labels=False, **kwargs):
    """Draws a triangulation: its triangles (one PolyCollection, gid "triangles", one
    polygon per triangle), the points (gid "points"), the boundary cycle highlighted (gid
    "hull"; for a collinear result the chain of distinct points) and the duplicates
    marked with crosses (gid "duplicates"). labels=True writes each vertex's index.
    tri: an exidel.Delaunay, a scipy.spatial.Delaunay, or anything with .points and
    .simplices. Extra keywords go to the PolyCollection."""
    from matplotlib.collections import LineCollection, PolyCollection

    ax = _axes(ax)
    pts, simplices, hull_segments, dups = _triangle_data(tri)
    ax.add_collection(PolyCollection(pts[simplices], facecolors=facecolor, edgecolors=edgecolor,
                                     linewidths=linewidth, gid="triangles", **kwargs))
    if hull and len(hull_segments):
        ax.add_collection(LineCollection(hull_segments, colors=hull_color, gid="hull",
                                         linewidths=2 * linewidth + 0.8, zorder=3,
                                         label="hull"))
    if points and len(pts):
        ax.plot(pts[:, 0], pts[:, 1], "o", color="black", markersize=point_size / 2,
                gid="points", label="points", zorder=4)
    if duplicates and dups.size:
        ax.plot(pts[dups, 0], pts[dups, 1], "x", color=_RED, markersize=point_size + 2,
                markeredgewidth=1.5, gid="duplicates", label=f"duplicates ({dups.size})", zorder=5)
    if labels:
        for i, (x, y) in enumerate(pts.tolist()):
            ax.annotate(str(i), (x, y), textcoords="offset points", xytext=(3, 3), fontsize=7)
    if len(pts):
        ax.update_datalim(pts)
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    return ax


def _rgb(signs):
    out = np.empty(signs.shape + (3,), dtype=np.uint8)
    for s, c in SIGN_COLOURS.items():
        out[signs == s] = c
    return out


def failure_map(signs, exact=None, ax=None, *, offsets=None, step=1, centered=True,
                fade=False, legend=True, title=None):
    """Draws a failure map with the C++ picture's colours: positive blue, zero white,
    negative amber, and, when `exact` is given, every cell whose sign differs from it red.
    fade=True draws the C++ third panel instead: the exact signs faded, wrong cells red.
    y grows upward; the axes are in ulp offsets of the moving point.

    signs    (height, width) int8, row j = offset j in y (or an exidel.research.FailureMap,
             which brings its exact signs, offsets and title)
    offsets  (offsets_x, offsets_y) in steps, times step; default -W/2.. (the window
             centred on the point, as compute_failure_map's default), or 0.. with
             centered=False
    Returns the Axes; the picture is an AxesImage with gid "signs"."""
    from matplotlib.patches import Patch

    ax = _axes(ax)
    if hasattr(signs, "signs") and hasattr(signs, "exact"):
        m = signs
        signs, exact = m.signs, m.exact if exact is None else exact
        offsets = (m.offsets_x, m.offsets_y) if offsets is None else offsets
        if title is None:
            title = f"{m.predicate}, kernel {m.kernel}: {m.wrong_count} wrong of {m.signs.size}"
    signs = np.asarray(signs)
    if signs.ndim != 2:
        raise ValueError(f"signs: expected a (height, width) array, got shape {signs.shape}")
    h, w = signs.shape
    if offsets is None:
        ox = np.arange(w) - (w // 2 if centered else 0)
        oy = np.arange(h) - (h // 2 if centered else 0)
    else:
        ox, oy = (np.asarray(o) for o in offsets)
    ox, oy = ox * step, oy * step
    wrong = None
    if exact is not None:
        exact = np.asarray(exact)
        if exact.shape != signs.shape:
            raise ValueError(f"exact has shape {exact.shape}, signs {signs.shape}")
        wrong = signs != exact
    if fade and exact is not None:
        rgb = _rgb(exact)
        rgb = ((rgb.astype(np.int32) + 3 * 255) // 4).astype(np.uint8)
    else:
        rgb = _rgb(signs)
    if wrong is not None:
        rgb[wrong] = WRONG_COLOUR
    dx = step if w > 1 else 1
    dy = step if h > 1 else 1
    extent = (ox[0] - dx / 2, ox[-1] + dx / 2, oy[0] - dy / 2, oy[-1] + dy / 2)
    ax.imshow(rgb, origin="lower", extent=extent, interpolation="nearest", aspect="equal",
              gid="signs")
    ax.set_xlabel("x offset (ulps)")
    ax.set_ylabel("y offset (ulps)")
    if title is None and wrong is not None:
        title = f"{int(np.count_nonzero(wrong))} wrong of {signs.size} cells"
    if title:
        ax.set_title(title)
    if legend:
        names = [("positive", SIGN_COLOURS[1]), ("zero", SIGN_COLOURS[0]),
                 ("negative", SIGN_COLOURS[-1])]
        if wrong is not None:
            names.append(("wrong", WRONG_COLOUR))
        handles = [Patch(facecolor=tuple(c / 255 for c in col), edgecolor="0.4", label=n)
                   for n, col in names]
        ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=8,
                  frameon=False)
    return ax


def _oriented(points, simplices):
    """The triangles as exidel.certify sees a bare array: clockwise ones with their second
    and third vertex swapped, so that half-edge 3t + k runs from s[t, k] to s[t, (k+1) % 3]."""
    from . import _core

    s = simplices.copy()
    if len(s):
        cw = _core.orient2d(points[s[:, 0]], points[s[:, 1]], points[s[:, 2]]) < 0
        s[cw, 1], s[cw, 2] = simplices[cw, 2], simplices[cw, 1]
    return s


def certificate(points, tri, cert=None, ax=None, *, reorient=True, show_triangulation=True):
    """Draws a triangulation with what the exact certifier found marked in red: edges that
    are not locally Delaunay (gid "not_delaunay", one line per finding) with the vertex
    inside their circumcircle, triangles not counter-clockwise or degenerate (gid
    "bad_triangles"), and points named by other findings (gid "findings": missing
    points, duplicate vertices, non-convex boundary turns). The title counts the
    findings by kind.

    tri   an exidel.Delaunay, a scipy.spatial.Delaunay, an (m, 3) simplices array or
          delaunator's arrays (as for exidel.certify)
    cert  the exidel.certify(points, tri, reorient) Certificate; computed when None
    reorient  as for exidel.certify (the findings name their points, so a certificate
          computed either way can be drawn); clockwise triangles are drawn turned."""
    from matplotlib.collections import LineCollection, PolyCollection

    from ._delaunay import Delaunay, certify

    ax = _axes(ax)
    pts = np.asarray(points, dtype=np.float64)
    if isinstance(tri, Delaunay):
        target, drawn = tri, tri
    else:
        if isinstance(tri, dict):  # delaunator's arrays
            raw = tri["triangles"]
        else:
            raw = getattr(tri, "simplices", getattr(tri, "triangles", tri))
        simplices = np.asarray(raw, dtype=np.int64).reshape(-1, 3)
        in_range = simplices.size == 0 or (simplices.min() >= 0 and simplices.max() < len(pts))
        if in_range and reorient:
            simplices = _oriented(pts, simplices)
        target = tri
        drawn = SimpleNamespace(points=pts, simplices=simplices if in_range else np.empty((0, 3), np.int64),
                                coplanar=getattr(tri, "coplanar", np.empty((0, 3))))
    if cert is None:
        cert = certify(pts, target, reorient=reorient)
    if show_triangulation:
        triangulation(drawn, ax=ax, hull=True, duplicates=False, edgecolor="0.6")

    edges, inside, bad, marked = [], [], [], []
    for f in cert.findings:  # every Finding names its points (input indices)
        if f.kind == "not_delaunay" and len(f.points) == 4:
            a, b, _, d = f.points
            edges.append(pts[[a, b]])
            inside.append(d)
        elif f.kind in ("not_ccw", "degenerate_triangle") and len(f.points) == 3:
            bad.append(pts[list(f.points)])
        elif f.kind in ("missing_point", "duplicate_vertex") and f.points:
            marked.append(f.points[0])
        elif f.kind == "boundary_not_convex" and len(f.points) == 3:
            marked.append(f.points[1])
    if bad:
        ax.add_collection(PolyCollection(bad, facecolors=(*_RED, 0.35), edgecolors=_RED,
                                         linewidths=1.2, gid="bad_triangles", zorder=5))
    if edges:
        ax.add_collection(LineCollection(edges, colors=[_RED], linewidths=2.2,
                                         gid="not_delaunay", zorder=6,
                                         label=f"not locally Delaunay ({len(edges)})"))
    if inside:
        ax.plot(pts[inside, 0], pts[inside, 1], "o", markerfacecolor="none",
                markeredgecolor=_RED, markersize=9, gid="inside_circumcircle", zorder=7)
    if marked:
        ax.plot(pts[marked, 0], pts[marked, 1], "D", markerfacecolor="none",
                markeredgecolor=_RED, markersize=9, gid="findings", zorder=7)
    if cert.ok:
        ax.set_title("certified Delaunay")
    else:
        kinds = {}
        for f in cert.findings:
            kinds[f.kind] = kinds.get(f.kind, 0) + 1
        shown = ", ".join(f"{k} {n}" for k, n in kinds.items())
        more = "" if cert.total_findings == len(cert.findings) else \
            f" (first {len(cert.findings)} of {cert.total_findings})"
        ax.set_title(f"not Delaunay: {shown}{more}", color=_RED, fontsize=10)
    ax.autoscale_view()
    return ax


def voronoi(vor, ax=None, *, points=True, vertices=True, line_colors="k", line_width=1.0,
            point_size=4, far=None):
    """Draws a Voronoi diagram given with scipy.spatial.Voronoi's names (an exidel.Voronoi
    or a scipy one): .points, .vertices, .ridge_points, .ridge_vertices (-1: at infinity).
    Finite ridges solid (gid "ridges"), unbounded ones dashed rays (gid "rays") from their
    vertex away from the other sites, like scipy.spatial.voronoi_plot_2d; `far` is their
    length (default: the points' extent). For a ridge with no vertex at all (collinear
    sites) the whole bisector line is drawn."""
    from matplotlib.collections import LineCollection

    ax = _axes(ax)
    pts = np.asarray(vor.points, dtype=np.float64)
    verts = np.asarray(vor.vertices, dtype=np.float64).reshape(-1, 2)
    center = pts.mean(axis=0)
    span = np.ptp(np.vstack([pts, verts]), axis=0).max() if len(pts) else 1.0
    far = float(far) if far is not None else (span if span > 0 else 1.0)
    finite, rays = [], []
    for (i, j), rv in zip(np.asarray(vor.ridge_points).tolist(), list(vor.ridge_vertices)):
        rv = [int(v) for v in rv]
        if all(v >= 0 for v in rv):
            finite.append(verts[rv])
            continue
        t = pts[j] - pts[i]
        n = np.array([-t[1], t[0]]) / np.hypot(*t)
        mid = (pts[i] + pts[j]) / 2
        known = [v for v in rv if v >= 0]
        if not known:  # a whole bisector line
            rays.append([mid - far * n, mid + far * n])
            continue
        start = verts[known[0]]
        direction = np.sign(np.dot(mid - center, n)) * n
        if not np.any(direction):
            direction = n
        rays.append([start, start + far * direction])
    if finite:
        ax.add_collection(LineCollection(finite, colors=line_colors, linewidths=line_width,
                                         gid="ridges"))
    if rays:
        ax.add_collection(LineCollection(rays, colors=line_colors, linewidths=line_width,
                                         linestyles="dashed", gid="rays"))
    if points and len(pts):
        ax.plot(pts[:, 0], pts[:, 1], "o", color="black", markersize=point_size,
                gid="points")
    if vertices and len(verts):
        ax.plot(verts[:, 0], verts[:, 1], "o", color="tab:orange", markersize=point_size * 0.75,
                gid="vertices")
    ax.set_aspect("equal", adjustable="datalim")
    lo = np.min(pts, axis=0) if len(pts) else np.zeros(2)
    hi = np.max(pts, axis=0) if len(pts) else np.ones(2)
    margin = 0.1 * (hi - lo).max() if (hi - lo).max() > 0 else 1.0
    ax.set_xlim(lo[0] - margin, hi[0] + margin)
    ax.set_ylim(lo[1] - margin, hi[1] + margin)
    return ax
