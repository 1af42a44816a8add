// The exact optimum of the steady-state fitness (eq. 11). The fitness is a convex quadratic in
// theta = (Rs, Ld, Lq, psi), so weighted linear least squares gives its global minimum theta*
// and f*: the accuracy limit no optimiser can beat, shown as the gap f - f* in every table.
//
// Besides the estimate: standard errors from the least-squares covariance sigma^2 (A^T W A)^-1
// with sigma^2 = f* / (m - 4) estimated from the residual (m = equations with non-zero weight),
// the condition number of the design, and the residual RMS of each axis - what an identification
// report must show alongside the point estimate (ARCHITECTURE.md section 10).
//
// Bounds: when theta* lies outside the search box, the box-constrained optimum is also computed
// (exactly, by trying every active set of the 3^4 lower/free/upper choices and keeping the best
// feasible one - the optimum of a convex QP is the unconstrained optimum of its own active set).
#pragma once

#include <Eigen/Core>

#include "problems/pmsm/steady_state_data.hpp"
#include "problems/problem.hpp"

namespace mhb::pmsm {

struct LeastSquaresResult {
    Eigen::Vector4d theta = Eigen::Vector4d::Zero(); // unconstrained optimum (Rs, Ld, Lq, psi)
    double f = 0.0;                                  // eq. 11 at theta
    Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();
    Eigen::Vector4d standard_error = Eigen::Vector4d::Zero();
    double sigma2 = 0.0;           // residual variance per unit weight; NaN when m <= 4
    int equations = 0;             // m
    double condition_number = 0.0; // 2-norm, of sqrt(W) A with unit-norm columns (scale-free)
    double residual_rms_d = 0.0;   // sqrt(mean r_d^2) over the 2n d-axis equations, V
    double residual_rms_q = 0.0;   // the same for the q axis, V

    bool inside_box = true;                              // theta lies in the box given
    Eigen::Vector4d box_theta = Eigen::Vector4d::Zero(); // the box-constrained optimum
    double box_f = 0.0;
};

// Solves the weighted least squares of `data`; `box` (optional) is the search box. Throws
// std::invalid_argument if the data do not determine all four parameters (singular normal
// equations) or the estimate is not finite; theta, f and the condition number are then always
// finite (the standard errors are NaN when m <= 4 equations leave no residual).
LeastSquaresResult solve_least_squares(const SteadyStateData& data, const Box* box = nullptr);

} // namespace mhb::pmsm
