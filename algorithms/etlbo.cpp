// ETLBO, the elitist teaching-learning-based optimisation of Rao and Patel (2012, "An elitist
// teaching-learning-based optimization algorithm for solving complex constrained optimization
// problems", Int. J. Industrial Engineering Computations 3:535-560), the variant the ITLBO paper
// cites. One iteration:
//   1. keep copies of the `elite` best learners;
//   2. teacher phase: X_new = X_i + r (X_teacher - TF Mean), TF = round(1 + rand), greedy;
//   3. learner phase: a random partner j != i; move towards the better of the two, greedy;
//   4. the `elite` worst learners are replaced by the kept copies (no evaluation: f is known);
//   5. duplicates are removed: a learner equal to an earlier one gets one randomly chosen
//      coordinate redrawn uniformly in the box and is re-evaluated (Rao and Patel's mutation).
// The teacher and the mean are taken at the start of the teacher phase; learners are updated in
// place in index order (as ARCHITECTURE.md section 9 reads TLBO). r is uniform per coordinate.
// Defaults: NP = 50 (the ITLBO paper's population, for comparisons at equal NP); elite = 4 (one of
// the elite sizes Rao and Patel tested, 4 to 16).
// Bounds: the Objective clamps, as in the ITLBO paper.
// Evaluations: NP to initialise, then 2 NP plus one per duplicate removed in each iteration.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/population.hpp"
#include "algorithms/population_limits.hpp"

namespace mhb {
namespace {

class Etlbo final : public Optimizer {
public:
    Etlbo(long long population, long long elite) : population_(population), elite_(elite) {}

    std::string name() const override { return "etlbo"; }

    // The class, its elite and the candidates being evaluated.
    std::optional<std::string> refusal(Eigen::Index dimension) const override {
        return population_memory_refusal("etlbo", 3.0 * static_cast<double>(population_), dimension, "np");
    }

    void run(Objective& objective, Rng& rng) const override {
        const Eigen::Index d = objective.dimension();
        const Box& box = objective.bounds();
        const auto np = static_cast<std::size_t>(population_);
        const auto n_elite = static_cast<std::size_t>(elite_);
        Population pop = random_population(objective, rng, np);
        auto& x = pop.x;
        auto& fx = pop.f;
        objective.initialised();

        std::vector<std::size_t> order;
        std::vector<Eigen::VectorXd> elite_x(n_elite);
        std::vector<double> elite_f(n_elite);
        Eigen::VectorXd candidate(d);
        std::vector<Eigen::VectorXd> candidates(np, Eigen::VectorXd::Zero(d));
        std::vector<double> f(np);
        while (!objective.exhausted()) {
            order = pop.ranking();
            for (std::size_t e = 0; e < n_elite; ++e) {
                elite_x[e] = x[order[e]];
                elite_f[e] = fx[order[e]];
            }

            // Teacher phase. The teacher and the mean are fixed for the phase and learner i's
            // move reads only x_i, so all moves are made first and evaluated as one batch (in
            // parallel for an expensive problem): the in-place loop, bit for bit.
            const Eigen::VectorXd teacher = x[order[0]];
            Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
            for (const auto& xi : x)
                mean += xi;
            mean /= static_cast<double>(np);
            for (std::size_t i = 0; i < np; ++i) {
                const double tf = std::round(1.0 + rng.uniform());
                for (Eigen::Index k = 0; k < d; ++k)
                    candidates[i][k] = x[i][k] + rng.uniform() * (teacher[k] - tf * mean[k]);
            }
            objective.evaluate_batch(candidates, f);
            for (std::size_t i = 0; i < np; ++i) {
                if (f[i] < fx[i]) {
                    x[i].swap(candidates[i]); // the candidate buffer is rewritten next time
                    fx[i] = f[i];
                }
            }

            // Learner phase: one at a time, since partner j may have just moved.
            for (std::size_t i = 0; i < np; ++i) {
                const auto j = static_cast<std::size_t>(rng.below_except(np, i));
                const bool i_better = fx[i] < fx[j];
                for (Eigen::Index k = 0; k < d; ++k) {
                    const double step = i_better ? x[i][k] - x[j][k] : x[j][k] - x[i][k];
                    candidate[k] = x[i][k] + rng.uniform() * step;
                }
                accept_if_better(objective, candidate, x[i], fx[i]);
            }

            // Elitism: the worst are replaced by the elites kept at the start of the iteration.
            order = pop.ranking();
            for (std::size_t e = 0; e < n_elite; ++e) {
                const std::size_t worst = order[np - 1 - e];
                x[worst] = elite_x[e];
                fx[worst] = elite_f[e];
            }

            // Duplicate removal by mutation of one random coordinate (rare; one at a time, since
            // the evaluation repairs x_i in place before later learners are compared with it).
            for (std::size_t i = 1; i < np; ++i) {
                for (std::size_t j = 0; j < i; ++j) {
                    if (x[i] != x[j])
                        continue;
                    const auto k = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(d)));
                    x[i][k] = rng.uniform(box.lower[k], box.upper[k]);
                    fx[i] = objective.evaluate(x[i]);
                    break;
                }
            }
            objective.end_iteration();
        }
    }

private:
    static void accept_if_better(Objective& objective, Eigen::VectorXd& candidate, Eigen::VectorXd& x,
                                 double& fx) {
        const double f = objective.evaluate(candidate);
        if (f < fx) {
            x = candidate;
            fx = f;
        }
    }

    long long population_;
    long long elite_;
};

} // namespace

void register_etlbo(AlgorithmRegistry& registry) {
    registry.add(
        {"etlbo",
         1,
         "elitist TLBO: teacher and learner phases, elites replace the worst, duplicates mutated; "
         "2 NP (+ duplicates) evaluations per iteration",
         "Rao and Patel (2012), Int. J. Industrial Engineering Computations 3:535-560",
         {ParameterInfo::integer("np", 50, 2, 1000000, "population size (50: the ITLBO paper's NP)"),
          ParameterInfo::integer("elite", 4, 0, 1000000,
                                 "elites kept per iteration (Rao and Patel 2012 tested 4 to 16); < np")},
         [](const ParameterValues& p) -> std::unique_ptr<Optimizer> {
             if (p.integer("elite") >= p.integer("np"))
                 throw std::invalid_argument(
                     "etlbo: parameter 'elite' = " + std::to_string(p.integer("elite")) +
                     " must be smaller than 'np' = " + std::to_string(p.integer("np")));
             return std::make_unique<Etlbo>(p.integer("np"), p.integer("elite"));
         }},
        {"ETLBO"});
}

} // namespace mhb
