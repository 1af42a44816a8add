// Every registered optimiser on the small problem set (sphere, shifted Rastrigin, the PMSM
// steady-state problem), run as a real study by the parallel runner: each run spends the
// evaluation budget exactly, no run fails, and the study's records are byte-identical for one and
// two threads.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

#include "algorithms/algorithm_registry.hpp"
#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

using mhb::test_support::read_text;

Study every_optimizer_study() {
    Study study;
    for (const auto& entry : builtin_algorithms().entries())
        study.algorithms.push_back(entry.name != "external"
                                       ? entry.name
                                       : "external:cmd='/usr/bin/python3 " + std::string(MHB_SOURCE_DIR) +
                                             "/scripts/external/one_plus_one_es.py'");
    study.problems = {"sphere:dim=5", "rastrigin:dim=5,shift=1,instance=11", "pmsm:speed=2500,load=2"};
    study.runs = 2;
    study.seed = 7;
    study.budgets.front().max_evaluations = 700;
    return study;
}

fs::path run_with_threads(const PreparedStudy& prepared, int threads) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_every_optimizer_" + std::to_string(::getpid()) +
                                                      "_" + std::to_string(threads));
    fs::remove_all(dir);
    StudyWriter writer(dir, study_ini(prepared.study), "", prepared.parameter_columns, false);
    RunnerOptions options;
    options.threads = threads;
    const RunnerOutcome outcome = run_study(prepared, writer, options);
    EXPECT_FALSE(outcome.interrupted);
    EXPECT_EQ(outcome.kept, prepared.run_count());
    return dir;
}

TEST(EveryOptimizerStudy, ExactBudgetsNoFailuresAndTheSameBytesForOneAndTwoThreads) {
    const PreparedStudy prepared = prepare_study(every_optimizer_study());
    const fs::path one = run_with_threads(prepared, 1);
    const fs::path two = run_with_threads(prepared, 2);

    const StudyData data = load_study(one);
    ASSERT_EQ(static_cast<std::int64_t>(data.runs.size()), prepared.run_count());
    for (const RunRecord& r : data.runs) {
        const std::string where = r.algorithm + " on " + r.problem;
        EXPECT_TRUE(r.ok) << where << ": " << r.message;
        EXPECT_EQ(r.evaluations, 700) << where;
        ASSERT_TRUE(r.error().has_value()) << where; // every problem here has a known optimum
        EXPECT_GE(*r.error(), -1e-12 * std::max(1.0, std::abs(*r.f_opt))) << where;
    }
    for (const char* file : {"runs.csv", "curves.csv", "checkpoints.csv", "trajectories.csv"})
        EXPECT_EQ(read_text(one / file), read_text(two / file)) << file;
    fs::remove_all(one);
    fs::remove_all(two);
}

} // namespace
} // namespace mhb
