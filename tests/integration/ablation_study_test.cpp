// The ablation preset end to end through the real binary, at reduced size (4 runs, two small
// budgets): the study is the 2^3 factorial design with common random numbers, every budget gets
// its own report with an effect table, the effects agree with runs.csv recomputed here from the
// definition, and the main-effects and interaction plots are drawn where matplotlib is found.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "cli_harness.hpp"
#include "results/report/report.hpp"
#include "results/store/csv.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::run_mhbench;

// The response of the effect table where f* is known (results/factorial_effects.*):
// log10(max(f - f*, floor)), floor = max(1e-300, 4 eps |f*|).
double response(double f, double f_opt) {
    const double floor = std::max(1e-300, 4.0 * std::numeric_limits<double>::epsilon() * std::fabs(f_opt));
    return std::log10(std::max(f - f_opt, floor));
}

TEST(SlowAblationStudy, EffectTablesPerBudgetAgreeWithTheRunRecordsAndThePlotsExist) {
    const fs::path dir = mhb::testing_cli::scratch_directory() / "ablation_small";
    fs::remove_all(dir);
    const bool figures = mhb::find_matplotlib_python({"/usr/bin/python3", "python3"}).has_value();
    const auto r =
        run_mhbench("run --study ablation --runs 4 --budget iterations=8 --budget evaluations=1500 "
                    "--threads 2 --quiet " +
                    std::string(figures ? "" : "--no-figures ") + "--out '" + dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;

    // Which variant has which switches on: algorithms.csv gives every parameter of each.
    const mhb::CsvTable algorithms = mhb::read_csv(dir / "algorithms.csv");
    ASSERT_EQ(algorithms.rows.size(), 8u);
    std::map<std::string, std::map<std::string, bool>> on; // spec -> switch -> on
    for (const auto& row : algorithms.rows)
        for (const char* factor : {"tutorial", "stepwise", "obl"})
            on[row[algorithms.column("algorithm")]][factor] =
                row[algorithms.column("parameters")].find(std::string(factor) + "=on") != std::string::npos;
    EXPECT_EQ(algorithms.rows.front()[algorithms.column("label")], "itlbo[T+S+O+]");

    const mhb::CsvTable runs = mhb::read_csv(dir / "runs.csv");
    ASSERT_EQ(runs.rows.size(), 8u * 3u * 2u * 4u);
    const mhb::CsvTable budgets = mhb::read_csv(dir / "report" / "budgets.csv");
    ASSERT_EQ(budgets.rows.size(), 2u);
    std::size_t checked = 0;
    for (const auto& budget_row : budgets.rows) {
        const std::string& budget = budget_row[budgets.column("budget")];
        const fs::path report = dir / "report" / budget_row[budgets.column("directory")];
        const mhb::CsvTable effects = mhb::read_csv(report / "effects.csv");
        // Per (problem, run index): the responses of the 8 variants, which share one seed.
        std::map<std::pair<std::string, std::string>, std::map<std::string, double>> blocks;
        std::map<std::pair<std::string, std::string>, std::string> seeds;
        for (std::size_t i = 0; i < runs.rows.size(); ++i) {
            const auto& row = runs.rows[i];
            if (row[runs.column("budget")] != budget)
                continue;
            const auto key = std::make_pair(row[runs.column("problem")], row[runs.column("run")]);
            blocks[key][row[runs.column("algorithm")]] =
                response(runs.number(i, runs.column("best_f")), runs.number(i, runs.column("f_opt")));
            if (seeds.count(key) != 0) {
                EXPECT_EQ(seeds[key], row[runs.column("seed")]); // common random numbers
            }
            seeds[key] = row[runs.column("seed")];
        }
        ASSERT_EQ(blocks.size(), 3u * 4u);
        for (std::size_t e = 0; e < effects.rows.size(); ++e) {
            const std::string problem = effects.rows[e][effects.column("Problem")];
            const std::string factor = effects.rows[e][effects.column("Effect")];
            if (factor.find(" x ") != std::string::npos || problem.rfind("all problems", 0) == 0)
                continue;
            // Main effect by its definition: per block, mean response with the switch on minus
            // with it off (each over the 4 settings of the other two switches); then the mean.
            double sum = 0;
            int count = 0;
            for (const auto& [key, values] : blocks) {
                if (key.first != problem)
                    continue;
                double with = 0;
                double without = 0;
                for (const auto& [spec, y] : values)
                    (on.at(spec).at(factor) ? with : without) += y / 4.0;
                sum += with - without;
                ++count;
            }
            ASSERT_EQ(count, 4) << problem;
            EXPECT_NEAR(effects.number(e, effects.column("Mean")), sum / count,
                        1e-9 * (1 + std::fabs(sum / count)))
                << budget << " " << problem << " " << factor;
            EXPECT_EQ(effects.rows[e][effects.column("Paired")], "yes");
            ++checked;
        }
        if (!figures)
            continue;
        for (const char* name :
             {"effects_overview_itlbo.png", "effects_main_itlbo.pdf", "effects_interaction_itlbo.png",
              "convergence_evaluations_all.png", "final_values_all.pdf"}) // three per design since issue 37
            EXPECT_TRUE(fs::exists(report / "figures" / name)) << report / "figures" / name;
    }
    EXPECT_EQ(checked, 2u * 3u * 3u); // two budgets x three problems x three main effects
}

} // namespace
