// --rope and --raw-rope of `mhbench report` and `mhbench run`: the half-width of the region of
// practical equivalence of the Bayesian signed-rank tests (results/analysis/bayesian_comparisons.hpp),
// said once for both commands.
#pragma once

#include <boost/program_options.hpp>
#include <optional>
#include <string>

#include "results/report/report.hpp"
#include "results/table_model/table.hpp" // format_number: the default as help prints it

namespace mhb::cli {

inline constexpr const char* rope_option_help =
    "half-width of the ROPE of the Bayesian signed-rank tests and effects, in decades of f - f* (two runs "
    "whose gaps differ by less are practically equal); a number >= 0";
inline constexpr const char* raw_rope_option_help =
    "the ROPE's half-width in units of f, for problems without a known f* (default: none, no ROPE there)";

// ReportOptions::rope and raw_rope from the parsed options (build_report checks them).
void set_rope_options(const boost::program_options::variables_map& vm, ReportOptions& options);

// "rope = -1 is outside [0, inf)" for a negative or NaN --rope or --raw-rope; `mhbench run` says it
// with the study's other errors, before any run.
std::optional<std::string> rope_option_error(const boost::program_options::variables_map& vm);

} // namespace mhb::cli
