// Speed of the `fluxmap` problem on the shipped Baldor map (567 points): one evaluation of each
// model at points spread over the default box (so the timing is not of one cached value), one
// through the counted Objective, and one bounded Levenberg-Marquardt start of the fit.
#include <benchmark/benchmark.h>
#include <cstdint>
#include <optional>

#include "problems/core/rng.hpp"
#include "problems/fluxmap/current_map_fit.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"

namespace {

using namespace mhb;

std::vector<Eigen::VectorXd> flux_sample_points(const Box& box, int count) {
    Rng rng(1);
    std::vector<Eigen::VectorXd> points;
    for (int i = 0; i < count; ++i) {
        Eigen::VectorXd x(box.dimension());
        for (Eigen::Index j = 0; j < x.size(); ++j)
            x[j] = rng.uniform(box.lower[j], box.upper[j]);
        points.push_back(x);
    }
    return points;
}

// Arg 0: model=syrm (9 parameters); arg 1: model=pmsyrm (14, the default).
void BM_FluxMapEvaluate(benchmark::State& state) {
    const auto problem = builtin_problems().create(state.range(0) == 0 ? "fluxmap:model=syrm" : "fluxmap");
    const auto points = flux_sample_points(problem->bounds(), 64);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(problem->evaluate(points[i]));
        i = (i + 1) % points.size();
    }
}
BENCHMARK(BM_FluxMapEvaluate)->Arg(0)->Arg(1);

void BM_FluxMapObjective(benchmark::State& state) {
    const auto problem = builtin_problems().create("fluxmap");
    const auto points = flux_sample_points(problem->bounds(), 64);
    Objective objective(*problem, Budget{std::int64_t{1} << 60, std::nullopt, std::nullopt});
    auto points_copy = points;
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(objective.evaluate(points_copy[i]));
        i = (i + 1) % points.size();
    }
}
BENCHMARK(BM_FluxMapObjective);

// One start of the fit that found the shipped optimum (fit_multistart runs 100 of them).
void BM_FluxMapFitOneStart(benchmark::State& state) {
    const auto problem = builtin_problems().create("fluxmap");
    const fluxmap::CurrentMap map(fluxmap::Model::pmsyrm, fluxmap::baldor_flux_map());
    const auto starts = flux_sample_points(problem->bounds(), 8);
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(fluxmap::fit_from(map, problem->bounds(), starts[i], 2000).f);
        i = (i + 1) % starts.size();
    }
}
BENCHMARK(BM_FluxMapFitOneStart)->Unit(benchmark::kMillisecond);

} // namespace
