// The "runs_by_precision" table of a study run with `runs = auto` (results/analysis/run_precision.hpp):
// per problem and algorithm, the runs the cell took, the standard error it reached and why it
// stopped, recomputed from the runs by the rule the runner followed, so that a reader sees where 20
// runs would have been too few and where they were more than needed.
#pragma once

#include <optional>

#include "results/analysis/run_precision.hpp"
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

// None for a study with a fixed number of runs (no rule).
std::optional<Table> precision_table(const StudyIndex& index, const std::optional<PrecisionRule>& rule);

// One line for the console: "runs by precision (SE <= 0.05 on log10(f - f*)): 4 of 6 cells settled
// after 10-35 runs, 2 stopped at max-runs = 40".
std::string precision_summary(const StudyIndex& index, const PrecisionRule& rule);

} // namespace mhb
