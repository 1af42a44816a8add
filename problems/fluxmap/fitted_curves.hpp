// The fitted model as drive papers show a flux map: psi_d against i_d at a few levels of i_q, and
// psi_q against i_q at a few levels of i_d. The models are current maps i(psi), so each curve
// point is the flux linkage at which the model gives the wanted currents, found by Newton's method
// on the 2 x 2 system from the nearest measured point.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "problems/fluxmap/current_map.hpp"

namespace mhb::fluxmap {

struct FluxCurve {
    bool d_axis = true;                    // psi_d(i_d) at i_q = level; else psi_q(i_q) at i_d = level
    double level = 0.0;                    // A
    Eigen::ArrayXd i_d, i_q, psi_d, psi_q; // NaN flux where Newton did not converge
};

// Up to `count` levels from the distinct values of `values`: evenly spaced among them, or over
// their range when there are more than 60 (a map not taken on a grid). `non_negative`: only
// values >= 0 (psi_d depends on i_q through psi_q^2, so i_q and -i_q give one curve).
std::vector<double> curve_levels(const Eigen::ArrayXd& values, int count, bool non_negative);

// psi_d(i_d) at each of `q_levels`, then psi_q(i_q) at each of `d_levels`, each over the map's range
// of the swept current in `samples` points.
std::vector<FluxCurve> fitted_curves(const CurrentMap& map, const Eigen::VectorXd& theta,
                                     const std::vector<double>& q_levels, const std::vector<double>& d_levels,
                                     int samples);

} // namespace mhb::fluxmap
