// Helpers for the tests of the paper's algorithms (TLBO, ITLBO, PSO): one run turned into a
// comparable outcome, a non-separable test function, and a problem that records every point
// it is asked to evaluate (so tests can check what an optimiser evaluated, in order).
#pragma once

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
