// Objective::evaluate_batch against the loop of evaluate() calls it stands for: the same values,
// repairs, counts, best, traces and target, the same exception at the same index, no evaluation
// past the budget, and the same result whatever the number of threads.
#include <atomic>
#include <bit>
#include <chrono>
#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <mutex>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/task_arena.h>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "problems/objective.hpp"

namespace mhb {
namespace {

// f on [-1, 1]^dimension, counting its calls (atomically: they may come from many threads), and
// saying parallel_evaluation() as told.
class CountingProblem final : public Problem {
public:
    using Function = std::function<double(const Eigen::VectorXd&)>;

    CountingProblem(Eigen::Index dimension, bool parallel, Function f = nullptr,
                    std::optional<KnownOptimum> optimum = std::nullopt)
        : box_{Eigen::VectorXd::Constant(dimension, -1.0), Eigen::VectorXd::Ones(dimension)},
          parallel_(parallel), f_(std::move(f)), optimum_(std::move(optimum)) {}

    std::string name() const override { return "counting"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        calls.fetch_add(1);
        return f_ ? f_(x) : x.squaredNorm() + 0.25 * x[0];
    }
    std::optional<KnownOptimum> known_optimum() const override { return optimum_; }
    bool parallel_evaluation() const override { return parallel_; }

    mutable std::atomic<int> calls{0};

private:
    Box box_;
    bool parallel_;
    Function f_;
    std::optional<KnownOptimum> optimum_;
};

// A value no evaluation returns, to see which f a batch left unset.
constexpr double unset = -12345.0;

// What evaluating a list of points left behind: everything a caller can observe.
struct Observed {
    std::vector<Eigen::VectorXd> x;
    std::vector<double> f;
    std::int64_t evaluations = 0;
    double best_f = 0.0;
    Eigen::VectorXd best_x;
    std::optional<std::int64_t> to_target;
    std::vector<CheckpointPoint> checkpoints;
    std::vector<IterationPoint> iterations;
    std::string error; // "" when nothing was thrown; "budget" for BudgetExhausted
};

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void expect_identical(const Observed& a, const Observed& b) {
    EXPECT_EQ(a.error, b.error);
    ASSERT_EQ(a.x.size(), b.x.size());
    for (std::size_t i = 0; i < a.x.size(); ++i) {
        EXPECT_EQ(a.x[i], b.x[i]) << "point " << i;
        EXPECT_TRUE(same_bits(a.f[i], b.f[i])) << "f of point " << i << ": " << a.f[i] << " vs " << b.f[i];
    }
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_TRUE(same_bits(a.best_f, b.best_f));
    EXPECT_EQ(a.best_x, b.best_x);
    EXPECT_EQ(a.to_target, b.to_target);
    ASSERT_EQ(a.checkpoints.size(), b.checkpoints.size());
    for (std::size_t i = 0; i < a.checkpoints.size(); ++i) {
        EXPECT_EQ(a.checkpoints[i].evaluations, b.checkpoints[i].evaluations);
        EXPECT_TRUE(same_bits(a.checkpoints[i].best_f, b.checkpoints[i].best_f));
    }
    ASSERT_EQ(a.iterations.size(), b.iterations.size());
    for (std::size_t i = 0; i < a.iterations.size(); ++i) {
        EXPECT_EQ(a.iterations[i].evaluations, b.iterations[i].evaluations);
        EXPECT_TRUE(same_bits(a.iterations[i].best_f, b.iterations[i].best_f));
        EXPECT_EQ(a.iterations[i].best_x, b.iterations[i].best_x);
    }
}

// Runs `batches` (lists of points) through a fresh Objective, each list by evaluate_batch or by a
// loop of evaluate(), ending an iteration after each list; stops at the first exception.
Observed observe(const Problem& problem, Budget budget,
                 const std::vector<std::vector<Eigen::VectorXd>>& batches, bool batched,
                 BoundPolicy policy = BoundPolicy::clamp) {
    ObjectiveOptions options;
    options.record_best_x = true;
    Objective objective(problem, budget, policy, options);
    Observed out;
    try {
        bool first = true;
        for (const auto& points : batches) {
            const std::size_t offset = out.x.size();
            out.x.insert(out.x.end(), points.begin(), points.end());
            out.f.resize(out.x.size(), unset);
            const std::span<Eigen::VectorXd> x(out.x.data() + offset, points.size());
            const std::span<double> f(out.f.data() + offset, points.size());
            if (batched) {
                objective.evaluate_batch(x, f);
            } else {
                for (std::size_t i = 0; i < x.size(); ++i)
                    f[i] = objective.evaluate(x[i]);
            }
            if (first)
                objective.initialised();
            else
                objective.end_iteration();
            first = false;
        }
    } catch (const BudgetExhausted&) {
        out.error = "budget";
    } catch (const std::exception& e) {
        out.error = e.what();
    }
    objective.finish();
    out.evaluations = objective.evaluations();
    out.best_f = objective.best_f();
    out.best_x = objective.best_x();
    out.to_target = objective.evaluations_to_target();
    out.checkpoints = objective.checkpoint_trace();
    out.iterations = objective.iteration_trace();
    return out;
}

// `n` points of dimension `d`, some outside the box [-1, 1]^d, so that repair acts.
std::vector<Eigen::VectorXd> points(std::size_t n, Eigen::Index d, double phase = 0.0) {
    std::vector<Eigen::VectorXd> out(n, Eigen::VectorXd::Zero(d));
    for (std::size_t i = 0; i < n; ++i)
        for (Eigen::Index k = 0; k < d; ++k)
            out[i][k] = 1.7 * std::sin(0.37 * static_cast<double>(i) + 1.3 * static_cast<double>(k) + phase);
    return out;
}

// The loop and the batch, with a parallel and a sequential problem and 1 and 2 threads: all equal.
void expect_batch_is_the_loop(const std::function<std::unique_ptr<CountingProblem>(bool)>& make,
                              Budget budget, const std::vector<std::vector<Eigen::VectorXd>>& batches,
                              BoundPolicy policy = BoundPolicy::clamp) {
    const auto sequential = make(false);
    const Observed loop = observe(*sequential, budget, batches, false, policy);
    {
        SCOPED_TRACE("parallel_evaluation() false");
        expect_identical(loop, observe(*sequential, budget, batches, true, policy));
    }
    for (const int threads : {1, 2}) {
        SCOPED_TRACE("parallel_evaluation() true, threads " + std::to_string(threads));
        const tbb::global_control cap(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(threads));
        tbb::task_arena arena(threads);
        const auto parallel = make(true);
        arena.execute([&] { expect_identical(loop, observe(*parallel, budget, batches, true, policy)); });
    }
}

TEST(ObjectiveBatch, IsTheLoopOfEvaluateCalls) {
    const auto make = [](bool parallel) { return std::make_unique<CountingProblem>(3, parallel); };
    const std::vector<std::vector<Eigen::VectorXd>> batches = {points(17, 3), points(1, 3, 0.5), points(0, 3),
                                                               points(40, 3, 1.1), points(9, 3, 2.0)};
    expect_batch_is_the_loop(make, Budget{1000, std::nullopt, std::nullopt}, batches);
    expect_batch_is_the_loop(make, Budget{1000, std::nullopt, std::nullopt}, batches, BoundPolicy::reflect);
    expect_batch_is_the_loop(make, Budget{std::nullopt, 100, std::nullopt}, batches, BoundPolicy::none);
}

TEST(ObjectiveBatch, AnIterationBudgetStopsTheNextBatchAsItStopsEvaluate) {
    const auto make = [](bool parallel) { return std::make_unique<CountingProblem>(2, parallel); };
    expect_batch_is_the_loop(make, Budget{std::nullopt, 2, std::nullopt},
                             {points(5, 2), points(5, 2, 1.0), points(5, 2, 2.0), points(5, 2, 3.0)});
}

TEST(ObjectiveBatch, TheBudgetEndsInTheMiddleOfABatchAndNothingPastItIsEvaluated) {
    const auto make = [](bool parallel) { return std::make_unique<CountingProblem>(2, parallel); };
    // 7 + 8 points against a budget of 10: the batch throws at its fourth point.
    expect_batch_is_the_loop(make, Budget{10, std::nullopt, std::nullopt}, {points(7, 2), points(8, 2, 1.0)});

    for (const int threads : {1, 2}) {
        const tbb::global_control cap(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(threads));
        CountingProblem problem(2, true);
        Objective objective(problem, Budget{10, std::nullopt, std::nullopt});
        std::vector<Eigen::VectorXd> first = points(7, 2);
        std::vector<double> f_first(7);
        objective.evaluate_batch(first, f_first);
        ASSERT_EQ(problem.calls.load(), 7);

        std::vector<Eigen::VectorXd> x = points(8, 2, 1.0);
        const std::vector<Eigen::VectorXd> given = x;
        std::vector<double> f(8, unset);
        EXPECT_THROW(objective.evaluate_batch(x, f), BudgetExhausted);
        EXPECT_EQ(problem.calls.load(), 10) << "only the three points within the budget are evaluated";
        EXPECT_EQ(objective.evaluations(), 10);
        for (std::size_t i = 0; i < 8; ++i) {
            if (i < 3) {
                EXPECT_NE(f[i], unset);
            } else {
                EXPECT_EQ(f[i], unset) << "point " << i;
                EXPECT_EQ(x[i], given[i]) << "point " << i << " is left as given";
            }
        }
        // A spent budget: the next batch evaluates nothing.
        EXPECT_THROW(objective.evaluate_batch(x, f), BudgetExhausted);
        EXPECT_EQ(problem.calls.load(), 10);
    }
}

TEST(ObjectiveBatch, NanOrMinusInfinityFailsAtTheSameEvaluationWithTheSameMessage) {
    for (const double bad :
         {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
        const auto make = [bad](bool parallel) {
            return std::make_unique<CountingProblem>(
                2, parallel, [bad](const Eigen::VectorXd& x) { return x[0] == 1.75 ? bad : x.squaredNorm(); },
                KnownOptimum{0.0, std::nullopt});
        };
        std::vector<Eigen::VectorXd> batch = points(12, 2, 0.4);
        batch[6] << 1.75, -0.5; // the bad value, at evaluation 3 + 7
        const auto loop = observe(*make(false), Budget{100, std::nullopt, std::nullopt},
                                  {points(3, 2), batch}, false, BoundPolicy::none);
        EXPECT_NE(loop.error.find("at evaluation 10"), std::string::npos) << loop.error;
        expect_batch_is_the_loop(make, Budget{100, std::nullopt, std::nullopt}, {points(3, 2), batch},
                                 BoundPolicy::none);
    }
}

TEST(ObjectiveBatch, AnExceptionOfTheProblemComesOutAtItsIndex) {
    const auto make = [](bool parallel) {
        return std::make_unique<CountingProblem>(2, parallel, [](const Eigen::VectorXd& x) {
            if (x[0] > 0.9)
                throw std::runtime_error("cannot simulate x0 = " + std::to_string(x[0]));
            return x.squaredNorm();
        });
    };
    std::vector<Eigen::VectorXd> batch = points(10, 2, 2.5);
    for (auto& x : batch)
        x[0] = std::min(x[0], 0.5);
    batch[4][0] = 0.95; // the first to throw
    batch[7][0] = 0.99; // would throw too, later
    expect_batch_is_the_loop(make, Budget{100, std::nullopt, std::nullopt}, {batch});
}

TEST(ObjectiveBatch, AWrongSizeFailsAtItsIndex) {
    const auto make = [](bool parallel) { return std::make_unique<CountingProblem>(3, parallel); };
    std::vector<Eigen::VectorXd> batch = points(9, 3);
    batch[5] = Eigen::VectorXd::Zero(2);
    expect_batch_is_the_loop(make, Budget{100, std::nullopt, std::nullopt}, {batch});

    CountingProblem problem(3, true);
    Objective objective(problem, Budget{100, std::nullopt, std::nullopt});
    std::vector<double> f(9);
    EXPECT_THROW(objective.evaluate_batch(batch, f), std::logic_error);
    EXPECT_EQ(problem.calls.load(), 5) << "no point past the wrong one is evaluated";
    std::vector<double> too_few(8);
    EXPECT_THROW(objective.evaluate_batch(batch, too_few), std::logic_error);
}

TEST(ObjectiveBatch, ATargetReachedInABatchStopsItThere) {
    const auto make = [](bool parallel) {
        return std::make_unique<CountingProblem>(
            2, parallel, [](const Eigen::VectorXd& x) { return x.squaredNorm(); },
            KnownOptimum{0.0, std::nullopt});
    };
    std::vector<Eigen::VectorXd> batch = points(20, 2, 0.8);
    batch[11] << 1e-6, -1e-6;
    const Budget budget{1000, std::nullopt, 1e-9};
    const auto loop = observe(*make(false), budget, {points(4, 2), batch}, false);
    EXPECT_EQ(loop.to_target, 16);
    EXPECT_EQ(loop.error, "budget");
    expect_batch_is_the_loop(make, budget, {points(4, 2), batch});
}

TEST(ObjectiveBatch, CheckpointsAndBestAreTheLoopsOverManyBatches) {
    const auto make = [](bool parallel) { return std::make_unique<CountingProblem>(4, parallel); };
    std::vector<std::vector<Eigen::VectorXd>> batches;
    for (int b = 0; b < 30; ++b)
        batches.push_back(points(static_cast<std::size_t>(1 + (b * 7) % 23), 4, 0.3 * b));
    expect_batch_is_the_loop(make, Budget{300, std::nullopt, std::nullopt}, batches);
}

// With two threads allowed, two evaluations of one batch do run at the same time; with one, never.
TEST(ObjectiveBatch, EvaluatesInParallelWhenTheProblemAsks) {
    std::mutex mutex;
    int running = 0;
    int most = 0;
    std::chrono::milliseconds patience{0};
    // Each evaluation waits until another runs beside it, or for `patience`.
    const auto f = [&](const Eigen::VectorXd& x) {
        const auto deadline = std::chrono::steady_clock::now() + patience;
        {
            const std::lock_guard lock(mutex);
            most = std::max(most, ++running);
        }
        while (std::chrono::steady_clock::now() < deadline) {
            {
                const std::lock_guard lock(mutex);
                if (most > 1)
                    break;
            }
            std::this_thread::yield();
        }
        const std::lock_guard lock(mutex);
        --running;
        return x.squaredNorm();
    };
    for (const int threads : {1, 2}) {
        const tbb::global_control cap(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(threads));
        tbb::task_arena arena(threads);
        most = 0;
        patience = threads == 1 ? std::chrono::milliseconds(5) : std::chrono::milliseconds(10000);
        CountingProblem problem(2, true, f);
        Objective objective(problem, Budget{100, std::nullopt, std::nullopt});
        std::vector<Eigen::VectorXd> x = points(8, 2);
        std::vector<double> values(x.size());
        arena.execute([&] { objective.evaluate_batch(x, values); });
        EXPECT_EQ(most, threads);
        EXPECT_EQ(objective.evaluations(), 8);
    }
}

} // namespace
} // namespace mhb
