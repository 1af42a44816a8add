// Sphere, f(x) = sum x_i^2 on [-100, 100]^D, f* = 0 at the origin. The simplest smooth,
// separable, unimodal test; used throughout the tests as the cheap reference problem.
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

class Sphere final : public Problem {
public:
    Sphere(Eigen::Index dimension, double half_width)
        : box_{Eigen::VectorXd::Constant(dimension, -half_width), Eigen::VectorXd::Constant(dimension, half_width)} {}

    std::string name() const override { return "sphere"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override { return x.squaredNorm(); }
    std::optional<KnownOptimum> known_optimum() const override {
        return KnownOptimum{0.0, Eigen::VectorXd::Zero(box_.dimension())};
    }

private:
    Box box_;
};

} // namespace

void register_sphere(ProblemRegistry& registry) {
    registry.add({"sphere",
                  "sum of squares; separable, unimodal, f* = 0 at the origin",
                  "De Jong (1975)",
                  {ParameterInfo::integer("dim", 10, 1, 10000, "dimension"),
                   ParameterInfo::real("bound", 100.0, 0.0, 1e12, "half-width of the box [-bound, bound]^dim")
                       .open_below()},
                  [](const ParameterValues& p) -> std::unique_ptr<Problem> {
                      return std::make_unique<Sphere>(static_cast<Eigen::Index>(p.integer("dim")), p.real("bound"));
                  }});
}

} // namespace mhb
