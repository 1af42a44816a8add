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

Statistics mode. Some authors published only statistics of the final errors (e.g.
lshade_cnepsin_D10_stats.csv: columns function,best,worst,median,mean,std, as the CEC 2017 MATLAB
script wrote them from 51 runs). When PUBLISHED_CSV has mean and std columns (detected from its
header) each function is judged by a two-sided Welch t-test on the means (n = 51 published runs,
or --published-runs) with the Student t distribution at the Welch-Satterthwaite degrees of freedom
(its CDF through the regularized incomplete beta function); the medians are shown side by side
but not tested. mhbench's errors are first rounded to the 8 significant digits the statistics
were printed with (as the runs mode rounds to 6). The t-test compares means, which the few far
outliers of heavy-tailed errors dominate: it is weaker than the rank-sum test of the runs mode, and
the output says so.

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
# Significant digits of a published statistics file (MATLAB's save -ascii, %.7e); mhbench's errors
# are rounded to as many before their statistics are taken, so that runs which all end at one
# optimum (a published std of 1e-13 around 100) do not differ by floating-point noise alone.
STATISTICS_DIGITS = 8


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


def read_published_stats(path):
    """{function: {column: value}} from a statistics file (best, worst, median, mean, std)."""
    stats = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            stats[int(row["function"])] = {k: clean(float(v)) for k, v in row.items() if k != "function"}
    return stats


def has_statistics_columns(path):
    with open(path, newline="") as f:
        header = next(csv.reader(f))
    return "mean" in header and "std" in header and "error" not in header


def regularized_incomplete_beta(x, a, b):
    """I_x(a, b) by Lentz's continued fraction (Numerical Recipes' betacf), for 0 <= x <= 1."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    if x > (a + 1.0) / (a + b + 2.0):
        return 1.0 - regularized_incomplete_beta(1.0 - x, b, a)
    log_front = math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log1p(-x)
    tiny = 1e-300
    c, d = 1.0, 1.0 - (a + b) * x / (a + 1.0)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    fraction = d
    for m in range(1, 1000):
        for numerator in (m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m)),
                          -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1))):
            d = 1.0 + numerator * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + numerator / c
            c = c if abs(c) > tiny else tiny
            fraction *= c * d
        if abs(c * d - 1.0) < 1e-15:
            break
    return math.exp(log_front) * fraction / a


def welch_test(mean_a, sd_a, n_a, mean_b, sd_b, n_b):
    """Two-sided Welch t-test from summary statistics: (p, degrees of freedom)."""
    va, vb = sd_a * sd_a / n_a, sd_b * sd_b / n_b
    if va + vb == 0.0:
        return (1.0 if mean_a == mean_b else 0.0), float("inf")
    t = (mean_a - mean_b) / math.sqrt(va + vb)
    df = (va + vb) ** 2 / ((va * va / (n_a - 1) if va else 0.0) + (vb * vb / (n_b - 1) if vb else 0.0))
    return regularized_incomplete_beta(df / (df + t * t), df / 2.0, 0.5), df


def verdict_of(p, alpha, ours_lower):
    if p >= alpha:
        return "equal"
    return "better" if ours_lower else "worse"


def print_totals(counts, alpha, compared):
    print(f"functions compared: {compared}; better {counts['better']}, equal {counts['equal']}, "
          f"worse {counts['worse']}; expected to differ by chance: {alpha:g} x {compared} = "
          f"{alpha * compared:.2f}")


def compare_statistics(args, suite, dim, ours, theirs):
    functions = sorted(f for f in set(ours) & set(theirs) if f not in EXCLUDED[suite])
    if not functions:
        sys.exit("no function in common")
    print(f"{TITLES[suite]}, D = {dim}: mhbench ({args.study_dir}) vs published statistics ({args.published_csv})")
    print(f"errors < {THRESHOLD:g} counted as 0; only statistics were published, so: two-sided Welch t-test on "
          f"the means (n = {args.published_runs} published runs), alpha = {args.alpha:g}.")
    print("Caution: a t-test on heavy-tailed errors is weaker than the rank-sum test of the runs mode (a few "
          "outliers dominate the means and standard deviations); the medians are shown, not tested.")
    print(f"{'F':>3} {'n':>7} {'mhbench mean':>13} {'published mean':>15} {'mhbench sd':>11} {'published sd':>13} "
          f"{'mhbench median':>15} {'published median':>17} {'p-value':>9}  verdict")
    counts = {"better": 0, "equal": 0, "worse": 0}
    differing = []
    for f in functions:
        a, b = ours[f], theirs[f]
        mean_a, sd_a = statistics.fmean(a), (statistics.stdev(a) if len(a) > 1 else 0.0)
        p, _ = welch_test(mean_a, sd_a, len(a), b["mean"], b["std"], args.published_runs)
        verdict = verdict_of(p, args.alpha, mean_a < b["mean"])
        if verdict != "equal":
            differing.append(f"F{f} {verdict}")
        counts[verdict] += 1
        print(f"{f:>3} {len(a):>3}/{args.published_runs:<3} {mean_a:>13.6g} {b['mean']:>15.6g} {sd_a:>11.4g} "
              f"{b['std']:>13.4g} {statistics.median(a):>15.6g} {b['median']:>17.6g} {p:>9.3g}  {verdict}")
    print_totals(counts, args.alpha, len(functions))
    if differing:
        print("differing: " + ", ".join(differing))


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
    parser.add_argument("--published-runs", type=int, default=51,
                        help="runs behind a statistics file's mean and std (statistics mode)")
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

    if has_statistics_columns(args.published_csv):
        ours = read_study(args.study_dir, suite, dim, args.algorithm, STATISTICS_DIGITS)
        compare_statistics(args, suite, dim, ours, read_published_stats(args.published_csv))
        return
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
        verdict = verdict_of(p, args.alpha, rank_difference < 0)
        counts[verdict] += 1
        print(f"{f:>3} {len(a):>3}/{len(b):<3} {statistics.median(a):>15.6g} {statistics.median(b):>17.6g} "
              f"{p:>9.3g}  {verdict}")
    print_totals(counts, args.alpha, len(functions))
    if missing:
        print(f"published but not in the study: {', '.join(map(str, missing))}")


if __name__ == "__main__":
    main()
