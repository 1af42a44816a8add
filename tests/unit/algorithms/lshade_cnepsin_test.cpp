// LSHADE-cnEpSin (algorithms/lshade_cnepsin.cpp): the published defaults as the registry lists them,
// the linear population size reduction against the budget (read from the evaluations each iteration
// charges, which are the population size), exact evaluation accounting under an evaluation and an
// iteration budget, determinism, and that it solves easy functions, with the eigenbasis crossover
// in every generation too. That one and two threads give the same run is in
// batch_equivalence_test.cpp (lshade-cnepsin is one of its batching specs).
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <vector>

#include "baselines_test_problems.hpp"
#include "paper_algorithms_support.hpp"
#include "problems/problem_registry.hpp"

namespace mhb::test {
namespace {

const ParameterInfo& cnepsin_parameter(const std::string& name) {
    for (const auto& p : builtin_algorithms().find("lshade-cnepsin").parameters)
        if (p.name == name)
            return p;
    throw std::out_of_range("lshade-cnepsin has no parameter " + name);
}

TEST(LshadeCnEpSin, ListsThePublishedDefaults) {
    const auto& entry = builtin_algorithms().find("lshade-cnepsin");
    EXPECT_EQ(entry.version, 1);
    EXPECT_NE(entry.reference.find("Awad"), std::string::npos);
    EXPECT_EQ(entry.parameters.size(), 12u);
    EXPECT_DOUBLE_EQ(std::stod(cnepsin_parameter("r_ninit").default_value), 18.0);
    EXPECT_EQ(cnepsin_parameter("n_min").default_value, "4");
    EXPECT_DOUBLE_EQ(std::stod(cnepsin_parameter("r_arc").default_value), 1.4);
    EXPECT_DOUBLE_EQ(std::stod(cnepsin_parameter("p").default_value), 0.11);
    EXPECT_EQ(cnepsin_parameter("H").default_value, "5");
    EXPECT_DOUBLE_EQ(std::stod(cnepsin_parameter("m_f").default_value), 0.5);
    EXPECT_DOUBLE_EQ(std::stod(cnepsin_parameter("m_cr").default_value), 0.5);
    EXPECT_DOUBLE_EQ(std::stod(cnepsin_parameter("freq").default_value), 0.5);
    EXPECT_DOUBLE_EQ(std::stod(cnepsin_parameter("pc").default_value), 0.4);
    EXPECT_DOUBLE_EQ(std::stod(cnepsin_parameter("ps").default_value), 0.5);
    EXPECT_EQ(cnepsin_parameter("LP").default_value, "20");
    EXPECT_EQ(cnepsin_parameter("bounds").default_value, "clamp"); // the code's is none: see the header
    EXPECT_DOUBLE_EQ(cnepsin_parameter("n_min").min, 4.0);         // current-to-pbest/1 needs four
}

TEST(LshadeCnEpSin, InitialPopulationIs18D) {
    for (const auto& [dim, expected] :
         std::vector<std::pair<int, std::int64_t>>{{10, 180}, {30, 540}, {2, 36}}) {
        const auto sphere = builtin_problems().create("sphere:dim=" + std::to_string(dim));
        const Outcome out = run("lshade-cnepsin", *sphere, 1, iterations(1));
        EXPECT_EQ(out.iterations_trace.front().evaluations, expected) << "D = " << dim;
    }
    // round(0.2 * 10) = 2 < N_min: a clear error rather than a crash.
    const auto sphere = builtin_problems().create("sphere:dim=10");
    EXPECT_THROW((void)run("lshade-cnepsin:r_ninit=0.2", *sphere, 1, evaluations(1000)),
                 std::invalid_argument);
}

TEST(LshadeCnEpSin, PopulationFallsLinearlyWithTheEvaluationsToFourAtTheEndOfTheBudget) {
    expect_lpsr_under_an_evaluation_budget("lshade-cnepsin", 180, 4);
}

TEST(LshadeCnEpSin, IterationBudgetDerivesMaxNfeSoThatTheReductionEndsAtTheLastGeneration) {
    expect_lpsr_under_an_iteration_budget("lshade-cnepsin", 180, 5);
}

TEST(LshadeCnEpSin, EvaluationBudgetIsChargedExactlyWhateverItsRemainder) {
    const auto problem = ShiftedRastrigin(6, 3);
    for (const std::int64_t budget : {100, 183, 5003, 12345}) {
        const Outcome out = run("lshade-cnepsin", problem, 2, evaluations(budget));
        EXPECT_EQ(out.evaluations, budget) << budget;
    }
}

TEST(LshadeCnEpSin, SameSeedSameRunOtherSeedOtherRun) {
    const auto problem = RotatedEllipsoid(5, 1e3, 7);
    const Outcome a = run("lshade-cnepsin", problem, 11, evaluations(7001));
    const Outcome b = run("lshade-cnepsin", problem, 11, evaluations(7001));
    const Outcome c = run("lshade-cnepsin", problem, 12, evaluations(7001));
    EXPECT_TRUE(identical(a, b));
    EXPECT_FALSE(identical(a, c));
    EXPECT_NE(a.best_f, c.best_f);
}

TEST(LshadeCnEpSin, SolvesSphereAndARotatedEllipsoidInTenDimensions) {
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const Outcome s = run("lshade-cnepsin", *sphere, 1, Budget{100000, std::nullopt, 1e-8});
    EXPECT_LE(s.best_f, 1e-8);
    EXPECT_LT(s.evaluations, 100000); // the target stopped it before the budget
    for (const std::string spec : {"lshade-cnepsin", "lshade-cnepsin:pc=1", "lshade-cnepsin:pc=0"}) {
        const Outcome e = run(spec, RotatedEllipsoid(10, 1e6, 3), 1, Budget{100000, std::nullopt, 1e-8});
        EXPECT_LE(e.best_f, 1e-8) << spec;
    }
}

} // namespace
} // namespace mhb::test
