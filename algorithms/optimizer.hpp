// The Optimizer contract. An optimiser holds only its hyper-parameters, fixed at construction;
// the objective and the random stream are passed to run(), so one configured instance is shared
// read-only by all the runs of a study, on any number of threads (pagmo's mutable RNG member is
// the thing avoided here).
#pragma once

#include <optional>
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

    // Why this configuration cannot run on a problem of `dimension`, as one line that starts with
    // the optimiser's name and says which parameter to change (a population the dimension makes
    // smaller than the method needs, or too large for memory); nothing when it can. A study asks
    // every optimiser about every problem's dimension before its first run, so that it is refused
    // at once, with no directory made; run() may still throw for a caller that did not ask.
    [[nodiscard]] virtual std::optional<std::string> refusal(Eigen::Index dimension) const {
        (void)dimension;
        return std::nullopt;
    }

    // What determines this optimiser's numbers beyond its spec and implementation version, as one
    // line that joins the identity of its runs: for an external program, the SHA-256 of its code
    // and the version it announces (problems/external/command.hpp). Empty for built-ins, so that
    // their run identities are unchanged.
    [[nodiscard]] virtual std::string identity_facts() const { return {}; }
};

// Runs `optimizer` to the end of the budget: BudgetExhausted is the normal way out, after which
// the objective's trace is closed. Any other exception propagates.
void run_to_budget(const Optimizer& optimizer, Objective& objective, Rng& rng);

} // namespace mhb
