// Evaluations per iteration are what each optimiser's header and `mhbench list` say, so that
// studies at equal iterations (the paper's habit) charge each method what it really spends.
// Figures at D = 5 with defaults: DE NP = 10 D = 50; CMA-ES lambda = 4 + floor(3 ln 5) = 8;
// SPSO 2011 S = 40; Jaya NP = 50; ETLBO 2 NP = 100 plus one per duplicate; NLopt 100 per iteration
// (the first evaluation is iteration 0); L-SHADE 18 D = 90 at first.
#include <gtest/gtest.h>

#include "baselines_test_problems.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

// Evaluations of each iteration after the initialisation, and of the initialisation itself.
std::pair<std::int64_t, std::vector<std::int64_t>> costs(const std::string& spec) {
    const auto sphere = builtin_problems().create("sphere:dim=5");
    const auto r = test::run_spec(spec, *sphere, Budget{std::nullopt, 8, std::nullopt}, 9);
    std::vector<std::int64_t> steps;
    for (std::size_t i = 1; i < r.iteration_trace.size(); ++i)
        steps.push_back(r.iteration_trace[i].evaluations - r.iteration_trace[i - 1].evaluations);
    return {r.iteration_trace.front().evaluations, steps};
}

TEST(BaselinesCost, EvaluationsPerIterationAreAsDocumented) {
    const auto expect_constant = [](const std::string& spec, std::int64_t first, std::int64_t per_iteration) {
        const auto [init, steps] = costs(spec);
        EXPECT_EQ(init, first) << spec;
        ASSERT_EQ(steps.size(), 8u) << spec;
        for (const auto s : steps)
            EXPECT_EQ(s, per_iteration) << spec;
    };
    expect_constant("de", 50, 50);
    expect_constant("cmaes", 8, 8);
    expect_constant("spso2011", 40, 40);
    expect_constant("jaya", 50, 50);
    expect_constant("nlopt:algorithm=LN_SBPLX", 1, 100);
    expect_constant("nlopt:algorithm=GN_ISRES,iteration_evals=30", 1, 30);

    const auto [etlbo_init, etlbo_steps] = costs("etlbo");
    EXPECT_EQ(etlbo_init, 50);
    for (const auto s : etlbo_steps) {
        EXPECT_GE(s, 100); // teacher and learner phases
        EXPECT_LE(s, 150); // at most one mutation per learner
    }
    // An elite copied over a worst learner duplicates its original unless that learner moved during
    // the iteration, so mutations (and their evaluations) do happen.
    EXPECT_GT(*std::max_element(etlbo_steps.begin(), etlbo_steps.end()), 100);

    const auto [lshade_init, lshade_steps] = costs("lshade");
    EXPECT_EQ(lshade_init, 90);
    EXPECT_EQ(lshade_steps.front(), 90);
    EXPECT_TRUE(std::is_sorted(lshade_steps.rbegin(), lshade_steps.rend()));
}

} // namespace
} // namespace mhb
