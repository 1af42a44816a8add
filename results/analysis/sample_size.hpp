// How many problems and runs a comparison needs, before any run: the sample sizes of Campelo &
// Takahashi ("Sample size estimation for power and accuracy in the experimental comparison of
// algorithms", J. Heuristics 25, 2019) and Campelo & Wanner (multiple algorithms, Holm), as their
// R package CAISEr computes them (calc_instances, calc_nreps).
//
// Problems (instances): the smallest N at which a two-sided paired t-test of the per-problem mean
// differences detects a standardised effect d (mean difference / its standard deviation across
// problems) with the power asked, each of K comparisons with the reference at its Holm level
// alpha / (K - i + 1), i = 1..K; the power asked is that of the mean comparison (CAISEr's default)
// or of the worst one (alpha / K: Bonferroni). The t-test's power comes from the noncentral t
// distribution (Boost.Math), one tail, as R's power.t.test computes it. A Wilcoxon signed-rank test
// needs N / 0.86 (its asymptotic relative efficiency to the t-test, at worst 0.864).
//
// Runs per problem: n = ceil((s / e)^2), the runs after which the standard error of a mean paired
// difference with standard deviation s is at most e (at least 2).
#pragma once

#include <cstdint>
#include <vector>

namespace mhb {

enum class PowerTarget { mean, worst_case };
enum class PlannedTest { t_test, wilcoxon };

// R's power.t.test(n, delta = d, sd = 1, sig.level = alpha, type = "paired", alternative =
// "two.sided")$power (strict = FALSE).
double paired_t_power(std::int64_t n, double d, double alpha);

struct InstancePlan {
    std::int64_t instances = 0;        // problems needed by the test planned
    std::int64_t t_test_instances = 0; // by the paired t-test
    std::vector<double> powers;        // of each comparison at t_test_instances, most significant first
    std::vector<double> levels;        // their Holm levels
    double mean_power = 0;
};

// Throws std::invalid_argument for d <= 0, alpha or power outside (0, 1), comparisons < 1.
InstancePlan plan_instances(std::int64_t comparisons, double d, double power, double alpha,
                            PowerTarget target, PlannedTest test);

// ceil((sd / precision)^2), at least 2.
std::int64_t runs_for_precision(double sd, double precision);

} // namespace mhb
