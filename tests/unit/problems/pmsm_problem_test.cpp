// Tests of the `pmsm` problem family as created through the registry (problems/pmsm/pmsm_family.cpp,
// steady_state_problem.*): parameters, bounds parsing, determinism, and the Problem contract.
#include <gtest/gtest.h>
#include <string>

#include "problems/pmsm/steady_state_problem.hpp"
#include "problems/problem_registry.hpp"
#include "support/data.hpp"

namespace mhb {
namespace {

using mhb::test_support::pmsm_data_dir;

std::string pmsm_spec_error_of(const std::string& spec) {
    try {
        (void)builtin_problems().create(spec);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "no error";
}

TEST(PmsmProblem, DefaultIsThePapersConditionAndBox) {
    const auto problem = builtin_problems().create("pmsm");
    EXPECT_EQ(problem->name(), "pmsm");
    EXPECT_EQ(problem->dimension(), 4);
    EXPECT_EQ(problem->parameter_names(), (std::vector<std::string>{"Rs", "Ld", "Lq", "psi"}));
    EXPECT_EQ(problem->bounds().lower, Eigen::Vector4d::Zero().eval());
    EXPECT_EQ(problem->bounds().upper, Eigen::Vector4d(0.5, 0.01, 0.01, 0.1));
    ASSERT_TRUE(problem->true_parameters().has_value());
    EXPECT_EQ(*problem->true_parameters(), Eigen::Vector4d(0.33, 3.24e-3, 3.24e-3, 0.0776));
    const auto known = problem->known_optimum();
    ASSERT_TRUE(known.has_value() && known->x.has_value());
    EXPECT_NEAR(problem->evaluate(*known->x), known->f, 1e-20);
    EXPECT_LT(known->f, 1e-8); // noise-free: see pmsm_least_squares_test
    // A point far from the optimum costs volts squared over 600 samples.
    EXPECT_GT(problem->evaluate(Eigen::Vector4d(0.1, 0.005, 0.005, 0.05)), 100.0);
}

TEST(PmsmProblem, IdenticalSpecGivesIdenticalDataBitForBit) {
    const std::string spec = "pmsm:speed=2000,load=3,noise_i=0.02,noise_u=0.5,seed=11";
    const auto a = builtin_problems().create(spec);
    const auto b = builtin_problems().create(spec);
    const auto& sa = dynamic_cast<const pmsm::SteadyStateProblem&>(*a).samples();
    const auto& sb = dynamic_cast<const pmsm::SteadyStateProblem&>(*b).samples();
    EXPECT_TRUE((sa.ud == sb.ud).all());
    EXPECT_TRUE((sa.iq == sb.iq).all());
    EXPECT_EQ(a->known_optimum()->f, b->known_optimum()->f);
    const auto c = builtin_problems().create("pmsm:speed=2000,load=3,noise_i=0.02,noise_u=0.5,seed=12");
    EXPECT_NE(a->known_optimum()->f, c->known_optimum()->f);
}

TEST(PmsmProblem, ReadsAUsersDataset) {
    const auto problem =
        builtin_problems().create("pmsm:data=" + pmsm_data_dir + "pmsm_public_2200rpm_2.5Nm_noisy_ss.csv");
    // expected.csv: f_ls = 45.077285948014918 for this file.
    EXPECT_NEAR(problem->known_optimum()->f, 45.077285948014918, 1e-7);
    EXPECT_EQ(dynamic_cast<const pmsm::SteadyStateProblem&>(*problem).samples().pairs, 150);
}

TEST(PmsmProblem, BoundsAreOverridableAndCheckedWithClearErrors) {
    const auto problem = builtin_problems().create("pmsm:rs=0.1:1,psi=0.05:0.2,n=50");
    EXPECT_EQ(problem->bounds().lower[0], 0.1);
    EXPECT_EQ(problem->bounds().upper[0], 1.0);
    EXPECT_EQ(problem->bounds().lower[3], 0.05);
    EXPECT_EQ(problem->bounds().upper[3], 0.2);
    EXPECT_EQ(problem->bounds().upper[1], 0.01);
    EXPECT_EQ(pmsm_spec_error_of("pmsm:rs=0.5:0.1"), "pmsm: parameter 'rs' = 0.5:0.1 needs lo < hi");
    EXPECT_EQ(pmsm_spec_error_of("pmsm:ld=0.001"),
              "pmsm: parameter 'ld' = 0.001 is not of the form lo:hi (two finite numbers, e.g. 0:0.5)");
    EXPECT_EQ(pmsm_spec_error_of("pmsm:lq=a:b"),
              "pmsm: parameter 'lq' = a:b is not of the form lo:hi (two finite numbers, e.g. 0:0.5)");
    EXPECT_EQ(pmsm_spec_error_of("pmsm:psi=0:inf"),
              "pmsm: parameter 'psi' = 0:inf is not of the form lo:hi (two finite numbers, e.g. 0:0.5)");
    EXPECT_EQ(pmsm_spec_error_of("pmsm:rs=0.2:0.2"), "pmsm: parameter 'rs' = 0.2:0.2 needs lo < hi");
}

TEST(PmsmProblem, RejectsBadParameters) {
    EXPECT_EQ(pmsm_spec_error_of("pmsm:n=501"), "pmsm: parameter 'n' = 501 is outside [2, 500]");
    EXPECT_EQ(pmsm_spec_error_of("pmsm:noise_i=-1"), "pmsm: parameter 'noise_i' = -1 is outside [0, 10]");
    EXPECT_EQ(pmsm_spec_error_of("pmsm:data=x.csv,speed=2000,seed=3"),
              "pmsm: 'data' reads datasets; the simulator parameters (speed, seed) cannot be given with it");
    EXPECT_THROW((void)builtin_problems().create("pmsm:data=/nonexistent.csv"), std::runtime_error);
}

TEST(PmsmProblem, WeightsChangeTheFitness) {
    const auto equal = builtin_problems().create("pmsm:n=20");
    const auto heavy = builtin_problems().create("pmsm:n=20,w1=1,w2=1,w3=1,w4=1");
    const Eigen::VectorXd x = Eigen::Vector4d(0.2, 0.004, 0.003, 0.07);
    EXPECT_NEAR(heavy->evaluate(x), 4.0 * equal->evaluate(x), 1e-9 * heavy->evaluate(x));
}

} // namespace
} // namespace mhb
