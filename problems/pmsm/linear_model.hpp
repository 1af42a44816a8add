// A model linear in its parameters, f(theta) = |b - A theta|^2, and its exact least-squares fit:
// the steady-state (eq. 11) and the dynamic (discrete dq voltage equation) identification
// problems are both of this form, with the square roots of the residual weights folded into the
// rows. The fit is what an identification report needs besides the estimate: standard errors,
// the scaled condition number, the numerical rank (which parameters the data leave
// undetermined), and the residuals' RMS, maximum and lag-1 autocorrelation per axis.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "problems/problem.hpp"

namespace mhb::pmsm {

struct LinearModel {
    Eigen::MatrixXd A;                        // m x k, weights folded in
    Eigen::VectorXd b;                        // m
    std::vector<std::string> parameter_names; // k, e.g. Rs Ld Lq psi [Vdt]
    // Rows [0, d_rows) are d-axis equations, [d_rows, m) q-axis ones, each in time order.
    Eigen::Index d_rows = 0;
    // Offsets (within an axis, 0-based from that axis' first row) where a new time-contiguous run
    // of equations begins; always starts with 0. Lag-1 autocorrelation never pairs across one.
    std::vector<Eigen::Index> run_starts{0};

    [[nodiscard]] Eigen::Index parameters() const { return A.cols(); }
    [[nodiscard]] Eigen::Index equations() const { return A.rows(); }
    // |b - A theta|^2, summed row by row (the reference any faster form is checked against).
    [[nodiscard]] double fitness(const Eigen::Ref<const Eigen::VectorXd>& theta) const;
};

// Residual statistics of one axis (d or q), in volts as the rows hold them (weights folded in).
struct ResidualStats {
    double rms = 0.0;
    double max_abs = 0.0;
    double lag1 = 0.0; // lag-1 autocorrelation within runs; NaN with fewer than 3 rows or zero variance
};

struct LinearFit {
    Eigen::VectorXd theta;          // least-squares estimate (minimum norm in scaled units if rank < k)
    double f = 0.0;                 // |b - A theta|^2
    Eigen::Index rank = 0;          // numerical rank of A with unit-norm columns (tolerance 1e-10 sigma_max)
    double condition_number = 0.0;  // sigma_max / sigma_min of A with unit-norm columns; inf if rank < k
    Eigen::MatrixXd covariance;     // sigma2 (A^T A)^-1; +inf entries for undetermined parameters
    Eigen::VectorXd standard_error; // sqrt of the diagonal; +inf for undetermined ones, NaN if m <= k
    double sigma2 = 0.0;            // f / (m - k); NaN when m <= k
    std::vector<bool> determined;   // false where the parameter has a component in A's null space
    // |components| of the weakest direction of A with unit-norm columns (its last right singular
    // vector): the parameters that share it are the ones the data tell apart worst.
    Eigen::VectorXd weakest_direction;
    ResidualStats residual_d, residual_q;

    bool inside_box = true;    // theta lies in the box (when one was given)
    Eigen::VectorXd box_theta; // the exact box-constrained optimum (== theta when inside)
    double box_f = 0.0;
    std::vector<int> active_bound; // per parameter: -1 at its lower bound, +1 at its upper, 0 free
};

// Never throws for rank deficiency (the report says what is undetermined); throws
// std::invalid_argument for an empty model, a non-finite entry, inconsistent sizes or run_starts,
// or a box of the wrong size or with more than 10 parameters (the box optimum tries all 3^k active
// sets, each a k-row problem reduced through the SVD, so k = 5 costs 243 tiny solves).
LinearFit fit_linear_model(const LinearModel& model, const Box* box = nullptr);

} // namespace mhb::pmsm
