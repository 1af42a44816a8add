// Jaya (R. V. Rao 2016, "Jaya: A simple and new optimization algorithm for solving constrained and
// unconstrained optimization problems", Int. J. Industrial Engineering Computations 7:19-34).
// Parameter-free apart from the population: each member moves towards the best and away from the
// worst, x'_k = x_k + r1 (best_k - |x_k|) - r2 (worst_k - |x_k|) with r1, r2 uniform per
// coordinate (eq. 1 of the paper), and keeps the move only if it improves f (greedy).
// The best and worst are those of the population at the start of the iteration (Rao's code);
// members are updated in place, in index order.
// Default NP = 50: the population of the ITLBO paper's study, so that the two compare at equal NP.
// Bounds: the Objective clamps (Rao clamps to the bounds as well).
// Evaluations: NP to initialise, then NP per iteration.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/population.hpp"
#include "algorithms/population_limits.hpp"

namespace mhb {
namespace {

class Jaya final : public Optimizer {
public:
    explicit Jaya(long long population) : population_(population) {}

    std::string name() const override { return "jaya"; }

    // The population and its candidates.
    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        return population_memory_refusal("jaya", 2.0 * static_cast<double>(population_), dimension, "np");
    }

    void run(Objective& objective, Rng& rng) const override {
        const Eigen::Index d = objective.dimension();
        const auto np = static_cast<std::size_t>(population_);
        auto [x, fx] = random_population(objective, rng, np);
        objective.initialised();

        std::vector<Eigen::VectorXd> candidates(np, Eigen::VectorXd::Zero(d));
        std::vector<double> f(np);
        while (!objective.exhausted()) {
            const auto [lo, hi] = std::minmax_element(fx.begin(), fx.end());
            const Eigen::VectorXd best = x[static_cast<std::size_t>(lo - fx.begin())];
            const Eigen::VectorXd worst = x[static_cast<std::size_t>(hi - fx.begin())];
            // Member i's move reads only x_i and the best and worst of the iteration's start, never
            // another member's update: all moves first, then one batch of evaluations, then the
            // greedy replacements, is the in-place loop bit for bit.
            for (std::size_t i = 0; i < np; ++i) {
                for (Eigen::Index k = 0; k < d; ++k) {
                    const double r1 = rng.uniform();
                    const double r2 = rng.uniform();
                    const double a = std::abs(x[i][k]);
                    candidates[i][k] = x[i][k] + r1 * (best[k] - a) - r2 * (worst[k] - a);
                }
            }
            objective.evaluate_batch(candidates, f);
            for (std::size_t i = 0; i < np; ++i) {
                if (f[i] < fx[i]) {
                    x[i].swap(candidates[i]); // the candidate buffer is rewritten next time
                    fx[i] = f[i];
                }
            }
            objective.end_iteration();
        }
    }

private:
    long long population_;
};

} // namespace

void register_jaya(AlgorithmRegistry& registry) {
    registry.add(
        {"jaya",
         1,
         "Jaya: move towards the best and away from the worst, greedy; NP evaluations per iteration",
         "Rao (2016), Int. J. Industrial Engineering Computations 7:19-34",
         {ParameterInfo::integer("np", 50, 2, 1000000, "population size (50: the ITLBO paper's NP)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             return std::make_unique<Jaya>(p.integer("np"));
         }},
        {"Jaya"});
}

} // namespace mhb
