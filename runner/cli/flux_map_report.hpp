// What `mhbench identify --flux-map` prints: the map, the fit and how many starts reached it, each
// parameter with its standard error, spread over the starts and verdict, the current errors, the
// residual map, the verdicts' reasons and what the standard errors do not cover.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "problems/fluxmap/current_map.hpp"
#include "problems/fluxmap/current_map_fit.hpp"
#include "problems/fluxmap/fit_assessment.hpp"
#include "problems/fluxmap/residual_map.hpp"
#include "problems/problem.hpp"

namespace mhb::cli {

struct FluxMapReport {
    const fluxmap::CurrentMap& map;
    const Box& box;
    const fluxmap::FitAssessment& assessment;
    const fluxmap::FitResult& fit; // the best start and every start's f
    int reached = 0;               // starts within 1e-6 relative of the best
    std::string map_name;
    std::optional<KnownOptimum> known; // the shipped best-known optimum, when the map is the shipped one
    fluxmap::ResidualMap residual_map;
    std::vector<std::string> warnings; // the problem's
};

void print_flux_map_report(std::ostream& out, const FluxMapReport& report);

} // namespace mhb::cli
