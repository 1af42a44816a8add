// jSO (algorithms/jso.cpp): the published defaults as the registry lists them, the linear
// population size reduction against the budget (read from the evaluations each iteration charges,
// which are the population size), exact evaluation accounting under an evaluation and an
// iteration budget, determinism, and that it solves easy functions. That one and two threads give
// the same run is in batch_equivalence_test.cpp (jso is one of its batching specs).
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

const ParameterInfo& jso_parameter(const std::string& name) {
    for (const auto& p : builtin_algorithms().find("jso").parameters)
        if (p.name == name)
            return p;
    throw std::out_of_range("jso has no parameter " + name);
}

TEST(Jso, ListsThePublishedDefaults) {
    const auto& entry = builtin_algorithms().find("jso");
    EXPECT_EQ(entry.version, 1);
    EXPECT_NE(entry.reference.find("Brest"), std::string::npos);
    EXPECT_EQ(entry.parameters.size(), 7u);
    EXPECT_DOUBLE_EQ(std::stod(jso_parameter("r_ninit").default_value), 25.0);
    EXPECT_EQ(jso_parameter("n_min").default_value, "4");
    EXPECT_DOUBLE_EQ(std::stod(jso_parameter("r_arc").default_value), 1.0);
    EXPECT_DOUBLE_EQ(std::stod(jso_parameter("p").default_value), 0.25);
    EXPECT_EQ(jso_parameter("H").default_value, "5");
    EXPECT_DOUBLE_EQ(std::stod(jso_parameter("m_f").default_value), 0.3);
    EXPECT_DOUBLE_EQ(std::stod(jso_parameter("m_cr").default_value), 0.8);
    EXPECT_DOUBLE_EQ(jso_parameter("n_min").min, 4.0); // current-to-pbest/1 needs four
}

TEST(Jso, InitialPopulationIs25SqrtDLnD) {
    // round(25 sqrt(D) ln D): 182 at D = 10 (182.03), 466 at D = 30 (465.7), 25 at D = 2 (24.5).
    for (const auto& [dim, expected] :
         std::vector<std::pair<int, std::int64_t>>{{10, 182}, {30, 466}, {2, 25}}) {
        const auto sphere = builtin_problems().create("sphere:dim=" + std::to_string(dim));
        const Outcome out = run("jso", *sphere, 1, iterations(1));
        EXPECT_EQ(out.iterations_trace.front().evaluations, expected) << "D = " << dim;
    }
    // D = 1: ln 1 = 0, no population; a clear error rather than a crash.
    const auto line = builtin_problems().create("sphere:dim=1");
    EXPECT_THROW((void)run("jso", *line, 1, evaluations(1000)), std::invalid_argument);
}

TEST(Jso, PopulationFallsLinearlyWithTheEvaluationsToFourAtTheEndOfTheBudget) {
    expect_lpsr_under_an_evaluation_budget("jso", 182, 4);
}

TEST(Jso, IterationBudgetDerivesMaxNfeSoThatTheReductionEndsAtTheLastGeneration) {
    expect_lpsr_under_an_iteration_budget("jso", 182, 5);
}

TEST(Jso, EvaluationBudgetIsChargedExactlyWhateverItsRemainder) {
    const auto problem = ShiftedRastrigin(6, 3);
    for (const std::int64_t budget : {100, 182 + 1, 5003, 12345}) {
        const Outcome out = run("jso", problem, 2, evaluations(budget));
        EXPECT_EQ(out.evaluations, budget) << budget;
    }
}

TEST(Jso, SameSeedSameRunOtherSeedOtherRun) {
    const auto problem = RotatedEllipsoid(5, 1e3, 7);
    const Outcome a = run("jso", problem, 11, evaluations(7001));
    const Outcome b = run("jso", problem, 11, evaluations(7001));
    const Outcome c = run("jso", problem, 12, evaluations(7001));
    EXPECT_TRUE(identical(a, b));
    EXPECT_FALSE(identical(a, c));
    EXPECT_NE(a.best_f, c.best_f);
}

TEST(Jso, SolvesSphereAndARotatedEllipsoidInTenDimensions) {
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const Outcome s = run("jso", *sphere, 1, Budget{100000, std::nullopt, 1e-8});
    EXPECT_LE(s.best_f, 1e-8);
    EXPECT_LT(s.evaluations, 100000); // the target stopped it before the budget
    const Outcome e = run("jso", RotatedEllipsoid(10, 1e6, 3), 1, Budget{100000, std::nullopt, 1e-8});
    EXPECT_LE(e.best_f, 1e-8);
}

} // namespace
} // namespace mhb::test
