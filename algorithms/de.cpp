// Differential evolution, DE/rand/1/bin (Storn and Price 1997, "Differential Evolution - A Simple
// and Efficient Heuristic for Global Optimization over Continuous Spaces", J. Global Optim. 11).
//
// For each target x_i: three distinct members r1, r2, r3 (all != i) give the mutant
// v = x_r1 + F (x_r2 - x_r3); binomial crossover takes v_k where rand < CR or k = k_rand, x_i,k
// otherwise; the trial replaces x_i if f(trial) <= f(x_i). A generation is synchronous: every trial
// is built from the population as it was when the generation began (Storn and Price's scheme).
//
// Defaults (Storn and Price 1997, section 3): NP = 10 D, F = 0.5, CR = 0.9 (their advice for a
// first try: F = 0.5, CR = 0.1 or 0.9; 0.9 since rotated problems need it).
// Bounds: out-of-box trials are clamped by the Objective (BoundPolicy::clamp).
// Evaluations: NP to initialise, then NP per iteration (one trial per member), each a batch
// (Objective::evaluate_batch).
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/population.hpp"
#include "algorithms/population_limits.hpp"

namespace mhb {
namespace {

class DifferentialEvolution final : public Optimizer {
public:
    DifferentialEvolution(long long population, double f, double cr)
        : population_(population), f_(f), cr_(cr) {}

    std::string name() const override { return "de"; }

    // The population and its trials; np = 0 means 10 D.
    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        const double np =
            population_ > 0 ? static_cast<double>(population_) : 10.0 * static_cast<double>(dimension);
        return population_memory_refusal("de", 2.0 * np, dimension, "np");
    }

    void run(Objective& objective, Rng& rng) const override {
        const Eigen::Index d = objective.dimension();
        const auto np = static_cast<std::size_t>(population_ > 0 ? population_ : 10 * d);
        auto [x, fx] = random_population(objective, rng, np);
        objective.initialised();

        std::vector<Eigen::VectorXd> next = x;
        std::vector<double> f_next = fx;
        std::vector<Eigen::VectorXd> trials(np, Eigen::VectorXd::Zero(d));
        std::vector<double> f_trials(np);
        while (!objective.exhausted()) {
            // Every trial first (they depend on the old generation only), then one batch of
            // evaluations, then the selections: the draws, points and evaluations of the
            // one-trial-at-a-time loop, in the same order.
            for (std::size_t i = 0; i < np; ++i) {
                Eigen::VectorXd& trial = trials[i];
                std::size_t r1 = 0, r2 = 0, r3 = 0;
                do {
                    r1 = rng.below(np);
                } while (r1 == i);
                do {
                    r2 = rng.below(np);
                } while (r2 == i || r2 == r1);
                do {
                    r3 = rng.below(np);
                } while (r3 == i || r3 == r1 || r3 == r2);
                const auto k_rand = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(d)));
                for (Eigen::Index k = 0; k < d; ++k)
                    trial[k] = (rng.uniform() < cr_ || k == k_rand) ? x[r1][k] + f_ * (x[r2][k] - x[r3][k])
                                                                    : x[i][k];
            }
            objective.evaluate_batch(trials, f_trials);
            for (std::size_t i = 0; i < np; ++i) {
                if (f_trials[i] <= fx[i]) {
                    next[i].swap(trials[i]); // the trial buffer is rewritten next generation
                    f_next[i] = f_trials[i];
                } else {
                    next[i] = x[i];
                    f_next[i] = fx[i];
                }
            }
            std::swap(x, next);
            std::swap(fx, f_next);
            objective.end_iteration();
        }
    }

private:
    long long population_;
    double f_;
    double cr_;
};

} // namespace

void register_de(AlgorithmRegistry& registry) {
    registry.add(
        {"de",
         1,
         "differential evolution DE/rand/1/bin; NP evaluations per iteration",
         "Storn and Price (1997), J. Global Optim. 11:341-359",
         {ParameterInfo::integer("np", 0, 0, 1000000,
                                 "population size; 0 = 10*D (Storn and Price 1997); otherwise at least 4"),
          ParameterInfo::real("F", 0.5, 0.0, 2.0, "differential weight (Storn and Price 1997: 0.5)")
              .open_below(),
          ParameterInfo::real("CR", 0.9, 0.0, 1.0, "crossover probability (Storn and Price 1997: 0.9)")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             const long long np = p.integer("np");
             if (np > 0 && np < 4)
                 throw std::invalid_argument("de: parameter 'np' = " + std::to_string(np) +
                                             " is too small: DE/rand/1 needs the target and three other "
                                             "members (0 or at least 4)");
             return std::make_unique<DifferentialEvolution>(np, p.real("F"), p.real("CR"));
         }},
        {"DE"});
}

} // namespace mhb
