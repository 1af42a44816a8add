// The Bayesian signed-rank tests against the reference (results/analysis/bayesian_comparisons.hpp),
// their table (results/tables/bayesian_table.hpp) and the Bayesian effects, on hand-made runs whose
// differences leave no doubt: which side is which, the log10 gap where f* is known and raw f with
// no ROPE elsewhere, the all-problems row, unpaired runs, and the CSV.
#include <cmath>
#include <gtest/gtest.h>

#include "results/analysis/bayesian_comparisons.hpp"
#include "results/analysis/bayesian_effects.hpp"
#include "results/store/study_index.hpp"
#include "results/tables/bayesian_table.hpp"

namespace mhb {
namespace {

RunRecord bayes_run(const std::string& problem, const std::string& algorithm, std::int64_t index,
                    double best_f, std::optional<double> f_opt, std::uint64_t seed) {
    RunRecord r;
    r.algorithm = algorithm;
    r.problem = problem;
    r.budget = "evaluations=100";
    r.run_index = index;
    r.seed = seed;
    r.f_opt = f_opt;
    r.best_f = best_f;
    r.evaluations = 100;
    r.best_x = {0.0};
    return r;
}

// 20 paired runs on two problems with f* = 0: "ref" ends 1e-8 x (1 + small), "slow" 1e-2 x (1 +
// small) (six decades worse), "twin" within 1e-3 decades of "ref". A third problem without f*:
// "ref" and "twin" equal, "slow" 1 higher.
StudyData bayes_study(bool common_seeds) {
    StudyData data;
    data.directory = "/nonexistent/bayes";
    for (const char* problem : {"sphere:dim=2", "rastrigin:dim=2"})
        for (std::int64_t i = 0; i < 20; ++i) {
            const double wobble = 1.0 + 0.01 * static_cast<double>(i % 7);
            const auto seed = [&](std::uint64_t a) {
                return common_seeds ? 7u + static_cast<std::uint64_t>(i)
                                    : 100 * a + static_cast<std::uint64_t>(i);
            };
            data.runs.push_back(bayes_run(problem, "ref", i, 1e-8 * wobble, 0.0, seed(1)));
            data.runs.push_back(bayes_run(problem, "slow", i, 1e-2 * wobble, 0.0, seed(2)));
            data.runs.push_back(bayes_run(problem, "twin", i, 1e-8 * wobble * 1.001, 0.0, seed(3)));
        }
    for (std::int64_t i = 0; i < 20; ++i) {
        const double f = 5.0 + 0.1 * static_cast<double>(i);
        const auto seed = static_cast<std::uint64_t>(50 + i);
        data.runs.push_back(bayes_run("external", "ref", i, f, std::nullopt, seed));
        data.runs.push_back(bayes_run("external", "slow", i, f + 1.0, std::nullopt, seed));
        data.runs.push_back(bayes_run("external", "twin", i, f, std::nullopt, seed));
    }
    return data;
}

const BayesianComparison& find_comparison(const std::vector<BayesianComparison>& all,
                                          const std::string& problem, const std::string& algorithm) {
    for (const auto& c : all)
        if (c.problem == problem && c.algorithm == algorithm)
            return c;
    throw std::logic_error("no comparison " + problem + " " + algorithm);
}

TEST(BayesianComparisons, SidesScalesAndTheAllProblemsRow) {
    const StudyData data = bayes_study(true);
    const StudyIndex index(data);
    const auto all = bayesian_comparisons(index, "ref", BayesianRope{}, 10);
    ASSERT_EQ(all.size(), 6U); // 3 problems x 2 algorithms; no all-problems row (one problem lacks f*)
    const auto& slow = find_comparison(all, "sphere:dim=2", "slow");
    EXPECT_TRUE(slow.log10_gap);
    EXPECT_EQ(slow.rope, 0.1);
    EXPECT_EQ(slow.result.pairs, 20U);
    EXPECT_EQ(slow.result.left, 1.0); // the reference is six decades better in every pair
    EXPECT_EQ(slow.result.thetas.size(), 10U);
    const auto& twin = find_comparison(all, "rastrigin:dim=2", "twin");
    EXPECT_EQ(twin.result.rope, 1.0); // 4e-4 decades apart: inside the 0.1-decade ROPE
    const auto& raw = find_comparison(all, "external", "slow");
    EXPECT_FALSE(raw.log10_gap);
    EXPECT_FALSE(raw.rope.has_value()); // raw f: no ROPE unless given
    EXPECT_EQ(raw.result.left, 1.0);
    const auto& raw_twin = find_comparison(all, "external", "twin");
    EXPECT_EQ(raw_twin.result.rope, 1.0); // every difference exactly 0: the closed ROPE [0, 0]

    // With a raw ROPE of 2 (units of f), "slow" (1 higher) is equivalent there.
    BayesianRope wide;
    wide.raw = 2.0;
    const auto given = bayesian_comparisons(index, "ref", wide, 0);
    EXPECT_EQ(find_comparison(given, "external", "slow").result.rope, 1.0);
}

TEST(BayesianComparisons, AllProblemsRowFromMediansWhenEveryProblemKnowsTheOptimum) {
    StudyData data = bayes_study(true);
    std::erase_if(data.runs, [](const RunRecord& r) { return r.problem == "external"; });
    const StudyIndex index(data);
    const auto all = bayesian_comparisons(index, "ref", BayesianRope{}, 0);
    const auto& across = find_comparison(all, "all problems (2)", "slow");
    EXPECT_TRUE(across.across_problems);
    EXPECT_EQ(across.result.pairs, 2U);
    // Two differences of -6 decades: theta_left = 1 - w0^2 is the largest unless w0 > 0.71, which
    // Beta(0.5, 2) gives with probability ~0.1.
    EXPECT_GT(across.result.left, 0.8);
    EXPECT_LT(across.result.left, 1.0);
    const std::string csv = bayesian_csv(index, "ref", all);
    EXPECT_NE(csv.find("\nall problems (2),slow,ref,1,log10_gap,0.1,2,"), std::string::npos) << csv;
    EXPECT_EQ(csv.rfind("problem,algorithm,reference,across_problems,scale,rope,pairs,", 0), 0U);
}

TEST(BayesianComparisons, UnpairedRunsAreNamedNotTested) {
    const StudyData data = bayes_study(false);
    const StudyIndex index(data);
    const auto all = bayesian_comparisons(index, "ref", BayesianRope{}, 0);
    const auto& slow = find_comparison(all, "sphere:dim=2", "slow");
    EXPECT_FALSE(slow.paired);
    const auto table = bayesian_table(index, "ref", all, BayesianRope{});
    ASSERT_TRUE(table.has_value());
    EXPECT_EQ(table->rows.front()[4].text, "no (seeds differ)");
    EXPECT_NE(table->caption.find("no (seeds differ)"), std::string::npos);
    EXPECT_EQ(bayesian_csv(index, "ref", all).find("sphere"), std::string::npos); // no test, no row
}

TEST(BayesianComparisons, TableShowsTheProbabilitiesAndSaysWhenThereIsNoRope) {
    const StudyData data = bayes_study(true);
    const StudyIndex index(data);
    const auto all = bayesian_comparisons(index, "ref", BayesianRope{}, 0);
    const auto table = bayesian_table(index, "ref", all, BayesianRope{});
    ASSERT_TRUE(table.has_value());
    EXPECT_EQ(table->id, "bayesian");
    ASSERT_EQ(table->rows.size(), 6U);
    EXPECT_EQ(table->rows[0][5].text, "1.000");   // sphere, slow: P(reference better)
    EXPECT_EQ(table->rows[4][3].text, "no ROPE"); // external
    EXPECT_NE(table->caption.find("--raw-rope"), std::string::npos);
}

TEST(BayesianEffects, ProbabilitiesPerEffectWithTheRopeOfTheScale) {
    // Two switches over 12 blocks: A lowers the response by 2 decades, B by 0.01 (inside the ROPE).
    std::vector<std::vector<double>> blocks;
    for (int b = 0; b < 12; ++b) {
        const double noise = 0.001 * b;
        blocks.push_back({noise, -2.0 + noise, -0.01 + noise, -2.01 + noise});
    }
    DesignEffects design;
    design.design.name = "x";
    design.design.factors = {"a", "b"};
    design.analyses.push_back(analyse_factorial_blocks(blocks, {"a", "b"}, ResponseScale::log10_gap, 0.05));
    std::vector<DesignEffects> designs = {design};
    add_bayesian_effects(designs, 0.1);
    const auto& effects = designs[0].analyses[0].effects;
    EXPECT_EQ(designs[0].analyses[0].rope, 0.1);
    EXPECT_EQ(effects[0].p_lowers, 1.0);    // a
    EXPECT_EQ(effects[1].p_no_effect, 1.0); // b
    EXPECT_EQ(effects[2].p_no_effect, 1.0); // a x b: 0 in every block
}

} // namespace
} // namespace mhb
