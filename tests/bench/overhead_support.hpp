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

// 1000 uniform points in the problem's box, the same for every benchmark (seed 1).
inline std::vector<Eigen::VectorXd> stored_points(const Problem& problem) {
    Rng rng(1);
    std::vector<Eigen::VectorXd> points(1000);
    for (auto& p : points)
        p = uniform_point(problem.bounds(), rng);
    return points;
}

// `budget` Objective::evaluate calls per iteration on the stored points: the problem plus the
// Objective's counting, repair and records. Points are copied into a preallocated vector (same
// size: a copy), so no allocation is timed.
inline void objective_only_runs(benchmark::State& state, const Problem& problem, std::int64_t budget) {
    const std::vector<Eigen::VectorXd> points = stored_points(problem);
    std::int64_t evaluations = 0;
    Eigen::VectorXd x(problem.dimension());
    for (auto _ : state) {
        Objective objective(problem, Budget{budget, std::nullopt, std::nullopt});
        for (std::int64_t i = 0; i < budget; ++i) {
            x = points[static_cast<std::size_t>(i % 1000)];
            benchmark::DoNotOptimize(objective.evaluate(x));
        }
        evaluations += objective.evaluations();
    }
    per_evaluation_counter(state, evaluations);
}

// The same loop calling the problem directly: what objective_only costs without the Objective, so
// that the Objective's own cost per evaluation is the difference of the two.
inline void problem_only_runs(benchmark::State& state, const Problem& problem, std::int64_t budget) {
    const std::vector<Eigen::VectorXd> points = stored_points(problem);
    Eigen::VectorXd x(problem.dimension());
    for (auto _ : state)
        for (std::int64_t i = 0; i < budget; ++i) {
            x = points[static_cast<std::size_t>(i % 1000)];
            benchmark::DoNotOptimize(problem.evaluate(x));
        }
    per_evaluation_counter(state, static_cast<std::int64_t>(state.iterations()) * budget);
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
