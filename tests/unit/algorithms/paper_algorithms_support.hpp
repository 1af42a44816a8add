// Helpers for the tests of the paper's algorithms (TLBO, ITLBO, PSO) and of the L-SHADE family: one
// run turned into a comparable outcome, the population sizes a run's iterations charged against
// linear population size reduction, a non-separable test function, and a problem that records every
// point it is asked to evaluate (so tests can check what an optimiser evaluated, in order).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "problems/objective.hpp"
#include "problems/problem_registry.hpp"

namespace mhb::test {

// Everything a run leaves behind that must be reproducible.
struct Outcome {
    double best_f = 0.0;
    Eigen::VectorXd best_x;
    std::int64_t evaluations = 0;
    std::int64_t iterations = 0;
    std::vector<IterationPoint> iterations_trace;
    std::vector<CheckpointPoint> checkpoints;
};

inline Outcome run(const std::string& algorithm, const Problem& problem, std::uint64_t seed, Budget budget) {
    const auto optimizer = builtin_algorithms().create(algorithm);
    ObjectiveOptions options;
    options.record_best_x = true;
    Objective objective(problem, budget, optimizer->bound_policy(), options);
    Rng rng(seed);
    run_to_budget(*optimizer, objective, rng);
    return {objective.best_f(),     objective.best_x(),          objective.evaluations(),
            objective.iterations(), objective.iteration_trace(), objective.checkpoint_trace()};
}

inline Budget iterations(std::int64_t n) {
    return Budget{std::nullopt, n, std::nullopt};
}
inline Budget evaluations(std::int64_t n) {
    return Budget{n, std::nullopt, std::nullopt};
}

// Bit-for-bit equality of two outcomes: best f and x, the whole iteration trace (with best x
// at every iteration) and the checkpoint trace.
inline bool identical(const Outcome& a, const Outcome& b) {
    if (a.best_f != b.best_f || a.best_x != b.best_x || a.evaluations != b.evaluations ||
        a.iterations != b.iterations || a.iterations_trace.size() != b.iterations_trace.size() ||
        a.checkpoints.size() != b.checkpoints.size())
        return false;
    for (std::size_t t = 0; t < a.iterations_trace.size(); ++t) {
        const auto& p = a.iterations_trace[t];
        const auto& q = b.iterations_trace[t];
        if (p.iteration != q.iteration || p.evaluations != q.evaluations || p.best_f != q.best_f ||
            p.best_x != q.best_x)
            return false;
    }
    for (std::size_t t = 0; t < a.checkpoints.size(); ++t)
        if (a.checkpoints[t].evaluations != b.checkpoints[t].evaluations ||
            a.checkpoints[t].best_f != b.checkpoints[t].best_f)
            return false;
    return true;
}

// Evaluations charged by each iteration after the initialisation (for a population method whose
// iteration evaluates its population once, the population size N_G).
inline std::vector<std::int64_t> generation_sizes(const Outcome& out) {
    std::vector<std::int64_t> sizes;
    for (std::size_t i = 1; i < out.iterations_trace.size(); ++i)
        sizes.push_back(out.iterations_trace[i].evaluations - out.iterations_trace[i - 1].evaluations);
    return sizes;
}

// Linear population size reduction (L-SHADE and its descendants): the size after a generation that
// ended with `nfes` evaluations spent, from a population of `n`:
// round((4 - N_init) / MAX_NFE nfes + N_init), not below 4, never growing.
inline std::int64_t lpsr_planned_size(std::int64_t n, std::int64_t n_init, double max_nfe,
                                      std::int64_t nfes) {
    const double planned =
        std::round((4.0 - static_cast<double>(n_init)) / max_nfe * static_cast<double>(nfes) +
                   static_cast<double>(n_init));
    return std::min<std::int64_t>(n, std::max<std::int64_t>(4, static_cast<std::int64_t>(planned)));
}

// Every whole generation of `out` evaluated the population LPSR planned from N_init = n_init and
// MAX_NFE = max_nfe (the iteration a budget cut short is not in the trace). Returns the sizes.
inline std::vector<std::int64_t> expect_lpsr_schedule(const Outcome& out, std::int64_t n_init,
                                                      double max_nfe) {
    const auto sizes = generation_sizes(out);
    std::int64_t n = n_init;
    for (std::size_t g = 0; g < sizes.size(); ++g) {
        EXPECT_EQ(sizes[g], n) << "generation " << g + 1;
        EXPECT_GE(sizes[g], 4);
        n = lpsr_planned_size(n, n_init, max_nfe, out.iterations_trace[g + 1].evaluations);
    }
    return sizes;
}

// `spec` (an L-SHADE-family method with N_init = n_init at D = 10) on the 10-D sphere with 20 000
// evaluations: the budget is spent exactly, every whole generation has the size LPSR planned, and
// N_min = 4 comes only at the very end: round(N_init - (N_init - 4) nfes / MAX) = 4 needs
// nfes >= MAX (1 - 0.5 / (N_init - 4)), the last ceil(0.5 MAX / (N_init - 4)) evaluations.
inline void expect_lpsr_under_an_evaluation_budget(const std::string& spec, std::int64_t n_init,
                                                   std::uint64_t seed) {
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const std::int64_t budget = 20000;
    const Outcome out = run(spec, *sphere, seed, evaluations(budget));
    EXPECT_EQ(out.evaluations, budget);
    const auto sizes = expect_lpsr_schedule(out, n_init, static_cast<double>(budget));
    ASSERT_GT(sizes.size(), 100u);
    EXPECT_EQ(sizes.back(), 4);
    const auto last = static_cast<std::int64_t>(
        std::ceil(0.5 * static_cast<double>(budget) / static_cast<double>(n_init - 4)));
    for (std::size_t g = 0; g < sizes.size(); ++g)
        if (sizes[g] == 4) {
            EXPECT_GE(out.iterations_trace[g].evaluations, budget - last - 4) << "generation " << g + 1;
            break;
        }
    EXPECT_LT(budget - out.iterations_trace.back().evaluations, 4); // the cut generation had < 4 left
}

// `spec` on the 10-D sphere with 200 iterations: MAX_NFE is derived as for L-SHADE,
// G (N_init - N_min) / ln(N_init / N_min), every generation has the size LPSR planned from it,
// nothing but the populations is charged, and the last generations are at or a little above N_min.
inline void expect_lpsr_under_an_iteration_budget(const std::string& spec, std::int64_t n_init,
                                                  std::uint64_t seed) {
    const auto sphere = builtin_problems().create("sphere:dim=10");
    const std::int64_t generations = 200;
    const Outcome out = run(spec, *sphere, seed, iterations(generations));
    EXPECT_EQ(out.iterations, generations);
    const auto n = static_cast<double>(n_init);
    const double max_nfe = static_cast<double>(generations) * (n - 4.0) / std::log(n / 4.0);
    const auto sizes = expect_lpsr_schedule(out, n_init, max_nfe);
    ASSERT_EQ(sizes.size(), static_cast<std::size_t>(generations));
    std::int64_t spent = n_init;
    for (const std::int64_t size : sizes)
        spent += size;
    EXPECT_EQ(out.evaluations, spent);
    EXPECT_LE(sizes.back(), 12);
    EXPECT_NEAR(static_cast<double>(out.evaluations), max_nfe, 0.05 * max_nfe);
}

// Rosenbrock's valley, f(x) = sum 100 (x_{k+1} - x_k^2)^2 + (1 - x_k)^2 on [-5, 10]^D,
// f* = 0 at (1, ..., 1): non-separable, so coordinate-wise moves cannot solve it one axis at a time.
class Rosenbrock final : public Problem {
public:
    explicit Rosenbrock(Eigen::Index dimension)
        : box_{Eigen::VectorXd::Constant(dimension, -5.0), Eigen::VectorXd::Constant(dimension, 10.0)} {}
    std::string name() const override { return "rosenbrock"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        double f = 0.0;
        for (Eigen::Index k = 0; k + 1 < x.size(); ++k) {
            const double a = x[k + 1] - x[k] * x[k];
            const double b = 1.0 - x[k];
            f += 100.0 * a * a + b * b;
        }
        return f;
    }

private:
    Box box_;
};

// Wraps a problem and records every point evaluated, in order. Test-only: it has the hidden
// state a real Problem must not have, so it is used on one thread, for one run.
class RecordingProblem final : public Problem {
public:
    explicit RecordingProblem(const Problem& inner) : inner_(inner) {}
    std::string name() const override { return inner_.name(); }
    Eigen::Index dimension() const override { return inner_.dimension(); }
    const Box& bounds() const override { return inner_.bounds(); }
    double evaluate(const Eigen::VectorXd& x) const override {
        points.push_back(x);
        return inner_.evaluate(x);
    }
    double f(std::size_t n) const { return inner_.evaluate(points.at(n)); }

    mutable std::vector<Eigen::VectorXd> points;

private:
    const Problem& inner_;
};

inline std::unique_ptr<Problem> sphere(int dim) {
    return builtin_problems().create("sphere:dim=" + std::to_string(dim));
}

} // namespace mhb::test
