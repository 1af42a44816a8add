// Each optimiser's own time per evaluation (its overhead, excluding the objective) on a very cheap
// problem, the 10-D sphere, with a budget of 20000 evaluations per run.
//   optimizer/<spec>      whole runs; the counter per_eval is the run's time per evaluation.
//   problem_only          the same loop calling the problem directly: objective_only minus this is
//                         the Objective's own cost per evaluation
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
#include "tests/bench/overhead_support.hpp"
#include "tests/unit/algorithms/baselines_test_problems.hpp" // baseline_specs(): the optimisers the tests cover

namespace mhb {
namespace {

constexpr std::int64_t budget = 20000;

const Problem& cheap_problem() {
    static const auto problem = builtin_problems().create("sphere:dim=10");
    return *problem;
}

void problem_only(benchmark::State& state) {
    bench::problem_only_runs(state, cheap_problem(), budget);
}

void objective_only(benchmark::State& state) {
    bench::objective_only_runs(state, cheap_problem(), budget);
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
    bench::per_evaluation_counter(state, evaluations);
}

void optimizer_run(benchmark::State& state, const std::string& spec) {
    bench::optimizer_runs(state, spec, cheap_problem(), budget);
}

const bool registered = [] {
    benchmark::RegisterBenchmark("problem_only", problem_only)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("objective_only", objective_only)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("objective_improving", objective_improving)->Unit(benchmark::kMillisecond);
    for (const auto& spec : test::baseline_specs())
        benchmark::RegisterBenchmark(("optimizer/" + spec).c_str(), optimizer_run, spec)
            ->Unit(benchmark::kMillisecond);
    return true;
}();

} // namespace
} // namespace mhb
