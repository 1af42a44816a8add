#!/usr/bin/python3
"""A mhbench study directory as pandas DataFrames.

    import mhbench_study
    study = mhbench_study.load_study("studies/paper")
    study.runs                       # one row per run, labelled, best_x as columns x1..xD
    study.curves                     # best-so-far per iteration, long (tidy) form
    study.report().tables["summary"] # a statistics table of the report, as its CSV holds it

Each file has its loader (load_runs, load_curves, load_checkpoints, load_improvements,
load_trajectories, load_timings, load_algorithms, load_report); load_study reads them all. Every
number is read exactly as mhbench wrote it (the shortest decimal of a double, so a value read
here is the double mhbench computed), `inf` and `-inf` included; an empty cell is NaN (numbers)
or <NA> (integers). A missing or malformed file is a StudyError whose one-line message names it.

The run tables share these columns, from runs.csv (results/store/run_fields.hpp):
    run_id       the run's number in the study (runs.csv is sorted by it)
    algorithm    the optimiser's canonical spec (`name:key=value,...`, defaults dropped)
    label        its display name, from algorithms.csv (the spec when the study has none)
    problem      the problem's canonical spec
    budget       the run's budget as the study wrote it (e.g. `evaluations=10000`); "" when
                 runs.csv predates budgets
    run          the 0-based run index: runs with the same index share a seed under common
                 random numbers
The columns of the report's files are in the report's README.md (its data dictionary, written by
results/report/report_readme.cpp). Standard library and pandas only (Debian's python3-pandas,
imported from /usr/bin/python3).
"""

import dataclasses
import pathlib
import sys

import pandas as pd

__all__ = [
    "StudyError", "Study", "Report", "load_study", "load_runs", "load_algorithms", "load_curves",
    "load_checkpoints", "load_improvements", "load_trajectories", "load_timings", "load_report",
]

# The columns every run table gets from runs.csv, to say which run a row belongs to.
RUN_KEY = ["run_id", "algorithm", "label", "problem", "budget", "run"]

# The report's curve data and other data files (its README.md describes each); every other CSV of
# a report folder is a statistics table, <id>.csv.
REPORT_DATA_FILES = [
    "curves_iteration", "curves_evaluations", "parameters_iteration", "final_values",
    "target_hits", "critical_difference", "effect_means", "relative_gap_medians",
]

# Columns of text in the report's files, never read as numbers (a label may look like one).
_TEXT_COLUMNS = {
    "problem", "algorithm", "label", "parameter", "name", "design", "scale", "factor", "level",
    "factor2", "level2", "budget", "directory",
    # the statistics tables' headers
    "Problem", "Algorithm", "Label", "Spec", "Full spec",
}

# Columns of counts in the report's data files: integers (Int64) even when every cell is empty,
# as evals_to_target is in a study without a target.
_INTEGER_COLUMNS = {"run", "runs", "iteration", "evaluations", "evals_to_target", "problems", "blocks",
                    "failed", "reached"}


class StudyError(Exception):
    """A study file that is missing or not what mhbench writes; the message names the file."""


@dataclasses.dataclass
class Report:
    """One budget's report: the folder mhbench report wrote for it.

    directory  the folder (DIR/report, or DIR/report/<budget slug> when the study has several)
    budget     the budget its runs had ("" when the report does not say: budget.txt missing)
    tables     statistics table id -> DataFrame (<id>.csv: the columns are the table's header,
               a cell that shows two numbers, "median (IQR) marker", stays text)
    data       data file name -> DataFrame: curves_iteration, curves_evaluations,
               parameters_iteration, final_values, target_hits and, when written,
               critical_difference, effect_means, relative_gap_medians
    """

    directory: pathlib.Path
    budget: str
    tables: dict
    data: dict


@dataclasses.dataclass
class Study:
    """A study directory read by load_study: every file as a DataFrame (None when absent)."""

    directory: pathlib.Path
    algorithms: pd.DataFrame
    runs: pd.DataFrame
    curves: pd.DataFrame
    checkpoints: pd.DataFrame
    improvements: pd.DataFrame
    trajectories: pd.DataFrame
    timings: pd.DataFrame
    reports: dict  # budget -> Report; empty when the study has no report

    def report(self, budget=None):
        """The report of `budget`, or the only one when budget is None."""
        if not self.reports:
            raise StudyError(f"{self.directory / 'report'}: no report "
                             f"(`mhbench report {self.directory}` writes it)")
        if budget is None:
            if len(self.reports) > 1:
                raise StudyError(f"{self.directory / 'report'}: {len(self.reports)} budgets, name one of "
                                 + ", ".join(repr(b) for b in self.reports))
            return next(iter(self.reports.values()))
        if budget not in self.reports:
            raise StudyError(f"{self.directory / 'report'}: no budget {budget!r} (it has "
                             + ", ".join(repr(b) for b in self.reports) + ")")
        return self.reports[budget]


# ---------------------------------------------------------------------------------------------
# Reading CSV files exactly


def _read_csv(path, required=()):
    """The CSV file `path` as a DataFrame of strings, every cell as written ('' when empty)."""
    path = pathlib.Path(path)
    try:
        frame = pd.read_csv(path, dtype=str, keep_default_na=False, na_filter=False, engine="c")
    except FileNotFoundError:
        raise StudyError(f"{path}: no such file") from None
    except pd.errors.EmptyDataError:
        raise StudyError(f"{path}: empty (no header line)") from None
    except (pd.errors.ParserError, UnicodeDecodeError) as e:
        raise StudyError(f"{path}: not a CSV file mhbench wrote: {_first_line(e)}") from None
    missing = [c for c in required if c not in frame.columns]
    if missing:
        raise StudyError(f"{path}: no column {', '.join(repr(c) for c in missing)} "
                         f"(its header: {','.join(frame.columns)})")
    return frame


def _first_line(error):
    """The first line of an exception's message."""
    return str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__


def _bad_cell(path, frame, column, description, valid):
    """The StudyError of the first cell of `column` that `valid` refuses, as not `description`."""
    for row, text in enumerate(frame[column]):
        if not valid(text):
            # Line 1 is the header; mhbench writes one row per line.
            return StudyError(f"{path}, line {row + 2}, column '{column}': {text!r} is not {description}")
    return StudyError(f"{path}, column '{column}': not {description}")


def _parses(convert, text):
    """Whether convert(text) succeeds (float or int)."""
    try:
        convert(text)
        return True
    except (ValueError, OverflowError):
        return False


def _numbers(frame, path, column):
    """Column `column` of strings as float64: exact (Python's float), '' as NaN."""
    texts = frame[column]
    try:
        return texts.where(texts != "", "nan").astype("float64")
    except ValueError:
        raise _bad_cell(path, frame, column, "a number", lambda t: t == "" or _parses(float, t)) from None


def _integers(frame, path, column):
    """Column `column` of strings as integers: int64, or nullable Int64 when a cell is empty."""
    texts = frame[column]
    try:
        if (texts == "").any():
            return pd.array([int(t) if t != "" else None for t in texts], dtype="Int64")
        return texts.astype("int64")
    except (ValueError, OverflowError):
        raise _bad_cell(path, frame, column, "an integer", lambda t: t == "" or _parses(int, t)) from None


def _infer(frame, path, text_columns=_TEXT_COLUMNS):
    """Every column of strings as integers, numbers or text, whichever all its cells are.

    A column of text (a name in text_columns) stays text; an empty column is NaN, or <NA> for a
    count (_INTEGER_COLUMNS).
    """
    out = frame.copy()
    for column in frame.columns:
        if column in text_columns:
            continue
        texts = frame[column]
        filled = texts[texts != ""]
        if filled.empty:
            empty = pd.array([None] * len(texts), dtype="Int64") if column in _INTEGER_COLUMNS else None
            out[column] = _numbers(frame, path, column) if empty is None else empty
        elif filled.str.fullmatch(r"-?\d{1,18}").all():
            out[column] = _integers(frame, path, column)
        else:
            try:
                out[column] = texts.where(texts != "", "nan").astype("float64")
            except ValueError:
                pass  # text, e.g. "1.2e-3 (4e-4) +"
    return out


# ---------------------------------------------------------------------------------------------
# The study's files


def load_algorithms(study_dir):
    """algorithms.csv: one row per algorithm of the study, or None when the study has none.

    Columns:
        algorithm   the canonical spec, as runs.csv's `algorithm` column writes it
        label       the display name: the spec's `label=`, a grid label such as itlbo[T-S+O-],
                    or the spec
        parameters  the full spec: every declared parameter with its value, defaults included,
                    e.g. tlbo:np=50,r=coordinate
    """
    path = pathlib.Path(study_dir) / "algorithms.csv"
    if not path.exists():
        return None
    frame = _read_csv(path, required=["algorithm", "label"])
    twice = frame["algorithm"][frame["algorithm"].duplicated()]
    if len(twice):
        raise StudyError(f"{path}: algorithm {twice.iloc[0]!r} is listed twice")
    return frame


def _labels(study_dir, specs):
    """spec -> label for each of `specs`: algorithms.csv's label, or the spec itself."""
    algorithms = load_algorithms(study_dir)
    known = {} if algorithms is None else dict(zip(algorithms["algorithm"], algorithms["label"]))
    return specs.map(lambda spec: known.get(spec, spec))


def _split_best_x(frame, path):
    """best_x ('1.5 -2 0.25', one space between numbers) as columns x1..xD (NaN past a run's D)."""
    texts = frame["best_x"]
    values = []
    for row, text in enumerate(texts):
        try:
            values.append([float(v) for v in text.split(" ")] if text != "" else [])
        except ValueError:
            raise StudyError(f"{path}, line {row + 2}, column 'best_x': {text!r} is not numbers "
                             "separated by single spaces") from None
    width = max((len(v) for v in values), default=0)
    columns = {f"x{k + 1}": [v[k] if k < len(v) else float("nan") for v in values] for k in range(width)}
    return pd.DataFrame(columns, index=frame.index, dtype="float64"), [len(v) for v in values]


def load_runs(study_dir):
    """runs.csv: one row per run, with its label, its best point as columns and typed values.

    Columns, in order (results/store/run_fields.hpp, the report's README.md):
        run_id, algorithm, label, problem, budget, run   the run (see the module's docstring)
        seed             the seed of its random stream (uint64)
        status           category: ok, or failed (an optimiser or problem threw, an external
                         program crashed: the run is no result and every report leaves it out)
        ok               bool: status == "ok"
        evaluations      objective evaluations it spent
        iterations       iterations it completed
        best_f           its final best-so-far f (NaN for a failed run)
        f_opt            the problem's known minimum f*, NaN when unknown
        error            best_f - f_opt (NaN without f* or for a failed run)
        evals_to_target  the evaluation at which it reached the study's target, <NA> when it
                         did not or the study has no target (Int64)
        dim              D, the number of values of best_x
        x1 .. xD         best_x, its final best point, one column per coordinate (NaN past a
                         run's own D when the study mixes dimensions)
        P, P_true, P_opt, P_err_pct
                         for each named parameter P of the study (pmsm: Rs, Ld, Lq, psi, ...):
                         the identified value, the value that generated the data, the value at
                         the known optimum and the error in % of the true value (NaN when the
                         run's problem has no such value)
        message          why a failed run failed ("" for a run that is ok)
    Columns a newer mhbench adds after message are kept, typed by their cells.
    """
    path = pathlib.Path(study_dir) / "runs.csv"
    raw = _read_csv(path, required=["run_id", "algorithm", "problem", "run", "seed", "status", "evaluations",
                                    "iterations", "best_f", "f_opt", "best_x", "message"])
    if "budget" not in raw.columns:  # runs.csv from before budgets
        raw.insert(raw.columns.get_loc("problem") + 1, "budget", "")
    bad = raw.index[~raw["status"].isin(["ok", "failed"])]
    if len(bad):
        raise StudyError(f"{path}, line {bad[0] + 2}, column 'status': {raw['status'][bad[0]]!r} "
                         "is not ok or failed")
    columns = list(raw.columns)
    first, end = columns.index("best_x") + 1, columns.index("message")
    parameters = columns[first:end]  # P, P_true, P_opt, P_err_pct per named parameter
    x, dims = _split_best_x(raw, path)

    runs = pd.DataFrame(index=raw.index)
    runs["run_id"] = _integers(raw, path, "run_id")
    runs["algorithm"] = raw["algorithm"]
    runs["label"] = _labels(study_dir, raw["algorithm"])
    runs["problem"] = raw["problem"]
    runs["budget"] = raw["budget"]
    runs["run"] = _integers(raw, path, "run")
    runs["seed"] = _unsigned(raw, path, "seed")
    runs["status"] = pd.Categorical(raw["status"], categories=["ok", "failed"])
    runs["ok"] = raw["status"] == "ok"
    for column in ["evaluations", "iterations"]:
        runs[column] = _integers(raw, path, column)
    for column in ["best_f", "f_opt"]:
        runs[column] = _numbers(raw, path, column)
    runs["error"] = _numbers(raw, path, "error") if "error" in raw.columns else runs["best_f"] - runs["f_opt"]
    if "evals_to_target" in raw.columns:
        runs["evals_to_target"] = pd.array(_integers(raw, path, "evals_to_target"), dtype="Int64")
    runs["dim"] = pd.Series(dims, index=raw.index, dtype="int64")
    runs = pd.concat([runs, x], axis=1)
    for column in parameters:
        runs[column] = _numbers(raw, path, column)
    runs["message"] = raw["message"]
    later = columns[columns.index("message") + 1:]
    if later:
        runs = pd.concat([runs, _infer(raw[later], path)], axis=1)
    if runs["run_id"].duplicated().any():
        twice = runs["run_id"][runs["run_id"].duplicated()].iloc[0]
        raise StudyError(f"{path}: run_id {twice} is listed twice")
    return runs


def _unsigned(frame, path, column):
    """Column `column` as uint64 (a seed may exceed int64)."""
    def valid(text):
        return _parses(int, text) and 0 <= int(text) < 2**64
    if not frame[column].map(valid).all():
        raise _bad_cell(path, frame, column, "an unsigned 64-bit integer", valid)
    return pd.Series([int(t) for t in frame[column]], index=frame.index, dtype="uint64")


def _with_run_key(frame, runs, path):
    """`frame` (with a run_id column) with the key columns of its runs put in front."""
    unknown = ~frame["run_id"].isin(runs["run_id"])
    if unknown.any():
        raise StudyError(f"{path}, line {int(unknown.values.argmax()) + 2}: run_id "
                         f"{frame['run_id'][unknown].iloc[0]} is not a run of runs.csv")
    keyed = frame.merge(runs[RUN_KEY], on="run_id", how="left", validate="many_to_one")
    return keyed[RUN_KEY + [c for c in frame.columns if c != "run_id"]]


def _optional_path(study_dir, name):
    """DIR/name, or None when the study does not have that file."""
    path = pathlib.Path(study_dir) / name
    return path if path.exists() else None


def _runs_or_load(study_dir, runs):
    """`runs` if given (the caller read runs.csv already), else runs.csv read now."""
    return load_runs(study_dir) if runs is None else runs


def load_curves(study_dir, runs=None):
    """curves.csv: best-so-far f after each iteration of each run, long form.

    Columns: run_id, algorithm, label, problem, budget, run (the run, from runs.csv), then
        iteration    0 = after the initial population, k = after iteration k
        evaluations  objective evaluations spent by then
        best_f       the run's best-so-far f at that point
        error        best_f - f_opt (NaN when the problem has no known f*)
    A run's curve ends at its last iteration (where its budget or target stopped it); every run
    of runs.csv has its curve, a failed run the part before it failed. `runs` (load_runs' frame)
    spares reading runs.csv again.
    """
    path = pathlib.Path(study_dir) / "curves.csv"
    runs = _runs_or_load(study_dir, runs)
    raw = _read_csv(path, required=["run_id", "iteration", "evaluations", "best_f"])
    curves = pd.DataFrame({c: _integers(raw, path, c) for c in ["run_id", "iteration", "evaluations"]})
    curves["best_f"] = _numbers(raw, path, "best_f")
    curves = _with_run_key(curves, runs, path)
    f_opt = curves["run_id"].map(runs.set_index("run_id")["f_opt"])
    curves["error"] = curves["best_f"] - f_opt
    return curves


def load_checkpoints(study_dir, runs=None):
    """checkpoints.csv: best-so-far f on the evaluation grid every run shares, long form.

    Columns: run_id, algorithm, label, problem, budget, run (the run), then
        evaluations  a count of the grid (about ten a decade: 1, 2, 3, 4, 5, 6, 8, 10, 13, ...),
                     up to the run's last evaluation
        best_f       its best-so-far f after exactly that many evaluations
        error        best_f - f_opt (NaN when the problem has no known f*)
    """
    path = pathlib.Path(study_dir) / "checkpoints.csv"
    runs = _runs_or_load(study_dir, runs)
    raw = _read_csv(path, required=["run_id", "evaluations", "best_f"])
    points = pd.DataFrame({c: _integers(raw, path, c) for c in ["run_id", "evaluations"]})
    points["best_f"] = _numbers(raw, path, "best_f")
    points = _with_run_key(points, runs, path)
    points["error"] = points["best_f"] - points["run_id"].map(runs.set_index("run_id")["f_opt"])
    return points


def load_improvements(study_dir, runs=None):
    """improvements.csv: every strict improvement of each run's best-so-far f, or None.

    Columns: run_id, algorithm, label, problem, budget, run (the run), then
        event        category: improvement (best-so-far f became f at that evaluation), or last
                     (one row per run: its last evaluation and its final f)
        evaluations  the evaluation (1-based count) that made it
        f            best-so-far f from that evaluation on
    Studies written before mhbench recorded improvements have no file (None); runs stored before
    then have no rows.
    """
    path = _optional_path(study_dir, "improvements.csv")
    if path is None:
        return None
    runs = _runs_or_load(study_dir, runs)
    raw = _read_csv(path, required=["run_id", "event", "evaluations", "f"])
    bad = raw.index[~raw["event"].isin(["improvement", "last"])]
    if len(bad):
        raise StudyError(f"{path}, line {bad[0] + 2}, column 'event': {raw['event'][bad[0]]!r} is not "
                         "improvement or last")
    points = pd.DataFrame({"run_id": _integers(raw, path, "run_id")})
    points["event"] = pd.Categorical(raw["event"], categories=["improvement", "last"])
    points["evaluations"] = _integers(raw, path, "evaluations")
    points["f"] = _numbers(raw, path, "f")
    return _with_run_key(points, runs, path)


def load_trajectories(study_dir, runs=None):
    """trajectories.csv: the best point's named parameters after each iteration, or None.

    Written for problems with named parameters (pmsm: Rs, Ld, Lq, psi, Vdt). Columns: run_id,
    algorithm, label, problem, budget, run (the run), iteration (as in load_curves), then one
    column per parameter of the study (NaN where the run's problem has no such parameter).
    None when the study has no file or no named parameters.
    """
    path = _optional_path(study_dir, "trajectories.csv")
    if path is None:
        return None
    runs = _runs_or_load(study_dir, runs)
    raw = _read_csv(path, required=["run_id", "iteration"])
    points = pd.DataFrame({c: _integers(raw, path, c) for c in ["run_id", "iteration"]})
    for column in raw.columns[2:]:
        points[column] = _numbers(raw, path, column)
    return _with_run_key(points, runs, path)


def load_timings(study_dir, runs=None):
    """timings.csv: wall-clock seconds each run took, or None without the file.

    Columns: run_id, algorithm, label, problem, budget, run (the run), wall_seconds (the one value
    that differs between two runs of one study: machine, load, threads).
    """
    path = _optional_path(study_dir, "timings.csv")
    if path is None:
        return None
    runs = _runs_or_load(study_dir, runs)
    raw = _read_csv(path, required=["run_id", "wall_seconds"])
    times = pd.DataFrame({"run_id": _integers(raw, path, "run_id"),
                          "wall_seconds": _numbers(raw, path, "wall_seconds")})
    return _with_run_key(times, runs, path)


# ---------------------------------------------------------------------------------------------
# The report


def _load_report_folder(folder, budget):
    """One budget's report folder as a Report."""
    tables, data = {}, {}
    for path in sorted(folder.glob("*.csv")):
        frame = _infer(_read_csv(path), path)
        (data if path.stem in REPORT_DATA_FILES else tables)[path.stem] = frame
    if not data:
        raise StudyError(f"{folder}: no curve data (curves_iteration.csv ...): not a report folder")
    if budget is None:
        budget_txt = folder / "budget.txt"
        budget = budget_txt.read_text().strip() if budget_txt.exists() else ""
    return Report(directory=folder, budget=budget, tables=tables, data=data)


def load_report(study_dir, report_dir=None):
    """The study's report (DIR/report, or report_dir) as budget -> Report; {} without a report.

    A study with one budget has its report in report/ itself (one entry); a study with several
    has one folder per budget, listed in report/budgets.csv (budget,directory), each a Report.
    Each Report's tables are the statistics tables (<id>.csv, what the report's README.md lists
    under "Tables", the caption saying what each column means) and its data the curve data and
    the other data files (the README's "Curve data": final_values, target_hits, ...). Numbers in
    them are read exactly; a column of integers (run, runs, evaluations) is int64, or Int64 when
    a cell is empty.
    """
    folder = pathlib.Path(report_dir) if report_dir is not None else pathlib.Path(study_dir) / "report"
    if not folder.is_dir():
        return {}
    index = folder / "budgets.csv"
    if not index.exists():
        if not any(folder.glob("*.csv")):
            return {}
        report = _load_report_folder(folder, None)
        return {report.budget: report}
    budgets = _read_csv(index, required=["budget", "directory"])
    reports = {}
    for budget, directory in zip(budgets["budget"], budgets["directory"]):
        sub = folder / directory
        if not sub.is_dir():
            raise StudyError(f"{index}: budget {budget!r}: no folder {sub}")
        reports[budget] = _load_report_folder(sub, budget)
    return reports


def load_study(study_dir, report_dir=None):
    """Every file of a finished study directory (and its report) as a Study.

    Study fields: directory, algorithms, runs, curves, checkpoints, improvements, trajectories,
    timings (each as its load_* function returns it; None for an optional file the study does
    not have) and reports (load_report). study.report() is the only budget's Report,
    study.report(budget) one budget's.
    """
    directory = pathlib.Path(study_dir)
    if not (directory / "runs.csv").exists():
        if not directory.is_dir():
            raise StudyError(f"{directory}: no such directory")
        raise StudyError(f"{directory / 'runs.csv'}: no such file (not a study directory, or a study "
                         "that has not finished: run its command again)")
    runs = load_runs(directory)
    return Study(directory=directory, algorithms=load_algorithms(directory), runs=runs,
                 curves=load_curves(directory, runs), checkpoints=load_checkpoints(directory, runs),
                 improvements=load_improvements(directory, runs),
                 trajectories=load_trajectories(directory, runs), timings=load_timings(directory, runs),
                 reports=load_report(directory, report_dir))


def _main(argv):
    """`mhbench_study.py DIR`: a summary of what the study holds, to check it reads."""
    if len(argv) != 2:
        print("usage: mhbench_study.py STUDY_DIR", file=sys.stderr)
        return 2
    try:
        study = load_study(argv[1])
    except StudyError as e:
        print(f"mhbench_study: {e}", file=sys.stderr)
        return 1
    print(f"{study.directory}: {len(study.runs)} runs, {study.runs['label'].nunique()} algorithms, "
          f"{study.runs['problem'].nunique()} problems, {study.runs['budget'].nunique()} budgets; "
          f"{len(study.curves)} curve points")
    for budget, report in study.reports.items():
        print(f"report{' of ' + budget if budget else ''}: tables {', '.join(report.tables)}; "
              f"data {', '.join(report.data)}")
    return 0


if __name__ == "__main__":
    sys.exit(_main(sys.argv))
