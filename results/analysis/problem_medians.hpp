// The blocks of the tests across problems (Friedman, the signed-rank test on medians, the critical
// difference diagram): one median final value per problem and algorithm.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// The blocks of the across-problem tests: the problems on which every algorithm has runs and, per
// problem, each algorithm's median final value (columns in study order). Empty with fewer than
// two such problems or two algorithms.
std::optional<std::pair<std::vector<std::string>, std::vector<std::vector<double>>>>
per_problem_medians(const StudyIndex& index);

} // namespace mhb
