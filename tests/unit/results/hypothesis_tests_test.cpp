// The nonparametric tests against published worked examples and independent implementations.
// Where a value comes from SciPy, it is scipy 1.10.1 (Debian's /usr/bin/python3), whose
// mannwhitneyu / wilcoxon / friedmanchisquare implement the same definitions independently.
#include <gtest/gtest.h>
#include <stdexcept>

#include "results/analysis/hypothesis_tests.hpp"

namespace mhb {
namespace {

TEST(RankSum, ExactWithoutTiesMatchesRsDocumentationExample) {
    // R's ?wilcox.test example (Hollander & Wolfe): x = permeability at delivery, y = at 12-26 weeks;
    // R prints "W = 35, p-value = 0.1272" for alternative = "greater"; the two-sided exact p is
    // twice that: scipy.stats.mannwhitneyu(x, y, method='exact') = 0.2544122544122544.
    const std::vector<double> x = {0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46};
    const std::vector<double> y = {1.15, 0.88, 0.90, 0.74, 1.21};
    const TestResult r = rank_sum_test(x, y);
    EXPECT_TRUE(r.exact);
    EXPECT_EQ(r.statistic, 35.0);
    EXPECT_NEAR(r.p_value, 0.2544122544122544, 1e-12);
    EXPECT_NE(r.name.find("Wilcoxon rank-sum"), std::string::npos);
    EXPECT_NE(r.name.find("exact"), std::string::npos);
    // Symmetry: swapping the samples gives U' = m n - U and the same two-sided p.
    const TestResult swapped = rank_sum_test(y, x);
    EXPECT_EQ(swapped.statistic, 50.0 - 35.0);
    EXPECT_NEAR(swapped.p_value, r.p_value, 1e-12);
}

TEST(RankSum, ExactTailByHand) {
    // x = {1, 2, 3} all below y = {4, 5, 6, 7}: U = 0, P(U <= 0) = 1 / C(7, 3) = 1/35, two-sided 2/35.
    const TestResult r = rank_sum_test({1, 2, 3}, {4, 5, 6, 7});
    EXPECT_EQ(r.statistic, 0.0);
    EXPECT_NEAR(r.p_value, 2.0 / 35.0, 1e-15);
}

TEST(RankSum, ExactStaysAccurateInTheFarTailAndForPaperSizedSamples) {
    // 30 values all below 30 others: U = 0, p = 2 / C(60, 30) = 1.6911233892144735e-17 (Python's
    // exact integer math.comb). And a 30 x 30 case with overlap: scipy.stats.mannwhitneyu(x, y,
    // method='exact') gives U = 184.0, p = 4.7002042164004806e-05.
    std::vector<double> low;
    std::vector<double> high;
    std::vector<double> x;
    std::vector<double> y;
    for (int i = 0; i < 30; ++i) {
        low.push_back(i);
        high.push_back(100 + i);
        x.push_back(i + 0.5);
        y.push_back(i * 0.9 + 12.25);
    }
    const TestResult tail = rank_sum_test(low, high);
    EXPECT_TRUE(tail.exact);
    EXPECT_NEAR(tail.p_value / 1.6911233892144735e-17, 1.0, 1e-12);
    const TestResult overlap = rank_sum_test(x, y);
    EXPECT_EQ(overlap.statistic, 184.0);
    EXPECT_NEAR(overlap.p_value / 4.7002042164004806e-05, 1.0, 1e-10);
}

TEST(RankSum, NormalApproximationWithTiesAndContinuityCorrection) {
    // scipy.stats.mannwhitneyu(x, y, method='asymptotic', use_continuity=True): U = 9.0,
    // p = 0.09667054340670089 (same formula as R's wilcox.test with correct = TRUE).
    const TestResult r = rank_sum_test({1, 2, 2, 3, 4, 5}, {2, 3, 3, 6, 7, 8, 9});
    EXPECT_FALSE(r.exact);
    EXPECT_EQ(r.statistic, 9.0);
    EXPECT_NEAR(r.p_value, 0.09667054340670089, 1e-12);
    EXPECT_NE(r.name.find("normal approx"), std::string::npos);
}

TEST(RankSum, LargeSamplesWithoutTiesUseTheNormalApproximation) {
    // 60 and 55 distinct values: scipy asymptotic with continuity: U = 1488.0, p = 0.3658753614407385.
    std::vector<double> x;
    std::vector<double> y;
    for (int i = 0; i < 60; ++i)
        x.push_back(i * 1.0 + 0.5);
    for (int i = 0; i < 55; ++i)
        y.push_back(i * 1.1 + 3.33);
    const TestResult r = rank_sum_test(x, y);
    EXPECT_FALSE(r.exact);
    EXPECT_EQ(r.statistic, 1488.0);
    EXPECT_NEAR(r.p_value, 0.3658753614407385, 1e-12);
    EXPECT_THROW((void)rank_sum_test({}, {1.0}), std::invalid_argument);
}

TEST(SignedRank, ExactMatchesRsDocumentationExample) {
    // R's ?wilcox.test paired example (depression scale, Hollander & Wolfe): V = 40, p = 0.01953
    // for "greater". By hand: negative differences have ranks 2 and 3, V = 45 - 5 = 40; subsets of
    // {1..9} with sum <= 5 number 10, so P = 10/512 one-sided, 20/512 = 0.0390625 two-sided.
    const std::vector<double> x = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
    const std::vector<double> y = {0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
    const TestResult r = signed_rank_test(x, y);
    EXPECT_TRUE(r.exact);
    EXPECT_EQ(r.statistic, 40.0);
    EXPECT_DOUBLE_EQ(r.p_value, 0.0390625);
    EXPECT_NE(r.name.find("Wilcoxon signed-rank"), std::string::npos);
}

TEST(SignedRank, NormalApproximationWithZerosAndTies) {
    // scipy.stats.wilcoxon(x, y, zero_method='wilcox', correction=True, mode='approx'):
    // statistic min(V+, V-) = 17.5, p = 0.17445220075642565. One zero is dropped (11 pairs, rank
    // total 66), so V+ = 66 - 17.5 = 48.5.
    const std::vector<double> x = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    const std::vector<double> y = {1.5, 2, 1, 2, 3, 4.5, 9, 6, 7, 7, 8, 16};
    const TestResult r = signed_rank_test(x, y);
    EXPECT_FALSE(r.exact);
    EXPECT_EQ(r.statistic, 48.5);
    EXPECT_NEAR(r.p_value, 0.17445220075642565, 1e-12);
    EXPECT_THROW((void)signed_rank_test({1, 2}, {1}), std::invalid_argument);
    EXPECT_EQ(signed_rank_test({1, 2}, {1, 2}).p_value, 1.0);
}

TEST(SignedRank, ExactBelowFiftyPairsNormalFromFiftyAsRsWilcoxTestPaired) {
    // R's wilcox.test(x, y, paired = TRUE) (exact = NULL, correct = TRUE) is exact for n < 50
    // non-zero differences without ties, normal with continuity correction otherwise. SciPy 1.10's
    // default switches at n <= 50, so the references name the method: d_i = 0.1 (i + 1), negative
    // for i divisible by 3.
    //   scipy.stats.wilcoxon(d[:49], method='exact')                  -> p = 0.06248542836759796
    //   scipy.stats.wilcoxon(d, method='approx', correction=True)     -> p = 0.04070768613514751
    // (SciPy reports min(V+, V-) = 425 for both; V+ = 800 and 850 by hand.)
    std::vector<double> d;
    for (int i = 0; i < 50; ++i)
        d.push_back(0.1 * (i + 1) * (i % 3 != 0 ? 1.0 : -1.0));
    const std::vector<double> first49(d.begin(), d.begin() + 49);
    const TestResult exact = signed_rank_test(first49, std::vector<double>(49, 0.0));
    EXPECT_TRUE(exact.exact);
    EXPECT_EQ(exact.statistic, 800.0);
    EXPECT_NEAR(exact.p_value, 0.06248542836759796, 1e-12);
    const TestResult normal = signed_rank_test(d, std::vector<double>(50, 0.0));
    EXPECT_FALSE(normal.exact);
    EXPECT_EQ(normal.statistic, 850.0);
    EXPECT_NEAR(normal.p_value, 0.04070768613514751, 1e-12);
    EXPECT_NE(normal.name.find("normal approx"), std::string::npos);
}

TEST(SignedRank, PairedDifferencesOfRunsAsScipy) {
    // The paired runs of report_factors_test.cpp: reference 1 + i, algorithm 1 + i + d_i.
    // scipy.stats.wilcoxon(x, y, method='exact') -> statistic 1.0 (= V-), p = 0.015625 = 4/256:
    // V+ = 36 - 1 = 35, and the subsets of {1..8} with sum <= 1 are {} and {1}.
    const std::vector<double> d = {0.5, 0.25, -0.125, 0.75, 1.0, 0.375, 0.625, 0.875};
    std::vector<double> x;
    std::vector<double> y;
    for (std::size_t i = 0; i < d.size(); ++i) {
        y.push_back(1.0 + static_cast<double>(i));
        x.push_back(y.back() + d[i]);
    }
    const TestResult r = signed_rank_test(x, y);
    EXPECT_TRUE(r.exact);
    EXPECT_EQ(r.statistic, 35.0);
    EXPECT_DOUBLE_EQ(r.p_value, 0.015625);
}

TEST(Friedman, MatchesRsRoundingTimesExample) {
    // R's ?friedman.test example (Hollander & Wolfe, rounding first base, 22 players x 3 methods):
    // "Friedman chi-squared = 11.143, df = 2, p-value = 0.003805"; scipy.stats.friedmanchisquare
    // gives 11.142857142857132 and p = 0.003805040775511383; average ranks (scipy rankdata) are
    // 2.40909091, 2.13636364, 1.45454545.
    const double data[22][3] = {
        {5.40, 5.50, 5.55}, {5.85, 5.70, 5.75}, {5.20, 5.60, 5.50}, {5.55, 5.50, 5.40}, {5.90, 5.85, 5.70},
        {5.45, 5.55, 5.60}, {5.40, 5.40, 5.35}, {5.45, 5.50, 5.35}, {5.25, 5.15, 5.00}, {5.85, 5.80, 5.70},
        {5.25, 5.20, 5.10}, {5.65, 5.55, 5.45}, {5.60, 5.35, 5.45}, {5.05, 5.00, 4.95}, {5.50, 5.50, 5.40},
        {5.45, 5.55, 5.50}, {5.55, 5.55, 5.35}, {5.45, 5.50, 5.55}, {5.50, 5.45, 5.25}, {5.65, 5.60, 5.40},
        {5.70, 5.65, 5.55}, {6.30, 6.30, 6.25}};
    std::vector<std::vector<double>> blocks;
    for (const auto& row : data)
        blocks.push_back({row[0], row[1], row[2]});
    const FriedmanResult r = friedman_test(blocks);
    EXPECT_NEAR(r.chi_square, 11.142857142857132, 1e-10);
    EXPECT_EQ(r.degrees_of_freedom, 2.0);
    EXPECT_NEAR(r.p_value, 0.003805040775511383, 1e-12);
    EXPECT_NEAR(r.average_ranks[0], 53.0 / 22.0, 1e-12);
    EXPECT_NEAR(r.average_ranks[1], 47.0 / 22.0, 1e-12);
    EXPECT_NEAR(r.average_ranks[2], 32.0 / 22.0, 1e-12);
    EXPECT_THROW((void)friedman_test({{1, 2}}), std::invalid_argument);
}

TEST(Friedman, PostHocAgainstControlByHand) {
    // k = 3, N = 22: se = sqrt(3 * 4 / 132) = sqrt(1/11). Against control 2 (rank 32/22), method 0
    // has z = (21/22) / sqrt(1/11) = 3.165869118066518 and two-sided p = 2 (1 - Phi(z)) =
    // 0.0015462034770807383 (scipy.stats.norm.sf(z) * 2).
    const auto p = friedman_posthoc_p_values({53.0 / 22.0, 47.0 / 22.0, 32.0 / 22.0}, 22, 2);
    EXPECT_NEAR(p[0], 0.0015462034770807383, 1e-14);
    EXPECT_EQ(p[2], 1.0);
    EXPECT_GT(p[1], p[0]);
}

TEST(Holm, StepDownByHand) {
    // p = {0.01, 0.04, 0.03, 0.005}, m = 4. Sorted: 0.005 * 4 = 0.02, 0.01 * 3 = 0.03,
    // 0.03 * 2 = 0.06, 0.04 * 1 = 0.04 -> monotone 0.06. (R: p.adjust(p, "holm") gives the same.)
    const auto adjusted = holm_adjust({0.01, 0.04, 0.03, 0.005});
    ASSERT_EQ(adjusted.size(), 4u);
    EXPECT_DOUBLE_EQ(adjusted[0], 0.03);
    EXPECT_DOUBLE_EQ(adjusted[1], 0.06);
    EXPECT_DOUBLE_EQ(adjusted[2], 0.06);
    EXPECT_DOUBLE_EQ(adjusted[3], 0.02);
    EXPECT_DOUBLE_EQ(holm_adjust({0.6, 0.7})[1], 1.0); // capped at 1
}

TEST(VarghaDelaney, A12ByHand) {
    // x = {1, 2, 3}, y = {2, 3, 4}: one pair x > y (3 > 2), two ties (2 = 2, 3 = 3) of nine:
    // A12 = (1 + 0.5 * 2) / 9 = 2/9.
    EXPECT_DOUBLE_EQ(vargha_delaney_a12({1, 2, 3}, {2, 3, 4}), 2.0 / 9.0);
    EXPECT_DOUBLE_EQ(vargha_delaney_a12({5, 6}, {1, 2}), 1.0);
    EXPECT_DOUBLE_EQ(vargha_delaney_a12({1, 2}, {1, 2}), 0.5);
}

TEST(Ranks, TiesShareTheMeanRank) {
    EXPECT_EQ(average_ranks({10, 20, 10, 30}), (std::vector<double>{1.5, 3, 1.5, 4}));
}

} // namespace
} // namespace mhb
