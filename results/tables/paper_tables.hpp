// The paper's table layouts as presets, for PMSM identification problems (spec name "pmsm"):
//  - Table 2 "Fitness of different algorithms": mean and std of the final fitness beside the
//    published ones, the evaluations actually spent, and the gap f - f* to the exact
//    least-squares optimum;
//  - Table 3 "Parameter identification results": identified parameters (mean and std over runs),
//    % error against the truth, deviation from the least-squares optimum theta*, beside the
//    published values, with theta* itself as the row no optimiser can beat;
//  - Table 4 "Identification results under different working conditions": the three conditions
//    of the paper side by side, this study against the paper.
// For PMSM conditions the paper did not run, the same layouts are produced without paper columns.
// The paper's values appear only beside the configurations it ran: the specs exactly `itlbo`,
// `tlbo` and `pso` (canonical, so every parameter at its default = the paper's settings), never
// beside a variant. Algorithms are named by their labels.
#pragma once

#include <vector>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

std::vector<Table> pmsm_paper_tables(const StudyIndex& index);

} // namespace mhb
