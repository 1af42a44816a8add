// Each baseline reaches a stated accuracy where it must, on fixed seeds 1..5 (all five must pass).
// Where the figures come from: the optimum of each test problem is known exactly (f* = 0 at the
// shift for the ellipsoid and Rastrigin; the QR least-squares solution for the PMSM-like quadratic).
// The thresholds are the (CMA-ES: 1e-10 on the 10-D rotated ellipsoid within 2e4
// evaluations; BOBYQA: 1e-9 relative on the steady-state quadratic) or the usual published
// behaviour of the method, set about 100x looser than what these seeds reach, so that a broken
// update (a wrong constant, a sign) fails them and rounding differences do not.
#include <algorithm>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"
#include "baselines_test_problems.hpp"
#include "problems/problem_registry.hpp"
#include "support/budgets.hpp"

namespace mhb {
namespace {

using mhb::test_support::evaluations;

struct Result {
    double gap = 0.0; // best f - f*
    std::int64_t evaluations = 0;
    std::optional<std::int64_t> to_target;
    std::vector<IterationPoint> trace;
};

Result run_for_accuracy(const std::string& spec, const Problem& problem, Budget budget, std::uint64_t seed) {
    const test::RunOutcome r = test::run_spec(spec, problem, budget, seed);
    return {r.best_f - problem.known_optimum()->f, r.evaluations, r.evaluations_to_target, r.iteration_trace};
}

// Checks that every seed 1..5 reaches `gap` (relative to f* when `relative`).
void expect_reaches(const std::string& spec, const Problem& problem, std::int64_t budget, double gap,
                    bool relative = false) {
    const double scale = relative ? problem.known_optimum()->f : 1.0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const Result r = run_for_accuracy(spec, problem, evaluations(budget), seed);
        EXPECT_EQ(r.evaluations, budget) << spec;
        EXPECT_LE(r.gap, gap * scale) << spec << " on " << problem.name() << ", seed " << seed;
    }
}

TEST(BaselinesAccuracy, CmaesSolvesTheRotatedEllipsoidTo1e10Within2e4Evaluations) {
    // The figure. Hansen's published runs need about 6000 evaluations on 10-D felli.
    const test::RotatedEllipsoid ellipsoid(10, 1e6, 3);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const Result r = run_for_accuracy("cmaes", ellipsoid, Budget{20000, std::nullopt, 1e-10}, seed);
        ASSERT_TRUE(r.to_target.has_value()) << "seed " << seed << " ended at gap " << r.gap;
        EXPECT_LE(*r.to_target, 20000);
        EXPECT_LE(r.gap, 1e-10);
    }
}

TEST(BaselinesAccuracy, CmaesIpopDoublesTheOffspringAfterEachRestart) {
    // On the 10-D sphere the first run (lambda = 4 + floor(3 ln 10) = 10) meets TolFun long before
    // 2e4 evaluations, so the trace must show generations of 10, then 20 (and maybe 40) evaluations.
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const Result r = run_for_accuracy("cmaes", *sphere, evaluations(20000), 1);
    std::vector<std::int64_t> steps;
    for (std::size_t i = 1; i < r.trace.size(); ++i)
        steps.push_back(r.trace[i].evaluations - r.trace[i - 1].evaluations);
    EXPECT_EQ(r.trace.front().evaluations, 10);
    EXPECT_NE(std::find(steps.begin(), steps.end(), 10), steps.end());
    EXPECT_NE(std::find(steps.begin(), steps.end(), 20), steps.end());
    EXPECT_TRUE(std::is_sorted(steps.begin(), steps.end() - 1)); // the last one may be cut by the budget
    // Without restarts the run ends at its first stop criterion, below the budget.
    EXPECT_LT(run_for_accuracy("cmaes:restarts=none", *sphere, evaluations(20000), 1).evaluations, 20000);
}

TEST(BaselinesAccuracy, BobyqaFindsTheLeastSquaresOptimumOfTheSteadyStateQuadratic) {
    // The figure: within 1e-9 relative of the exact least-squares optimum.
    const test::SteadyStateQuadratic quadratic(7);
    expect_reaches("nlopt:algorithm=LN_BOBYQA", quadratic, 2000, 1e-9, true);
}

TEST(BaselinesAccuracy, NloptMethodsOnTheSteadyStateQuadratic) {
    // Observed on these seeds: Nelder-Mead <= 4e-13, Sbplx <= 4e-10, CRS2 <= 5e-13, MLSL-LDS 5e-15
    // (relative); COBYLA's linear models crawl on this badly scaled quadratic (7e-4 to 6e-2).
    const test::SteadyStateQuadratic quadratic(7);
    expect_reaches("nlopt:algorithm=LN_NELDERMEAD", quadratic, 4000, 1e-9, true);
    expect_reaches("nlopt:algorithm=LN_SBPLX", quadratic, 4000, 1e-8, true);
    expect_reaches("nlopt:algorithm=GN_CRS2_LM", quadratic, 4000, 1e-9, true);
    expect_reaches("nlopt:algorithm=GN_MLSL_LDS", quadratic, 4000, 1e-9, true);
    expect_reaches("nlopt:algorithm=LN_COBYLA", quadratic, 4000, 0.5, true);
}

TEST(BaselinesAccuracy, PopulationMethodsOnTheSteadyStateQuadratic) {
    // Observed: DE, L-SHADE and CMA-ES reach f* to rounding (|gap| ~ 1e-15 relative), ETLBO <= 1.1e-6.
    const test::SteadyStateQuadratic quadratic(7);
    expect_reaches("de", quadratic, 10000, 1e-12, true);
    expect_reaches("lshade", quadratic, 10000, 1e-12, true);
    expect_reaches("cmaes", quadratic, 10000, 1e-12, true);
    expect_reaches("etlbo", quadratic, 10000, 1e-4, true);
}

TEST(BaselinesAccuracy, DifferentialEvolutionOnTheSphere) {
    // Observed: <= 6e-20 after 6e4 evaluations (NP = 100: 600 generations).
    const auto sphere = builtin_problems().create("sphere:dim=10");
    expect_reaches("de", *sphere, 60000, 1e-12);
}

TEST(BaselinesAccuracy, LshadeSolvesShiftedRastriginAndTheRotatedEllipsoid) {
    // CEC budgets (1e4 D). L-SHADE solves the 10-D shifted Rastrigin exactly on these seeds
    // (gap 0), and the ellipsoid to ~1e-28; DE/rand/1/bin, for contrast, stays at 13 to 19.
    expect_reaches("lshade", test::ShiftedRastrigin(10, 11), 100000, 1e-8);
    expect_reaches("lshade", test::RotatedEllipsoid(10, 1e6, 3), 100000, 1e-8);
}

TEST(BaselinesAccuracy, LshadeReducesItsPopulationLinearlyTo4) {
    // N_init = 18 D = 180 at D = 10; the generation sizes fall to N_min = 4 by the end of the budget.
    const auto sphere = builtin_problems().create("sphere:dim=10");
    for (const Budget budget : {evaluations(20000), Budget{std::nullopt, 200, std::nullopt}}) {
        const Result r = run_for_accuracy("lshade", *sphere, budget, 1);
        ASSERT_GE(r.trace.size(), 3u);
        EXPECT_EQ(r.trace[0].evaluations, 180);
        EXPECT_EQ(r.trace[1].evaluations - r.trace[0].evaluations, 180);
        std::vector<std::int64_t> sizes;
        for (std::size_t i = 1; i < r.trace.size(); ++i)
            sizes.push_back(r.trace[i].evaluations - r.trace[i - 1].evaluations);
        EXPECT_TRUE(std::is_sorted(sizes.rbegin() + 1, sizes.rend())) << "population never grows";
        // With an iteration budget the derived MAX_NFE brings N near N_min around the last generation.
        EXPECT_LE(sizes[sizes.size() - 2], 12);
    }
}

TEST(BaselinesAccuracy, Spso2011EtlboAndJayaOnTheSphere) {
    // Observed after 3e4 evaluations: SPSO 2011 <= 1e-13, ETLBO <= 8e-14, Jaya <= 4.2e-9.
    const auto sphere = builtin_problems().create("sphere:dim=10");
    expect_reaches("spso2011", *sphere, 30000, 1e-10);
    expect_reaches("etlbo", *sphere, 30000, 1e-10);
    expect_reaches("jaya", *sphere, 30000, 1e-6);
}

// Pure random search with the same budget: the floor any optimiser must clear.
double random_search_gap(const Problem& problem, std::int64_t budget, std::uint64_t seed) {
    Objective objective(problem, evaluations(budget));
    Rng rng(seed);
    while (!objective.exhausted()) {
        Eigen::VectorXd x = uniform_point(problem.bounds(), rng);
        objective.evaluate(x);
    }
    return objective.best_f() - problem.known_optimum()->f;
}

TEST(BaselinesAccuracy, EveryRegisteredOptimiserBeatsRandomSearch) {
    // On each problem the median gap over seeds 1..5 must be below random search's median,
    // for every entry of the registry (so the paper's optimisers are covered once merged) and each
    // NLopt algorithm the issue names.
    const std::vector<std::string> specs = test::baseline_specs();
    const std::vector<std::shared_ptr<const Problem>> problems = {
        std::make_shared<test::ShiftedRastrigin>(5, 11), std::make_shared<test::SteadyStateQuadratic>(7),
        std::make_shared<test::RotatedEllipsoid>(5, 1e3, 4)};
    const std::int64_t budget = 3000;
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    for (const auto& problem : problems) {
        std::vector<double> random;
        for (std::uint64_t seed = 1; seed <= 5; ++seed)
            random.push_back(random_search_gap(*problem, budget, seed));
        const double floor = median(random);
        for (const auto& spec : specs) {
            // Restarted local searches end in Rastrigin's local minima, which random search
            // matches (Nelder-Mead 23, COBYLA 31 against 22): they must win on the unimodal ones.
            if (problem->name() == "shifted_rastrigin" && spec.find("=LN_") != std::string::npos)
                continue;
            std::vector<double> gaps;
            for (std::uint64_t seed = 1; seed <= 5; ++seed)
                gaps.push_back(run_for_accuracy(spec, *problem, evaluations(budget), seed).gap);
            if (spec == "random-search") // the registered baseline is this floor, draw for draw
                EXPECT_EQ(median(gaps), floor) << problem->name();
            else
                EXPECT_LT(median(gaps), floor) << spec << " on " << problem->name();
        }
    }
}

} // namespace
} // namespace mhb
