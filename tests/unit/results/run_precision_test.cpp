// The rule of runs by precision (results/analysis/run_precision.hpp): standard errors worked out by
// hand, the stopping points they give, and the rule read back from a study.ini.
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

#include "results/analysis/run_precision.hpp"

namespace mhb {
namespace run_precision_test {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinite = std::numeric_limits<double>::infinity();

TEST(RunPrecision, PairedStandardErrorIsThatOfTheDifferences) {
    const std::vector<double> a{1, 2, 3, 4};
    const std::vector<double> ref{0, 0, 0, 0};
    // sd(1, 2, 3, 4) = sqrt(5 / 3); / sqrt(4)
    EXPECT_DOUBLE_EQ(standard_error(a, &ref, true, 4), std::sqrt(5.0 / 3.0) / 2.0);
    // Only the first n count.
    EXPECT_DOUBLE_EQ(standard_error(a, &ref, true, 2), std::sqrt(0.5) / std::sqrt(2.0));
    // A shift common to both runs of a pair cancels: that is what pairing buys.
    const std::vector<double> shifted{11, 22, 33, 44};
    const std::vector<double> ref_shifted{10, 20, 30, 40};
    EXPECT_DOUBLE_EQ(standard_error(shifted, &ref_shifted, true, 4), std::sqrt(5.0 / 3.0) / 2.0);
    EXPECT_GT(standard_error(shifted, &ref_shifted, false, 4), 5.0);
}

TEST(RunPrecision, WelchStandardErrorAddsTheTwoVariances) {
    const std::vector<double> a{1, 2, 3};
    const std::vector<double> ref{2, 4, 6};
    EXPECT_DOUBLE_EQ(standard_error(a, &ref, false, 3), std::sqrt(1.0 / 3.0 + 4.0 / 3.0));
    EXPECT_DOUBLE_EQ(standard_error(a, nullptr, false, 3), 1.0 / std::sqrt(3.0));
}

TEST(RunPrecision, FailedRunsAreLeftOutAndInfinitiesAreHonest) {
    // A failed run (NaN) drops its pair.
    const std::vector<double> a{1, not_a_number, 3, 5};
    const std::vector<double> ref{0, 0, 0, 0};
    EXPECT_DOUBLE_EQ(standard_error(a, &ref, true, 4), 2.0 / std::sqrt(3.0));
    // Two runs that both ended at +inf tie: a zero difference, not inf - inf.
    const std::vector<double> tied{infinite, 1, 2};
    const std::vector<double> tied_ref{infinite, 1, 2};
    EXPECT_EQ(standard_error(tied, &tied_ref, true, 3), 0.0);
    // One that did not: nothing is known of the difference.
    const std::vector<double> lost{infinite, 1, 2};
    EXPECT_EQ(standard_error(lost, &ref, true, 3), infinite);
    // Fewer than two usable values: unknown.
    EXPECT_EQ(standard_error({1.0}, nullptr, false, 1), infinite);
}

TEST(RunPrecision, StoppingPointsFollowTheRounds) {
    PrecisionRule rule;
    rule.precision = 0.1;
    rule.initial = 4;
    rule.step = 3;
    rule.max = 12;
    const std::vector<double> ref(12, 0.0);
    // A constant difference: settled at the first look.
    const CellPrecision constant = stopping_point(std::vector<double>(12, 1.0), &ref, true, rule);
    EXPECT_EQ(constant.stop, PrecisionStop::precision_reached);
    EXPECT_EQ(constant.runs, 4);
    EXPECT_EQ(constant.standard_error, 0.0);
    // Noisy first runs, quiet later: 4 runs (SE 0.5), 7, then 10 runs reach it.
    const std::vector<double> settling{1, -1, 1, -1, 0, 0, 0, 0, 0, 0, 0, 0};
    const CellPrecision later = stopping_point(settling, &ref, true, rule);
    // At 7: sd = sqrt(4 / 6) = 0.816, SE 0.309; at 10: sqrt(4 / 9) / sqrt(10) = 0.211; at 12 (the
    // most): sqrt(4 / 11) / sqrt(12) = 0.174 > 0.1: the cell stops at max-runs.
    EXPECT_EQ(later.stop, PrecisionStop::max_reached);
    EXPECT_EQ(later.runs, 12);
    EXPECT_NEAR(later.standard_error, std::sqrt(4.0 / 11.0) / std::sqrt(12.0), 1e-15);
    // With 7 runs known, the rule asks for 10.
    const std::vector<double> partial(settling.begin(), settling.begin() + 7);
    const CellPrecision waiting = stopping_point(partial, &ref, true, rule);
    EXPECT_EQ(waiting.stop, PrecisionStop::needs_runs);
    EXPECT_EQ(waiting.runs, 10);
    // The reference's runs count as much as the cell's own.
    const std::vector<double> short_ref(5, 0.0);
    EXPECT_EQ(stopping_point(settling, &short_ref, true, rule).runs, 7);
}

TEST(RunPrecision, TheRuleIsReadBackFromStudyIni) {
    EXPECT_FALSE(precision_rule_of("runs = 20\nseed = 1\n"));
    const auto rule = precision_rule_of(
        "algorithms = tlbo\nruns = auto\nprecision = 0.05\nmax-runs = 40\ninitial-runs = 6\n"
        "round-runs = 2\n");
    ASSERT_TRUE(rule);
    EXPECT_EQ(rule->precision, 0.05);
    EXPECT_EQ(rule->max, 40);
    EXPECT_EQ(rule->initial, 6);
    EXPECT_EQ(rule->step, 2);
}

TEST(RunPrecision, TheDefaultReferenceIsThePapersItlbo) {
    EXPECT_EQ(default_reference_index({"pso", "tlbo", "itlbo"}), 2u);
    EXPECT_EQ(default_reference_index({"pso", "itlbo:obl=off", "itlbo:stepwise=off"}), 1u);
    EXPECT_EQ(default_reference_index({"pso", "tlbo"}), 0u);
}

TEST(RunPrecision, ComparedValueIsTheLog10GapWhereTheOptimumIsKnown) {
    RunRecord run;
    run.ok = true;
    run.best_f = 1.001;
    EXPECT_EQ(compared_value(run), 1.001);
    run.f_opt = 1.0;
    EXPECT_NEAR(compared_value(run), -3.0, 1e-9);
    run.ok = false;
    EXPECT_TRUE(std::isnan(compared_value(run)));
}

} // namespace run_precision_test
} // namespace mhb
