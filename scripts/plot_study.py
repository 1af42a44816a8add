#!/usr/bin/env python3
"""Draw the figures of an mhbench report from its curve-data CSVs (nothing else is read).

Usage: plot_study.py REPORT_DIR

Reads REPORT_DIR/curves_iteration.csv, curves_evaluations.csv, parameters_iteration.csv,
final_values.csv, target_hits.csv, critical_difference.csv, effects.csv, effect_means.csv and
relative_gap_medians.csv
(written by `mhbench report`) and writes PDF, PNG and SVG files to REPORT_DIR/figures/ (the SVG
files are inlined in the report's index.html). Algorithms are named by their labels (the `label`
column). A study with several budgets has one report folder per
budget, listed in REPORT_DIR/budgets.csv: each is drawn into its own figures/ folder, and every
title names its budget (budget.txt of the folder).
  convergence_iteration_<problem>   median best-so-far vs iteration, IQR band, log y (the paper's Fig. 5
                                    shows the mean; the quartiles stay meaningful on a log axis)
  convergence_evaluations_<problem> median best-so-far vs evaluations, IQR band, log-log
  parameter_<name>_<problem>        mean best-so-far parameter vs iteration, the true value as a
                                    line and the least-squares optimum dotted (the paper's Figs. 6-9)
  final_values_<problem>            box plots of the final values per algorithm
  ecdf_target_<problem>             fixed-target ECDF: fraction of runs that reached the study's
                                    target within a number of evaluations (when targets were set)
  ecdf_targets_<problem>            fixed-target ECDF over the targets f - f* = 1e2 ... 1e-8 (COCO's
                                    bbob targets): fraction of (run, target) pairs reached within a
                                    number of evaluations (problems with a known optimum)
  relative_gaps                     median relative gap (f - f*) / |f*| per problem (log y, problems in
                                    the study's order), one line per algorithm; the relative target
                                    dashed; medians at or below 4 eps (what doubles resolve of f*) drawn
                                    at 4 eps (a budget with a relative target and two or more problems
                                    with a known, non-zero f*)
  critical_difference               Friedman average ranks with the Nemenyi critical difference
                                    (Demsar 2006), bars joining algorithms that do not differ
  effects_overview_<design>         every main effect and interaction of a 2^k on/off design per
                                    problem as a bar (mean over blocks; negative = lower f = helps),
                                    hatched when not significant after Holm
  effects_main_<design>_<problem>   main-effects plot: mean response with each switch off and on
  effects_interaction_<design>_<problem>  interaction plot: mean response of A off/on, one line per
                                    level of B, for every pair of switches
Values a figure cannot show are left out and said so, on the figure and in a line on stdout: values
that are not finite (+inf is a legal final value: the worst; runs.csv writes "inf"), and values <= 0
on a log axis. A log axis is used only when every finite value is positive. A figure whose every
value was left out is still drawn, with a note saying why. A figure that fails anyway is reported
in one line on stderr ("figure NAME failed: reason") and the others are drawn; the exit status is
non-zero only when figures were due and none could be drawn.
Each figure is written under a temporary name (.NAME.EXT.tmp-PID) and renamed: a stop at any moment
leaves whole figures only, and a temporary file whose process is gone is removed by the next run.
Ctrl-C (SIGINT) or SIGTERM stops it quietly: one line on stderr, no traceback, exit status 130
(mhbench then says "figures interrupted"); it also stops when its parent process goes away, unless
started with nohup.
Needs matplotlib (Debian: apt install python3-matplotlib); uses the Agg backend, opens no window.
"""
import signal
import sys


class Interrupted(BaseException):
    """SIGINT or SIGTERM arrived, or the parent went away: stop drawing (not an Exception, so that no
    figure's `except Exception` takes it for a failed figure)."""


EXIT_INTERRUPTED = 130
STOP = []  # the signal that asked to stop, once one has


def on_stop(signum, _frame):
    # Later signals are ignored: the first one's clean-up (removing a temporary file) must not be cut.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    STOP.append(signum)
    raise Interrupted(signum)


# First of all, before the slow matplotlib import, so that a Ctrl-C at any moment ends quietly.
signal.signal(signal.SIGINT, on_stop)
signal.signal(signal.SIGTERM, on_stop)

import csv  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
import re  # noqa: E402
import warnings  # noqa: E402
from collections import OrderedDict  # noqa: E402

# mhbench, or the shell: when it is gone, nobody waits for these figures (unless started with nohup,
# which ignores SIGHUP precisely so that the work outlives the shell).
PARENT = None if signal.getsignal(signal.SIGHUP) == signal.SIG_IGN else os.getppid()
plt = None  # matplotlib.pyplot, imported by import_matplotlib()


def check_stop():
    """Raises Interrupted when a stop was asked for (a library that swallowed it) or the parent is gone."""
    if STOP or (PARENT is not None and os.getppid() != PARENT):
        raise Interrupted(STOP[0] if STOP else 0)


def import_matplotlib():
    global plt
    try:
        import matplotlib

        matplotlib.use("Agg")
        # SVG for the HTML report (index.html inlines them): text as text, not glyph outlines (files
        # several times smaller, and searchable), and ids from a fixed salt, so that the same figure
        # gives the same bytes.
        matplotlib.rcParams["svg.fonttype"] = "none"
        matplotlib.rcParams["svg.hashsalt"] = "mhbench"
        import matplotlib.pyplot as pyplot
    except Exception as error:  # noqa: BLE001 - any import failure means no figures, said in one line
        sys.stderr.write("cannot import matplotlib: %s: %s\n"
                         % (type(error).__name__, (str(error).strip().splitlines() or [""])[0]))
        sys.exit(1)
    plt = pyplot


# Notes and failures are said explicitly; library warnings (an empty legend, a NaN in a mean) would
# only repeat them as multi-line noise on stderr.
warnings.simplefilter("ignore")


def one_line(error):
    """An exception as one line: its type and the first line of its message."""
    text = str(error).strip().splitlines()
    return type(error).__name__ + (": " + text[0] if text else "")


class Figures:
    """What was drawn, what failed and what each figure left out, for the summary lines."""

    def __init__(self):
        self.drawn = 0
        self.failed = 0
        self.notes = []

    def attempt(self, name, draw, *args):
        """Draws one figure (or one group of figures); a failure is one line on stderr, not a traceback."""
        check_stop()
        try:
            draw(*args)
        except Exception as error:  # noqa: BLE001 - any failure of one figure must not stop the others
            self.failed += 1
            sys.stderr.write("figure %s failed: %s\n" % (name, one_line(error)))
            plt.close("all")

    def note(self, name, text):
        self.notes.append("figure %s: %s" % (name, text))


FIGURES = Figures()


def read_rows(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def slug(text):
    return re.sub(r"[^A-Za-z0-9]+", "_", text).strip("_")


def number(text):
    """A CSV field as a float: "" is NaN, "inf" is +inf."""
    return float(text) if text not in ("", None) else math.nan


def group(rows, *keys):
    """OrderedDict: tuple of key values -> list of rows, in file order."""
    out = OrderedDict()
    for row in rows:
        out.setdefault(tuple(row[k] for k in keys), []).append(row)
    return out


TEMPORARY = re.compile(r"^\..+\.tmp-([0-9]+)$")


def temporary_name(out_dir, file_name):
    return os.path.join(out_dir, ".%s.tmp-%d" % (file_name, os.getpid()))


def save(fig, out_dir, name):
    """Writes NAME.pdf, NAME.png and NAME.svg whole or not at all: under a temporary name, then renamed."""
    for ext in ("pdf", "png", "svg"):
        check_stop()
        final = os.path.join(out_dir, name + "." + ext)
        temporary = temporary_name(out_dir, name + "." + ext)
        # The SVG's <title> names the figure; no date, so that a figure redrawn is the same file.
        metadata = {"Title": name, "Date": None} if ext == "svg" else None
        try:
            fig.savefig(temporary, format=ext, dpi=150, bbox_inches="tight", metadata=metadata)
            os.replace(temporary, final)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
    plt.close(fig)
    FIGURES.drawn += 1


def remove_stale_temporaries(out_dir):
    """Removes the temporary figures of a run that was killed (SIGKILL leaves no time to clean up)."""
    for file_name in os.listdir(out_dir):
        match = TEMPORARY.match(file_name)
        if not match or int(match.group(1)) == os.getpid():
            continue
        try:
            os.kill(int(match.group(1)), 0)
            continue  # its process is still running (another report of the same folder)
        except ProcessLookupError:
            pass
        except OSError:
            continue
        try:
            os.remove(os.path.join(out_dir, file_name))
        except OSError:
            pass


def label_of(row):
    return row.get("label") or row["algorithm"]


class LeftOut:
    """Counts the values a figure could not show, by reason."""

    def __init__(self):
        self.counts = OrderedDict()

    def add(self, reason, n=1):
        if n:
            self.counts[reason] = self.counts.get(reason, 0) + n

    def reason_of(self, value, log):
        """The reason `value` cannot be shown (None when it can)."""
        if math.isnan(value):
            return "undefined (nan)"
        if math.isinf(value):
            return "at +inf" if value > 0 else "at -inf"
        if log and value <= 0:
            return "<= 0 on the log axis"
        return None

    def keep(self, value, log):
        reason = self.reason_of(value, log)
        if reason:
            self.add(reason)
        return reason is None

    def text(self):
        return ", ".join("%d %s" % (n, reason) for reason, n in self.counts.items())

    def total(self):
        return sum(self.counts.values())


def shows(value, log):
    return math.isfinite(value) and (not log or value > 0)


def finish_note(ax, name, left_out, anything_drawn, what="values"):
    """Writes on the figure (and in a stdout line) what it left out, or why it is empty."""
    lines = []
    if left_out.total():
        lines.append("left out: " + left_out.text())
        FIGURES.note(name, "left out " + left_out.text())
    if not anything_drawn:
        lines.append("nothing to draw: no finite %s" % what)
        ax.text(0.5, 0.5, "no finite %s to draw\n(%s)" % (what, left_out.text() or "no data"), ha="center",
                va="center", transform=ax.transAxes, fontsize="small")
        ax.set_xticks([])
        ax.set_yticks([])
    if lines and anything_drawn:
        ax.text(0.01, 0.01, "; ".join(lines), transform=ax.transAxes, fontsize="x-small", color="grey")


def log_axis_possible(values):
    """A log axis when every finite value is positive (and there is one)."""
    finite = [v for v in values if math.isfinite(v)]
    return bool(finite) and all(v > 0 for v in finite)


def convergence(rows, x_key, centre, low, high, band_label, log_x, title_x, name_prefix, out_dir, budget):
    for (problem,), problem_rows in group(rows, "problem").items():
        name = name_prefix + slug(problem)
        FIGURES.attempt(name, convergence_figure, problem, problem_rows, x_key, centre, low, high, band_label,
                        log_x, title_x, name, out_dir, budget)


def convergence_figure(problem, problem_rows, x_key, centre, low, high, band_label, log_x, title_x, name, out_dir,
                       budget):
    fig, ax = plt.subplots(figsize=(6, 4))
    log_y = log_axis_possible([number(row[centre]) for row in problem_rows])
    left_out = LeftOut()
    drawn = False
    for (algorithm,), r in group(problem_rows, "algorithm").items():
        x = [number(row[x_key]) for row in r]
        c = [number(row[centre]) for row in r]
        lo, hi = low(r), high(r)
        # NaN breaks the line where a value cannot be shown; a band point needs all three values.
        x_ok = [shows(v, log_x) for v in x]
        for v, ok in zip(x, x_ok):
            if not ok:
                left_out.add(left_out.reason_of(v, log_x))
        y = [v if ok and left_out.keep(v, log_y) else math.nan for v, ok in zip(c, x_ok)]
        band = [ok and shows(a, log_y) and shows(b, log_y) for ok, a, b in zip(x_ok, lo, hi)]
        xs = [v if ok else 1.0 for v, ok in zip(x, x_ok)]
        visible = any(math.isfinite(v) for v in y)
        label = label_of(r[0]) + ("" if visible else " (nothing finite to draw)")
        (line,) = ax.plot(xs if visible else [], y if visible else [], label=label)
        if any(band):
            ax.fill_between(xs, [a if k else 1.0 for a, k in zip(lo, band)], [b if k else 1.0 for b, k in zip(hi, band)],
                            where=band, alpha=0.2, color=line.get_color())
        drawn = drawn or visible
    if drawn and log_y:
        ax.set_yscale("log")
    if drawn and log_x:
        ax.set_xscale("log")
    ax.set_xlabel(title_x)
    ax.set_ylabel("best-so-far f (%s)" % band_label)
    ax.set_title(problem + budget)
    if drawn:
        ax.legend(fontsize="small")
    finish_note(ax, name, left_out, drawn)
    save(fig, out_dir, name)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_study.py REPORT_DIR")
    report = sys.argv[1]
    import_matplotlib()
    budgets = []
    FIGURES.attempt("budgets.csv", lambda: budgets.extend(read_rows(os.path.join(report, "budgets.csv"))))
    if budgets:
        for row in budgets:
            folder = os.path.join(report, row.get("directory") or "")
            FIGURES.attempt("(all of %s)" % folder, plot_report, folder)
    else:
        FIGURES.attempt("(all of %s)" % report, plot_report, report)
    for line in FIGURES.notes:
        print(line)
    if FIGURES.failed:
        print("figures: %d drawn, %d failed (each named on stderr)" % (FIGURES.drawn, FIGURES.failed))
    if FIGURES.failed and not FIGURES.drawn:
        sys.stderr.write("no figure could be drawn (%d failed)\n" % FIGURES.failed)
        sys.exit(1)


def read_budget(report):
    """ " [budget X]" for titles when the report folder is one budget's, else ""."""
    path = os.path.join(report, "budget.txt")
    if not os.path.exists(path):
        return ""
    with open(path) as f:
        text = f.read().strip()
    return " [budget %s]" % text if text else ""


def plot_report(report):
    out_dir = os.path.join(report, "figures")
    os.makedirs(out_dir, exist_ok=True)
    remove_stale_temporaries(out_dir)
    budget = read_budget(report)

    # Median and quartiles, not mean +/- std: order statistics are the same on a log axis, where a
    # std band would have to be clipped at zero and a single bad run drags the mean by decades.
    FIGURES.attempt("convergence_iteration_*", lambda: convergence(
        read_rows(os.path.join(report, "curves_iteration.csv")), "iteration", "median",
        lambda r: [number(x["q25"]) for x in r], lambda r: [number(x["q75"]) for x in r], "median, band: IQR", False,
        "iteration", "convergence_iteration_", out_dir, budget))
    FIGURES.attempt("convergence_evaluations_*", lambda: convergence(
        read_rows(os.path.join(report, "curves_evaluations.csv")), "evaluations", "median",
        lambda r: [number(x["q25"]) for x in r], lambda r: [number(x["q75"]) for x in r], "median, band: IQR", True,
        "evaluations", "convergence_evaluations_", out_dir, budget))
    FIGURES.attempt("parameter_*", parameter_figures, report, out_dir, budget)
    FIGURES.attempt("final_values_*", final_value_figures, report, out_dir, budget)
    FIGURES.attempt("ecdf_targets_*", target_ecdfs, report, out_dir, budget)
    FIGURES.attempt("relative_gaps", relative_gaps, report, out_dir, budget)
    FIGURES.attempt("critical_difference", critical_difference, report, out_dir, budget)
    FIGURES.attempt("effects_*", effects_figures, report, out_dir, budget)


def parameter_figures(report, out_dir, budget):
    parameters = read_rows(os.path.join(report, "parameters_iteration.csv"))
    for (problem, parameter), rows in group(parameters, "problem", "parameter").items():
        name = "parameter_%s_%s" % (slug(parameter), slug(problem))
        FIGURES.attempt(name, parameter_figure, problem, parameter, rows, name, out_dir, budget)


def parameter_figure(problem, parameter, rows, name, out_dir, budget):
    fig, ax = plt.subplots(figsize=(6, 4))
    truth, optimum = math.nan, math.nan
    left_out = LeftOut()
    drawn = False
    for (algorithm,), r in group(rows, "algorithm").items():
        x = [number(row["iteration"]) for row in r]
        m = [number(row["mean"]) for row in r]
        s = [number(row["std"]) for row in r]
        y = [v if math.isfinite(i) and left_out.keep(v, False) else math.nan for i, v in zip(x, m)]
        band = [math.isfinite(i) and math.isfinite(a) and math.isfinite(b) for i, a, b in zip(x, m, s)]
        xs = [i if math.isfinite(i) else 0.0 for i in x]
        (line,) = ax.plot(xs, y, label=label_of(r[0]))
        if any(band):
            ax.fill_between(xs, [a - b if k else 0.0 for a, b, k in zip(m, s, band)],
                            [a + b if k else 0.0 for a, b, k in zip(m, s, band)], where=band, alpha=0.15,
                            color=line.get_color())
        drawn = drawn or any(math.isfinite(v) for v in y)
        truth, optimum = number(r[0]["true"]), number(r[0]["opt"])
    if math.isfinite(truth):
        ax.axhline(truth, color="black", linestyle="--", linewidth=1, label="true value")
    if math.isfinite(optimum):
        ax.axhline(optimum, color="grey", linestyle=":", linewidth=1, label="least-squares optimum")
    ax.set_xlabel("iteration")
    ax.set_ylabel(parameter + " (best-so-far, mean +/- std)")
    ax.set_title(problem + budget)
    if drawn:
        ax.legend(fontsize="small")
    finish_note(ax, name, left_out, drawn)
    save(fig, out_dir, name)


def final_value_figures(report, out_dir, budget):
    finals = read_rows(os.path.join(report, "final_values.csv"))
    for (problem,), rows in group(finals, "problem").items():
        by_algorithm = group(rows, "algorithm")
        name = "final_values_" + slug(problem)
        FIGURES.attempt(name, box_plot, problem, by_algorithm, name, out_dir, budget)
        if not any(row["evals_to_target"] for row in rows):
            continue
        curves = [(label_of(r[0]), [number(row["evals_to_target"]) for row in r if row["evals_to_target"]], len(r))
                  for r in by_algorithm.values()]
        name = "ecdf_target_" + slug(problem)
        FIGURES.attempt(name, ecdf_figure, curves, "fraction of runs that reached the target",
                        problem + " (fixed-target ECDF)" + budget, name, out_dir)


def box_plot(problem, by_algorithm, name, out_dir, budget):
    fig, ax = plt.subplots(figsize=(6, 4))
    data = [[number(row["best_f"]) for row in r] for r in by_algorithm.values()]
    log_y = log_axis_possible([v for d in data for v in d])
    left_out = LeftOut()
    kept = [[v for v in d if left_out.keep(v, log_y)] for d in data]
    positions = [i + 1 for i, d in enumerate(kept) if d]
    if positions:
        ax.boxplot([d for d in kept if d], positions=positions)
    for i, (d, values) in enumerate(zip(kept, data)):
        if not d:  # a box that cannot be drawn says why where it would stand
            why = "all +inf" if values and all(v == math.inf for v in values) else "nothing finite"
            ax.text(i + 1, 0.5, why, ha="center", va="center", rotation=90, fontsize="x-small", color="grey",
                    transform=ax.get_xaxis_transform())
    ax.set_xticks(range(1, len(data) + 1))
    ax.set_xticklabels([label_of(r[0]) for r in by_algorithm.values()], rotation=20, fontsize="small")
    ax.set_xlim(0.5, len(data) + 0.5)
    if positions and log_y:
        ax.set_yscale("log")
    ax.set_ylabel("final best f")
    ax.set_title(problem + budget)
    finish_note(ax, name, left_out, bool(positions), "final values")
    save(fig, out_dir, name)


def ecdf_figure(curves, ylabel, title, name, out_dir):
    """curves: (label, evaluations at which a run / target was reached, number of trials)."""
    fig, ax = plt.subplots(figsize=(6, 4))
    left_out = LeftOut()
    curves = [(label, [e for e in reached if left_out.keep(e, True)], trials) for label, reached, trials in curves]
    right = 1.5 * max([1.0] + [e for _, reached, _ in curves for e in reached])
    for label, reached, trials in curves:
        reached = sorted(reached)
        y = [0.0] + [(i + 1) / trials for i in range(len(reached))] if trials else [0.0]
        ax.step([1.0] + reached + [right], y + [y[-1]], where="post", label=label)
    ax.set_xscale("log")
    ax.set_xlim(1, right)
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("evaluations")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize="small")
    finish_note(ax, name, left_out, True)
    save(fig, out_dir, name)


def target_ecdfs(report, out_dir, budget):
    hits = read_rows(os.path.join(report, "target_hits.csv"))
    for (problem,), rows in group(hits, "problem").items():
        curves = [(label_of(r[0]), [number(row["evaluations"]) for row in r if row["evaluations"]], len(r))
                  for r in group(rows, "algorithm").values()]
        name = "ecdf_targets_" + slug(problem)
        FIGURES.attempt(name, ecdf_figure, curves, "fraction of (run, target) pairs reached",
                        problem + ": targets f - f* = 1e2 ... 1e-8" + budget, name, out_dir)


# A relative gap below this is f* reached to what doubles resolve of it (the effects' floor, 4 eps |f*|,
# relative): on the log axis such medians, 0 and below 0 among them, are drawn at it.
GAP_FLOOR = 4 * sys.float_info.epsilon


def relative_target_of(budget):
    """R of "relative_target=R" in a " [budget ...]" title suffix; NaN without one."""
    match = re.search(r"relative_target=([^,\]]+)", budget)
    return number(match.group(1)) if match else math.nan


def relative_gaps(report, out_dir, budget):
    rows = read_rows(os.path.join(report, "relative_gap_medians.csv"))
    if not rows:
        return
    problems = list(OrderedDict.fromkeys(r["problem"] for r in rows))
    names = OrderedDict((r["problem"], r.get("name") or r["problem"]) for r in rows)
    fig, ax = plt.subplots(figsize=(max(6, 1.6 * len(problems) + 2), 4.4))
    left_out = LeftOut()
    floored = 0
    drawn = False
    for (algorithm,), r in group(rows, "algorithm").items():
        by_problem = {row["problem"]: number(row["median_relative_gap"]) for row in r}
        xs, ys = [], []
        for i, problem in enumerate(problems):
            gap = by_problem.get(problem, math.nan)
            if math.isnan(gap) or math.isinf(gap):
                left_out.add("without a successful run" if math.isnan(gap) else "at +inf")
                xs.append(i)
                ys.append(math.nan)  # breaks the line there
                continue
            if gap <= GAP_FLOOR:
                floored += 1
            xs.append(i)
            ys.append(max(gap, GAP_FLOOR))
        ax.plot(xs, ys, marker="o", label=label_of(r[0]))
        drawn = drawn or any(math.isfinite(y) for y in ys)
    target = relative_target_of(budget)
    if math.isfinite(target) and target > 0:
        ax.axhline(target, color="black", linestyle="--", linewidth=1, label="relative target %g" % target)
    if floored:
        ax.axhline(GAP_FLOOR, color="grey", linestyle=":", linewidth=1)
        FIGURES.note("relative_gaps", "%d median%s at or below 4 eps drawn at 4 eps"
                     % (floored, "" if floored == 1 else "s"))
        ax.set_xlabel("dotted: %d median%s at or below 4 eps (f* to double precision), drawn at 4 eps"
                      % (floored, "" if floored == 1 else "s"), fontsize="small", color="grey")
    if drawn:
        ax.set_yscale("log")
        ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_xticks(range(len(problems)))
    ax.set_xticklabels([names[p] for p in problems], rotation=15, fontsize="small")
    ax.set_xlim(-0.3, len(problems) - 0.7)
    ax.set_ylabel("median relative gap (f - f*) / |f*|")
    ax.set_title("Relative gap to f* per problem" + budget, fontsize="small")
    finish_note(ax, "relative_gaps", left_out, drawn, "medians")
    save(fig, out_dir, "relative_gaps")


def critical_difference(report, out_dir, budget):
    rows = read_rows(os.path.join(report, "critical_difference.csv"))
    if not rows:
        return
    left_out = LeftOut()
    ranked = sorted((number(r["average_rank"]), label_of(r)) for r in rows
                    if left_out.keep(number(r["average_rank"]), False))
    cd = number(rows[0]["cd"])
    k = len(rows)
    fig, ax = plt.subplots(figsize=(7, 1.2 + 0.3 * k))
    ax.set_xlim(0.5, k + 0.5)
    ax.set_ylim(-k - 1, 2)
    ax.axhline(0, color="black", linewidth=1)
    for r in range(1, k + 1):
        ax.plot([r, r], [0, 0.15], color="black", linewidth=1)
        ax.text(r, 0.3, str(r), ha="center", fontsize="small")
    if math.isfinite(cd):
        ax.plot([1, 1 + cd], [1.3, 1.3], color="black", linewidth=2)
        ax.text(1 + cd / 2, 1.5, "CD = %.3g (alpha %s, %s problems)" % (cd, rows[0]["alpha"], rows[0]["problems"]),
                ha="center", fontsize="small")
    for i, (rank, name) in enumerate(ranked):
        y = -(i + 1)
        ax.plot([rank, rank], [0, y], color="grey", linewidth=0.8)
        ax.text(rank + 0.05, y, "%s (%.2f)" % (name, rank), va="center", fontsize="small")
    # Bars under the axis join the maximal groups whose ranks lie within CD of each other.
    last_end, level = -1, 0
    for i in range(len(ranked) if math.isfinite(cd) else 0):
        j = i
        while j + 1 < len(ranked) and ranked[j + 1][0] - ranked[i][0] < cd:
            j += 1
        if j > i and j > last_end:
            level += 1
            ax.plot([ranked[i][0] - 0.05, ranked[j][0] + 0.05], [-0.25 * level, -0.25 * level], color="black",
                    linewidth=3)
            last_end = j
    ax.axis("off")
    if budget:
        ax.set_title(budget.strip(), fontsize="small")
    finish_note(ax, "critical_difference", left_out, bool(ranked), "average ranks")
    save(fig, out_dir, "critical_difference")


def finite(values):
    """The finite values and how many were left out."""
    kept = [v for v in values if math.isfinite(v)]
    return kept, len(values) - len(kept)


def left_out_note(ax, count, name=None):
    if count:
        ax.text(0.01, 0.01, "%d non-finite value%s left out" % (count, "" if count == 1 else "s"),
                transform=ax.transAxes, fontsize="x-small", color="grey")
        if name:
            FIGURES.note(name, "left out %d non-finite value%s" % (count, "" if count == 1 else "s"))


def short_reading(reading):
    if not reading:
        return "see effects table"
    if reading.startswith("no significant"):
        return "n.s."
    if reading.endswith(": helps"):
        return "helps"
    if reading.endswith(": hurts"):
        return "hurts"
    # "interaction -0.19: A helps more ..." -> "interaction -0.19 (significant)"
    return reading.split(":")[0] + " (significant)" if reading.startswith("interaction") else "inspect"


def effects_figures(report, out_dir, budget):
    """Main-effects, interaction and overview plots of each 2^k on/off design (effect_means.csv, effects.csv)."""
    means = read_rows(os.path.join(report, "effect_means.csv"))
    effects = read_rows(os.path.join(report, "effects.csv"))
    readings = {(r["Design"], r["Problem"], r["Effect"]): r["Reading"] for r in effects}
    for (design, problem), rows in group(means, "design", "problem").items():
        design_slug = slug(design.split(":")[0])
        name = "effects_main_%s_%s" % (design_slug, slug(problem))
        FIGURES.attempt(name, effects_main, design, problem, rows, readings, name, out_dir, budget)
        name = "effects_interaction_%s_%s" % (design_slug, slug(problem))
        FIGURES.attempt(name, effects_interaction, design, problem, rows, readings, name, out_dir, budget)
    for (design,), rows in group(effects, "Design").items():
        name = "effects_overview_" + slug(design.split(":")[0])
        FIGURES.attempt(name, effects_overview, design, rows, out_dir, budget)


def effects_title(design, problem, rows, budget):
    return "%s\n%s%s (%s blocks)" % (design, problem, budget, rows[0]["blocks"])


def effects_main(design, problem, rows, readings, name, out_dir, budget):
    scale = rows[0]["scale"]
    mains = [r for r in rows if not r["factor2"]]
    factors = list(OrderedDict.fromkeys(r["factor"] for r in mains))
    if not factors:
        return
    fig, axes = plt.subplots(1, len(factors), figsize=(2.6 * len(factors) + 1, 3.6), sharey=True, squeeze=False)
    for ax, factor in zip(axes[0], factors):
        points = [(r["level"], number(r["mean_response"])) for r in mains if r["factor"] == factor]
        kept, dropped = finite([v for _, v in points])
        xs = [0 if level == "off" else 1 for level, v in points if math.isfinite(v)]
        ax.plot(xs, kept, marker="o")
        ax.set_xticks([0, 1])
        ax.set_xticklabels(["off", "on"])
        ax.set_xlim(-0.3, 1.3)
        ax.set_title("%s\n%s" % (factor, short_reading(readings.get((design, problem, factor), ""))),
                     fontsize="small")
        left_out_note(ax, dropped, name)
    axes[0][0].set_ylabel("mean " + scale)
    fig.suptitle(effects_title(design, problem, rows, budget), fontsize="small", y=1.1)
    save(fig, out_dir, name)


def effects_interaction(design, problem, rows, readings, name, out_dir, budget):
    scale = rows[0]["scale"]
    pairs = list(OrderedDict.fromkeys((r["factor"], r["factor2"]) for r in rows if r["factor2"]))
    if not pairs:
        return
    fig, axes = plt.subplots(1, len(pairs), figsize=(2.8 * len(pairs) + 1, 3.6), sharey=True, squeeze=False)
    for ax, (a, b) in zip(axes[0], pairs):
        dropped_total = 0
        for level_b, style in (("off", "--"), ("on", "-")):
            points = [(r["level"], number(r["mean_response"])) for r in rows
                      if r["factor"] == a and r["factor2"] == b and r["level2"] == level_b]
            kept, dropped = finite([v for _, v in points])
            dropped_total += dropped
            xs = [0 if level == "off" else 1 for level, v in points if math.isfinite(v)]
            ax.plot(xs, kept, marker="o", linestyle=style, label="%s %s" % (b, level_b))
        ax.set_xticks([0, 1])
        ax.set_xticklabels([a + " off", a + " on"])
        ax.set_xlim(-0.3, 1.3)
        effect = "%s x %s" % (a, b)
        ax.set_title("%s\n%s" % (effect, short_reading(readings.get((design, problem, effect), ""))),
                     fontsize="small")
        ax.legend(fontsize="x-small")
        left_out_note(ax, dropped_total, name)
    axes[0][0].set_ylabel("mean " + scale)
    fig.suptitle(effects_title(design, problem, rows, budget), fontsize="small", y=1.1)
    save(fig, out_dir, name)


def effects_overview(design, rows, out_dir, budget):
    name = "effects_overview_" + slug(design.split(":")[0])
    names = list(OrderedDict.fromkeys(r["Effect"] for r in rows))
    problems = list(OrderedDict.fromkeys(r["Problem"] for r in rows))
    fig, ax = plt.subplots(figsize=(7, 1.0 + 0.35 * len(names) * len(problems)))
    height = 0.8 / max(1, len(problems))
    dropped = 0
    for p, problem in enumerate(problems):
        by_effect = {r["Effect"]: r for r in rows if r["Problem"] == problem}
        ys, values, hatches = [], [], []
        for i, effect in enumerate(names):
            row = by_effect.get(effect)
            value = number(row["Mean"]) if row else math.nan
            if not math.isfinite(value):
                dropped += 1 if row else 0
                continue
            ys.append(i + p * height)
            values.append(value)
            hatches.append("" if short_reading(row["Reading"]) != "n.s." else "//")
        bars = ax.barh(ys, values, height=height, label=problem)
        for bar, hatch in zip(bars, hatches):
            bar.set_hatch(hatch)
            if hatch:
                bar.set_alpha(0.45)
    ax.axvline(0, color="black", linewidth=0.8)
    ax.set_yticks([i + 0.4 - height / 2 for i in range(len(names))])
    ax.set_yticklabels(names, fontsize="small")
    ax.invert_yaxis()
    scales = sorted(set(r["Scale"] for r in rows))
    ax.set_xlabel("mean effect on %s (negative: lower f, helps; hatched: not significant, Holm)" % " / ".join(scales),
                  fontsize="small")
    ax.set_title(design + budget, fontsize="small")
    ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    left_out_note(ax, dropped, name)
    save(fig, out_dir, name)


if __name__ == "__main__":
    try:
        main()
    except (Interrupted, KeyboardInterrupt):
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        sys.stderr.write("figures interrupted: %d drawn\n" % FIGURES.drawn)
        sys.exit(EXIT_INTERRUPTED)
