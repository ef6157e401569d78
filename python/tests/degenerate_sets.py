"""Degenerate point sets, and what exidel and scipy.spatial.Delaunay make of them.

    PYTHONPATH=build/python /usr/bin/python3 python/tests/degenerate_sets.py

prints one row per set: exidel's certificate (always expected Delaunay) and scipy's outcome
with default options as a new user calls it: QhullError, points left out of the
triangulation (scipy's `coplanar`: not a vertex of any simplex), or a triangulation that
exidel's exact certifier rejects (and why). test_scipy_degenerate.py runs the same."""

import math
import sys

import numpy as np

TINY = math.ulp(0.0)


def grid(k, scale=1.0, offset=(0.0, 0.0)):
    g = np.array([[i, j] for i in range(k) for j in range(k)], dtype=float)
    return g * scale + np.asarray(offset)


def lattice_circle(r, offset=(0.0, 0.0), scale=1.0):
    pts = [(x, y) for x in range(-r, r + 1) for y in (math.isqrt(r * r - x * x),)
           if x * x + y * y == r * r]
    pts = sorted(set(pts) | {(x, -y) for x, y in pts})
    return np.array(pts, dtype=float) * scale + np.asarray(offset)


def rounded_line(n, seed):
    """Points p + t (q - p), each rounded once: within an ulp of one line."""
    rng = np.random.default_rng(seed)
    p, q = rng.random(2), rng.random(2) + 10
    t = np.sort(rng.random(n)) * 3 - 1
    return p + t[:, None] * (q - p)


def rounded_circle(n, seed, centre=1e3):
    rng = np.random.default_rng(seed)
    theta = rng.random(n) * 2 * np.pi
    return centre + np.stack([np.cos(theta), np.sin(theta)], axis=1)


def nudged(points, seed, ulps=1):
    rng = np.random.default_rng(seed)
    out = points.copy()
    for _ in range(ulps):
        direction = np.where(rng.random(out.shape) < 0.5, -np.inf, np.inf)
        move = rng.random(out.shape) < 0.5
        out = np.where(move, np.nextafter(out, direction), out)
    return out


def sets():
    """(name, points) for every set, in a fixed order."""
    out = [
        ("grid 10x10", grid(10)),
        ("grid 30x30", grid(30)),
        ("grid 10x10, scaled 2^-1074 (subnormal)", grid(10, TINY)),
        ("grid 10x10, scaled 2^-1060", grid(10, 2.0 ** -1060)),
        ("grid 10x10, scaled 2^1000", grid(10, 2.0 ** 1000)),
        ("grid 10x10, scaled 2^-40", grid(10, 2.0 ** -40)),
        ("grid 10x10 at (2^30, 2^30)", grid(10, 1.0, (2.0 ** 30, 2.0 ** 30))),
        ("grid 10x10 at (1e15, -1e15)", grid(10, 1.0, (1e15, -1e15))),
        ("grid 10x10 nudged 1 ulp", nudged(grid(10, 1.0, (1.0, 1.0)), 1)),
        ("grid 10x10 nudged 1 ulp at 2^20", nudged(grid(10, 1.0, (2.0 ** 20, 2.0 ** 20)), 2)),
        ("lattice circle r=5", lattice_circle(5)),
        ("lattice circle r=65", lattice_circle(65)),
        ("lattice circle r=1105", lattice_circle(1105)),
        ("lattice circle r=1105 at 2^26", lattice_circle(1105, (2.0 ** 26, 2.0 ** 26))),
        ("lattice circle r=65, scaled 2^-1000", lattice_circle(65, scale=2.0 ** -1000)),
        ("lattice circle r=65, scaled 2^900", lattice_circle(65, scale=2.0 ** 900)),
        ("lattice circle r=65 and its centre", np.vstack([lattice_circle(65), [[0.0, 0.0]]])),
        ("lattice circle r=65 nudged 1 ulp", nudged(lattice_circle(65, (1e4, 1e4)), 3)),
        ("rounded circle, 100 points at 1e3", rounded_circle(100, 4)),
        ("rounded circle, 300 points at 1e6", rounded_circle(300, 5, 1e6)),
        ("collinear, 50 integer points", np.stack([np.arange(50.0), 2 * np.arange(50.0)], 1)),
        ("collinear, 3 points", np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]])),
        ("rounded line, 50 points", rounded_line(50, 6)),
        ("rounded line, 500 points", rounded_line(500, 7)),
        ("rounded line + 1 point off it", np.vstack([rounded_line(100, 8), [[0.0, 5.0]]])),
        ("square with duplicates", np.array([[0.0, 0], [1, 0], [1, 1], [0, 1], [1, 1], [0, 0]])),
        ("grid 8x8 twice (all duplicated)", np.vstack([grid(8), grid(8)])),
        ("uniform 200 + 20 duplicates", (lambda p: np.vstack([p, p[:20]]))(
            np.random.default_rng(9).random((200, 2)))),
        ("two points", np.array([[0.0, 0.0], [1.0, 1.0]])),
        ("Kettner et al. (near-collinear triple) + square",
         np.array([[0.5, 0.5], [12.0, 12.0], [24.0, 24.0], [0.50000000000002531, 0.5000000000000171],
                   [0.0, 24.0], [24.0, 0.0]])),
        ("huge coordinates 1e300, uniform", np.random.default_rng(10).random((100, 2)) * 1e300),
        ("tiny coordinates 1e-300, uniform", np.random.default_rng(11).random((100, 2)) * 1e-300),
        ("mixed magnitudes (1e-200 .. 1e200)", np.vstack([
            np.random.default_rng(12).random((30, 2)) * 1e-200,
            np.random.default_rng(13).random((30, 2)) * 1e200])),
    ]
    return out


def scipy_outcome(points, exidel):
    """What scipy.spatial.Delaunay(points) gives, as (outcome, detail)."""
    import scipy.spatial
    try:
        tri = scipy.spatial.Delaunay(points)
    except Exception as error:  # QhullError (a RuntimeError) or ValueError
        first = str(error).strip().splitlines()[0] if str(error).strip() else ""
        return type(error).__name__, first[:60]
    distinct = np.unique(points, axis=0).shape[0]
    used = np.unique(points[np.unique(tri.simplices)], axis=0).shape[0]
    if used < distinct:
        return "points left out", f"{distinct - used} of {distinct} distinct points"
    cert = exidel.certify(points, tri.simplices)
    if not cert.ok:
        kinds = sorted(cert.kinds)
        return "not certified", f"{cert.total_findings} findings: {', '.join(kinds)}"
    return "Delaunay", ""


def observe():
    """Rows (name, n, exidel certificate ok, scipy outcome, scipy detail)."""
    import exidel
    rows = []
    for name, pts in sets():
        ok = exidel.Delaunay(pts).certify().ok
        outcome, detail = scipy_outcome(pts, exidel)
        rows.append((name, len(pts), ok, outcome, detail))
    return rows


def markdown(rows):
    lines = ["| set | n | exidel | scipy | detail |", "|---|---:|---|---|---|"]
    for name, n, ok, outcome, detail in rows:
        lines.append(f"| {name} | {n} | {'Delaunay' if ok else 'NOT CERTIFIED'} | {outcome} | {detail} |")
    certified = sum(r[3] == "Delaunay" for r in rows)
    lines.append("")
    lines.append(f"exidel certified {sum(r[2] for r in rows)} of {len(rows)}; "
                 f"scipy's result certified on {certified} of {len(rows)}.")
    return "\n".join(lines)


if __name__ == "__main__":
    print(markdown(observe()))
    sys.exit(0)
