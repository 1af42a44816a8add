// `mhbench identify` judges what a dataset determines: on crafted data whose information is known
// by construction (no injection, a tiny injection, one constant speed, noise only) each verdict
// must name the parameters the data cannot give and say what to change; on the shared clean
// file every parameter is determined.
#include <gtest/gtest.h>
#include <string>

#include "cli_harness.hpp"
#include "problems/core/rng.hpp"
#include "problems/pmsm/dataset_csv.hpp"

namespace {

using mhb::pmsm::Dataset;

std::string run_identify(const Dataset& data, const std::string& name, const std::string& options = "") {
    const std::string path = testing::TempDir() + "verdict_" + name + ".csv";
    mhb::pmsm::write_dataset_csv(path, data);
    const auto r = mhb::testing_cli::run_mhbench("identify --data " + path + options);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    return r.out + r.err;
}

bool output_says(const std::string& output, const std::string& line) {
    return output.find(line) != std::string::npos;
}

// Steady-state rows of the paper's motor (eq. 2) at one speed, the d current alternating in
// blocks between 0 and `injection`, with Gaussian voltage noise.
Dataset steady_rows(double injection, double noise, std::uint64_t seed) {
    const double Rs = 0.33, Ld = 3.24e-3, Lq = 3.24e-3, psi = 0.0776, w = 500.0, iq = 8.0;
    mhb::Rng rng(seed);
    Dataset d;
    for (int k = 0; k < 400; ++k) {
        const bool on = k >= 200;
        const double id = on ? injection : 0.0;
        d.push_back(k * 1e-4, Rs * id - Lq * w * iq + noise * rng.normal(),
                    Rs * iq + Ld * w * id + psi * w + noise * rng.normal(), id, iq, w, on);
    }
    return d;
}

TEST(IdentifyVerdicts, NoInjectionLeavesLdUndetermined) {
    const std::string out = run_identify(steady_rows(0.0, 0.1, 1), "none");
    EXPECT_TRUE(output_says(out, "Ld: not identifiable from this data")) << out;
    EXPECT_TRUE(output_says(out, "inject a larger d-axis current")) << out;
    // Rs iq and psi omega are both constant: one column is a multiple of the other.
    EXPECT_TRUE(output_says(out, "Rs: not identifiable from this data")) << out;
    EXPECT_TRUE(output_says(out, "psi: not identifiable from this data")) << out;
    EXPECT_TRUE(output_says(out, "Lq: determined")) << out;
}

TEST(IdentifyVerdicts, ATinyInjectionDeterminesLdPoorly) {
    const std::string out = run_identify(steady_rows(-0.02, 0.5, 2), "tiny");
    EXPECT_FALSE(output_says(out, "Ld: determined")) << out;
    EXPECT_FALSE(output_says(out, "Rs: determined")) << out;
    EXPECT_TRUE(output_says(out, "Lq: determined")) << out;
    // A -2 A injection with the same noise determines Ld.
    const std::string good = run_identify(steady_rows(-2.0, 0.5, 2), "normal");
    EXPECT_TRUE(output_says(good, "Ld: determined")) << good;
}

// The dynamic model at one constant speed with constant currents: no di/dt, no d current, and
// Rs iq against psi omega cannot be told apart.
TEST(IdentifyVerdicts, ConstantSpeedAndCurrentsDetermineOnlyLq) {
    Dataset d;
    mhb::Rng rng(3);
    for (int k = 0; k < 300; ++k)
        d.push_back(k * 1e-4, -3.24e-3 * 500 * 8 + 0.1 * rng.normal(),
                    0.33 * 8 + 0.0776 * 500 + 0.1 * rng.normal(), 0.0, 8.0, 500.0, false);
    const std::string out = run_identify(d, "constant", " --model dynamic");
    EXPECT_TRUE(output_says(out, "Lq: determined")) << out;
    for (const char* p : {"Rs", "Ld", "psi"})
        EXPECT_TRUE(output_says(out, std::string(p) + ": not identifiable from this data")) << out;
    EXPECT_TRUE(output_says(out, "record several speeds")) << out;
    EXPECT_TRUE(output_says(out, "include d-current steps")) << out;
}

TEST(IdentifyVerdicts, NoiseOnlyDeterminesNothing) {
    Dataset d;
    mhb::Rng rng(4);
    for (int k = 0; k < 400; ++k)
        d.push_back(k * 1e-4, rng.normal(), rng.normal(), rng.normal(), rng.normal(), 500 + rng.normal(),
                    k >= 200);
    const std::string out = run_identify(d, "noise");
    int not_identifiable = 0;
    for (const char* p : {"Rs", "Ld", "Lq", "psi"})
        not_identifiable += output_says(out, std::string(p) + ": not identifiable from this data") ? 1 : 0;
    EXPECT_GE(not_identifiable, 3) << out;
}

// At standstill only Rs acts; with as many equations as parameters nothing is left to judge by.
TEST(IdentifyVerdicts, StandstillAndTooFewSamplesAreSaidPlainly) {
    Dataset standstill;
    for (int k = 0; k < 40; ++k)
        standstill.push_back(k * 1e-4, 0.33 * (k < 20 ? 0.0 : -2.0) + 0.01 * (k % 3),
                             0.33 * 8 + 0.01 * (k % 5), k < 20 ? 0.0 : -2.0, 8.0, 0.0, k >= 20);
    const std::string out = run_identify(standstill, "standstill");
    EXPECT_TRUE(output_says(out, "Rs: determined")) << out;
    for (const char* p : {"Ld", "Lq", "psi"})
        EXPECT_TRUE(output_says(out, std::string(p) +
                                         ": not identifiable from this data (the data leave it undetermined"))
            << out;
    EXPECT_FALSE(output_says(out, "nan")) << out;
    EXPECT_FALSE(output_says(out, "inf ")) << out;

    Dataset four = steady_rows(-2.0, 0.0, 5);
    Dataset two_by_two;
    for (const std::size_t k : {0u, 200u, 201u, 202u})
        two_by_two.push_back(four.t[k], four.ud[k], four.uq[k], four.id[k], four.iq[k], four.omega[k],
                             four.injected[k]);
    const std::string few = run_identify(two_by_two, "few");
    EXPECT_TRUE(output_says(few, "no residual is left to estimate its error from")) << few;
    EXPECT_FALSE(output_says(few, "nan")) << few;
}

TEST(IdentifyVerdicts, TheSharedCleanFileDeterminesEverything) {
    const auto r = mhb::testing_cli::run_mhbench("identify --data " + std::string(MHB_TEST_DATA_DIR) +
                                                 "/pmsm/pmsm_public_2200rpm_2.5Nm_clean_ss.csv");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* p : {"Rs", "Ld", "Lq", "psi"})
        EXPECT_TRUE(output_says(r.out, std::string(p) + ": determined")) << r.out;
}

} // namespace
