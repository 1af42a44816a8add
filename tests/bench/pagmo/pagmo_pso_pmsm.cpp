// The yardstick of BENCHMARKS.md "Whole process against pagmo2": pagmo2's PSO on mhbench's PMSM
// problem, the paper's study size (20 seeds x 7550 evaluations: a population of 50 and 150
// generations), as one whole process to time against `mhbench run --algorithms pso ...
// --no-report --threads 1`. Both evaluate the same Problem::evaluate (mhbench's drive simulator
// makes the data once, in both processes), so what differs is each framework's own work: its
// start-up, its optimiser's bookkeeping and what it writes. pagmo's pso is its default variant
// (constriction, lbest ring of 4); mhbench's is the paper's; both draw 7550 points a run.
// Built only with -DMHB_WITH_PAGMO=ON (Debian's libpagmo-dev: scripts/setup-debian.sh pagmo);
// scripts/pagmo-compare.sh builds both, times them and prints the ratio.
// Prints one line per seed (its best f) so that the work cannot be optimised away.
#include <cstdio>
#include <memory>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/types.hpp>
#include <utility>

#include "problems/problem_registry.hpp"

namespace {

constexpr unsigned population_size = 50;
constexpr unsigned generations = 150;
constexpr unsigned seeds = 20;

// pagmo's user-defined problem: a view of one mhbench Problem (shared, const).
struct PmsmProblem {
    std::shared_ptr<const mhb::Problem> problem;

    [[nodiscard]] pagmo::vector_double fitness(const pagmo::vector_double& x) const {
        const Eigen::VectorXd point =
            Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
        return {problem->evaluate(point)};
    }
    [[nodiscard]] std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
        const mhb::Box& box = problem->bounds();
        return {{box.lower.data(), box.lower.data() + box.lower.size()},
                {box.upper.data(), box.upper.data() + box.upper.size()}};
    }
};

} // namespace

int main() {
    const std::shared_ptr<const mhb::Problem> problem =
        mhb::builtin_problems().create("pmsm:speed=2500,load=2");
    const pagmo::problem udp{PmsmProblem{problem}};
    for (unsigned seed = 1; seed <= seeds; ++seed) {
        pagmo::population population{udp, population_size, seed};
        const pagmo::algorithm pso{pagmo::pso{generations, 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, false, seed}};
        population = pso.evolve(population);
        std::printf("seed %u: best f %.17g after %llu evaluations\n", seed, population.champion_f()[0],
                    static_cast<unsigned long long>(population.get_problem().get_fevals()));
    }
    return 0;
}
