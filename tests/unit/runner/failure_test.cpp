// Non-finite values and failing components, defined once for all: +inf is a legal (worst) value;
// NaN, or -inf below a finite known minimum, fails the run with a message naming the evaluation
// and the point; a problem that throws from any method the runner calls fails its own run, and
// the study goes on.
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>

#include "problems/objective.hpp"
#include "runner/run/execute_run.hpp"
#include "runner/study/study.hpp"
#include "support/numbers.hpp"
#include "tests/unit/runner/test_problem.hpp"

namespace mhb {
namespace {

using mhb::test_support::inf;

// A problem whose every method can be made to throw.
class ThrowingProblem final : public Problem {
public:
    explicit ThrowingProblem(std::string where) : where_(std::move(where)) {}
    std::string name() const override { return "thrower"; }
    Eigen::Index dimension() const override { return 2; }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        fail("evaluate");
        return x.squaredNorm();
    }
    std::optional<KnownOptimum> known_optimum() const override {
        fail("known_optimum");
        return KnownOptimum{0.0, std::nullopt};
    }
    std::vector<std::string> parameter_names() const override {
        fail("parameter_names");
        return {};
    }
    std::optional<Eigen::VectorXd> true_parameters() const override {
        fail("true_parameters");
        return std::nullopt;
    }

private:
    void fail(const char* method) const {
        if (where_ == method)
            throw std::runtime_error(std::string("thrower: ") + method + " failed");
    }
    std::string where_;
    Box box_{Eigen::VectorXd::Constant(2, -1.0), Eigen::VectorXd::Ones(2)};
};

RunRecord run_on(const Problem& problem, const char* algorithm = "random-search") {
    const auto optimizer = builtin_algorithms().create(algorithm);
    RunRequest request;
    request.optimizer = optimizer.get();
    request.problem = &problem;
    request.algorithm_spec = algorithm;
    request.problem_spec = problem.name();
    request.seed = 3;
    request.budget.max_evaluations = 50;
    request.budget_text = "evaluations=50";
    return execute_run(request);
}

TEST(NonFiniteValues, PlusInfinityIsALegalWorstValue) {
    // +inf on half of the box: the run goes on and finds the finite half.
    const test::TestProblem p(2, [](const Eigen::VectorXd& x) { return x[0] > 0.5 ? inf : x.squaredNorm(); });
    const RunRecord r = run_on(p);
    EXPECT_TRUE(r.ok) << r.message;
    EXPECT_LT(r.best_f, inf);
    // Everywhere +inf: still a run, whose best is +inf.
    const test::TestProblem all(2, [](const Eigen::VectorXd&) { return inf; });
    const RunRecord worst = run_on(all);
    EXPECT_TRUE(worst.ok) << worst.message;
    EXPECT_EQ(worst.best_f, inf);
    EXPECT_EQ(worst.evaluations, 50);
}

TEST(NonFiniteValues, NanOrMinusInfinityBelowAFiniteMinimumFailsTheRunNamingEvaluationAndPoint) {
    const test::TestProblem nan(2, [](const Eigen::VectorXd&) { return std::nan(""); });
    const RunRecord r = run_on(nan);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.message.rfind("problem 'test' returned NaN at evaluation 1, x = (", 0), 0u) << r.message;
    EXPECT_TRUE(r.curve.empty());

    const test::TestProblem minus(
        2, [](const Eigen::VectorXd& x) { return x[0] > 0.9 ? -inf : 1.0; }, {},
        KnownOptimum{0.0, std::nullopt});
    const RunRecord m = run_on(minus);
    EXPECT_FALSE(m.ok);
    EXPECT_NE(m.message.find("returned -inf at evaluation "), std::string::npos) << m.message;
    // Without a known finite minimum, -inf is the best value there is.
    const test::TestProblem unbounded(2, [](const Eigen::VectorXd& x) { return x[0] > 0.9 ? -inf : 1.0; });
    const RunRecord u = run_on(unbounded);
    EXPECT_TRUE(u.ok) << u.message;
    EXPECT_EQ(u.best_f, -inf);

    // The point is named in full for small dimensions, and cut short for large ones.
    const test::TestProblem wide(9, [](const Eigen::VectorXd&) { return std::nan(""); });
    EXPECT_NE(run_on(wide).message.find(", ... 3 more)"), std::string::npos) << run_on(wide).message;
}

TEST(FailingComponents, AProblemThrowingFromAnyMethodFailsOnlyItsRun) {
    for (const char* method : {"evaluate", "known_optimum", "parameter_names", "true_parameters"}) {
        const ThrowingProblem p(method);
        RunRecord r;
        EXPECT_NO_THROW(r = run_on(p)) << method;
        EXPECT_FALSE(r.ok) << method;
        EXPECT_EQ(r.message, std::string("thrower: ") + method + " failed");
    }
    const ThrowingProblem fine("nowhere");
    EXPECT_TRUE(run_on(fine).ok);
}

} // namespace
} // namespace mhb
