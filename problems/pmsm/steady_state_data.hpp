// The samples of the steady-state fitness (the paper's eq. 11), laid out for fast evaluation.
//
// Which samples. Eq. 2 holds only where the currents and speed have settled, so:
//  - a switch of the injection state seen between two consecutive rows (one sampling period
//    apart) starts a transient, and the rows of the new state less than `settle_time` after the
//    first row of that state are not used (across a jump in t the switch itself is not in the
//    log and nothing is dropped: a logged window of the settled end of a plateau is used whole);
//  - of the rows left, the last n of each state are paired, n = min of the two counts: the
//    settled ends of the plateaus, as the paper takes them (a longer state loses its first rows).
// Sample k of the id = 0 state is paired with sample k of the injected state, k = 1..n, and
// each of the four residuals gets its weight:
//   f = sum_k w1 r_d(0,k)^2 + w2 r_q(0,k)^2 + w3 r_d(1,k)^2 + w4 r_q(1,k)^2,
//   r_d = ud - (Rs id - Lq omega iq),   r_q = uq - (Rs iq + Ld omega id + psi omega)   (eq. 2).
// The arrays hold the n id = 0 samples followed by the n injected ones, with the products
// omega*iq and omega*id computed once. Several datasets (operating conditions fitted with one
// parameter vector) are paired each on its own and concatenated.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

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

// 10 ms: a current loop of ~3000 rad/s settles in ~1 ms, the paper's speed loop in a few; a
// motor with slower loops needs a longer setting.
inline constexpr double default_settle_time = 0.01;

// Pairs the samples of `data`. Throws std::invalid_argument if a state has no sample left or a
// weight is negative or not finite.
SteadyStateData pair_samples(const Dataset& data, const FitnessWeights& weights = {},
                             double settle_time = default_settle_time);
// The datasets paired one by one and concatenated; errors name the dataset by `sources`.
SteadyStateData pair_samples(const std::vector<Dataset>& datasets, const std::vector<std::string>& sources,
                             const FitnessWeights& weights = {}, double settle_time = default_settle_time);

} // namespace mhb::pmsm
