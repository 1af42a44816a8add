// The table "effects" of a study whose variants form full 2^k factorial designs
// (results/analysis/factorial_effects.hpp computes the effects; this lays them out).
#pragma once

#include <optional>
#include <vector>

#include "results/analysis/factorial_effects.hpp"
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

// The table "effects" (one row per design, problem and effect), or none without analyses.
std::optional<Table> effects_table(const std::vector<DesignEffects>& designs,
                                   const std::vector<DesignCandidate>& rejected, double alpha);

} // namespace mhb
