// Tests of the steady-state fitness (eq. 11) and its least-squares reference
// (problems/pmsm/steady_state_data.*, least_squares.*), against data built directly from eq. 2
// and against the independent reference values in tests/data/pmsm/expected.csv.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "problems/core/rng.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "problems/pmsm/least_squares.hpp"
#include "problems/pmsm/steady_state_problem.hpp"
#include "problems/problem_registry.hpp"
#include "support/data.hpp"

namespace mhb::pmsm {
namespace {

using mhb::test_support::pmsm_data_dir;

// Noise-free samples of eq. 2 at two operating states, with a little scatter in the currents and
// speed so every sample differs; an interior-permanent-magnet motor (Ld != Lq) so that a swap
// of Ld and Lq would show.
Dataset eq2_dataset(const Eigen::Vector4d& theta, int n) {
    Rng rng(2024);
    Dataset d;
    for (int state = 0; state < 2; ++state)
        for (int k = 0; k < n; ++k) {
            const double id = (state == 0 ? 0.0 : -2.0) + 0.05 * rng.normal();
            const double iq = 8.6 + 0.05 * rng.normal();
            const double w = 523.6 + 0.5 * rng.normal();
            const double ud = theta[0] * id - theta[2] * w * iq;
            const double uq = theta[0] * iq + theta[1] * w * id + theta[3] * w;
            d.push_back(1e-4 * k, ud, uq, id, iq, w, state == 1);
        }
    return d;
}

TEST(PmsmLeastSquares, RecoversParametersExactlyFromEq2Data) {
    const Eigen::Vector4d truth(0.33, 2.9e-3, 4.1e-3, 0.0776);
    const SteadyStateData s = pair_samples(eq2_dataset(truth, 300));
    const LeastSquaresResult r = solve_least_squares(s);
    for (int j = 0; j < 4; ++j)
        EXPECT_NEAR(r.theta[j] / truth[j], 1.0, 1e-9) << "parameter " << j;
    EXPECT_LT(r.f, 1e-18);
    EXPECT_LT(s.fitness(truth), 1e-18);
}

// Noise-free output of our simulator: eq. 2 holds to the ~1e-5 V the transient tail leaves (see
// pmsm_simulator_test), and the least-squares estimate is within the error that causes:
// measured -1.6e-5 relative on Rs (the weakly determined parameter), about 1e-6 on the others.
TEST(PmsmLeastSquares, RecoversParametersFromNoiseFreeSimulation) {
    const SimulatorConfig config;
    const SteadyStateData s = pair_samples(simulate_dataset(config));
    const LeastSquaresResult r = solve_least_squares(s);
    const Eigen::Vector4d truth = config.motor.identified();
    EXPECT_NEAR(r.theta[0] / truth[0], 1.0, 5e-5);
    for (int j = 1; j < 4; ++j)
        EXPECT_NEAR(r.theta[j] / truth[j], 1.0, 5e-6) << "parameter " << j;
    EXPECT_LT(r.f, 1e-8);
}

// The fitness is eq. 11 literally: check it against a plain loop over the paired samples with
// unequal weights, and the pairing rule (the last n samples of each state, in order: an extra
// sample at the start of the longer state is unused).
TEST(PmsmLeastSquares, FitnessIsEq11WithPairedSamples) {
    const Eigen::Vector4d truth(0.33, 3.24e-3, 3.24e-3, 0.0776);
    const Dataset five = eq2_dataset(truth, 5);
    Dataset d;
    for (std::size_t k = 0; k < five.size(); ++k) {
        if (k == 5) // a sixth injected sample, first of its state: not paired
            d.push_back(-1.0, 100.0, 100.0, -2.0, 8.6, 523.6, true);
        d.push_back(five.t[k], five.ud[k], five.uq[k], five.id[k], five.iq[k], five.omega[k],
                    five.injected[k]);
    }
    // Rows 6-10 are the five injected samples of eq2_dataset; residuals on rows 0, 1, 6 and 10.
    d.ud[0] += 0.1;
    d.uq[1] -= 0.2;
    d.ud[6] += 0.3;
    d.uq[10] += 0.4;
    const FitnessWeights w{0.1, 0.2, 0.3, 0.4};
    const SteadyStateData s = pair_samples(d, w);
    EXPECT_EQ(s.pairs, 5);
    // r = 0.1 at row 0 (w1), -0.2 at row 1 (w2), 0.3 at row 6 (w3), 0.4 at row 10 (w4).
    const double expected = 0.1 * 0.01 + 0.2 * 0.04 + 0.3 * 0.09 + 0.4 * 0.16;
    EXPECT_NEAR(s.fitness(truth), expected, 1e-14);
}

struct Expected {
    Eigen::Vector4d theta_ls;
    double f_ls = 0;
    Eigen::Vector4d truth;
};

Expected read_expected(const std::string& file) {
    std::ifstream in(pmsm_data_dir + "expected.csv");
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line)) {
        std::stringstream row(line);
        std::string name;
        std::getline(row, name, ',');
        if (name != file)
            continue;
        Expected e;
        std::string cell;
        double v[9];
        for (double& x : v) {
            std::getline(row, cell, ',');
            x = std::stod(cell);
        }
        e.theta_ls = Eigen::Vector4d(v[0], v[1], v[2], v[3]);
        e.f_ls = v[4];
        e.truth = Eigen::Vector4d(v[5], v[6], v[7], v[8]);
        return e;
    }
    throw std::runtime_error("expected.csv has no row for " + file);
}

// expected.csv holds the exact least-squares optimum of each file, solved from the decimal numbers
// as written (README in tests/data/pmsm/). Parameters to 1e-9 relative on both files; f_ls to 1e-9
// on the noisy file, and to 1e-6 on the clean one, where f ~ 5e-11 is a sum of residuals of
// volt-sized terms and double precision gives no more.
TEST(PmsmLeastSquares, ReproducesExpectedCsvOnTheNoisyFile) {
    const std::string file = "pmsm_public_2200rpm_2.5Nm_noisy_ss.csv";
    const Expected e = read_expected(file);
    const Dataset d = read_dataset_csv(pmsm_data_dir + file);
    ASSERT_EQ(d.size(), 300u);
    EXPECT_EQ(d.state_counts(), (std::pair<std::size_t, std::size_t>(150, 150)));
    const SteadyStateData s = pair_samples(d);
    const LeastSquaresResult r = solve_least_squares(s);
    for (int j = 0; j < 4; ++j)
        EXPECT_NEAR(r.theta[j] / e.theta_ls[j], 1.0, 1e-9) << "parameter " << j;
    EXPECT_NEAR(r.f / e.f_ls, 1.0, 1e-9);
    // README: "45.29 at the truth against 45.08 at the optimum".
    EXPECT_NEAR(s.fitness(e.truth), 45.29, 0.005);
    ASSERT_TRUE(d.true_parameters().has_value());
    EXPECT_EQ(*d.true_parameters(), e.truth);
    // README: least-squares standard errors of about 9.6 %, 2.1 %, 0.28 % and 0.96 % (of the true
    // values; measured 9.616, 2.126, 0.280, 0.962).
    const Eigen::Vector4d relative_se = r.standard_error.cwiseQuotient(e.truth) * 100.0;
    EXPECT_NEAR(relative_se[0], 9.6, 0.05);
    EXPECT_NEAR(relative_se[1], 2.1, 0.05);
    EXPECT_NEAR(relative_se[2], 0.28, 0.02);
    EXPECT_NEAR(relative_se[3], 0.96, 0.05);
}

TEST(PmsmLeastSquares, ReproducesExpectedCsvOnTheCleanFile) {
    const std::string file = "pmsm_public_2200rpm_2.5Nm_clean_ss.csv";
    const Expected e = read_expected(file);
    const SteadyStateData s = pair_samples(read_dataset_csv(pmsm_data_dir + file));
    const LeastSquaresResult r = solve_least_squares(s);
    for (int j = 0; j < 4; ++j)
        EXPECT_NEAR(r.theta[j] / e.theta_ls[j], 1.0, 1e-9) << "parameter " << j;
    EXPECT_NEAR(r.f / e.f_ls, 1.0, 1e-6);
}

// The interior-PM motor (Ld != Lq) of the shared data: eq. 11 by the `pmsm` problem on its
// settled plateaus, against the independent solver's optimum, and (clean file) the truth.
TEST(PmsmLeastSquares, ReproducesExpectedCsvForTheInteriorPmMotor) {
    for (const std::string file :
         {"pmsm_public_ipm_1800rpm_4Nm_clean_ss.csv", "pmsm_public_ipm_1800rpm_4Nm_noisy_ss.csv"}) {
        const Expected e = read_expected(file);
        const auto problem = builtin_problems().create("pmsm:data=" + pmsm_data_dir + file);
        const auto optimum = problem->known_optimum();
        ASSERT_TRUE(optimum && optimum->x);
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR((*optimum->x)[j] / e.theta_ls[j], 1.0, 1e-9) << file << " parameter " << j;
        if (file.find("clean") != std::string::npos)
            EXPECT_LT(((*optimum->x - Eigen::VectorXd(e.truth)).array() / e.truth.array()).abs().maxCoeff(),
                      1e-5);
        else
            EXPECT_NEAR(optimum->f / e.f_ls, 1.0, 1e-9) << file;
    }
}

// The optimum is a minimum: f rises in every direction (a convexity check that can fail if the
// solver or the fitness has a sign wrong).
TEST(PmsmLeastSquares, OptimumIsAMinimumOfTheFitness) {
    const SteadyStateData s =
        pair_samples(read_dataset_csv(pmsm_data_dir + "pmsm_public_2200rpm_2.5Nm_noisy_ss.csv"));
    const LeastSquaresResult r = solve_least_squares(s);
    for (int j = 0; j < 4; ++j)
        for (const double step : {-1e-3, 1e-3}) {
            Eigen::Vector4d x = r.theta;
            x[j] *= 1.0 + step;
            EXPECT_GT(s.fitness(x), r.f) << "parameter " << j;
        }
}

// When theta* is outside the box, known_optimum() is the box-constrained optimum: the best
// value on the box, which no feasible point beats (checked on a grid of feasible points).
TEST(PmsmLeastSquares, BoxConstrainedOptimumWhenOutside) {
    const Dataset d = read_dataset_csv(pmsm_data_dir + "pmsm_public_2200rpm_2.5Nm_noisy_ss.csv");
    Box box = paper_bounds();
    box.upper[0] = 0.3; // Rs* = 0.359 lies above it
    const SteadyStateProblem problem(d, FitnessWeights{}, box);
    const LeastSquaresResult& r = problem.least_squares();
    EXPECT_FALSE(r.inside_box);
    EXPECT_DOUBLE_EQ(r.box_theta[0], 0.3);
    EXPECT_GT(r.box_f, r.f);
    const auto known = problem.known_optimum();
    ASSERT_TRUE(known.has_value());
    EXPECT_NEAR(known->f, r.box_f, 1e-12 * r.box_f); // through evaluate(): the expanded form
    Rng rng(5);
    for (int trial = 0; trial < 2000; ++trial) {
        Eigen::VectorXd x = r.box_theta;
        for (int j = 0; j < 4; ++j)
            x[j] = std::clamp(x[j] * (1.0 + 0.01 * rng.normal()), box.lower[j], box.upper[j]);
        EXPECT_GE(problem.evaluate(x), r.box_f * (1 - 1e-12));
    }
    // With the default box the optimum is inside and known_optimum() is the plain least squares.
    const SteadyStateProblem inside(d, FitnessWeights{}, paper_bounds());
    EXPECT_TRUE(inside.least_squares().inside_box);
    EXPECT_EQ(inside.known_optimum()->f, inside.least_squares().f);
}

} // namespace
} // namespace mhb::pmsm
