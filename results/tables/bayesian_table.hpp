// The table "bayesian": the Bayesian signed-rank test (Benavoli et al. 2017) of each algorithm
// against the reference, per problem on the paired runs and across problems on per-problem
// medians: P(reference better), P(equivalent: inside the ROPE), P(algorithm better), beside the
// frequentist tests of the "tests" table.
#pragma once

#include <optional>
#include <vector>

#include "results/analysis/bayesian_comparisons.hpp"
#include "results/table_model/table.hpp" // the model a builder fills

namespace mhb {

// None without comparisons (one algorithm, or no problem on which the reference has runs).
std::optional<Table> bayesian_table(const StudyIndex& index, const std::string& reference,
                                    const std::vector<BayesianComparison>& comparisons,
                                    const BayesianRope& rope);

} // namespace mhb
