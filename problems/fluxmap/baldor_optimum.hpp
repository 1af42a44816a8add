// The best-known least-squares optimum of each model on the shipped Baldor map, as shipped in
// data/baldor-optimum.csv (17 significant digits; how it was found and how often: data/README.md).
// The test SlowFluxMapOptimum.ReDerivesTheShippedOptimum re-derives it with fit_multistart.
#pragma once

#include "problems/fluxmap/current_map.hpp"
#include "problems/problem.hpp"

namespace mhb::fluxmap {

// f* (A^2) and theta* of `model` on baldor_flux_map() in the default box.
KnownOptimum baldor_optimum(Model model);

} // namespace mhb::fluxmap
