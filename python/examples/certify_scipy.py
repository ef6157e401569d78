"""scipy.spatial.Delaunay on survey-like data, certified exactly by exidel.

A seeded generator of a realistic family: a terrain survey (LiDAR-like) on a 1 m grid, each
position jittered by a few centimetres and rounded to the centimetre, at UTM coordinates
(easting 500 km, northing 4100 km): the magnitudes and roundings real survey files have.
qhull decides with floating-point arithmetic on coordinates of 4e6; exidel.certify checks
every edge with exact predicates and says which are not locally Delaunay.

    python3 python/examples/certify_scipy.py [n] [seed]
"""

import sys
from collections import Counter

import numpy as np
import scipy.spatial

import exidel


def survey(n, seed):
    """About n points (the nearest square grid), seeded: a 1 m grid jittered by a normal
    of 5 cm, rounded to the centimetre, offset to UTM-like coordinates."""
    rng = np.random.default_rng(seed)
    m = max(2, int(round(np.sqrt(n))))
    grid = np.stack(np.meshgrid(np.arange(m), np.arange(m)), -1).reshape(-1, 2).astype(float)
    grid += rng.normal(scale=0.05, size=grid.shape)
    return np.round(grid + [500000.0, 4100000.0], 2)


def report(name, points, triangulation):
    cert = exidel.certify(points, triangulation, all=True)
    kinds = Counter(f.kind for f in cert.findings)
    shown = ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())) or "none"
    print(f"{name}: {len(points)} points, certified: {cert.ok}, findings: {shown}")
    return cert


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 200_000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    points = survey(n, seed)
    scipy_cert = report("scipy", points, scipy.spatial.Delaunay(points))
    moved = points - [500000.0, 4100000.0]  # the same survey translated to the origin
    report("scipy, translated to the origin", moved, scipy.spatial.Delaunay(moved))
    if not report("exidel", points, exidel.Delaunay(points)).ok:
        sys.exit(1)
    if not scipy_cert.ok:
        print("first finding:", scipy_cert.findings[0])


if __name__ == "__main__":
    main()
