// The improvement record: every strict improvement of best-so-far f at the evaluation that made it,
// and the last evaluation's f, checked against a brute-force replay of the values the problem
// returned, through evaluate, evaluate_batch and whole optimiser runs (execute_run).
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <mutex>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/objective.hpp"
#include "runner/run/execute_run.hpp"

namespace mhb {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// f(x) = x[0] with no repair: a test hands the Objective exactly the values it wants.
class ValueProblem final : public Problem {
public:
    explicit ValueProblem(bool parallel = false) : parallel_(parallel) {}
    std::string name() const override { return "value"; }
    Eigen::Index dimension() const override { return 1; }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override { return x[0]; }
    bool parallel_evaluation() const override { return parallel_; }

private:
    bool parallel_;
    Box box_{Eigen::VectorXd::Constant(1, -1e300), Eigen::VectorXd::Constant(1, 1e300)};
};

// A rugged function that keeps every value it returns, in order (runs evaluate serially).
class LoggingProblem final : public Problem {
public:
    explicit LoggingProblem(Eigen::Index dimension)
        : box_{Eigen::VectorXd::Constant(dimension, -5.0), Eigen::VectorXd::Constant(dimension, 5.0)} {}
    std::string name() const override { return "logging"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        double f = 0.0;
        for (Eigen::Index i = 0; i < x.size(); ++i)
            f += x[i] * x[i] - 3.0 * std::cos(5.0 * x[i]);
        const std::lock_guard<std::mutex> lock(mutex_);
        values_.push_back(f);
        return f;
    }
    const std::vector<double>& values() const { return values_; }

private:
    Box box_;
    mutable std::mutex mutex_;
    mutable std::vector<double> values_;
};

struct Replay {
    std::vector<CheckpointPoint> improvements;
    double last_f = std::numeric_limits<double>::quiet_NaN();
};

// The definition, by brute force: evaluation i (1-based) improves when f_i < min(f_1..f_{i-1}).
Replay replay(const std::vector<double>& values) {
    Replay out;
    double best = inf;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (values[i] < best) {
            best = values[i];
            out.improvements.push_back({static_cast<std::int64_t>(i + 1), values[i]});
        }
        out.last_f = values[i];
    }
    return out;
}

void expect_same(const std::vector<CheckpointPoint>& got, const std::vector<CheckpointPoint>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].evaluations, want[i].evaluations) << i;
        EXPECT_EQ(got[i].best_f, want[i].best_f) << i;
    }
}

// Ties, +inf first and later, -inf (legal without a known optimum), a last value that is no
// improvement.
const std::vector<double> scripted = {inf, 5.0,  5.0, 7.0,  3.0, inf,  3.0,
                                      2.5, -0.0, 0.0, -1.0, 4.0, -inf, 8.0};

TEST(TraceRecorder, ImprovementsAreTheStrictDropsOfBestSoFar) {
    const ValueProblem problem;
    Objective objective(problem, Budget{100, std::nullopt, std::nullopt}, BoundPolicy::none);
    for (const double f : scripted) {
        Eigen::VectorXd x = Eigen::VectorXd::Constant(1, f);
        objective.evaluate(x);
    }
    const Replay want = replay(scripted);
    expect_same(objective.recorder().improvements(), want.improvements);
    // The first +inf is no improvement, nor is a tie (5, 3, and 0 after -0): 5, 3, 2.5, -0, -1, -inf.
    ASSERT_EQ(want.improvements.size(), 6u);
    EXPECT_EQ(want.improvements.front().evaluations, 2);
    EXPECT_EQ(objective.recorder().last_f(), 8.0);
}

TEST(TraceRecorder, TheSameThroughEvaluateBatchInParallel) {
    const ValueProblem problem(true);
    Objective objective(problem, Budget{100, std::nullopt, std::nullopt}, BoundPolicy::none);
    std::vector<Eigen::VectorXd> x;
    for (const double f : scripted)
        x.push_back(Eigen::VectorXd::Constant(1, f));
    std::vector<double> f(x.size());
    objective.evaluate_batch(x, f);
    expect_same(objective.recorder().improvements(), replay(scripted).improvements);
    EXPECT_EQ(objective.recorder().last_f(), 8.0);
}

TEST(TraceRecorder, NoEvaluationNoImprovementAndLastFIsNaN) {
    const ValueProblem problem;
    const Objective objective(problem, Budget{10, std::nullopt, std::nullopt}, BoundPolicy::none);
    EXPECT_TRUE(objective.recorder().improvements().empty());
    EXPECT_TRUE(std::isnan(objective.recorder().last_f()));
}

TEST(TraceRecorder, GridAndIterationTraceAreKeptAsBefore) {
    const ValueProblem problem;
    Objective objective(problem, Budget{std::nullopt, 3, std::nullopt}, BoundPolicy::none);
    const std::vector<double> values = {9, 8, 10, 7, 7, 6, 11};
    std::size_t next = 0;
    const auto evaluate = [&](std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            Eigen::VectorXd x = Eigen::VectorXd::Constant(1, values[next++]);
            objective.evaluate(x);
        }
    };
    evaluate(1);
    objective.initialised();
    evaluate(3);
    objective.end_iteration();
    evaluate(3);
    objective.end_iteration();
    objective.finish();
    // Grid 1, 2, 3, 4, 5, 6 and the end (7); iterations after 1, 4 and 7 evaluations.
    ASSERT_EQ(objective.checkpoint_trace().size(), 7u);
    EXPECT_EQ(objective.checkpoint_trace()[5].evaluations, 6);
    EXPECT_EQ(objective.checkpoint_trace()[5].best_f, 6.0);
    EXPECT_EQ(objective.checkpoint_trace()[6].evaluations, 7);
    ASSERT_EQ(objective.iteration_trace().size(), 3u);
    EXPECT_EQ(objective.iteration_trace()[1].evaluations, 4);
    EXPECT_EQ(objective.iteration_trace()[1].best_f, 7.0);
    expect_same(objective.recorder().improvements(), {{1, 9}, {2, 8}, {4, 7}, {6, 6}});
    EXPECT_EQ(objective.recorder().last_f(), 11.0);
}

// Whole runs of real optimisers: the record's improvements are the replay of every value the
// problem returned, and its last f the last of them.
TEST(TraceRecorder, RecordOfAnOptimiserRunEqualsTheReplayOfItsEvaluations) {
    for (const char* spec : {"itlbo", "pso", "de", "cmaes", "nlopt:algorithm=LN_NELDERMEAD"}) {
        const LoggingProblem problem(3);
        const auto optimizer = builtin_algorithms().create(spec);
        RunRequest request;
        request.optimizer = optimizer.get();
        request.problem = &problem;
        request.algorithm_spec = spec;
        request.problem_spec = "logging";
        request.seed = 42;
        request.budget = Budget{1500, std::nullopt, std::nullopt};
        const RunRecord record = execute_run(request);
        ASSERT_TRUE(record.ok) << spec << ": " << record.message;
        ASSERT_TRUE(record.improvements.has_value()) << spec;
        EXPECT_EQ(static_cast<std::size_t>(record.evaluations), problem.values().size()) << spec;
        const Replay want = replay(problem.values());
        const auto& got = record.improvements->points;
        ASSERT_EQ(got.size(), want.improvements.size()) << spec;
        for (std::size_t i = 0; i < got.size(); ++i) {
            EXPECT_EQ(got[i].evaluations, want.improvements[i].evaluations) << spec << ' ' << i;
            EXPECT_EQ(got[i].best_f, want.improvements[i].best_f) << spec << ' ' << i;
        }
        EXPECT_EQ(record.improvements->last_f, want.last_f) << spec;
        EXPECT_EQ(got.back().best_f, record.best_f) << spec;
        EXPECT_GT(got.size(), 3u) << spec; // a real run improves more than a few times
    }
}

TEST(TraceRecorder, AFailedRunHasNoImprovementRecord) {
    class NanProblem final : public Problem {
    public:
        std::string name() const override { return "nan"; }
        Eigen::Index dimension() const override { return 1; }
        const Box& bounds() const override { return box_; }
        double evaluate(const Eigen::VectorXd& x) const override {
            return x[0] > 0.9 ? std::numeric_limits<double>::quiet_NaN() : x[0];
        }

    private:
        Box box_{Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1)};
    };
    const NanProblem problem;
    const auto optimizer = builtin_algorithms().create("random-search");
    RunRequest request;
    request.optimizer = optimizer.get();
    request.problem = &problem;
    request.algorithm_spec = "random-search";
    request.problem_spec = "nan";
    request.seed = 1;
    request.budget = Budget{1000, std::nullopt, std::nullopt};
    const RunRecord record = execute_run(request);
    ASSERT_FALSE(record.ok);
    EXPECT_FALSE(record.improvements.has_value());
}

} // namespace
} // namespace mhb
