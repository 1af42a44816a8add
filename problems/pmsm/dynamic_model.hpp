// The dynamic identification model: the discrete-time dq voltage equations on transient data,
// in the form that matches a row's timing (the voltage of row k acts from t_k to t_k + Ts, the
// currents are measured at t_k), for every pair of consecutive rows k, k + 1 one period apart:
//
//   ud[k] = Rs m_d + Ld (id[k+1] - id[k]) / Ts - Lq (w iq)_m [+ Vdt s_d]
//   uq[k] = Rs m_q + Lq (iq[k+1] - iq[k]) / Ts + Ld (w id)_m + psi w_m [+ Vdt s_q]
//
// with m_d = (id[k] + id[k+1]) / 2, w_m likewise, the products averaged at the two ends, and,
// when the dead-time voltage is fitted, (s_d, s_q) the mean over the two ends of the unit
// current vector i / |i| (an inverter's dead time opposes the current with a voltage of
// magnitude Vdt = (4 / pi) Vdc t_dead / Ts at the fundamental). Central or backward differences
// bias Rs by ~10 % (tests/data/pmsm/README.md), which is why this pairing is used.
//
// Every equation has weight 0.25, as eq. 11's, so f = sum 0.25 (r_d^2 + r_q^2). Still linear in
// the parameters: its exact least-squares optimum is the reference f*.
//
// Ts is each dataset's own sampling period (segments.hpp), taken as the mean step over its
// contiguous segments: one step of logged times carries ~1e-13 of rounding, which on clean data
// would move f* by ~1e-9 relative.
#pragma once

#include <string>
#include <vector>

#include "problems/pmsm/dataset.hpp"
#include "problems/pmsm/linear_model.hpp"

namespace mhb::pmsm {

struct DynamicModelOptions {
    bool fit_dead_time = false; // a fifth parameter Vdt (V)
    // Half-width K of a centred moving average (2K + 1 samples, shrinking at segment ends)
    // applied to ud, uq, id, iq and omega of each segment before the equations are formed; the
    // same filter on both sides keeps the equations (exactly for the linear terms, to first
    // order for the speed products). 0: no filtering.
    int smoothing = 0;
};

// The equations of all datasets stacked (several operating conditions, one parameter vector):
// all d-axis equations in order, then all q-axis ones. `sources` name the datasets in errors.
// Throws std::invalid_argument when no pair of consecutive rows exists.
LinearModel dynamic_model(const std::vector<Dataset>& datasets, const std::vector<std::string>& sources,
                          const DynamicModelOptions& options = {});

// The dead-time voltage of a dataset's metadata (Vdc, deadtime_s, Ts), or 0 when absent.
double dead_time_voltage(const Dataset& data);

} // namespace mhb::pmsm
