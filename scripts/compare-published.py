#!/usr/bin/env python3
"""Compare an mhbench study's final CEC 2017 or CEC 2022 errors with an algorithm's published runs.

    python3 scripts/compare-published.py STUDY_DIR PUBLISHED_CSV [--algorithm LABEL] [--alpha 0.05]

STUDY_DIR is an mhbench study directory (its runs.csv: one row per run, with algorithm, problem
such as `cec2017:f=5,dim=10`, and error = best_f - f_opt). PUBLISHED_CSV has the columns
function,run,error (tests/data/published/cec2017/ or cec2022/, e.g. jso_D10.csv: the error after
MaxFES evaluations in the authors' result files). The suite is the published file's folder
(cec2017 or cec2022, or --suite) and the dimension its name's `_D<dim>` (or --dim). Errors below
1e-8 count as 0 on both sides; for CEC 2017 F2 is left out (the organisers excluded it), for CEC 2022
nothing is. The published files print errors with 6
significant digits (the C++ stream default the authors' code wrote them with), so mhbench's errors
are rounded to as many digits (--digits) before they are compared: many runs of the hybrid and
composition functions end at the same local optimum, and unrounded values would turn the
published ties into spurious rank differences.

Per function: the two medians, the p-value of a two-sided Wilcoxon rank-sum (Mann-Whitney) test
and a verdict at level alpha: "better" or "worse" (mhbench's errors are significantly lower or
higher, judged by the mean ranks), else "equal". The test uses the normal approximation with a
correction for ties and no continuity correction, which is accurate enough for n = 51 (or 30) per side
(exact tables are for small samples). Where both samples are all equal (e.g. all 0) the p-value
is 1. Totals follow, with the number of functions expected to differ by chance alone if the two
implementations were the same: alpha x functions compared.

Standard library only.
"""

import argparse
import csv
import math
import os
import re
import statistics
import sys

THRESHOLD = 1e-8
EXCLUDED = {"cec2017": {2}, "cec2022": set()}
TITLES = {"cec2017": "CEC 2017", "cec2022": "CEC 2022"}


def clean(error, digits=None):
    if digits:
        error = float(f"{error:.{digits}g}")
    return 0.0 if error < THRESHOLD else error


def rank_sum_test(a, b):
    """Two-sided Wilcoxon rank-sum test, normal approximation with tie correction.

    Returns (p, mean rank of a - mean rank of b)."""
    n1, n2 = len(a), len(b)
    pooled = sorted([(v, 0) for v in a] + [(v, 1) for v in b])
    n = n1 + n2
    ranks = [0.0] * n
    tie_term = 0.0
    i = 0
    while i < n:
        j = i
        while j + 1 < n and pooled[j + 1][0] == pooled[i][0]:
            j += 1
        average = (i + j) / 2.0 + 1.0
        for k in range(i, j + 1):
            ranks[k] = average
        t = j - i + 1
        tie_term += t ** 3 - t
        i = j + 1
    r1 = sum(r for r, (_, side) in zip(ranks, pooled) if side == 0)
    u1 = r1 - n1 * (n1 + 1) / 2.0
    mean_u = n1 * n2 / 2.0
    var_u = n1 * n2 / 12.0 * ((n + 1) - tie_term / (n * (n - 1)))
    mean_rank_a = r1 / n1
    mean_rank_b = (n * (n + 1) / 2.0 - r1) / n2
    if var_u <= 0.0:
        return 1.0, 0.0
    z = (u1 - mean_u) / math.sqrt(var_u)
    p = math.erfc(abs(z) / math.sqrt(2.0))
    return min(1.0, p), mean_rank_a - mean_rank_b


def read_study(study_dir, suite, dim, algorithm, digits):
    path = os.path.join(study_dir, "runs.csv")
    errors = {}
    labels = set()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            m = re.match(suite + r":(.*)$", row["problem"])
            if not m:
                continue
            params = dict(kv.split("=", 1) for kv in m.group(1).split(",") if "=" in kv)
            if int(params.get("dim", "-1")) != dim:
                continue
            labels.add(row["algorithm"])
            if algorithm is not None and row["algorithm"] != algorithm:
                continue
            if row["status"] != "ok" or row["error"] == "":
                sys.exit(f"{path}: run {row['run_id']} ({row['problem']}) has no error ({row['status']})")
            errors.setdefault(int(params["f"]), []).append(clean(float(row["error"]), digits))
    if algorithm is None and len(labels) > 1:
        sys.exit(f"{path}: several algorithms ({', '.join(sorted(labels))}); choose one with --algorithm")
    return errors


def read_published(path):
    errors = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            errors.setdefault(int(row["function"]), []).append(clean(float(row["error"])))
    return errors


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("study_dir")
    parser.add_argument("published_csv")
    parser.add_argument("--algorithm", help="the study's algorithm label (needed if it has several)")
    parser.add_argument("--dim", type=int, help="dimension (default: _D<dim> in the published file's name)")
    parser.add_argument("--suite", choices=sorted(TITLES),
                        help="benchmark suite (default: the published file's folder, cec2017 or cec2022)")
    parser.add_argument("--alpha", type=float, default=0.05)
    parser.add_argument("--digits", type=int, default=6,
                        help="significant digits mhbench's errors are rounded to, as published (0: none)")
    args = parser.parse_args()

    dim = args.dim
    if dim is None:
        m = re.search(r"_D(\d+)", os.path.basename(args.published_csv))
        if not m:
            sys.exit("no _D<dim> in the published file's name; give --dim")
        dim = int(m.group(1))

    suite = args.suite
    if suite is None:
        suite = os.path.basename(os.path.dirname(os.path.abspath(args.published_csv)))
        if suite not in TITLES:
            sys.exit("the published file is not in a cec2017/ or cec2022/ folder; give --suite")
    excluded = EXCLUDED[suite]

    ours = read_study(args.study_dir, suite, dim, args.algorithm, args.digits)
    theirs = read_published(args.published_csv)
    functions = sorted(f for f in set(ours) & set(theirs) if f not in excluded)
    missing = sorted(f for f in set(theirs) - set(ours) if f not in excluded)
    if not functions:
        sys.exit("no function in common")

    print(f"{TITLES[suite]}, D = {dim}: mhbench ({args.study_dir}) vs published ({args.published_csv})")
    print(f"errors < {THRESHOLD:g} counted as 0; two-sided Wilcoxon rank-sum, normal approximation with "
          f"tie correction, alpha = {args.alpha:g}; mhbench's errors rounded to "
          f"{args.digits or 'all'} significant digits as published")
    print(f"{'F':>3} {'n':>7} {'mhbench median':>15} {'published median':>17} {'p-value':>9}  verdict")
    counts = {"better": 0, "equal": 0, "worse": 0}
    for f in functions:
        a, b = ours[f], theirs[f]
        p, rank_difference = rank_sum_test(a, b)
        verdict = "equal"
        if p < args.alpha:
            verdict = "better" if rank_difference < 0 else "worse"
        counts[verdict] += 1
        print(f"{f:>3} {len(a):>3}/{len(b):<3} {statistics.median(a):>15.6g} {statistics.median(b):>17.6g} "
              f"{p:>9.3g}  {verdict}")
    compared = len(functions)
    print(f"functions compared: {compared}; better {counts['better']}, equal {counts['equal']}, "
          f"worse {counts['worse']}; expected to differ by chance: {args.alpha:g} x {compared} = "
          f"{args.alpha * compared:.2f}")
    if missing:
        print(f"published but not in the study: {', '.join(map(str, missing))}")


if __name__ == "__main__":
    main()
