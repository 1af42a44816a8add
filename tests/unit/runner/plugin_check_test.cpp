// plugin-check must pass what is fit for a study and catch each way a user's optimiser or problem
// can be unfit: its own random numbers, state shared between runs, points outside the box, a
// problem with hidden state, NaN, or values below the optimum it declares.
#include <atomic>
#include <gtest/gtest.h>
#include <random>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"
#include "problems/problem_registry.hpp"
#include "runner/plugins/plugin_check.hpp"

namespace mhb {
namespace {

PluginCheckOptions small() {
    PluginCheckOptions options;
    options.evaluations = 300;
    options.runs = 3;
    options.points = 200;
    return options;
}

const CheckResult& find(const std::vector<CheckResult>& results, const std::string& name) {
    for (const auto& r : results)
        if (r.name == name)
            return r;
    throw std::logic_error("no check " + name);
}

std::vector<CheckResult> check(const Optimizer& optimizer, const std::string& problem_spec = "sphere:dim=3") {
    const auto problem = builtin_problems().create(problem_spec);
    return check_optimizer(optimizer, optimizer.name(), *problem, problem_spec, small());
}

TEST(PluginCheck, BuiltInOptimizersAndProblemsPass) {
    for (const char* algorithm : {"pso", "itlbo", "lshade", "random-search"}) {
        const auto optimizer = builtin_algorithms().create(algorithm);
        for (const auto& r : check(*optimizer))
            EXPECT_EQ(r.verdict, CheckVerdict::pass) << algorithm << ": " << r.name << ": " << r.detail;
    }
    for (const char* problem : {"pmsm", "bbob:f=3,dim=5", "cec2017:f=9,dim=10"}) {
        const auto p = builtin_problems().create(problem);
        for (const auto& r : check_problem(*p, small()))
            EXPECT_EQ(r.verdict, CheckVerdict::pass) << problem << ": " << r.name << ": " << r.detail;
    }
}

// Random points drawn from a generator of its own, not from the run's stream.
class OwnRandomNumbers final : public Optimizer {
public:
    std::string name() const override { return "own-random"; }
    void run(Objective& objective, Rng&) const override {
        thread_local std::mt19937_64 engine(std::random_device{}());
        while (!objective.exhausted()) {
            Eigen::VectorXd x(objective.dimension());
            for (Eigen::Index k = 0; k < x.size(); ++k)
                x[k] = std::uniform_real_distribution<double>(objective.bounds().lower[k],
                                                              objective.bounds().upper[k])(engine);
            objective.evaluate(x);
        }
    }
};

TEST(PluginCheck, AnOptimizerWithItsOwnRandomNumbersFailsTheSameSeedCheck) {
    const auto results = check(OwnRandomNumbers());
    EXPECT_EQ(find(results, "same seed").verdict, CheckVerdict::fail) << find(results, "same seed").detail;
    EXPECT_EQ(find(results, "budget").verdict, CheckVerdict::pass);
}

// Each run starts where the previous one stopped: state shared between runs.
class SharedState final : public Optimizer {
public:
    std::string name() const override { return "shared-state"; }
    void run(Objective& objective, Rng& rng) const override {
        const double shift = 0.01 * static_cast<double>(calls_++ % 7);
        while (!objective.exhausted()) {
            Eigen::VectorXd x = uniform_point(objective.bounds(), rng);
            x[0] = std::min(x[0] + shift, objective.bounds().upper[0]);
            objective.evaluate(x);
        }
    }

private:
    mutable std::atomic<int> calls_{0};
};

TEST(PluginCheck, AnOptimizerWithStateSharedBetweenRunsFails) {
    const auto results = check(SharedState());
    EXPECT_TRUE(find(results, "same seed").verdict == CheckVerdict::fail ||
                find(results, "threads").verdict == CheckVerdict::fail);
}

// Declares that it keeps to the box itself (no repair), and does not.
class LeavesTheBox final : public Optimizer {
public:
    std::string name() const override { return "leaves-the-box"; }
    BoundPolicy bound_policy() const override { return BoundPolicy::none; }
    void run(Objective& objective, Rng& rng) const override {
        while (!objective.exhausted()) {
            Eigen::VectorXd x = uniform_point(objective.bounds(), rng) * 1.5;
            objective.evaluate(x);
        }
    }
};

TEST(PluginCheck, PointsOutsideTheBoxFailTheBoundsCheck) {
    const auto results = check(LeavesTheBox());
    const auto& bounds = find(results, "bounds");
    EXPECT_EQ(bounds.verdict, CheckVerdict::fail);
    EXPECT_NE(bounds.detail.find("is outside [-100, 100]"), std::string::npos) << bounds.detail;
}

// Stops after a tenth of its budget: allowed, and said.
class StopsEarly final : public Optimizer {
public:
    std::string name() const override { return "stops-early"; }
    void run(Objective& objective, Rng& rng) const override {
        for (int i = 0; i < 30; ++i) {
            Eigen::VectorXd x = uniform_point(objective.bounds(), rng);
            objective.evaluate(x);
        }
    }
};

TEST(PluginCheck, AnOptimizerThatStopsEarlyIsAWarning) {
    const auto results = check(StopsEarly());
    const auto& budget = find(results, "budget");
    EXPECT_EQ(budget.verdict, CheckVerdict::warn);
    EXPECT_NE(budget.detail.find("stopped after 30 of 300 evaluations"), std::string::npos) << budget.detail;
}

// A sphere with a defect chosen by the test.
class FaultyProblem final : public Problem {
public:
    enum class Fault { counts_calls, nan_somewhere, below_optimum };
    explicit FaultyProblem(Fault fault) : fault_(fault) {}
    std::string name() const override { return "faulty"; }
    Eigen::Index dimension() const override { return 2; }
    const Box& bounds() const override { return box_; }
    std::optional<KnownOptimum> known_optimum() const override {
        return KnownOptimum{0.0, Eigen::Vector2d(0.0, 0.0)};
    }
    double evaluate(const Eigen::VectorXd& x) const override {
        const double f = x.squaredNorm();
        switch (fault_) {
        case Fault::counts_calls:
            return f + 1e-12 * static_cast<double>(calls_++); // drifts with every call
        case Fault::nan_somewhere:
            return x[0] > 4 ? std::numeric_limits<double>::quiet_NaN() : f;
        case Fault::below_optimum:
            return f - 1.0;
        }
        return f;
    }

private:
    Fault fault_;
    Box box_{Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5)};
    mutable std::atomic<long> calls_{0};
};

TEST(PluginCheck, ProblemsWithHiddenStateNanOrValuesBelowTheOptimumFail) {
    using Fault = FaultyProblem::Fault;
    EXPECT_EQ(find(check_problem(FaultyProblem(Fault::counts_calls), small()), "same point").verdict,
              CheckVerdict::fail);
    const auto nan = check_problem(FaultyProblem(Fault::nan_somewhere), small());
    const auto& values = find(nan, "values");
    EXPECT_EQ(values.verdict, CheckVerdict::fail);
    EXPECT_NE(values.detail.find("f = nan"), std::string::npos) << values.detail;
    const auto below = check_problem(FaultyProblem(Fault::below_optimum), small());
    EXPECT_EQ(find(below, "optimum").verdict, CheckVerdict::fail) << find(below, "optimum").detail;
}

} // namespace
} // namespace mhb
