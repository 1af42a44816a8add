// CMA-ES's restart strategies (algorithms/cmaes.cpp): BIPOP's schedule read back from the
// evaluations each generation charges (its population size) on a flat function, where every run
// ends by TolFun after exactly 10 + ceil(30 D / lambda) generations, so that each run's length and
// regime can be checked against Hansen's (2009) rules; BIPOP's first run is IPOP's; exact
// evaluation accounting; the registry's choices. That one and two threads give the same run is in
// batch_equivalence_test.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "baselines_test_problems.hpp"
#include "paper_algorithms_support.hpp"
#include "problems/problem_registry.hpp"

namespace mhb::test {
namespace {

// f = 1 everywhere in [-1, 1]^D: a CMA-ES run sees no progress and stops by TolFun once its
// history of best values is full.
class FlatPlateau final : public Problem {
public:
    explicit FlatPlateau(Eigen::Index dimension)
        : box_{Eigen::VectorXd::Constant(dimension, -1.0), Eigen::VectorXd::Constant(dimension, 1.0)} {}
    std::string name() const override { return "flat_plateau"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd&) const override { return 1.0; }

private:
    Box box_;
};

// The population size of every generation, in order (the first is the initialisation's).
std::vector<std::int64_t> cmaes_generation_sizes(const Outcome& out) {
    std::vector<std::int64_t> sizes{out.iterations_trace.front().evaluations};
    for (std::size_t i = 1; i < out.iterations_trace.size(); ++i)
        sizes.push_back(out.iterations_trace[i].evaluations - out.iterations_trace[i - 1].evaluations);
    return sizes;
}

// Generations until TolFun on a flat function: the best-value history of 10 + ceil(30 D / lambda).
std::int64_t flat_run_length(std::int64_t dimension, std::int64_t lambda) {
    return 10 + static_cast<std::int64_t>(
                    std::ceil(30.0 * static_cast<double>(dimension) / static_cast<double>(lambda)));
}

// Consumes one run of `length` generations of `lambda` from sizes[pos...]; the budget may cut the
// last run short. Returns the evaluations the run charged.
std::int64_t consume_run(const std::vector<std::int64_t>& sizes, std::size_t& pos, std::int64_t lambda,
                         std::int64_t length) {
    std::int64_t spent = 0;
    for (std::int64_t g = 0; g < length && pos < sizes.size(); ++g, ++pos) {
        EXPECT_EQ(sizes[pos], lambda) << "generation " << pos;
        spent += sizes[pos];
    }
    return spent;
}

TEST(CmaEsRestarts, BipopAlternatesItsRegimesByTheEvaluationsEachHasSpent) {
    constexpr std::int64_t dim = 4;
    constexpr std::int64_t default_lambda = 8; // 4 + floor(3 ln 4)
    const FlatPlateau flat(dim);
    const Outcome out = run("cmaes:restarts=bipop", flat, 7, evaluations(60000));
    EXPECT_EQ(out.evaluations, 60000);
    auto sizes = cmaes_generation_sizes(out);
    sizes.pop_back(); // the budget may cut the last generation short

    std::size_t pos = 0;
    // The first run has the default population and is charged to the small regime.
    std::int64_t small = consume_run(sizes, pos, default_lambda, flat_run_length(dim, default_lambda));
    std::int64_t large = 0, large_lambda = default_lambda;
    int small_runs = 0, large_runs = 0;
    while (pos < sizes.size()) {
        if (small < large) {
            // Small regime: lambda_def <= lambda <= the last large population, capped at half the
            // large regime's evaluations.
            const std::int64_t lambda = sizes[pos];
            EXPECT_GE(lambda, default_lambda);
            EXPECT_LE(lambda, large_lambda);
            const auto cap = static_cast<std::int64_t>(
                std::ceil(0.5 * static_cast<double>(large) / static_cast<double>(lambda)));
            small += consume_run(sizes, pos, lambda, std::min(flat_run_length(dim, lambda), cap));
            ++small_runs;
        } else {
            large_lambda *= 2;
            large += consume_run(sizes, pos, large_lambda, flat_run_length(dim, large_lambda));
            ++large_runs;
        }
    }
    EXPECT_GE(large_runs, 4);
    EXPECT_GE(small_runs, 10); // many small runs fit in half of each large one
}

TEST(CmaEsRestarts, BipopsFirstRunIsIpops) {
    // Until its first restart BIPOP is the plain CMA-ES: the same draws, the same records.
    const RotatedEllipsoid ellipsoid(10, 1e6, 5);
    const Outcome ipop = run("cmaes", ellipsoid, 3, evaluations(1500));
    const Outcome bipop = run("cmaes:restarts=bipop", ellipsoid, 3, evaluations(1500));
    ASSERT_EQ(ipop.iterations_trace.size(), bipop.iterations_trace.size());
    for (std::size_t i = 0; i < ipop.iterations_trace.size(); ++i) {
        EXPECT_EQ(ipop.iterations_trace[i].evaluations, bipop.iterations_trace[i].evaluations);
        EXPECT_EQ(ipop.iterations_trace[i].best_f, bipop.iterations_trace[i].best_f);
    }
    EXPECT_EQ(ipop.best_f, bipop.best_f);
}

TEST(CmaEsRestarts, BipopChargesExactlyTheBudgetOfEitherKind) {
    const ShiftedRastrigin rastrigin(5, 11);
    for (const std::int64_t budget : {100, 5003, 40000})
        EXPECT_EQ(run("cmaes:restarts=bipop", rastrigin, 2, evaluations(budget)).evaluations, budget);
    const Outcome by_iterations = run("cmaes:restarts=bipop", rastrigin, 2, iterations(3000));
    EXPECT_EQ(by_iterations.iterations, 3000);
}

TEST(CmaEsRestarts, RegistryOffersIpopBipopAndNoneWithIpopTheDefault) {
    const auto& entry = builtin_algorithms().find("cmaes");
    const auto restarts = std::find_if(entry.parameters.begin(), entry.parameters.end(),
                                       [](const ParameterInfo& p) { return p.name == "restarts"; });
    ASSERT_NE(restarts, entry.parameters.end());
    EXPECT_EQ(restarts->default_value, "ipop");
    EXPECT_EQ(restarts->choices, (std::vector<std::string>{"ipop", "bipop", "none"}));
    EXPECT_NE(entry.reference.find("BIPOP"), std::string::npos);
}

} // namespace
} // namespace mhb::test
