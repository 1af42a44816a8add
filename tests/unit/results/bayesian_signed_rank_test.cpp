// The Bayesian signed-rank test (results/analysis/bayesian_signed_rank.hpp) against an independent
// Monte Carlo and against cases whose answer is exact.
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>

#include "results/analysis/bayesian_signed_rank.hpp"

namespace mhb {
namespace {

BayesianSignedRank run_test(const std::vector<double>& z, double rope, std::uint64_t seed = 7) {
    BayesianSignedRankOptions options;
    options.rope = rope;
    options.seed = seed;
    return bayesian_signed_rank(z, options);
}

// Reference values from `/usr/bin/python3 tests/python/bayesian_signed_rank_reference.py`: numpy's
// Dirichlet draws and baycomp's O(n^2) matrix of Walsh sums, 200 000 samples. The two Monte Carlo
// estimates differ by a standard error of at most sqrt(0.25 / 50000 + 0.25 / 200000) = 0.0025 for
// a probability, so 0.0125 is five standard errors; the posterior means of theta vary far less.
struct ReferenceCase {
    const char* name;
    double rope;
    std::vector<double> z;
    std::array<double, 3> p;
    std::array<double, 3> mean_theta;
};

std::vector<double> near_rope_differences() {
    std::vector<double> z;
    for (int i = 0; i < 20; ++i)
        z.push_back(0.01 * ((7 * i) % 13 - 6));
    return z;
}

std::vector<double> skewed_differences() {
    std::vector<double> z;
    for (int i = 0; i < 30; ++i)
        z.push_back(0.5 * std::sin(1.3 * i) + 0.15);
    return z;
}

TEST(BayesianSignedRank, AgreesWithAnIndependentMonteCarlo) {
    const std::vector<ReferenceCase> cases = {
        {"mixed",
         0.1,
         {-0.3, -0.25, -0.1, 0.02, -0.4, 0.15, -0.2, -0.05, -0.35, 0.1},
         {0.6883, 0.3115, 0.0003},
         {0.5637, 0.4033, 0.0330}},
        {"near_rope", 0.02, near_rope_differences(), {0.0459, 0.9518, 0.0023}, {0.2722, 0.5688, 0.1589}},
        {"skewed", 0.2, skewed_differences(), {0.0000, 0.7174, 0.2826}, {0.0980, 0.4945, 0.4075}},
    };
    for (const auto& c : cases) {
        const BayesianSignedRank r = run_test(c.z, c.rope);
        SCOPED_TRACE(c.name);
        EXPECT_EQ(r.pairs, c.z.size());
        EXPECT_NEAR(r.left, c.p[0], 0.0125);
        EXPECT_NEAR(r.rope, c.p[1], 0.0125);
        EXPECT_NEAR(r.right, c.p[2], 0.0125);
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_NEAR(r.mean_theta[k], c.mean_theta[k], 0.003);
        EXPECT_DOUBLE_EQ(r.left + r.rope + r.right, 1.0);
    }
}

TEST(BayesianSignedRank, EverythingInsideTheRopeIsEquivalentForSure) {
    // Every Walsh sum (the pseudo-observation 0 included) lies in [-2 rope, 2 rope]: theta_rope = 1.
    const BayesianSignedRank r = run_test({0.05, -0.09, 0.1, -0.1, 0.0, 0.07}, 0.1);
    EXPECT_EQ(r.rope, 1.0);
    EXPECT_EQ(r.left, 0.0);
    EXPECT_EQ(r.right, 0.0);
    EXPECT_DOUBLE_EQ(r.mean_theta[1], 1.0);
}

TEST(BayesianSignedRank, FarLeftIsLeftForSure) {
    // theta_left = 1 - w_0^2, where w_0 ~ Beta(0.5, 30) exceeds 1/sqrt(2) with probability ~1e-17.
    std::vector<double> z(30);
    for (std::size_t i = 0; i < z.size(); ++i)
        z[i] = -5.0 - static_cast<double>(i);
    const BayesianSignedRank r = run_test(z, 0.5);
    EXPECT_EQ(r.left, 1.0);
    EXPECT_EQ(r.rope + r.right, 0.0);
    EXPECT_EQ(r.mean_theta[2], 0.0); // no Walsh sum lies right of the rope
}

TEST(BayesianSignedRank, SwappingTheSamplesSwapsLeftAndRightExactly) {
    const std::vector<double> z = {-0.3, 0.2, -0.1, 0.02, -0.4, 0.15, 0.2, -0.05, -0.35, 0.1, 0.1, -0.1};
    std::vector<double> negated;
    for (double v : z)
        negated.push_back(-v);
    for (const double rope : {0.0, 0.05, 0.2}) {
        const BayesianSignedRank a = run_test(z, rope, 42);
        const BayesianSignedRank b = run_test(negated, rope, 42);
        EXPECT_EQ(a.left, b.right);
        EXPECT_EQ(a.right, b.left);
        EXPECT_EQ(a.rope, b.rope);
        EXPECT_EQ(a.mean_theta[0], b.mean_theta[2]);
    }
}

TEST(BayesianSignedRank, TheSameSeedGivesTheSameProbabilitiesAndAnotherSeedOthers) {
    const std::vector<double> z = {-0.3, 0.2, -0.1, 0.02, -0.4, 0.15, 0.2, -0.05};
    const BayesianSignedRank a = run_test(z, 0.05, 3);
    const BayesianSignedRank b = run_test(z, 0.05, 3);
    const BayesianSignedRank c = run_test(z, 0.05, 4);
    EXPECT_EQ(a.left, b.left);
    EXPECT_EQ(a.mean_theta, b.mean_theta);
    EXPECT_NE(a.mean_theta[0], c.mean_theta[0]);
    EXPECT_NEAR(a.left, c.left, 0.02);
}

TEST(BayesianSignedRank, KeepsTheFirstSamplesOfTheta) {
    BayesianSignedRankOptions options;
    options.rope = 0.1;
    options.kept_samples = 5;
    options.samples = 1000;
    const BayesianSignedRank r = bayesian_signed_rank({-0.3, 0.2, 0.05}, options);
    ASSERT_EQ(r.thetas.size(), 5U);
    for (const auto& t : r.thetas) {
        EXPECT_NEAR(t[0] + t[1] + t[2], 1.0, 1e-12);
        EXPECT_GE(t[0], 0.0);
        EXPECT_GE(t[2], 0.0);
    }
}

TEST(BayesianSignedRank, InfiniteDifferencesAreTheLargest) {
    const double inf = std::numeric_limits<double>::infinity();
    const BayesianSignedRank r = run_test({inf, inf, 1.0, inf, inf, inf, inf, inf}, 0.1);
    EXPECT_GT(r.right, 0.99);
    EXPECT_TRUE(std::isfinite(r.mean_theta[1]));
}

TEST(BayesianSignedRank, RefusesWhatItCannotTest) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(run_test({}, 0.1), std::invalid_argument);
    EXPECT_THROW(run_test({1.0, nan}, 0.1), std::invalid_argument);
    EXPECT_THROW(run_test({1.0}, -0.1), std::invalid_argument);
    EXPECT_THROW(run_test({1.0}, nan), std::invalid_argument);
}

} // namespace
} // namespace mhb
