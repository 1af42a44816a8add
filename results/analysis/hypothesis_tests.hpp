// Nonparametric tests for comparing optimisers, each labelled with its exact name:
//  - Wilcoxon rank-sum test (= Mann-Whitney U) of two independent samples (runs of two
//    algorithms on one problem): exact null distribution for small samples without ties, normal
//    approximation with tie and continuity correction otherwise (the choices of R's wilcox.test).
//  - Wilcoxon signed-rank test of paired samples (runs paired by seed, per-problem medians paired
//    by problem, per-block factorial effects against 0): zero differences dropped; exact for fewer
//    than 50 non-zero differences without ties, normal with tie and continuity correction
//    otherwise (the choices of R's wilcox.test(paired = TRUE); SciPy's default switches at <= 50).
//  - Friedman test with average ranks (ties get mean ranks; tie-corrected chi-square) and the
//    Holm-adjusted post-hoc comparisons against a control (Demsar 2006, JMLR 7:1-30).
//  - Holm's step-down adjustment and the Vargha-Delaney A12 effect size.
// All p-values are two-sided. Distributions come from Boost.Math.
// +inf (a legal final value, the worst) is ranked above every finite value and ties with +inf;
// in the signed-rank test a pair of equal infinities is a zero difference and +inf - finite the
// largest magnitude, so every test here is defined for samples holding +inf.
#pragma once

#include <string>
#include <vector>

namespace mhb {

struct TestResult {
    std::string name;     // e.g. "Wilcoxon rank-sum (Mann-Whitney U), exact"
    double statistic = 0; // rank-sum: W = U of the first sample; signed-rank: V = sum of positive ranks
    double z = 0;         // the normal score (0 for exact tests)
    double p_value = 1;   // two-sided
    bool exact = false;
};

// Samples of fewer than this many values each (and no ties) get exact p-values, as in R.
inline constexpr std::size_t exact_test_limit = 50;

// Wilcoxon rank-sum test of x against y. Throws std::invalid_argument if either is empty.
TestResult rank_sum_test(const std::vector<double>& x, const std::vector<double>& y);

// Wilcoxon signed-rank test of the pairs (x[i], y[i]); zero differences are dropped (R's default).
// Throws std::invalid_argument on different lengths; p = 1 when every difference is zero.
TestResult signed_rank_test(const std::vector<double>& x, const std::vector<double>& y);

struct FriedmanResult {
    std::string name = "Friedman test";
    double chi_square = 0;
    double degrees_of_freedom = 0;
    double p_value = 1;
    std::vector<double> average_ranks; // per treatment (column), rank 1 = smallest value
};

// Friedman test on blocks (rows: e.g. problems) x treatments (columns: algorithms); lower values
// get lower ranks. Needs at least two rows and two columns of equal length.
FriedmanResult friedman_test(const std::vector<std::vector<double>>& blocks);

// Post-hoc after Friedman: z = (R_j - R_c) / sqrt(k (k + 1) / (6 n)) for each treatment j != c,
// two-sided unadjusted p-values (index c gets p = 1). Adjust them with holm_adjust.
std::vector<double> friedman_posthoc_p_values(const std::vector<double>& average_ranks, std::size_t blocks,
                                              std::size_t control);

// Holm's step-down adjusted p-values, in the input order (as R's p.adjust(p, "holm")).
std::vector<double> holm_adjust(const std::vector<double>& p_values);

// Vargha-Delaney A12 = P(X > Y) + P(X = Y) / 2, estimated over all pairs.
double vargha_delaney_a12(const std::vector<double>& x, const std::vector<double>& y);

// Average ranks (1-based) of the values, ties sharing the mean of their ranks.
std::vector<double> average_ranks(const std::vector<double>& values);

} // namespace mhb
