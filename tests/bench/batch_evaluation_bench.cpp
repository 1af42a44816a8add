// Objective::evaluate_batch: what parallel evaluation inside a run buys on an expensive problem,
// and what batching costs on a cheap one.
//   expensive/single           one evaluation of the synthetic expensive problem (~50 us of arithmetic)
//   expensive/loop             50 evaluate() calls, one after another
//   expensive/batch/threads:N  one evaluate_batch of the same 50 points, N threads allowed
//                              (tbb::global_control), the problem saying parallel_evaluation()
//   cheap/loop, cheap/batch    the 10-D sphere (parallel_evaluation() false): 50 evaluate() calls
//                              against one evaluate_batch of 50, which is then a plain loop
//   cheap/batch_parallel/threads:N  the same sphere claiming parallel_evaluation(): the cost of
//                              sending a cheap population to oneTBB (why cheap problems say false)
// The counter per_eval is the time per evaluation.
// Run: build/release/tests/bench/batch_evaluation_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>
#include <cmath>
#include <oneapi/tbb/global_control.h>
#include <vector>

#include "algorithms/sampling.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

constexpr std::size_t population = 50;

// A stand-in for a motor simulation: a fixed amount of floating-point work per evaluation (about
// 50 us on a 2020s x86 core), with a result that depends on every coordinate.
class Expensive final : public Problem {
public:
    explicit Expensive(Eigen::Index dimension)
        : box_{Eigen::VectorXd::Constant(dimension, -5.0), Eigen::VectorXd::Constant(dimension, 5.0)} {}
    std::string name() const override { return "expensive"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        // An explicit Euler integration of dy/dt = -y + sum_k sin(x_k t), like a simulator's loop.
        double y = 0.0;
        const double dt = 1e-4;
        for (int step = 0; step < 1300; ++step) {
            const double t = dt * step;
            double u = 0.0;
            for (Eigen::Index k = 0; k < x.size(); ++k)
                u += std::sin(x[k] * t);
            y += dt * (u - y);
        }
        return y * y + x.squaredNorm();
    }
    bool parallel_evaluation() const override { return true; }

private:
    Box box_;
};

// A problem as it is, apart from what parallel_evaluation() says.
class ClaimsParallel final : public Problem {
public:
    explicit ClaimsParallel(const Problem& inner) : inner_(inner) {}
    std::string name() const override { return inner_.name(); }
    Eigen::Index dimension() const override { return inner_.dimension(); }
    const Box& bounds() const override { return inner_.bounds(); }
    double evaluate(const Eigen::VectorXd& x) const override { return inner_.evaluate(x); }
    bool parallel_evaluation() const override { return true; }

private:
    const Problem& inner_;
};

const Problem& expensive_problem() {
    static const Expensive problem(4);
    return problem;
}

const Problem& cheap_problem() {
    static const auto problem = builtin_problems().create("sphere:dim=10");
    return *problem;
}

std::vector<Eigen::VectorXd> points_in(const Problem& problem) {
    Rng rng(7);
    std::vector<Eigen::VectorXd> points(population);
    for (auto& p : points)
        p = uniform_point(problem.bounds(), rng);
    return points;
}

// No evaluation budget: the objective outlives every benchmark iteration (an iteration budget
// that is never counted down keeps it open).
Budget open_budget() {
    return Budget{std::nullopt, 1, std::nullopt};
}

void per_evaluation_counter(benchmark::State& state) {
    state.counters["per_eval"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * static_cast<double>(population),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void loop(benchmark::State& state, const Problem& problem) {
    std::vector<Eigen::VectorXd> points = points_in(problem);
    Objective objective(problem, open_budget());
    for (auto _ : state) {
        for (auto& x : points)
            benchmark::DoNotOptimize(objective.evaluate(x));
    }
    per_evaluation_counter(state);
}

void batch(benchmark::State& state, const Problem& problem) {
    const tbb::global_control cap(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(state.range(0)));
    std::vector<Eigen::VectorXd> points = points_in(problem);
    std::vector<double> f(population);
    Objective objective(problem, open_budget());
    for (auto _ : state) {
        objective.evaluate_batch(points, f);
        benchmark::DoNotOptimize(f.data());
    }
    per_evaluation_counter(state);
}

void expensive_single(benchmark::State& state) {
    const Problem& problem = expensive_problem();
    const Eigen::VectorXd x = points_in(problem).front();
    for (auto _ : state)
        benchmark::DoNotOptimize(problem.evaluate(x));
}

void expensive_loop(benchmark::State& state) {
    loop(state, expensive_problem());
}
void expensive_batch(benchmark::State& state) {
    batch(state, expensive_problem());
}
void cheap_loop(benchmark::State& state) {
    loop(state, cheap_problem());
}
void cheap_batch(benchmark::State& state) {
    batch(state, cheap_problem());
}
void cheap_batch_parallel(benchmark::State& state) {
    static const ClaimsParallel problem(cheap_problem());
    batch(state, problem);
}

BENCHMARK(expensive_single)->Name("expensive/single")->Unit(benchmark::kMicrosecond);
BENCHMARK(expensive_loop)->Name("expensive/loop")->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(expensive_batch)
    ->Name("expensive/batch")
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK(cheap_loop)->Name("cheap/loop")->Unit(benchmark::kMicrosecond);
BENCHMARK(cheap_batch)->Name("cheap/batch")->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(cheap_batch_parallel)
    ->Name("cheap/batch_parallel")
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

} // namespace
} // namespace mhb
