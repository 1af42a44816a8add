// The samples of the steady-state fitness (the paper's eq. 11), laid out for fast evaluation.
// Sample k of the id = 0 state is paired with sample k of the injected state, k = 1..n with
// n = min of the two counts (samples beyond n in the larger state are not used), and each of the
// four residuals gets its weight:
//   f = sum_k w1 r_d(0,k)^2 + w2 r_q(0,k)^2 + w3 r_d(1,k)^2 + w4 r_q(1,k)^2,
//   r_d = ud - (Rs id - Lq omega iq),   r_q = uq - (Rs iq + Ld omega id + psi omega)   (eq. 2).
// The arrays hold the n id = 0 samples followed by the n injected ones, with the products
// omega*iq and omega*id computed once.
#pragma once

#include <Eigen/Core>

#include "problems/pmsm/dataset.hpp"

namespace mhb::pmsm {

struct FitnessWeights {
    double w1 = 0.25, w2 = 0.25, w3 = 0.25, w4 = 0.25; // the paper's equal weights
};

struct SteadyStateData {
    Eigen::Index pairs = 0;                                   // n
    Eigen::ArrayXd ud, uq, id, iq, omega, omega_iq, omega_id; // 2n each
    Eigen::ArrayXd weight_d, weight_q;                        // w1/w3 and w2/w4 per sample

    // Eq. 11 at theta = (Rs, Ld, Lq, psi). No allocation.
    [[nodiscard]] double fitness(const Eigen::Ref<const Eigen::VectorXd>& theta) const {
        const double rs = theta[0], ld = theta[1], lq = theta[2], psi = theta[3];
        return (weight_d * (ud - rs * id + lq * omega_iq).square()).sum() +
               (weight_q * (uq - rs * iq - ld * omega_id - psi * omega).square()).sum();
    }
};

// Eq. 11 as a stacked linear system: f(theta) = |b - A theta|^2 with the square roots of the
// weights folded into A and b; the d-axis rows of all 2n samples, then the q-axis rows.
struct WeightedSystem {
    Eigen::MatrixXd A; // 4n x 4
    Eigen::VectorXd b; // 4n
};
WeightedSystem weighted_system(const SteadyStateData& data);

// Pairs the samples of `data`. Throws std::invalid_argument if a state has no sample or a
// weight is negative or not finite.
SteadyStateData pair_samples(const Dataset& data, const FitnessWeights& weights = {});

} // namespace mhb::pmsm
