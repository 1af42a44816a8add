// Small problems and helpers for the baseline optimisers' tests, defined here so that the tests do not wait
// for the test-function and PMSM families: a shifted Rastrigin, a shifted and rotated ellipsoid,
// and a 4-D convex quadratic that stands in for the PMSM steady-state problem (the same linear
// least-squares structure, eq. 2 and 11 of the ITLBO paper, with its exact optimum from QR).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/core/rng.hpp"
#include "problems/problem.hpp"

namespace mhb::test {

// f(x) = 10 D + sum (z^2 - 10 cos(2 pi z)), z = x - o, o uniform in [-4, 4]^D; box [-5.12, 5.12]^D.
class ShiftedRastrigin final : public Problem {
public:
    ShiftedRastrigin(Eigen::Index dimension, std::uint64_t seed)
        : box_{Eigen::VectorXd::Constant(dimension, -5.12), Eigen::VectorXd::Constant(dimension, 5.12)},
          shift_(dimension) {
        Rng rng(seed);
        for (Eigen::Index k = 0; k < dimension; ++k)
            shift_[k] = rng.uniform(-4.0, 4.0);
    }
    std::string name() const override { return "shifted_rastrigin"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        double f = 10.0 * static_cast<double>(x.size());
        for (Eigen::Index k = 0; k < x.size(); ++k) {
            const double z = x[k] - shift_[k];
            f += z * z - 10.0 * std::cos(2.0 * std::numbers::pi * z);
        }
        return f;
    }
    std::optional<KnownOptimum> known_optimum() const override { return KnownOptimum{0.0, shift_}; }

private:
    Box box_;
    Eigen::VectorXd shift_;
};

// f(x) = sum_i cond^(i/(D-1)) z_i^2, z = R (x - o): R a random rotation (QR of a Gaussian matrix),
// o uniform in [-3, 3]^D; box [-5, 5]^D. Condition number `cond` (1e6, as BBOB's f10).
class RotatedEllipsoid final : public Problem {
public:
    RotatedEllipsoid(Eigen::Index dimension, double cond, std::uint64_t seed)
        : box_{Eigen::VectorXd::Constant(dimension, -5.0), Eigen::VectorXd::Constant(dimension, 5.0)},
          shift_(dimension), scale_(dimension) {
        Rng rng(seed);
        Eigen::MatrixXd g(dimension, dimension);
        for (Eigen::Index i = 0; i < dimension; ++i)
            for (Eigen::Index j = 0; j < dimension; ++j)
                g(i, j) = rng.normal();
        rotation_ = Eigen::HouseholderQR<Eigen::MatrixXd>(g).householderQ();
        for (Eigen::Index k = 0; k < dimension; ++k) {
            shift_[k] = rng.uniform(-3.0, 3.0);
            scale_[k] = std::pow(
                cond, dimension > 1 ? static_cast<double>(k) / static_cast<double>(dimension - 1) : 0.0);
        }
    }
    std::string name() const override { return "rotated_ellipsoid"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        const Eigen::VectorXd z = rotation_ * (x - shift_);
        return scale_.dot(z.cwiseAbs2());
    }
    std::optional<KnownOptimum> known_optimum() const override { return KnownOptimum{0.0, shift_}; }

private:
    Box box_;
    Eigen::VectorXd shift_;
    Eigen::VectorXd scale_;
    Eigen::MatrixXd rotation_;
};

// The steady-state PMSM fitness in the form of the ITLBO paper's eq. 11 with equal weights:
// f(theta) = sum_k 0.25 (r_d^2 + r_q^2) over 300 samples of the i_d = 0 state and 300 of the
// i_d = -2 A state, theta = (R_s, L_d, L_q, psi_f), residuals of eq. 2:
//   r_d = u_d - (R_s i_d - L_q omega i_q),  r_q = u_q - (R_s i_q + L_d omega i_d + psi_f omega).
// Synthetic data for the paper's motor (R_s 0.33, L_d = L_q = 3.24e-3, psi_f 0.0776) at 2500 rpm,
// p = 2, i_q about 8.6 A, with 0.5 V voltage and 0.02 A current noise; bounds of ARCHITECTURE.md section 10.
// It is a convex quadratic, so linear least squares gives its exact optimum (known_optimum()).
class SteadyStateQuadratic final : public Problem {
public:
    explicit SteadyStateQuadratic(std::uint64_t seed) : box_{Eigen::VectorXd::Zero(4), Eigen::VectorXd(4)} {
        box_.upper << 0.5, 0.01, 0.01, 0.1;
        const double rs = 0.33, ld = 3.24e-3, lq = 3.24e-3, psi = 0.0776;
        const double omega = 2500.0 / 60.0 * 2.0 * std::numbers::pi * 2.0;
        const Eigen::Index samples = 300;
        Rng rng(seed);
        a_.resize(4 * samples, 4);
        b_.resize(4 * samples);
        Eigen::Index row = 0;
        for (const double id_set : {0.0, -2.0}) {
            for (int k = 0; k < samples; ++k) {
                const double iq = 8.59 + 0.05 * std::sin(0.1 * k);
                const double ud = rs * id_set - lq * omega * iq + 0.5 * rng.normal();
                const double uq = rs * iq + ld * omega * id_set + psi * omega + 0.5 * rng.normal();
                const double id_meas = id_set + 0.02 * rng.normal();
                const double iq_meas = iq + 0.02 * rng.normal();
                // Rows of sqrt(0.25) (A theta - b): r_d and r_q are linear in theta.
                a_.row(row) << 0.5 * id_meas, 0.0, -0.5 * omega * iq_meas, 0.0;
                b_[row++] = 0.5 * ud;
                a_.row(row) << 0.5 * iq_meas, 0.5 * omega * id_meas, 0.0, 0.5 * omega;
                b_[row++] = 0.5 * uq;
            }
        }
        a_.conservativeResize(row, 4);
        b_.conservativeResize(row);
        const Eigen::VectorXd theta = a_.colPivHouseholderQr().solve(b_);
        optimum_ = KnownOptimum{evaluate(theta), theta};
    }
    std::string name() const override { return "steady_state_quadratic"; }
    Eigen::Index dimension() const override { return 4; }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override { return (a_ * x - b_).squaredNorm(); }
    std::optional<KnownOptimum> known_optimum() const override { return optimum_; }
    std::vector<std::string> parameter_names() const override { return {"Rs", "Ld", "Lq", "psi"}; }

private:
    Box box_;
    Eigen::MatrixXd a_;
    Eigen::VectorXd b_;
    KnownOptimum optimum_;
};

// Every entry of the algorithm registry with its defaults (so the paper's optimisers are covered
// once merged), plus each NLopt algorithm the issue names.
inline std::vector<std::string> baseline_specs() {
    std::vector<std::string> specs;
    for (const auto& entry : builtin_algorithms().entries())
        if (entry.name != "external") // another program: tests/unit/algorithms/external_optimizer_test.cpp
            specs.push_back(entry.name);
    for (const char* name : {"GN_ISRES", "GN_ESCH", "GN_DIRECT_L", "GN_MLSL_LDS", "LN_BOBYQA",
                             "LN_NELDERMEAD", "LN_SBPLX", "LN_COBYLA"})
        specs.push_back(std::string("nlopt:algorithm=") + name);
    return specs;
}

// What one run leaves in its Objective.
struct RunOutcome {
    double best_f = 0.0;
    Eigen::VectorXd best_x;
    std::int64_t evaluations = 0;
    std::int64_t iterations = 0;
    std::optional<std::int64_t> evaluations_to_target;
    std::vector<IterationPoint> iteration_trace;
    std::vector<CheckpointPoint> checkpoints;
};

inline RunOutcome run_spec(const std::string& spec, const Problem& problem, Budget budget,
                           std::uint64_t seed) {
    const auto optimizer = builtin_algorithms().create(spec);
    Objective objective(problem, budget, optimizer->bound_policy());
    Rng rng(seed);
    run_to_budget(*optimizer, objective, rng);
    return {objective.best_f(),
            objective.best_x(),
            objective.evaluations(),
            objective.iterations(),
            objective.evaluations_to_target(),
            objective.iteration_trace(),
            objective.checkpoint_trace()};
}

} // namespace mhb::test
