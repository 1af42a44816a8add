// The `pmsm` family end to end: any motor simulated and identified by the three models, search
// boxes from the motor's values or the spec, the warning when the box cuts the optimum, several
// conditions or files fitted jointly, the steady model's settle rule, and the refusals.
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"
#include "problems/pmsm/steady_state_data.hpp"
#include "problems/pmsm/steady_state_problem.hpp"
#include "problems/problem_registry.hpp"
#include "support/numbers.hpp"

namespace mhb {
namespace {

using mhb::test_support::max_relative_error;

std::unique_ptr<Problem> make_pmsm_model(const std::string& spec) {
    return builtin_problems().create(Spec::parse(spec));
}

// An interior-PM motor (Ld 6 mH != Lq 14 mH) simulated without noise is recovered by each model:
// the exact optimum of the two linear models and the best known optimum of the output-error one.
TEST(PmsmModels, AnInteriorPmMotorIsRecoveredByEveryModel) {
    const Eigen::Vector4d truth = pmsm::ipm_motor().identified();
    // Tolerances a few times what was measured: steady 3e-7, dynamic 1.3e-4 (the discrete
    // equations' own error; the issue asks for 0.05 %), output 2e-6 (RK4 at 2 substeps against
    // the simulator's 10 with the speed known only at samples).
    const std::pair<const char*, double> cases[] = {{"steady", 1e-5}, {"dynamic", 5e-4}, {"output", 2e-5}};
    for (const auto& [model, tolerance] : cases) {
        const auto problem = make_pmsm_model(std::string("pmsm:motor=ipm,speed=1800,load=4,model=") + model);
        ASSERT_EQ(problem->dimension(), 4) << model;
        const auto optimum = problem->known_optimum();
        ASSERT_TRUE(optimum && optimum->x) << model;
        EXPECT_LT(max_relative_error(*optimum->x, truth), tolerance)
            << model << ": " << optimum->x->transpose();
        ASSERT_TRUE(problem->true_parameters());
        EXPECT_EQ(*problem->true_parameters(), Eigen::VectorXd(truth)) << model;
        // The box is [0, 3 x nominal] for a motor other than the paper's.
        EXPECT_EQ(problem->bounds().upper, Eigen::VectorXd(3.0 * truth)) << model;
        EXPECT_TRUE(problem->warnings().empty()) << model;
    }
}

TEST(PmsmModels, ThePaperMotorKeepsThePaperBoxAndTheSpecOverridesIt) {
    EXPECT_EQ(make_pmsm_model("pmsm")->bounds().upper, pmsm::paper_bounds().upper);
    const auto dynamic = make_pmsm_model("pmsm:model=dynamic,ld=0.001:0.02");
    EXPECT_EQ(dynamic->bounds().lower[1], 0.001);
    EXPECT_EQ(dynamic->bounds().upper[1], 0.02);
    EXPECT_EQ(dynamic->bounds().upper[0], 0.5);
}

// A box that excludes the motor's Rs: f* is the box-constrained optimum, and the problem says so.
TEST(PmsmModels, ABoxThatCutsTheOptimumIsWarnedAbout) {
    for (const char* model : {"steady", "dynamic", "output"}) {
        const auto problem = make_pmsm_model(std::string("pmsm:rs=0:0.2,model=") + model);
        const auto warnings = problem->warnings();
        ASSERT_EQ(warnings.size(), 1u) << model;
        EXPECT_NE(warnings[0].find("Rs"), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find("rs="), std::string::npos) << warnings[0];
        EXPECT_NEAR(problem->known_optimum()->x->coeff(0), 0.2, 1e-12) << model;
        EXPECT_TRUE(make_pmsm_model(std::string("pmsm:model=") + model)->warnings().empty()) << model;
    }
}

TEST(PmsmModels, TheDeadTimeVoltageIsAFifthParameter) {
    const auto problem = make_pmsm_model("pmsm:model=dynamic,fit_vdt=on,deadtime=5e-7");
    ASSERT_EQ(problem->dimension(), 5);
    EXPECT_EQ(problem->parameter_names().back(), "Vdt");
    EXPECT_EQ(problem->bounds().upper[4], 20.0);
    // The truth holds the fundamental of the simulated dead time: (4 / pi) Vdc t_dead / Ts.
    EXPECT_NEAR(problem->true_parameters()->coeff(4), 4.0 / M_PI * 540.0 * 5e-7 / 1e-4, 1e-12);
}

// conditions=paper simulates the paper's three conditions and fits them jointly: eq. 11 of the
// three is the sum of eq. 11 of each.
TEST(PmsmModels, SeveralConditionsAreFittedJointly) {
    const auto joint = make_pmsm_model("pmsm:conditions=paper");
    const auto a = make_pmsm_model("pmsm:speed=2500,load=2");
    const auto* steady = dynamic_cast<const pmsm::SteadyStateProblem*>(joint.get());
    ASSERT_NE(steady, nullptr);
    EXPECT_EQ(steady->samples().pairs, 900);
    // The first condition keeps the seed, so its data are the single condition's.
    const auto* single = dynamic_cast<const pmsm::SteadyStateProblem*>(a.get());
    EXPECT_TRUE((steady->samples().ud.head(600) == single->samples().ud).all());
}

TEST(PmsmModels, SeveralFilesAreFittedJointlyAndEachIsNamedByItsContent) {
    pmsm::SimulatorConfig config;
    config.condition = {2500, 2};
    const std::string a = testing::TempDir() + "joint_a.csv";
    const std::string b = testing::TempDir() + "joint_b.csv";
    pmsm::write_dataset_csv(a, pmsm::simulate_dataset(config));
    config.condition = {2000, 2};
    pmsm::write_dataset_csv(b, pmsm::simulate_dataset(config));
    const auto joint = make_pmsm_model("pmsm:fitness=direct,data=" + a + "+" + b);
    const auto pa = make_pmsm_model("pmsm:fitness=direct,data=" + a);
    const auto pb = make_pmsm_model("pmsm:fitness=direct,data=" + b);
    ASSERT_EQ(joint->data_files().size(), 2u);
    EXPECT_EQ(joint->data_files()[1].sha256, pb->data_files()[0].sha256);
    const Eigen::VectorXd x = Eigen::Vector4d(0.3, 0.003, 0.0035, 0.07);
    EXPECT_NEAR(joint->evaluate(x), pa->evaluate(x) + pb->evaluate(x), 1e-12 * joint->evaluate(x));
    EXPECT_THROW(make_pmsm_model("pmsm:data=" + a + "+" + a), std::invalid_argument);
}

// The settle rule: after a switch seen between consecutive rows, 10 ms of the new state are left
// out; across a jump in t nothing is; the last n rows of each state are paired.
TEST(PmsmModels, TheSteadyModelPairsTheSettledEndsOfThePlateaus) {
    pmsm::Dataset consecutive, jumped;
    for (int k = 0; k < 400; ++k) {
        const bool on = k >= 200;
        // iq marks the row, so the rows used can be read back.
        consecutive.push_back(k * 1e-4, 1, 2, on ? -2.0 : 0.0, k, 500, on);
        jumped.push_back(k * 1e-4 + (on ? 0.035 : 0.0), 1, 2, on ? -2.0 : 0.0, k, 500, on);
    }
    const pmsm::SteadyStateData s = pmsm::pair_samples(consecutive);
    ASSERT_EQ(s.pairs, 100);     // 200 id = 0 rows, 200 - 100 settled injected rows
    EXPECT_EQ(s.iq[0], 100.0);   // the last 100 of the id = 0 state
    EXPECT_EQ(s.iq[100], 300.0); // injected rows 300-399: 10 ms after the switch at row 200
    EXPECT_EQ(pmsm::pair_samples(jumped).pairs, 200);
    EXPECT_EQ(pmsm::pair_samples(consecutive, {}, 0.0).pairs, 200);
    EXPECT_THROW(pmsm::pair_samples(consecutive, {}, 0.05), std::invalid_argument); // nothing settled
}

TEST(PmsmModels, ClashingParametersAreRefused) {
    const char* refused[] = {"pmsm:conditions=paper,speed=2000", "pmsm:vdt=0:5",
                             "pmsm:model=dynamic,w1=1",          "pmsm:model=steady,smooth=2",
                             "pmsm:conditions=2500@x",           "pmsm:model=output,settle=0.1"};
    for (const char* spec : refused)
        EXPECT_THROW(make_pmsm_model(spec), std::invalid_argument) << spec;
}

} // namespace
} // namespace mhb
