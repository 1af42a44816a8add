// Convergence of the paper's algorithms on the 10-D sphere ([-100, 100]^10, f* = 0), ten fixed
// seeds each, and the best-so-far never worsening along the iteration and checkpoint traces.
// Thresholds come from measuring these runs (20 seeds, NP = 50) and keeping a wide margin:
//   TLBO  150 iterations (the paper's count, 15050 evaluations): worst 7e-29;        asserted 1e-20.
//   ITLBO  50 iterations (about 27800 evaluations):               worst 3e-24;        asserted 1e-20.
//   PSO   400 iterations (20050 evaluations):                     worst 2e-18;        asserted 1e-12.
//   With r=learner: TLBO worst 2e-31, ITLBO 9e-32; asserted 1e-20. (PSO with r=learner does not
//   converge here, worst 11; likely the loss of diversity pso.cpp's header describes.)
// ITLBO's figure is for the mutation stream taken as a jumped copy of the run's stream (it was
// 7e-25 with the earlier peeked seed: another stream, other runs).
// A regression that breaks a phase (a wrong sign, a lost greedy step) misses these by many
// orders of magnitude.
#include <gtest/gtest.h>

#include "tests/unit/algorithms/paper_algorithms_support.hpp"

namespace mhb::test {
namespace {

void expect_never_worsens(const Outcome& o, const std::string& what) {
    for (std::size_t t = 1; t < o.iterations_trace.size(); ++t)
        EXPECT_LE(o.iterations_trace[t].best_f, o.iterations_trace[t - 1].best_f)
            << what << " iteration " << t;
    for (std::size_t t = 1; t < o.checkpoints.size(); ++t)
        EXPECT_LE(o.checkpoints[t].best_f, o.checkpoints[t - 1].best_f) << what << " checkpoint " << t;
    ASSERT_FALSE(o.iterations_trace.empty());
    EXPECT_EQ(o.iterations_trace.back().best_f, o.best_f) << what;
}

void expect_converges(const std::string& algorithm, std::int64_t iteration_budget, double below) {
    const auto p = sphere(10);
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const Outcome o = run(algorithm, *p, seed, iterations(iteration_budget));
        const std::string what = algorithm + " seed " + std::to_string(seed);
        EXPECT_EQ(o.iterations, iteration_budget) << what;
        EXPECT_LT(o.best_f, below) << what;
        EXPECT_GE(o.best_f, 0.0) << what;
        expect_never_worsens(o, what);
    }
}

TEST(PaperAlgorithmConvergence, TlboReaches1em20OnSphere10In150Iterations) {
    expect_converges("tlbo", 150, 1e-20);
}

TEST(PaperAlgorithmConvergence, ItlboReaches1em20OnSphere10In50Iterations) {
    expect_converges("itlbo", 50, 1e-20);
}

TEST(PaperAlgorithmConvergence, PsoReaches1em12OnSphere10In400Iterations) {
    expect_converges("pso", 400, 1e-12);
}

// The learning factor drawn per learner (eqs. 7 and 9's reading) converges as well.
TEST(PaperAlgorithmConvergence, LearnerModeTlboAndItlboReach1em20OnSphere10) {
    expect_converges("tlbo:r=learner", 150, 1e-20);
    expect_converges("itlbo:r=learner", 50, 1e-20);
}

// The options that the paper leaves open must converge too (same budget as ITLBO's default).
TEST(PaperAlgorithmConvergence, ItlboOptionsConvergeOnSphere10) {
    expect_converges("itlbo:obl_greedy=on", 50, 1e-20);
    expect_converges("itlbo:obl_bounds=population", 50, 1e-20);
}

} // namespace
} // namespace mhb::test
