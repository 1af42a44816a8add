// Example: extending mhbench with your own problem and your own optimiser, then running them in a
// study beside the built-in ones. This is the whole of what a user writes; it is built and run as a
// test so that it keeps working.
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

#include "algorithms/algorithm_registry.hpp"
#include "algorithms/sampling.hpp"
#include "problems/problem_registry.hpp"
#include "results/store.hpp"
#include "runner/parallel_runner.hpp"
#include "runner/study.hpp"
#include "runner/study_file.hpp"

namespace {

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

TEST(ExtensionExample, OwnProblemAndOptimiserRunInAStudyBesideBuiltInOnes) {
    // 3. Registration: the built-in components plus one entry each.
    mhb::AlgorithmRegistry algorithms("algorithm");
    mhb::register_builtin_algorithms(algorithms);
    algorithms.add(
        {"one-plus-one",
         1,
         "(1+1)-ES with a fixed Gaussian step",
         "Rechenberg (1973)",
         {mhb::ParameterInfo::real("step", 0.1, 0.0, 1e6, "standard deviation of the step").open_below()},
         [](const mhb::ParameterValues& p) -> std::unique_ptr<mhb::Optimizer> {
             return std::make_unique<OnePlusOne>(p.real("step"));
         }});
    mhb::ProblemRegistry problems("problem");
    mhb::register_builtin_problems(problems);
    problems.add({"booth",
                  1,
                  "Booth's function, f* = 0 at (1, 3)",
                  "Jamil, Yang (2013), test function 12",
                  {},
                  [](const mhb::ParameterValues&) -> std::unique_ptr<mhb::Problem> {
                      return std::make_unique<Booth>();
                  }});

    // 4. A study, as `mhbench run` would make it.
    mhb::Study study;
    study.algorithms = {"one-plus-one:step=0.5", "tlbo:np=10"};
    study.problems = {"booth", "sphere:dim=2"};
    study.runs = 3;
    study.budgets.front().max_evaluations = 2000;
    const mhb::PreparedStudy prepared = mhb::prepare_study(study, algorithms, problems);
    const auto dir = std::filesystem::temp_directory_path() / ("mhb_extension_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    mhb::StudyWriter writer(dir, mhb::study_ini(prepared.study), "", prepared.parameter_columns, false);
    ASSERT_EQ(mhb::run_study(prepared, writer).kept, 12);

    for (const auto& r : mhb::load_study(dir).runs) {
        EXPECT_TRUE(r.ok) << r.message;
        EXPECT_EQ(r.evaluations, 2000);
        // A fixed step of 0.5 stalls at an error of order 1e-3; TLBO goes much further.
        EXPECT_LT(*r.error(), r.algorithm.rfind("tlbo", 0) == 0 ? 1e-10 : 1e-2)
            << r.algorithm << " on " << r.problem;
    }
    EXPECT_THROW(
        (void)mhb::prepare_study(
            mhb::Study{
                {"one-plus-one:step=0"}, {"booth"}, {}, {}, 1, 1, mhb::SeedMode::common, study.budgets},
            algorithms, problems),
        std::invalid_argument);
    std::filesystem::remove_all(dir);
}

} // namespace
