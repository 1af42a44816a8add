// What the overhead benchmarks share: whole optimiser runs on a cheap problem, and the same number
// of bare Objective::evaluate calls, each reported as CPU time per evaluation (counter per_eval).
// An optimiser's own cost per evaluation is the difference of the two.
#pragma once

#include <benchmark/benchmark.h>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"

namespace mhb::bench {

inline void per_evaluation_counter(benchmark::State& state, std::int64_t evaluations) {
    state.counters["per_eval"] = benchmark::Counter(
        static_cast<double>(evaluations), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// `budget` Objective::evaluate calls per iteration on 1000 stored uniform points: the problem plus
// the Objective's counting, repair and records. Points are copied into a preallocated vector, so
// no allocation is timed.
inline void objective_only_runs(benchmark::State& state, const Problem& problem, std::int64_t budget) {
    Rng rng(1);
    std::vector<Eigen::VectorXd> points(1000);
    for (auto& p : points)
        p = uniform_point(problem.bounds(), rng);
    std::int64_t evaluations = 0;
    Eigen::VectorXd x(problem.dimension());
    for (auto _ : state) {
        Objective objective(problem, Budget{budget, std::nullopt, std::nullopt});
        for (std::int64_t i = 0; i < budget; ++i) {
            x = points[static_cast<std::size_t>(i % 1000)]; // same size: a copy, no allocation
            benchmark::DoNotOptimize(objective.evaluate(x));
        }
        evaluations += objective.evaluations();
    }
    per_evaluation_counter(state, evaluations);
}

// Whole runs of `spec` with a budget of `budget` evaluations, a new seed each iteration.
inline void optimizer_runs(benchmark::State& state, const std::string& spec, const Problem& problem,
                           std::int64_t budget) {
    const auto optimizer = builtin_algorithms().create(spec);
    std::int64_t evaluations = 0;
    std::uint64_t seed = 0;
    for (auto _ : state) {
        Objective objective(problem, Budget{budget, std::nullopt, std::nullopt}, optimizer->bound_policy());
        Rng rng(++seed);
        run_to_budget(*optimizer, objective, rng);
        evaluations += objective.evaluations();
        benchmark::DoNotOptimize(objective.best_f());
    }
    per_evaluation_counter(state, evaluations);
}

} // namespace mhb::bench
