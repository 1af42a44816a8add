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

// Evaluations charged by each iteration after the initialisation (= the population size N_G).
std::vector<std::int64_t> jso_generation_sizes(const Outcome& out) {
    std::vector<std::int64_t> sizes;
    for (std::size_t i = 1; i < out.iterations_trace.size(); ++i)
        sizes.push_back(out.iterations_trace[i].evaluations - out.iterations_trace[i - 1].evaluations);
    return sizes;
}

// The population size after a generation that ended with `nfes` evaluations spent, from a
// population of `n`: round((4 - N_init) / MAX_NFE nfes + N_init), not below 4, never growing.
std::int64_t jso_planned_size(std::int64_t n, std::int64_t n_init, double max_nfe, std::int64_t nfes) {
    const double planned =
        std::round((4.0 - static_cast<double>(n_init)) / max_nfe * static_cast<double>(nfes) +
                   static_cast<double>(n_init));
    return std::min<std::int64_t>(n, std::max<std::int64_t>(4, static_cast<std::int64_t>(planned)));
}

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
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const std::int64_t budget = 20000;
    const Outcome out = run("jso", *sphere, 4, evaluations(budget));
    EXPECT_EQ(out.evaluations, budget);
    const auto sizes = jso_generation_sizes(out);
    ASSERT_GT(sizes.size(), 100u);
    std::int64_t n = 182;
    for (std::size_t g = 0; g < sizes.size(); ++g) {
        // The iteration that the budget cut short is not in the trace: every step is a whole one.
        EXPECT_EQ(sizes[g], n) << "generation " << g + 1;
        EXPECT_GE(sizes[g], 4);
        n = jso_planned_size(n, 182, static_cast<double>(budget), out.iterations_trace[g + 1].evaluations);
    }
    // It reaches N_min = 4 only at the very end: round(182 - 178 nfes / MAX) = 4 needs
    // nfes >= MAX (1 - 0.5 / 178), the last 57 evaluations here.
    EXPECT_EQ(sizes.back(), 4);
    for (std::size_t g = 0; g < sizes.size(); ++g)
        if (sizes[g] == 4) {
            EXPECT_GE(out.iterations_trace[g].evaluations, budget - 57 - 4) << "generation " << g + 1;
            break;
        }
    EXPECT_LT(budget - out.iterations_trace.back().evaluations, 4); // the cut generation had < 4 left
}

TEST(Jso, IterationBudgetDerivesMaxNfeSoThatTheReductionEndsAtTheLastGeneration) {
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const std::int64_t generations = 200;
    const Outcome out = run("jso", *sphere, 5, iterations(generations));
    EXPECT_EQ(out.iterations, generations);
    const auto sizes = jso_generation_sizes(out);
    ASSERT_EQ(sizes.size(), static_cast<std::size_t>(generations));
    // MAX_NFE = G (N_init - N_min) / ln(N_init / N_min), as for L-SHADE.
    const double max_nfe = static_cast<double>(generations) * 178.0 / std::log(182.0 / 4.0);
    std::int64_t n = 182;
    std::int64_t spent = 182;
    for (std::size_t g = 0; g < sizes.size(); ++g) {
        EXPECT_EQ(sizes[g], n) << "generation " << g + 1;
        spent += sizes[g];
        n = jso_planned_size(n, 182, max_nfe, out.iterations_trace[g + 1].evaluations);
    }
    EXPECT_EQ(out.evaluations, spent); // nothing but the populations is charged
    // Rounding leaves the last generations a little above or at N_min, not stuck far above it.
    EXPECT_LE(sizes.back(), 12);
    EXPECT_NEAR(static_cast<double>(out.evaluations), max_nfe, 0.05 * max_nfe);
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
