// The Optimizer contract. An optimiser holds only its hyper-parameters, fixed at construction;
// the objective and the random stream are passed to run(), so one configured instance is shared
// read-only by all the runs of a study, on any number of threads (pagmo's mutable RNG member is
// the thing avoided here).
#pragma once

#include <string>

#include "problems/core/rng.hpp"
#include "problems/objective.hpp"

namespace mhb {

class Optimizer {
public:
    virtual ~Optimizer() = default;

    [[nodiscard]] virtual std::string name() const = 0;

    // How out-of-bounds candidates are repaired; the runner builds the Objective with it.
    [[nodiscard]] virtual BoundPolicy bound_policy() const { return BoundPolicy::clamp; }

    // Minimises through `objective` until objective.exhausted(). May stop early by returning
    // (e.g. a deterministic method that has converged); may also be unwound by BudgetExhausted
    // from objective.evaluate(). Must draw every random number from `rng`.
    virtual void run(Objective& objective, Rng& rng) const = 0;
};

// Runs `optimizer` to the end of the budget: BudgetExhausted is the normal way out, after which
// the objective's trace is closed. Any other exception propagates.
void run_to_budget(const Optimizer& optimizer, Objective& objective, Rng& rng);

} // namespace mhb
