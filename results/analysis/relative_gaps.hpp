// How close each algorithm came to f* on each problem, on one scale for problems whose f* differ
// by orders of magnitude (a PMSM fit's residual in V^2, a flux map's in A^2): the relative gap
// (f - f*) / |f*| of each run's final best value, its median per (problem, algorithm), and the
// share of runs that reached the study's target. Where one problem is solved by every optimiser
// and the next by few, the gaps show where metaheuristics stop being interchangeable.
//
// Only meaningful where f* is a quantity of its own (a least-squares residual), not an offset
// chosen by a suite (BBOB's f_opt, CEC's 100 i): so it is computed for a budget that asked for a
// relative target (`relative_target=R`, results/analysis/budget_target.hpp), on the problems with
// a known, finite, non-zero f*, when there are two or more of them.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

struct RelativeGapCell {
    std::size_t runs = 0;    // successful runs: their gaps make the median
    std::size_t failed = 0;  // failed runs: unsuccessful in the success rate, out of the median
    std::size_t reached = 0; // runs that reached the study's target
    double median = std::numeric_limits<double>::quiet_NaN(); // NaN without a successful run

    // reached / (runs + failed); NaN without any run.
    [[nodiscard]] double success_rate() const;
};

struct RelativeGaps {
    std::vector<std::string> problems;               // with a known, non-zero f*, in the study's order
    std::vector<std::string> names;                  // short_problem_names of them, for headers and axes
    std::vector<double> f_opt;                       // f* of each
    std::vector<std::string> left_out;               // the budget's other problems (no such f*)
    std::vector<std::string> algorithms;             // in the study's order
    std::vector<std::vector<RelativeGapCell>> cells; // [algorithm][problem]
};

// (f - f*) / |f*| of one run (+inf for a run that ended at +inf); NaN without a known, finite,
// non-zero f*.
double relative_gap(const RunRecord& run);

// A short name per problem: the family name, and the parameters whose values differ between the
// listed problems of that family ("pmsm model=steady", "pmsm model=output", "fluxmap"); the spec
// itself where two would be named alike.
std::vector<std::string> short_problem_names(const std::vector<std::string>& problems);

// Empty unless the index's budget has a relative target and two or more of its problems a known,
// finite, non-zero f*.
std::optional<RelativeGaps> relative_gaps(const StudyIndex& index);

// The gaps as CSV, a row per (problem, algorithm) in the study's order:
// problem,name,algorithm,label,f_opt,runs,failed,median_relative_gap,reached,success_rate
// (the data of the figure `relative_gaps`).
std::string relative_gap_medians_csv(const StudyIndex& index, const RelativeGaps& gaps);

} // namespace mhb
