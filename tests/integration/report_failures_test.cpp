// Failed and infinite runs through the real binary (issue 9): the study on
// schwefel_2_22:dim=30,bound=1e12 that once ended in a 47-line Python traceback and exit 1 now runs
// end to end with exit 0 (PSO's runs end at +inf there, DE's are finite), and a study that mixes
// successful, failed and +inf runs is reported with every count said and no "nan" in any table;
// where matplotlib is found, the figures are drawn and the plotting step prints no traceback.
#include <filesystem>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <unistd.h>

#include "cli_harness.hpp"
#include "results/report/report.hpp"
#include "results/store/csv.hpp"
#include "results/store/study_writer.hpp"
#include "support/text.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::fresh;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;

bool matplotlib_found() {
    return find_matplotlib_python({"/usr/bin/python3", "python3"}).has_value();
}

using mhb::test_support::prints_nan;

void expect_no_nan_in_tables(const fs::path& report) {
    std::size_t tables = 0;
    for (const auto& entry : fs::directory_iterator(report)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".md" && ext != ".tex" && ext != ".csv")
            continue;
        EXPECT_FALSE(prints_nan(read_text(entry.path()))) << entry.path();
        ++tables;
    }
    EXPECT_GE(tables, 10u);
}

// Slow when it draws the figures (matplotlib takes a few seconds).
TEST(SlowReportFailuresCli, Schwefel222AtBound1e12RunsEndToEndWithExitZero) {
    const fs::path dir = fresh("schwefel_2_22_bound_1e12");
    const bool figures = matplotlib_found();
    const auto r =
        run_mhbench("run --problems schwefel_2_22:dim=30,bound=1e12 --algorithms 'pso de' --runs 3 "
                    "--iterations 10 --threads 2 " +
                    std::string(figures ? "" : "--no-figures ") + "--out '" + dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("figures failed"), std::string::npos) << r.err;
    // What it produces: every PSO run ends at +inf (x * 1e12 overflows the product of |x_i|), DE's
    // runs are finite; all are successful runs.
    const CsvTable runs = read_csv(dir / "runs.csv");
    std::size_t infinite = 0;
    for (std::size_t i = 0; i < runs.rows.size(); ++i) {
        EXPECT_EQ(runs.rows[i][runs.column("status")], "ok");
        infinite += runs.rows[i][runs.column("best_f")] == "inf" ? 1U : 0U;
    }
    EXPECT_GT(infinite, 0u);
    EXPECT_NE(r.out.find(std::to_string(infinite) + " runs ended at +inf"), std::string::npos) << r.out;
    expect_no_nan_in_tables(dir / "report");
    const CsvTable summary = read_csv(dir / "report" / "summary.csv");
    EXPECT_EQ(summary.rows[0][summary.column("Mean")], "inf");
    EXPECT_EQ(summary.rows[0][summary.column("Runs")], "3/3");
    if (figures) {
        EXPECT_NE(r.out.find("figures: "), std::string::npos) << r.out;
        for (const char* name : {"final_values_schwefel_2_22_bound_1e_12_dim_30",
                                 "convergence_iteration_schwefel_2_22_bound_1e_12_dim_30"})
            EXPECT_GT(fs::file_size(dir / "report" / "figures" / (std::string(name) + ".png")), 1000u)
                << name;
    }
}

// A finished study written directly (a problem's NaN fails a run: the runner makes such records):
// on sphere, pso's runs 0 and 2 failed and tlbo's run 1 ended at +inf; on rastrigin every tlbo run
// ended at +inf.
fs::path mixed_study(const std::string& name) {
    const fs::path dir = fresh(name);
    StudyWriter writer(dir, "[study]\nname=mixed\n", "threads=1\n", {}, false);
    std::int64_t id = 0;
    for (const char* problem : {"sphere:dim=2", "rastrigin:dim=2"})
        for (const char* algorithm : {"pso", "tlbo"})
            for (std::int64_t i = 0; i < 4; ++i) {
                RunRecord r;
                r.run_id = id++;
                r.algorithm = algorithm;
                r.problem = problem;
                r.budget = "iterations=2";
                r.run_index = i;
                r.seed = 7 + static_cast<std::uint64_t>(i);
                r.f_opt = 0.0;
                r.evaluations = 100;
                r.iterations = 2;
                r.best_x = {0.5, -0.5};
                const bool sphere = std::string(problem) == "sphere:dim=2";
                const bool pso = std::string(algorithm) == "pso";
                if (sphere && pso && (i == 0 || i == 2)) {
                    r.ok = false;
                    r.message = "the problem returned NaN at evaluation 3";
                    writer.append(r, 0.0);
                    continue;
                }
                const bool infinite = !pso && (!sphere || i == 1);
                r.best_f = infinite ? std::numeric_limits<double>::infinity() : 1.0 + static_cast<double>(i);
                r.curve = {{0, 50, 2.0 * r.best_f, {}}, {1, 75, 1.5 * r.best_f, {}}, {2, 100, r.best_f, {}}};
                r.checkpoints = {{1, 4.0 * r.best_f}, {100, r.best_f}};
                writer.append(r, 0.0);
            }
    writer.finish();
    return dir;
}

TEST(ReportFailuresCli, MixedStudyIsReportedWithEveryCountSaid) {
    const fs::path dir = mixed_study("mixed_no_figures");
    const auto r = run_mhbench("report '" + dir.string() + "' --no-figures");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("16 runs (2 failed)"), std::string::npos) << r.out;
    // Each reason once, with its first run, and what to do about them.
    EXPECT_NE(r.out.find("2 failed runs left out (running the study's command again computes them again, "
                         "keeping every other run):\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("(first: sphere:dim=2, pso, run 0): the problem returned NaN at evaluation 3\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("5 runs ended at +inf"), std::string::npos) << r.out;
    expect_no_nan_in_tables(dir / "report");
    const CsvTable summary = read_csv(dir / "report" / "summary.csv");
    EXPECT_EQ(summary.rows[0][summary.column("Runs")], "2/4");
    EXPECT_EQ(summary.rows[1][summary.column("Mean")], "inf");
    EXPECT_EQ(summary.rows[1][summary.column("Median")], "3.5"); // 1, 3, 4, inf: +inf ranks last
    EXPECT_NE(read_text(dir / "report" / "summary.md").find("2 failed runs left out of every statistic"),
              std::string::npos);
}

TEST(SlowReportFailuresCli, MixedStudyFiguresAreDrawnWithoutATraceback) {
    if (!matplotlib_found())
        GTEST_SKIP() << "no Python with matplotlib";
    const fs::path dir = mixed_study("mixed_figures");
    const auto r = run_mhbench("report '" + dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    // Two problems: a panel each in one figure per kind, the note naming the panel (issue 37).
    EXPECT_NE(r.out.find("figure final_values_all: rastrigin: left out 4 at +inf"), std::string::npos)
        << r.out;
    for (const char* name :
         {"convergence_iteration_all", "convergence_evaluations_all", "final_values_all", "ecdf_targets_all"})
        EXPECT_GT(fs::file_size(dir / "report" / "figures" / (std::string(name) + ".png")), 1000u) << name;
}

} // namespace
} // namespace mhb
