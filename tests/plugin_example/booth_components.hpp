// The example components of tests/plugin_example: Booth's function and a (1+1) evolution
// strategy, with their registration. One header shared by the two ways of adding them to mhbench,
// so that both run the same code: compiled into a program that links mhbench's libraries
// (tests/integration/extension_example_test.cpp), or built as a plug-in module against the
// installed package (booth_plugin.cpp, this folder's CMakeLists.txt).
#pragma once

#include <cmath>
#include <memory>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"
#include "problems/problem_registry.hpp"

namespace booth_example {

// 1. A problem: the Booth function, f(x, y) = (x + 2y - 7)^2 + (2x + y - 5)^2 on [-10, 10]^2,
//    minimum 0 at (1, 3). evaluate() is const and keeps no state.
class Booth final : public mhb::Problem {
public:
    std::string name() const override { return "booth"; }
    Eigen::Index dimension() const override { return 2; }
    const mhb::Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override {
        return std::pow(x[0] + 2 * x[1] - 7, 2) + std::pow(2 * x[0] + x[1] - 5, 2);
    }
    std::optional<mhb::KnownOptimum> known_optimum() const override {
        return mhb::KnownOptimum{0.0, Eigen::Vector2d(1.0, 3.0)};
    }

private:
    mhb::Box box_{Eigen::Vector2d(-10, -10), Eigen::Vector2d(10, 10)};
};

// 2. An optimiser: a (1+1) evolution strategy with a fixed step, as simple as they come. It holds
//    only its parameter; the objective and the random stream are passed in.
class OnePlusOne final : public mhb::Optimizer {
public:
    explicit OnePlusOne(double step) : step_(step) {}
    std::string name() const override { return "one-plus-one"; }
    void run(mhb::Objective& objective, mhb::Rng& rng) const override {
        Eigen::VectorXd parent = mhb::uniform_point(objective.bounds(), rng);
        double f_parent = objective.evaluate(parent);
        objective.initialised();
        Eigen::VectorXd child(parent.size());
        while (!objective.exhausted()) {
            for (Eigen::Index k = 0; k < child.size(); ++k)
                child[k] = parent[k] + step_ * rng.normal();
            const double f = objective.evaluate(child); // counted; repaired into the box
            if (f < f_parent) {
                parent = child;
                f_parent = f;
            }
            objective.end_iteration();
        }
    }

private:
    double step_;
};

// 3. Registration: one entry each, into whatever registries the caller holds (mhbench's, when
//    it loads the plug-in; the built-ins plus these, in the in-tree example).
inline void register_components(mhb::AlgorithmRegistry& algorithms, mhb::ProblemRegistry& problems) {
    algorithms.add(
        {"one-plus-one",
         1,
         "(1+1)-ES with a fixed Gaussian step",
         "Rechenberg (1973)",
         {mhb::ParameterInfo::real("step", 0.1, 0.0, 1e6, "standard deviation of the step").open_below()},
         [](const mhb::ParameterValues& p) -> std::unique_ptr<mhb::Optimizer> {
             return std::make_unique<OnePlusOne>(p.real("step"));
         }});
    problems.add({"booth",
                  1,
                  "Booth's function, f* = 0 at (1, 3)",
                  "Jamil, Yang (2013), test function 12",
                  {},
                  [](const mhb::ParameterValues&) -> std::unique_ptr<mhb::Problem> {
                      return std::make_unique<Booth>();
                  }});
}

} // namespace booth_example
