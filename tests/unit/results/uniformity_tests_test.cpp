// Kolmogorov-Smirnov and Anderson-Darling against U(0, 1) (results/analysis/uniformity_tests.hpp)
// against scipy 1.10.1 (Debian's /usr/bin/python3 with python3-scipy; not needed to run this).
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

#include "results/analysis/uniformity_tests.hpp"

namespace mhb {
namespace {

const std::vector<double> ten_points = {0.12, 0.53, 0.91, 0.07, 0.64, 0.33, 0.78, 0.45, 0.29, 0.98};

// ten_points squeezed towards 0.5 by `factor`.
std::vector<double> squeezed(double factor) {
    std::vector<double> y;
    for (double v : ten_points)
        y.push_back(0.5 + factor * (v - 0.5));
    return y;
}

TEST(KolmogorovSmirnovUniform, ExactDistributionMatchesScipyKstwo) {
    // scipy.stats.kstwo.sf(d, n): the matrix method (n d^2 <= 4 up to n = 140, <= 2.2 beyond), the
    // one-sided Smirnov tail beyond, and the exact limits d <= 1/(2n) and d >= 1/2. Beyond n = 140,
    // where n d^1.5 > 1.4, scipy uses Pelz and Good's asymptotic series (n = 200, d = 0.08), within
    // 2e-6 of the exact matrix value computed here.
    struct Case {
        std::size_t n;
        double d;
        double p;
        double tolerance = 1e-9;
    };
    for (const Case& c : {Case{100, 0.05, 0.9532159710635725}, Case{100, 0.1, 0.2526927570063874},
                          Case{100, 0.15, 0.019839242125643017}, Case{100, 0.25, 5.408871776434847e-06},
                          Case{20, 0.3, 0.04306706665851623}, Case{10, 0.5, 0.00777741},
                          Case{200, 0.08, 0.1463961356372503, 2e-6}, Case{200, 0.12, 0.005745760601982814},
                          Case{5, 0.95, 6.250000000000028e-07}, Case{100, 0.005, 1.0}})
        EXPECT_NEAR(kolmogorov_smirnov_p_value(c.n, c.d) / c.p, 1.0, c.tolerance)
            << "n = " << c.n << ", d = " << c.d;
}

TEST(KolmogorovSmirnovUniform, StatisticAndPValueMatchScipyKstest) {
    // scipy.stats.kstest(x, 'uniform', method='exact')
    const UniformityTest spread = kolmogorov_smirnov_uniform(ten_points);
    EXPECT_NEAR(spread.statistic, 0.10999999999999999, 1e-15);
    EXPECT_NEAR(spread.p_value, 0.9983423072842209, 1e-12);
    const UniformityTest centre = kolmogorov_smirnov_uniform(squeezed(0.1));
    EXPECT_NEAR(centre.statistic, 0.457, 1e-12);
    EXPECT_NEAR(centre.p_value, 0.01984580332245911, 1e-12);
}

TEST(AndersonDarlingUniform, StatisticIsExactAndPValueAgreesWithScipyMonteCarlo) {
    // A^2 in numpy: -n - sum((2i - 1)(log x_(i) + log1p(-x_(n+1-i)))) / n. The p-values:
    // scipy.stats.goodness_of_fit(uniform, x, known_params={'loc': 0, 'scale': 1}, statistic='ad',
    // n_mc_samples=100000, random_state=1): 0.99605 and 0.082489, each within 0.0009 (its Monte
    // Carlo error) plus Marsaglia's 5 digits.
    const UniformityTest spread = anderson_darling_uniform(ten_points);
    EXPECT_NEAR(spread.statistic, 0.1781117747203762, 1e-13);
    EXPECT_NEAR(spread.p_value, 0.996050039499605, 0.003);
    const UniformityTest centre = anderson_darling_uniform(squeezed(0.3));
    EXPECT_NEAR(centre.statistic, 2.0946543321103928, 1e-13);
    EXPECT_NEAR(centre.p_value, 0.08248917510824892, 0.003);
}

TEST(AndersonDarlingUniform, LargeSamplesMeetStephensCriticalValues) {
    // The asymptotic critical values of A^2 for a fully specified distribution (Stephens 1974):
    // 1.933 at 10%, 2.492 at 5%, 3.857 at 1%; at n = 10^4 the finite-n correction is negligible.
    EXPECT_NEAR(anderson_darling_p_value(10000, 1.933), 0.10, 0.001);
    EXPECT_NEAR(anderson_darling_p_value(10000, 2.492), 0.05, 0.001);
    EXPECT_NEAR(anderson_darling_p_value(10000, 3.857), 0.01, 0.0005);
}

TEST(AndersonDarlingUniform, AValueOnABoundIsCertainRejection) {
    std::vector<double> at_bound = ten_points;
    at_bound[3] = 0.0;
    const UniformityTest t = anderson_darling_uniform(at_bound);
    EXPECT_TRUE(std::isinf(t.statistic));
    EXPECT_EQ(t.p_value, 0.0);
}

TEST(UniformityTests, RefuseEmptySamplesAndValuesOutsideTheUnitInterval) {
    EXPECT_THROW((void)kolmogorov_smirnov_uniform({}), std::invalid_argument);
    EXPECT_THROW((void)anderson_darling_uniform({}), std::invalid_argument);
    EXPECT_THROW((void)kolmogorov_smirnov_uniform({0.5, 1.5}), std::invalid_argument);
    EXPECT_THROW((void)anderson_darling_uniform({-0.1, 0.5}), std::invalid_argument);
}

} // namespace
} // namespace mhb
