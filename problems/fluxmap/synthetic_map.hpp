// Synthetic flux maps with a known truth (`fluxmap:synthetic=on`): nothing is inverted; the flux
// linkages are a 21 x 27 grid of psi_d x psi_q spanning the shipped Baldor map's range (psi_d from
// its least to its greatest value, psi_q likewise, both ends included, as the measured grid is
// 21 x 27), the currents are the model's at the truth, and Gaussian noise of std `noise` A is
// added to each current from the project's Rng(seed) (i_d then i_q, point by point, psi_d
// varying slowest). The same arguments give the same map bit for bit.
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "problems/fluxmap/current_map.hpp"

namespace mhb::fluxmap {

// motulator's values for the Baldor machine (data/README.md), all 14 in PM-SyRM order:
// a_d0 = 3.96, a_dd = 28.5, a_q0 = 5.89, a_qq = 2.67, a_dq = 41.5, S = 4, T = 6, U = 1, V = 1,
// psi_n = 0.804, a_b = 81.75, a_bp = 1, W = 2, k_q = 0.1. SyRM takes the first nine.
Eigen::VectorXd published_values();

FluxMap synthetic_map(Model model, const Eigen::VectorXd& truth, double noise, std::uint64_t seed);

} // namespace mhb::fluxmap
