#!/usr/bin/env python3
"""Markdown table of exidel_bench_triangulation: exidel against CGAL, medians.

Reads the JSON of exidel_bench_triangulation (Google Benchmark, --benchmark_format=json),
or runs the binary itself:

  python3 bench/triangulation_table.py results.json
  python3 bench/triangulation_table.py --run build/bench/exidel_bench_triangulation \
      --repetitions 3 [--filter REGEX] [--json-out results.json] [-- binary args]

Times are medians over the repetitions of each benchmark's CPU time, in ms (the machine
is shared: CPU time is less disturbed by other processes than wall time). flips/pt and
bytes/pt come from one untimed run per benchmark (see triangulation_bench.cpp). Only
ratios measured in one run mean anything. Standard library only.
"""
import argparse
import json
import statistics
import subprocess
import sys
from collections import defaultdict

ORDER = ["uniform", "gaussian", "circle", "grid", "parabola-desc", "parabola-asc"]


def collect(report):
    """{(input, n, impl): {"ms": median, "n": count, counters...}}; "error" on failures."""
    samples = defaultdict(list)
    medians = {}
    extra = {}
    for b in report["benchmarks"]:
        name = b.get("run_name", b["name"])
        parts = name.split("/")
        if len(parts) < 4 or parts[0] != "tri":
            continue
        key = (parts[1], int(parts[2]), parts[3])
        if b.get("error_occurred"):
            extra[key] = {"error": b.get("error_message", "error")}
            continue
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
        info = extra.setdefault(key, {})
        # Counters are the same in every repetition; the stddev/cv aggregates are not them.
        if b.get("run_type") != "aggregate" or b.get("aggregate_name") == "median":
            for c in ("n", "flips_per_pt", "bytes_per_pt"):
                if c in b:
                    info[c] = b[c]
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                medians[key] = b["cpu_time"] * scale
        else:
            samples[key].append(b["cpu_time"] * scale)
    result = {}
    for key, info in extra.items():
        row = dict(info)
        if key in medians:
            row["ms"] = medians[key]
        elif samples.get(key):
            row["ms"] = statistics.median(samples[key])
        row["reps"] = len(samples.get(key, [])) or (1 if key in medians else 0)
        result[key] = row
    return result


def table(rows, out=sys.stdout):
    cases = sorted({(i, n) for i, n, _ in rows},
                   key=lambda c: (ORDER.index(c[0]) if c[0] in ORDER else len(ORDER), c[0], c[1]))

    def ms(i, n, impl):
        r = rows.get((i, n, impl))
        if r is None:
            return None, "-"
        if "error" in r:
            return None, "fail"
        return r.get("ms"), f"{r['ms']:.2f}" if r.get("ms") is not None else "-"

    def ratio(a, b):
        return f"{a / b:.2f}" if a is not None and b else "-"

    out.write("| input | n | exidel-adaptive ms | exidel-double ms | exidel-exact ms | CGAL ms "
              "| adaptive/CGAL | adaptive/double | flips/pt | exidel bytes/pt "
              "| CGAL bytes/pt |\n")
    out.write("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n")
    for i, n in cases:
        a, a_s = ms(i, n, "exidel-adaptive")
        d, d_s = ms(i, n, "exidel-double")
        _, e_s = ms(i, n, "exidel-exact")
        c, c_s = ms(i, n, "cgal-epick")
        ad = rows.get((i, n, "exidel-adaptive"), {})
        cg = rows.get((i, n, "cgal-epick"), {})
        count = int(ad.get("n", cg.get("n", n)))
        flips = f"{ad['flips_per_pt']:.2f}" if "flips_per_pt" in ad else "-"
        eb = f"{ad['bytes_per_pt']:.0f}" if "bytes_per_pt" in ad else "-"
        cb = f"{cg['bytes_per_pt']:.0f}" if "bytes_per_pt" in cg else "-"
        out.write(f"| {i} | {count} | {a_s} | {d_s} | {e_s} | {c_s} | {ratio(a, c)} "
                  f"| {ratio(a, d)} | {flips} | {eb} | {cb} |\n")
    reps = sorted({r.get("reps", 0) for r in rows.values() if "error" not in r})
    out.write(f"\nrepetitions per benchmark: {', '.join(map(str, reps))}\n")
    for key, r in sorted(rows.items()):
        if "error" in r:
            out.write(f"- {'/'.join(map(str, key))}: {r['error']}\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json", nargs="?", help="benchmark JSON output")
    ap.add_argument("--run", metavar="BINARY", help="run the benchmark binary")
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--filter", default=None)
    ap.add_argument("--json-out", default=None, help="also save the raw JSON here")
    argv = sys.argv[1:]
    extra = argv[argv.index("--") + 1:] if "--" in argv else []
    args = ap.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    if args.run:
        cmd = [args.run, f"--benchmark_repetitions={args.repetitions}",
               "--benchmark_format=json"]
        if args.filter:
            cmd.append(f"--benchmark_filter={args.filter}")
        cmd += extra
        print("running: " + " ".join(cmd), file=sys.stderr)
        text = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout
        report = json.loads(text)
        if args.json_out:
            with open(args.json_out, "w") as f:
                f.write(text)
    elif args.json:
        with open(args.json) as f:
            report = json.load(f)
    else:
        ap.error("give a JSON file or --run BINARY")
    table(collect(report))


if __name__ == "__main__":
    main()
