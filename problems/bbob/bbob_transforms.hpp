// The BBOB transformations (Hansen, Finck, Ros, Auger 2009, "Real-parameter black-box optimization
// benchmarking 2009: noiseless functions definitions", section 0), as COCO computes them:
//   T_osz  the smooth oscillation of each coordinate (or of f),
//   T_asy  the asymmetric power of positive coordinates,
//   Lambda the diagonal scaling alpha^(0.5 (i-1)/(D-1)),
//   f_pen  the quadratic penalty outside [-5, 5]^D.
// Each works on a small vector in place; vectors here never exceed 40 entries, so they live on
// the stack (no allocation per evaluation).
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace mhb::bbob {

inline constexpr Eigen::Index max_dimension = 40;

// A vector of at most max_dimension entries, stored inline.
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, max_dimension, 1>;

// T_osz of one value: sign(x) exp(x_hat + 0.049 (sin(c1 x_hat) + sin(c2 x_hat))), x_hat = log|x|,
// c1 = 10, c2 = 7.9 for x > 0 and 5.5, 3.1 for x < 0. COCO writes it pow(exp(t + 0.49 (...)), 0.1)
// with t = log|x| / 0.1; exp(0.1 t) is |x| itself, so this is x exp(0.049 (...)): the same value
// to a few ulps for one exp instead of an exp and a pow.
inline double t_osz(double x) {
    if (x > 0.0) {
        const double t = std::log(x) / 0.1;
        return x * std::exp(0.049 * (std::sin(t) + std::sin(0.79 * t)));
    }
    if (x < 0.0) {
        const double t = std::log(-x) / 0.1;
        return x * std::exp(0.049 * (std::sin(0.55 * t) + std::sin(0.31 * t)));
    }
    return 0.0;
}

inline void t_osz(SmallVector& x) {
    for (Eigen::Index i = 0; i < x.size(); ++i)
        x[i] = t_osz(x[i]);
}

// T_asy^beta: x_i > 0 becomes x_i^(1 + beta (i-1)/(D-1) sqrt(x_i)).
inline void t_asy(SmallVector& x, double beta) {
    const double d1 = static_cast<double>(x.size()) - 1.0;
    for (Eigen::Index i = 0; i < x.size(); ++i)
        if (x[i] > 0.0)
            x[i] = std::pow(x[i], 1.0 + (beta * static_cast<double>(i)) / d1 * std::sqrt(x[i]));
}

// The diagonal of Lambda^alpha: alpha^(0.5 i / (D-1)), i = 0..D-1.
inline Eigen::VectorXd lambda_diagonal(double alpha, Eigen::Index dimension) {
    Eigen::VectorXd d(dimension);
    for (Eigen::Index i = 0; i < dimension; ++i)
        d[i] = std::pow(alpha, 0.5 * static_cast<double>(i) / (static_cast<double>(dimension) - 1.0));
    return d;
}

// The same diagonal written as COCO writes it inside its composed matrices:
// sqrt(alpha)^(i / (D-1)) (equal to lambda_diagonal up to the last bit).
inline Eigen::VectorXd sqrt_power_diagonal(double alpha, Eigen::Index dimension) {
    Eigen::VectorXd d(dimension);
    for (Eigen::Index i = 0; i < dimension; ++i)
        d[i] = std::pow(std::sqrt(alpha), static_cast<double>(i) / (static_cast<double>(dimension) - 1.0));
    return d;
}

// sum over i of max(0, |x_i| - 5)^2.
template <class Vector> double f_pen(const Vector& x) {
    double penalty = 0.0;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        const double excess = std::fabs(x[i]) - 5.0;
        if (excess > 0.0)
            penalty += excess * excess;
    }
    return penalty;
}

// COCO's rounding: floor(x + 0.5).
inline double round_half_up(double x) {
    return std::floor(x + 0.5);
}

} // namespace mhb::bbob
