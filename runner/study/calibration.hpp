// A rough estimate of what a study costs before it runs (`mhbench run --dry-run`): evaluations
// and CPU time, calibrated on short runs of each algorithm, because evaluations per iteration and
// time per evaluation differ between optimisers by orders of magnitude, and between dimensions.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
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
    std::vector<BudgetEstimate> budgets;   // in the study's order
    std::vector<double> algorithm_seconds; // CPU seconds of each algorithm's runs, all budgets
    std::int64_t calibration_runs = 0;
    double calibration_seconds = 0; // wall time the calibration took
    [[nodiscard]] double evaluations() const;
    [[nodiscard]] double cpu_seconds() const;
};

// A short run: `request` cut to at most 3 iterations and `max_evaluations` evaluations, no
// target. Deterministic like every run.
RunRecord short_run(RunRequest request, std::int64_t max_evaluations);

// A calibration run: `request` with its budget scaled down, to 1/50 of its evaluations (at least
// 2000) and of its iterations (at least 3), no target. Optimisers that plan by their budget
// (population reduction, phases, restarts) then go through their whole schedule, compressed, so
// the time per evaluation is that of a whole run rather than of its first generations.
RunRecord calibration_run(RunRequest request);

// The evaluations one run under `budget` spends, extrapolated from a short run of the same
// algorithm and problem: its initialisation plus its evaluations per iteration times the
// iterations, capped by the budget's evaluations (1e300 for a budget without either).
double extrapolated_evaluations(const RunRecord& short_run, const Budget& budget);

// Runs each algorithm on up to `problems_per_dimension` problems of each dimension of the study
// (spread over the problems of that dimension, each standing for its share of them) as
// calibration runs on `threads` threads, and extrapolates to the full budgets. The times are
// CPU seconds on one thread (wall time of each run, which also counts an external program's).
StudyEstimate estimate_study(const PreparedStudy& study, int threads = 1,
                             std::size_t problems_per_dimension = 2);

// What the report after the runs costs: its tables, and the figures scripts/plot_study.py draws,
// counted by kind from the study (the script's own plan: `plot_study.py --plan REPORT_DIR`).
struct ReportEstimate {
    double tables_seconds = 0;
    std::vector<std::pair<std::string, std::int64_t>> figures; // kind and count, in the script's order
    double figures_seconds = 0; // wall time: the interpreter's start, then the figures on `workers`
    double speed_ratio = 1;     // this machine's time for the figures' reference work over the reference VM's
    [[nodiscard]] std::int64_t figure_count() const;
    [[nodiscard]] double seconds() const { return tables_seconds + figures_seconds; }
};

// The report's estimate, `figures` false for --no-figures. Per-kind costs are measured once on the
// project's 2-vCPU machine (calibration.cpp says how) and scaled by this machine's speed: the time
// of a fixed piece of work here over its time there (a few milliseconds, best of three). A rough
// figure, like the runs' estimate.
ReportEstimate estimate_report(const PreparedStudy& study, bool figures);

} // namespace mhb
