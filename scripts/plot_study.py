#!/usr/bin/env python3
"""Draw the figures of an mhbench report from its curve-data CSVs (nothing else is read).

Usage: plot_study.py REPORT_DIR            draw every figure
       plot_study.py --plan REPORT_DIR     print "KIND COUNT" per figure kind, draw nothing

Reads REPORT_DIR/algorithms.csv, problems.csv, budget.txt, curves_iteration.csv,
curves_evaluations.csv, parameters_iteration.csv, final_values.csv, target_hits.csv,
critical_difference.csv, effects.csv, effect_means.csv, relative_gap_medians.csv, final_points.csv,
structural_bias.csv, bayesian_probabilities.csv, bayesian_samples.csv and overhead.csv (written by
`mhbench report`) and writes NAME.pdf (vector, fonts embedded as TrueType, for a paper) and NAME.png
(for the HTML page) to REPORT_DIR/figures/, with styles.csv (algorithm,label,colour,marker,linestyle:
each algorithm's style, a function of its place in algorithms.csv, the same in every figure). A study
with several budgets has one report folder per budget, listed in REPORT_DIR/budgets.csv: each is
drawn into its own figures/ folder, and every title names its budget.

Where a problem's optimum f* is known (problems.csv), values are drawn as the gap f - f* on a log
axis, the axis label says "f - f*"; elsewhere as f. Gaps at or below the floor (4 eps |f*|, what
doubles resolve of f*; for f* = 0 a tenth of the smallest positive gap) -- 0 among them -- are drawn
at the floor, a dotted line that says so. Figures of a kind drawn per problem are one figure with a
panel per problem (<kind>_all) for two to six problems (MOST_PANELS), else one figure per problem
(<kind>_<problem>).
  convergence_evaluations_<problem>  median best-so-far vs evaluations, IQR band (log-log)
  convergence_iteration_<problem>    the same vs iteration, only at budgets that count iterations
                                     (iterations of different algorithms are not comparable at an
                                     evaluation budget)
  parameters_<problem>               mean best-so-far of each identified parameter (one panel each,
                                     in its unit), the true value dashed and the least-squares
                                     optimum dotted; vs iteration, or vs mean evaluations at
                                     evaluation budgets (the paper's Figs. 6-9); always per problem
  final_values_<problem>             box plots of the final values, one colour per algorithm
  ecdf_target_<problem>|_all         fraction of runs that reached the study's target (when set),
                                     the problems pooled
  ecdf_targets_all                   fixed-target ECDF over f - f* = 1e2 ... 1e-8 (COCO's targets),
                                     the problems pooled as COCO does; none for one problem, whose
                                     convergence figure shows the same runs
  relative_gaps                      median relative gap per problem, one line per algorithm (a
                                     budget with a relative target and two or more such problems)
  overhead                           median wall time per evaluation vs dimension (log-log), one line
                                     per algorithm (overhead.csv, when an algorithm ran at 3+ dimensions)
  critical_difference                Friedman average ranks with the Nemenyi critical difference
  effects_overview_<design>          every effect of a 2^k design per problem as a bar, hatched when
                                     not significant after Holm
  effects_main_<design>              mean response with each switch off and on, one line per problem
  effects_interaction_<design>       A off/on, one line per level of B, for every pair of switches,
                                     pooled over the problems (or the design's only problem)
  structural_bias_<problem>          f0's final best points as per-dimension histograms (density
                                     relative to uniform), a panel per algorithm titled with its
                                     verdict (final_points.csv and the structural_bias table)
  bayesian_simplex_<problem>         the Bayesian signed-rank test's posterior samples of theta in
                                     the simplex (Benavoli et al. 2017), a panel per algorithm
                                     against the reference; of the test on all problems' medians
                                     when there is one, else of each problem's
Sizes: one column (3.5 in) for a single panel, two columns (7.16 in) for several; 8-9 pt serif
(STIX, Times-like); PNG at 140 dpi (scripts/figure_style.py, shared with plot_flux_map.py). Figures
are drawn by as many forked workers as the process may use CPUs (MHB_PLOT_WORKERS overrides), each
figure whole or not at all (a temporary name, then a rename; a temporary file whose process is gone
is removed by the next run).
Values a figure cannot show (not finite; <= 0 on a log axis) are left out and said so, on the figure
and in a line on stdout. A figure that fails is one line on stderr ("figure NAME failed: reason");
the exit status is non-zero only when figures were due and none could be drawn (3 when matplotlib
cannot be imported: mhbench then tries its next Python). Ctrl-C (SIGINT) or
SIGTERM stops it quietly with exit status 130; it also stops when its parent goes away (unless
started with nohup). Needs matplotlib (Debian: apt install python3-matplotlib); Agg, no window.
"""
import signal
import sys


class Interrupted(BaseException):
    """SIGINT or SIGTERM arrived, or the parent went away: stop drawing (not an Exception, so that no
    figure's `except Exception` takes it for a failed figure)."""


EXIT_INTERRUPTED = 130
EXIT_NO_MATPLOTLIB = 3  # mhbench then tries its next Python (results/report/report_figures.cpp)
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
import gc  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import os  # noqa: E402
import re  # noqa: E402
import selectors  # noqa: E402
import warnings  # noqa: E402
from collections import OrderedDict  # noqa: E402

# mhbench, or the shell: when it is gone, nobody waits for these figures (unless started with nohup,
# which ignores SIGHUP precisely so that the work outlives the shell). A worker watches its parent.
PARENT = None if signal.getsignal(signal.SIGHUP) == signal.SIG_IGN else os.getppid()
Figure = None  # matplotlib.figure.Figure, set by import_matplotlib()

# Notes and failures are said explicitly; library warnings would only repeat them as noise.
warnings.simplefilter("ignore")


def check_stop():
    """Raises Interrupted when a stop was asked for or the parent is gone."""
    if STOP or (PARENT is not None and os.getppid() != PARENT):
        raise Interrupted(STOP[0] if STOP else 0)


# ----------------------------------------------------------------------------------------------
# Look: sizes, fonts, one style per algorithm

import figure_style  # noqa: E402
from figure_style import COLUMN, NEUTRAL, PALETTE, TWO_COLUMNS  # noqa: E402

MARKERS = ["o", "s", "^", "D", "v", "P", "X"]  # 7, coprime with the 8 colours: 56 distinct pairs
LINESTYLES = ["-", "--", "-.", ":"]


def style_of(index):
    """(colour, marker, linestyle) of the algorithm at `index` of the study's list: colour and marker
    cycle with coprime periods (8, 7), so no two of the first 56 share both; the line style changes
    every 8 algorithms on top."""
    return (PALETTE[index % len(PALETTE)], MARKERS[index % len(MARKERS)],
            LINESTYLES[(index // len(PALETTE)) % len(LINESTYLES)])


def import_matplotlib():
    global Figure
    try:
        import matplotlib

        figure_style.use_style(matplotlib)
        from matplotlib.figure import Figure as figure_class
        # Loaded once here, before the workers fork: they share the fonts and the PDF back end.
        import matplotlib.backends.backend_agg  # noqa: F401
        import matplotlib.backends.backend_pdf  # noqa: F401
    except Exception as error:  # noqa: BLE001 - any import failure means no figures, said in one line
        sys.stderr.write("cannot import matplotlib: %s: %s\n"
                         % (type(error).__name__, (str(error).strip().splitlines() or [""])[0]))
        sys.exit(EXIT_NO_MATPLOTLIB)
    Figure = figure_class
    cache_font_subsets()


# Every character a figure is likely to hold: a PDF embeds the subset of its fonts with all of them,
# so that the subset is computed once per font (fontTools takes a fifth of a PDF's time) and shared
# by the workers; a figure with a character outside it gets its own subset, as matplotlib makes it.
COMMON_CHARACTERS = "".join(chr(c) for c in range(32, 127)) + "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075" \
    "\u2076\u2077\u2078\u2079\u2264\u2212\u03c8\u00b1"


def cache_font_subsets():
    """Wraps matplotlib's private subsetting function (3.6's `_backend_pdf_ps.get_glyphs_subset`);
    where another matplotlib has no such function, figures are drawn as matplotlib makes them."""
    try:
        import io
        from matplotlib.backends import _backend_pdf_ps
    except ImportError:
        return
    make_subset = getattr(_backend_pdf_ps, "get_glyphs_subset", None)
    if make_subset is None:
        return
    cached = {}

    def get_glyphs_subset(fontfile, characters):
        if not set(characters) <= set(COMMON_CHARACTERS):
            return make_subset(fontfile, characters)
        if fontfile not in cached:
            cached[fontfile] = make_subset(fontfile, COMMON_CHARACTERS).getvalue()
        return io.BytesIO(cached[fontfile])

    _backend_pdf_ps.get_glyphs_subset = get_glyphs_subset


SUPERSCRIPTS = str.maketrans("-0123456789", "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079")


def decade_label(value, _position=None):
    """A log axis' tick label in plain text: "10⁻⁵" with Unicode superscripts (matplotlib's default
    is mathtext, parsed anew for every label and size: most of a figure's drawing time)."""
    if value <= 0 or not math.isfinite(value):
        return ""
    exponent = math.log10(value)
    if abs(exponent - round(exponent)) < 1e-9:
        return "10" + str(int(round(exponent))).translate(SUPERSCRIPTS)
    return ""


def log_axis(ax, which="y"):
    """A log scale with plain-text decade labels (minor ticks unlabelled)."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullLocator

    axis = ax.yaxis if which == "y" else ax.xaxis
    (ax.set_yscale if which == "y" else ax.set_xscale)("log")
    axis.set_major_locator(LogLocator(base=10, numticks=7))
    axis.set_major_formatter(FuncFormatter(decade_label))
    axis.set_minor_locator(NullLocator())  # minor ticks: a quarter of a figure's drawing, little to read


def short_log_axes(ax):
    """Labels 2, 3 and 5 times the decades on a log axis that spans less than two decades: with the
    decades alone it would show one label, or none."""
    from matplotlib.ticker import FuncFormatter, LogLocator

    for axis, limits in ((ax.xaxis, ax.get_xlim), (ax.yaxis, ax.get_ylim)):
        low, high = sorted(limits())
        if axis.get_scale() != "log" or low <= 0 or high / low >= 100:
            continue
        axis.set_minor_locator(LogLocator(base=10, subs=(2.0, 3.0, 5.0)))
        axis.set_minor_formatter(FuncFormatter(lambda v, _p: "%g" % float("%.2g" % v)))


def finish_axes(fig):
    """What every figure's axes get once drawn: few ticks, and labels on short log axes."""
    for ax in fig.axes:
        few_ticks(ax)
        short_log_axes(ax)


def few_ticks(ax):
    """At most five labelled ticks on a linear axis left to matplotlib's default locator: each tick is
    several artists and a text layout per format, most of an axes' cost (an axes with matplotlib's
    eight or nine ticks per axis costs 60% more to draw than with four), and four labels read as well."""
    from matplotlib.ticker import AutoLocator, MaxNLocator

    for axis in (ax.xaxis, ax.yaxis):
        if axis.get_scale() == "linear" and type(axis.get_major_locator()) is AutoLocator:
            axis.set_major_locator(MaxNLocator(nbins=4, steps=[1, 2, 2.5, 5, 10]))


def warm_up(mathtext):
    """Draws a tiny figure in both formats: fonts, glyph and (when `mathtext`: the parameters'
    symbols) mathtext caches are then loaded once, before the workers fork."""
    import io

    fig = Figure(figsize=(1, 1))
    ax = fig.add_subplot()
    ax.plot([1, 2], [1, 10], marker="o")
    log_axis(ax)
    ax.set_title("f - f* \u2264 10\u207b\u00b9")
    for name in PARAMETER_UNITS if mathtext else ():
        ax.text(0, 0, parameter_axis(name)[0], fontsize=8)
    for ext in ("png", "pdf"):
        fig.savefig(io.BytesIO(), format=ext)


class Styles:
    """Each algorithm's style by its label, in the order of the study's algorithms.csv."""

    def __init__(self, algorithm_rows):
        self.order = OrderedDict()
        self.keys = {}
        for row in algorithm_rows:
            self.add(row.get("Label") or row.get("label") or "", row.get("Spec") or row.get("algorithm") or "")

    def add(self, label, algorithm=""):
        if label and label not in self.order:
            self.order[label] = style_of(len(self.order))
            self.keys[label] = algorithm or label
        return self.order.get(label)

    def of(self, label):
        return self.order.get(label) or self.add(label)

    def csv_text(self):
        lines = ["algorithm,label,colour,marker,linestyle"]
        for label, (colour, marker, linestyle) in self.order.items():
            lines.append(",".join(csv_field(v) for v in (self.keys[label], label, colour, marker, linestyle)))
        return "\n".join(lines) + "\n"


def csv_field(text):
    return '"%s"' % text.replace('"', '""') if any(c in text for c in ',"\n') else text


def legend_columns(labels, width):
    """How many legend columns fit across `width` inches at 7 pt."""
    longest = max([len(label) for label in labels] + [4])
    return max(1, min(len(labels), int(width // (0.5 + 0.058 * longest))))


def new_figure(width, rows=1, cols=1, panel_height=1.9, legend_labels=(), title_lines=1, xlabel=True,
               left=0.55, right=0.12, wspace=0.55, hspace=0.62, sharex=False, sharey=False, bottom_extra=0.0):
    """A figure with fixed margins in inches (no tight bounding box: one draw per format), room for a
    title above and for one shared legend below the axes. Returns (figure, axes as a flat list, the
    number of legend columns)."""
    ncol = legend_columns(legend_labels, width) if legend_labels else 1
    legend_rows = math.ceil(len(legend_labels) / ncol) if legend_labels else 0
    top = 0.08 + 0.16 * title_lines
    bottom = (0.42 if xlabel else 0.22) + bottom_extra + (0.06 + 0.145 * legend_rows if legend_rows else 0)
    height = top + rows * panel_height + (rows - 1) * hspace + bottom
    fig = Figure(figsize=(width, height))
    fig.subplots_adjust(left=left / width, right=1 - right / width, top=1 - top / height,
                        bottom=bottom / height, wspace=wspace * cols / max(width - left - right, 1),
                        hspace=hspace / panel_height)
    axes = fig.subplots(rows, cols, squeeze=False, sharex=sharex, sharey=sharey)
    return fig, [ax for row in axes for ax in row], ncol


def shared_legend(fig, handles, labels, ncol):
    if handles:
        fig.legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, 0.0), ncol=ncol,
                   borderaxespad=0.2, columnspacing=1.2, handletextpad=0.5)


# ----------------------------------------------------------------------------------------------
# Reading

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


def label_of(row):
    return row.get("label") or row["algorithm"]


def tidy_problem(spec):
    """A spec without the punctuation, for titles when problems.csv has no name: "pmsm load=2 speed=2500"."""
    name, _, keys = spec.partition(":")
    return (name + " " + keys.replace(",", " ")).strip()


class Problems:
    """Each problem's title and known optimum (problems.csv: problem,name,f_opt)."""

    def __init__(self, rows):
        self.names = {r["problem"]: r.get("name") or tidy_problem(r["problem"]) for r in rows}
        self.optima = {r["problem"]: number(r.get("f_opt", "")) for r in rows}

    def name(self, problem):
        return self.names.get(problem) or tidy_problem(problem)

    def f_opt(self, problem):
        value = self.optima.get(problem, math.nan)
        return value if math.isfinite(value) else None


def read_budget(report):
    """The budget's text (budget.txt), "" without one."""
    path = os.path.join(report, "budget.txt")
    if not os.path.exists(path):
        return ""
    with open(path) as f:
        return f.read().strip()


def counts_iterations(budget):
    """Whether iterations end this budget's runs, so that they are comparable across algorithms (a
    report without a budget.txt is an older one: iterations are drawn, as they always were)."""
    return not budget or "iterations=" in budget


# ----------------------------------------------------------------------------------------------
# What a figure leaves out

class LeftOut:
    """Counts the values a figure could not show, by reason."""

    def __init__(self):
        self.counts = OrderedDict()

    def add(self, reason, n=1):
        if n and reason:
            self.counts[reason] = self.counts.get(reason, 0) + n

    def keep(self, value, log):
        if math.isnan(value):
            reason = "undefined (nan)"
        elif math.isinf(value):
            reason = "at +inf" if value > 0 else "at -inf"
        elif log and value <= 0:
            reason = "<= 0 on the log axis"
        else:
            return True
        self.add(reason)
        return False

    def text(self):
        return ", ".join("%d %s" % (n, reason) for reason, n in self.counts.items())

    def total(self):
        return sum(self.counts.values())


def finish_note(job, ax, left_out, anything_drawn, what="values", where=""):
    """Writes on the figure (and in a stdout line) what it left out, or why it is empty; `where` names
    the panel (its problem) in the line."""
    if left_out.total():
        job.note((where + ": " if where else "") + "left out " + left_out.text())
    if not anything_drawn:
        ax.text(0.5, 0.5, "no finite %s to draw\n(%s)" % (what, left_out.text() or "no data"), ha="center",
                va="center", transform=ax.transAxes)
        ax.set_xticks([])
        ax.set_yticks([])
    elif left_out.total():
        ax.text(0.01, 0.01, "left out: " + left_out.text(), transform=ax.transAxes, fontsize=6, color="grey")


def log_axis_possible(values):
    """A log axis when every finite value is positive (and there is one)."""
    finite = [v for v in values if math.isfinite(v)]
    return bool(finite) and all(v > 0 for v in finite)


class Scale:
    """How values of one problem are drawn: the gap f - f* where f* is known, with its floor, else f."""

    def __init__(self, f_opt, values):
        self.f_opt = f_opt
        self.floored = 0
        self.floor = None
        if f_opt is None:
            self.log = log_axis_possible(values)
            return
        gaps = [v - f_opt for v in values if math.isfinite(v)]
        positive = [g for g in gaps if g > 0]
        self.floor = 4 * sys.float_info.epsilon * abs(f_opt) if f_opt != 0 else \
            (min(positive) / 10 if positive else 1e-16)
        if positive:
            self.floor = min(self.floor, min(positive))
        self.log = True

    def label(self, what="best-so-far"):
        return "%s f - f*" % what if self.f_opt is not None else "%s f" % what

    def value(self, v):
        """The value drawn for f = v (NaN and infinities pass through)."""
        if self.f_opt is None or not math.isfinite(v):
            return v
        gap = v - self.f_opt
        if gap <= self.floor:
            self.floored += 1
            return self.floor
        return gap

    def mark_floor(self, ax):
        """A dotted line at the floor and what it means, when any value was drawn there."""
        if not self.floored:
            return
        ax.axhline(self.floor, color=NEUTRAL, linestyle=":", linewidth=0.7)
        ax.text(0.99, self.floor, "f - f* <= %.1e (0 incl.) drawn here" % self.floor, ha="right", va="bottom",
                fontsize=6, color=NEUTRAL, transform=ax.get_yaxis_transform())


def downsample(points, log_x, most=300):
    """At most `most` points of a curve sorted by x, spread evenly on the axis (log or linear); the
    first and last are kept."""
    if len(points) <= most:
        return points
    xs = [p[0] for p in points]
    first, last = xs[0], xs[-1]
    if log_x and first > 0:
        targets = [first * (last / first) ** (k / (most - 1)) for k in range(most)]
    else:
        targets = [first + (last - first) * k / (most - 1) for k in range(most)]
    keep, i = [], 0
    for t in targets:
        while i + 1 < len(xs) and xs[i + 1] <= t:
            i += 1
        if not keep or keep[-1] != i:
            keep.append(i)
    if keep[-1] != len(xs) - 1:
        keep.append(len(xs) - 1)
    return [points[i] for i in keep]


# ----------------------------------------------------------------------------------------------
# Jobs: every figure is one, drawn by a worker

class Job:
    """One figure: its folder, name, kind, and the function (with its arguments) that draws it."""

    def __init__(self, out_dir, name, kind, draw, *args):
        self.out_dir, self.name, self.kind, self.draw, self.args = out_dir, name, kind, draw, args
        self.notes = []

    def note(self, text):
        self.notes.append("figure %s: %s" % (self.name, text))

    def cost(self):
        """Relative drawing time, for the order of the jobs: CPU time of a panel of its kind (measured
        as runner/study/calibration.cpp says) times its panels."""
        panels = len(self.args[2]) if self.draw is panels_figure else 1
        return JOB_COST.get(self.kind, 1.0) * panels

    def run(self):
        """{"drawn": 0 or 1, "failed": line or None, "notes": [...]}; a failure is one line."""
        check_stop()
        try:
            fig = self.draw(self, *self.args)
            if fig is not None:
                finish_axes(fig)
                save(fig, self.out_dir, self.name)
            return {"drawn": 1 if fig is not None else 0, "failed": None, "notes": self.notes}
        except Exception as error:  # noqa: BLE001 - any failure of one figure must not stop the others
            return {"drawn": 0, "failed": "figure %s failed: %s" % (self.name, one_line(error)), "notes": []}


def one_line(error):
    text = str(error).strip().splitlines()
    return type(error).__name__ + (": " + text[0] if text else "")


# Per panel, or per figure of a single panel: a convergence panel is 1.
JOB_COST = {"parameters": 3.5, "bayesian": 3.0, "effects": 2.0, "ecdf": 1.3, "final_values": 1.0,
            "critical_difference": 0.8}

TEMPORARY = re.compile(r"^\..+\.tmp-([0-9]+)$")


def save(fig, out_dir, name):
    """NAME.pdf and NAME.png, each whole or not at all (figure_style.save_figure)."""
    figure_style.save_figure(fig, out_dir, name, check_stop)


def remove_stale_figures(out_dir, names):
    """Removes the temporary files of a run that was killed (SIGKILL leaves no time to clean up), and
    the figures of an earlier report that this one does not draw (another kind of figure, an SVG of an
    older mhbench): the page shows every figure in the folder, and a stale one would pass for current."""
    for file_name in os.listdir(out_dir):
        stem, ext = os.path.splitext(file_name)
        if not file_name.startswith(".") and ext in (".pdf", ".png", ".svg") and \
                (ext == ".svg" or stem not in names):
            try:
                os.remove(os.path.join(out_dir, file_name))
            except OSError:
                pass
            continue
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


def worker_count(jobs):
    text = os.environ.get("MHB_PLOT_WORKERS", "")
    try:
        wanted = int(text) if text else len(os.sched_getaffinity(0))
    except (ValueError, AttributeError):
        wanted = os.cpu_count() or 1
    return max(1, min(wanted, len(jobs)))


def run_jobs(jobs):
    """Every job's result, in job order: drawn here, or by forked workers that take the next job
    from a shared counter (the costliest are planned first)."""
    workers = worker_count(jobs)
    if workers <= 1:
        return [job.run() for job in jobs]
    import multiprocessing

    counter = multiprocessing.get_context("fork").Value("i", 0)
    # What the parent loaded (matplotlib, the fonts) moves to a generation the collector never
    # visits: a collection in a worker would otherwise touch, and so copy, every shared page.
    gc.freeze()
    children = {}
    for _ in range(workers):
        read_end, write_end = os.pipe()
        pid = os.fork()
        if pid == 0:  # a worker
            os.close(read_end)
            worker(jobs, counter, write_end)
        os.close(write_end)
        children[read_end] = pid
    results = [None] * len(jobs)
    try:
        collect(children, results)
    except BaseException:
        for pid in children.values():
            try:
                os.kill(pid, signal.SIGTERM)
            except OSError:
                pass
        for pid in children.values():
            try:
                os.waitpid(pid, 0)
            except OSError:
                pass
        raise
    for i, result in enumerate(results):
        if result is None:  # a worker that died (killed, out of memory) took it
            results[i] = {"drawn": 0, "failed": "figure %s failed: its worker died" % jobs[i].name, "notes": []}
    return results


def worker(jobs, counter, write_end):
    """Draws jobs until none is left; each result is one JSON line on `write_end`. Never returns."""
    global PARENT
    if PARENT is not None:
        PARENT = os.getppid()  # the plotting process; it watches mhbench
    # The collector runs once per figure, when its artists' cycles are garbage, rather than every
    # few hundred allocations while they are drawn (each pass walks them all to free nothing).
    gc.disable()
    status = 0
    try:
        with os.fdopen(write_end, "w") as out:
            while True:
                with counter.get_lock():
                    i = counter.value
                    counter.value += 1
                if i >= len(jobs):
                    break
                out.write(json.dumps([i, jobs[i].run()]) + "\n")
                out.flush()
                gc.collect()
    except Interrupted:
        status = EXIT_INTERRUPTED
    except BaseException:  # noqa: BLE001 - a worker must end here, never return into the parent's code
        status = 1
    os._exit(status)


def collect(children, results):
    """Reads the workers' result lines until every pipe is closed, then reaps the workers."""
    selector = selectors.DefaultSelector()
    buffers = {}
    for fd in children:
        selector.register(fd, selectors.EVENT_READ)
        buffers[fd] = b""
    open_fds = set(children)
    while open_fds:
        check_stop()
        for key, _ in selector.select(timeout=0.5):
            chunk = os.read(key.fd, 65536)
            if not chunk:
                selector.unregister(key.fd)
                os.close(key.fd)
                open_fds.discard(key.fd)
                continue
            lines = (buffers[key.fd] + chunk).split(b"\n")
            buffers[key.fd] = lines.pop()
            for line in lines:
                i, result = json.loads(line)
                results[i] = result
    for pid in children.values():
        _, status = os.waitpid(pid, 0)
        if os.WIFEXITED(status) and os.WEXITSTATUS(status) == EXIT_INTERRUPTED:
            raise Interrupted(0)


# ----------------------------------------------------------------------------------------------
# Planning: read each folder's CSVs once, one job per figure

class Folder:
    """What every figure of one report folder shares."""

    def __init__(self, report):
        self.report = report
        self.out_dir = os.path.join(report, "figures")
        self.budget = read_budget(report)
        self.suffix = " [budget %s]" % self.budget if self.budget and os.path.exists(
            os.path.join(report, "budget.txt")) and self.multi_budget() else ""
        self.styles = Styles(read_rows(os.path.join(report, "algorithms.csv")))
        self.problems = Problems(read_rows(os.path.join(report, "problems.csv")))

    def multi_budget(self):
        return os.path.exists(os.path.join(os.path.dirname(os.path.abspath(self.report)), "budgets.csv"))

    def read(self, name):
        return read_rows(os.path.join(self.report, name))

    def title(self, problem, what=""):
        return self.problems.name(problem) + (": " + what if what else "") + self.suffix


def plan_folder(report):
    """The jobs of one report folder (main() orders them by cost)."""
    folder = Folder(report)
    jobs = []

    def add(name, kind, draw, *args):
        jobs.append(Job(folder.out_dir, name, kind, draw, folder, *args))

    def per_problem(prefix, kind, draw_panel, rows, what, *args):
        """A figure with a panel per problem, or one figure per problem (one, or more than MOST_PANELS)."""
        items = [(problem, r) for (problem,), r in group(rows, "problem").items()]
        if 2 <= len(items) <= MOST_PANELS:
            add(prefix + "all", kind, panels_figure, draw_panel, items, what, *args)
        else:
            for item in items:
                add(prefix + slug(item[0]), kind, panels_figure, draw_panel, [item], what, *args)

    curves_iteration = folder.read("curves_iteration.csv")
    per_problem("convergence_evaluations_", "convergence", convergence_panel, folder.read("curves_evaluations.csv"),
                "median best-so-far by evaluations", "evaluations", True)
    if counts_iterations(folder.budget):
        per_problem("convergence_iteration_", "convergence", convergence_panel, curves_iteration,
                    "median best-so-far by iteration", "iteration", False)
    evaluations_at = {(r["problem"], r["algorithm"], r["iteration"]): number(r["evaluations_mean"])
                      for r in curves_iteration} if not counts_iterations(folder.budget) else None
    for (problem,), rows in group(folder.read("parameters_iteration.csv"), "problem").items():
        add("parameters_" + slug(problem), "parameters", parameters_figure, problem, rows, evaluations_at)
    finals = folder.read("final_values.csv")
    per_problem("final_values_", "final_values", box_panel, finals, "final values")
    # Fixed-target ECDFs pool the problems, as COCO does (a problem's own is a reading of its
    # convergence figure: the fraction of runs below each target by evaluations); of one problem,
    # only the study's own target, which no other figure shows.
    problems = list(OrderedDict.fromkeys(r["problem"] for r in finals))
    if any(row["evals_to_target"] for row in finals):
        curves = pooled_curves(finals, "evals_to_target")
        if len(problems) == 1:
            add("ecdf_target_" + slug(problems[0]), "ecdf", ecdf_figure, curves,
                "fraction of runs that reached the target", folder.title(problems[0], "fixed-target ECDF"))
        else:
            add("ecdf_target_all", "ecdf", ecdf_figure, curves, "fraction of (problem, run) pairs",
                "%d problems: runs that reached the study's target%s" % (len(problems), folder.suffix))
    hits = folder.read("target_hits.csv")
    hit_problems = list(OrderedDict.fromkeys(r["problem"] for r in hits))
    if len(hit_problems) >= 2:
        add("ecdf_targets_all", "ecdf", ecdf_figure, pooled_curves(hits, "evaluations"),
            "fraction of (problem, run, target) triples",
            "%d problems: targets f - f* = 1e2...1e-8%s" % (len(hit_problems), folder.suffix))
    gaps = folder.read("relative_gap_medians.csv")
    if gaps:
        add("relative_gaps", "relative_gaps", relative_gaps_figure, gaps)
    ranks = folder.read("critical_difference.csv")
    if ranks:
        add("critical_difference", "critical_difference", critical_difference_figure, ranks)
    timing = folder.read("overhead.csv")
    if any(len({r["Dimension"] for r in rows}) >= 3 for rows in group(timing, "Algorithm").values()):
        add("overhead", "overhead", overhead_figure, timing)
    means = folder.read("effect_means.csv")
    effects = folder.read("effects.csv")
    readings = {(r["Design"], r["Problem"], r["Effect"]): r["Reading"] for r in effects}
    for (design,), rows in group(means, "design").items():
        design_slug = slug(design.split(":")[0])
        add("effects_main_" + design_slug, "effects", effects_main, design, rows, readings)
        add("effects_interaction_" + design_slug, "effects", effects_interaction, design, rows, readings)
    for (design,), rows in group(effects, "Design").items():
        add("effects_overview_" + slug(design.split(":")[0]), "effects", effects_overview, design, rows)
    verdicts = {(r.get("Problem", ""), r["Algorithm"]): r["Verdict"] for r in folder.read("structural_bias.csv")}
    for (problem,), rows in group(folder.read("final_points.csv"), "problem").items():
        add("structural_bias_" + slug(problem), "structural_bias", structural_bias_figure, problem, rows, verdicts)
    tests = {(r["problem"], r["algorithm"]): r for r in folder.read("bayesian_probabilities.csv")}
    for (problem,), rows in group(folder.read("bayesian_samples.csv"), "problem").items():
        add("bayesian_simplex_" + slug(problem), "bayesian", bayesian_simplex, problem, rows, tests)
    return folder, jobs


# ----------------------------------------------------------------------------------------------
# The figures. Each takes (job, folder, ...) and returns the figure to save (None: nothing to draw).

# Problems drawn as the panels of one figure per kind (the figures to read side by side, one legend,
# and a third of the figures to draw), up to this many; a study with more gets a figure per problem
# (nine panels on a page's width are too small to read).
MOST_PANELS = 6
# Per kind: (panel height, in; whether the figure has an algorithm legend).
PANEL_LOOK = {"convergence_panel": (2.0, True), "box_panel": (1.9, False)}


def panels_figure(job, folder, draw_panel, items, what, *args):
    """items: (problem, rows); draw_panel(job, folder, ax, problem, rows, where, *args) draws one panel
    and returns its legend handles. One problem: a one-column figure titled by it; several: two
    columns, up to three panels a row, each titled by its problem, and `what` above them."""
    height, legend = PANEL_LOOK[draw_panel.__name__]
    rows = [row for _, r in items for row in r]
    labels = list(OrderedDict.fromkeys(label_of(r) for r in rows)) if legend else []
    single = len(items) == 1
    cols = 1 if single else min(len(items), 3)
    room = box_label_room(rows) if draw_panel is box_panel else 0.0
    fig, axes, ncol = new_figure(COLUMN if single else TWO_COLUMNS, rows=math.ceil(len(items) / cols), cols=cols,
                                 panel_height=height if single else height - 0.25, legend_labels=labels,
                                 title_lines=1 if single else 2, left=0.62, wspace=0.8, hspace=0.62 + room,
                                 bottom_extra=room, xlabel=draw_panel is not box_panel)  # boxes: labels, no x label
    handles = OrderedDict()
    for ax, (problem, problem_rows) in zip(axes, items):
        where = "" if single else folder.problems.name(problem)
        for handle in draw_panel(job, folder, ax, problem, problem_rows, where, *args):
            key = label_of_handle(handle)  # a line that drew something stands for its algorithm first
            if key not in handles or handles[key].get_label() != key:
                handles[key] = handle
        ax.set_title(folder.title(problem) if single else folder.problems.name(problem))
    for ax in axes[len(items):]:
        ax.set_visible(False)
    if not single:  # in the top margin, above the panels' titles
        fig.suptitle(what[0].upper() + what[1:] + folder.suffix, y=1 - 0.04 / fig.get_figheight(), va="top")
    if legend:
        shared_legend(fig, list(handles.values()), [h.get_label() for h in handles.values()], ncol)
    return fig


NOTHING_FINITE = " (nothing finite to draw)"


def label_of_handle(handle):
    """The algorithm a legend handle stands for (a line with nothing to draw says so in its label)."""
    label = handle.get_label()
    return label[:-len(NOTHING_FINITE)] if label.endswith(NOTHING_FINITE) else label


def pooled_curves(rows, column):
    """ECDF curves pooled over the problems of `rows` (one row per trial, `column` the evaluations at
    which it succeeded, empty if never): (label, evaluations of the successes, trials) per algorithm."""
    return [(label_of(r[0]), [number(row[column]) for row in r if row[column]], len(r))
            for r in group(rows, "algorithm").values()]


def algorithm_line(ax, folder, label, xs, ys, log_x, index_in_figure, **extra):
    colour, marker, linestyle = folder.styles.of(label)
    # Markers spaced along the curve (a fraction of the axes' diagonal), each algorithm offset so
    # that markers of curves lying on each other do not hide each other.
    step = 0.11
    if not any(math.isfinite(y) for y in ys):  # nothing to draw: the legend says so (markevery needs points)
        return ax.plot([], [], color=colour, marker=marker, linestyle=linestyle,
                       label=label + NOTHING_FINITE, **extra)[0]
    return ax.plot(xs, ys, color=colour, marker=marker, linestyle=linestyle, label=label,
                   markevery=((0.013 * index_in_figure) % step, step), markersize=3.2, **extra)[0]


# Bands (IQR, std) are drawn for up to this many algorithms; more overlap into a grey wash.
MOST_BANDS = 5


def convergence_panel(job, folder, ax, problem, rows, where, x_key, log_x):
    by_algorithm = group(rows, "algorithm")
    labels = [label_of(r[0]) for r in by_algorithm.values()]
    scale = Scale(folder.problems.f_opt(problem), [number(r["median"]) for r in rows])
    left_out = LeftOut()
    handles, drawn = [], False
    bands = len(labels) <= MOST_BANDS
    for i, r in enumerate(by_algorithm.values()):
        points = []
        for row in r:
            x = number(row[x_key])
            if not (math.isfinite(x) and (x > 0 or not log_x)):
                left_out.add("x <= 0 on the log axis" if math.isfinite(x) else "x not finite")
                continue
            points.append((x, scale.value(number(row["median"])), scale.value(number(row["q25"])),
                           scale.value(number(row["q75"]))))
        points = downsample(points, log_x)
        xs = [p[0] for p in points]
        ys = [p[1] if left_out.keep(p[1], scale.log) else math.nan for p in points]
        line = algorithm_line(ax, folder, label_of(r[0]), xs, ys, log_x, i)
        handles.append(line)
        band = [bands and shows(p[2], scale.log) and shows(p[3], scale.log) for p in points]
        if any(band):
            ax.fill_between(xs, [p[2] if k else 1.0 for p, k in zip(points, band)],
                            [p[3] if k else 1.0 for p, k in zip(points, band)], where=band, alpha=0.13,
                            color=line.get_color(), linewidth=0)
        drawn = drawn or any(math.isfinite(v) for v in ys)
    if drawn and scale.log:
        log_axis(ax, "y")
    if drawn and log_x:
        log_axis(ax, "x")
    scale.mark_floor(ax)
    ax.set_xlabel(x_key)
    ax.set_ylabel(scale.label() + (" (median, IQR)" if bands else " (median)"))
    finish_note(job, ax, left_out, drawn, where=where)
    return handles


def shows(value, log):
    return math.isfinite(value) and (not log or value > 0)


# Units of the PMSM model's parameters (problems/pmsm): the name shown, the unit, and the factor that
# takes the stored SI value to it (inductances in mH: values near 3e-3 H read better as 3.24).
PARAMETER_UNITS = {
    "Rs": ("$R_s$", "ohm", 1.0), "Ld": ("$L_d$", "mH", 1e3), "Lq": ("$L_q$", "mH", 1e3),
    "psi": (r"$\psi_f$", "Wb", 1.0), "Vdt": ("$V_{dt}$", "V", 1.0),
}


def parameter_axis(name):
    shown, unit, factor = PARAMETER_UNITS.get(name, (name, "", 1.0))
    return (shown + (" (%s)" % unit if unit else "")), factor


def parameters_figure(job, folder, problem, rows, evaluations_at):
    from matplotlib.ticker import MaxNLocator

    by_parameter = group(rows, "parameter")
    labels = list(OrderedDict.fromkeys(label_of(r) for r in rows))
    extra = ["true value", "least-squares optimum"]
    cols = 2 if len(by_parameter) > 1 else 1
    count = len(by_parameter)
    fig, axes, ncol = new_figure(TWO_COLUMNS if cols > 1 else COLUMN, rows=math.ceil(count / cols), cols=cols,
                                 panel_height=1.45, legend_labels=labels + extra, left=0.6, wspace=0.75,
                                 hspace=0.3, sharex=True)  # one x axis: labelled under the last row only
    left_out = LeftOut()
    handles, drawn = OrderedDict(), False
    x_name = "iteration" if evaluations_at is None else "evaluations (mean at each iteration)"
    for ax, ((parameter,), prow) in zip(axes, by_parameter.items()):
        ylabel, factor = parameter_axis(parameter)
        truth = optimum = math.nan
        for i, r in enumerate(group(prow, "algorithm").values()):
            xs, ys, lo, hi = [], [], [], []
            for row in r:
                x = number(row["iteration"]) if evaluations_at is None else \
                    evaluations_at.get((row["problem"], row["algorithm"], row["iteration"]), math.nan)
                m, s = number(row["mean"]) * factor, number(row["std"]) * factor
                if not math.isfinite(x) or not left_out.keep(m, False):
                    continue
                xs.append(x)
                ys.append(m)
                lo.append(m - s if math.isfinite(s) else m)
                hi.append(m + s if math.isfinite(s) else m)
            points = downsample(list(zip(xs, ys, lo, hi)), False)
            line = algorithm_line(ax, folder, label_of(r[0]), [p[0] for p in points], [p[1] for p in points],
                                  False, i)
            if len(labels) <= MOST_BANDS:
                ax.fill_between([p[0] for p in points], [p[2] for p in points], [p[3] for p in points],
                                alpha=0.1, color=line.get_color(), linewidth=0)
            handles.setdefault(label_of(r[0]), line)
            drawn = drawn or bool(points)
            truth, optimum = number(r[0]["true"]) * factor, number(r[0]["opt"]) * factor
        if math.isfinite(truth):
            handles.setdefault("true value", ax.axhline(truth, color="black", linestyle="--", linewidth=0.9))
        if math.isfinite(optimum):
            handles.setdefault("least-squares optimum",
                               ax.axhline(optimum, color=NEUTRAL, linestyle=":", linewidth=1.0))
        ax.set_ylabel(ylabel)
        if ax in axes[count - cols:]:  # the last panel of each column (above an empty one, its labels back)
            ax.set_xlabel(x_name)
            ax.xaxis.set_tick_params(labelbottom=True)
        zoom_on_truth(ax, truth, optimum)
        # Few ticks: matplotlib builds each tick of each panel as several artists (a third of the
        # figure's time), and four labels read as well as eight.
        ax.xaxis.set_major_locator(MaxNLocator(5))
        ax.yaxis.set_major_locator(MaxNLocator(4))
    for ax in axes[count:]:
        ax.set_visible(False)
    fig.suptitle(folder.title(problem, "identified parameters (best-so-far, mean%s)"
                              % (" +/- std" if len(labels) <= MOST_BANDS else "")))
    shared_legend(fig, list(handles.values()), list(handles.keys()), ncol)
    finish_note(job, axes[0], left_out, drawn)
    return fig


def zoom_on_truth(ax, truth, optimum):
    """Keeps the true value and the optimum in view, but lets the curves' first iterations (far off)
    leave the axes: the last decades of convergence are what the figure is read for."""
    low, high = ax.get_ylim()
    anchors = [v for v in (truth, optimum) if math.isfinite(v)]
    if not anchors:
        return
    centre = sum(anchors) / len(anchors)
    spread = max(abs(high - centre), abs(centre - low))
    half = max(spread * 0.35, abs(centre) * 0.05, 1e-12)
    ax.set_ylim(max(low, centre - half), min(high, centre + half))


def box_panel(job, folder, ax, problem, rows, where):
    by_algorithm = group(rows, "algorithm")
    labels = [label_of(r[0]) for r in by_algorithm.values()]
    data = [[number(row["best_f"]) for row in r] for r in by_algorithm.values()]
    scale = Scale(folder.problems.f_opt(problem), [v for d in data for v in d])
    left_out = LeftOut()
    kept = [[scale.value(v) for v in d if left_out.keep(scale.value(v), scale.log)] for d in data]
    positions = [i + 1 for i, d in enumerate(kept) if d]
    if positions:
        boxes = ax.boxplot([d for d in kept if d], positions=positions, widths=0.6, patch_artist=True,
                           medianprops={"color": "black", "linewidth": 1.0},
                           flierprops={"markersize": 2.5, "markeredgewidth": 0.5})
        for box, flier, position in zip(boxes["boxes"], boxes["fliers"], positions):
            colour, marker, linestyle = folder.styles.of(labels[position - 1])
            box.set(facecolor=colour, alpha=0.55, edgecolor="black", linewidth=0.6)
            if linestyle != "-":  # the 9th algorithm on has a colour again: hatched, as its line is dashed
                box.set(hatch="////")
            flier.set(marker=marker, markeredgecolor=colour)
    for i, (d, values) in enumerate(zip(kept, data)):
        if not d:  # a box that cannot be drawn says why where it would stand
            why = "all +inf" if values and all(v == math.inf for v in values) else "nothing finite"
            ax.text(i + 1, 0.5, why, ha="center", va="center", rotation=90, fontsize=6, color="grey",
                    transform=ax.get_xaxis_transform())
    ax.set_xticks(range(1, len(data) + 1))
    ax.set_xticklabels(labels, rotation=BOX_LABEL_ROTATION if len(labels) > 3 else 0,
                       ha="right" if len(labels) > 3 else "center", rotation_mode="anchor")
    ax.set_xlim(0.5, len(data) + 0.5)
    ax.grid(False, axis="x")
    if positions and scale.log:
        log_axis(ax, "y")
    scale.mark_floor(ax)
    ax.set_ylabel(scale.label("final"))
    finish_note(job, ax, left_out, bool(positions), "final values", where)
    return []  # no legend: the labels stand under the boxes


BOX_LABEL_ROTATION = 35


def box_label_room(rows):
    """Inches below a box plot's axes for its algorithm labels, rotated when there are more than three:
    as much as the longest takes at 7 pt."""
    labels = list(OrderedDict.fromkeys(label_of(r) for r in rows))
    if len(labels) <= 3:
        return 0.0
    longest = max(len(label) for label in labels)
    # About 0.05 in per character of the serif face at 7 pt (measured on "LSHADE-cnEpSin", whose end
    # was cut off at 0.035), plus the line's own height across the slant.
    angle = math.radians(BOX_LABEL_ROTATION)
    return 0.05 * longest * math.sin(angle) + 0.1 * math.cos(angle) + 0.05


def ecdf_figure(job, folder, curves, ylabel, title):
    """curves: (label, evaluations at which a run / target was reached, number of trials)."""
    from matplotlib.lines import Line2D

    labels = [label for label, _, _ in curves]
    fig, (ax,), ncol = new_figure(COLUMN, legend_labels=labels, panel_height=1.8)
    left_out = LeftOut()
    curves = [(label, [e for e in reached if left_out.keep(e, True)], trials) for label, reached, trials in curves]
    right = 1.5 * max([1.0] + [e for _, reached, _ in curves for e in reached])
    handles = []
    for i, (label, reached, trials) in enumerate(curves):
        reached = sorted(reached)
        y = [0.0] + [(k + 1) / trials for k in range(len(reached))] if trials else [0.0]
        xs, ys = [1.0] + reached + [right], y + [y[-1]]
        colour, marker, linestyle = folder.styles.of(label)
        ax.step(xs, ys, where="post", color=colour, linestyle=linestyle)
        # Markers on a step curve: a few, at the steps' ends, so the styles are told apart in grey too.
        every = max(1, len(xs) // 6)
        ax.plot(xs[1 + i % every::every], ys[1 + i % every::every], linestyle="none", marker=marker,
                color=colour, markersize=3.0)
        handles.append(Line2D([], [], color=colour, marker=marker, linestyle=linestyle, markersize=3.0))
    log_axis(ax, "x")
    ax.set_xlim(1, right)
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("evaluations")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    shared_legend(fig, handles, labels, ncol)
    finish_note(job, ax, left_out, True)
    return fig


# A relative gap below this is f* reached to what doubles resolve of it (the effects' floor, 4 eps |f*|,
# relative): on the log axis such medians, 0 and below 0 among them, are drawn at it.
GAP_FLOOR = 4 * sys.float_info.epsilon


def relative_target_of(budget):
    """R of "relative_target=R" in a budget's text; NaN without one."""
    match = re.search(r"relative_target=([^,\]]+)", budget)
    return number(match.group(1)) if match else math.nan


def relative_gaps_figure(job, folder, rows):
    problems = list(OrderedDict.fromkeys(r["problem"] for r in rows))
    names = OrderedDict((r["problem"], r.get("name") or folder.problems.name(r["problem"])) for r in rows)
    by_algorithm = group(rows, "algorithm")
    labels = [label_of(r[0]) for r in by_algorithm.values()]
    fig, (ax,), ncol = new_figure(TWO_COLUMNS, legend_labels=labels + ["relative target"], panel_height=2.1,
                                  left=0.65)
    left_out = LeftOut()
    floored, drawn, handles = 0, False, []
    for i, r in enumerate(by_algorithm.values()):
        by_problem = {row["problem"]: number(row["median_relative_gap"]) for row in r}
        ys = []
        for problem in problems:
            gap = by_problem.get(problem, math.nan)
            if math.isnan(gap) or math.isinf(gap):
                left_out.add("without a successful run" if math.isnan(gap) else "at +inf")
                ys.append(math.nan)  # breaks the line there
                continue
            floored += 1 if gap <= GAP_FLOOR else 0
            ys.append(max(gap, GAP_FLOOR))
        colour, marker, linestyle = folder.styles.of(label_of(r[0]))
        handles.append(ax.plot(range(len(problems)), ys, color=colour, marker=marker, linestyle=linestyle,
                               label=label_of(r[0]))[0])
        drawn = drawn or any(math.isfinite(y) for y in ys)
    target = relative_target_of(folder.budget)
    if math.isfinite(target) and target > 0:
        handles.append(ax.axhline(target, color="black", linestyle="--", linewidth=0.9,
                                  label="relative target %g" % target))
    if floored:
        ax.axhline(GAP_FLOOR, color=NEUTRAL, linestyle=":", linewidth=0.7)
        job.note("%d median%s at or below 4 eps drawn at 4 eps" % (floored, "" if floored == 1 else "s"))
        ax.text(0.99, GAP_FLOOR, "<= 4 eps (f* to double precision) drawn here", ha="right", va="bottom",
                fontsize=6, color=NEUTRAL, transform=ax.get_yaxis_transform())
    if drawn:
        log_axis(ax, "y")
    ax.set_xticks(range(len(problems)))
    ax.set_xticklabels([names[p] for p in problems], rotation=20 if len(problems) > 4 else 0,
                       ha="right" if len(problems) > 4 else "center")
    ax.set_xlim(-0.3, len(problems) - 0.7)
    ax.set_ylabel("median (f - f*) / |f*|")
    ax.set_title("Relative gap to f* per problem" + folder.suffix)
    shared_legend(fig, handles, [h.get_label() for h in handles], ncol)
    finish_note(job, ax, left_out, drawn, "medians")
    return fig


BIAS_BINS = 20  # bins of [0, 1] per dimension in the structural-bias figure


def structural_bias_figure(job, folder, problem, rows, verdicts):
    """f0's final points as per-dimension histograms, a panel per algorithm: column d is the histogram
    of coordinate d over the runs (20 bins), coloured by its density relative to uniform (white 1,
    red more, blue fewer; 2 and above saturate). Uniform points leave the panel pale; a pull to the
    centre is a red band at 0.5, a pull to the bounds red rows at 0 and 1. Titled with the verdict."""
    by_algorithm = group(rows, "algorithm")
    cols = min(len(by_algorithm), 4)
    fig, axes, _ = new_figure(TWO_COLUMNS, rows=math.ceil(len(by_algorithm) / cols), cols=cols,
                              panel_height=1.5, title_lines=2, left=0.45, wspace=0.35, hspace=0.75,
                              sharey=True)
    for ax, ((label,), points) in zip(axes, by_algorithm.items()):
        dimensions = max(int(c["dimension"]) for c in points)
        counts = [[0] * dimensions for _ in range(BIAS_BINS)]
        for c in points:
            x = min(max(number(c["x"]), 0.0), 1.0)
            counts[min(int(x * BIAS_BINS), BIAS_BINS - 1)][int(c["dimension"]) - 1] += 1
        expected = len(points) / dimensions / BIAS_BINS
        density = [[n / expected for n in row] for row in counts]
        ax.imshow(density, origin="lower", aspect="auto", cmap="RdBu_r", vmin=0.0, vmax=2.0,
                  extent=(0.5, dimensions + 0.5, 0.0, 1.0), interpolation="nearest")
        verdict = verdicts.get((problem, label)) or verdicts.get(("", label))
        ax.set_title(label + (": " + verdict if verdict else ""), fontsize=7)
        ax.set_xlabel("dimension")
    for ax in axes[len(by_algorithm):]:
        ax.set_visible(False)
    axes[0].set_ylabel("final x")
    fig.suptitle(folder.title(problem, "final best points per dimension, density / uniform "
                                       "(white 1, red more, blue fewer)"),
                 y=1 - 0.04 / fig.get_figheight(), va="top")
    return fig


def overhead_figure(job, folder, rows):
    """COCO's timing figure: median wall time per evaluation against the dimension (log-log), one line
    per algorithm, from the report's overhead table (a study of the sphere at several dimensions)."""
    by_algorithm = group(rows, "Algorithm")
    labels = list(by_algorithm)
    fig, (ax,), ncol = new_figure(COLUMN, legend_labels=[label for (label,) in labels], panel_height=2.0)
    left_out = LeftOut()
    handles = []
    for i, ((label,), r) in enumerate(by_algorithm.items()):
        points = sorted((number(row["Dimension"]), number(row["Median time per evaluation (us)"])) for row in r)
        points = [(d, t) for d, t in points if left_out.keep(d, True) and left_out.keep(t, True)]
        handles.append(algorithm_line(ax, folder, label, [d for d, _ in points], [t for _, t in points], True, i))
    log_axis(ax, "x")
    log_axis(ax, "y")
    ax.set_xlabel("dimension")
    ax.set_ylabel("wall time per evaluation (us)")
    ax.set_title("Time per evaluation (COCO's timing)" + folder.suffix)
    shared_legend(fig, handles, [h.get_label() for h in handles], ncol)
    finish_note(job, ax, left_out, True, "times")
    return fig


def critical_difference_figure(job, folder, rows):
    left_out = LeftOut()
    ranked = sorted((number(r["average_rank"]), label_of(r)) for r in rows
                    if left_out.keep(number(r["average_rank"]), False))
    cd = number(rows[0]["cd"])
    k = len(rows)
    fig = Figure(figsize=(TWO_COLUMNS if k > 6 else COLUMN, 0.75 + 0.17 * k))
    fig.subplots_adjust(left=0.03, right=0.97, top=0.97, bottom=0.02)
    ax = fig.add_subplot()
    ax.set_xlim(0.5, k + 1.6)
    ax.set_ylim(-k - 0.8, 2.1)
    ax.axhline(0, xmax=(k + 0.5 - 0.5) / (k + 1.1), color="black", linewidth=0.8)
    for r in range(1, k + 1):
        ax.plot([r, r], [0, 0.15], color="black", linewidth=0.8)
        ax.text(r, 0.3, str(r), ha="center", fontsize=7)
    if math.isfinite(cd):
        ax.plot([1, 1 + cd], [1.3, 1.3], color="black", linewidth=1.5)
        ax.text(1, 1.5, "CD = %.3g (alpha %s, %s problems)%s" % (cd, rows[0]["alpha"], rows[0]["problems"],
                                                                 folder.suffix), ha="left", fontsize=7)
    for i, (rank, name) in enumerate(ranked):
        y = -(i + 1) * 0.9
        colour, marker, _ = folder.styles.of(name)
        ax.plot([rank, rank], [0, y], color=colour, linewidth=0.8)
        ax.plot([rank], [y], marker=marker, color=colour, markersize=3.5)
        ax.text(rank + 0.08, y, "%s (%.2f)" % (name, rank), va="center", fontsize=7)
    # Bars under the axis join the maximal groups whose ranks lie within CD of each other.
    last_end, level = -1, 0
    for i in range(len(ranked) if math.isfinite(cd) else 0):
        j = i
        while j + 1 < len(ranked) and ranked[j + 1][0] - ranked[i][0] < cd:
            j += 1
        if j > i and j > last_end:
            level += 1
            ax.plot([ranked[i][0] - 0.05, ranked[j][0] + 0.05], [-0.22 * level, -0.22 * level], color="black",
                    linewidth=2.5)
            last_end = j
    ax.axis("off")
    finish_note(job, ax, left_out, bool(ranked), "average ranks")
    return fig


def short_reading(reading):
    if not reading:
        return "see effects table"
    if reading.startswith("no significant"):
        return "n.s."
    if reading.endswith(": helps"):
        return "helps"
    if reading.endswith(": hurts"):
        return "hurts"
    return reading.split(":")[0] + " (significant)" if reading.startswith("interaction") else "inspect"


def level_x(level):
    return 0 if level == "off" else 1


def problem_style(index):
    """Problems in effects plots: neutral tones with their own markers (algorithms own the colours)."""
    tones = ["#222222", "#777777", "#444444", "#999999", "#333333", "#666666"]
    return tones[index % len(tones)], MARKERS[index % len(MARKERS)], LINESTYLES[index % len(LINESTYLES)]


def effects_main(job, folder, design, rows, readings):
    """One panel per switch, one line per problem (pooled one thick and black)."""
    mains = [r for r in rows if not r["factor2"]]
    factors = list(OrderedDict.fromkeys(r["factor"] for r in mains))
    problems = list(OrderedDict.fromkeys(r["problem"] for r in mains))
    if not factors:
        return None
    names = [effects_problem_name(folder, p) for p in problems]
    cols = min(len(factors), 4)
    fig, axes, ncol = new_figure(TWO_COLUMNS if cols > 1 else COLUMN, rows=math.ceil(len(factors) / cols),
                                 cols=cols, panel_height=1.5, legend_labels=names, title_lines=2, sharey=True,
                                 wspace=0.25)
    dropped, handles = 0, []
    for ax, factor in zip(axes, factors):
        for p, problem in enumerate(problems):
            points = [(level_x(r["level"]), number(r["mean_response"])) for r in mains
                      if r["factor"] == factor and r["problem"] == problem]
            kept = [(x, y) for x, y in points if math.isfinite(y)]
            dropped += len(points) - len(kept)
            colour, marker, linestyle = problem_style(p)
            pooled = problem.startswith("all problems")
            line = ax.plot([x for x, _ in kept], [y for _, y in kept], color="black" if pooled else colour,
                           marker=marker, linestyle="-" if pooled else linestyle, linewidth=1.8 if pooled else 1.0,
                           label=names[p])[0]
            if ax is axes[0]:
                handles.append(line)
        reading = readings.get((design, pooled_problem(problems), factor), "")
        ax.set_title("%s: %s" % (factor, short_reading(reading)))
        ax.set_xticks([0, 1])
        ax.set_xticklabels(["off", "on"])
        ax.set_xlim(-0.3, 1.3)
    for ax in axes[len(factors):]:
        ax.set_visible(False)
    axes[0].set_ylabel("mean " + rows[0]["scale"])
    fig.suptitle("Main effects, %s%s" % (design, folder.suffix))
    shared_legend(fig, handles, names, ncol)
    if dropped:
        job.note("left out %d non-finite value%s" % (dropped, "" if dropped == 1 else "s"))
    return fig


def effects_problem_name(folder, problem):
    return problem if problem.startswith("all problems") else folder.problems.name(problem)


def pooled_problem(problems):
    """The problem whose readings a panel title gives: the pooled one, else the only (or first) one."""
    return next((p for p in problems if p.startswith("all problems")), problems[0] if problems else "")


def effects_interaction(job, folder, design, rows, readings):
    problems = list(OrderedDict.fromkeys(r["problem"] for r in rows))
    problem = pooled_problem(problems)
    rows = [r for r in rows if r["problem"] == problem]
    pairs = list(OrderedDict.fromkeys((r["factor"], r["factor2"]) for r in rows if r["factor2"]))
    if not pairs:
        return None
    cols = min(len(pairs), 3)
    fig, axes, ncol = new_figure(TWO_COLUMNS if cols > 1 else COLUMN, rows=math.ceil(len(pairs) / cols),
                                 cols=cols, panel_height=1.5, legend_labels=["B off", "B on"], title_lines=2,
                                 sharey=True, wspace=0.25)
    dropped, handles = 0, []
    for ax, (a, b) in zip(axes, pairs):
        for level_b, linestyle, marker in (("off", "--", "o"), ("on", "-", "s")):
            points = [(level_x(r["level"]), number(r["mean_response"])) for r in rows
                      if r["factor"] == a and r["factor2"] == b and r["level2"] == level_b]
            kept = [(x, y) for x, y in points if math.isfinite(y)]
            dropped += len(points) - len(kept)
            line = ax.plot([x for x, _ in kept], [y for _, y in kept], color="black" if level_b == "on" else NEUTRAL,
                           marker=marker, linestyle=linestyle, label="%s %s" % (b, level_b))[0]
            if ax is axes[0]:
                handles.append(line)
            ax.text(1.05, kept[-1][1] if kept else 0, "%s %s" % (b, level_b), fontsize=6, va="center")
        effect = "%s x %s" % (a, b)
        ax.set_title("%s: %s" % (effect, short_reading(readings.get((design, problem, effect), ""))))
        ax.set_xticks([0, 1])
        ax.set_xticklabels([a + " off", a + " on"])
        ax.set_xlim(-0.3, 1.5)
    for ax in axes[len(pairs):]:
        ax.set_visible(False)
    axes[0].set_ylabel("mean " + rows[0]["scale"])
    fig.suptitle("Interactions, %s\n%s%s" % (design, effects_problem_name(folder, problem), folder.suffix))
    shared_legend(fig, handles, ["second switch off (dashed)", "second switch on (solid)"], ncol)
    if dropped:
        job.note("left out %d non-finite value%s" % (dropped, "" if dropped == 1 else "s"))
    return fig


def effects_overview(job, folder, design, rows):
    names = list(OrderedDict.fromkeys(r["Effect"] for r in rows))
    problems = list(OrderedDict.fromkeys(r["Problem"] for r in rows))
    labels = [effects_problem_name(folder, p) for p in problems]
    fig, (ax,), ncol = new_figure(TWO_COLUMNS, panel_height=0.3 + 0.16 * len(names) * len(problems),
                                  legend_labels=labels, left=1.2, title_lines=1)
    height = 0.8 / max(1, len(problems))
    dropped, handles = 0, []
    for p, problem in enumerate(problems):
        by_effect = {r["Effect"]: r for r in rows if r["Problem"] == problem}
        ys, values, significant = [], [], []
        for i, effect in enumerate(names):
            row = by_effect.get(effect)
            value = number(row["Mean"]) if row else math.nan
            if not math.isfinite(value):
                dropped += 1 if row else 0
                continue
            ys.append(i + p * height)
            values.append(value)
            significant.append(short_reading(row["Reading"]) != "n.s.")
        colour = "black" if problem.startswith("all problems") else problem_style(p)[0]
        bars = ax.barh(ys, values, height=height * 0.92, color=colour, label=labels[p])
        for bar, yes in zip(bars, significant):
            if not yes:
                bar.set(hatch="////", facecolor="white", edgecolor=colour, linewidth=0.5)
        handles.append(bars)
    ax.axvline(0, color="black", linewidth=0.6)
    ax.set_yticks([i + 0.4 - height / 2 for i in range(len(names))])
    ax.set_yticklabels(names)
    ax.invert_yaxis()
    ax.grid(False, axis="y")
    scales = sorted(set(r["Scale"] for r in rows))
    ax.set_xlabel("mean effect on %s (negative: helps; hatched: not significant, Holm)" % " / ".join(scales))
    ax.set_title(design + folder.suffix)
    shared_legend(fig, handles, labels, ncol)
    if dropped:
        job.note("left out %d non-finite value%s" % (dropped, "" if dropped == 1 else "s"))
    return fig


# ----------------------------------------------------------------------------------------------

def simplex_xy(reference_better, equivalent):
    """A point (theta_reference_better, theta_equivalent, theta_algorithm_better) of the simplex drawn
    as an equilateral triangle: reference better at the bottom left, the algorithm at the bottom right,
    equivalent (inside the ROPE) at the top."""
    return 1 - reference_better - equivalent / 2, equivalent * math.sqrt(3) / 2


def bayesian_simplex(job, folder, problem, rows, tests):
    """Benavoli et al. (2017)'s simplex of the Bayesian signed-rank test: a panel per algorithm
    against the reference, the posterior samples of theta as a cloud, the lines from the centre
    splitting the triangle where each region's mass is the largest, each vertex with its probability."""
    by_algorithm = group(rows, "algorithm")
    cols = min(len(by_algorithm), 3)
    nrows = math.ceil(len(by_algorithm) / cols)
    fig = Figure(figsize=(COLUMN if cols == 1 else TWO_COLUMNS, 0.35 + 2.2 * nrows))
    fig.subplots_adjust(left=0.02, right=0.98, top=1 - 0.35 / fig.get_figheight(), bottom=0.02, wspace=0.15)
    centre = simplex_xy(1 / 3, 1 / 3)
    for i, ((label,), samples) in enumerate(by_algorithm.items()):
        ax = fig.add_subplot(nrows, cols, i + 1)
        ax.set_aspect("equal")
        ax.axis("off")
        corners = [simplex_xy(1, 0), simplex_xy(0, 0), simplex_xy(0, 1), simplex_xy(1, 0)]
        ax.plot([c[0] for c in corners], [c[1] for c in corners], color="black", linewidth=0.8)
        for half in ((0.5, 0.5), (0.5, 0), (0, 0.5)):  # midpoints: two regions' masses equal
            edge = simplex_xy(*half)
            ax.plot([centre[0], edge[0]], [centre[1], edge[1]], color=NEUTRAL, linewidth=0.6, linestyle="--")
        colour = folder.styles.of(label)[0]
        xy = [simplex_xy(number(r["theta_reference_better"]), number(r["theta_equivalent"])) for r in samples]
        ax.scatter([p[0] for p in xy], [p[1] for p in xy], s=2, color=colour, alpha=0.35, linewidths=0)
        test = tests.get((problem, label), {})
        reference = test.get("reference", "reference")

        def probability(key, test=test):
            return "P = %.3f" % number(test[key]) if key in test else ""

        ax.text(0, -0.04, "%s better\n%s" % (reference, probability("p_reference_better")), ha="center",
                va="top", fontsize=6.5)
        ax.text(1, -0.04, "%s better\n%s" % (label, probability("p_algorithm_better")), ha="center",
                va="top", fontsize=6.5)
        ax.text(0.5, math.sqrt(3) / 2 + 0.03, "equivalent\n%s" % probability("p_equivalent"), ha="center",
                va="bottom", fontsize=6.5)
        ax.set_xlim(-0.25, 1.25)
        ax.set_ylim(-0.25, 1.0)
        ax.set_title("%s vs %s (ROPE %s)" % (label, reference, test.get("rope") or "none"), fontsize=7.5)
    fig.suptitle("Bayesian signed-rank test, %s: posterior samples of theta%s" % (
        folder.problems.name(problem), folder.suffix), y=1 - 0.04 / fig.get_figheight(), va="top", fontsize=8)
    return fig


def report_folders(report):
    budgets = read_rows(os.path.join(report, "budgets.csv"))
    return [os.path.join(report, row.get("directory") or "") for row in budgets] if budgets else [report]


def main():
    args = sys.argv[1:]
    plan_only = bool(args) and args[0] == "--plan"
    if plan_only:
        args = args[1:]
    if len(args) != 1:
        sys.exit("usage: plot_study.py [--plan] REPORT_DIR")
    if not plan_only:
        import_matplotlib()
    jobs, failures = [], []
    for report in report_folders(args[0]):
        try:
            folder, folder_jobs = plan_folder(report)
        except Exception as error:  # noqa: BLE001 - one folder's unreadable CSV must not stop the others
            failures.append("figure (all of %s) failed: %s" % (report, one_line(error)))
            continue
        jobs.extend(folder_jobs)
        if not plan_only:
            os.makedirs(folder.out_dir, exist_ok=True)
            remove_stale_figures(folder.out_dir, {job.name for job in folder_jobs})
            with open(os.path.join(folder.out_dir, "styles.csv"), "w") as f:
                f.write(folder.styles.csv_text())
    if plan_only:
        for kind, count in OrderedDict((j.kind, sum(1 for k in jobs if k.kind == j.kind)) for j in jobs).items():
            print("%s %d" % (kind, count))
        return
    warm_up(any(job.kind == "parameters" for job in jobs))
    # Drawn costliest first, so that the workers end together (the longest-processing-time rule);
    # the results, notes among them, are read in the plan's order.
    order = sorted(range(len(jobs)), key=lambda i: -jobs[i].cost())
    results = [None] * len(jobs)
    for i, result in zip(order, run_jobs([jobs[i] for i in order])):
        results[i] = result
    drawn = sum(r["drawn"] for r in results)
    failures += [r["failed"] for r in results if r["failed"]]
    for result in results:
        for line in result["notes"]:
            print(line)
    for line in failures:
        sys.stderr.write(line + "\n")
    if failures:
        print("figures: %d drawn, %d failed (each named on stderr)" % (drawn, len(failures)))
    if failures and not drawn:
        sys.stderr.write("no figure could be drawn (%d failed)\n" % len(failures))
        sys.exit(1)


if __name__ == "__main__":
    try:
        main()
    except (Interrupted, KeyboardInterrupt):
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        sys.stderr.write("figures interrupted\n")
        sys.exit(EXIT_INTERRUPTED)
