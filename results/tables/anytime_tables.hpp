// The anytime tables of a report: what a run achieves over its whole length rather than at its end.
//  - "ecdf_area": per problem with a known f* and algorithm, the area under the ECDF of targets
//    (results/analysis/ecdf_area.hpp), and over the problems pooled;
//  - "ert": per problem, algorithm and target f - f* of the fixed-target ECDF (1e2 ... 1e-8) that
//    any run on the problem reached, the ERT with COCO's bootstrap percentiles of simulated
//    restarts (results/analysis/ert_bootstrap.hpp), seeded from the problem, algorithm and target.
// Both are absent (nullopt) when no problem has a known f*.
#pragma once

#include <optional>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

std::optional<Table> ecdf_area_table(const StudyIndex& index);
std::optional<Table> ert_table(const StudyIndex& index);

} // namespace mhb
