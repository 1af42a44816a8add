// A rough estimate of what a study costs before it runs (`mhbench run --dry-run`): evaluations
// and CPU time, calibrated on a few short runs of each algorithm and budget, because evaluations
// per iteration and time per evaluation differ between optimisers by orders of magnitude.
#pragma once

#include <cstdint>
#include <vector>

#include "results/store/run_record.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/study.hpp"

namespace mhb {

struct BudgetEstimate {
    double evaluations = 0; // all runs of the budget; an upper bound when a target may stop runs
    bool exact = false;     // evaluation budgets without a target are spent exactly
    double cpu_seconds = 0; // on one thread
};

struct StudyEstimate {
    std::vector<BudgetEstimate> budgets; // in the study's order
    std::int64_t calibration_runs = 0;
    [[nodiscard]] double evaluations() const;
    [[nodiscard]] double cpu_seconds() const;
};

// A short run: `request` cut to at most 3 iterations and `max_evaluations` evaluations, no
// target. Deterministic like every run.
RunRecord short_run(RunRequest request, std::int64_t max_evaluations);

// The evaluations one run under `budget` spends, extrapolated from a short run of the same
// algorithm and problem: its initialisation plus its evaluations per iteration times the
// iterations, capped by the budget's evaluations (1e300 for a budget without either).
double extrapolated_evaluations(const RunRecord& short_run, const Budget& budget);

// Runs each algorithm on up to `problems_per_algorithm` problems (spread over the study's list)
// for at most 3 iterations and 2000 evaluations, and extrapolates to the full budgets.
StudyEstimate estimate_study(const PreparedStudy& study, std::size_t problems_per_algorithm = 4);

} // namespace mhb
