#!/usr/bin/python3
"""scripts/python/mhbench_study.py against the files of a real study, read again with csv alone.

    mhbench_study_test.py MHBENCH MODULE_DIR [unittest options]

Runs MHBENCH (the built or installed executable) to make a small study with two budgets and a
report in a scratch directory, loads it with the mhbench_study module found in MODULE_DIR, and
checks each DataFrame against an independent reading of the same file with the csv module: row
counts, the label joined to every run, best_x's numbers in x1..xD bit for bit, every number of
runs.csv, the curves, and every cell of the report's tables. Then the module's one-line errors
for missing and malformed files. Debian's python3-pandas (scripts/setup-debian.sh).
"""

import csv
import math
import pathlib
import shutil
import subprocess
import sys
import tempfile
import unittest

if len(sys.argv) < 3:
    sys.exit("usage: mhbench_study_test.py MHBENCH MODULE_DIR [unittest options]")
MHBENCH = sys.argv[1]
sys.path.insert(0, sys.argv[2])
try:
    import pandas as pd
except ImportError:
    sys.exit("python3-pandas is not installed: scripts/setup-debian.sh installs it")
import mhbench_study  # noqa: E402  (found through MODULE_DIR)

# The algorithms, one with a label unlike its spec; problems of two dimensions and one with named
# parameters (pmsm: Rs, Ld, Lq, psi); two budgets, the second with a target that runs reach.
STUDY = ["--algorithms", "itlbo tlbo:label=TLBO-x pso", "--problems", "sphere:dim=4 rastrigin:dim=2 pmsm",
         "--runs", "3", "--budget", "iterations=8", "--budget", "evaluations=1000,target=0.5",
         "--no-figures", "--threads", "2"]


def read_rows(path):
    """A CSV file as a list of dicts of strings (csv module only)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def same_number(value, text):
    """Whether a loaded cell holds exactly the number `text` ('' and 'nan' as missing)."""
    if text in ("", "nan"):
        return value is pd.NA or (isinstance(value, float) and math.isnan(value))
    if value is pd.NA or isinstance(value, str):
        return False
    return float(value) == float(text) and (not text.lstrip("-").isdigit() or int(value) == int(text))


def same_cell(value, text):
    """Whether a loaded cell is the CSV's text: as text, or as the number it reads."""
    if isinstance(value, str):
        return value == text
    return same_number(value, text)


class StudyModuleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = pathlib.Path(tempfile.mkdtemp(prefix="mhb_pandas_"))
        # Removed even when what follows fails (tearDownClass would not run then).
        cls.addClassCleanup(shutil.rmtree, cls.scratch, ignore_errors=True)
        cls.dir = cls.scratch / "study"
        done = subprocess.run([MHBENCH, "run", *STUDY, "--out", str(cls.dir)], capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"mhbench run failed ({done.returncode}): {done.stderr}")
        cls.study = mhbench_study.load_study(cls.dir)
        cls.csv_runs = read_rows(cls.dir / "runs.csv")
        cls.labels = {row["algorithm"]: row["label"] for row in read_rows(cls.dir / "algorithms.csv")}

    def copy_study(self, name):
        """A copy of the study's files (not its report) to break."""
        copy = self.scratch / name
        shutil.copytree(self.dir, copy, ignore=shutil.ignore_patterns("report", "store.bin"))
        return copy

    def label_of_run(self):
        """run_id -> the label algorithms.csv gives the run's algorithm."""
        return {int(row["run_id"]): self.labels[row["algorithm"]] for row in self.csv_runs}

    # runs.csv

    def test_runs_are_the_rows_of_runs_csv(self):
        runs = self.study.runs
        self.assertEqual(len(runs), len(self.csv_runs))
        self.assertEqual(len(runs), 3 * 3 * 2 * 3)
        self.assertEqual(list(runs["run_id"]), [int(row["run_id"]) for row in self.csv_runs])
        for column in ["algorithm", "problem", "budget", "message"]:
            self.assertEqual(list(runs[column]), [row[column] for row in self.csv_runs], column)

    def test_every_run_has_its_label_from_algorithms_csv(self):
        runs = self.study.runs
        self.assertEqual(list(runs["label"]), [self.labels[row["algorithm"]] for row in self.csv_runs])
        self.assertEqual(sorted(set(runs["label"])), ["ITLBO", "PSO", "TLBO-x"])
        self.assertTrue((runs.loc[runs["label"] == "TLBO-x", "algorithm"] == "tlbo").all())

    def test_best_x_columns_are_the_numbers_of_best_x(self):
        runs = self.study.runs
        width = max(len(row["best_x"].split(" ")) for row in self.csv_runs)
        self.assertEqual(width, 4)
        self.assertNotIn("best_x", runs.columns)
        for i, row in enumerate(self.csv_runs):
            values = [float(t) for t in row["best_x"].split(" ")]
            self.assertEqual(runs["dim"][i], len(values))
            for k in range(width):
                cell = runs[f"x{k + 1}"][i]
                if k < len(values):
                    self.assertEqual(cell, values[k], f"run {row['run_id']}, x{k + 1}")
                else:
                    self.assertTrue(math.isnan(cell), f"run {row['run_id']}, x{k + 1} past D")

    def test_every_number_of_runs_csv_is_read_exactly(self):
        runs = self.study.runs
        numeric = [c for c in self.csv_runs[0] if c not in ("algorithm", "problem", "budget", "status",
                                                            "best_x", "message")]
        self.assertIn("Rs_true", numeric)  # pmsm's parameter columns
        for i, row in enumerate(self.csv_runs):
            for column in numeric:
                self.assertTrue(same_number(runs[column][i], row[column]),
                                f"run {row['run_id']}, {column}: {runs[column][i]!r} "
                                f"read from {row[column]!r}")

    def test_errors_and_types(self):
        runs = self.study.runs
        self.assertEqual(str(runs["status"].dtype), "category")
        self.assertEqual(list(runs["ok"]), [row["status"] == "ok" for row in self.csv_runs])
        for column, dtype in [("run_id", "int64"), ("run", "int64"), ("seed", "uint64"),
                              ("evaluations", "int64"), ("best_f", "float64"), ("error", "float64"),
                              ("evals_to_target", "Int64")]:
            self.assertEqual(str(runs[column].dtype), dtype, column)
        for i, row in enumerate(self.csv_runs):
            self.assertEqual(float(row["error"]), float(row["best_f"]) - float(row["f_opt"]))
            self.assertEqual(runs["error"][i], runs["best_f"][i] - runs["f_opt"][i])
        # The second budget's target is reached by some runs, not by all.
        self.assertTrue(0 < runs["evals_to_target"].notna().sum() < len(runs))
        # Named parameters: values for pmsm's runs, none for the others.
        pmsm = runs["problem"].str.startswith("pmsm")
        self.assertTrue(runs.loc[pmsm, "Rs"].notna().all())
        self.assertTrue(runs.loc[~pmsm, "Rs"].isna().all())

    # The long files

    def check_run_key(self, frame, rows, name):
        """`frame` has the rows of `rows` in order, each with its run's label, problem and index."""
        self.assertEqual(len(frame), len(rows), name)
        self.assertEqual(list(frame["run_id"]), [int(r["run_id"]) for r in rows], name)
        label_of = self.label_of_run()
        by_id = {int(r["run_id"]): r for r in self.csv_runs}
        self.assertEqual(list(frame["label"]), [label_of[int(r["run_id"])] for r in rows], name)
        for column in ["problem", "budget"]:
            self.assertEqual(list(frame[column]), [by_id[int(r["run_id"])][column] for r in rows], name)
        self.assertEqual(list(frame["run"]), [int(by_id[int(r["run_id"])]["run"]) for r in rows], name)

    def test_curves(self):
        rows = read_rows(self.dir / "curves.csv")
        curves = self.study.curves
        self.check_run_key(curves, rows, "curves.csv")
        for i, r in enumerate(rows):
            self.assertEqual(curves["iteration"][i], int(r["iteration"]))
            self.assertEqual(curves["evaluations"][i], int(r["evaluations"]))
            self.assertEqual(curves["best_f"][i], float(r["best_f"]))
        lengths = curves.groupby("run_id").size()
        for row in self.csv_runs:  # iterations 0..n: one point more than the iterations run
            self.assertEqual(lengths[int(row["run_id"])], int(row["iterations"]) + 1, row["run_id"])
        f_opt = {int(r["run_id"]): float(r["f_opt"]) for r in self.csv_runs}
        self.assertTrue((curves["error"] == curves["best_f"] - curves["run_id"].map(f_opt)).all())

    def test_checkpoints_improvements_timings(self):
        for name, frame, value in [("checkpoints.csv", self.study.checkpoints, "best_f"),
                                   ("improvements.csv", self.study.improvements, "f"),
                                   ("timings.csv", self.study.timings, "wall_seconds")]:
            rows = read_rows(self.dir / name)
            self.check_run_key(frame, rows, name)
            self.assertEqual(list(frame[value]), [float(r[value]) for r in rows], name)
        events = self.study.improvements["event"]
        self.assertEqual((events == "last").sum(), len(self.csv_runs))

    def test_trajectories_of_named_parameters(self):
        rows = read_rows(self.dir / "trajectories.csv")
        trajectories = self.study.trajectories
        self.check_run_key(trajectories, rows, "trajectories.csv")
        self.assertEqual(list(trajectories["Rs"]), [float(r["Rs"]) for r in rows])

    # The report

    def test_one_report_per_budget_of_budgets_csv(self):
        listed = read_rows(self.dir / "report" / "budgets.csv")
        self.assertEqual(len(listed), 2)
        self.assertEqual(list(self.study.reports), [r["budget"] for r in listed])
        for r in listed:
            report = self.study.report(r["budget"])
            folder = self.dir / "report" / r["directory"]
            self.assertEqual(report.directory, folder)
            self.assertEqual(report.budget, (folder / "budget.txt").read_text().strip())
            files = {p.stem for p in folder.glob("*.csv")}
            self.assertEqual(set(report.tables) | set(report.data), files)
            self.assertIn("summary", report.tables)
            self.assertIn("final_values", report.data)
        with self.assertRaisesRegex(mhbench_study.StudyError, "2 budgets"):
            self.study.report()

    def test_every_cell_of_every_report_csv(self):
        for budget, report in self.study.reports.items():
            for name, frame in {**report.tables, **report.data}.items():
                path = report.directory / f"{name}.csv"
                with open(path, newline="") as f:
                    header, *rows = list(csv.reader(f))
                self.assertEqual(list(frame.columns), header, path)
                self.assertEqual(len(frame), len(rows), path)
                for i, row in enumerate(rows):
                    for column, text in zip(header, row):
                        self.assertTrue(same_cell(frame[column][i], text),
                                        f"{path}, row {i}, {column}: {frame[column][i]!r} read from {text!r}")

    def test_summary_table_values(self):
        summary = self.study.report("iterations=8").tables["summary"]
        self.assertEqual(str(summary["Median"].dtype), "float64")
        rows = read_rows(self.dir / "report" / "iterations_8" / "summary.csv")
        self.assertEqual(list(summary["Median"]), [float(r["Median"]) for r in rows])
        self.assertEqual(list(summary["Algorithm"]), [r["Algorithm"] for r in rows])

    def test_final_values_agree_with_the_runs(self):
        runs = self.study.runs.set_index(["budget", "problem", "label", "run"])
        for budget, report in self.study.reports.items():
            final = report.data["final_values"]
            self.assertEqual(len(final), (self.study.runs["budget"] == budget).sum())
            for _, row in final.iterrows():
                run = runs.loc[(budget, row["problem"], row["label"], row["run"])]
                self.assertEqual(run["best_f"], row["best_f"])
                self.assertEqual(run["evaluations"], row["evaluations"])

    # Without algorithms.csv, and broken files

    def test_without_algorithms_csv_the_label_is_the_spec(self):
        copy = self.copy_study("no_algorithms")
        (copy / "algorithms.csv").unlink()
        runs = mhbench_study.load_runs(copy)
        self.assertEqual(list(runs["label"]), list(runs["algorithm"]))
        self.assertIsNone(mhbench_study.load_study(copy).algorithms)

    def test_a_missing_runs_csv_is_one_line_naming_it(self):
        copy = self.copy_study("no_runs")
        (copy / "runs.csv").unlink()
        with self.assertRaises(mhbench_study.StudyError) as caught:
            mhbench_study.load_study(copy)
        message = str(caught.exception)
        self.assertIn(str(copy / "runs.csv"), message)
        self.assertNotIn("\n", message)

    def test_a_malformed_best_x_names_file_line_and_column(self):
        copy = self.copy_study("bad_best_x")
        lines = (copy / "runs.csv").read_text().splitlines(keepends=True)
        row = next(csv.reader([lines[3]]))
        header = next(csv.reader([lines[0]]))
        row[header.index("best_x")] = row[header.index("best_x")].replace(" ", "  ", 1)
        buffer = []
        csv.writer(_Lines(buffer), lineterminator="\n").writerow(row)
        lines[3] = buffer[0]
        (copy / "runs.csv").write_text("".join(lines))
        with self.assertRaisesRegex(mhbench_study.StudyError, r"runs\.csv, line 4, column 'best_x'"):
            mhbench_study.load_runs(copy)

    def test_a_malformed_number_names_file_line_and_column(self):
        copy = self.copy_study("bad_number")
        text = (copy / "curves.csv").read_text().splitlines(keepends=True)
        fields = text[2].split(",")
        fields[3] = "1.5x\n"
        text[2] = ",".join(fields)
        (copy / "curves.csv").write_text("".join(text))
        expected = r"curves\.csv, line 3, column 'best_f': '1\.5x' is not a number"
        with self.assertRaisesRegex(mhbench_study.StudyError, expected):
            mhbench_study.load_curves(copy)

    def test_a_missing_column_is_named(self):
        copy = self.copy_study("no_column")
        text = (copy / "timings.csv").read_text().replace("wall_seconds", "seconds", 1)
        (copy / "timings.csv").write_text(text)
        with self.assertRaisesRegex(mhbench_study.StudyError, r"timings\.csv: no column 'wall_seconds'"):
            mhbench_study.load_timings(copy)

    def test_a_run_id_of_no_run_is_refused(self):
        copy = self.copy_study("stray_run")
        with open(copy / "timings.csv", "a") as f:
            f.write("999,0.5\n")
        expected = r"timings\.csv, line \d+: run_id 999 is not a run of runs\.csv"
        with self.assertRaisesRegex(mhbench_study.StudyError, expected):
            mhbench_study.load_timings(copy)


class _Lines:
    """A file-like object collecting what csv.writer writes."""

    def __init__(self, into):
        self.into = into

    def write(self, text):
        self.into.append(text)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], *sys.argv[3:]], verbosity=1)
