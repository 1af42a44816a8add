// What one run of one algorithm on one problem produced. This is the unit of a study's results:
// the runner fills it, the store writes and reads it, statistics and tables read it.
// Wall time is deliberately not here: it is the one thing that differs between two runs of the
// same study, so it lives in timings.csv and the records stay byte-identical.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mhb {

// Best-so-far at the end of an iteration (iteration 0 = after initialisation).
struct CurvePoint {
    std::int64_t iteration = 0;
    std::int64_t evaluations = 0;
    double best_f = 0.0;
    std::vector<double> best_x; // only for problems with named parameters (trajectories)
};

// Best-so-far after exactly `evaluations` evaluations, on the grid every run shares; in an
// ImprovementTrace, the f of evaluation number `evaluations`, which improved on all before it.
struct CheckpointSample {
    std::int64_t evaluations = 0;
    double best_f = 0.0;
};

// Every strict improvement of best-so-far f, at the evaluation that made it (the first f below
// +inf is one), and the f of the run's last evaluation: what IOHexperimenter's analyzer logger
// writes by default (a row per improvement, and a last row for the last evaluation when it is not
// one). The Objective's TraceRecorder records it (problems/trace_recorder.hpp).
struct ImprovementTrace {
    std::vector<CheckpointSample> points; // by evaluation
    double last_f = std::numeric_limits<double>::quiet_NaN();
};

// Its fields are listed once more, each with its runs.csv column and its place in store.bin, in
// run_fields.hpp: a member missing there is neither stored nor in runs.csv. The curve, checkpoints
// and improvements are not in that list: they have code and files of their own.
struct RunRecord {
    std::int64_t run_id = 0; // position in the study's run list, 0-based
    std::string algorithm;   // canonical spec, e.g. "itlbo:obl=off"
    std::string problem;     // canonical spec, e.g. "pmsm:load=2,speed=2500"
    // The budget the run was given, as text: "iterations=150", "evaluations=15050",
    // "iterations=150,evaluations=20000", with ",target=1e-08" when a target was set. A study may
    // hold several budgets (a factor of its design); each is reported separately. Empty in
    // studies written before budgets were recorded.
    std::string budget;
    std::int64_t run_index = 0; // 0-based repetition of this (algorithm, problem) pair
    std::uint64_t seed = 0;     // the run's stream seed

    bool ok = true;
    std::string message; // why a failed run failed

    double best_f = std::numeric_limits<double>::quiet_NaN();
    std::optional<double> f_opt; // known optimum of the problem
    std::vector<double> x_opt;   // where it is attained, where known (e.g. the least-squares theta*)
    std::int64_t evaluations = 0;
    std::int64_t iterations = 0;
    std::optional<std::int64_t> evaluations_to_target;
    std::vector<double> best_x;

    std::vector<std::string> parameter_names; // empty for test functions
    std::vector<double> true_parameters;      // empty when unknown

    std::vector<CurvePoint> curve;
    std::vector<CheckpointSample> checkpoints;
    // Absent for failed runs, and for runs stored before improvements were recorded (then the
    // grid above is all there is).
    std::optional<ImprovementTrace> improvements;

    // best_f - f_opt, where the optimum is known.
    [[nodiscard]] std::optional<double> error() const {
        if (!f_opt || !ok)
            return std::nullopt;
        return best_f - *f_opt;
    }
};

} // namespace mhb
