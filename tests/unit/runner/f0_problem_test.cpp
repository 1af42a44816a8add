// f0, the structural-bias test function (problems/functions/f0.cpp): a fresh U(0, 1) value at each
// evaluation from a per-run instance (Problem::for_run, ARCHITECTURE.md section 4.1), so that a run
// is reproducible from its seed, two runs differ, and the thread count changes no record.
#include <filesystem>
#include <gtest/gtest.h>

#include "problems/core/rng.hpp"
#include "problems/problem_registry.hpp"
#include "results/store/study_writer.hpp"
#include "runner/execution/parallel_runner.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/study.hpp"
#include "runner/study/study_file.hpp"
#include "support/files.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

std::vector<double> values_of(const Problem& problem, int count) {
    const Eigen::VectorXd x = Eigen::VectorXd::Constant(problem.dimension(), 0.5);
    std::vector<double> values;
    for (int i = 0; i < count; ++i)
        values.push_back(problem.evaluate(x));
    return values;
}

TEST(F0Problem, EachRunDrawsItsOwnReproducibleStream) {
    const auto shared = builtin_problems().create("f0:dim=4");
    EXPECT_EQ(shared->bounds().lower, Eigen::VectorXd::Zero(4));
    EXPECT_EQ(shared->bounds().upper, Eigen::VectorXd::Ones(4));
    EXPECT_FALSE(shared->known_optimum().has_value());
    const auto run = shared->for_run(42);
    ASSERT_NE(run, nullptr);
    EXPECT_FALSE(run->parallel_evaluation());
    EXPECT_FALSE(run->batch_evaluation());
    const std::vector<double> first = values_of(*run, 50);
    // The same point gives a fresh value each time, every one in [0, 1).
    EXPECT_NE(first[0], first[1]);
    for (double v : first)
        EXPECT_TRUE(v >= 0.0 && v < 1.0) << v;
    EXPECT_EQ(values_of(*shared->for_run(42), 50), first); // same seed, same values
    EXPECT_NE(values_of(*shared->for_run(43), 50), first); // another run, other values
    // Not the optimiser's stream, nor its jumped copy.
    Rng optimiser(42);
    Rng jumped = optimiser.jumped();
    EXPECT_NE(optimiser.uniform(), first[0]);
    EXPECT_NE(jumped.uniform(), first[0]);
    // Other problems serve every run from one instance.
    EXPECT_EQ(builtin_problems().create("sphere:dim=2")->for_run(42), nullptr);
}

PreparedStudy f0_study() {
    Study s;
    s.algorithms = {"random-search:batch=5", "pso:np=6"};
    s.problems = {"f0:dim=3"};
    s.runs = 4;
    s.seed = 3;
    s.budgets.front().max_evaluations = 60;
    return prepare_study(s);
}

TEST(F0Problem, RunsAreReproducibleAndDiffer) {
    const PreparedStudy study = f0_study();
    const RunRecord a = execute_run(study.request(0));
    const RunRecord again = execute_run(study.request(0));
    const RunRecord b = execute_run(study.request(1));
    ASSERT_TRUE(a.ok && b.ok) << a.message << b.message;
    EXPECT_EQ(a.best_f, again.best_f);
    EXPECT_EQ(a.best_x, again.best_x);
    EXPECT_EQ(a.evaluations, 60);
    EXPECT_NE(a.best_f, b.best_f);
    EXPECT_NE(a.best_x, b.best_x);
}

fs::path run_with_threads(const PreparedStudy& study, int threads) {
    const fs::path dir = fs::temp_directory_path() / ("mhb_f0_threads_" + std::to_string(threads));
    fs::remove_all(dir);
    StudyWriter writer(dir, study_ini(study.study), "threads = test\n", study.parameter_columns, false);
    RunnerOptions options;
    options.threads = threads;
    (void)run_study(study, writer, options);
    return dir;
}

TEST(F0Problem, OneThreadAndTwoGiveTheSameRecords) {
    const PreparedStudy study = f0_study();
    const fs::path one = run_with_threads(study, 1);
    const fs::path two = run_with_threads(study, 2);
    for (const char* file : {"runs.csv", "improvements.csv", "curves.csv"})
        EXPECT_EQ(test_support::read_text(one / file), test_support::read_text(two / file)) << file;
    fs::remove_all(one);
    fs::remove_all(two);
}

} // namespace
} // namespace mhb
