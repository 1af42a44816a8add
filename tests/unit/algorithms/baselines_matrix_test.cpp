// The matrix test: every registered optimiser (every entry of builtin_algorithms(), with its
// defaults, plus each NLopt algorithm the issue names) on a small problem set spends an evaluation
// budget exactly, stops at an iteration budget exactly, is deterministic for a fixed seed, and gives
// the same results when runs are spread over 2 threads as when they run one after another (NLopt's
// thread-local random generator is the usual way to lose that).
// The lead adds the real `pmsm` and `rastrigin` specs, and the runner's 1-vs-2-thread check, on merge.
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "baselines_test_problems.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

std::vector<std::string> algorithm_specs() {
    std::vector<std::string> specs = test::baseline_specs();
    specs.emplace_back("nlopt:algorithm=LN_PRAXIS");
    specs.emplace_back("nlopt:algorithm=GN_MLSL_LDS,local=LN_SBPLX");
    specs.emplace_back("cmaes:restarts=none");
    return specs;
}

// The small problem set, as users write it: sphere, a shifted Rastrigin and the paper's
// PMSM steady-state identification problem (a convex quadratic with a known optimum).
std::vector<std::shared_ptr<const Problem>> problem_set() {
    std::vector<std::shared_ptr<const Problem>> problems;
    for (const char* spec : {"sphere:dim=5", "rastrigin:dim=5,shift=1,instance=11", "pmsm:speed=2500,load=2"})
        problems.emplace_back(builtin_problems().create(spec));
    return problems;
}

using Outcome = test::RunOutcome;

Outcome run_matrix_case(const std::string& spec, const Problem& problem, Budget budget, std::uint64_t seed) {
    return test::run_spec(spec, problem, budget, seed);
}

void expect_identical(const Outcome& a, const Outcome& b, const std::string& where) {
    EXPECT_EQ(a.best_f, b.best_f) << where; // bit for bit
    EXPECT_EQ(a.best_x, b.best_x) << where;
    EXPECT_EQ(a.evaluations, b.evaluations) << where;
    ASSERT_EQ(a.checkpoints.size(), b.checkpoints.size()) << where;
    for (std::size_t i = 0; i < a.checkpoints.size(); ++i)
        EXPECT_EQ(a.checkpoints[i].best_f, b.checkpoints[i].best_f) << where << " checkpoint " << i;
    ASSERT_EQ(a.iteration_trace.size(), b.iteration_trace.size()) << where;
}

TEST(BaselinesMatrix, SpendsTheEvaluationBudgetExactlyAndIsDeterministic) {
    const Budget budget{1500, std::nullopt, std::nullopt};
    for (const auto& spec : algorithm_specs()) {
        for (const auto& problem : problem_set()) {
            const std::string where = spec + " on " + problem->name();
            const Outcome a = run_matrix_case(spec, *problem, budget, 42);
            const Outcome b = run_matrix_case(spec, *problem, budget, 42);
            // `cmaes:restarts=none` may end early by design; everything else spends the budget.
            if (spec == "cmaes:restarts=none")
                EXPECT_LE(a.evaluations, 1500) << where;
            else
                EXPECT_EQ(a.evaluations, 1500) << where;
            expect_identical(a, b, where);
            EXPECT_TRUE(problem->bounds().contains(a.best_x)) << where;
            EXPECT_DOUBLE_EQ(problem->evaluate(a.best_x), a.best_f) << where;
            // The trace is a best-so-far curve: evaluations rise, best f never rises.
            ASSERT_FALSE(a.iteration_trace.empty()) << where;
            for (std::size_t i = 1; i < a.iteration_trace.size(); ++i) {
                EXPECT_GT(a.iteration_trace[i].evaluations, a.iteration_trace[i - 1].evaluations) << where;
                EXPECT_LE(a.iteration_trace[i].best_f, a.iteration_trace[i - 1].best_f) << where;
            }
            EXPECT_EQ(a.checkpoints.back().evaluations, a.evaluations) << where;
            // A different seed gives a different run. DIRECT_L is deterministic by design, and MLSL_LDS
            // samples a Sobol sequence, so only its (unimportant) first point depends on the seed.
            if (spec.find("GN_DIRECT_L") == std::string::npos &&
                spec.find("GN_MLSL_LDS") == std::string::npos) {
                const Outcome c = run_matrix_case(spec, *problem, budget, 43);
                EXPECT_NE(a.best_x, c.best_x) << where;
            }
        }
    }
}

TEST(BaselinesMatrix, StopsExactlyAtAnIterationBudget) {
    const Budget budget{std::nullopt, 6, std::nullopt};
    for (const auto& spec : algorithm_specs()) {
        for (const auto& problem : problem_set()) {
            const std::string where = spec + " on " + problem->name();
            const Outcome a = run_matrix_case(spec, *problem, budget, 5);
            if (spec == "cmaes:restarts=none")
                EXPECT_LE(a.iterations, 6) << where;
            else
                EXPECT_EQ(a.iterations, 6) << where;
            // Iteration 0 (initialisation) plus one point per iteration.
            EXPECT_EQ(a.iteration_trace.size(), static_cast<std::size_t>(a.iterations + 1)) << where;
            EXPECT_GT(a.evaluations, 0) << where;
        }
    }
}

TEST(BaselinesMatrix, TwoThreadsGiveTheSameRunsAsOne) {
    const auto problems = problem_set();
    const auto specs = algorithm_specs();
    const Budget budget{600, std::nullopt, std::nullopt};
    // Every (spec, problem, seed) once serially, once spread over 2 threads in a different order.
    struct Task {
        std::size_t spec, problem;
        std::uint64_t seed;
    };
    std::vector<Task> tasks;
    for (std::size_t s = 0; s < specs.size(); ++s)
        for (std::size_t p = 0; p < problems.size(); ++p)
            for (std::uint64_t seed = 1; seed <= 2; ++seed)
                tasks.push_back({s, p, seed});
    std::vector<Outcome> serial(tasks.size()), parallel(tasks.size());
    for (std::size_t t = 0; t < tasks.size(); ++t)
        serial[t] = run_matrix_case(specs[tasks[t].spec], *problems[tasks[t].problem], budget, tasks[t].seed);
    tbb::task_arena arena(2);
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t i) {
            const std::size_t t = tasks.size() - 1 - i;
            parallel[t] =
                run_matrix_case(specs[tasks[t].spec], *problems[tasks[t].problem], budget, tasks[t].seed);
        });
    });
    for (std::size_t t = 0; t < tasks.size(); ++t)
        expect_identical(serial[t], parallel[t],
                         specs[tasks[t].spec] + " on " + problems[tasks[t].problem]->name() + " seed " +
                             std::to_string(tasks[t].seed));
}

} // namespace
} // namespace mhb
