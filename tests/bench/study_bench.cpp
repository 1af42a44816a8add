// A whole study, end to end: every run of a preset executed by the parallel runner and written
// by the StudyWriter (store.bin, then the sorted files), with 1 and 2 threads. Building the
// problems and optimisers (prepare_study) is done once, outside the timing.
//
//   ./build/release/tests/bench/study_bench                       (the paper's study)
//   MHB_BENCH_STUDY=smoke ./build/release/tests/bench/study_bench (another preset)
//
// Counters: runs/s and evaluations/s of the whole study, so figures for presets of different
// sizes compare.
#include <benchmark/benchmark.h>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "runner/study/study_presets.hpp"

namespace {

// The preset measured by default: the paper's study (3 algorithms x 20 runs on the PMSM problem).
constexpr const char* default_preset = "paper";

std::string preset_name() {
    const char* chosen = std::getenv("MHB_BENCH_STUDY");
    return chosen != nullptr && *chosen != '\0' ? chosen : default_preset;
}

void BM_Study(benchmark::State& state) {
    const std::string name = preset_name();
    const mhb::PreparedStudy study = mhb::prepare_study(mhb::find_study_preset(name).study);
    const auto dir = std::filesystem::temp_directory_path() / ("mhb_study_bench_" + name);
    const std::string study_text = mhb::study_ini(study.study);
    mhb::RunnerOptions options;
    options.threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        mhb::StudyWriter writer(dir, study_text, "benchmark\n", study.parameter_columns, true);
        const mhb::RunnerOutcome outcome = mhb::run_study(study, writer, options);
        benchmark::DoNotOptimize(outcome.kept);
    }
    std::int64_t evaluations = 0;
    for (const auto& r : mhb::load_study(dir).runs)
        evaluations += r.evaluations;
    const auto iterations = static_cast<double>(state.iterations());
    state.counters["runs/s"] =
        benchmark::Counter(static_cast<double>(study.run_count()) * iterations, benchmark::Counter::kIsRate);
    state.counters["evals/s"] =
        benchmark::Counter(static_cast<double>(evaluations) * iterations, benchmark::Counter::kIsRate);
    state.SetLabel(name + ", " + std::to_string(study.run_count()) + " runs");
    std::filesystem::remove_all(dir);
}
BENCHMARK(BM_Study)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
