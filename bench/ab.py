#!/usr/bin/python3
"""A/B timing of two builds of a benchmark binary (exidel_bench_triangulation,
exidel_bench_predicates, exidel_bench_predicates3d), interleaved runs.

usage: ab.py OLD_BINARY NEW_BINARY --filter REGEX --rounds R [--out results.json]
                   [--threshold 1.03] [-- EXTRA_BENCHMARK_ARGS...]

Each round runs OLD then NEW (odd rounds) or NEW then OLD (even rounds), each as its own
process with --benchmark_filter=REGEX --benchmark_format=json (one repetition per process),
and records real_time (in ms) per benchmark name. Aggregates and entries with
"error_occurred" are skipped (errors are listed). The table gives, per benchmark:
  old, new     median real_time over rounds (ms)
  new/old      median(new) / median(old)                      <- the number that is flagged
  pair med/min/max   median, min and max over rounds of new_i/old_i (same round)
  old/cgal, new/cgal  median over rounds of t/t(cgal-epick of the same input and n, same
               process), when the filter also selects cgal-epick; n/c:o/c is their quotient
               (a load-robust cross-check: both builds normalised by CGAL in their process)
A benchmark is FLAGGED when new/old or the median paired ratio exceeds --threshold.
Exit status: 0 nothing flagged, 1 something flagged, 2 errors / missing benchmarks.
Standard library only. Raw numbers (every run) go to --out as JSON, rewritten after every
round so an interrupted run keeps what it measured.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

UNIT_TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def die(msg):
    print("ab.py: " + msg, file=sys.stderr, flush=True)
    sys.exit(2)


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def run_once(binary, flt, extra):
    """One process; returns (times_ms {name: ms}, errors {name: msg}, context, wall_s, cmd)."""
    fd, outfile = tempfile.mkstemp(prefix="bench_ab_", suffix=".json")
    os.close(fd)
    cmd = [binary, "--benchmark_filter=" + flt, "--benchmark_format=json",
           "--benchmark_out=" + outfile, "--benchmark_out_format=json"] + extra
    t0 = time.monotonic()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - t0
    try:
        text = ""
        try:
            with open(outfile) as f:
                text = f.read()
        except OSError:
            pass
        if not text.strip():
            text = proc.stdout
        try:
            data = json.loads(text)
        except ValueError:
            i = text.find("{")
            data = json.loads(text[i:]) if i >= 0 else {}
    except ValueError as e:
        die("cannot parse JSON from %s (exit %d): %s\nstderr: %s"
                         % (binary, proc.returncode, e, proc.stderr[-2000:]))
    finally:
        try:
            os.unlink(outfile)
        except OSError:
            pass
    if proc.returncode != 0:
        log("bench_ab: WARNING %s exited with %d; stderr tail:\n%s"
            % (binary, proc.returncode, proc.stderr[-2000:]))
    times, errors = {}, {}
    for b in data.get("benchmarks", []):
        if b.get("run_type", "iteration") != "iteration" or "aggregate_name" in b:
            continue
        name = b["name"]
        if b.get("error_occurred"):
            errors[name] = b.get("error_message", "error")
            continue
        times[name] = b["real_time"] * UNIT_TO_MS[b.get("time_unit", "ns")]
    return times, errors, data.get("context", {}), wall, cmd


def cgal_name(name):
    """The same benchmark with impl = cgal-epick: tri/<input>/<n>/<impl>[/...] (the
    triangulation benchmark) or <predicate>/<input>/<impl> (the predicate benchmarks);
    None for another form or for CGAL itself."""
    parts = name.split("/")
    at = 3 if parts[0] == "tri" else 2
    if len(parts) <= at or (parts[0] != "tri" and len(parts) != 3) or parts[at] == "cgal-epick":
        return None
    parts[at] = "cgal-epick"
    return "/".join(parts)


def summarize(runs, threshold):
    """runs: list of {"round", "old": {...}, "new": {...}}. Returns list of row dicts."""
    names = []
    for r in runs:
        for side in ("old", "new"):
            for n in r[side]["times"]:
                if n not in names:
                    names.append(n)
    rows = []
    for name in names:
        old = [r["old"]["times"][name] for r in runs if name in r["old"]["times"]]
        new = [r["new"]["times"][name] for r in runs if name in r["new"]["times"]]
        pairs = [r["new"]["times"][name] / r["old"]["times"][name] for r in runs
                 if name in r["old"]["times"] and name in r["new"]["times"]
                 and r["old"]["times"][name] > 0]
        row = {"name": name, "n_old": len(old), "n_new": len(new),
               "old_ms": statistics.median(old) if old else None,
               "new_ms": statistics.median(new) if new else None,
               "pair_median": statistics.median(pairs) if pairs else None,
               "pair_min": min(pairs) if pairs else None,
               "pair_max": max(pairs) if pairs else None}
        row["ratio"] = (row["new_ms"] / row["old_ms"]
                        if row["old_ms"] and row["new_ms"] is not None else None)
        c = cgal_name(name)
        for side in ("old", "new"):
            rs = [r[side]["times"][name] / r[side]["times"][c] for r in runs
                  if c and name in r[side]["times"] and c in r[side]["times"]
                  and r[side]["times"][c] > 0]
            row[side + "_cgal"] = statistics.median(rs) if rs else None
        row["cgal_norm"] = (row["new_cgal"] / row["old_cgal"]
                            if row["old_cgal"] and row["new_cgal"] is not None else None)
        row["flag"] = any(v is not None and v > threshold
                          for v in (row["ratio"], row["pair_median"]))
        row["complete"] = len(old) == len(runs) and len(new) == len(runs)
        rows.append(row)
    return rows


def fmt(v, spec):
    return "-" if v is None else format(v, spec)


def print_table(rows, rounds, threshold, have_cgal):
    w = max([len("benchmark")] + [len(r["name"]) for r in rows])
    hdr = "%-*s %10s %10s %8s %8s %8s %8s" % (w, "benchmark", "old ms", "new ms", "new/old",
                                             "pair.med", "pair.min", "pair.max")
    if have_cgal:
        hdr += " %9s %9s %9s" % ("old/cgal", "new/cgal", "n/c:o/c")
    print(hdr)
    print("-" * len(hdr))
    for r in rows:
        line = "%-*s %10s %10s %8s %8s %8s %8s" % (
            w, r["name"], fmt(r["old_ms"], ".2f"), fmt(r["new_ms"], ".2f"),
            fmt(r["ratio"], ".4f"), fmt(r["pair_median"], ".4f"),
            fmt(r["pair_min"], ".4f"), fmt(r["pair_max"], ".4f"))
        if have_cgal:
            line += " %9s %9s %9s" % (fmt(r["old_cgal"], ".3f"), fmt(r["new_cgal"], ".3f"),
                                      fmt(r["cgal_norm"], ".4f"))
        if r["flag"]:
            line += "  <-- SLOWER > %.0f%%" % ((threshold - 1) * 100)
        if not r["complete"]:
            line += "  (runs old %d new %d of %d)" % (r["n_old"], r["n_new"], rounds)
        print(line)
    flagged = [r["name"] for r in rows if r["flag"]]
    print()
    print("medians over %d interleaved rounds; new/old = median(new)/median(old); "
          "pair = new_i/old_i within round i" % rounds)
    if flagged:
        print("FLAGGED (new/old or paired median > %.3f): %d" % (threshold, len(flagged)))
        for n in flagged:
            print("  " + n)
    else:
        print("no benchmark slower by more than %.1f%% (threshold %.3f)"
              % ((threshold - 1) * 100, threshold))


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        i = argv.index("--")
        argv, extra = argv[:i], argv[i + 1:]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--filter", required=True, help="--benchmark_filter regex")
    ap.add_argument("--rounds", type=int, required=True)
    ap.add_argument("--out", help="write raw numbers here (JSON)")
    ap.add_argument("--threshold", type=float, default=1.03)
    a = ap.parse_args(argv)
    for b in (a.old, a.new):
        if not (os.path.isfile(b) and os.access(b, os.X_OK)):
            die("not an executable: %s" % b)
    if a.rounds < 1:
        die("--rounds must be >= 1")

    bins = {"old": os.path.abspath(a.old), "new": os.path.abspath(a.new)}
    result = {"old_binary": bins["old"], "new_binary": bins["new"], "filter": a.filter,
              "rounds": a.rounds, "threshold": a.threshold, "extra_args": extra,
              "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "unit": "ms (real_time)",
              "runs": []}
    all_errors = {}
    t_start = time.monotonic()
    for rnd in range(1, a.rounds + 1):
        order = ["old", "new"] if rnd % 2 == 1 else ["new", "old"]
        entry = {"round": rnd, "order": order}
        for side in order:
            log("round %d/%d: %s (%s) ..." % (rnd, a.rounds, side, bins[side]))
            times, errors, ctx, wall, cmd = run_once(bins[side], a.filter, extra)
            if not times and not errors:
                die("the filter selects no benchmark in %s" % bins[side])
            for n, m in errors.items():
                all_errors.setdefault((side, n), m)
            entry[side] = {"times": times, "errors": errors, "wall_s": round(wall, 3),
                           "load_avg": ctx.get("load_avg"), "date": ctx.get("date"),
                           "cmd": cmd}
            log("  %d benchmarks, %d errors, process wall %.1f s, load %s"
                % (len(times), len(errors), wall, ctx.get("load_avg")))
        result["runs"].append(entry)
        result["elapsed_s"] = round(time.monotonic() - t_start, 1)
        if a.out:
            tmp = a.out + ".tmp"
            with open(tmp, "w") as f:
                json.dump(result, f, indent=1, sort_keys=True)
            os.replace(tmp, a.out)

    rows = summarize(result["runs"], a.threshold)
    have_cgal = any(r["old_cgal"] is not None or r["new_cgal"] is not None for r in rows)
    print_table(rows, a.rounds, a.threshold, have_cgal)
    if all_errors:
        print("\nERRORS (skipped):")
        for (side, n), m in sorted(all_errors.items()):
            print("  %s %s: %s" % (side, n, m))
    wall = {s: sum(r[s]["wall_s"] for r in result["runs"]) for s in ("old", "new")}
    print("\ntotal %.1f s (process wall: old %.1f s, new %.1f s)"
          % (time.monotonic() - t_start, wall["old"], wall["new"]))
    result["summary"] = rows
    result["elapsed_s"] = round(time.monotonic() - t_start, 1)
    if a.out:
        with open(a.out, "w") as f:
            json.dump(result, f, indent=1, sort_keys=True)
    incomplete = any(not r["complete"] for r in rows)
    if all_errors or incomplete:
        return 2
    return 1 if any(r["flag"] for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
