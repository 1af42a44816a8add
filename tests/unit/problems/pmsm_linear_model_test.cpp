// Tests of the linear least-squares core (problems/pmsm/linear_model.*) on crafted systems whose
// answers are known exactly, and of LinearModelProblem (linear_model_problem.*): its constant-time
// evaluate against the direct sum, its known optimum, its warnings and its refusals.
#include <Eigen/Cholesky>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>

#include "problems/core/rng.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/dynamic_model.hpp"
#include "problems/pmsm/linear_model.hpp"
#include "problems/pmsm/linear_model_problem.hpp"
#include "support/data.hpp"

namespace mhb::pmsm {
namespace {

using mhb::test_support::pmsm_data_dir;

// m x k Gaussian columns with very different scales (as ohm and henry columns differ), so that
// a solver which does not scale its columns would show it.
LinearModel random_model(Eigen::Index m, Eigen::Index k, std::uint64_t seed) {
    Rng rng(seed);
    LinearModel model;
    model.A.resize(m, k);
    for (Eigen::Index j = 0; j < k; ++j)
        for (Eigen::Index i = 0; i < m; ++i)
            model.A(i, j) = std::pow(10.0, static_cast<double>(j) - 2.0) * rng.normal();
    model.b = Eigen::VectorXd::Zero(m);
    for (Eigen::Index j = 0; j < k; ++j)
        model.parameter_names.push_back(
            std::string("p").append(std::to_string(j))); // GCC 12 -Wrestrict on "p" +
    model.d_rows = m / 2;
    return model;
}

TEST(PmsmLinearModel, FitnessIsTheSumOfSquaredResiduals) {
    LinearModel model = random_model(7, 3, 1);
    model.b = Eigen::VectorXd::LinSpaced(7, -1.0, 2.0);
    const Eigen::Vector3d theta(0.5, -2.0, 3.0);
    double expected = 0.0;
    for (Eigen::Index i = 0; i < 7; ++i) {
        double prediction = 0.0;
        for (Eigen::Index j = 0; j < 3; ++j)
            prediction += model.A(i, j) * theta[j];
        expected += (model.b[i] - prediction) * (model.b[i] - prediction);
    }
    EXPECT_NEAR(model.fitness(theta), expected, 1e-13 * expected);
    EXPECT_THROW((void)model.fitness(Eigen::Vector2d(1.0, 2.0)), std::logic_error);
}

TEST(PmsmLinearModel, RecoversExactParametersFromConsistentData) {
    LinearModel model = random_model(40, 5, 2);
    Eigen::VectorXd truth(5);
    truth << 0.33, 3.2e-3, 4.1e-3, 0.0776, 1.5;
    model.b = model.A * truth;
    const LinearFit fit = fit_linear_model(model);
    // Parameter j contributes |A_j| theta_j to b, from 3e-4 (j = 1) to 150 (j = 4): the smallest is
    // good to ~1e-16 times their ratio (measured 5e-12).
    for (Eigen::Index j = 0; j < 5; ++j)
        EXPECT_NEAR(fit.theta[j] / truth[j], 1.0, 1e-10) << "parameter " << j;
    EXPECT_LT(fit.f, 1e-25);
    EXPECT_EQ(fit.rank, 5);
    for (const bool d : fit.determined)
        EXPECT_TRUE(d);
    EXPECT_TRUE(std::isfinite(fit.condition_number));
    EXPECT_GE(fit.condition_number, 1.0);
    EXPECT_TRUE(fit.inside_box);
    EXPECT_EQ(fit.box_theta, fit.theta);
}

// With noise: the covariance is sigma2 (A^T A)^-1 (checked against the normal equations, fine on a
// well-conditioned design), sigma2 = f / (m - k), and the condition number is that of A with
// unit-norm columns.
TEST(PmsmLinearModel, CovarianceAndConditionNumber) {
    LinearModel model = random_model(60, 4, 3);
    Rng rng(4);
    model.b = model.A * Eigen::Vector4d(1.0, 2.0, 3.0, 4.0);
    for (Eigen::Index i = 0; i < 60; ++i)
        model.b[i] += 0.01 * rng.normal();
    const LinearFit fit = fit_linear_model(model);
    EXPECT_NEAR(fit.sigma2, fit.f / 56.0, 1e-15 * fit.f);
    const Eigen::MatrixXd normal = model.A.transpose() * model.A;
    const Eigen::MatrixXd expected = fit.sigma2 * normal.ldlt().solve(Eigen::MatrixXd::Identity(4, 4));
    for (Eigen::Index i = 0; i < 4; ++i) {
        for (Eigen::Index j = 0; j < 4; ++j)
            EXPECT_NEAR(fit.covariance(i, j), expected(i, j),
                        1e-9 * std::sqrt(expected(i, i) * expected(j, j)));
        EXPECT_DOUBLE_EQ(fit.standard_error[i], std::sqrt(fit.covariance(i, i)));
    }
    // The normal equations' solution agrees with the SVD one on this easy design.
    const Eigen::VectorXd theta_normal = normal.ldlt().solve(model.A.transpose() * model.b);
    for (Eigen::Index j = 0; j < 4; ++j)
        EXPECT_NEAR(fit.theta[j], theta_normal[j], 1e-9 * std::fabs(theta_normal[j]));
    const Eigen::MatrixXd scaled = model.A * model.A.colwise().norm().cwiseInverse().asDiagonal();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled);
    EXPECT_NEAR(fit.condition_number, svd.singularValues()[0] / svd.singularValues()[3], 1e-10);
}

// A duplicated column: the two parameters are confounded (only their sum is determined). No
// throw; the report says which ones, with infinite standard errors; the others stay exact.
TEST(PmsmLinearModel, RankDeficientDataReportUndeterminedParameters) {
    LinearModel model = random_model(30, 4, 5);
    model.A.col(3) = model.A.col(1);
    const Eigen::Vector4d truth(0.5, 1.0, -2.0, 3.0);
    model.b = model.A * truth;
    LinearFit fit;
    ASSERT_NO_THROW(fit = fit_linear_model(model));
    EXPECT_EQ(fit.rank, 3);
    EXPECT_TRUE(std::isinf(fit.condition_number));
    EXPECT_TRUE(fit.determined[0]);
    EXPECT_FALSE(fit.determined[1]);
    EXPECT_TRUE(fit.determined[2]);
    EXPECT_FALSE(fit.determined[3]);
    EXPECT_EQ(fit.standard_error[1], std::numeric_limits<double>::infinity());
    EXPECT_EQ(fit.standard_error[3], std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isfinite(fit.standard_error[0]));
    EXPECT_TRUE(std::isfinite(fit.standard_error[2]));
    EXPECT_NEAR(fit.theta[0], truth[0], 1e-12);
    EXPECT_NEAR(fit.theta[2], truth[2], 1e-12);
    // Minimum norm in scaled units: equal columns, equal scales, so the sum splits evenly.
    EXPECT_NEAR(fit.theta[1], 2.0, 1e-12);
    EXPECT_NEAR(fit.theta[3], 2.0, 1e-12);
    EXPECT_LT(fit.f, 1e-25);

    // A zero column is undetermined too.
    LinearModel zero = random_model(10, 3, 6);
    zero.A.col(2).setZero();
    zero.b = zero.A.col(0);
    const LinearFit z = fit_linear_model(zero);
    EXPECT_EQ(z.rank, 2);
    EXPECT_FALSE(z.determined[2]);
    EXPECT_TRUE(z.determined[0] && z.determined[1]);
    EXPECT_EQ(z.theta[2], 0.0);
}

// The exact box optimum satisfies the KKT conditions of the convex QP: zero gradient in the free
// coordinates, a gradient pushing outwards at each active bound. Sufficient for optimality.
void expect_kkt(const LinearModel& model, const Box& box, const LinearFit& fit) {
    const Eigen::VectorXd gradient = -2.0 * model.A.transpose() * (model.b - model.A * fit.box_theta);
    const double size = model.b.norm() + (model.A * fit.box_theta).norm();
    for (Eigen::Index j = 0; j < model.parameters(); ++j) {
        const int side = fit.active_bound[static_cast<std::size_t>(j)];
        const double g = gradient[j];
        const double gradient_scale = 2.0 * model.A.col(j).norm() * size; // of one term's rounding
        if (side < 0) {
            EXPECT_EQ(fit.box_theta[j], box.lower[j]);
            EXPECT_GE(g, -1e-10 * gradient_scale) << "parameter " << j;
        } else if (side > 0) {
            EXPECT_EQ(fit.box_theta[j], box.upper[j]);
            EXPECT_LE(g, 1e-10 * gradient_scale) << "parameter " << j;
        } else {
            EXPECT_NEAR(g, 0.0, 1e-10 * gradient_scale) << "parameter " << j;
        }
    }
    EXPECT_TRUE(box.contains(fit.box_theta));
    EXPECT_DOUBLE_EQ(fit.box_f, model.fitness(fit.box_theta));
}

TEST(PmsmLinearModel, BoxOptimumMatchesBruteForceOnAGrid) {
    LinearModel model = random_model(20, 3, 7);
    model.A = model.A * Eigen::Vector3d(100.0, 10.0, 1.0).asDiagonal(); // unit-sized columns
    Eigen::Vector3d truth(1.0, -1.0, 2.0);
    model.b = model.A * truth;
    Rng rng(8);
    for (Eigen::Index i = 0; i < 20; ++i)
        model.b[i] += 0.3 * rng.normal();
    // The unconstrained optimum lies near (1, -1, 2): outside this box in two coordinates.
    const Box box{Eigen::Vector3d(0.0, -0.5, 0.0), Eigen::Vector3d(0.8, 1.0, 3.0)};
    const LinearFit fit = fit_linear_model(model, &box);
    EXPECT_FALSE(fit.inside_box);
    EXPECT_GT(fit.box_f, fit.f);
    expect_kkt(model, box, fit);
    // No point of a 61^3 grid of the box beats it; the best grid point comes within the grid's
    // resolution.
    double grid_best = std::numeric_limits<double>::infinity();
    const int steps = 60;
    for (int a = 0; a <= steps; ++a)
        for (int b = 0; b <= steps; ++b)
            for (int c = 0; c <= steps; ++c) {
                Eigen::Vector3d x;
                for (Eigen::Index j = 0; j < 3; ++j) {
                    const int step = j == 0 ? a : (j == 1 ? b : c);
                    x[j] = box.lower[j] + (box.upper[j] - box.lower[j]) * step / steps;
                }
                const double f = model.fitness(x);
                EXPECT_GE(f, fit.box_f * (1.0 - 1e-12));
                grid_best = std::min(grid_best, f);
            }
    EXPECT_LT(grid_best - fit.box_f, 0.02 * fit.box_f);
}

TEST(PmsmLinearModel, BoxOptimumWithFiveParametersSatisfiesKkt) {
    for (std::uint64_t seed = 10; seed < 20; ++seed) {
        LinearModel model = random_model(25, 5, seed);
        Rng rng(seed);
        Eigen::VectorXd truth(5);
        for (Eigen::Index j = 0; j < 5; ++j)
            truth[j] = rng.uniform(-2.0, 2.0);
        model.b = model.A * truth;
        for (Eigen::Index i = 0; i < 25; ++i)
            model.b[i] += 0.01 * rng.normal();
        const Box box{Eigen::VectorXd::Constant(5, -1.0), Eigen::VectorXd::Constant(5, 1.0)};
        const LinearFit fit = fit_linear_model(model, &box);
        expect_kkt(model, box, fit);
        if (fit.inside_box) {
            EXPECT_EQ(fit.box_theta, fit.theta);
        }
    }
}

// Residual statistics: with a single all-ones column the estimate is the overall mean (0 here),
// so the residuals are the b values themselves.
LinearModel known_residuals(const Eigen::VectorXd& d, const Eigen::VectorXd& q) {
    LinearModel model;
    model.A = Eigen::MatrixXd::Ones(d.size() + q.size(), 1);
    model.b.resize(d.size() + q.size());
    model.b << d, q;
    model.parameter_names = {"c"};
    model.d_rows = d.size();
    return model;
}

TEST(PmsmLinearModel, ResidualStatisticsPerAxis) {
    Eigen::VectorXd d(6), q(6);
    d << 1, -1, 1, -1, 1, -1;
    q << 1, 2, 3, -3, -2, -1;
    LinearModel model = known_residuals(d, q);
    LinearFit fit = fit_linear_model(model);
    ASSERT_NEAR(fit.theta[0], 0.0, 1e-15);
    EXPECT_NEAR(fit.residual_d.rms, 1.0, 1e-15);
    EXPECT_NEAR(fit.residual_d.max_abs, 1.0, 1e-15);
    EXPECT_NEAR(fit.residual_d.lag1, -5.0 / 6.0, 1e-15);
    EXPECT_NEAR(fit.residual_q.rms, std::sqrt(28.0 / 6.0), 1e-14);
    EXPECT_NEAR(fit.residual_q.max_abs, 3.0, 1e-15);
    EXPECT_NEAR(fit.residual_q.lag1, 7.0 / 28.0, 1e-15); // 2 + 6 - 9 + 6 + 2 over 28

    // Two runs of three: the pairs (2, 3) across the run start are left out.
    model.run_starts = {0, 3};
    fit = fit_linear_model(model);
    EXPECT_NEAR(fit.residual_d.lag1, -4.0 / 6.0, 1e-15);
    EXPECT_NEAR(fit.residual_q.lag1, 16.0 / 28.0, 1e-15);
}

// About each axis' own mean: d = (2, 0, 2, 0) and q = -d give theta = 0, residual means +-1, and
// the centred sequences alternate, so lag1 = -3/4 (about zero instead it would be 0).
TEST(PmsmLinearModel, Lag1IsAboutTheAxisMean) {
    Eigen::VectorXd d(4);
    d << 2, 0, 2, 0;
    const LinearFit fit = fit_linear_model(known_residuals(d, -d));
    EXPECT_NEAR(fit.residual_d.lag1, -0.75, 1e-15);
    EXPECT_NEAR(fit.residual_q.lag1, -0.75, 1e-15);
    // Fewer than three rows, or no variance: NaN.
    EXPECT_TRUE(std::isnan(
        fit_linear_model(known_residuals(Eigen::Vector2d(1, -1), Eigen::Vector2d(1, -1))).residual_d.lag1));
    EXPECT_TRUE(
        std::isnan(fit_linear_model(known_residuals(Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, -1, -1)))
                       .residual_d.lag1));
}

TEST(PmsmLinearModel, RefusesMalformedModels) {
    EXPECT_THROW((void)fit_linear_model(LinearModel{}), std::invalid_argument);
    LinearModel model = random_model(10, 2, 9);
    model.b = model.A.col(0);
    model.A(3, 1) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW((void)fit_linear_model(model), std::invalid_argument);
    model.A(3, 1) = 1.0;
    const Box wrong{Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()};
    EXPECT_THROW((void)fit_linear_model(model, &wrong), std::invalid_argument);
    model.run_starts = {0, 4, 4};
    EXPECT_THROW((void)fit_linear_model(model), std::invalid_argument);
}

// --- LinearModelProblem, on the dynamic model of real transient data.

LinearModel ipm_model(bool fit_dead_time) {
    const std::string file = "pmsm_public_ipm_1800rpm_4Nm_noisy_tr.csv";
    return dynamic_model({read_dataset_csv(pmsm_data_dir + file)}, {file}, {fit_dead_time, 0});
}

Box ipm_box(bool fit_dead_time) {
    Box box{Eigen::Vector4d(0.0, 0.0, 0.0, 0.0), Eigen::Vector4d(2.0, 0.02, 0.02, 0.3)};
    if (fit_dead_time) {
        box.lower.conservativeResize(5);
        box.upper.conservativeResize(5);
        box.lower[4] = -5.0;
        box.upper[4] = 5.0;
    }
    return box;
}

TEST(PmsmLinearModelProblem, EvaluateEqualsTheDirectSum) {
    for (const bool dead_time : {false, true}) {
        const LinearModelProblem problem(ipm_model(dead_time), ipm_box(dead_time), std::nullopt);
        const Box& box = problem.bounds();
        Rng rng(11);
        for (int trial = 0; trial < 200; ++trial) {
            Eigen::VectorXd x(box.dimension());
            for (Eigen::Index j = 0; j < x.size(); ++j)
                x[j] = rng.uniform(box.lower[j], box.upper[j]);
            const double direct = problem.model().fitness(x);
            EXPECT_NEAR(problem.evaluate(x), direct, 1e-12 * direct);
        }
        // Near the optimum too, where f is smallest.
        const Eigen::VectorXd near = problem.fit().theta * (1.0 + 1e-3);
        EXPECT_NEAR(problem.evaluate(near), problem.model().fitness(near),
                    1e-12 * problem.model().fitness(near));
        EXPECT_THROW((void)problem.evaluate(Eigen::VectorXd::Zero(3)), std::logic_error);
    }
}

TEST(PmsmLinearModelProblem, KnownOptimumIsNeverAboveAPointOfTheBox) {
    for (const bool narrow : {false, true}) {
        Box box = ipm_box(false);
        if (narrow)
            box.upper[0] = 0.5; // Rs* ~ 1.39 on this noisy file: the box cuts the optimum
        const LinearModelProblem problem(ipm_model(false), box, Eigen::Vector4d(0.9, 6e-3, 14e-3, 0.17));
        const auto known = problem.known_optimum();
        ASSERT_TRUE(known.has_value() && known->x.has_value());
        EXPECT_TRUE(box.contains(*known->x));
        EXPECT_EQ(problem.fit().inside_box, !narrow);
        Rng rng(12);
        for (int trial = 0; trial < 2000; ++trial) {
            Eigen::VectorXd x(4);
            for (Eigen::Index j = 0; j < 4; ++j) // half near the optimum, half anywhere
                x[j] = trial % 2 == 0 ? rng.uniform(box.lower[j], box.upper[j])
                                      : std::clamp((*known->x)[j] * (1.0 + 0.01 * rng.normal()), box.lower[j],
                                                   box.upper[j]);
            EXPECT_GE(problem.evaluate(x), known->f);
        }
        ASSERT_TRUE(problem.true_parameters().has_value());
        EXPECT_EQ(problem.true_parameters()->size(), 4);
    }
}

TEST(PmsmLinearModelProblem, WarnsWhenTheBoxCutsTheOptimum) {
    Box box = ipm_box(false);
    EXPECT_TRUE(LinearModelProblem(ipm_model(false), box, std::nullopt).warnings().empty());
    box.upper[0] = 0.5;
    const LinearModelProblem problem(ipm_model(false), box, std::nullopt);
    const auto warnings = problem.warnings();
    ASSERT_EQ(warnings.size(), 1u) << (warnings.empty() ? "" : warnings[0]);
    const std::string& w = warnings[0];
    EXPECT_NE(w.find("Rs = 1.39"), std::string::npos) << w;
    EXPECT_NE(w.find("[0, 0.5]"), std::string::npos) << w;
    EXPECT_NE(w.find("upper bound of Rs"), std::string::npos) << w;
    EXPECT_NE(w.find("rs=lo:hi"), std::string::npos) << w;
    EXPECT_EQ(problem.known_optimum()->x->coeff(0), 0.5);
}

// Constant currents with id = 0 everywhere: Ld multiplies d(id)/dt and w id, both zero.
TEST(PmsmLinearModelProblem, RefusesDataThatLeaveAParameterUndetermined) {
    Dataset d;
    Rng rng(13);
    for (int k = 0; k < 50; ++k)
        d.push_back(1e-4 * k, -10.0 + rng.normal(), 40.0 + rng.normal(), 0.0, 10.0 + 0.1 * rng.normal(),
                    460.0 + rng.normal(), false);
    const LinearModel model = dynamic_model({d}, {"flat.csv"});
    try {
        const LinearModelProblem problem(model, ipm_box(false), std::nullopt);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("pmsm: the data do not determine Ld (", 0), 0u) << message;
    }
    // The wrong number of bounds, too.
    EXPECT_THROW(LinearModelProblem(ipm_model(false), ipm_box(true), std::nullopt), std::invalid_argument);
}

} // namespace
} // namespace mhb::pmsm
