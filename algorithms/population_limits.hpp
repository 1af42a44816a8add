// What every population-based optimiser checks before a study starts (Optimizer::refusal): that
// its points fit in this machine's memory. A population of 10^6 points at D = 10^4 would
// otherwise end each run in std::bad_alloc, after the study directory had been made.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>

namespace mhb {

// Refuses, in one line naming `parameter`, a run that holds `points` vectors of `dimension`
// doubles (its population, trials, archive) when they alone would need more than this machine's
// physical memory. `algorithm`: the optimiser's name, which starts the line.
std::optional<std::string> population_memory_refusal(const std::string& algorithm, double points,
                                                     Eigen::Index dimension, const std::string& parameter);

// The SHADE variants' check (L-SHADE, jSO, LSHADE-cnEpSin, NL-SHADE-LBC): an initial population
// `n_init` = `formula` (e.g. "round(r_ninit * D)") that the dimension makes smaller than `n_min`,
// or that does not fit in memory with its trials and an archive of r_arc n_init. `hint` follows
// "raise 'r_ninit'" when not empty.
std::optional<std::string> shade_population_refusal(const std::string& algorithm, const std::string& formula,
                                                    std::size_t n_init, long long n_min, double r_arc,
                                                    Eigen::Index dimension, const std::string& hint = "");

} // namespace mhb
