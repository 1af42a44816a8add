// The area under the ECDF of targets (AUC): one number per algorithm and problem (and over the
// problems pooled) for the whole run, not one budget or one target. IOHanalyzer's runtime ECDF
// (generate_data.ECDF, generate_data.AUC: the fraction of (run, target) pairs whose best-so-far
// reached the target after t evaluations, on a log-scaled budget axis, its area normalised so
// that a perfect algorithm gets 1), computed here exactly: the ECDF is a step function of the
// first hits, so its area is a sum, where IOHanalyzer takes trapezoids on a grid of 50 budgets.
//
//  - Targets: f - f* <= each gap of ecdf_target_gaps() (1e2 ... 1e-8, COCO's), the targets of the
//    report's fixed-target ECDF figure and of target_hits.csv, so that the area and the figure
//    show the same curves. Only problems with a known f*.
//  - Budget range: evaluations 1 ... B, B the problem's evaluation count E (budget_evaluations:
//    the study's evaluation budget, else the largest count any run on the problem spent).
//  - Scale: log10 of evaluations. A pair first reached at evaluation t <= B adds
//    (log10 B - log10 t) / log10 B; a pair never reached (or after B) adds 0; the area is their
//    mean, so 1 means every target at the first evaluation, 0 none within B. With B = 1 the axis
//    is one point and the area is the fraction reached at it.
//  - Pooled: the mean of the problems' areas (each problem weighs the same, as in COCO's
//    aggregated ECDFs), over the problems the algorithm has an area on.
// Runs that failed are left out; hits come from each run's improvement log (evaluation_counts.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "results/store/study_index.hpp" // runs, grouped: every room reads them here

namespace mhb {

// The area of (run, target) pairs given their first hits (nullopt: never), on [1, budget].
// Throws std::invalid_argument for an empty list or a budget below 1.
double ecdf_area(const std::vector<std::optional<std::int64_t>>& first_hits, std::int64_t budget);

struct EcdfAreaCell {
    std::string algorithm;
    std::size_t runs = 0;    // successful runs it rests on (pooled: their sum)
    std::size_t pairs = 0;   // (run, target) pairs
    std::size_t reached = 0; // of them, reached within the budget
    double area = 0.0;
};

struct EcdfAreaGroup {
    std::string problem;             // empty for the pooled group
    std::int64_t budget = 0;         // B (pooled: 0, each problem its own)
    std::size_t problems = 1;        // the problems it pools
    std::vector<EcdfAreaCell> cells; // in study order
};

// One group per problem with a known f* (in study order), then the pooled group when there are
// two or more. Empty when no problem has a known f*.
std::vector<EcdfAreaGroup> ecdf_areas(const StudyIndex& index);

} // namespace mhb
