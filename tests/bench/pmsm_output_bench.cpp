// Cost of one output-error fitness evaluation (problems/pmsm/output_error.hpp): a simulation of
// every row, so O(rows x substeps). Args: rows (300: one shared `_tr` file; 3000), RK4 substeps
// per period (1, 2, 10) and parameters (4; 5 with the dead-time voltage, one hypot more per step).
#include <benchmark/benchmark.h>

#include "problems/core/rng.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "problems/pmsm/output_error.hpp"

namespace {

using namespace mhb;

// `rows` consecutive periods of the default drive centred on an injection step.
pmsm::Dataset step_window(int rows) {
    const pmsm::SimulatorConfig config;
    const int step = config.settle_steps() + 2 * config.plateau_steps();
    const pmsm::Dataset trace = pmsm::simulate_trace(config, step + rows / 2);
    pmsm::Dataset out;
    for (auto k = static_cast<std::size_t>(step - rows / 2); k < trace.size(); ++k)
        out.push_back(trace.t[k], trace.ud[k], trace.uq[k], trace.id[k], trace.iq[k], trace.omega[k],
                      trace.injected[k]);
    return out;
}

// Points within 20 % of the truth (a population near convergence; far points may diverge and
// stop early, which would flatter the timing).
std::vector<Eigen::VectorXd> sample_points(Eigen::Index n, int count) {
    const Eigen::Vector4d truth = pmsm::paper_motor().identified();
    Rng rng(1);
    std::vector<Eigen::VectorXd> points;
    for (int i = 0; i < count; ++i) {
        Eigen::VectorXd x(n);
        for (Eigen::Index j = 0; j < 4; ++j)
            x[j] = truth[j] * rng.uniform(0.8, 1.2);
        if (n == 5)
            x[4] = rng.uniform(0.0, 5.0);
        points.push_back(x);
    }
    return points;
}

void BM_OutputErrorFitness(benchmark::State& state) {
    const auto rows = static_cast<int>(state.range(0));
    const auto substeps = static_cast<int>(state.range(1));
    const bool dead_time = state.range(2) == 5;
    const pmsm::OutputErrorModel model({step_window(rows)}, {"simulated"}, {dead_time, substeps});
    const auto points = sample_points(model.parameters(), 64);
    std::size_t i = 0;
    for (auto _ : state)
        benchmark::DoNotOptimize(model.fitness(points[i++ & 63]));
    state.SetItemsProcessed(state.iterations());
    state.counters["time_per_row"] =
        benchmark::Counter(static_cast<double>(state.iterations() * model.rows()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_OutputErrorFitness)
    ->ArgsProduct({{300, 3000}, {1, 2, 10}, {4, 5}})
    ->ArgNames({"rows", "substeps", "params"})
    ->Unit(benchmark::kMicrosecond);

} // namespace
