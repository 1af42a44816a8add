// A plug-in that registers a problem under a built-in's name ("sphere"): mhbench must refuse it
// (tests/integration/plugin_test.cpp), not replace or shadow the built-in.
#include "problems/problem.hpp"
#include "runner/plugin_api.hpp"

namespace {

class Flat final : public mhb::Problem {
public:
    std::string name() const override { return "sphere"; }
    Eigen::Index dimension() const override { return 1; }
    const mhb::Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd&) const override { return 0.0; }

private:
    mhb::Box box_{Eigen::VectorXd::Constant(1, -1.0), Eigen::VectorXd::Constant(1, 1.0)};
};

void register_flat(mhb::AlgorithmRegistry&, mhb::ProblemRegistry& problems) {
    problems.add({"sphere", 1, "a flat function under a taken name", "", {}, [](const mhb::ParameterValues&) {
                      return std::unique_ptr<mhb::Problem>(std::make_unique<Flat>());
                  }});
}

} // namespace

MHBENCH_PLUGIN("clash", register_flat)
