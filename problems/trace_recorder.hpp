// What a run leaves behind besides its result. The Objective counts and keeps the best-so-far; it
// calls this recorder after every evaluation and every iteration, and the recorder keeps
// (IOHexperimenter's split of problems and loggers: the one computes, the other records)
//   - the iteration trace: best-so-far at the end of every iteration (with best x on request,
//     for parameter trajectories);
//   - the checkpoint grid: best-so-far at a fixed, log-spaced set of evaluation counts shared by
//     every run (so curves share one x-axis), closed by the run's last evaluation;
//   - the improvements: every strict improvement of best-so-far f, at the evaluation that made it,
//     and the f of the run's last evaluation. This is exactly what IOHexperimenter's analyzer
//     logger writes with its default trigger (a row at each improvement, and a last row for the
//     last evaluation when that was not one), so an export needs no grid.
// Its work per evaluation is one store and two rarely taken branches: improvements are few (about
// log(evaluations) for most runs, a few thousand at most in practice).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <vector>

namespace mhb {

struct IterationPoint {
    std::int64_t iteration = 0; // 0 = after initialisation
    std::int64_t evaluations = 0;
    double best_f = 0.0;
    Eigen::VectorXd best_x; // empty unless the recorder keeps best x
};

// Best-so-far after `evaluations` evaluations (a grid point), or, in the improvements, the f of
// the evaluation numbered `evaluations`, which improved on every one before it.
struct CheckpointPoint {
    std::int64_t evaluations = 0;
    double best_f = 0.0;
};

// The shared evaluation grid: about ten points per decade (1, 2, 3, 4, 5, 6, 8, 10, 13, 16, 20,
// 25, ...), i.e. round(10^(k/10)) for k = 0, 1, 2, ... without repeats.
// The smallest grid point greater than `evaluations`.
std::int64_t next_checkpoint(std::int64_t evaluations);

class TraceRecorder {
public:
    explicit TraceRecorder(bool record_best_x = false) : record_best_x_(record_best_x) {}

    // Evaluation number `evaluation` (1-based) gave f. `best_f` is best-so-far with it; `improved`
    // says f is below the best before it (strictly; the first evaluation improves on +inf, so an
    // f of +inf is never an improvement).
    void evaluated(std::int64_t evaluation, double f, double best_f, bool improved) {
        last_f_ = f;
        if (improved) [[unlikely]]
            improvements_.push_back({evaluation, f});
        if (evaluation == next_checkpoint_) [[unlikely]]
            add_checkpoint(evaluation, best_f);
    }

    // The end of iteration `iteration` (0: the initial population), after `evaluations`.
    void iteration_ended(std::int64_t iteration, std::int64_t evaluations, double best_f,
                         const Eigen::VectorXd& best_x);

    // Closes the checkpoint grid: the final evaluation count becomes its last point. Idempotent.
    void finish(std::int64_t evaluations, double best_f);

    [[nodiscard]] const std::vector<IterationPoint>& iteration_trace() const { return iteration_trace_; }
    [[nodiscard]] const std::vector<CheckpointPoint>& checkpoint_trace() const { return checkpoint_trace_; }
    [[nodiscard]] const std::vector<CheckpointPoint>& improvements() const { return improvements_; }
    // f of the last evaluation (not necessarily the best); NaN before the first.
    [[nodiscard]] double last_f() const { return last_f_; }

private:
    void add_checkpoint(std::int64_t evaluation, double best_f);

    bool record_best_x_;
    std::int64_t next_checkpoint_ = 1;
    double last_f_ = std::numeric_limits<double>::quiet_NaN();
    std::vector<IterationPoint> iteration_trace_;
    std::vector<CheckpointPoint> checkpoint_trace_;
    std::vector<CheckpointPoint> improvements_;
};

} // namespace mhb
