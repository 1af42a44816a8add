// A run's best-so-far as a function of the evaluation count, shared by everything that measures
// runs at evaluation counts: the summary's budget columns, the CEC protocols' checkpoints, the
// curves by evaluations and the target hits (results/analysis/curve_data.hpp).
//
// Exact for every run that recorded its improvements (RunRecord::improvements: every strict
// improvement at the evaluation that made it): best-so-far after n >= 1 evaluations is the f of
// the last improvement at or before n (+inf when none: every evaluation so far gave +inf), and a
// run that stopped keeps its final value ever after. Runs stored before improvements were recorded
// have only their sampled points (iteration ends and the checkpoint grid): their values are those
// of the last sampled point, and hits the first sampled point that reached the target.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "results/store/run_record.hpp"  // a run's record: every room reads it
#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// Best-so-far of a run after `at` evaluations: its final value if it stopped by then, else the
// last improvement at or before `at` (+inf if none and at >= 1); for a run without improvements,
// the last sampled point at or before `at`. NaN when there is no value (at < 1, or no sampled point
// yet).
double value_at_evaluations(const RunRecord& r, std::int64_t at);

// The first evaluation count at which the run's best-so-far satisfied `reached`: exact from its
// improvements, else the first sampled point (or its final value) that did; nullopt when it never
// did. `reached` must hold for every value below one it holds for (a target: f - f* <= gap).
std::optional<std::int64_t> first_evaluation_reaching(const RunRecord& r,
                                                      const std::function<bool(double)>& reached);

// The dimension of a problem's runs (the length of their best x), 0 when no run has one.
std::int64_t problem_dimension(const StudyIndex& index, const std::string& problem);

// The evaluation count E a problem's budget gives, which fractions of a budget are taken of: the
// study's evaluation budget at the problem's dimension ("evaluations=N", or a count that depends
// on the dimension: results/analysis/dimension_budget.hpp) when it has one, else the largest evaluation
// count any run on the problem spent. One E per problem, so that every algorithm is measured at
// the same counts.
std::int64_t budget_evaluations(const StudyIndex& index, const std::string& problem);

// The count of `fraction` of E, floor(fraction E) (fraction E of 0.3 x 1000 is 300, not 299).
std::int64_t evaluations_at(double fraction, std::int64_t budget);

} // namespace mhb
