// `mhbench identify --flux-map FILE`: a saturation model (PM-SyRM or SyRM) fitted to a measured
// flux map by the bounded multi-start Levenberg-Marquardt method that found the shipped map's
// best-known optimum; estimates with standard errors and verdicts, the current errors and a
// residual map on the terminal; with --out, the numbers as CSV and a figure of the measured points
// against the fitted psi_d(i_d) and psi_q(i_q) curves.
#pragma once

#include <cstdint>
#include <string>

namespace mhb::cli {

struct FluxMapIdentifyOptions {
    std::string map;    // a CSV with columns i_d,i_q,psi_d,psi_q, or "shipped" (the Baldor map)
    std::string model;  // syrm or pmsyrm
    std::string bounds; // bounds of the fluxmap family, "S=1:8,a_d0=0:2000"
    int starts = 100;
    std::uint64_t seed = 1;
    int threads = 0; // 0: all cores
    std::string out; // a directory for the CSVs and the figure; empty: the terminal only
};

// The word that names the shipped Baldor map instead of a file.
inline constexpr const char* shipped_map_word = "shipped";

int identify_flux_map(const FluxMapIdentifyOptions& options);

} // namespace mhb::cli
