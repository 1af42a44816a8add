#!/usr/bin/env python3
"""Draw the figures of an mhbench report from its curve-data CSVs (nothing else is read).

Usage: plot_study.py REPORT_DIR

Reads REPORT_DIR/curves_iteration.csv, curves_evaluations.csv, parameters_iteration.csv,
final_values.csv, target_hits.csv and critical_difference.csv (written by `mhbench report`) and writes PDF and PNG files to REPORT_DIR/figures/:
  convergence_iteration_<problem>   mean best-so-far vs iteration, std band, log y (the paper's Fig. 5)
  convergence_evaluations_<problem> median best-so-far vs evaluations, IQR band, log-log
  parameter_<name>_<problem>        mean best-so-far parameter vs iteration, the true value as a
                                    line and the least-squares optimum dotted (the paper's Figs. 6-9)
  final_values_<problem>            box plots of the final values per algorithm
  ecdf_target_<problem>             fixed-target ECDF: fraction of runs that reached the study's
                                    target within a number of evaluations (when targets were set)
  ecdf_targets_<problem>            fixed-target ECDF over the targets f - f* = 1e2 ... 1e-8 (COCO's
                                    bbob targets): fraction of (run, target) pairs reached within a
                                    number of evaluations (problems with a known optimum)
  critical_difference               Friedman average ranks with the Nemenyi critical difference
                                    (Demsar 2006), bars joining algorithms that do not differ
Needs matplotlib (Debian: apt install python3-matplotlib); uses the Agg backend, opens no window.
"""
import csv
import math
import os
import re
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def slug(text):
    return re.sub(r"[^A-Za-z0-9]+", "_", text).strip("_")


def number(text):
    return float(text) if text not in ("", None) else math.nan


def group(rows, *keys):
    """OrderedDict: tuple of key values -> list of rows, in file order."""
    out = OrderedDict()
    for row in rows:
        out.setdefault(tuple(row[k] for k in keys), []).append(row)
    return out


def save(fig, out_dir, name):
    for ext in ("pdf", "png"):
        fig.savefig(os.path.join(out_dir, name + "." + ext), dpi=150, bbox_inches="tight")
    plt.close(fig)


def positive(values):
    return all(v > 0 for v in values if not math.isnan(v))


def convergence(rows, x_key, centre, low, high, band_label, log_x, title_x, name_prefix, out_dir):
    for (problem,), problem_rows in group(rows, "problem").items():
        fig, ax = plt.subplots(figsize=(6, 4))
        all_values = []
        for (algorithm,), r in group(problem_rows, "algorithm").items():
            x = [number(row[x_key]) for row in r]
            c = [number(row[centre]) for row in r]
            lo, hi = low(r), high(r)
            all_values += c
            ax.plot(x, c, label=algorithm)
            ax.fill_between(x, lo, hi, alpha=0.2)
        if positive(all_values):
            ax.set_yscale("log")
        if log_x:
            ax.set_xscale("log")
        ax.set_xlabel(title_x)
        ax.set_ylabel("best-so-far f (%s)" % band_label)
        ax.set_title(problem)
        ax.legend(fontsize="small")
        save(fig, out_dir, name_prefix + slug(problem))


def mean_std_band(rows, sign):
    values = []
    for row in rows:
        m, s = number(row["mean"]), number(row["std"])
        v = m + sign * s
        # On a log axis a band below zero cannot be drawn: keep it at the mean's scale.
        values.append(v if v > 0 or m <= 0 else m * 1e-3)
    return values


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_study.py REPORT_DIR")
    report = sys.argv[1]
    out_dir = os.path.join(report, "figures")
    os.makedirs(out_dir, exist_ok=True)

    convergence(read_rows(os.path.join(report, "curves_iteration.csv")), "iteration", "mean",
                lambda r: mean_std_band(r, -1), lambda r: mean_std_band(r, +1), "mean, band: +/- std",
                False, "iteration", "convergence_iteration_", out_dir)
    convergence(read_rows(os.path.join(report, "curves_evaluations.csv")), "evaluations", "median",
                lambda r: [number(x["q25"]) for x in r], lambda r: [number(x["q75"]) for x in r],
                "median, band: IQR", True, "evaluations", "convergence_evaluations_", out_dir)

    parameters = read_rows(os.path.join(report, "parameters_iteration.csv"))
    for (problem, parameter), rows in group(parameters, "problem", "parameter").items():
        fig, ax = plt.subplots(figsize=(6, 4))
        truth, optimum = math.nan, math.nan
        for (algorithm,), r in group(rows, "algorithm").items():
            x = [number(row["iteration"]) for row in r]
            m = [number(row["mean"]) for row in r]
            s = [number(row["std"]) for row in r]
            ax.plot(x, m, label=algorithm)
            ax.fill_between(x, [a - b for a, b in zip(m, s)], [a + b for a, b in zip(m, s)], alpha=0.15)
            truth, optimum = number(r[0]["true"]), number(r[0]["opt"])
        if not math.isnan(truth):
            ax.axhline(truth, color="black", linestyle="--", linewidth=1, label="true value")
        if not math.isnan(optimum):
            ax.axhline(optimum, color="grey", linestyle=":", linewidth=1, label="least-squares optimum")
        ax.set_xlabel("iteration")
        ax.set_ylabel(parameter + " (best-so-far, mean +/- std)")
        ax.set_title(problem)
        ax.legend(fontsize="small")
        save(fig, out_dir, "parameter_%s_%s" % (slug(parameter), slug(problem)))

    finals = read_rows(os.path.join(report, "final_values.csv"))
    for (problem,), rows in group(finals, "problem").items():
        by_algorithm = group(rows, "algorithm")
        fig, ax = plt.subplots(figsize=(6, 4))
        data = [[number(row["best_f"]) for row in r] for r in by_algorithm.values()]
        ax.boxplot(data)
        ax.set_xticks(range(1, len(data) + 1))
        ax.set_xticklabels([a for (a,) in by_algorithm.keys()], rotation=20, fontsize="small")
        if positive([v for d in data for v in d]):
            ax.set_yscale("log")
        ax.set_ylabel("final best f")
        ax.set_title(problem)
        save(fig, out_dir, "final_values_" + slug(problem))

        if not any(row["evals_to_target"] for row in rows):
            continue
        curves = [(algorithm, [number(row["evals_to_target"]) for row in r if row["evals_to_target"]], len(r))
                  for (algorithm,), r in by_algorithm.items()]
        ecdf_figure(curves, "fraction of runs that reached the target", problem + " (fixed-target ECDF)",
                    "ecdf_target_" + slug(problem), out_dir)

    target_ecdfs(report, out_dir)
    critical_difference(report, out_dir)


def ecdf_figure(curves, ylabel, title, name, out_dir):
    """curves: (label, evaluations at which a run / target was reached, number of trials)."""
    fig, ax = plt.subplots(figsize=(6, 4))
    right = 1.5 * max([1.0] + [e for _, reached, _ in curves for e in reached])
    for label, reached, trials in curves:
        reached = sorted(reached)
        y = [0.0] + [(i + 1) / trials for i in range(len(reached))]
        ax.step([1.0] + reached + [right], y + [y[-1]], where="post", label=label)
    ax.set_xscale("log")
    ax.set_xlim(1, right)
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("evaluations")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize="small")
    save(fig, out_dir, name)


def target_ecdfs(report, out_dir):
    hits = read_rows(os.path.join(report, "target_hits.csv"))
    for (problem,), rows in group(hits, "problem").items():
        curves = [(algorithm, [number(row["evaluations"]) for row in r if row["evaluations"]], len(r))
                  for (algorithm,), r in group(rows, "algorithm").items()]
        ecdf_figure(curves, "fraction of (run, target) pairs reached", problem + ": targets f - f* = 1e2 ... 1e-8",
                    "ecdf_targets_" + slug(problem), out_dir)


def critical_difference(report, out_dir):
    rows = read_rows(os.path.join(report, "critical_difference.csv"))
    if not rows:
        return
    ranked = sorted(((number(r["average_rank"]), r["algorithm"]) for r in rows))
    cd = number(rows[0]["cd"])
    k = len(ranked)
    fig, ax = plt.subplots(figsize=(7, 1.2 + 0.3 * k))
    ax.set_xlim(0.5, k + 0.5)
    ax.set_ylim(-k - 1, 2)
    ax.axhline(0, color="black", linewidth=1)
    for r in range(1, k + 1):
        ax.plot([r, r], [0, 0.15], color="black", linewidth=1)
        ax.text(r, 0.3, str(r), ha="center", fontsize="small")
    ax.plot([1, 1 + cd], [1.3, 1.3], color="black", linewidth=2)
    ax.text(1 + cd / 2, 1.5, "CD = %.3g (alpha %s, %s problems)" % (cd, rows[0]["alpha"], rows[0]["problems"]),
            ha="center", fontsize="small")
    for i, (rank, name) in enumerate(ranked):
        y = -(i + 1)
        ax.plot([rank, rank], [0, y], color="grey", linewidth=0.8)
        ax.text(rank + 0.05, y, "%s (%.2f)" % (name, rank), va="center", fontsize="small")
    # Bars under the axis join the maximal groups whose ranks lie within CD of each other.
    last_end, level = -1, 0
    for i in range(k):
        j = i
        while j + 1 < k and ranked[j + 1][0] - ranked[i][0] < cd:
            j += 1
        if j > i and j > last_end:
            level += 1
            ax.plot([ranked[i][0] - 0.05, ranked[j][0] + 0.05], [-0.25 * level, -0.25 * level], color="black",
                    linewidth=3)
            last_end = j
    ax.axis("off")
    save(fig, out_dir, "critical_difference")


if __name__ == "__main__":
    main()
