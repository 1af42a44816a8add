// The table "structural_bias": the structural-bias audit of each algorithm on f0
// (results/analysis/structural_bias.hpp states the tests and the classification rule), one row per
// algorithm (and f0 problem), with the evidence beside the verdict.
#pragma once

#include <optional>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

// None when the budget has no f0 problem with two successful runs of an algorithm.
std::optional<Table> structural_bias_table(const StudyIndex& index, double alpha);

} // namespace mhb
