// How long `mhbench report` takes (without figures) for a study the size of the paper's: 3
// algorithms x 20 runs x 151 iterations on one PMSM problem with 4 named parameters, plus the
// rank-sum test at the paper's 20-vs-20 size (exact null distribution).
#include <benchmark/benchmark.h>
#include <filesystem>
#include <sstream>

#include "results/analysis/hypothesis_tests.hpp"
#include "results/report/report.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"

namespace {
namespace fs = std::filesystem;

fs::path paper_sized_study() {
    const fs::path dir = fs::temp_directory_path() / "mhb_report_bench_study";
    if (fs::exists(dir / "runs.csv"))
        return dir;
    fs::remove_all(dir);
    mhb::StudyWriter writer(dir, "bench\n", "", {"Rs", "Ld", "Lq", "psi"}, false);
    const char* algorithms[] = {"itlbo", "tlbo", "pso"};
    std::int64_t id = 0;
    for (int a = 0; a < 3; ++a)
        for (int i = 0; i < 20; ++i, ++id) {
            mhb::RunRecord r;
            r.run_id = id;
            r.algorithm = algorithms[a];
            r.problem = "pmsm:load=2,speed=2500";
            r.run_index = i;
            r.parameter_names = {"Rs", "Ld", "Lq", "psi"};
            r.true_parameters = {0.33, 0.00324, 0.00324, 0.0776};
            r.x_opt = r.true_parameters;
            r.f_opt = 3.9;
            r.iterations = 150;
            r.evaluations = std::int64_t{50} * 151;
            for (std::int64_t it = 0; it <= 150; ++it) {
                const double f = 3.9 + (1.0 + 0.1 * a + 0.01 * i) * 100.0 / static_cast<double>(it + 1);
                std::vector<double> x = r.true_parameters;
                for (auto& v : x)
                    v *= 1.0 + 1.0 / static_cast<double>(it + 2);
                r.curve.push_back({it, 50 * (it + 1), f, x});
            }
            r.best_f = r.curve.back().best_f;
            r.best_x = r.curve.back().best_x;
            for (std::int64_t e = 1; e <= r.evaluations; e *= 2)
                r.checkpoints.push_back({e, r.curve[static_cast<std::size_t>(e / 50)].best_f});
            writer.append(r, 0.0);
        }
    writer.finish();
    return dir;
}

void BM_LoadStudyAndBuildReport(benchmark::State& state) {
    const fs::path dir = paper_sized_study();
    mhb::ReportOptions options;
    options.figures = false;
    for (auto _ : state) {
        std::ostringstream console;
        mhb::build_report(mhb::load_study(dir), options, console);
        benchmark::DoNotOptimize(console.str().size());
    }
}
BENCHMARK(BM_LoadStudyAndBuildReport)->Unit(benchmark::kMillisecond);

void BM_RankSumExact20x20(benchmark::State& state) {
    std::vector<double> x;
    std::vector<double> y;
    for (int i = 0; i < 20; ++i) {
        x.push_back(1.0 + 0.37 * i);
        y.push_back(1.1 + 0.41 * i);
    }
    for (auto _ : state)
        benchmark::DoNotOptimize(mhb::rank_sum_test(x, y).p_value);
}
BENCHMARK(BM_RankSumExact20x20);

} // namespace
