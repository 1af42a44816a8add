#include "problems/pmsm/steady_state_data.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace mhb::pmsm {

SteadyStateData pair_samples(const Dataset& data, const FitnessWeights& weights) {
    for (const double w : {weights.w1, weights.w2, weights.w3, weights.w4})
        if (!std::isfinite(w) || w < 0)
            throw std::invalid_argument("pmsm: weights must be finite and >= 0");
    std::vector<std::size_t> state_rows[2];
    for (std::size_t k = 0; k < data.size(); ++k)
        state_rows[data.injected[k] ? 1 : 0].push_back(k);
    const std::size_t n = std::min(state_rows[0].size(), state_rows[1].size());
    if (n == 0)
        throw std::invalid_argument(
            "pmsm: the dataset needs samples in both the id = 0 and the injected state");

    SteadyStateData s;
    s.pairs = static_cast<Eigen::Index>(n);
    const Eigen::Index m = 2 * s.pairs;
    for (Eigen::ArrayXd* a :
         {&s.ud, &s.uq, &s.id, &s.iq, &s.omega, &s.omega_iq, &s.omega_id, &s.weight_d, &s.weight_q})
        a->resize(m);
    for (int state = 0; state < 2; ++state)
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t row = state_rows[state][k];
            const Eigen::Index i = state * s.pairs + static_cast<Eigen::Index>(k);
            s.ud[i] = data.ud[row];
            s.uq[i] = data.uq[row];
            s.id[i] = data.id[row];
            s.iq[i] = data.iq[row];
            s.omega[i] = data.omega[row];
            s.omega_iq[i] = data.omega[row] * data.iq[row];
            s.omega_id[i] = data.omega[row] * data.id[row];
            s.weight_d[i] = state == 0 ? weights.w1 : weights.w3;
            s.weight_q[i] = state == 0 ? weights.w2 : weights.w4;
        }
    return s;
}

WeightedSystem weighted_system(const SteadyStateData& s) {
    const Eigen::Index m = s.ud.size();
    WeightedSystem sys{Eigen::MatrixXd::Zero(2 * m, 4), Eigen::VectorXd(2 * m)};
    const Eigen::ArrayXd sd = s.weight_d.sqrt();
    const Eigen::ArrayXd sq = s.weight_q.sqrt();
    // r_d = ud - (Rs id - Lq omega iq)
    sys.A.col(0).head(m) = (sd * s.id).matrix();
    sys.A.col(2).head(m) = (-sd * s.omega_iq).matrix();
    sys.b.head(m) = (sd * s.ud).matrix();
    // r_q = uq - (Rs iq + Ld omega id + psi omega)
    sys.A.col(0).tail(m) = (sq * s.iq).matrix();
    sys.A.col(1).tail(m) = (sq * s.omega_id).matrix();
    sys.A.col(3).tail(m) = (sq * s.omega).matrix();
    sys.b.tail(m) = (sq * s.uq).matrix();
    return sys;
}

} // namespace mhb::pmsm
