// Speed of the PMSM identification problem: one eq. 11 evaluation at n = 300 pairs (the hot loop
// of every PMSM study; expanded and direct forms), the expanded one through the counted Objective, the
// least-squares reference, and the drive simulator making the default dataset (0.4 s of drive at Ts = 100 us,
// RK4 at 10 us). For the dynamic model: one evaluation of LinearModelProblem (the constant-time
// expansion) against the direct sum LinearModel::fitness, and the exact fit, against the number of rows.
#include <benchmark/benchmark.h>

#include "problems/core/rng.hpp"
#include "problems/objective.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "problems/pmsm/dynamic_model.hpp"
#include "problems/pmsm/least_squares.hpp"
#include "problems/pmsm/linear_model.hpp"
#include "problems/pmsm/linear_model_problem.hpp"
#include "problems/pmsm/steady_state_problem.hpp"

namespace {

using namespace mhb;

// Points spread over the paper's box, so the timing is not of one cached value.
std::vector<Eigen::VectorXd> sample_points(const Box& box, int count) {
    Rng rng(1);
    std::vector<Eigen::VectorXd> points;
    for (int i = 0; i < count; ++i) {
        Eigen::VectorXd x(4);
        for (int j = 0; j < 4; ++j)
            x[j] = rng.uniform(box.lower[j], box.upper[j]);
        points.push_back(x);
    }
    return points;
}

// Arg 0: the default constant-time expansion; arg 1: the direct sum over the 600 samples.
void BM_PmsmFitness300(benchmark::State& state) {
    const auto evaluation =
        state.range(0) == 0 ? pmsm::FitnessEvaluation::expanded : pmsm::FitnessEvaluation::direct;
    const pmsm::SteadyStateProblem problem(pmsm::simulate_dataset({}), {}, pmsm::paper_bounds(), evaluation);
    const auto points = sample_points(problem.bounds(), 64);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(problem.evaluate(points[i++ & 63]));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PmsmFitness300)->Arg(0)->Arg(1);

void BM_PmsmFitness300ThroughObjective(benchmark::State& state) {
    const pmsm::SteadyStateProblem problem(pmsm::simulate_dataset({}), {}, pmsm::paper_bounds());
    auto points = sample_points(problem.bounds(), 64);
    Objective objective(problem, Budget{std::int64_t{1} << 60, std::nullopt, std::nullopt});
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(objective.evaluate(points[i++ & 63]));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PmsmFitness300ThroughObjective);

void BM_PmsmLeastSquares300(benchmark::State& state) {
    const pmsm::SteadyStateData samples = pmsm::pair_samples(pmsm::simulate_dataset({}));
    for (auto _ : state)
        benchmark::DoNotOptimize(pmsm::solve_least_squares(samples).f);
}
BENCHMARK(BM_PmsmLeastSquares300)->Unit(benchmark::kMicrosecond);

void BM_PmsmSimulateDefaultDataset(benchmark::State& state) {
    const pmsm::SimulatorConfig config;
    for (auto _ : state)
        benchmark::DoNotOptimize(pmsm::simulate_dataset(config).ud.data());
}
BENCHMARK(BM_PmsmSimulateDefaultDataset)->Unit(benchmark::kMillisecond);

// `rows` consecutive samples of a noisy drive whose d-current reference steps every 5 ms, so every
// size holds transients and determines all four parameters.
pmsm::LinearModel dynamic_model_of(std::int64_t rows) {
    pmsm::SimulatorConfig config;
    config.settle_time = 0.005;
    config.plateau = 0.005;
    config.samples_per_state = 50;
    config.noise_i = 0.02;
    config.noise_u = 0.5;
    const pmsm::Dataset trace = pmsm::simulate_trace(config, static_cast<int>(rows));
    return pmsm::dynamic_model({trace}, {"simulated"});
}

// Arg: rows. Constant time whatever the rows (the expansion about the least-squares optimum).
void BM_PmsmDynamicEvaluate(benchmark::State& state) {
    const pmsm::LinearModelProblem problem(dynamic_model_of(state.range(0)), pmsm::paper_bounds(),
                                           std::nullopt);
    const auto points = sample_points(problem.bounds(), 64);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(problem.evaluate(points[i++ & 63]));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PmsmDynamicEvaluate)->Arg(300)->Arg(3000)->Arg(30000);

// Arg: rows. The direct sum over the 2 (rows - 1) equations, the reference the expansion is checked
// against.
void BM_PmsmDynamicFitnessDirect(benchmark::State& state) {
    const pmsm::LinearModel model = dynamic_model_of(state.range(0));
    const auto points = sample_points(pmsm::paper_bounds(), 64);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(model.fitness(points[i++ & 63]));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PmsmDynamicFitnessDirect)->Arg(300)->Arg(3000)->Arg(30000);

// Arg: rows. The exact fit with its box search, paid once per problem instance.
void BM_PmsmDynamicFit(benchmark::State& state) {
    const pmsm::LinearModel model = dynamic_model_of(state.range(0));
    const Box box = pmsm::paper_bounds();
    for (auto _ : state)
        benchmark::DoNotOptimize(pmsm::fit_linear_model(model, &box).f);
}
BENCHMARK(BM_PmsmDynamicFit)->Arg(300)->Arg(3000)->Arg(30000)->Unit(benchmark::kMicrosecond);

} // namespace
