// Bad configuration is a clear error naming the component, the parameter and the rule; an error
// inside the objective comes out of every optimiser with its own message (NLopt's C++ wrapper would
// otherwise turn it into a bare "nlopt failure").
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

#include "algorithms/algorithm_registry.hpp"
#include "baselines_test_problems.hpp"
#include "problems/core/spec.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

// The message of the std::invalid_argument that `f` throws ("" if it throws nothing).
template <class F> std::string invalid_argument_message(F&& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

std::string creation_error(const std::string& spec) {
    return invalid_argument_message([&] { (void)builtin_algorithms().create(spec); });
}

TEST(BaselinesErrors, BadParametersNameTheParameterAndTheRule) {
    EXPECT_EQ(creation_error("lshade:n_min=3"), "lshade: parameter 'n_min' = 3 is outside [4, 1000000]");
    EXPECT_EQ(creation_error("de:np=3"),
              "de: parameter 'np' = 3 is too small: DE/rand/1 needs the target and three other members "
              "(0 or at least 4)");
    EXPECT_EQ(creation_error("de:F=0"), "de: parameter 'F' = 0 is outside (0, 2]");
    EXPECT_EQ(creation_error("cmaes:lambda=1").rfind("cmaes: parameter 'lambda' = 1 is too small", 0), 0u);
    EXPECT_EQ(creation_error("etlbo:np=4,elite=4"),
              "etlbo: parameter 'elite' = 4 must be smaller than 'np' = 4");
    EXPECT_EQ(creation_error("spso2011:K=0"), "spso2011: parameter 'K' = 0 is outside [1, 1000]");
    EXPECT_EQ(creation_error("jaya:np=1"), "jaya: parameter 'np' = 1 is outside [2, 1000000]");
}

TEST(BaselinesErrors, UnknownNloptAlgorithmListsTheKnownOnes) {
    const std::string message = creation_error("nlopt:algorithm=GN_FOO");
    EXPECT_EQ(message.rfind("nlopt: parameter 'algorithm' = GN_FOO is not one of {", 0), 0u) << message;
    EXPECT_NE(message.find("GN_CRS2_LM"), std::string::npos);
    EXPECT_NE(message.find("LN_BOBYQA"), std::string::npos);
    // Gradient-based algorithms are not offered: every evaluation must go through the Objective.
    EXPECT_FALSE(creation_error("nlopt:algorithm=LD_LBFGS").empty());
    EXPECT_EQ(
        creation_error("nlopt:algorithm=LN_SBPLX,local=LN_BOBYQA"),
        "nlopt: parameter 'local' = LN_BOBYQA only applies to GN_MLSL and GN_MLSL_LDS, not to LN_SBPLX");
}

TEST(BaselinesErrors, LshadeRejectsAnInitialPopulationSmallerThanNmin) {
    const auto optimizer = builtin_algorithms().create("lshade:r_ninit=1");
    const auto problem = builtin_problems().create("sphere:dim=2");
    Objective objective(*problem, Budget{100, std::nullopt, std::nullopt});
    Rng rng(1);
    EXPECT_EQ(invalid_argument_message([&] { run_to_budget(*optimizer, objective, rng); }),
              "lshade: initial population round(r_ninit * D) = 2 at D = 2 is smaller than n_min = 4; raise "
              "'r_ninit' (the population is too small)");
    EXPECT_EQ(objective.evaluations(), 0);
    // The same line before any run, as a study asks it (Optimizer::refusal), and none at D = 10.
    EXPECT_EQ(optimizer->refusal(2).value_or(""),
              invalid_argument_message([&] { run_to_budget(*optimizer, objective, rng); }));
    EXPECT_FALSE(optimizer->refusal(10).has_value());
}

TEST(BaselinesErrors, EveryPopulationTooLargeForMemoryIsRefusedBeforeARun) {
    // At D = 10^6, populations of 10^5 points and more need petabytes; their defaults at D = 10 fit.
    for (const char* spec :
         {"pso:np=100000", "tlbo:np=100000", "itlbo:np=100000", "etlbo:np=1000000", "jaya:np=1000000",
          "de:np=1000000", "lshade:r_ninit=1e4", "jso:r_ninit=1e4", "lshade-cnepsin:r_ninit=1e4",
          "nl-shade-lbc:r_ninit=1e4", "spso2011:S=1000000", "cmaes:lambda=1000000"}) {
        const auto huge = builtin_algorithms().create(spec);
        const std::string name = Spec::parse(spec).name;
        const auto why = huge->refusal(1000000);
        ASSERT_TRUE(why.has_value()) << spec;
        EXPECT_EQ(why->rfind(name + ": its population at D = 1000000 needs ", 0), 0U) << *why;
        EXPECT_NE(why->find("more than this machine's"), std::string::npos) << *why;
        EXPECT_FALSE(builtin_algorithms().create(name)->refusal(10).has_value()) << name;
    }
}

// A problem that fails on part of its box, as a data-driven problem may (message kept verbatim).
class FailingProblem final : public Problem {
public:
    FailingProblem() : box_{Eigen::VectorXd::Constant(3, -1.0), Eigen::VectorXd::Constant(3, 1.0)} {}
    std::string name() const override { return "failing"; }
    Eigen::Index dimension() const override { return 3; }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        if (x[0] > 0.5)
            throw std::runtime_error("failing: simulated data error at x0 = " + std::to_string(x[0]));
        return x.squaredNorm();
    }

private:
    Box box_;
};

TEST(BaselinesErrors, AnExceptionInsideTheObjectiveComesOutWithItsMessage) {
    const FailingProblem problem;
    for (const auto& spec : test::baseline_specs()) {
        const auto optimizer = builtin_algorithms().create(spec);
        Objective objective(problem, Budget{5000, std::nullopt, std::nullopt}, optimizer->bound_policy());
        Rng rng(3);
        try {
            run_to_budget(*optimizer, objective, rng);
            ADD_FAILURE() << spec << " did not report the error";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()).rfind("failing: simulated data error at x0 = ", 0), 0u)
                << spec << ": " << e.what();
        }
        EXPECT_LT(objective.evaluations(), 5000) << spec;
    }
}

} // namespace
} // namespace mhb
