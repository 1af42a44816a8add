// `mhbench report` end to end through the executable: a finished study gives the tables on stdout
// and exit 0; a damaged study or a bad option gives exactly one line on stderr naming the problem
// and a non-zero exit (1 for bad data, 2 for a bad command line).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_harness.hpp"
#include "results/store/algorithm_info.hpp"
#include "results/store/study_writer.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

// Removes the studies and output files this process made when it exits.
struct TemporaryPaths {
    std::vector<fs::path> paths;
    ~TemporaryPaths() {
        std::error_code ec;
        for (const auto& p : paths)
            fs::remove_all(p, ec);
    }
} temporary_paths;

using Outcome = mhb::testing_cli::CliResult;
using mhb::testing_cli::read_text;

Outcome run_report_cli(const std::string& arguments) {
    return mhb::testing_cli::run_mhbench(arguments);
}

// Two algorithms, 3 runs each; with `budgets`, the runs are repeated at every budget, and the
// study lists its algorithms with labels (algorithms.csv).
fs::path small_study_dir(const std::string& name, const std::vector<std::string>& budgets = {""}) {
    const fs::path dir =
        fs::temp_directory_path() / ("mhb_report_cli_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    temporary_paths.paths.push_back(dir);
    std::vector<AlgorithmInfo> algorithms;
    if (budgets.size() > 1)
        algorithms = {{"itlbo", "ITLBO", "itlbo:np=50,obl=on,stepwise=on,tutorial=on"},
                      {"pso", "PSO 2017", "pso:c1=2,c2=2,np=50,w=0.5"}};
    StudyWriter writer(dir, "cli test\n", "threads=1\n", {"Rs", "Ld", "Lq", "psi"}, false, algorithms);
    std::int64_t id = 0;
    for (const auto& budget : budgets)
        for (const char* algorithm : {"itlbo", "pso"})
            for (std::int64_t i = 0; i < 3; ++i, ++id) {
                RunRecord r;
                r.run_id = id;
                r.algorithm = algorithm;
                r.problem = "pmsm:load=2,speed=2500";
                r.budget = budget;
                r.run_index = i;
                r.best_f = 4.0 + static_cast<double>(id);
                r.f_opt = 3.9;
                r.evaluations = 100;
                r.iterations = 1;
                r.best_x = {0.33, 0.00324, 0.00324, 0.0776};
                r.parameter_names = {"Rs", "Ld", "Lq", "psi"};
                r.true_parameters = r.best_x;
                r.x_opt = r.best_x;
                r.curve = {{0, 50, r.best_f + 1.0, r.best_x}, {1, 100, r.best_f, r.best_x}};
                r.checkpoints = {{1, r.best_f + 2.0}, {100, r.best_f}};
                writer.append(r, 0.0);
            }
    writer.finish();
    return dir;
}

std::size_t line_count(const std::string& text) {
    std::size_t lines = 0;
    for (char c : text)
        lines += c == '\n' ? 1 : 0;
    return lines;
}

TEST(ReportCli, WritesTheTablesAndWithTablesPrintsThemInMarkdown) {
    const fs::path dir = small_study_dir("ok");
    const Outcome o = run_report_cli("report '" + dir.string() + "' --no-figures --tables");
    EXPECT_EQ(o.exit_code, 0) << o.err;
    // No protocol: the study's own PMSM tables, never the paper's Table 2.
    EXPECT_NE(o.out.find("### Fitness of each algorithm (PMSM, 2500 rpm, 2 N m)"), std::string::npos)
        << o.out;
    EXPECT_EQ(o.out.find("Table 2"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("| itlbo | 3/3 |"), std::string::npos) << o.out;
    EXPECT_TRUE(fs::exists(dir / "report" / "parameters.tex"));
    EXPECT_TRUE(fs::exists(dir / "report" / "curves_iteration.csv"));
}

TEST(ReportCli, QuietWritesTheReportAndPrintsNothing) {
    const fs::path dir = small_study_dir("quiet");
    const Outcome o = run_report_cli("report '" + dir.string() + "' --no-figures -q");
    EXPECT_EQ(o.exit_code, 0) << o.err;
    EXPECT_EQ(o.out, "");
    EXPECT_EQ(o.err, "");
    EXPECT_TRUE(fs::exists(dir / "report" / "parameters.tex"));
    EXPECT_TRUE(fs::exists(dir / "report" / "index.html"));
}

TEST(ReportCli, SeveralBudgetsEachInItsOwnFolderWithLabels) {
    const fs::path dir = small_study_dir("budgets", {"iterations=1", "evaluations=100"});
    const Outcome o = run_report_cli("report '" + dir.string() + "' --no-figures --tables");
    EXPECT_EQ(o.exit_code, 0) << o.err;
    EXPECT_NE(o.out.find("2 budgets, each reported in its own folder"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("### Fitness of each algorithm (PMSM, 2500 rpm, 2 N m) [budget evaluations=100]"),
              std::string::npos)
        << o.out;
    EXPECT_NE(o.out.find("| PSO 2017 | 3/3 |"), std::string::npos) << o.out;
    EXPECT_TRUE(fs::exists(dir / "report" / "budgets.csv"));
    EXPECT_TRUE(fs::exists(dir / "report" / "iterations_1" / "fitness.md"));
    EXPECT_TRUE(fs::exists(dir / "report" / "evaluations_100" / "curves_iteration.csv"));
    // All seeds are equal here: the runs pair, and the tests table says so.
    EXPECT_NE(read_text(dir / "report" / "iterations_1" / "tests.md").find("Wilcoxon signed-rank"),
              std::string::npos);
}

TEST(ReportCli, DamagedStudyGivesOneLineNamingTheFile) {
    const fs::path dir = small_study_dir("damaged");
    fs::remove(dir / "trajectories.csv");
    const Outcome o = run_report_cli("report '" + dir.string() + "' --no-figures");
    EXPECT_EQ(o.exit_code, 1);
    EXPECT_EQ(line_count(o.err), 1u) << o.err;
    EXPECT_NE(o.err.find("trajectories.csv"), std::string::npos) << o.err;

    const fs::path truncated = small_study_dir("truncated");
    const std::string runs = read_text(truncated / "runs.csv");
    std::ofstream(truncated / "runs.csv", std::ios::trunc) << runs.substr(0, runs.size() - 7);
    const Outcome t = run_report_cli("report '" + truncated.string() + "' --no-figures");
    EXPECT_EQ(t.exit_code, 1);
    EXPECT_EQ(line_count(t.err), 1u) << t.err;
    EXPECT_NE(t.err.find("runs.csv"), std::string::npos) << t.err;
}

TEST(ReportCli, BadOptionsAreUsageErrors) {
    const fs::path dir = small_study_dir("options");
    const Outcome alpha = run_report_cli("report '" + dir.string() + "' --alpha 0 --no-figures");
    EXPECT_EQ(alpha.exit_code, 2);
    EXPECT_NE(alpha.err.find("--alpha"), std::string::npos) << alpha.err;
    const Outcome reference = run_report_cli("report '" + dir.string() + "' --reference cmaes --no-figures");
    EXPECT_EQ(reference.exit_code, 2);
    EXPECT_NE(reference.err.find("the study has: itlbo, pso"), std::string::npos) << reference.err;
    EXPECT_EQ(run_report_cli("report").exit_code, 2);
    const Outcome help = run_report_cli("report --help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("--reference"), std::string::npos);
}

} // namespace
} // namespace mhb
