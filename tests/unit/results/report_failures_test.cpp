// Reports of studies that mix successful, failed and infinite runs (issue 9): +inf is a legal final
// value (the worst), a failed run is left out of every statistic and counted. Checked here: the
// statistics with +inf by hand (R's quantile() and wilcox.test() give the same), no table prints
// "nan", every count and note is right, the effects switch to ranks, the IOH export leaves out
// what its format cannot hold, and a plotting script that fails is one line, never an exception.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>
#include <unistd.h>

#include "results/analysis/hypothesis_tests.hpp"
#include "results/analysis/statistics.hpp"
#include "results/latex/latex_table.hpp"
#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "results/store/study_index.hpp"
#include "results/table_model/table.hpp"
#include "results/text/csv_table.hpp"
#include "results/text/markdown_table.hpp"
#include "support/files.hpp"
#include "support/numbers.hpp"
#include "support/text.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;
using mhb::test_support::read_text;

using mhb::test_support::inf;

fs::path fresh_report_failures_dir(const std::string& name) {
    const fs::path dir = mhb::test_support::fresh_temporary_path("mhb_report_failures_", name);
    return dir;
}

TEST(StatisticsWithInfinity, OrderStatisticsRankItLastAndMomentsAreInf) {
    // R: quantile(c(1, 2, Inf), c(.25, .5, .75)) = 1.5, 2, Inf; mean Inf; sd NaN (shown inf here).
    const Summary s = summarize({2.0, inf, 1.0});
    EXPECT_EQ(s.q25, 1.5);
    EXPECT_EQ(s.median, 2.0);
    EXPECT_EQ(s.q75, inf);
    EXPECT_EQ(s.mean, inf);
    EXPECT_EQ(s.std, inf);
    EXPECT_EQ(s.worst, inf);
    EXPECT_EQ(s.infinite, 1u);
    // Every value +inf: quantiles are +inf, never inf - inf (R: quantile(c(Inf, Inf, Inf)) = Inf).
    const Summary all = summarize({inf, inf, inf});
    EXPECT_EQ(all.median, inf);
    EXPECT_EQ(all.q25, inf);
    EXPECT_EQ(all.iqr(), 0.0); // the quartiles tie
    EXPECT_EQ(all.std, inf);
    EXPECT_EQ(standard_deviation({inf}), 0.0); // one value: no spread, as for a finite one
}

TEST(TestsWithInfinity, EqualInfinitiesAreTiesAndPlusInfIsTheWorst) {
    // Pairs (inf, inf) are a zero difference and dropped; the rest: 1-3, 2-5, inf-4 = -2, -3, +inf.
    // R: wilcox.test(c(1, 2, Inf), c(3, 5, 4), paired = TRUE): V = 3 (the rank of +inf), p = 1.
    const TestResult paired = signed_rank_test({inf, 1.0, 2.0, inf}, {inf, 3.0, 5.0, 4.0});
    EXPECT_EQ(paired.statistic, 3.0);
    EXPECT_FALSE(std::isnan(paired.p_value));
    EXPECT_FALSE(std::isnan(paired.z));
    // Rank-sum: x = {inf, inf} above y = {1, 2}: U = 4 of 4; the two +inf tie, so normal with tie and
    // continuity correction: sigma^2 = 4/12 (5 - 6/12) = 1.5, z = (4 - 2 - 0.5) / sqrt(1.5),
    // p = 2 (1 - Phi(z)) = 0.22067136191984676 (R: wilcox.test(c(Inf, Inf), c(1, 2))).
    const TestResult rank_sum = rank_sum_test({inf, inf}, {1.0, 2.0});
    EXPECT_EQ(rank_sum.statistic, 4.0);
    EXPECT_NEAR(rank_sum.z, 1.5 / std::sqrt(1.5), 1e-12);
    EXPECT_NEAR(rank_sum.p_value, 0.22067136191984676, 1e-12);
    EXPECT_EQ(vargha_delaney_a12({inf}, {inf, 1.0}), 0.75);
    const FriedmanResult friedman = friedman_test({{1.0, inf}, {inf, inf}});
    EXPECT_EQ(friedman.average_ranks[0], 1.25);
    EXPECT_EQ(friedman.average_ranks[1], 1.75);
}

TEST(TableNumbers, NanIsNeverPrinted) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(format_number(nan), undefined_text);
    EXPECT_EQ(format_number(inf), "inf");
    Table t;
    t.id = "t";
    t.title = "t";
    t.header = {"a", "b"};
    t.add_row({number_cell(nan), number_cell(inf)});
    EXPECT_EQ(render_csv(t), "a,b\n,inf\n");
    EXPECT_NE(render_markdown(t).find(undefined_text), std::string::npos);
    // LaTeX: the em dash and the infinity sign, each in maths aligned as a number of its column.
    EXPECT_NE(render_latex(t).find("$\\mbox{---}$ & $\\infty$"), std::string::npos) << render_latex(t);
}

// Two problems with f* = 0; itlbo and itlbo:obl=off form a 2^1 on/off design, pso is the third.
//   sphere:    itlbo finite; itlbo:obl=off runs 1 and 3 at +inf, run 5 failed; pso: every run failed.
//   rastrigin: itlbo finite; itlbo:obl=off every run at +inf; pso run 2 at +inf.
// So 7 failed runs and 2 + 6 + 1 = 9 runs at +inf.
RunRecord failures_run(const std::string& algorithm, const std::string& problem, std::int64_t index,
                       double f) {
    static std::int64_t id = 0;
    RunRecord r;
    r.run_id = id++;
    r.algorithm = algorithm;
    r.problem = problem;
    r.budget = "iterations=2";
    r.run_index = index;
    r.seed = 100 + static_cast<std::uint64_t>(index);
    r.best_f = f;
    r.f_opt = 0.0;
    r.evaluations = 100;
    r.iterations = 2;
    r.best_x = {0.1, 0.2};
    r.curve = {{0, 50, 2 * f, {}}, {1, 75, 1.5 * f, {}}, {2, 100, f, {}}};
    r.checkpoints = {{1, 4 * f}, {50, 2 * f}, {100, f}};
    return r;
}

RunRecord failed(const std::string& algorithm, const std::string& problem, std::int64_t index) {
    RunRecord r = failures_run(algorithm, problem, index, 0.0);
    r.ok = false;
    r.message = "the problem returned NaN at evaluation 7";
    r.best_f = std::numeric_limits<double>::quiet_NaN();
    r.curve.clear();
    r.checkpoints.clear();
    return r;
}

StudyData mixed_study() {
    StudyData data;
    data.directory = "/nonexistent/mixed";
    data.algorithms = {{"itlbo", "ITLBO[O+]", "itlbo:np=50,obl=on"},
                       {"itlbo:obl=off", "ITLBO[O-]", "itlbo:np=50,obl=off"},
                       {"pso", "PSO", "pso:np=50"}};
    const std::string sphere = "sphere:dim=2";
    const std::string rastrigin = "rastrigin:dim=2";
    for (std::int64_t i = 0; i < 6; ++i) {
        const double f = 1.0 + static_cast<double>(i);
        data.runs.push_back(failures_run("itlbo", sphere, i, f));
        if (i == 5)
            data.runs.push_back(failed("itlbo:obl=off", sphere, i));
        else
            data.runs.push_back(failures_run("itlbo:obl=off", sphere, i, i == 1 || i == 3 ? inf : 2.0 * f));
        data.runs.push_back(failed("pso", sphere, i));
    }
    for (std::int64_t i = 0; i < 6; ++i) {
        const double f = 10.0 + static_cast<double>(i);
        data.runs.push_back(failures_run("itlbo", rastrigin, i, f));
        data.runs.push_back(failures_run("itlbo:obl=off", rastrigin, i, inf));
        data.runs.push_back(failures_run("pso", rastrigin, i, i == 2 ? inf : 3.0 * f));
    }
    return data;
}

using mhb::test_support::prints_nan;

std::size_t row_of_problem_and_label(const CsvTable& t, const std::string& problem,
                                     const std::string& label) {
    for (std::size_t r = 0; r < t.rows.size(); ++r)
        if (t.rows[r][0] == problem && t.rows[r][1] == label)
            return r;
    ADD_FAILURE() << problem << " / " << label << " not in " << t.path;
    return 0;
}

class ReportFailures : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = fresh_report_failures_dir("mixed");
        ReportOptions options;
        options.out_dir = dir_;
        options.figures = false;
        std::ostringstream console;
        build_report(mixed_study(), options, console);
        console_ = console.str();
    }
    static fs::path dir_;
    static std::string console_;
};
fs::path ReportFailures::dir_;
std::string ReportFailures::console_;

TEST_F(ReportFailures, NoFileOfTheReportPrintsNan) {
    std::size_t checked = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
        if (!entry.is_regular_file())
            continue;
        const std::string text = read_text(entry.path());
        EXPECT_FALSE(prints_nan(text)) << entry.path() << ":\n" << text;
        ++checked;
    }
    EXPECT_GE(checked, 20u);
    EXPECT_FALSE(prints_nan(console_)) << console_;
}

TEST_F(ReportFailures, SummaryCountsRunsAndSaysWhatItLeftOut) {
    const CsvTable t = read_csv(dir_ / "summary.csv");
    const std::size_t off = row_of_problem_and_label(t, "sphere:dim=2", "ITLBO[O-]");
    EXPECT_EQ(t.rows[off][t.column("Runs")], "5/6");
    EXPECT_EQ(t.rows[off][t.column("Mean")], "inf");
    EXPECT_EQ(t.rows[off][t.column("Std")], "inf");
    // Values 2, inf, 6, inf, 10: sorted 2, 6, 10, inf, inf (+inf ranks last), the median is 10.
    EXPECT_EQ(t.number(off, t.column("Median")), 10.0);
    EXPECT_EQ(t.number(off, t.column("Best")), 2.0);
    EXPECT_EQ(t.rows[off][t.column("Worst")], "inf");
    const std::size_t pso = row_of_problem_and_label(t, "sphere:dim=2", "PSO");
    EXPECT_EQ(t.rows[pso][t.column("Runs")], "0/6");
    EXPECT_EQ(t.rows[pso][t.column("Mean")], "no successful run (6 failed)");
    const std::size_t all_inf = row_of_problem_and_label(t, "rastrigin:dim=2", "ITLBO[O-]");
    EXPECT_EQ(t.rows[all_inf][t.column("Median")], "inf");
    EXPECT_EQ(t.number(all_inf, t.column("IQR")), 0.0);

    const std::string md = read_text(dir_ / "summary.md");
    EXPECT_NE(md.find("7 failed runs left out of every statistic (first: sphere:dim=2, PSO, run 0: the "
                      "problem returned NaN at evaluation 7)."),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("9 runs ended at +inf"), std::string::npos) << md;
    EXPECT_NE(md.find("1 group has no successful run"), std::string::npos) << md;
    for (const char* table : {"tests.md", "comparison.md"})
        EXPECT_NE(read_text(dir_ / table).find("7 failed runs left out"), std::string::npos) << table;
}

TEST_F(ReportFailures, ConsoleSaysWhatWasLeftOut) {
    EXPECT_NE(console_.find("36 runs (7 failed)"), std::string::npos) << console_;
    EXPECT_NE(console_.find("7 failed runs left out (running the study's command again computes them again, "
                            "keeping every other run):\n"),
              std::string::npos)
        << console_;
    EXPECT_NE(console_.find("(first: sphere:dim=2, PSO, run 0): the problem returned NaN at evaluation 7\n"),
              std::string::npos)
        << console_;
    EXPECT_NE(console_.find("9 runs ended at +inf"), std::string::npos) << console_;
    EXPECT_NE(console_.find("IOHprofiler export: left out 9 runs that ended at +inf"), std::string::npos)
        << console_;
}

TEST_F(ReportFailures, ComparisonNamesGroupsWithoutSuccessAndBoldsOnlyFiniteMeans) {
    const CsvTable c = read_csv(dir_ / "comparison.csv");
    EXPECT_EQ(c.rows[0][c.column("PSO")], "no successful run (6 failed)");
    // Every run at +inf: median inf, IQR 0 (both quartiles +inf: a tie, not inf - inf).
    EXPECT_EQ(c.rows[1][c.column("ITLBO[O-]")].rfind("inf (0)", 0), 0u) << c.rows[1][c.column("ITLBO[O-]")];
    const std::string md = read_text(dir_ / "comparison.md");
    EXPECT_EQ(md.find("**inf"), std::string::npos) << md;
    // The rank tests keep +inf: ITLBO[O-] (every run +inf) is significantly worse on rastrigin.
    const CsvTable t = read_csv(dir_ / "tests.csv");
    const std::size_t row = row_of_problem_and_label(t, "rastrigin:dim=2", "ITLBO[O-]");
    EXPECT_EQ(t.number(row, t.column("A12")), 1.0);
}

TEST_F(ReportFailures, EffectsUseRanksWhereARunEndedAtInf) {
    const CsvTable e = read_csv(dir_ / "effects.csv");
    ASSERT_FALSE(e.rows.empty());
    for (std::size_t r = 0; r < e.rows.size(); ++r)
        EXPECT_EQ(e.rows[r][e.column("Scale")], "within-block rank") << e.rows[r][e.column("Problem")];
    // Sphere: 5 blocks (run 5 of ITLBO[O-] failed); in 2 of them obl=off is +inf, the worst rank.
    const std::size_t sphere = row_of_problem_and_label(e, "itlbo: obl (2^1)", "sphere:dim=2");
    EXPECT_EQ(e.rows[sphere][e.column("Blocks")], "5");
    // Every block: obl on is rank 1, off rank 2: the effect of obl is 1 - 2 = -1.
    EXPECT_EQ(e.number(sphere, e.column("Mean")), -1.0);
    const std::string md = read_text(dir_ / "effects.md");
    EXPECT_NE(md.find("Run indices left out (a variant failed or did not run): 1 on sphere:dim=2"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("Runs that ended at +inf"), std::string::npos) << md;
    EXPECT_NE(md.find("2 on sphere:dim=2, 6 on rastrigin:dim=2"), std::string::npos) << md;
}

TEST_F(ReportFailures, CurveDataWritesInfAndIohLeavesItOut) {
    const CsvTable finals = read_csv(dir_ / "final_values.csv");
    EXPECT_EQ(finals.rows.size(), 29u); // 36 runs, 7 failed
    const std::string curves = read_text(dir_ / "curves_iteration.csv");
    EXPECT_NE(curves.find(",inf,"), std::string::npos);
    std::size_t dat_files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir_ / "ioh")) {
        if (entry.path().extension() != ".dat")
            continue;
        ++dat_files;
        EXPECT_EQ(read_text(entry.path()).find("inf"), std::string::npos) << entry.path();
    }
    EXPECT_EQ(dat_files, 4u); // itlbo on both problems, ITLBO[O-] on sphere, PSO on rastrigin
    EXPECT_FALSE(fs::exists(dir_ / "ioh" / "itlbo_obl_off" / "IOHprofiler_f110_rastrigin.json"));
    EXPECT_TRUE(fs::exists(dir_ / "ioh" / "itlbo_obl_off" / "IOHprofiler_f101_sphere.json"));
}

// A plotting script that ends in a traceback: one line on the error stream, the log keeps the rest,
// and the report succeeds with its tables written.
TEST(ReportFigureFailures, AFailingScriptIsOneLineAndTheReportStillSucceeds) {
    ReportOptions options;
    if (!find_matplotlib_python(options.python_candidates))
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = fresh_report_failures_dir("failing_script");
    fs::create_directories(dir);
    const fs::path script = dir / "failing_plot.py";
    std::ofstream(script) << "def draw():\n    raise RuntimeError('boom: axis limits cannot be NaN or Inf')\n"
                          << "draw()\n";
    options.out_dir = dir / "report";
    options.plot_script = script;
    std::ostringstream console;
    std::ostringstream errors;
    options.errors = &errors;
    ASSERT_NO_THROW(build_report(mixed_study(), options, console));
    const std::string said = errors.str();
    EXPECT_EQ(said.rfind("figures failed: RuntimeError: boom: axis limits cannot be NaN or Inf (full "
                         "output: ",
                         0),
              0u)
        << said;
    EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;
    EXPECT_EQ(console.str().find("Traceback"), std::string::npos);
    EXPECT_NE(read_text(dir / "report" / "figures" / "plot_study.log").find("Traceback"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "report" / "summary.md"));
}

// Slow: matplotlib draws every figure of the mixed study (a few seconds).
TEST(SlowReportFailureFigures, DrawnWithNotesAndExitZero) {
    ReportOptions options;
    if (!find_matplotlib_python(options.python_candidates))
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = fresh_report_failures_dir("figures");
    options.out_dir = dir;
    options.plot_script = fs::path(MHB_SOURCE_DIR) / "scripts" / "plot_study.py";
    std::ostringstream console;
    std::ostringstream errors;
    options.errors = &errors;
    build_report(mixed_study(), options, console);
    EXPECT_EQ(errors.str(), "");
    EXPECT_NE(console.str().find("figures: " + (dir / "figures").string()), std::string::npos)
        << console.str();
    // The panel of a problem where one algorithm is +inf throughout says what it left out (two
    // problems: one figure per kind, a panel each, issue 37).
    EXPECT_NE(console.str().find("figure final_values_all: rastrigin: left out 7 at +inf"), std::string::npos)
        << console.str();
    for (const char* name : {"convergence_iteration_all", "convergence_evaluations_all", "final_values_all",
                             "ecdf_targets_all", "effects_main_itlbo", "effects_overview_itlbo"})
        EXPECT_GT(fs::file_size(dir / "figures" / (std::string(name) + ".png")), 1000u) << name;
    EXPECT_FALSE(fs::exists(dir / "figures" / "plot_study.log"));
}

// Slow: one figure whose data is damaged fails alone; the others are drawn and the script exits 0.
TEST(SlowReportFailureFigures, OneFailingFigureDoesNotStopTheOthers) {
    ReportOptions options;
    const auto python = find_matplotlib_python(options.python_candidates);
    if (!python)
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = fresh_report_failures_dir("one_figure_fails");
    options.out_dir = dir;
    options.figures = false;
    std::ostringstream console;
    build_report(mixed_study(), options, console);
    std::string finals = read_text(dir / "final_values.csv");
    const std::string row = "sphere:dim=2,itlbo,ITLBO[O+],0,1,";
    const auto at = finals.find(row);
    ASSERT_NE(at, std::string::npos) << finals;
    finals.replace(at, row.size(), "sphere:dim=2,itlbo,ITLBO[O+],0,x,");
    std::ofstream(dir / "final_values.csv", std::ios::trunc) << finals;
    const std::string command = "'" + *python + "' '" + MHB_SOURCE_DIR + "/scripts/plot_study.py' '" +
                                dir.string() + "' >'" + (dir / "out.txt").string() + "' 2>'" +
                                (dir / "err.txt").string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0);
    const std::string err = read_text(dir / "err.txt");
    EXPECT_EQ(
        err.rfind("figure final_values_all failed: ValueError: could not convert string to float: 'x'\n", 0),
        0u)
        << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_FALSE(fs::exists(dir / "figures" / "final_values_all.png"));
    EXPECT_TRUE(fs::exists(dir / "figures" / "convergence_iteration_all.png"));
    EXPECT_TRUE(fs::exists(dir / "figures" / "ecdf_targets_all.png"));
}

} // namespace
} // namespace mhb
