#!/usr/bin/env python3
"""The anytime tables recomputed from the study's own files, independently of the C++ code.

Usage: anytime_check.py MHBENCH

Runs a small study (two optimisers, two problems with f* = 0, 6 runs, 3000 evaluations), then
reads runs.csv and improvements.csv with the csv module and recomputes
  - ecdf_area.csv: the area under the ECDF of (run, target) pairs, targets f - f* <= 1e2 ... 1e-8,
    over log10 evaluations from 1 to B = 3000, divided by log10 B; pooled: the mean of the problems';
  - ert.csv: COCO's ERT per target exactly, and its 10% / 90% columns against our own simulated
    restarts (Python's random, 20000 draws): each of the report's percentiles (1000 draws there)
    must lie between this sample's 6th and 14th (10%) or 86th and 94th (90%) percentiles, about
    four standard errors of a percentile of 1000 draws.
Standard library only. Exit 0 when everything agrees; one line per disagreement otherwise.
"""
import csv
import math
import random
import subprocess
import sys
import tempfile
from pathlib import Path

GAPS = [10.0 ** k for k in range(2, -9, -1)]
BUDGET = 3000


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def first_hits(study):
    """(problem, algorithm) -> list per run of (evaluations spent, {gap: first evaluation or None})."""
    improvements = {}
    for row in read(study / "improvements.csv"):
        if row["event"] == "improvement":
            improvements.setdefault(row["run_id"], []).append((int(row["evaluations"]), float(row["f"])))
    groups = {}
    for run in read(study / "runs.csv"):
        if run["status"] != "ok":
            continue
        f_opt = float(run["f_opt"])
        hits = {}
        for gap in GAPS:
            hits[gap] = next((e for e, f in improvements[run["run_id"]] if f - f_opt <= gap), None)
        groups.setdefault((run["problem"], run["algorithm"]), []).append((int(run["evaluations"]), hits))
    return groups


def area(runs):
    log_b = math.log10(BUDGET)
    pairs = [hits[g] for _, hits in runs for g in GAPS]
    return sum((log_b - math.log10(h)) / log_b for h in pairs if h is not None and h <= BUDGET) / len(pairs)


def prctile(sorted_x, p):
    """cocopp's prctile."""
    n = len(sorted_x)
    i = p / 100.0 * n - 0.5
    if i <= 0:
        return sorted_x[0]
    if i >= n - 1:
        return sorted_x[-1]
    lo, hi = math.floor(i), math.ceil(i)
    return sorted_x[lo] if lo == hi else (hi - i) * sorted_x[lo] + (i - lo) * sorted_x[hi]


def restarts(hits, rng, samples=20000):
    lengths = []
    for _ in range(samples):
        total = 0
        while True:
            success, evaluations = hits[rng.randrange(len(hits))]
            total += evaluations
            if success:
                break
        lengths.append(total)
    return sorted(lengths)


def main():
    mhbench = sys.argv[1]
    errors = []
    with tempfile.TemporaryDirectory() as tmp:
        study = Path(tmp) / "study"
        subprocess.run([mhbench, "run", "--algorithms", "random-search", "pso:np=10", "--problems", "sphere:dim=2",
                        "rastrigin:dim=2", "--runs", "6", "--evaluations", str(BUDGET), "--no-figures", "--quiet",
                        "--out", str(study)], check=True, stdout=subprocess.DEVNULL)
        groups = first_hits(study)
        report = study / "report"
        labels = {r["algorithm"]: r["label"] for r in read(study / "algorithms.csv")}

        areas = {}
        for row in read(report / "ecdf_area.csv"):
            areas[(row["Problem"], row["Algorithm"])] = float(row["AUC"])
        pooled = {}
        for (problem, algorithm), runs in groups.items():
            label = labels.get(algorithm, algorithm)
            expected = area(runs)
            pooled.setdefault(label, []).append(expected)
            got = areas.get((problem, label))
            if got is None or abs(got - expected) > 1e-12:
                errors.append("ecdf_area %s %s: %s, recomputed %r" % (problem, label, got, expected))
        for label, values in pooled.items():
            got = areas.get(("all 2 problems", label))
            expected = sum(values) / len(values)
            if got is None or abs(got - expected) > 1e-12:
                errors.append("ecdf_area pooled %s: %s, recomputed %r" % (label, got, expected))

        rng = random.Random(38)
        checked = 0
        for row in read(report / "ert.csv"):
            algorithm = next(a for a in (k[1] for k in groups) if labels.get(a, a) == row["Algorithm"])
            gap = float(row["Target f - f*"])
            hits = [(h[gap] is not None, h[gap] if h[gap] is not None else spent)
                    for spent, h in groups[(row["Problem"], algorithm)]]
            successes = sum(1 for s, _ in hits if s)
            if row["Successes"] != "%d/%d" % (successes, len(hits)):
                errors.append("ert %s %s %g: successes %s, recomputed %d" % (row["Problem"], row["Algorithm"], gap,
                                                                              row["Successes"], successes))
            if successes == 0:
                if row["ERT"] != "inf" or row["ERT 10%"] or row["ERT 90%"]:
                    errors.append("ert %s %s %g: no success, yet %s" % (row["Problem"], row["Algorithm"], gap, row))
                continue
            ert = sum(e for _, e in hits) / successes
            if abs(float(row["ERT"]) - ert) > 1e-9 * ert:
                errors.append("ert %s %s %g: ERT %s, recomputed %r" % (row["Problem"], row["Algorithm"], gap,
                                                                        row["ERT"], ert))
            lengths = restarts(hits, rng)
            for column, low, high in (("ERT 10%", 6, 14), ("ERT 90%", 86, 94)):
                value = float(row[column])
                if not prctile(lengths, low) <= value <= prctile(lengths, high):
                    errors.append("ert %s %s %g: %s = %s outside [%g, %g]" % (
                        row["Problem"], row["Algorithm"], gap, column, value, prctile(lengths, low),
                        prctile(lengths, high)))
            checked += 1
        if checked < 10:
            errors.append("only %d ERT rows with a success to check" % checked)
    for e in errors:
        print(e)
    print("anytime_check: %d disagreements" % len(errors))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
