// How long one Bayesian signed-rank test takes (results/analysis/bayesian_signed_rank.hpp) at
// baycomp's 50 000 posterior samples, for n differences: the report runs one per problem and
// algorithm, and one per factorial effect. O(n) a sample after one sort.
#include <benchmark/benchmark.h>
#include <cmath>

#include "results/analysis/bayesian_signed_rank.hpp"

namespace {

void BM_BayesianSignedRank(benchmark::State& state) {
    std::vector<double> z;
    for (std::int64_t i = 0; i < state.range(0); ++i)
        z.push_back(0.3 * std::sin(1.7 * static_cast<double>(i)) - 0.05);
    mhb::BayesianSignedRankOptions options;
    options.rope = 0.1;
    for (auto _ : state)
        benchmark::DoNotOptimize(mhb::bayesian_signed_rank(z, options));
}
BENCHMARK(BM_BayesianSignedRank)
    ->Arg(10)
    ->Arg(20)
    ->Arg(50)
    ->Arg(100)
    ->Arg(300)
    ->Unit(benchmark::kMillisecond);

} // namespace
