// The counted Objective: counts, budget stop, trace, bound repair.
#include <gtest/gtest.h>

#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

std::unique_ptr<Problem> sphere(int dim) {
    return builtin_problems().create("sphere:dim=" + std::to_string(dim));
}

TEST(Objective, CountsEveryEvaluationAndKeepsTheBest) {
    const auto p = sphere(2);
    Objective obj(*p, Budget{100, std::nullopt, std::nullopt});
    Eigen::VectorXd a(2), b(2), c(2);
    a << 3, 4;
    b << 1, 0;
    c << 2, 0;
    EXPECT_DOUBLE_EQ(obj.evaluate(a), 25.0);
    EXPECT_DOUBLE_EQ(obj.evaluate(b), 1.0);
    EXPECT_DOUBLE_EQ(obj.evaluate(c), 4.0);
    EXPECT_EQ(obj.evaluations(), 3);
    EXPECT_DOUBLE_EQ(obj.best_f(), 1.0);
    EXPECT_EQ(obj.best_x(), b);
}

TEST(Objective, StopsExactlyAtTheEvaluationBudget) {
    const auto p = sphere(3);
    Objective obj(*p, Budget{5, std::nullopt, std::nullopt});
    Eigen::VectorXd x = Eigen::VectorXd::Ones(3);
    for (int i = 0; i < 5; ++i) {
        EXPECT_FALSE(obj.exhausted());
        obj.evaluate(x);
    }
    EXPECT_TRUE(obj.exhausted());
    EXPECT_THROW(obj.evaluate(x), BudgetExhausted);
    EXPECT_EQ(obj.evaluations(), 5);
    EXPECT_EQ(obj.remaining_evaluations(), 0);
}

TEST(Objective, IterationBudgetAndIterationTrace) {
    const auto p = sphere(1);
    Objective obj(*p, Budget{std::nullopt, 3, std::nullopt});
    Eigen::VectorXd x(1);
    x << 10;
    obj.evaluate(x);
    obj.initialised();
    for (double v : {5.0, 7.0, 2.0}) {
        ASSERT_FALSE(obj.exhausted());
        x << v;
        obj.evaluate(x);
        obj.end_iteration();
    }
    EXPECT_TRUE(obj.exhausted());
    ASSERT_EQ(obj.iteration_trace().size(), 4u);
    const double expected[] = {100, 25, 25, 4};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(obj.iteration_trace()[i].iteration, static_cast<std::int64_t>(i));
        EXPECT_EQ(obj.iteration_trace()[i].evaluations, static_cast<std::int64_t>(i + 1));
        EXPECT_DOUBLE_EQ(obj.iteration_trace()[i].best_f, expected[i]);
    }
}

TEST(Objective, CheckpointsFollowTheSharedLogGridAndEndAtTheLastEvaluation) {
    const auto p = sphere(1);
    Objective obj(*p, Budget{47, std::nullopt, std::nullopt});
    Eigen::VectorXd x(1);
    for (int i = 0; i < 47; ++i) {
        x << 47 - i;
        obj.evaluate(x);
    }
    obj.finish();
    std::vector<std::int64_t> at;
    for (const auto& c : obj.checkpoint_trace())
        at.push_back(c.evaluations);
    const std::vector<std::int64_t> expected = {1, 2, 3, 4, 5, 6, 8, 10, 13, 16, 20, 25, 32, 40, 47};
    EXPECT_EQ(at, expected);
    EXPECT_DOUBLE_EQ(obj.checkpoint_trace()[3].best_f, 44.0 * 44.0);
    EXPECT_EQ(next_checkpoint(100), 126);
    EXPECT_EQ(next_checkpoint(0), 1);
}

TEST(Objective, ClampRepairsInPlace) {
    const auto p = builtin_problems().create("sphere:dim=2,bound=1");
    Objective obj(*p, Budget{10, std::nullopt, std::nullopt}, BoundPolicy::clamp);
    Eigen::VectorXd x(2);
    x << 3, -0.5;
    EXPECT_DOUBLE_EQ(obj.evaluate(x), 1.25);
    EXPECT_DOUBLE_EQ(x[0], 1.0);
    EXPECT_DOUBLE_EQ(x[1], -0.5);
}

TEST(Objective, ReflectMirrorsAtTheViolatedFace) {
    const auto p = builtin_problems().create("sphere:dim=3,bound=1");
    Objective obj(*p, Budget{10, std::nullopt, std::nullopt}, BoundPolicy::reflect);
    Eigen::VectorXd x(3);
    x << 1.25, -1.5, 4.5; // 4.5 folds twice: 4.5 -> -2.5 -> 0.5
    obj.repair(x);
    EXPECT_DOUBLE_EQ(x[0], 0.75);
    EXPECT_DOUBLE_EQ(x[1], -0.5);
    EXPECT_DOUBLE_EQ(x[2], 0.5);
}

TEST(Objective, TargetStopsTheRunAndRecordsTheEvaluationsItTook) {
    const auto p = sphere(1);
    Objective obj(*p, Budget{100, std::nullopt, 1e-8});
    Eigen::VectorXd x(1);
    x << 1;
    obj.evaluate(x);
    x << 1e-5;
    obj.evaluate(x);
    EXPECT_TRUE(obj.exhausted());
    EXPECT_EQ(obj.evaluations_to_target(), 2);
}

TEST(Objective, RejectsABudgetWithoutLimitsAndWrongSizes) {
    const auto p = sphere(2);
    EXPECT_THROW(Objective(*p, Budget{}), std::invalid_argument);
    EXPECT_THROW(Objective(*p, Budget{0, std::nullopt, std::nullopt}), std::invalid_argument);
    Objective obj(*p, Budget{10, std::nullopt, std::nullopt});
    Eigen::VectorXd x(3);
    EXPECT_THROW(obj.evaluate(x), std::logic_error);
}

} // namespace
} // namespace mhb
