// The CEC protocols end to end through the real binary, at reduced size: the cec2017 preset with
// two algorithms, two functions and three runs (its budget, 10 000 x D with a target of 1e-8, kept),
// and a cec2022 study file at two dimensions with a small budget per dimension. Checked against the
// study's own records: each run's budget resolved for its dimension, the organisers' files named
// <Algorithm>_<F>_<D>.txt with a row per checkpoint and a column per run whose values are the errors
// recomputed here from improvements.csv and runs.csv (below 1e-8: 0), FEterm for 2022, and the errors
// table's best, worst, median, mean and std recomputed from runs.csv.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "cli_harness.hpp"
#include "results/store/csv.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;

double rule(double error) {
    return error < 1e-8 ? 0.0 : error;
}

// The numbers of a result file, row by row.
std::vector<std::vector<double>> matrix(const fs::path& file) {
    std::vector<std::vector<double>> rows;
    std::istringstream in(read_text(file));
    for (std::string line; std::getline(in, line);) {
        std::istringstream fields(line);
        std::vector<double> row;
        for (std::string field; fields >> field;)
            row.push_back(std::stod(field));
        rows.push_back(row);
    }
    return rows;
}

struct StoredRun {
    std::string algorithm;
    std::string problem;
    std::int64_t index = 0;
    std::int64_t evaluations = 0;
    double best_f = 0;
    double f_opt = 0;
    std::vector<std::pair<std::int64_t, double>> improvements;

    // The error after `at` evaluations, from the recorded improvements, with the 1e-8 rule.
    [[nodiscard]] double error_at(std::int64_t at) const {
        double f = best_f;
        if (evaluations > at) {
            f = NAN;
            for (const auto& [e, value] : improvements)
                if (e <= at)
                    f = value;
        }
        return rule(f - f_opt);
    }
};

// runs.csv with improvements.csv, by run_id.
std::map<std::int64_t, StoredRun> read_runs(const fs::path& dir) {
    const mhb::CsvTable runs = mhb::read_csv(dir / "runs.csv");
    std::map<std::int64_t, StoredRun> out;
    for (std::size_t i = 0; i < runs.rows.size(); ++i) {
        StoredRun r;
        r.algorithm = runs.rows[i][runs.column("algorithm")];
        r.problem = runs.rows[i][runs.column("problem")];
        r.index = runs.integer(i, runs.column("run"));
        r.evaluations = runs.integer(i, runs.column("evaluations"));
        r.best_f = runs.number(i, runs.column("best_f"));
        r.f_opt = runs.number(i, runs.column("f_opt"));
        out[runs.integer(i, runs.column("run_id"))] = r;
    }
    const mhb::CsvTable improvements = mhb::read_csv(dir / "improvements.csv");
    for (std::size_t i = 0; i < improvements.rows.size(); ++i)
        if (improvements.rows[i][improvements.column("event")] == "improvement")
            out[improvements.integer(i, improvements.column("run_id"))].improvements.emplace_back(
                improvements.integer(i, improvements.column("evaluations")),
                improvements.number(i, improvements.column("f")));
    return out;
}

// The runs of one algorithm on one problem, by run index.
std::vector<const StoredRun*> runs_of(const std::map<std::int64_t, StoredRun>& runs,
                                      const std::string& algorithm, const std::string& problem) {
    std::vector<const StoredRun*> out;
    for (const auto& [id, r] : runs)
        if (r.algorithm == algorithm && r.problem == problem)
            out.push_back(&r);
    std::sort(out.begin(), out.end(),
              [](const StoredRun* a, const StoredRun* b) { return a->index < b->index; });
    return out;
}

std::size_t result_files(const fs::path& dir) {
    std::size_t n = 0;
    for (const auto& entry : fs::directory_iterator(dir))
        n += entry.path().extension() == ".txt" ? 1U : 0U;
    return n;
}

TEST(CecProtocolCli, Cec2017PresetAtReducedSizeWritesTheOrganisersFilesAndTables) {
    const fs::path dir = mhb::testing_cli::scratch_directory() / "cec2017_small";
    fs::remove_all(dir);
    const auto r =
        run_mhbench("run --study cec2017 --algorithms 'pso cmaes' --problems 'cec2017:f={1,5},dim=10' "
                    "--runs 3 --threads 2 --no-figures --out '" +
                    dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("CEC 2017 result files (4, the organisers' layout"), std::string::npos) << r.out;
    EXPECT_NE(read_text(dir / "study.ini").find("\nprotocol = cec2017\n"), std::string::npos);

    const auto runs = read_runs(dir);
    ASSERT_EQ(runs.size(), 12u);
    const mhb::CsvTable runs_csv = mhb::read_csv(dir / "runs.csv");
    for (std::size_t i = 0; i < runs_csv.rows.size(); ++i)
        EXPECT_EQ(runs_csv.rows[i][runs_csv.column("budget")], "evaluations=10000*dim,target=1e-08");
    for (const auto& [id, run] : runs) {
        // 10 000 x D evaluations at D = 10, fewer only for a run that reached the target.
        if (run.best_f - run.f_opt > 1e-8)
            EXPECT_EQ(run.evaluations, 100000) << "run " << id;
        else
            EXPECT_LE(run.evaluations, 100000) << "run " << id;
    }

    const fs::path cec = dir / "report" / "cec";
    EXPECT_EQ(result_files(cec), 4u);
    const std::vector<std::int64_t> checkpoints = {1000,  2000,  3000,  5000,  10000, 20000, 30000,
                                                   40000, 50000, 60000, 70000, 80000, 90000, 100000};
    std::size_t zeros = 0;
    for (const std::string algorithm : {"pso", "cmaes"})
        for (const int f : {1, 5}) {
            const std::string problem = "cec2017:dim=10,f=" + std::to_string(f);
            // Files are named by label: the registered display names (PSO, CMA-ES (IPOP)) made safe.
            const std::string label = algorithm == std::string("pso") ? "PSO" : "CMA-ES-IPOP";
            const auto file = matrix(cec / (label + "_" + std::to_string(f) + "_10.txt"));
            const auto group = runs_of(runs, algorithm, problem);
            ASSERT_EQ(group.size(), 3u);
            ASSERT_EQ(file.size(), checkpoints.size()) << algorithm << " F" << f;
            for (std::size_t k = 0; k < checkpoints.size(); ++k) {
                ASSERT_EQ(file[k].size(), 3u);
                for (std::size_t j = 0; j < 3; ++j) {
                    EXPECT_EQ(file[k][j], group[j]->error_at(checkpoints[k]))
                        << algorithm << " F" << f << " row " << k << " run " << j;
                    zeros += file[k][j] == 0.0 ? 1U : 0U;
                }
            }
            for (std::size_t j = 0; j < 3; ++j) // the last row is the final error
                EXPECT_EQ(file.back()[j], rule(group[j]->best_f - group[j]->f_opt));
        }
    EXPECT_GT(zeros, 0u); // CMA-ES solves F1 to the target: errors below 1e-8 written as 0

    // The errors table: per function and algorithm, the statistics of runs.csv's errors (rule applied).
    const mhb::CsvTable table = mhb::read_csv(dir / "report" / "cec_errors_d10.csv");
    ASSERT_EQ(table.rows.size(), 4u);
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const std::string function = table.rows[i][table.column("Function")];
        const std::string problem = "cec2017:dim=10,f=" + function.substr(1);
        std::vector<double> errors;
        const std::string label = table.rows[i][table.column("Algorithm")]; // the table names labels
        const std::string algorithm = label == "PSO" ? "pso" : label == "CMA-ES (IPOP)" ? "cmaes" : label;
        for (const StoredRun* run : runs_of(runs, algorithm, problem))
            errors.push_back(rule(run->best_f - run->f_opt));
        ASSERT_EQ(errors.size(), 3u);
        std::sort(errors.begin(), errors.end());
        const double mean = (errors[0] + errors[1] + errors[2]) / 3.0;
        double squares = 0;
        for (const double e : errors)
            squares += (e - mean) * (e - mean);
        const double std = std::sqrt(squares / 2.0);
        const auto near = [](double expected) { return 1e-12 * std::max(1.0, std::fabs(expected)); };
        EXPECT_EQ(table.number(i, table.column("Best")), errors[0]);
        EXPECT_EQ(table.number(i, table.column("Worst")), errors[2]);
        EXPECT_EQ(table.number(i, table.column("Median")), errors[1]);
        EXPECT_NEAR(table.number(i, table.column("Mean")), mean, near(mean));
        EXPECT_NEAR(table.number(i, table.column("Std")), std, near(std));
    }
    EXPECT_TRUE(fs::exists(dir / "report" / "cec_ranks_d10.csv"));
    EXPECT_NE(read_text(cec / "README").find("D = 10, MaxFES = 100000: 1000 2000 3000 5000 10000"),
              std::string::npos);
}

TEST(CecProtocolCli, Cec2022StudyFileGivesEachDimensionItsBudgetAndFeTerm) {
    const fs::path dir = mhb::testing_cli::scratch_directory() / "cec2022_small";
    fs::remove_all(dir);
    const fs::path file = mhb::testing_cli::scratch_directory() / "cec2022_small.ini";
    std::ofstream(file) << "# CEC 2022 at reduced size\n"
                           "protocol = cec2022\n"
                           "algorithms = pso\n"
                           "problems = cec2022:f=2,dim={10,20}\n"
                           "runs = 2\n"
                           "budget = evaluations=dim10:3000+dim20:6000\n";
    const auto dry =
        run_mhbench("run --study-file '" + file.string() + "' --dry-run --out '" + dir.string() + "'");
    ASSERT_EQ(dry.exit_code, 0) << dry.err;
    EXPECT_NE(
        dry.out.find("evaluations=dim10:3000+dim20:6000: 18000 evaluations (per run: 3000 at D = 10, 6000 "
                     "at D = 20)"),
        std::string::npos)
        << dry.out;
    EXPECT_NE(dry.out.find("protocol: cec2022"), std::string::npos);

    const auto r = run_mhbench("run --study-file '" + file.string() + "' --no-figures --quiet --out '" +
                               dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto runs = read_runs(dir);
    ASSERT_EQ(runs.size(), 4u);
    const std::map<std::int64_t, std::vector<std::int64_t>> checkpoints = {
        // floor(D^(k/5 - 3) x MaxFES), k = 0..15 (at least 1).
        {10, {3, 4, 7, 11, 18, 30, 47, 75, 119, 189, 300, 475, 753, 1194, 1892, 3000}},
        {20, {1, 1, 2, 4, 8, 15, 27, 49, 90, 164, 300, 546, 994, 1810, 3295, 6000}},
    };
    for (const std::int64_t d : {10, 20}) {
        const auto group = runs_of(runs, "pso", "cec2022:dim=" + std::to_string(d) + ",f=2");
        ASSERT_EQ(group.size(), 2u);
        const std::int64_t max_fes = d == 10 ? 3000 : 6000;
        for (const StoredRun* run : group)
            EXPECT_EQ(run->evaluations, max_fes); // no target in this budget: every run spends it all
        const auto rows = matrix(dir / "report" / "cec" / ("PSO_2_" + std::to_string(d) + ".txt"));
        ASSERT_EQ(rows.size(), 17u);
        for (std::size_t k = 0; k < 16; ++k)
            for (std::size_t j = 0; j < 2; ++j)
                EXPECT_EQ(rows[k][j], group[j]->error_at(checkpoints.at(d)[k])) << "D " << d << " row " << k;
        for (std::size_t j = 0; j < 2; ++j) { // FEterm: when the error first fell below 1e-8, else MaxFES
            std::int64_t expected = max_fes;
            for (const auto& [evaluations, f] : group[j]->improvements)
                if (f - group[j]->f_opt < 1e-8) {
                    expected = evaluations;
                    break;
                }
            EXPECT_EQ(rows[16][j], static_cast<double>(expected));
        }
    }
    const std::string ranks = read_text(dir / "report" / "cec_ranks_d20.csv");
    EXPECT_NE(ranks.find("U-score"), std::string::npos) << ranks;
}

TEST(CecProtocolCli, PresetsAreListedAndBadProtocolInputIsOneLine) {
    const auto list = run_mhbench("list studies");
    ASSERT_EQ(list.exit_code, 0);
    for (const char* preset : {"cec2017\n", "cec2017-smoke\n", "cec2022\n"})
        EXPECT_NE(list.out.find(std::string("  ") + preset), std::string::npos) << preset;
    EXPECT_NE(list.out.find("runs: 51, seeds: common, budgets: evaluations=10000*dim,target=1e-08"),
              std::string::npos);
    const auto help = run_mhbench("run --help");
    EXPECT_NE(help.out.find("cec2017-smoke"), std::string::npos);
    EXPECT_NE(help.out.find("10000*dim"), std::string::npos);

    const auto missing = run_mhbench("run --study cec2022 --problems 'cec2022:f=1,dim=2' --dry-run");
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(
        missing.err.find("budget 'evaluations=dim10:200000+dim20:1000000,target=1e-08' gives no evaluations "
                         "at dimension 2 (problem 'cec2022:dim=2,f=1'); it lists 10, 20"),
        std::string::npos)
        << missing.err;
    const auto protocol = run_mhbench("run --study cec2017-smoke --protocol cec2020 --dry-run");
    EXPECT_EQ(protocol.exit_code, 2);
    EXPECT_NE(protocol.err.find("protocol = cec2020 is not one of {cec2017, cec2022, pmsm-paper, none}"),
              std::string::npos)
        << protocol.err;
}

} // namespace
