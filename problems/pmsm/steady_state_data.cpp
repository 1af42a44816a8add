#include "problems/pmsm/steady_state_data.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "problems/core/parameters.hpp"
#include "problems/pmsm/segments.hpp"

namespace mhb::pmsm {

namespace {

// The rows of each state that eq. 2 may use (see the header): rows of a state less than
// `settle_time` after a switch into it, seen between consecutive rows, are left out.
void settled_rows(const Dataset& data, double settle_time, std::vector<std::size_t> (&rows)[2]) {
    bool timed = false;
    for (std::size_t k = 0; k + 1 < data.size() && !timed; ++k)
        timed = data.t[k + 1] > data.t[k];
    const double Ts = timed ? sampling_period(data, "") : 0.0;
    double state_start = -std::numeric_limits<double>::infinity(); // t of the switch into the state
    for (std::size_t k = 0; k < data.size(); ++k) {
        if (timed && k > 0 && data.injected[k] != data.injected[k - 1] && consecutive(data, k - 1, Ts))
            state_start = data.t[k];
        else if (k > 0 && data.injected[k] != data.injected[k - 1])
            state_start = -std::numeric_limits<double>::infinity();
        if (data.t[k] - state_start >= settle_time)
            rows[data.injected[k] ? 1 : 0].push_back(k);
    }
}

} // namespace

SteadyStateData pair_samples(const std::vector<Dataset>& datasets, const std::vector<std::string>& sources,
                             const FitnessWeights& weights, double settle_time) {
    for (const double w : {weights.w1, weights.w2, weights.w3, weights.w4})
        if (!std::isfinite(w) || w < 0)
            throw std::invalid_argument("pmsm: weights must be finite and >= 0");
    if (!std::isfinite(settle_time) || settle_time < 0)
        throw std::invalid_argument("pmsm: the settle time must be finite and >= 0");
    // Rows of each dataset in eq. 11's layout: its n id = 0 rows, then its n injected ones.
    std::vector<std::pair<std::size_t, std::size_t>> layout; // (dataset, row)
    std::vector<bool> injected_state;
    for (std::size_t i = 0; i < datasets.size(); ++i) {
        std::vector<std::size_t> rows[2];
        settled_rows(datasets[i], settle_time, rows);
        const std::size_t n = std::min(rows[0].size(), rows[1].size());
        if (n == 0) {
            const std::string source = i < sources.size() && !sources[i].empty() ? sources[i] + ": " : "";
            throw std::invalid_argument(
                "pmsm: " + source + "the steady-state model needs settled samples in both the id = 0 and " +
                "the injected state (" + std::to_string(rows[0].size()) + " and " +
                std::to_string(rows[1].size()) + " after leaving out " + format_real(settle_time) +
                " s after each switch)");
        }
        for (int state = 0; state < 2; ++state)
            for (std::size_t k = rows[state].size() - n; k < rows[state].size(); ++k) {
                layout.emplace_back(i, rows[state][k]);
                injected_state.push_back(state == 1);
            }
    }
    if (layout.empty())
        throw std::invalid_argument("pmsm: no dataset to pair");

    SteadyStateData s;
    const auto m = static_cast<Eigen::Index>(layout.size());
    s.pairs = m / 2;
    for (Eigen::ArrayXd* a :
         {&s.ud, &s.uq, &s.id, &s.iq, &s.omega, &s.omega_iq, &s.omega_id, &s.weight_d, &s.weight_q})
        a->resize(m);
    for (Eigen::Index i = 0; i < m; ++i) {
        const Dataset& data = datasets[layout[static_cast<std::size_t>(i)].first];
        const std::size_t row = layout[static_cast<std::size_t>(i)].second;
        const bool state = injected_state[static_cast<std::size_t>(i)];
        s.ud[i] = data.ud[row];
        s.uq[i] = data.uq[row];
        s.id[i] = data.id[row];
        s.iq[i] = data.iq[row];
        s.omega[i] = data.omega[row];
        s.omega_iq[i] = data.omega[row] * data.iq[row];
        s.omega_id[i] = data.omega[row] * data.id[row];
        s.weight_d[i] = state ? weights.w3 : weights.w1;
        s.weight_q[i] = state ? weights.w4 : weights.w2;
    }
    return s;
}

SteadyStateData pair_samples(const Dataset& data, const FitnessWeights& weights, double settle_time) {
    return pair_samples(std::vector<Dataset>{data}, {""}, weights, settle_time);
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
