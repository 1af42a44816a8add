// The runner's cost per run, apart from the optimiser: a study of many nearly empty runs
// (random search, a handful of evaluations on a 2-D sphere) through the real path — keys and
// identities, the oneTBB runner, store.bin, the parallel rendering of the result files.
//
//   ./build/release/tests/bench/runner_overhead_bench
//
//   BM_RunnerOverhead/threads:T   a whole study of 20 000 runs on T threads; "us/run" is wall
//                                 time per run, so 1 vs 2 threads gives the parallel efficiency
//   BM_ExecuteOnly/threads:T      the same runs without the store: what the runs themselves cost
//   BM_ShardsMerged               the same study as 3 shards, then merged (run_ids + store)
//   BM_Rerender                   a finished study opened again: keys, index, rendering only
//
// Records with MPI ranks are measured with mpirun (BENCHMARKS.md gives the command).
#include <benchmark/benchmark.h>
#include <filesystem>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <string>

#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "runner/distribution/shards.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/execution/run_identity.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"

namespace {
namespace fs = std::filesystem;

constexpr std::int64_t run_count = 20000;

const mhb::PreparedStudy& tiny_study() {
    static const mhb::PreparedStudy study = [] {
        mhb::Study s;
        s.algorithms = {"random-search"};
        s.problems = {"sphere:dim=2"};
        s.runs = run_count;
        s.budgets = {mhb::parse_budget("evaluations=10")};
        return mhb::prepare_study(s);
    }();
    return study;
}

fs::path scratch(const std::string& name) {
    return fs::temp_directory_path() / ("mhb_runner_bench_" + name);
}

void per_run(benchmark::State& state) {
    state.counters["us/run"] =
        benchmark::Counter(static_cast<double>(run_count) * 1e-6,
                           benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_RunnerOverhead(benchmark::State& state) {
    const mhb::PreparedStudy& study = tiny_study();
    const fs::path dir = scratch("whole");
    mhb::RunnerOptions options;
    options.threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        mhb::StudyWriter writer(dir, mhb::study_ini(study.study), "benchmark\n", study.parameter_columns,
                                true, study.algorithm_infos(), mhb::study_run_keys(study));
        benchmark::DoNotOptimize(mhb::run_study(study, writer, options).kept);
    }
    per_run(state);
    fs::remove_all(dir);
}
BENCHMARK(BM_RunnerOverhead)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_ExecuteOnly(benchmark::State& state) {
    const mhb::PreparedStudy& study = tiny_study();
    const tbb::global_control cap(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(state.range(0)));
    for (auto _ : state)
        tbb::parallel_for(std::int64_t{0}, run_count, [&](std::int64_t id) {
            benchmark::DoNotOptimize(mhb::execute_run(study.request(id)).best_f);
        });
    per_run(state);
}
BENCHMARK(BM_ExecuteOnly)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ShardsMerged(benchmark::State& state) {
    const mhb::PreparedStudy& study = tiny_study();
    const std::string text = mhb::study_ini(study.study);
    const auto shards = mhb::shard_run_ids(study, 3);
    for (auto _ : state) {
        mhb::StudyWriter merged(scratch("merged"), text, "benchmark\n", study.parameter_columns, true,
                                study.algorithm_infos(), mhb::study_run_keys(study));
        for (std::size_t i = 0; i < shards.size(); ++i) {
            const fs::path dir = scratch("shard" + std::to_string(i));
            mhb::StudyWriter writer(dir, text, "benchmark\n", study.parameter_columns, true,
                                    study.algorithm_infos(), mhb::study_run_keys(study));
            mhb::RunnerOptions options;
            options.threads = 1;
            options.run_ids = shards[i];
            (void)mhb::run_study(study, writer, options);
            for (const auto& record : mhb::load_study(dir).runs)
                merged.append(record, 0.0);
        }
        merged.finish();
    }
    per_run(state);
    for (const auto* name : {"merged", "shard0", "shard1", "shard2"})
        fs::remove_all(scratch(name));
}
BENCHMARK(BM_ShardsMerged)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Rerender(benchmark::State& state) {
    const mhb::PreparedStudy& study = tiny_study();
    const fs::path dir = scratch("rerender");
    const std::string text = mhb::study_ini(study.study);
    {
        mhb::StudyWriter writer(dir, text, "benchmark\n", study.parameter_columns, true,
                                study.algorithm_infos(), mhb::study_run_keys(study));
        (void)mhb::run_study(study, writer);
    }
    mhb::RunnerOptions options;
    options.threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        mhb::StudyWriter writer(dir, text, "benchmark\n", study.parameter_columns, false,
                                study.algorithm_infos(), mhb::study_run_keys(study));
        benchmark::DoNotOptimize(mhb::run_study(study, writer, options).resumed);
    }
    per_run(state);
    fs::remove_all(dir);
}
BENCHMARK(BM_Rerender)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
