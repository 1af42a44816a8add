// The parallel runner: every run done once, results byte-identical for any thread count, and a
// study cancelled after K runs then resumed gives files byte-identical to an uninterrupted one.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

#include "results/store/study_data.hpp"
#include "results/store/study_writer.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "support/files.hpp"
#include "tests/unit/runner/test_problem.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_runner_test_" + name);
    fs::remove_all(dir);
    return dir;
}

using mhb::test_support::read_text;

// 2 problems x 2 algorithms x 4 runs = 16 short runs.
PreparedStudy make_study() {
    Study s;
    s.algorithms = {"random-search:batch=5", "random-search:batch=9"};
    s.problems = {"sphere:dim=2", "sphere:dim=3"};
    s.runs = 4;
    s.seed = 7;
    s.budgets.front().max_iterations = 20;
    s.budgets.front().max_evaluations = 150; // both: the evaluations end the batch=9 runs first
    return prepare_study(s);
}

RunnerOutcome run_with_options_into(const fs::path& dir, const PreparedStudy& study,
                                    const RunnerOptions& options) {
    StudyWriter writer(dir, study_ini(study.study), "threads = test\n", study.parameter_columns, false);
    return run_study(study, writer, options);
}

const char* const deterministic_files[] = {"runs.csv",         "curves.csv",       "checkpoints.csv",
                                           "trajectories.csv", "improvements.csv", "study.ini"};

TEST(ParallelRunner, RunsEveryRunOnceAndFinishesTheStudy) {
    const PreparedStudy study = make_study();
    const fs::path dir = fresh_dir("all");
    RunnerOptions options;
    options.threads = 2;
    std::vector<std::int64_t> progress;
    options.on_run_finished = [&](std::int64_t kept, std::int64_t total, const RunRecord&) {
        EXPECT_EQ(total, 16);
        progress.push_back(kept);
    };
    const RunnerOutcome outcome = run_with_options_into(dir, study, options);
    EXPECT_FALSE(outcome.interrupted);
    EXPECT_EQ(outcome.total, 16);
    EXPECT_EQ(outcome.kept, 16);
    EXPECT_EQ(outcome.resumed, 0);
    // Serialised callbacks: the counts arrive in order, one per run.
    ASSERT_EQ(progress.size(), 16u);
    for (std::size_t i = 0; i < progress.size(); ++i)
        EXPECT_EQ(progress[i], static_cast<std::int64_t>(i + 1));
    const StudyData data = load_study(dir);
    ASSERT_EQ(data.runs.size(), 16u);
    for (std::size_t i = 0; i < data.runs.size(); ++i) {
        const RunRecord& r = data.runs[i];
        EXPECT_EQ(r.run_id, static_cast<std::int64_t>(i));
        EXPECT_TRUE(r.ok) << r.message;
        EXPECT_EQ(r.seed, derive_seed(7, r.problem, static_cast<std::uint64_t>(r.run_index)));
        // The budget is exact: batch=5 reaches 150 evaluations at iteration 29 > 20, so it stops on
        // iterations (5 + 20 * 5 = 105); batch=9 spends exactly 150 evaluations first.
        EXPECT_EQ(r.evaluations, r.algorithm == "random-search:batch=5" ? 105 : 150) << r.algorithm;
    }
}

TEST(ParallelRunner, OutputIsByteIdenticalForOneAndTwoThreads) {
    const PreparedStudy study = make_study();
    const fs::path one = fresh_dir("threads1");
    const fs::path two = fresh_dir("threads2");
    RunnerOptions options;
    options.threads = 1;
    run_with_options_into(one, study, options);
    options.threads = 2;
    run_with_options_into(two, study, options);
    for (const char* name : deterministic_files)
        EXPECT_EQ(read_text(one / name), read_text(two / name)) << name;
}

// A problem whose evaluation is a simulation (the output-error PMSM model) has each run's
// populations evaluated in parallel inside the run when threads are idle (nested oneTBB): with
// one run of each population optimiser and two threads that is what happens, and the records are
// still those of one thread, byte for byte.
TEST(ParallelRunner, NestedPopulationEvaluationGivesTheRecordsOfOneThread) {
    Study s;
    s.algorithms = {"cmaes", "lshade", "pso", "itlbo"};
    s.problems = {"pmsm:model=output,motor=ipm,speed=1800,load=4,n=40,noise_i=0.02"};
    s.runs = 1;
    s.seed = 3;
    s.budgets.front().max_evaluations = 600;
    const PreparedStudy study = prepare_study(s);
    ASSERT_TRUE(study.problems.front().problem->parallel_evaluation());
    const fs::path one = fresh_dir("nested1");
    const fs::path two = fresh_dir("nested2");
    RunnerOptions options;
    options.threads = 1;
    run_with_options_into(one, study, options);
    options.threads = 2;
    run_with_options_into(two, study, options);
    for (const char* name : deterministic_files)
        EXPECT_EQ(read_text(one / name), read_text(two / name)) << name;
}

TEST(ParallelRunner, CancelledAfterKRunsThenResumedMatchesAnUninterruptedStudy) {
    const PreparedStudy study = make_study();
    const fs::path reference = fresh_dir("reference");
    RunnerOptions plain;
    plain.threads = 2;
    run_with_options_into(reference, study, plain);

    const fs::path dir = fresh_dir("resumed");
    std::atomic<bool> stop{false};
    RunnerOptions cancelling;
    cancelling.threads = 1; // one thread: exactly K runs are kept
    cancelling.stop = &stop;
    cancelling.on_run_finished = [&](std::int64_t kept, std::int64_t, const RunRecord&) {
        if (kept == 5)
            stop.store(true);
    };
    const RunnerOutcome first = run_with_options_into(dir, study, cancelling);
    EXPECT_TRUE(first.interrupted);
    EXPECT_EQ(first.kept, 5);
    EXPECT_FALSE(fs::exists(dir / "runs.csv")); // not a finished study
    EXPECT_TRUE(fs::exists(dir / "store.bin"));
    EXPECT_THROW((void)load_study(dir), std::runtime_error);

    const RunnerOutcome second = run_with_options_into(dir, study, plain); // "run the same command again"
    EXPECT_FALSE(second.interrupted);
    EXPECT_EQ(second.resumed, 5);
    EXPECT_EQ(second.kept, 16);
    EXPECT_TRUE(fs::exists(dir / "runs.csv"));
    for (const char* name : deterministic_files)
        EXPECT_EQ(read_text(reference / name), read_text(dir / name)) << name;
}

TEST(ParallelRunner, AStopBeforeTheStartKeepsNothingAndResumesFromScratch) {
    const PreparedStudy study = make_study();
    const fs::path dir = fresh_dir("stopped");
    std::atomic<bool> stop{true};
    RunnerOptions options;
    options.stop = &stop;
    const RunnerOutcome outcome = run_with_options_into(dir, study, options);
    EXPECT_TRUE(outcome.interrupted);
    EXPECT_EQ(outcome.kept, 0);
    EXPECT_FALSE(fs::exists(dir / "runs.csv"));
}

TEST(ParallelRunner, AFailingRunBecomesAFailedRecordAndTheStudyGoesOn) {
    // A problem that returns NaN makes the Objective throw; execute_run turns it into a record.
    const ProblemRegistry problems =
        test::registry_of("nan", [](const ParameterValues&) -> std::unique_ptr<Problem> {
            return std::make_unique<test::TestProblem>(
                1, [](const Eigen::VectorXd& x) { return x[0] > 0.5 ? std::nan("") : x[0]; });
        });
    Study s;
    s.algorithms = {"random-search:batch=3"};
    s.problems = {"nan"};
    s.runs = 3;
    s.budgets.front().max_iterations = 50; // 153 uniform draws: a value above 0.5 is all but certain
    const PreparedStudy study = prepare_study(s, builtin_algorithms(), problems);
    const fs::path dir = fresh_dir("failing");
    const RunnerOutcome outcome = run_with_options_into(dir, study, {});
    EXPECT_FALSE(outcome.interrupted);
    const StudyData data = load_study(dir);
    ASSERT_EQ(data.runs.size(), 3u);
    for (const auto& r : data.runs) {
        EXPECT_FALSE(r.ok);
        EXPECT_NE(r.message.find("returned NaN"), std::string::npos) << r.message;
    }
}

} // namespace
} // namespace mhb
