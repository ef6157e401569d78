#!/usr/bin/python3
"""Hashes of the default triangulation's arrays, from an `exidel` binary's JSON output.

usage: golden_hash.py EXIDEL [--threads 1,2,3]

Generates the four inputs of tests/delaunay/golden_test.cpp (same generator, same
doubles), writes each as .f64 into a temporary directory, runs
`EXIDEL triangulate -i IN.f64 -o OUT.json --threads T -q` and prints the FNV-1a hash of
the arrays as golden_test.cpp computes it. Run it with the binary of the commit whose
output the test pins (7c2f955) to check the test's constants. Standard library only.
"""
import json
import os
import struct
import subprocess
import sys
import tempfile

MASK = (1 << 64) - 1


class SplitMix64:
    def __init__(self, seed):
        self.state = seed

    def next(self):
        self.state = (self.state + 0x9E3779B97F4A7C15) & MASK
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)

    def unit(self):
        return float(self.next() >> 11) * 2.0**-53


def golden_input(name):
    g = SplitMix64(17)
    p = []
    if name == "uniform":
        for _ in range(200000):
            x = g.unit()
            p.append((x, g.unit()))
    elif name == "grid":
        p = [(float(i % 450), float(i // 450)) for i in range(450 * 450)]
        for i in range(len(p) - 1, 0, -1):
            j = g.next() % (i + 1)
            p[i], p[j] = p[j], p[i]
    elif name == "circle":
        for _ in range(150000):
            t = 4 * g.unit() - 2
            d = 1 + t * t
            p.append(((1 - t * t) / d, 2 * t / d))
    else:
        for _ in range(200000):
            x = float(g.next() % 400)
            p.append((x, float(g.next() % 400)))
    return p


def fnv(arrays):
    h = 0xCBF29CE484222325
    for values in arrays:
        for v in [len(values)] + list(values):
            for byte in struct.pack("<I", v & 0xFFFFFFFF):
                h = ((h ^ byte) * 0x100000001B3) & MASK
    return h


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    exidel = sys.argv[1]
    threads = [1, 2, 3]
    if len(sys.argv) == 4 and sys.argv[2] == "--threads":
        threads = [int(t) for t in sys.argv[3].split(",")]
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("uniform", "grid", "circle", "repeats"):
            path = os.path.join(tmp, name + ".f64")
            with open(path, "wb") as f:
                for x, y in golden_input(name):
                    f.write(struct.pack("<dd", x, y))
            for t in threads:
                out = os.path.join(tmp, "out.json")
                subprocess.run([exidel, "triangulate", "-i", path, "-o", out,
                                "--threads", str(t), "-q"], check=True)
                with open(out) as f:
                    r = json.load(f)
                h = fnv([r["triangles"], r["halfedges"], r["hull"], r["duplicates"]])
                print(f"{name} threads {t}: 0x{h:016x}", flush=True)


if __name__ == "__main__":
    main()
