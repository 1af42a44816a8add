// Each optimiser's own time per evaluation (its overhead, excluding the objective) on a very cheap
// problem, the 10-D sphere, with a budget of 20000 evaluations per run.
//   optimizer/<spec>      whole runs; the counter per_eval is the run's time per evaluation.
//   objective_only        the same number of Objective::evaluate calls on stored points: the cost
//                         of the problem plus the Objective's counting, repair and trace.
//   objective_improving   the same, on points each better than the last: every evaluation is an
//                         improvement, the worst case for the improvement record.
// An optimiser's overhead per evaluation is per_eval(optimizer) - per_eval(objective_only).
// Run: build/release/tests/bench/optimizer_overhead_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"
#include "problems/problem_registry.hpp"
#include "tests/unit/algorithms/baselines_test_problems.hpp" // baseline_specs(): the optimisers the tests cover

namespace mhb {
namespace {

constexpr std::int64_t budget = 20000;

const Problem& cheap_problem() {
    static const auto problem = builtin_problems().create("sphere:dim=10");
    return *problem;
}

void per_evaluation_counter(benchmark::State& state, std::int64_t evaluations) {
    state.counters["per_eval"] = benchmark::Counter(
        static_cast<double>(evaluations), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void objective_only(benchmark::State& state) {
    const Problem& problem = cheap_problem();
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

// Every evaluation improves best-so-far: points on a ray towards the optimum, nearest last.
void objective_improving(benchmark::State& state) {
    const Problem& problem = cheap_problem();
    std::vector<Eigen::VectorXd> points(static_cast<std::size_t>(budget));
    for (std::size_t i = 0; i < points.size(); ++i)
        points[i] =
            Eigen::VectorXd::Constant(problem.dimension(), 50.0 * static_cast<double>(points.size() - i) /
                                                               static_cast<double>(points.size()));
    std::int64_t evaluations = 0;
    Eigen::VectorXd x(problem.dimension());
    for (auto _ : state) {
        Objective objective(problem, Budget{budget, std::nullopt, std::nullopt});
        for (std::size_t i = 0; i < points.size(); ++i) {
            x = points[i];
            benchmark::DoNotOptimize(objective.evaluate(x));
        }
        evaluations += objective.evaluations();
    }
    per_evaluation_counter(state, evaluations);
}

void optimizer_run(benchmark::State& state, const std::string& spec) {
    const auto optimizer = builtin_algorithms().create(spec);
    const Problem& problem = cheap_problem();
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

const bool registered = [] {
    benchmark::RegisterBenchmark("objective_only", objective_only)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("objective_improving", objective_improving)->Unit(benchmark::kMillisecond);
    for (const auto& spec : test::baseline_specs())
        benchmark::RegisterBenchmark(("optimizer/" + spec).c_str(), optimizer_run, spec)
            ->Unit(benchmark::kMillisecond);
    return true;
}();

} // namespace
} // namespace mhb
