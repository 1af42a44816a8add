// The paper's study end to end through the real binary, at reduced size (4 runs, 20 iterations):
// `mhbench run --study paper` prints Tables 2 and 3 beside the published numbers and writes the
// report; the tables agree with the run records; and the study's records are byte-identical for
// one and two threads.
#include <cmath>
#include <filesystem>
#include <map>

#include "cli_harness.hpp"
#include "results/store/csv.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::fresh;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;

std::size_t count_of(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
        ++n;
    return n;
}

TEST(PaperStudy, PrintsTablesTwoAndThreeThatAgreeWithTheRunRecords) {
    const fs::path dir = fresh("paper_small");
    const auto r =
        run_mhbench("run --study paper --runs 4 --iterations 20 --threads 2 --no-figures --tables --out '" +
                    dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;

    // Both tables are printed, with the published numbers beside ours.
    EXPECT_NE(r.out.find("Table 2"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Table 3"), std::string::npos);
    for (const char* published : {"3.9904", "0.0725", "4.9905", "1.6258", "5.5904", "1.6625", // Table 2
                                  "0.3325", "0.00363", "0.0763"})                             // Table 3
        EXPECT_NE(r.out.find(published), std::string::npos) << published;
    for (const char* file : {"table2_fitness.md", "table2_fitness.tex", "table2_fitness.csv",
                             "table3_parameters.md", "table3_parameters.tex", "table3_parameters.csv",
                             "curves_iteration.csv", "parameters_iteration.csv"})
        EXPECT_TRUE(fs::exists(dir / "report" / file)) << file;

    // Table 2 (CSV, full precision) against the run records: the mean final fitness and the
    // evaluations each algorithm actually spent.
    const mhb::CsvTable runs = mhb::read_csv(dir / "runs.csv");
    std::map<std::string, std::vector<double>> best;
    std::map<std::string, std::vector<double>> evaluations;
    for (std::size_t i = 0; i < runs.rows.size(); ++i) {
        const std::string& algorithm = runs.rows[i][runs.column("algorithm")];
        best[algorithm].push_back(runs.number(i, runs.column("best_f")));
        evaluations[algorithm].push_back(runs.number(i, runs.column("evaluations")));
        EXPECT_GE(runs.number(i, runs.column("best_f")), runs.number(i, runs.column("f_opt")) * (1 - 1e-12));
    }
    ASSERT_EQ(best.size(), 3u);
    const mhb::CsvTable table2 = mhb::read_csv(dir / "report" / "table2_fitness.csv");
    ASSERT_EQ(table2.rows.size(), 3u);
    for (std::size_t i = 0; i < table2.rows.size(); ++i) {
        const std::string algorithm = table2.rows[i][table2.column("Algorithm")];
        ASSERT_EQ(best[algorithm].size(), 4u) << algorithm;
        double mean = 0;
        for (double v : best[algorithm])
            mean += v / 4.0;
        EXPECT_NEAR(table2.number(i, table2.column("Mean f")), mean, 1e-12 * std::fabs(mean)) << algorithm;
        double spent = 0;
        for (double v : evaluations[algorithm])
            spent += v / 4.0;
        EXPECT_DOUBLE_EQ(table2.number(i, table2.column("Evaluations (mean)")), spent) << algorithm;
    }
    // The paper compares at equal iterations: NP to initialise, then per iteration 2 NP for TLBO,
    // NP for PSO and NP (D + 1) plus the mutations for ITLBO (NP = 50, D = 4, 20 iterations).
    EXPECT_EQ(evaluations["tlbo"], std::vector<double>(4, 50 + 20 * 100));
    EXPECT_EQ(evaluations["pso"], std::vector<double>(4, 50 + 20 * 50));
    for (double v : evaluations["itlbo"]) {
        EXPECT_GE(v, 50 + 20 * 250);
        EXPECT_LE(v, 50 + 20 * 300);
    }

    // Table 3: the truth, the least-squares optimum and, per algorithm, our values and the paper's.
    const std::string table3 = read_text(dir / "report" / "table3_parameters.md");
    EXPECT_NE(table3.find("True value"), std::string::npos);
    EXPECT_NE(table3.find("theta* (least squares)"), std::string::npos);
    EXPECT_EQ(count_of(table3, "paper identified"), 3u) << table3;
}

TEST(PaperStudy, RecordsAreByteIdenticalForOneAndTwoThreads) {
    const fs::path one = fresh("paper_threads_1");
    const fs::path two = fresh("paper_threads_2");
    const std::string study = "run --study paper --runs 3 --iterations 15 --no-report --quiet";
    ASSERT_EQ(run_mhbench(study + " --threads 1 --out '" + one.string() + "'").exit_code, 0);
    ASSERT_EQ(run_mhbench(study + " --threads 2 --out '" + two.string() + "'").exit_code, 0);
    for (const char* file : {"study.ini", "runs.csv", "curves.csv", "checkpoints.csv", "trajectories.csv"}) {
        const std::string a = read_text(one / file);
        EXPECT_FALSE(a.empty()) << file;
        EXPECT_EQ(a, read_text(two / file)) << file;
    }
}

} // namespace
