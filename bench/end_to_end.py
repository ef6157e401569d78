#!/usr/bin/env python3
"""End-to-end times of `exidel triangulate`: reading, triangulating and writing, per input
file and output format, as the command's own --stats phases report them (read_ms,
triangulate_ms, write_ms, total_ms), medians of interleaved repetitions, and the share of
reading and writing in the total.

  build/bench/exidel_bench_triangulation --exidel_write=poisson-disc:1000000:/dev/shm/p.xy
  sed 's/ /,/' /dev/shm/p.xy > /dev/shm/p.csv
  python3 bench/end_to_end.py --exidel build/cli/exidel /dev/shm/p.xy /dev/shm/p.csv \\
      [--formats json,ele,geojson] [--repetitions 3] [--out-dir /dev/shm] [--markdown] \\
      [-- more exidel triangulate arguments]

Outputs go to --out-dir (default /dev/shm, a memory file system: the disk's own speed,
about 300 MB/s on the project's machines, would otherwise dominate the large formats)
and are deleted after each run. Standard library only.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

PHASES = ("read_ms", "triangulate_ms", "write_ms", "total_ms")


def run(exidel, path, fmt, out_dir, extra):
    out = os.path.join(out_dir, "exidel-end-to-end." + fmt)
    cmd = [exidel, "triangulate", "-i", path, "-o", out, "--stats"] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    for f in (out, os.path.splitext(out)[0] + ".node"):
        if os.path.exists(f) and f != path:
            os.unlink(f)
    if r.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{r.stderr}")
    stats = json.loads(r.stderr.strip().splitlines()[-1])
    return [stats[p] for p in PHASES]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("inputs", nargs="+")
    ap.add_argument("--exidel", default="build/cli/exidel")
    ap.add_argument("--formats", default="json,ele,geojson")
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--out-dir", default="/dev/shm")
    ap.add_argument("--markdown", action="store_true")
    # After "--": more arguments of exidel triangulate (e.g. --threads 1).
    argv = sys.argv[1:]
    extra = argv[argv.index("--") + 1:] if "--" in argv else []
    args = ap.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    formats = args.formats.split(",")
    samples = {}
    for _ in range(args.repetitions):  # interleaved: every case once per round
        for path in args.inputs:
            for fmt in formats:
                samples.setdefault((path, fmt), []).append(
                    run(args.exidel, path, fmt, args.out_dir, extra))
    if args.markdown:
        print("| input | output | read ms | triangulate ms | write ms | total ms | I/O share |")
        print("|---|---|---:|---:|---:|---:|---:|")
    for (path, fmt), runs in samples.items():
        m = [statistics.median(r[i] for r in runs) for i in range(len(PHASES))]
        share = (m[0] + m[2]) / m[3] if m[3] else 0.0
        name = os.path.basename(path)
        if args.markdown:
            print(f"| {name} | {fmt} | {m[0]:.0f} | {m[1]:.0f} | {m[2]:.0f} | {m[3]:.0f} "
                  f"| {100 * share:.0f}% |")
        else:
            print(f"{name:>16} {fmt:>8}  read {m[0]:7.0f}  triangulate {m[1]:7.0f}  "
                  f"write {m[2]:7.0f}  total {m[3]:7.0f} ms  I/O {100 * share:3.0f}%")


if __name__ == "__main__":
    main()
