// Whole runs of the paper's algorithms (TLBO, ITLBO of Li, Wang, Ji 2017 and its variants, PSO)
// on the 10-D sphere with a fixed budget of 10^4 evaluations: the time of one run, and per
// evaluation (the "evaluations" rate counter, shown inverted as time per evaluation), so the
// optimisers' own overhead can be compared with the cost of the problems they solve.
//
//   build/release/tests/bench/algorithms_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>
#include <string>

#include "algorithms/algorithm_registry.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"

namespace {

constexpr std::int64_t budget = 10000;

void whole_run(benchmark::State& state, const std::string& algorithm) {
    const auto problem = mhb::builtin_problems().create("sphere:dim=10");
    const auto optimizer = mhb::builtin_algorithms().create(algorithm);
    std::uint64_t seed = 1;
    std::int64_t evaluations = 0;
    for (auto _ : state) {
        mhb::Objective objective(*problem, mhb::Budget{budget, std::nullopt, std::nullopt},
                                 optimizer->bound_policy());
        mhb::Rng rng(seed++);
        mhb::run_to_budget(*optimizer, objective, rng);
        evaluations += objective.evaluations();
        benchmark::DoNotOptimize(objective.best_f());
    }
    state.counters["time_per_evaluation"] = benchmark::Counter(
        static_cast<double>(evaluations), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK_CAPTURE(whole_run, tlbo, std::string("tlbo"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(whole_run, itlbo, std::string("itlbo"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(whole_run, itlbo_all_off, std::string("itlbo:tutorial=off,stepwise=off,obl=off"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(whole_run, itlbo_population_bounds, std::string("itlbo:obl_bounds=population"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(whole_run, pso, std::string("pso"))->Unit(benchmark::kMicrosecond);
