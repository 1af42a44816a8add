// Nanoseconds per evaluation of every test function at D = 10 and 30: each classic function
// plain, shifted, and shifted+rotated, and every BBOB function (instance 1). Problems are built
// once, outside the timed loop, so this also shows that no rotation is recomputed per evaluation
// (a rotated evaluation costs one D x D product, not a QR). Results go to BENCHMARKS.md.
//   build/release/tests/bench/functions_bench --benchmark_min_time=0.1
#include <benchmark/benchmark.h>
#include <memory>
#include <string>
#include <vector>

#include "problems/functions/classic_function.hpp"
#include "problems/problem_registry.hpp"
#include "problems/rng.hpp"

namespace {

void evaluate_problem(benchmark::State& state, const std::string& spec) {
    const auto problem = mhb::builtin_problems().create(spec);
    const mhb::Box& box = problem->bounds();
    // A fixed set of points inside the box, cycled through, so branches are not all predicted.
    mhb::Rng rng(2017);
    std::vector<Eigen::VectorXd> points(64, Eigen::VectorXd(problem->dimension()));
    for (auto& x : points)
        for (Eigen::Index i = 0; i < x.size(); ++i)
            x[i] = rng.uniform(box.lower[i], box.upper[i]);
    std::size_t k = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(problem->evaluate(points[k]));
        k = (k + 1) % points.size();
    }
    state.SetItemsProcessed(state.iterations());
}

bool register_all() {
    for (const int dim : {10, 30}) {
        const std::string d = ":dim=" + std::to_string(dim);
        for (const auto& name : mhb::classic_function_names())
            for (const std::string variant : {"", ",shift=1", ",shift=1,rotate=1"}) {
                const std::string spec = name + d + variant;
                benchmark::RegisterBenchmark(spec.c_str(), evaluate_problem, spec);
            }
        for (int f = 1; f <= 24; ++f) {
            const std::string spec = "bbob:f=" + std::to_string(f) + ",dim=" + std::to_string(dim);
            benchmark::RegisterBenchmark(spec.c_str(), evaluate_problem, spec);
        }
    }
    return true;
}

const bool registered = register_all();

} // namespace
