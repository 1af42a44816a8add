// The paper's study end to end through the real binary, at reduced size (4 runs at the paper's 150
// iterations): `mhbench run --study paper` prints Tables 2 and 3 beside the published numbers and
// writes the report; the tables agree with the run records; and the study's records are
// byte-identical for one and two threads. The same problem without the paper's protocol, or at
// another budget, gets the study's own tables: no "Table 2", no paper column (issue 37).
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
    const auto r = run_mhbench("run --study paper --runs 4 --threads 2 --no-figures --tables --out '" +
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
    // Table 2 names the algorithms by their labels (algorithms.csv), the runs by their specs.
    const mhb::CsvTable labels = mhb::read_csv(dir / "algorithms.csv");
    std::map<std::string, std::string> spec_of;
    for (const auto& row : labels.rows)
        spec_of[row[labels.column("label")]] = row[labels.column("algorithm")];
    EXPECT_EQ(spec_of["ITLBO"], "itlbo");
    for (std::size_t i = 0; i < table2.rows.size(); ++i) {
        const std::string algorithm = spec_of[table2.rows[i][table2.column("Algorithm")]];
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
    // NP for PSO and NP (D + 1) plus the mutations for ITLBO (NP = 50, D = 4, 150 iterations).
    EXPECT_EQ(evaluations["tlbo"], std::vector<double>(4, 50 + 150 * 100));
    EXPECT_EQ(evaluations["pso"], std::vector<double>(4, 50 + 150 * 50));
    for (double v : evaluations["itlbo"]) {
        EXPECT_GE(v, 50 + 150 * 250);
        EXPECT_LE(v, 50 + 150 * 300);
    }

    // Table 3: the truth, the least-squares optimum and, per algorithm, our values and the paper's.
    const std::string table3 = read_text(dir / "report" / "table3_parameters.md");
    EXPECT_NE(table3.find("True value"), std::string::npos);
    EXPECT_NE(table3.find("theta* (least squares)"), std::string::npos);
    EXPECT_EQ(count_of(table3, "paper identified"), 3u) << table3;
}

// Every file of a report directory (tables in every format, index.html, README.md), each line that
// names the paper's framing.
std::string paper_framing_in(const fs::path& report) {
    std::string found;
    for (const auto& entry : fs::recursive_directory_iterator(report)) {
        if (!entry.is_regular_file() || entry.path().extension() == ".pdf")
            continue;
        const std::string text = read_text(entry.path());
        for (const char* phrase : {"Table 2", "Table 3", "Table 4", "Paper mean", "Paper std",
                                   "paper identified", "table2_", "table3_", "table4_", "Li, Wang, Ji"})
            if (text.find(phrase) != std::string::npos)
                found += entry.path().filename().string() + ": " + phrase + "\n";
    }
    return found;
}

TEST(PaperStudy, APmsmStudyWithoutTheProtocolHasNoPaperFraming) {
    const fs::path dir = fresh("pmsm_neutral");
    const auto r = run_mhbench("run --algorithms 'itlbo tlbo pso' --problems pmsm:speed=2500,load=2 --runs 2 "
                               "--iterations 150 --no-figures -q --out '" +
                               dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(paper_framing_in(dir / "report"), "");
    EXPECT_TRUE(fs::exists(dir / "report" / "fitness.md"));
    EXPECT_TRUE(fs::exists(dir / "report" / "parameters.md"));
    // One condition: no table of conditions side by side.
    EXPECT_FALSE(fs::exists(dir / "report" / "conditions.md"));
}

TEST(PaperStudy, ThePaperPresetsAtAnotherBudgetKeepTheirOwnTables) {
    const fs::path dir = fresh("paper_other_budget");
    const auto r = run_mhbench("run --study paper-table4 --runs 2 --iterations 20 --no-figures -q --out '" +
                               dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(paper_framing_in(dir / "report"), "");
    // Three conditions: the study's own table of them.
    EXPECT_TRUE(fs::exists(dir / "report" / "conditions.md"));
    EXPECT_TRUE(fs::exists(dir / "report" / "fitness_pmsm_load_3_speed_2500.md"));
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
