// The tables of a study's PMSM identification problems (spec name "pmsm"), in two framings:
//  - the study's own (pmsm_tables, every study): per problem its fitness ("fitness": mean and std of
//    the final fitness, the evaluations spent, the gap f - f* to the exact least-squares optimum)
//    and its identified parameters ("parameters": mean and std over runs, % error against the
//    truth, deviation from theta*), and the operating conditions side by side ("conditions") when
//    two or more problems identify the paper's four parameters;
//  - the paper's (pmsm_paper_tables: the pmsm-paper protocol at the paper's budget, 150 iterations):
//    the same as the paper's Table 2 "Fitness of different algorithms", Table 3 "Parameter
//    identification results" and Table 4 "Identification results under different working
//    conditions" for the conditions the paper ran (Li, Wang, Ji 2017), beside the published values;
//    problems of other conditions keep the study's own tables.
// The paper's values appear only beside the configurations it ran: the specs exactly `itlbo`,
// `tlbo` and `pso` (canonical, so every parameter at its default = the paper's settings), never
// beside a variant. Algorithms are named by their labels, problems by their conditions.
#pragma once

#include <string>
#include <vector>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

std::vector<Table> pmsm_tables(const StudyIndex& index);
std::vector<Table> pmsm_paper_tables(const StudyIndex& index);
// Whether a file stem is one a PMSM table of either framing may have ("fitness", "table2_fitness",
// "parameters_pmsm_load_3_speed_2500"; not "parameters_iteration"), for removing stale ones.
bool is_pmsm_table_id(const std::string& id);
// Whether a budget (StudyIndex::budget()) is the paper's, at which the paper's framing applies.
bool is_paper_budget(const std::string& budget);

} // namespace mhb
