#include "algorithms/optimizer.hpp"

namespace mhb {

void run_to_budget(const Optimizer& optimizer, Objective& objective, Rng& rng) {
    try {
        optimizer.run(objective, rng);
    } catch (const BudgetExhausted&) {
        // The budget ran out in the middle of an iteration: the normal end of a run.
    }
    objective.finish();
}

} // namespace mhb
