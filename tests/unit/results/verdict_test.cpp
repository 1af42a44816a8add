// The verdict (results/analysis/verdict.*, results/reporters/verdict_lines.*): the ranking by median,
// the test against the best with hand-checked exact p-values and Holm, the rank-sum test where runs
// are not paired, the components of a factorial design, and the console's bound of lines and columns
// on a large study.
#include <gtest/gtest.h>

#include "results/analysis/verdict.hpp"
#include "results/reporters/verdict_lines.hpp"
#include "results/store/study_index.hpp"
#include "results/tables/verdict_tables.hpp"

namespace mhb {
namespace {

RunRecord verdict_run(const std::string& algorithm, const std::string& problem, std::int64_t index, double f,
                      std::uint64_t seed) {
    RunRecord r;
    r.algorithm = algorithm;
    r.problem = problem;
    r.budget = "evaluations=100";
    r.run_index = index;
    r.seed = seed;
    r.best_f = f;
    r.f_opt = 0.0;
    r.evaluations = 100;
    return r;
}

// Three algorithms on one problem, 8 runs each: a = 1..8 (median 4.5), b = 1.1 (a) in run a
// (b - a = 0.1, ..., 0.8: no ties; median 4.95), c = a + {8, -1, 7, -2, 6, -3, 5, -4} (median 6.5),
// listed in the order c, b, a.
StudyData three_algorithms(bool common_seeds) {
    StudyData data;
    const double c_shift[] = {8, -1, 7, -2, 6, -3, 5, -4};
    std::int64_t id = 0;
    for (const char* algorithm : {"c", "b", "a"})
        for (std::int64_t i = 0; i < 8; ++i) {
            const double a = static_cast<double>(i + 1);
            const double f = algorithm[0] == 'a' ? a : algorithm[0] == 'b' ? a * 1.1 : a + c_shift[i];
            const std::uint64_t seed = common_seeds ? 100U + static_cast<std::uint64_t>(i)
                                                    : static_cast<std::uint64_t>(id) * 7U + 1U;
            data.runs.push_back(verdict_run(algorithm, "sphere:dim=2", i, f, seed));
            data.runs.back().run_id = id++;
        }
    return data;
}

TEST(Verdict, RanksByMedianAndTestsEachAgainstTheBestWithHolm) {
    const StudyData data = three_algorithms(true);
    const StudyIndex index(data);
    const BudgetVerdict verdict = budget_verdict(index, 0.05, {});
    ASSERT_EQ(verdict.problems.size(), 1u);
    const ProblemVerdict& p = verdict.problems.front();
    EXPECT_TRUE(p.paired);
    ASSERT_EQ(p.ranking.size(), 3u);
    EXPECT_EQ(p.ranking[0].algorithm, "a");
    EXPECT_EQ(p.ranking[1].algorithm, "b");
    EXPECT_EQ(p.ranking[2].algorithm, "c");
    EXPECT_EQ(p.ranking[0].versus_best, VersusBest::best);
    ASSERT_TRUE(p.ranking[0].median_gap.has_value());
    EXPECT_DOUBLE_EQ(*p.ranking[0].median_gap, 4.5);
    // b - a > 0 in all 8 pairs, no ties: exact signed-rank p = 2 / 2^8 = 0.0078125, Holm (2 tests) x 2.
    EXPECT_DOUBLE_EQ(p.ranking[1].adjusted_p, 0.015625);
    EXPECT_EQ(p.ranking[1].versus_best, VersusBest::worse);
    // c - a: V = 8 + 7 + 6 + 5 = 26, P(V >= 26) = 40 / 256 (enumerated), two-sided 0.3125; Holm keeps it.
    EXPECT_DOUBLE_EQ(p.ranking[2].adjusted_p, 0.3125);
    EXPECT_EQ(p.ranking[2].versus_best, VersusBest::not_different);
    // At alpha = 0.01, b is no longer significantly worse.
    EXPECT_EQ(budget_verdict(index, 0.01, {}).problems.front().ranking[1].versus_best,
              VersusBest::not_different);
}

TEST(Verdict, UsesTheRankSumTestWhereRunsAreNotPaired) {
    const StudyData data = three_algorithms(false);
    const StudyIndex index(data);
    const ProblemVerdict p = budget_verdict(index, 0.05, {}).problems.front();
    EXPECT_FALSE(p.paired);
    // b against a, unpaired: 1.1..8.8 against 1..8 are far from separated (exact rank-sum).
    EXPECT_EQ(p.ranking[1].algorithm, "b");
    EXPECT_EQ(p.ranking[1].versus_best, VersusBest::not_different);
    EXPECT_GT(p.ranking[1].adjusted_p, 0.05);
}

TEST(Verdict, SaysWhatEachComponentDoesPooledFirst) {
    const StudyData data = three_algorithms(true);
    const StudyIndex index(data);
    DesignEffects design;
    design.design.name = "itlbo";
    design.design.factors = {"obl", "tutorial"};
    EffectAnalysis one;
    one.problem = "sphere:dim=2";
    one.scale = ResponseScale::log10_gap;
    EffectEstimate helps;
    helps.name = "tutorial";
    helps.factors = {1};
    helps.mean = -2.0;
    helps.adjusted_p = 0.001;
    helps.direction = EffectDirection::lowers;
    helps.reading = "tutorial on lowers log10(f - f*) by 2: helps";
    EffectEstimate none = helps;
    none.name = "obl";
    none.factors = {0};
    none.direction = EffectDirection::none;
    none.reading = "no significant effect";
    EffectEstimate interaction = helps;
    interaction.name = "obl x tutorial";
    interaction.factors = {0, 1};
    one.effects = {none, helps, interaction};
    EffectAnalysis pooled = one;
    pooled.problem = "all problems (2)";
    pooled.problems = 2;
    pooled.effects[0].direction = EffectDirection::raises;
    pooled.effects[0].reading = "obl on raises log10(f - f*) by 1: hurts";
    design.analyses = {one, pooled};
    const BudgetVerdict verdict = budget_verdict(index, 0.05, {design});
    ASSERT_EQ(verdict.effects.size(), 4u); // main effects only
    EXPECT_TRUE(verdict.effects[0].pooled);
    EXPECT_EQ(verdict.effects[0].component, "obl");
    EXPECT_EQ(verdict.effects[0].effect, ComponentEffect::hurts);
    EXPECT_EQ(verdict.effects[1].effect, ComponentEffect::helps);
    EXPECT_FALSE(verdict.effects[2].pooled);
    EXPECT_EQ(verdict.effects[2].effect, ComponentEffect::no_evidence);
    const std::vector<Table> tables = verdict_tables(verdict);
    ASSERT_EQ(tables.size(), 2u); // one problem: no ranking across problems
    EXPECT_EQ(tables[0].id, "verdict_effects");
    EXPECT_EQ(tables[0].rows[0][3].text, "hurts");
    EXPECT_EQ(tables[0].header.size(), 7u); // no Bayesian test computed: no probability columns
}

TEST(VerdictLines, PrintTheRankingOfOneProblem) {
    const StudyData data = three_algorithms(true);
    const std::vector<std::string> lines = verdict_lines(budget_verdict(StudyIndex(data), 0.05, {}), 20);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0], "Verdict, budget evaluations=100 (alpha = 0.05):");
    EXPECT_NE(lines[1].find("sphere:dim=2 (8 runs, 100 evaluations; vs best: Wilcoxon signed-rank"),
              std::string::npos)
        << lines[1];
    EXPECT_NE(lines[3].find("   1 a "), std::string::npos) << lines[3];
    EXPECT_NE(lines[3].find("best"), std::string::npos);
    EXPECT_NE(lines[4].find("worse (p = 0.016)"), std::string::npos) << lines[4];
    EXPECT_NE(lines[5].find("not different (p = 0.31)"), std::string::npos) << lines[5];
}

// 40 problems x 12 algorithms with long labels: whatever the detail, the bound holds.
TEST(VerdictLines, KeepALargeStudyWithinItsLinesAndColumns) {
    StudyData data;
    std::int64_t id = 0;
    for (int p = 0; p < 40; ++p)
        for (int a = 0; a < 12; ++a)
            for (std::int64_t i = 0; i < 5; ++i) {
                data.runs.push_back(verdict_run(
                    "algorithm_with_a_rather_long_name:variant=" + std::to_string(a),
                    "cec2017:dim=10,f=" + std::to_string(p), i, static_cast<double>((a * 7 + p * 3 + i) % 11),
                    10U + static_cast<std::uint64_t>(i)));
                data.runs.back().run_id = id++;
            }
    const BudgetVerdict verdict = budget_verdict(StudyIndex(data), 0.05, {});
    for (std::size_t max_lines : {8U, 22U, 40U}) {
        const std::vector<std::string> lines = verdict_lines(verdict, max_lines);
        EXPECT_LE(lines.size(), max_lines);
        for (const auto& line : lines)
            EXPECT_LE(line.size(), verdict_width) << line;
    }
    const std::vector<std::string> lines = verdict_lines(verdict, 22);
    EXPECT_NE(lines[1].find("Across 40 problems: Friedman p = "), std::string::npos) << lines[1];
    EXPECT_NE(lines.back().find("Per problem (40 problems): comparison.md and tests.md"), std::string::npos)
        << lines.back();
}

} // namespace
} // namespace mhb
