#!/usr/bin/env python3
"""Compares two report.json files figure by figure: exit 0 when equal.

Left out: what a run measures of itself (times, rates, when and how it was
started) and where saved files are (paths compared by file name; the set of
files may differ: sharded runs cap saved cases per shard).

usage: compare_reports.py A/report.json B/report.json
"""
import json
import os
import sys

# Keys whose values are timings or describe the run, not its figures.
VOLATILE = {
    "started", "command_line", "subject_ns_per_query", "oracle_us_per_case", "cases_per_second_per_core",
    "ns_per_call", "production_us", "cgal_us", "production_ms", "cgal_ms", "speed_ratio", "time_ratio",
    "production_us_per_set", "cgal_us_per_set", "production_us_total", "cgal_us_total", "production_over_cgal",
    "seconds", "meshes_per_second", "brute_force_us_total", "brute_force_over_production",
}
# Lists of saved files: capped per run or shard, so only checked to exist.
PATHS = {"counterexamples", "cases", "bugreports_failed"}
# How many saved cases were shrunk: follows the saved files (caps per shard).
VOLATILE |= {"shrunk"}


def diff(a, b, path, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k in VOLATILE:
                continue
            if k not in a or k not in b:
                out.append(f"{path}.{k}: only in {'first' if k in a else 'second'}")
                continue
            if k in PATHS and isinstance(a[k], list):
                continue
            diff(a[k], b[k], f"{path}.{k}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{path}: {len(a)} vs {len(b)} items")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            diff(x, y, f"{path}[{i}]", out)
    elif a != b:
        out.append(f"{path}: {a!r} vs {b!r}")


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    a, b = (json.load(open(p)) for p in sys.argv[1:])
    out = []
    diff(a, b, "$", out)
    for line in out[:40]:
        print(line)
    if out:
        print(f"{len(out)} differences", file=sys.stderr)
        return 1
    print("same figures")
    return 0


if __name__ == "__main__":
    sys.exit(main())
