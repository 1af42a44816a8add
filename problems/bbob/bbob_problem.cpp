// The `bbob` problem family: COCO's noiseless BBOB suite, 24 functions in dimension 2-40, by
// instance number, on [-5, 5]^D, with f_opt and x_opt known. `bbob:f=1-24,dim=10,instance=1-5`
// expands into the 120 problems of a suite run.
#include <string>

#include "problems/bbob/bbob_function.hpp"
#include "problems/bbob/bbob_random.hpp"
#include "problems/bbob/bbob_transforms.hpp"
#include "problems/problem_registry.hpp"

namespace mhb {
namespace {

const char* const bbob_names[24] = {"sphere",
                                    "ellipsoid (separable)",
                                    "Rastrigin (separable)",
                                    "Bueche-Rastrigin",
                                    "linear slope",
                                    "attractive sector",
                                    "step ellipsoid",
                                    "Rosenbrock (original)",
                                    "Rosenbrock (rotated)",
                                    "ellipsoid",
                                    "discus",
                                    "bent cigar",
                                    "sharp ridge",
                                    "different powers",
                                    "Rastrigin",
                                    "Weierstrass",
                                    "Schaffers F7",
                                    "Schaffers F7 (ill-conditioned)",
                                    "Griewank-Rosenbrock F8F2",
                                    "Schwefel x sin(sqrt|x|)",
                                    "Gallagher 101 peaks",
                                    "Gallagher 21 peaks",
                                    "Katsuura",
                                    "Lunacek bi-Rastrigin"};

class BbobProblem final : public Problem {
public:
    BbobProblem(int function, Eigen::Index dimension, std::int64_t instance)
        : function_(bbob::make_function(function, dimension, instance)),
          box_{Eigen::VectorXd::Constant(dimension, -5.0), Eigen::VectorXd::Constant(dimension, 5.0)},
          // f* is COCO's f_opt by definition; f(x_opt) equals it to within rounding.
          optimum_{bbob::legacy_fopt(function, instance), function_->x_opt()} {}

    std::string name() const override { return "bbob"; }
    Eigen::Index dimension() const override { return box_.dimension(); }
    const Box& bounds() const override { return box_; }
    double evaluate(const Eigen::VectorXd& x) const override { return function_->value(x); }
    std::optional<KnownOptimum> known_optimum() const override { return optimum_; }

private:
    std::unique_ptr<bbob::Function> function_;
    Box box_;
    KnownOptimum optimum_;
};

std::string bbob_function_help() {
    std::string s = "function number:";
    for (int f = 0; f < 24; ++f)
        s.append(f == 0 ? " " : ", ").append(std::to_string(f + 1)).append(" ").append(bbob_names[f]);
    return s + "; a range such as 1-24 expands";
}

} // namespace

void register_bbob(ProblemRegistry& registry) {
    registry.add(
        {"bbob",
         1,
         "COCO's noiseless BBOB suite, 24 functions exact to COCO, by instance number, on [-5, 5]^dim; "
         "f* and x* known",
         "Hansen, Finck, Ros, Auger (2009), Real-parameter black-box optimization benchmarking 2009: "
         "noiseless functions definitions, INRIA RR-6829; instances as in COCO (numbbo/coco)",
         {ParameterInfo::integer("f", 1, 1, 24, bbob_function_help()).ranged(),
          ParameterInfo::integer("dim", 10, 2, bbob::max_dimension,
                                 "dimension (COCO's 2, 3, 5, 10, 20, 40 and "
                                 "any other from 2 to 40)"),
          ParameterInfo::integer("instance", 1, 1, 100000,
                                 "instance number (x_opt, f_opt, rotations from seed f + 10000 instance); "
                                 "a range such as 1-5 expands")
              .ranged()},
         [](const ParameterValues& p) -> std::unique_ptr<Problem> {
             return std::make_unique<BbobProblem>(static_cast<int>(p.integer("f")),
                                                  static_cast<Eigen::Index>(p.integer("dim")),
                                                  static_cast<std::int64_t>(p.integer("instance")));
         }});
}

} // namespace mhb
