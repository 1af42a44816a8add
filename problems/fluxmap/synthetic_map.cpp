// Synthetic flux maps of synthetic_map.hpp.
#include "problems/fluxmap/synthetic_map.hpp"

#include "problems/core/rng.hpp"

namespace mhb::fluxmap {

Eigen::VectorXd published_values() {
    Eigen::VectorXd v(14);
    v << 3.96, 28.5, 5.89, 2.67, 41.5, 4, 6, 1, 1, 0.804, 81.75, 1, 2, 0.1;
    return v;
}

FluxMap synthetic_map(Model model, const Eigen::VectorXd& truth, double noise, std::uint64_t seed) {
    constexpr Eigen::Index n_d = 21, n_q = 27;
    const FluxMap& measured = baldor_flux_map();
    const Eigen::ArrayXd psi_d =
        Eigen::ArrayXd::LinSpaced(n_d, measured.psi_d.minCoeff(), measured.psi_d.maxCoeff());
    const Eigen::ArrayXd psi_q =
        Eigen::ArrayXd::LinSpaced(n_q, measured.psi_q.minCoeff(), measured.psi_q.maxCoeff());
    FluxMap map;
    map.psi_d.resize(n_d * n_q);
    map.psi_q.resize(n_d * n_q);
    for (Eigen::Index a = 0; a < n_d; ++a)
        for (Eigen::Index b = 0; b < n_q; ++b)
            map.psi_d[a * n_q + b] = psi_d[a], map.psi_q[a * n_q + b] = psi_q[b];
    map.i_d = Eigen::ArrayXd::Zero(n_d * n_q);
    map.i_q = map.i_d;
    const CurrentMap exact(model, map);
    exact.currents(truth, map.i_d, map.i_q);
    if (noise > 0) {
        Rng rng(seed);
        for (Eigen::Index k = 0; k < map.size(); ++k) {
            map.i_d[k] += noise * rng.normal();
            map.i_q[k] += noise * rng.normal();
        }
    }
    return map;
}

} // namespace mhb::fluxmap
