"""Nearest points from Python: exidel.Delaunay.nearest (k = 1 and k nearest) and
within_radius against scipy.spatial.cKDTree's query and query_ball_point on the same
points and queries, in one process, one thread on each side.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_neighbors.py \
        [--n 1000000] [--queries 1000000] [--k 8] [--reps 3]

Points and queries uniform in the unit square; the radius holds about k points on
average. Each side's structure is built once (exidel: the triangulation and its Locator,
on the first query; scipy: the tree) and reported apart; the queries are timed on the
built structure, medians of --reps interleaved runs. Every answer is compared: the same
nearest point and the same k points in order (or, where they differ, points at the same
distance: each side breaks ties its own way), the same set of points within the radius
(a point within rounding of the circle could differ: exidel decides exactly).
"""

import argparse
import statistics

import numpy as np
import scipy
import scipy.spatial

import exidel
from bench_locate import timed  # this directory is on the path of a script run from it


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--queries", type=int, default=1_000_000)
    parser.add_argument("--k", type=int, default=8)
    parser.add_argument("--reps", type=int, default=3)
    parser.add_argument("--seed", type=int, default=20261206)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    pts = rng.random((args.n, 2))
    q = rng.random((args.queries, 2))
    radius = float(np.sqrt(args.k / (np.pi * args.n)))

    build_ours, ours = timed(lambda: exidel.Delaunay(pts, threads=1))
    first, _ = timed(lambda: ours.nearest(q[:1], threads=1))  # builds the Locator
    build_ours += first
    build_theirs, tree = timed(lambda: scipy.spatial.cKDTree(pts))

    tasks = {
        "nearest (k = 1)": (lambda: ours.nearest(q, threads=1),
                            lambda: tree.query(q, k=1, workers=1)),
        f"k nearest (k = {args.k})": (lambda: ours.nearest(q, k=args.k, threads=1),
                                      lambda: tree.query(q, k=args.k, workers=1)),
        f"within radius (about {args.k} points)": (
            lambda: ours.within_radius(q, radius, threads=1),
            lambda: tree.query_ball_point(q, radius, workers=1)),
    }
    print(f"{args.n} points, {args.queries} queries, uniform in the unit square; "
          f"scipy {scipy.__version__}; medians of {args.reps} interleaved runs (s)")
    print(f"{'building':40s} exidel {build_ours:8.3f}  cKDTree {build_theirs:8.3f}")
    answers = {}
    for name, (a, b) in tasks.items():
        ex, sc = [], []
        for _ in range(args.reps):
            t, ra = timed(a)
            ex.append(t)
            t, rb = timed(b)
            sc.append(t)
        answers[name] = (ra, rb)
        e, s = statistics.median(ex), statistics.median(sc)
        print(f"{name:40s} exidel {e:8.3f}  cKDTree {s:8.3f}  ratio {e / s:6.2f}x")

    # Where the indices differ, the distances must be equal (a tie, which each side
    # breaks its own way); distances are compared as both sides round them.
    def tied(ours_idx, theirs_dist):
        d = np.hypot(pts[ours_idx][..., 0] - q[:, None, 0], pts[ours_idx][..., 1] - q[:, None, 1])
        return np.abs(d - theirs_dist) <= 1e-15 * np.maximum(d, 1e-300)

    bad = 0
    near, (dist1, idx1) = answers["nearest (k = 1)"]
    differs = near != idx1
    bad += int(np.count_nonzero(differs & ~tied(near[:, None], dist1[:, None])[:, 0]))
    knn, (distk, idxk) = answers[f"k nearest (k = {args.k})"]
    bad += int(np.count_nonzero(np.any((knn != idxk) & ~tied(knn, distk), axis=1)))
    (indptr, indices), lists = answers[f"within radius (about {args.k} points)"]
    for i in range(len(q)):
        if set(indices[indptr[i]:indptr[i + 1]].tolist()) != set(lists[i]):
            bad += 1
    print(f"queries whose answers differ: {bad}")
    return 0 if bad == 0 else 1


if __name__ == "__main__":
    raise SystemExit(main())
