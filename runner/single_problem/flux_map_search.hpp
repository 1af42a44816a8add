// The search of `mhbench identify --flux-map`: fluxmap::fit_multistart's starts, each a bounded
// Levenberg-Marquardt descent, run in parallel with oneTBB. Every start is independent and the best
// is chosen in start order, so the result is fit_multistart's, bit for bit, at any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "problems/fluxmap/current_map_fit.hpp"

namespace mhb {

struct FluxMapSearch {
    fluxmap::FitResult best;                  // theta, f and every start's f, in start order
    std::vector<Eigen::VectorXd> start_theta; // each start's end point, in start order
};

FluxMapSearch search_flux_map(const fluxmap::CurrentMap& map, const Box& box,
                              const fluxmap::FitOptions& options, int threads);

} // namespace mhb
