#include "problems/trace_recorder.hpp"

#include <algorithm>
#include <cmath>

namespace mhb {

std::int64_t next_checkpoint(std::int64_t evaluations) {
    if (evaluations < 1)
        return 1;
    // Start a little below the answer and walk up the grid.
    auto k = static_cast<int>(std::floor(10.0 * std::log10(static_cast<double>(evaluations)))) - 1;
    k = std::max(k, 0);
    while (true) {
        const std::int64_t g = std::llround(std::pow(10.0, k / 10.0));
        if (g > evaluations)
            return g;
        ++k;
    }
}

// Out of line: reached about ten times per decade of evaluations.
void TraceRecorder::add_checkpoint(std::int64_t evaluation, double best_f) {
    checkpoint_trace_.push_back({evaluation, best_f});
    next_checkpoint_ = next_checkpoint(evaluation);
}

void TraceRecorder::iteration_ended(std::int64_t iteration, std::int64_t evaluations, double best_f,
                                    const Eigen::VectorXd& best_x) {
    IterationPoint point{iteration, evaluations, best_f, {}};
    if (record_best_x_)
        point.best_x = best_x;
    iteration_trace_.push_back(std::move(point));
}

void TraceRecorder::finish(std::int64_t evaluations, double best_f) {
    if (evaluations > 0 && (checkpoint_trace_.empty() || checkpoint_trace_.back().evaluations != evaluations))
        checkpoint_trace_.push_back({evaluations, best_f});
}

} // namespace mhb
