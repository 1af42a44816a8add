// Nanoseconds per evaluation of every test function at D = 10 and 30: each classic function
// plain, shifted, and shifted+rotated, every BBOB function (instance 1), and the CEC 2017 and CEC
// 2022 functions at every dimension with data. Problems are built once, outside the timed loop, so this also
// shows that no rotation is recomputed per evaluation (a rotated evaluation costs one D x D product, not a
// QR). Results go to BENCHMARKS.md.
//   build/release/tests/bench/functions_bench --benchmark_min_time=0.1
#include <benchmark/benchmark.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/core/rng.hpp"
#include "problems/functions/classic_function.hpp"
#include "problems/problem_registry.hpp"

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

// Whether the suite has official data for this function and dimension (the family refuses it
// otherwise).
bool has_data(const std::string& spec) {
    try {
        (void)mhb::builtin_problems().create(spec);
        return true;
    } catch (const std::invalid_argument&) {
        return false;
    }
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
    // The CEC suites at every dimension with official data, compared in BENCHMARKS.md with the
    // official code built -O2 (filter with --benchmark_filter=cec).
    const auto register_cec = [](const std::string& suite, int functions, std::initializer_list<int> dims) {
        for (const int dim : dims)
            for (int f = 1; f <= functions; ++f) {
                const std::string spec = suite + ":f=" + std::to_string(f) + ",dim=" + std::to_string(dim);
                if (has_data(spec))
                    benchmark::RegisterBenchmark(spec.c_str(), evaluate_problem, spec);
            }
    };
    register_cec("cec2017", 30, {2, 10, 20, 30, 50, 100});
    register_cec("cec2022", 12, {2, 10, 20});
    return true;
}

const bool registered = register_all();

} // namespace
