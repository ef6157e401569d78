#!/usr/bin/python3
"""Write the deterministic point files of the exidel verification harness.

Every file is in exidel's "xy" format: one point per line, "x y", each coordinate
written with float.hex() so that exidel reads back exactly the double Python had.
Every family uses its own fixed seed, so the files are the same on every run
(a re-run rewrites them byte for byte; check with sha256sum inputs/*).

Usage: /usr/bin/python3 make_inputs.py [OUTDIR]   (default: inputs/ next to this file)
"""
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "inputs")


def write(name, points):
    path = os.path.join(OUT, name + ".xy")
    tmp = path + ".tmp"
    with open(tmp, "w", newline="\n") as f:
        for x, y in points:
            x = float(x)
            y = float(y)
            assert math.isfinite(x) and math.isfinite(y), (name, x, y)
            f.write(x.hex() + " " + y.hex() + "\n")
    os.replace(tmp, path)
    print("%-28s %7d points" % (name + ".xy", len(points)))


def uniform(n, seed):
    r = random.Random(seed)
    return [(r.random(), r.random()) for _ in range(n)]


def circle(n, seed):
    pts = [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)]
    random.Random(seed).shuffle(pts)
    return pts


def parabola_asc(n, seed):
    # x = -n..-1: lexicographic order walks towards the vertex (quadratic for that order).
    pts = [(float(x), float(x * x)) for x in range(-n, 0)]
    random.Random(seed).shuffle(pts)
    return pts


def parabola_desc(n):
    # x = 1..n, left in increasing x (already sorted input), away from the vertex.
    return [(float(x), float(x * x)) for x in range(1, n + 1)]


def grid(s, seed):
    pts = [(float(i), float(j)) for i in range(s) for j in range(s)]
    random.Random(seed).shuffle(pts)
    return pts


def rotated_grid(s, seed):
    c = math.cos(math.radians(30.0))
    si = math.sin(math.radians(30.0))
    pts = [(i * c - j * si, i * si + j * c) for i in range(s) for j in range(s)]
    random.Random(seed).shuffle(pts)
    return pts


def clustered(n, clusters, sigma, seed):
    r = random.Random(seed)
    centres = [(r.random(), r.random()) for _ in range(clusters)]
    pts = []
    for _ in range(n):
        cx, cy = centres[r.randrange(clusters)]
        pts.append((r.gauss(cx, sigma), r.gauss(cy, sigma)))
    return pts


def wide(n, seed):
    r = random.Random(seed)

    def coord():
        m = r.uniform(1.0, 2.0) * r.choice((-1.0, 1.0))
        return math.ldexp(m, r.randint(-300, 300))

    return [(coord(), coord()) for _ in range(n)]


def degenerate_mixed(seed):
    """Random points plus duplicates, collinear runs (axis-parallel, diagonal, on the
    hull and inside), a cocircular ring with its centre, and a few exact repeats."""
    r = random.Random(seed)
    pts = [(float(r.randint(0, 64)) / 4, float(r.randint(0, 64)) / 4) for _ in range(120)]
    pts += [(float(i), 0.0) for i in range(0, 17)]          # bottom edge, collinear
    pts += [(0.0, float(j)) for j in range(0, 17)]          # left edge, collinear
    pts += [(float(i), float(i)) for i in range(0, 17)]     # diagonal through the inside
    pts += [(8.0 + 0.5 * i, 3.0) for i in range(-6, 7)]     # horizontal run inside
    ring = [(8.0 + 4.0 * math.cos(2 * math.pi * k / 12), 8.0 + 4.0 * math.sin(2 * math.pi * k / 12))
            for k in range(12)]
    pts += ring + [(8.0, 8.0)]
    pts += [(8.0 + x, 8.0 + y) for x, y in ((3, 4), (4, 3), (-3, 4), (4, -3), (-4, -3), (0, 5), (5, 0))]
    dups = [pts[r.randrange(len(pts))] for _ in range(40)]
    pts += dups + [(0.0, 0.0)] * 3 + [(16.0, 0.0)] * 2
    r.shuffle(pts)
    return pts


def degenerate_collinear(seed):
    """50 points on y = 2x + 1 (exact in doubles: small integers), some repeated."""
    r = random.Random(seed)
    xs = [r.randint(-20, 20) for _ in range(50)]
    pts = [(float(x), float(2 * x + 1)) for x in xs]
    r.shuffle(pts)
    return pts


def degenerate_collinear_inexact(seed):
    """Points on y = x/3 + 0.1 rounded to doubles: nearly, not exactly, collinear."""
    r = random.Random(seed)
    pts = []
    for _ in range(60):
        x = r.uniform(-1.0, 1.0)
        pts.append((x, x / 3.0 + 0.1))
    pts += pts[:10]
    r.shuffle(pts)
    return pts


def main():
    os.makedirs(OUT, exist_ok=True)
    write("uniform-1000", uniform(1000, 101))
    write("uniform-100000", uniform(100000, 102))
    write("uniform-300000", uniform(300000, 103))
    write("circle-1000", circle(1000, 201))
    write("circle-100000", circle(100000, 202))
    write("parabola-asc-1000", parabola_asc(1000, 301))
    write("parabola-asc-100000", parabola_asc(100000, 302))
    write("parabola-desc-100000", parabola_desc(100000))
    write("grid-30", grid(30, 401))
    write("grid-300", grid(300, 402))
    write("rotated-grid-30", rotated_grid(30, 501))
    write("rotated-grid-300", rotated_grid(300, 502))
    write("clustered-100000", clustered(100000, 100, 1e-3, 601))
    write("wide-2000", wide(2000, 701))
    write("degenerate-mixed", degenerate_mixed(801))
    write("degenerate-collinear", degenerate_collinear(802))
    write("degenerate-collinear-inexact", degenerate_collinear_inexact(803))
    write("degenerate-all-same", [(float.fromhex("0x1.8p-3"), -2.5)] * 7)
    write("degenerate-2-same", [(1.0, 1.0), (1.0, 1.0)])
    write("degenerate-3-collinear", [(0.0, 1.0), (2.0, 5.0), (1.0, 3.0)])
    write("degenerate-4-cocircular", [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)])
    write("tiny-0", [])
    write("tiny-1", [(0.5, -0.25)])
    write("tiny-2", [(0.0, 0.0), (1.0, 0.5)])
    write("tiny-3", [(0.0, 0.0), (1.0, 0.0), (0.25, 0.75)])


if __name__ == "__main__":
    main()
