// Random search: exact evaluation accounting, samples uniform inside the box, reproducible from
// the seed, and the expected accuracy on a sphere.
#include <cmath>
#include <gtest/gtest.h>

#include "algorithms/algorithm_registry.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"
#include "support/budgets.hpp"

namespace mhb {
namespace {

using mhb::test_support::evaluations;

// Records every point it is asked about (single-threaded test use only).
class RecordingBox final : public Problem {
public:
    RecordingBox() : box_{Eigen::Vector2d(-1.0, 2.0), Eigen::Vector2d(1.0, 6.0)} {}
    std::string name() const override { return "recording"; }
    Eigen::Index dimension() const override { return 2; }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        seen.push_back(x);
        return x.squaredNorm();
    }
    mutable std::vector<Eigen::VectorXd> seen;

private:
    Box box_;
};

std::unique_ptr<Objective> run_random_search(const Optimizer& optimizer, const Problem& problem,
                                             Budget budget, std::uint64_t seed) {
    auto objective = std::make_unique<Objective>(problem, budget, optimizer.bound_policy());
    Rng rng(seed);
    run_to_budget(optimizer, *objective, rng);
    return objective;
}

TEST(RandomSearch, SpendsBatchPerIterationPlusOneBatchToStart) {
    const auto optimizer = builtin_algorithms().create("random-search:batch=7");
    RecordingBox problem;
    Budget budget;
    budget.max_iterations = 10;
    const auto objective = run_random_search(*optimizer, problem, budget, 1);
    EXPECT_EQ(objective->evaluations(), 7 + 10 * 7);
    ASSERT_EQ(objective->iteration_trace().size(), 11u); // iteration 0 (initial batch) to 10
    for (std::size_t i = 0; i < objective->iteration_trace().size(); ++i)
        EXPECT_EQ(objective->iteration_trace()[i].evaluations, 7 * static_cast<std::int64_t>(i + 1));
    // An evaluation budget that ends mid-batch is spent exactly.
    EXPECT_EQ(run_random_search(*optimizer, problem, evaluations(30), 1)->evaluations(), 30);
}

TEST(RandomSearch, SamplesUniformlyInsideTheBoxAndIsReproducible) {
    const auto optimizer = builtin_algorithms().create("random-search");
    EXPECT_EQ(optimizer->name(), "random-search");
    RecordingBox problem;
    const auto objective = run_random_search(*optimizer, problem, evaluations(20000), 99);
    ASSERT_EQ(problem.seen.size(), 20000u);
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& x : problem.seen) {
        EXPECT_TRUE(problem.bounds().contains(x));
        mean += x;
    }
    mean /= 20000.0;
    // Uniform on [-1, 1] x [2, 6]: means 0 and 4, standard errors 0.577/141 = 0.004 and
    // 1.155/141 = 0.008; 0.03 and 0.06 are more than 7 standard errors.
    EXPECT_NEAR(mean[0], 0.0, 0.03);
    EXPECT_NEAR(mean[1], 4.0, 0.06);
    // The best point is the best of what was sampled: nothing is invented.
    double best = INFINITY;
    for (const auto& x : problem.seen)
        best = std::min(best, x.squaredNorm());
    EXPECT_EQ(objective->best_f(), best);

    // Same seed, same samples.
    RecordingBox again;
    const auto repeated = run_random_search(*optimizer, again, evaluations(20000), 99);
    EXPECT_EQ(again.seen, problem.seen);
    EXPECT_EQ(repeated->best_f(), objective->best_f());
}

TEST(RandomSearch, ReachesTheExpectedAccuracyOnATwoDimensionalSphere) {
    // For N uniform points in [-1, 1]^2, P(min |x|^2 > r) = (1 - pi r / 4)^N, so E[min] is about
    // 4 / (pi N) = 1.3e-4 for N = 10000, and min > 2e-3 has probability exp(-15.7).
    const auto problem = builtin_problems().create("sphere:dim=2,bound=1");
    const auto optimizer = builtin_algorithms().create("random-search:batch=100");
    const auto objective = run_random_search(*optimizer, *problem, evaluations(10000), 2024);
    EXPECT_LT(objective->best_f(), 2e-3);
    EXPECT_GT(objective->best_f(), 0.0);
}

TEST(RandomSearch, RejectsABatchOutsideItsRange) {
    EXPECT_THROW((void)builtin_algorithms().create("random-search:batch=0"), std::invalid_argument);
    EXPECT_THROW((void)builtin_algorithms().create("random-search:batch=2.5"), std::invalid_argument);
}

} // namespace
} // namespace mhb
