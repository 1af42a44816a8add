// A failed run is not final (issue 34): a model that failed for a passing reason (a program that
// crashed while its licence server was down) fails its runs, each recording the evaluations it
// spent; the same command, run again once the fault is gone, computes exactly those runs again,
// saying so, and ends with the records a study that never failed has, byte for byte.
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

#include "cli_harness.hpp"
#include "results/store/study_data.hpp"

namespace {

namespace fs = std::filesystem;
using mhb::testing_cli::fresh;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::run_shell;

const std::string transient_script = std::string(MHB_TEST_DATA_DIR) + "/external/transient_problem.py";

// random-search and DE on a built-in sphere and on the transient model (it fails at its 5th
// eval message while MHB_TEST_TRANSIENT_FAULT is set). On one thread, so that which runs meet the
// fault is fixed: each run on the model has more than 5 messages, and the one worker process that
// serves them all starts again after each fault, so each of them fails. (On two threads the runs'
// messages interleave, and how many fail depends on the scheduler.)
std::string retry_study(const fs::path& dir) {
    return "run --algorithms 'random-search de' --problems sphere:dim=2 --problem "
           "\"external:cmd='/usr/bin/python3 " +
           transient_script +
           " 5 failed-runs-marker'\" --runs 2 --evaluations 300 --seed 4 --no-report --threads 1 --out '" +
           dir.string() + "'";
}

TEST(FailedRuns, TheSameCommandRetriesRunsThatFailedAndEndsAsIfTheyNeverHad) {
    const fs::path dir = fresh("failed_runs_retried");
    const auto with_fault =
        run_shell("MHB_TEST_TRANSIENT_FAULT=1 '" + std::string(MHB_CLI_PATH) + "' " + retry_study(dir));
    ASSERT_EQ(with_fault.exit_code, 0) << with_fault.err;
    EXPECT_NE(with_fault.err.find("4 of 8 runs failed"), std::string::npos) << with_fault.err;
    std::size_t failed = 0;
    for (const auto& r : mhb::load_study(dir).runs) {
        if (r.ok)
            continue;
        ++failed;
        EXPECT_NE(r.message.find("licence server is down"), std::string::npos) << r.message;
        // What it spent before the program died (4 messages answered) is recorded, not 0.
        EXPECT_GT(r.evaluations, 0) << r.algorithm << " run " << r.run_index;
        EXPECT_LT(r.evaluations, 300) << r.algorithm << " run " << r.run_index;
    }
    EXPECT_EQ(failed, 4U);

    const auto retried = run_mhbench(retry_study(dir));
    ASSERT_EQ(retried.exit_code, 0) << retried.err;
    EXPECT_NE(retried.err.find("mhbench run: 4 runs of the store failed before; computing them again"),
              std::string::npos)
        << retried.err;
    EXPECT_NE(retried.out.find("(4 run now, 4 found in the store)"), std::string::npos) << retried.out;
    const fs::path clean = fresh("failed_runs_never");
    ASSERT_EQ(run_mhbench(retry_study(clean)).exit_code, 0);
    for (const char* file : {"runs.csv", "curves.csv", "improvements.csv"})
        EXPECT_EQ(read_text(dir / file), read_text(clean / file)) << file;

    // Nothing failed is left: the same command again computes nothing.
    const auto again = run_mhbench(retry_study(dir));
    EXPECT_EQ(again.err.find("failed before"), std::string::npos) << again.err;
    EXPECT_NE(again.out.find("(0 run now, 8 found in the store)"), std::string::npos) << again.out;
}

} // namespace
