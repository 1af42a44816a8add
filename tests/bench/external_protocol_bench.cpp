// The external protocol's cost per evaluation (problems/external/), against the same function
// computed in process. Each benchmark evaluates batches through Objective::evaluate_batch, as an
// optimiser does:
//   in_process/B          the built-in 10-D sphere, batches of B
//   python/B              scripts/external/sphere_problem.py (Debian's /usr/bin/python3), one
//                         message of B points per batch: pipes, JSON both ways, Python's loop
//   cpp/B                 the header-only C++ client's Rosenbrock (mhb_external_example_problem,
//                         when MHB_EXTERNAL_EXAMPLE is set to its path): the protocol without Python
// The counter per_eval is the wall time per evaluation; B = 1, 10, 100 points per message.
// Run: build/release/tests/bench/external_protocol_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>
#include <cstdlib>
#include <vector>

#include "algorithms/sampling.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

void evaluate_batches(benchmark::State& state, const Problem& problem) {
    const auto batch = static_cast<std::size_t>(state.range(0));
    Rng rng(1);
    std::vector<Eigen::VectorXd> x(batch);
    std::vector<double> f(batch);
    for (auto& point : x)
        point = uniform_point(problem.bounds(), rng);
    Objective objective(problem, Budget{std::int64_t{1} << 60, std::nullopt, std::nullopt});
    for (auto _ : state) {
        objective.evaluate_batch(x, f);
        benchmark::DoNotOptimize(f.data());
    }
    state.counters["per_eval"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * static_cast<double>(batch),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void in_process(benchmark::State& state) {
    const auto problem = builtin_problems().create("sphere:dim=10,bound=5");
    evaluate_batches(state, *problem);
}

void python(benchmark::State& state) {
    const auto problem =
        builtin_problems().create("external:cmd=/usr/bin/python3 '" + std::string(MHB_SOURCE_DIR) +
                                  "/scripts/external/sphere_problem.py',params=dim=10");
    evaluate_batches(state, *problem);
}

void cpp(benchmark::State& state) {
    const char* path = std::getenv("MHB_EXTERNAL_EXAMPLE");
    if (path == nullptr) {
        state.SkipWithError("set MHB_EXTERNAL_EXAMPLE to build/release/tests/mhb_external_example_problem");
        return;
    }
    const auto problem = builtin_problems().create("external:cmd=" + std::string(path) + ",params=dim=10");
    evaluate_batches(state, *problem);
}

// Wall time: the child's work is not this process's CPU time.
BENCHMARK(in_process)->Arg(1)->Arg(10)->Arg(100)->UseRealTime();
BENCHMARK(python)->Arg(1)->Arg(10)->Arg(100)->UseRealTime();
BENCHMARK(cpp)->Arg(1)->Arg(10)->Arg(100)->UseRealTime();

} // namespace
} // namespace mhb
