"""Point location from Python: exidel.Delaunay.find_simplex against scipy.spatial.Delaunay's
find_simplex on the same points and queries, in one process.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_locate.py \
        [--n 1000000] [--queries 1000000] [--reps 3] [--interpolate]

Points and queries uniform in the unit square (queries also 5% beyond it). exidel's first
call builds its Locator (the mesh laid out for walks) and is reported apart from the
later calls. scipy walks each query from the previous answer, so the order of the queries
decides its time: it is measured on the queries as given, once (slow: a walk from a
random place per query), and on the same queries sorted in serpentine strips (rows of
about 2 queries' height, alternately left to right and right to left: consecutive queries
are neighbours, its best case; the sort not counted). Every answer is compared: the same triangle (as a
vertex set) or -1 on both sides. Medians of --reps interleaved runs.
"""

import argparse
import statistics
import time

import numpy as np
import scipy
import scipy.interpolate
import scipy.spatial

import exidel


def timed(f):
    start = time.perf_counter()
    out = f()
    return time.perf_counter() - start, out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--queries", type=int, default=1_000_000)
    parser.add_argument("--reps", type=int, default=3)
    parser.add_argument("--seed", type=int, default=20261205)
    parser.add_argument("--interpolate", action="store_true",
                        help="also LinearNDInterpolator against scipy's, triangulation included "
                             "on both sides, once (scipy's walks make it slow on queries in "
                             "random order)")
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    pts = rng.random((args.n, 2))
    q = rng.random((args.queries, 2)) * 1.1 - 0.05
    ours = exidel.Delaunay(pts, threads=1)
    theirs = scipy.spatial.Delaunay(pts)
    first, a = timed(lambda: ours.find_simplex(q))
    # Serpentine strips, for scipy's best case.
    rows = max(1, int(np.sqrt(len(q) / 2)))
    row = np.floor((q[:, 1] + 0.05) / 1.1 * rows)
    order = np.lexsort((np.where(row % 2 == 0, q[:, 0], -q[:, 0]), row))
    qs = np.ascontiguousarray(q[order])
    ex, sc = [], []
    for _ in range(args.reps):
        ex.append(timed(lambda: ours.find_simplex(q))[0])
        t, b_sorted = timed(lambda: theirs.find_simplex(qs))
        sc.append(t)
    given, b = timed(lambda: theirs.find_simplex(q))
    b_back = np.empty_like(b_sorted)
    b_back[order] = b_sorted
    for name, other in (("as given", b), ("sorted", b_back)):
        both = (a >= 0) & (other >= 0)
        same = (np.sort(ours.simplices[a[both]], axis=1) ==
                np.sort(theirs.simplices[other[both]], axis=1)).all(axis=1).sum()
        agree = same + ((a == -1) & (other == -1)).sum()
        print(f"answers agreeing with scipy ({name}): {agree} of {len(q)}")
    if args.interpolate:
        values = np.sin(6 * pts[:, 0]) + pts[:, 1] ** 2
        t_ours, v_ours = timed(lambda: exidel.LinearNDInterpolator(pts, values)(q))
        t_theirs, v_theirs = timed(lambda: scipy.interpolate.LinearNDInterpolator(pts, values)(q))
        close = np.isclose(v_ours, v_theirs, rtol=1e-12, atol=1e-12, equal_nan=True).sum()
        print(f"LinearNDInterpolator(points, values)(queries): exidel {t_ours:.3f} s, scipy "
              f"{t_theirs:.3f} s, ratio {t_ours / t_theirs:.4f}x (goal <= 0.2x); "
              f"{close} of {len(q)} values equal to 1e-12")
    e, s = statistics.median(ex), statistics.median(sc)
    print(f"n = {args.n} points, {args.queries} queries, scipy {scipy.__version__}, "
          f"exidel {exidel.__version__}; medians of {args.reps} (s)")
    print(f"exidel find_simplex, first call (builds the Locator)  {first:9.3f}")
    print(f"exidel find_simplex, later calls                      {e:9.3f}")
    print(f"scipy find_simplex, queries as given (once)           {given:9.3f}")
    print(f"scipy find_simplex, queries in serpentine strips      {s:9.3f}")
    print(f"ratio exidel first call / scipy as given   {first / given:8.4f}x (goal <= 0.1x)")
    print(f"ratio exidel later calls / scipy sorted    {e / s:8.4f}x")


if __name__ == "__main__":
    main()
