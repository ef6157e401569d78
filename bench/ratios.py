#!/usr/bin/env python3
"""Median ns per call of every predicate x input x kernel, and the ratios that matter.

Reads the JSON of exidel_bench_predicates (Google Benchmark, --benchmark_format=json), or
runs the binary itself:

  python3 bench/ratios.py results.json
  python3 bench/ratios.py --run build/bench/exidel_bench_predicates --repetitions 5 \
      [--filter REGEX] [--markdown]

Uses the median over repetitions of each benchmark's CPU time (the machine is shared:
CPU time is less disturbed by other processes than wall time). With one repetition the
single measurement is used. Only ratios measured in one run mean anything.
Standard library only.
"""
import argparse
import json
import statistics
import subprocess
import sys
from collections import defaultdict

PEER = "cgal-epick"


def medians(report):
    """{(predicate, input, kernel): median ns per call}."""
    samples = defaultdict(list)
    aggregated = {}
    for b in report["benchmarks"]:
        name = b.get("run_name", b["name"])
        parts = name.split("/")
        if len(parts) != 3:
            continue
        key = tuple(parts)
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
        # A batched benchmark handles per_iteration queries per iteration: per query.
        scale /= b.get("per_iteration") or 1.0  # (0 in the stddev aggregate)
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                aggregated[key] = b["cpu_time"] * scale
        else:
            samples[key].append(b["cpu_time"] * scale)
    result = {k: statistics.median(v) for k, v in samples.items()}
    result.update(aggregated)  # the library's own medians win when present
    return result


def table_rows(m):
    """(predicate, input) pairs, uniform first within each predicate."""
    return sorted({(p, i) for p, i, _ in m}, key=lambda r: (r[0], r[1] != "uniform", r[1]))


def ratio(m, p, i, num, den):
    """num's median over den's for one predicate and input, or '-' if either is missing."""
    a, b = m.get((p, i, num)), m.get((p, i, den))
    return f"{a / b:.2f}" if a is not None and b else "-"


def print_tables(m, out=sys.stdout):
    rows = table_rows(m)
    kernels = []
    for _, _, k in sorted(m):
        if k not in kernels:
            kernels.append(k)
    order = ["double", "long-double", "adaptive", "adaptive-batch", "exact", "exact-cpp"]

    def column(k):
        if k in order:
            return (order.index(k), 0)
        if k.startswith("mpfr:") and k[5:].isdigit():
            return (len(order), int(k[5:]))
        return (len(order) + 1, 0)  # the peer and anything unknown last
    kernels.sort(key=column)

    out.write("median ns per call\n")
    out.write(f"{'predicate/input':28}" + "".join(f"{k:>12}" for k in kernels) + "\n")
    for p, i in rows:
        cells = "".join(
            f"{m[(p, i, k)]:12.1f}" if (p, i, k) in m else f"{'-':>12}" for k in kernels)
        out.write(f"{p + '/' + i:28}{cells}\n")

    out.write("\nratios of medians\n")
    out.write(f"{'predicate/input':28}{'adaptive/double':>17}{'cgal/double':>13}"
              f"{'adaptive/cgal':>15}{'batch speed-up':>16}\n")
    for p, i in rows:
        out.write(f"{p + '/' + i:28}{ratio(m, p, i, 'adaptive', 'double'):>17}"
                  f"{ratio(m, p, i, PEER, 'double'):>13}{ratio(m, p, i, 'adaptive', PEER):>15}"
                  f"{ratio(m, p, i, 'adaptive', 'adaptive-batch'):>16}\n")


def print_markdown(m, out=sys.stdout):
    """The table of docs/benchmarks.md ("The plane"): per predicate and input, double, adaptive (one call per query),
    adaptive batched, CGAL, and the ratios adaptive / CGAL and adaptive / batched."""
    rows = table_rows(m)
    out.write("| predicate / input | double | adaptive | batched | CGAL Epick | "
              "adaptive / CGAL | batch speed-up |\n|---|---:|---:|---:|---:|---:|---:|\n")
    for p, i in rows:
        def cell(k):
            v = m.get((p, i, k))
            return "-" if v is None else (f"{v:.1f}" if v < 100 else f"{v:.0f}")
        out.write(f"| {p} / {i} | {cell('double')} | {cell('adaptive')} | "
                  f"{cell('adaptive-batch')} | {cell(PEER)} | {ratio(m, p, i, 'adaptive', PEER)} | "
                  f"{ratio(m, p, i, 'adaptive', 'adaptive-batch')} |\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json", nargs="?", help="benchmark JSON output ('-' for stdin)")
    ap.add_argument("--run", metavar="BINARY", help="run this exidel_bench_predicates")
    ap.add_argument("--repetitions", type=int, default=5)
    ap.add_argument("--filter", default="", help="--benchmark_filter for --run")
    ap.add_argument("--markdown", action="store_true", help="the table of docs/benchmarks.md instead")
    args = ap.parse_args()
    if (args.json is None) == (args.run is None):
        ap.error("give either a JSON file or --run BINARY")
    if args.run:
        cmd = [args.run, f"--benchmark_repetitions={args.repetitions}",
               "--benchmark_report_aggregates_only=true", "--benchmark_format=json"]
        if args.filter:
            cmd.append(f"--benchmark_filter={args.filter}")
        sys.stderr.write("running: " + " ".join(cmd) + "\n")
        report = json.loads(subprocess.run(cmd, check=True, capture_output=True,
                                           text=True).stdout)
    elif args.json == "-":
        report = json.load(sys.stdin)
    else:
        with open(args.json) as f:
            report = json.load(f)
    m = medians(report)
    if not m:
        sys.exit("no predicate/input/kernel benchmarks in the input")
    if args.markdown:
        print_markdown(m)
    else:
        print_tables(m)


if __name__ == "__main__":
    main()
