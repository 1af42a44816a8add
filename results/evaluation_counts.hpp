// Values at evaluation counts, shared by the tables that measure runs at fractions of a budget
// (the summary's budget columns, the CEC protocols' checkpoints).
#pragma once

#include <cstdint>
#include <string>

#include "results/run_record.hpp"
#include "results/study_index.hpp"

namespace mhb {

// Best-so-far of a run after `at` evaluations: its final value if it stopped by then, else the
// last recorded point with evaluations <= at (its exact improvements where recorded, else its
// iteration curve and checkpoints); NaN if none is.
double value_at_evaluations(const RunRecord& r, std::int64_t at);

// The dimension of a problem's runs (the length of their best x), 0 when no run has one.
std::int64_t problem_dimension(const StudyIndex& index, const std::string& problem);

// The evaluation count E a problem's budget gives, which fractions of a budget are taken of: the
// study's evaluation budget at the problem's dimension ("evaluations=N", or a count that depends
// on the dimension: results/dimension_budget.hpp) when it has one, else the largest evaluation
// count any run on the problem spent. One E per problem, so that every algorithm is measured at
// the same counts.
std::int64_t budget_evaluations(const StudyIndex& index, const std::string& problem);

// The count of `fraction` of E, floor(fraction E) (fraction E of 0.3 x 1000 is 300, not 299).
std::int64_t evaluations_at(double fraction, std::int64_t budget);

} // namespace mhb
