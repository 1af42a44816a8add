// One writer per study directory (runner/execution/study_lock.hpp) with real processes: while one
// `mhbench run` writes a study, a second run on the same --out and a report into it are each
// refused in one line naming the first's pid, and change nothing; the first finishes and leaves
// the records of a clean single run, byte for byte, and no lock file.
#include <filesystem>
#include <regex>
#include <string>

#include "cli_harness.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::lines_of;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::run_shell;

fs::path fresh_lock_dir(const std::string& name) {
    const fs::path dir = mhb::testing_cli::scratch_directory() / ("lock_" + name);
    fs::remove_all(dir);
    return dir;
}

// Long enough (seconds) that the first run is still under way when the others start.
const std::string slow_study = "--algorithms 'random-search:batch=50 tlbo' --problems 'sphere:dim=4 pmsm' "
                               "--evaluations 100000 --runs 40 --threads 2 --quiet --no-report";

// A shell script: a first run of slow_study into `dir`; once it has written its lock and its first
// run, it is stopped (SIGSTOP: it holds its lock and writes nothing, so that what changes in `dir`
// is the others' doing, however fast the machine), `meanwhile`, then a second run (stderr in
// logs/run.err) and a report (logs/report.err) into `dir`, each printing its exit status
// ("run=1"), with `dir` listed before them (logs/before) and after (logs/after); then the first
// goes on, and its pid ("pid=...") and exit status ("first=0") are printed.
std::string while_the_first_writes(const fs::path& dir, const fs::path& logs, const std::string& meanwhile) {
    const std::string first =
        std::string("'") + MHB_CLI_PATH + "' run " + slow_study + " --out '" + dir.string() + "'";
    const std::string lock = (dir / ".mhbench.lock").string();
    return first + " & pid=$!; i=0; while ! ( grep -q '^pid = ' '" + lock + "' && [ -s '" +
           (dir / "store.bin").string() +
           "' ] ) 2>/dev/null && [ $i -lt 3000 ]; do sleep 0.01; i=$((i+1)); done; kill -STOP $pid; " +
           meanwhile + "; ls -A '" + dir.string() + "' > '" + (logs / "before").string() + "'; " + first +
           " 2>'" + (logs / "run.err").string() + "'; echo \"run=$?\"; '" + MHB_CLI_PATH + "' report '" +
           dir.string() + "' --no-figures >/dev/null 2>'" + (logs / "report.err").string() +
           "'; echo \"report=$?\"; ls -A '" + dir.string() + "' > '" + (logs / "after").string() +
           "'; kill -CONT $pid; echo \"pid=$pid\"; wait $pid; echo \"first=$?\"";
}

TEST(StudyLock, ASecondWriterIsRefusedWhileTheFirstRunsAndTheFirstEndsAsACleanRun) {
    const fs::path dir = fresh_lock_dir("shared");
    const fs::path reference = fresh_lock_dir("reference");
    const fs::path logs = fresh_lock_dir("logs");
    fs::create_directories(logs);
    ASSERT_EQ(run_mhbench("run " + slow_study + " --out '" + reference.string() + "'").exit_code, 0);

    const std::string lock = (dir / ".mhbench.lock").string();
    const auto r =
        run_shell(while_the_first_writes(dir, logs, "cp '" + lock + "' '" + (logs / "lock").string() + "'"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::smatch pid;
    ASSERT_TRUE(std::regex_search(r.out, pid, std::regex("pid=([0-9]+)"))) << r.out;
    EXPECT_NE(r.out.find("run=1\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("report=1\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("first=0\n"), std::string::npos) << r.out << read_text(logs / "run.err");

    const std::string holder = "is in use by mhbench run (pid " + pid[1].str() + " on host ";
    const auto run_err = lines_of(read_text(logs / "run.err"));
    ASSERT_EQ(run_err.size(), 1u) << read_text(logs / "run.err");
    EXPECT_EQ(run_err[0].rfind("mhbench run: " + dir.string() + " " + holder, 0), 0u) << run_err[0];
    EXPECT_NE(run_err[0].find(" UTC); wait for it or use another --out"), std::string::npos) << run_err[0];
    const auto report_err = lines_of(read_text(logs / "report.err"));
    ASSERT_EQ(report_err.size(), 1u) << read_text(logs / "report.err");
    EXPECT_EQ(report_err[0].rfind("mhbench report: " + dir.string() + " " + holder, 0), 0u) << report_err[0];

    // The lock file named the first run; the refused ones added nothing (no report, no .tmp).
    const std::string lock_text = read_text(logs / "lock");
    EXPECT_NE(lock_text.find("command = mhbench run\npid = " + pid[1].str() + "\nhost = "), std::string::npos)
        << lock_text;
    EXPECT_EQ(read_text(logs / "after"), read_text(logs / "before"));
    EXPECT_EQ(read_text(logs / "after").find("report"), std::string::npos);

    for (const char* file : {"runs.csv", "curves.csv", "checkpoints.csv", "trajectories.csv",
                             "improvements.csv", "algorithms.csv", "study.ini"})
        EXPECT_EQ(read_text(dir / file), read_text(reference / file)) << file;
    EXPECT_FALSE(fs::exists(dir / ".mhbench.lock")) << "the lock goes with its holder";
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
}

// Issue 34: .mhbench.lock deleted while the first run writes lets no second writer in (the lock is
// on the directory): the second run and a report into the study are refused in one line naming
// no holder, and change nothing; the first ends as a clean run.
TEST(StudyLock, DeletingTheLockFileWhileAStudyRunsLetsNoSecondWriterIn) {
    const fs::path dir = fresh_lock_dir("deleted");
    const fs::path logs = fresh_lock_dir("deleted_logs");
    fs::create_directories(logs);
    const auto r =
        run_shell(while_the_first_writes(dir, logs, "rm '" + (dir / ".mhbench.lock").string() + "'"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("run=1\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("report=1\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("first=0\n"), std::string::npos) << r.out;
    EXPECT_EQ(read_text(logs / "run.err"), "mhbench run: " + dir.string() +
                                               " is in use by another mhbench process; wait for it or use "
                                               "another --out\n");
    EXPECT_EQ(read_text(logs / "report.err"), "mhbench report: " + dir.string() +
                                                  " is in use by another mhbench process; wait for it, or "
                                                  "give --out a directory outside the study\n");
    EXPECT_EQ(read_text(logs / "after"), read_text(logs / "before")) << "the refused ones wrote nothing";
    EXPECT_EQ(read_text(logs / "after").find(".mhbench.lock"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "runs.csv"));
    const auto report = run_mhbench("report '" + dir.string() + "' --no-figures");
    EXPECT_EQ(report.exit_code, 0) << report.err;
}

TEST(StudyLock, ARunKilledWithSigkillLeavesALockTheNextRunTakesOver) {
    const fs::path dir = fresh_lock_dir("killed");
    const std::string command =
        std::string("'") + MHB_CLI_PATH + "' run " + slow_study + " --out '" + dir.string() + "'";
    const std::string lock = (dir / ".mhbench.lock").string();
    const auto killed = run_shell(command + " & pid=$!; i=0; while ! grep -q '^pid = ' '" + lock +
                                  "' 2>/dev/null && [ $i -lt 3000 ]; do sleep 0.01; i=$((i+1)); done; "
                                  "kill -KILL $pid; wait $pid");
    EXPECT_EQ(killed.exit_code, 137) << killed.err;
    ASSERT_TRUE(fs::exists(lock)) << "kill -9 leaves the file; the kernel dropped the lock";
    const auto again = run_shell(command);
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_FALSE(fs::exists(lock));
    EXPECT_TRUE(fs::exists(dir / "runs.csv"));
}

} // namespace
