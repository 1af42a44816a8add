// The files of `mhbench identify --flux-map ... --out DIR`: estimates.csv (each parameter with its
// standard error, spread, verdict and box), points.csv (every measured point with the model's
// currents and the errors), curves.csv (the fitted psi_d(i_d) and psi_q(i_q) curves) and the
// figure flux-map.{pdf,png} drawn from them by scripts/plot_flux_map.py.
#pragma once

#include <ostream>
#include <string>

#include "runner/cli/flux_map_report.hpp"

namespace mhb::cli {

// Creates DIR (and its parents) and checks that a file can be written in it; throws
// std::runtime_error naming it and the system's reason otherwise.
void prepare_output_directory(const std::string& dir);

// Writes the CSVs (atomically) and draws the figure when a Python with matplotlib is found; says on
// `console` what it wrote or why the figure was skipped.
void write_flux_map_files(const std::string& dir, const FluxMapReport& report, std::ostream& console);

} // namespace mhb::cli
