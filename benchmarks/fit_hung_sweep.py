#!/usr/bin/env python3
"""The time a hung skeleton's simulated second takes at a given error, read from a sweep.

The `sweep` benchmarks of bench_engine_skeleton and the `merson_sweep` ones of
bench_simbody_hung run one simulated second at accuracies a quarter decade apart, each reporting
its CPU time, its error against a tight reference (`err_rad`) and its evaluations. The error
does not fall smoothly with the accuracy, so the time at an error (issue #15: 3e-6 rad) is read
in two ways:
  fit        the least-squares line through log time against log error, at that error;
  threshold  the loosest accuracy from which every tighter one stays at or below that error.

Usage: fit_hung_sweep.py RESULTS.json [RESULTS.json ...] [--error 3e-6]
where each file is a program's --benchmark_out (--benchmark_out_format=json).

With --compare BEFORE.json AFTER.json it compares two sweeps of the same benchmarks over the
whole range instead: at errors from 1e-5 to 1e-9 rad, the evaluations each takes by the
least-squares line through its five points nearest in log error (a change that helps at one
error and hurts at another shows as such).
"""
import argparse
import json
import math
import re
from collections import defaultdict

import numpy as np


def read_sweeps(paths):
    """{family: [(k, cpu_ms, err_rad, evaluations)]} for every benchmark named .../sweep/k."""
    sweeps = defaultdict(list)
    for path in paths:
        with open(path) as f:
            results = json.load(f)["benchmarks"]
        for run in results:
            match = re.match(r"(.*sweep)/(\d+)$", run["name"])
            if not match or run.get("run_type") == "aggregate":
                continue
            scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[run["time_unit"]]
            sweeps[match.group(1)].append((int(match.group(2)), run["cpu_time"] * scale,
                                           run["err_rad"], run["evaluations"]))
    return sweeps


def at_error(rows, error):
    rows = sorted(rows)
    log_err = np.log([r[2] for r in rows])
    fit = {}
    for name, column in (("ms", 1), ("evaluations", 3)):
        slope, intercept = np.polyfit(log_err, np.log([r[column] for r in rows]), 1)
        fit[name] = math.exp(intercept + slope * math.log(error))
    threshold = next((r for i, r in enumerate(rows) if all(s[2] <= error for s in rows[i:])),
                     None)
    return fit, threshold


def local_evaluations(rows, error):
    """Evaluations at `error` by the line through the five rows nearest it in log error."""
    log_err = np.log([r[2] for r in rows])
    nearest = np.argsort(np.abs(log_err - math.log(error)))[:5]
    slope, intercept = np.polyfit(log_err[nearest], np.log([rows[i][3] for i in nearest]), 1)
    return math.exp(intercept + slope * math.log(error))


def compare(before_path, after_path):
    before, after = read_sweeps([before_path]), read_sweeps([after_path])
    for family in sorted(set(before) & set(after)):
        print(f"{family}: evaluations at equal error, before -> after")
        for error in (1e-5, 3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8, 1e-9):
            b = local_evaluations(before[family], error)
            a = local_evaluations(after[family], error)
            print(f"  {error:.0e} rad: {b:6.0f} -> {a:6.0f} ({100 * (a / b - 1):+.1f}%)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="+")
    parser.add_argument("--error", type=float, default=3e-6)
    parser.add_argument("--compare", action="store_true",
                        help="compare two sweeps (BEFORE.json AFTER.json) over the whole range")
    args = parser.parse_args()
    if args.compare:
        if len(args.results) != 2:
            raise SystemExit("fit_hung_sweep: --compare takes BEFORE.json AFTER.json")
        return compare(*args.results)
    sweeps = read_sweeps(args.results)
    if not sweeps:
        raise SystemExit("fit_hung_sweep: no .../sweep/k benchmarks in " + ", ".join(args.results))
    for family, rows in sorted(sweeps.items()):
        fit, threshold = at_error(rows, args.error)
        line = (f"{family}: at {args.error:g} rad, fit {fit['ms']:.1f} ms "
                f"({fit['evaluations']:.0f} evaluations)")
        if threshold:
            k, ms, err, evaluations = threshold
            line += (f"; threshold 1e-{k / 4:g}: {ms:.1f} ms ({evaluations:.0f} evaluations, "
                     f"error {err:.2e} rad)")
        else:
            line += "; threshold: no accuracy of the sweep is tight enough"
        print(line)


if __name__ == "__main__":
    main()
