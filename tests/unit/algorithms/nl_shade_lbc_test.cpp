// NL-SHADE-LBC (algorithms/nl_shade_lbc.cpp): the published defaults as the registry lists them, the
// non-linear population size reduction against the budget (read from the evaluations each
// iteration charges, which are the population size), exact evaluation accounting under an
// evaluation and an iteration budget, determinism, and that it solves easy functions. That one and
// two threads give the same run is in batch_equivalence_test.cpp (nl-shade-lbc is one of its specs).
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "baselines_test_problems.hpp"
#include "paper_algorithms_support.hpp"
#include "problems/problem_registry.hpp"

namespace mhb::test {
namespace {

// Evaluations charged by each iteration after the initialisation (= the population size N_G).
std::vector<std::int64_t> nl_shade_lbc_generation_sizes(const Outcome& out) {
    std::vector<std::int64_t> sizes;
    for (std::size_t i = 1; i < out.iterations_trace.size(); ++i)
        sizes.push_back(out.iterations_trace[i].evaluations - out.iterations_trace[i - 1].evaluations);
    return sizes;
}

// The population size after a generation that ended with `nfes` evaluations spent, from a
// population of `n`: round(N_init + (4 - N_init) r^(1 - r)) with r = nfes / MAX_NFE, not below 4,
// never growing.
std::int64_t nl_shade_lbc_planned_size(std::int64_t n, std::int64_t n_init, double max_nfe,
                                       std::int64_t nfes) {
    const double r = std::min(1.0, static_cast<double>(nfes) / max_nfe);
    const double planned =
        std::round(static_cast<double>(n_init) + (4.0 - static_cast<double>(n_init)) * std::pow(r, 1.0 - r));
    return std::min<std::int64_t>(n, std::max<std::int64_t>(4, static_cast<std::int64_t>(planned)));
}

// Every whole generation of a D = 10 run (N_init = 230) has the size planned from the evaluations
// spent before it.
void nl_shade_lbc_expect_planned_sizes(const Outcome& out, double max_nfe) {
    const auto sizes = nl_shade_lbc_generation_sizes(out);
    std::int64_t n = 230;
    for (std::size_t g = 0; g < sizes.size(); ++g) {
        EXPECT_EQ(sizes[g], n) << "generation " << g + 1;
        n = nl_shade_lbc_planned_size(n, 230, max_nfe, out.iterations_trace[g + 1].evaluations);
    }
}

const ParameterInfo& nl_shade_lbc_parameter(const std::string& name) {
    for (const auto& p : builtin_algorithms().find("nl-shade-lbc").parameters)
        if (p.name == name)
            return p;
    throw std::out_of_range("nl-shade-lbc has no parameter " + name);
}

TEST(NlShadeLbc, ListsThePublishedDefaults) {
    const auto& entry = builtin_algorithms().find("nl-shade-lbc");
    EXPECT_EQ(entry.version, 1);
    EXPECT_NE(entry.reference.find("Stanovov"), std::string::npos);
    EXPECT_EQ(entry.parameters.size(), 14u);
    const auto real = [](const char* name) { return std::stod(nl_shade_lbc_parameter(name).default_value); };
    EXPECT_DOUBLE_EQ(real("r_ninit"), 23.0);
    EXPECT_EQ(nl_shade_lbc_parameter("n_min").default_value, "4");
    EXPECT_DOUBLE_EQ(real("r_arc"), 1.0);
    EXPECT_DOUBLE_EQ(real("r_h"), 20.0);
    EXPECT_DOUBLE_EQ(real("m_f"), 0.5);
    EXPECT_DOUBLE_EQ(real("m_cr"), 0.9);
    EXPECT_DOUBLE_EQ(real("p_a"), 0.5);
    EXPECT_DOUBLE_EQ(real("p_b_start"), 0.2);
    EXPECT_DOUBLE_EQ(real("p_b_end"), 0.3);
    EXPECT_DOUBLE_EQ(real("lehmer_f"), 3.5);
    EXPECT_DOUBLE_EQ(real("lehmer_cr"), 1.0);
    EXPECT_DOUBLE_EQ(real("lehmer_end"), 1.5);
    EXPECT_DOUBLE_EQ(real("lehmer_m"), 1.5);
    EXPECT_EQ(nl_shade_lbc_parameter("tries").default_value, "100");
    EXPECT_DOUBLE_EQ(nl_shade_lbc_parameter("n_min").min, 4.0); // current-to-pbest/1 needs four
}

TEST(NlShadeLbc, InitialPopulationIs23D) {
    for (const auto& [dim, expected] :
         std::vector<std::pair<int, std::int64_t>>{{10, 230}, {20, 460}, {2, 46}}) {
        const auto sphere = builtin_problems().create("sphere:dim=" + std::to_string(dim));
        const Outcome out = run("nl-shade-lbc", *sphere, 1, iterations(1));
        EXPECT_EQ(out.iterations_trace.front().evaluations, expected) << "D = " << dim;
    }
    // round(0.1 * 10) = 1 < n_min: a clear error rather than a crash.
    const auto sphere = builtin_problems().create("sphere:dim=10");
    EXPECT_THROW((void)run("nl-shade-lbc:r_ninit=0.1", *sphere, 1, evaluations(1000)), std::invalid_argument);
}

TEST(NlShadeLbc, PopulationFallsNonLinearlyWithTheEvaluationsToFourAtTheEndOfTheBudget) {
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const std::int64_t budget = 30000;
    const Outcome out = run("nl-shade-lbc", *sphere, 4, evaluations(budget));
    EXPECT_EQ(out.evaluations, budget);
    const auto sizes = nl_shade_lbc_generation_sizes(out);
    ASSERT_GT(sizes.size(), 100u);
    // The iteration that the budget cut short is not in the trace: every step is a whole one.
    nl_shade_lbc_expect_planned_sizes(out, static_cast<double>(budget));
    // Non-linear: half-way through the budget N is already round(230 - 226 sqrt(0.5)) = 70, where a
    // linear reduction would be at 117.
    for (std::size_t g = 0; g < sizes.size(); ++g)
        if (out.iterations_trace[g].evaluations >= budget / 2) {
            EXPECT_NEAR(static_cast<double>(sizes[g]), 70.0, 1.0) << "generation " << g + 1;
            break;
        }
    EXPECT_LE(sizes.back(), 5);
    EXPECT_LT(budget - out.iterations_trace.back().evaluations, sizes.back()); // the cut generation
}

TEST(NlShadeLbc, IterationBudgetDerivesMaxNfeSoThatTheReductionEndsAtTheLastGeneration) {
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const std::int64_t generations = 300;
    const Outcome out = run("nl-shade-lbc", *sphere, 5, iterations(generations));
    EXPECT_EQ(out.iterations, generations);
    const auto sizes = nl_shade_lbc_generation_sizes(out);
    ASSERT_EQ(sizes.size(), static_cast<std::size_t>(generations));
    // MAX_NFE = G / integral_0^1 dr / N(r), N(r) = 230 - 226 r^(1 - r) (a fine midpoint sum here).
    double integral = 0.0;
    constexpr int steps = 100000;
    for (int k = 0; k < steps; ++k) {
        const double r = (k + 0.5) / steps;
        integral += 1.0 / (steps * (230.0 - 226.0 * std::pow(r, 1.0 - r)));
    }
    const double max_nfe = static_cast<double>(generations) / integral;
    nl_shade_lbc_expect_planned_sizes(out, max_nfe);
    const std::int64_t spent = std::accumulate(sizes.begin(), sizes.end(), std::int64_t{230});
    EXPECT_EQ(out.evaluations, spent); // nothing but the populations is charged
    // Rounding leaves the last generations a little above or at N_min, not stuck far above it.
    EXPECT_LE(sizes.back(), 6);
    EXPECT_NEAR(static_cast<double>(out.evaluations), max_nfe, 0.05 * max_nfe);
}

TEST(NlShadeLbc, EvaluationBudgetIsChargedExactlyWhateverItsRemainder) {
    const auto problem = ShiftedRastrigin(6, 3);
    for (const std::int64_t budget : {100, 183, 5003, 12345}) {
        const Outcome out = run("nl-shade-lbc", problem, 2, evaluations(budget));
        EXPECT_EQ(out.evaluations, budget) << budget;
    }
}

TEST(NlShadeLbc, SameSeedSameRunOtherSeedOtherRun) {
    const auto problem = RotatedEllipsoid(5, 1e3, 7);
    const Outcome a = run("nl-shade-lbc", problem, 11, evaluations(7001));
    const Outcome b = run("nl-shade-lbc", problem, 11, evaluations(7001));
    const Outcome c = run("nl-shade-lbc", problem, 12, evaluations(7001));
    EXPECT_TRUE(identical(a, b));
    EXPECT_FALSE(identical(a, c));
    EXPECT_NE(a.best_f, c.best_f);
}

TEST(NlShadeLbc, SolvesSphereAndARotatedEllipsoidInTenDimensions) {
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const Outcome s = run("nl-shade-lbc", *sphere, 1, Budget{100000, std::nullopt, 1e-8});
    EXPECT_LE(s.best_f, 1e-8);
    EXPECT_LT(s.evaluations, 100000); // the target stopped it before the budget
    const Outcome e =
        run("nl-shade-lbc", RotatedEllipsoid(10, 1e6, 3), 1, Budget{100000, std::nullopt, 1e-8});
    EXPECT_LE(e.best_f, 1e-8);
}

} // namespace
} // namespace mhb::test
