// Eq. 11 in constant time. The fitness is a quadratic in theta, so about any point theta0
//   f(theta) = f0 + 2 g0 . d + |R d|^2,   d = theta - theta0,
// with f0 = f(theta0) and g0 = -A^T W r0 summed once over the samples, and R the 4x4 triangular
// factor of sqrt(W) A (Householder QR, so |R d|^2 = d^T A^T W A d without forming A^T W A, which
// would square the condition number). This is eq. 11 exactly, rearranged: a study's millions of
// evaluations cost ~30 flops each instead of ~16 per sample.
//
// Accuracy: with theta0 the least-squares optimum, f0 is the direct sum at the optimum and the
// increments are computed from d, so the result agrees with the direct sum over the samples to
// ~1e-13 relative (tests/unit/problems/pmsm_expanded_fitness_test.cpp); near the optimum of
// noise-free data, where f ~ 1e-11 is a sum of residuals of volt-sized terms, both are limited by
// the ~1e-9 relative accuracy of f0 itself.
#pragma once

#include <Eigen/Core>

#include "problems/pmsm/steady_state_data.hpp"

namespace mhb::pmsm {

class ExpandedFitness {
public:
    ExpandedFitness() = default;
    ExpandedFitness(const SteadyStateData& data, const Eigen::Vector4d& theta0);

    [[nodiscard]] double operator()(const Eigen::Ref<const Eigen::VectorXd>& theta) const {
        const Eigen::Vector4d d = theta - theta0_;
        // R d row by row, each row summed left to right from its diagonal: the order of Eigen's
        // triangular product, written out because that product is an out-of-line call (a fifth
        // of a PSO run's time on this problem) where four short rows are a few inline flops.
        Eigen::Vector4d rd;
        for (Eigen::Index i = 0; i < 4; ++i) {
            double row = 0.0;
            for (Eigen::Index j = i; j < 4; ++j)
                row += r_(i, j) * d[j];
            rd[i] = row;
        }
        return f0_ + 2.0 * g0_.dot(d) + rd.squaredNorm();
    }

    [[nodiscard]] const Eigen::Vector4d& centre() const { return theta0_; }

private:
    Eigen::Vector4d theta0_ = Eigen::Vector4d::Zero();
    double f0_ = 0.0;
    Eigen::Vector4d g0_ = Eigen::Vector4d::Zero();
    Eigen::Matrix4d r_ = Eigen::Matrix4d::Zero();
};

} // namespace mhb::pmsm
