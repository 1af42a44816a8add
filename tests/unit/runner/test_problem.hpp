// A small configurable problem for the runner's tests: f on [0, 1]^dimension, with optional
// parameter names and known optimum, so a test can build exactly the case it checks (no optimum,
// named parameters, a NaN) without a new Problem class each time.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "problems/problem_registry.hpp"

namespace mhb::test {

class TestProblem final : public Problem {
public:
    using Function = std::function<double(const Eigen::VectorXd&)>;

    TestProblem(Eigen::Index dimension, Function f, std::vector<std::string> names = {},
                std::optional<KnownOptimum> optimum = std::nullopt)
        : box_{Eigen::VectorXd::Zero(dimension), Eigen::VectorXd::Ones(dimension)}, f_(std::move(f)),
          names_(std::move(names)), optimum_(std::move(optimum)) {}

    std::string name() const override { return "test"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override { return f_(x); }
    std::optional<KnownOptimum> known_optimum() const override { return optimum_; }
    std::vector<std::string> parameter_names() const override { return names_; }

private:
    Box box_;
    Function f_;
    std::vector<std::string> names_;
    std::optional<KnownOptimum> optimum_;
};

// A registry holding one family `name` made by `factory`, with the declared parameters.
inline ProblemRegistry registry_of(std::string name, ProblemRegistry::Factory factory,
                                   std::vector<ParameterInfo> parameters = {}) {
    ProblemRegistry registry("problem");
    registry.add({std::move(name), 1, "a test problem", "", std::move(parameters), std::move(factory)});
    return registry;
}

} // namespace mhb::test
