// End-to-end tests of `mhbench simulate` and `mhbench identify` (runner/cli/simulate_command.cpp,
// identify_command.cpp): files written, read back, exit codes and one-line errors.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "cli_harness.hpp"
#include "problems/pmsm/dataset_csv.hpp"
#include "problems/pmsm/drive_simulator.hpp"

namespace {

struct PmsmCliResult {
    int exit_code = -1;
    std::string output; // stdout and stderr together
};

PmsmCliResult run_pmsm_cli(const std::string& arguments) {
    const auto r = mhb::testing_cli::run_mhbench(arguments);
    return {r.exit_code, r.out + r.err};
}

using mhb::testing_cli::read_text;

// The written file is what the library simulates for the same settings, bit for bit (the CSV
// holds every double exactly), and two runs write identical bytes.
TEST(PmsmCli, SimulateWritesTheDatasetOfTheLibrary) {
    const std::string a = testing::TempDir() + "pmsm_sim_a.csv";
    const std::string b = testing::TempDir() + "pmsm_sim_b.csv";
    const std::string options = " --speed 2000 --load 3 --noise-i 0.02 --noise-u 0.5 --seed 9 --samples 100";
    ASSERT_EQ(run_pmsm_cli("simulate --out " + a + options).exit_code, 0);
    ASSERT_EQ(run_pmsm_cli("simulate --out " + b + options).exit_code, 0);
    EXPECT_EQ(read_text(a), read_text(b));

    mhb::pmsm::SimulatorConfig config;
    config.condition = {2000.0, 3.0};
    config.noise_i = 0.02;
    config.noise_u = 0.5;
    config.seed = 9;
    config.samples_per_state = 100;
    const mhb::pmsm::Dataset expected = mhb::pmsm::simulate_dataset(config);
    const mhb::pmsm::Dataset written = mhb::pmsm::read_dataset_csv(a);
    EXPECT_EQ(written.ud, expected.ud);
    EXPECT_EQ(written.iq, expected.iq);
    EXPECT_EQ(written.injected, expected.injected);
    EXPECT_EQ(*written.find_metadata("speed_rpm"), "2000");
}

TEST(PmsmCli, SimulateErrorsAreOneLineWithNonZeroExit) {
    PmsmCliResult r = run_pmsm_cli("simulate");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.output, "mhbench simulate: --out FILE is required (see mhbench simulate --help)\n");
    r = run_pmsm_cli("simulate --out " + testing::TempDir() + "x.csv --samples 501");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.output, "mhbench simulate: --samples = 501 is outside [1, 500]\n");
    r = run_pmsm_cli("simulate --out " + testing::TempDir() + "x.csv --load abc");
    EXPECT_EQ(r.exit_code, 2);
    r = run_pmsm_cli("simulate --out /nonexistent-dir/x.csv");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.output,
              "mhbench simulate: /nonexistent-dir/x.csv: cannot be written (No such file or directory)\n");
    r = run_pmsm_cli("simulate --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("--noise-u"), std::string::npos);
}

// identify on the shared noisy file prints the least-squares optimum of expected.csv
// (Rs_ls = 0.35919398646..., psi_ls = 0.07691100150...) and the errors against the truth.
TEST(PmsmCli, IdentifyReportsTheLeastSquaresEstimate) {
    const PmsmCliResult r = run_pmsm_cli("identify --data " + std::string(MHB_TEST_DATA_DIR) +
                                         "/pmsm/pmsm_public_2200rpm_2.5Nm_noisy_ss.csv");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("0.35919399"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("0.076911002"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("+8.85 %"), std::string::npos) << r.output; // Rs error against 0.33
    EXPECT_NE(r.output.find("f* (eq. 11 at the estimate) = 45.07728595"), std::string::npos) << r.output;

    const std::string bad = testing::TempDir() + "pmsm_bad.csv";
    std::ofstream(bad) << "t,ud,uq,id,iq,omega\n0,1,2,0,8,500\n0,1,x,-2,8,500\n";
    const PmsmCliResult e = run_pmsm_cli("identify --data " + bad);
    EXPECT_EQ(e.exit_code, 1);
    EXPECT_EQ(e.output, "mhbench identify: " + bad + ": line 3, column 'uq': 'x' is not a number\n");
}

} // namespace
