#!/usr/bin/python3
"""Shares of a triangulation's profile per phase, from `perf report` symbol shares.

usage: profile_phases.py PERF_DATA [PERF_DATA ...]

Runs `perf report -i PERF_DATA --no-children --stdio --sort sym` and adds up the
shares of the symbols of each phase of the default triangulation (strips):

  sort         the lexicographic sort and deduplication of the input (sort_and_dedupe,
               its radix passes and run sorts, their parallel_for bodies)
  predicates   the kernel's orient2d, incircle, compare_distance (all stages)
  strips       the strips' insertions: Builder (tangent walks, erosion, connect), the
               radial hash, the strips' radial sorts, copying a strip into the mesh
  merges       the Guibas-Stolfi zipper (Merger, its half-edge set)
  compaction   to_triangulation (dropping free slots, input indices)
  memory       zero-filling fresh arrays (memset, vector fills) and the kernel's page
               faults and page clearing ([k] symbols)
  other        the rest (benchmark harness, input generation, libc)

The predicates are called from both the strips and the merges; perf without call graphs
cannot split them, so they are a phase of their own. Hardware events (cycles, cache and
branch misses) need a PMU, which the project's virtual machines do not expose
(`perf stat -e cycles` prints <not supported>): the samples are cpu-clock.
Standard library only.
"""
import re
import subprocess
import sys

PHASES = [
    ("predicates", r"AdaptiveKernel::|orient2d|incircle|compare_distance|expansion|two_"),
    ("sort", r"sort_and_dedupe|radix_pass|sort_run|Record|\(anonymous namespace\)::Buckets"),
    ("merges", r"Merger<|HalfEdgeSet"),
    ("compaction", r"to_triangulation"),
    ("strips", r"Builder<|RadialHullHash|radial_|build_piece|build_strips|radix_sort|"
               r"guess_order|merge_sort|Mesh::|strip_cuts|push_back|emplace_back|"
               r"_M_realloc_insert"),
    ("memory", r"memset|_M_fill_assign|resize_fresh|assign_fresh|\[k\]"),
]


def shares(path):
    out = subprocess.run(["perf", "report", "-i", path, "--no-children", "--stdio",
                          "--sort", "dso,sym"], capture_output=True, text=True,
                         check=True).stdout
    totals = {name: 0.0 for name, _ in PHASES}
    totals["other"] = 0.0
    for line in out.splitlines():
        m = re.match(r"\s*([0-9.]+)%\s+(\S+)\s+(.*)$", line)
        if not m:
            continue
        share, sym = float(m.group(1)), m.group(2) + " " + m.group(3)
        for name, pattern in PHASES:
            if re.search(pattern, sym):
                totals[name] += share
                break
        else:
            totals["other"] += share
    return totals


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    names = [name for name, _ in PHASES] + ["other"]
    print("| profile | " + " | ".join(names) + " |")
    print("|---|" + "---:|" * len(names))
    for path in sys.argv[1:]:
        t = shares(path)
        print(f"| {path} | " + " | ".join(f"{t[n]:.1f}%" for n in names) + " |")


if __name__ == "__main__":
    main()
