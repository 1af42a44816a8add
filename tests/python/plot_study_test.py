#!/usr/bin/env python3
"""scripts/plot_study.py on small hand-written reports: one style per algorithm, distinct for 20;
the gap axis where f* is known; no convergence-by-iteration figure at an evaluation budget; PDF
fonts embedded as TrueType; PDF and PNG only (no SVG). Usage: plot_study_test.py SCRIPTS_DIR"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

SCRIPTS = sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import plot_study  # noqa: E402


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def tiny_report(directory, budget, f_opt="100"):
    """Two algorithms on one problem: curves by iteration and evaluations, final values."""
    os.makedirs(directory, exist_ok=True)
    write(os.path.join(directory, "budget.txt"), budget + "\n")
    write(os.path.join(directory, "algorithms.csv"), "Label,Spec,Full spec\nPSO,pso,pso:np=40\nDE,de,de:np=50\n")
    write(os.path.join(directory, "problems.csv"), "problem,name,f_opt\ncec2017:f=1,cec2017 f=1,%s\n" % f_opt)
    head = "problem,algorithm,label,"
    rows = [("pso", "PSO", [200.0, 150.0, 100.0]), ("de", "DE", [300.0, 120.0, 100.0 + 1e-9])]
    text = head + "iteration,runs,evaluations_mean,mean,std,median,q25,q75\n"
    for algorithm, label, values in rows:
        for i, v in enumerate(values):
            text += "cec2017:f=1,%s,%s,%d,5,%d,%r,0,%r,%r,%r\n" % (algorithm, label, i, 10 * (i + 1), v, v, v, v)
    write(os.path.join(directory, "curves_iteration.csv"), text)
    text = head + "evaluations,runs,mean,std,median,q25,q75\n"
    for algorithm, label, values in rows:
        for i, v in enumerate(values):
            text += "cec2017:f=1,%s,%s,%d,5,%r,0,%r,%r,%r\n" % (algorithm, label, 10 ** (i + 1), v, v, v, v)
    write(os.path.join(directory, "curves_evaluations.csv"), text)
    text = head + "run,best_f,evaluations,evals_to_target\n"
    for algorithm, label, values in rows:
        for run in range(3):
            text += "cec2017:f=1,%s,%s,%d,%r,1000,\n" % (algorithm, label, run, values[-1] + run)
    write(os.path.join(directory, "final_values.csv"), text)


class Styles(unittest.TestCase):
    def test_twenty_algorithms_get_twenty_different_styles(self):
        styles = [plot_study.style_of(i) for i in range(20)]
        self.assertEqual(len(set(styles)), 20)
        self.assertEqual(len(set(plot_study.style_of(i) for i in range(56))), 56)

    def test_a_style_depends_on_the_position_only(self):
        rows = [{"Label": "A%d" % i, "Spec": "a%d" % i} for i in range(12)]
        self.assertEqual(plot_study.Styles(rows).order["A7"], plot_study.style_of(7))
        self.assertEqual(plot_study.Styles(rows).csv_text(), plot_study.Styles(rows).csv_text())
        first = plot_study.Styles(rows).csv_text().splitlines()
        self.assertEqual(first[0], "algorithm,label,colour,marker,linestyle")
        self.assertEqual(first[1].split(",")[:2], ["a0", "A0"])


class Scale(unittest.TestCase):
    def test_known_optimum_gives_the_gap_and_a_floor_for_zero(self):
        scale = plot_study.Scale(100.0, [100.0, 101.0])
        self.assertEqual(scale.label(), "best-so-far f - f*")
        self.assertAlmostEqual(scale.value(101.0), 1.0)
        self.assertGreater(scale.value(100.0), 0.0)  # a gap of 0 is drawn at the floor, not dropped
        self.assertEqual(scale.floored, 1)

    def test_unknown_optimum_gives_f(self):
        self.assertEqual(plot_study.Scale(None, [1.0, 2.0]).label(), "best-so-far f")


class Script(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="mhb-plot-")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def run_script(self, *args):
        return subprocess.run(["/usr/bin/python3", os.path.join(SCRIPTS, "plot_study.py")] + list(args),
                              capture_output=True, text=True, timeout=120)

    def test_an_evaluation_budget_has_no_convergence_by_iteration(self):
        tiny_report(self.dir, "evaluations=1000")
        plan = self.run_script("--plan", self.dir)
        self.assertEqual(plan.returncode, 0, plan.stderr)
        self.assertIn("convergence 1", plan.stdout)
        tiny_report(self.dir, "iterations=2")
        self.assertIn("convergence 2", self.run_script("--plan", self.dir).stdout)

    def test_figures_are_pdf_with_embedded_truetype_and_png(self):
        tiny_report(self.dir, "evaluations=1000")
        write(os.path.join(self.dir, "figures.svg"), "")  # not a figure: left alone
        os.makedirs(os.path.join(self.dir, "figures"))
        write(os.path.join(self.dir, "figures", "old.svg"), "<svg/>")  # an older mhbench's: removed
        run = self.run_script(self.dir)
        self.assertEqual(run.returncode, 0, run.stderr)
        files = sorted(os.listdir(os.path.join(self.dir, "figures")))
        self.assertIn("convergence_evaluations_cec2017_f_1.pdf", files)
        self.assertIn("convergence_evaluations_cec2017_f_1.png", files)
        self.assertNotIn("convergence_iteration_cec2017_f_1.pdf", files)
        self.assertFalse([f for f in files if f.endswith(".svg")], files)
        self.assertIn("styles.csv", files)
        with open(os.path.join(self.dir, "figures", "convergence_evaluations_cec2017_f_1.pdf"), "rb") as f:
            pdf = f.read()
        self.assertIn(b"/FontFile2", pdf)  # TrueType embedded (pdf.fonttype 42), not Type 3
        self.assertNotIn(b"/Type3", pdf)

    def test_the_gap_label_is_on_the_axis(self):
        tiny_report(self.dir, "evaluations=1000")
        folder, jobs = plot_study.plan_folder(self.dir)
        plot_study.import_matplotlib()
        job = [j for j in jobs if j.name.startswith("convergence_evaluations")][0]
        fig = job.draw(job, *job.args)
        self.assertTrue(fig.axes[0].get_ylabel().startswith("best-so-far f - f*"))
        tiny_report(self.dir, "evaluations=1000", f_opt="")
        folder, jobs = plot_study.plan_folder(self.dir)
        job = [j for j in jobs if j.name.startswith("convergence_evaluations")][0]
        self.assertTrue(job.draw(job, *job.args).axes[0].get_ylabel().startswith("best-so-far f ("))


if __name__ == "__main__":
    unittest.main()
