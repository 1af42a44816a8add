// `mpirun -np 2 mhbench run` (MHB_MPIRUN) writes the study directory `mhbench run` writes in one
// process, runs, curves, checkpoints and trajectories byte for byte, prints its summary once and
// records the rank count in context.ini; it finishes a study a one-process run left interrupted;
// when rank 0 refuses the directory every rank ends, without a hang; and ranks that read different
// contents of a data file are refused before any run.
#include <filesystem>
#include <fstream>
#include <string>

#include "integration/cli_harness.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::run_shell;

// Run costs over an order of magnitude apart (about 3 ms for random search on the sphere, 40 ms
// for CMA-ES on the PMSM problem), named parameters so that trajectories.csv has rows, and 90
// runs, about 1.5 s on one thread: time enough to interrupt one process after its first runs.
const std::string study_options =
    "--algorithms 'random-search tlbo cmaes' --problems 'sphere:dim=5 rastrigin:dim=5 pmsm' "
    "--budget evaluations=100000 --runs 10 --no-report ";

fs::path fresh(const std::string& name) {
    const fs::path dir = mhb::testing_cli::scratch_directory() / ("mpi_" + name);
    fs::remove_all(dir);
    return dir;
}

// `mhbench ARGS` on 2 ranks; `timeout` turns a hang into a failure with a message.
mhb::testing_cli::CliResult mpirun_mhbench(const std::string& args) {
    return run_shell(std::string("timeout 300 ") + MHB_MPIRUN + " '" + MHB_CLI_PATH + "' " + args);
}

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
        ++n;
    return n;
}

void expect_same_records(const fs::path& dir, const fs::path& reference) {
    for (const char* file :
         {"runs.csv", "curves.csv", "checkpoints.csv", "trajectories.csv", "study.ini", "algorithms.csv"}) {
        EXPECT_TRUE(fs::exists(dir / file)) << file;
        EXPECT_EQ(read_text(dir / file), read_text(reference / file)) << file;
    }
}

TEST(MpiCli, TwoRanksWriteTheDirectoryOneProcessWritesByteForByte) {
    const fs::path one = fresh("one");
    const auto single = run_mhbench("run " + study_options + "--threads 2 --quiet --out " + one.string());
    ASSERT_EQ(single.exit_code, 0) << single.err;
    ASSERT_NE(read_text(one / "trajectories.csv").find('\n'), read_text(one / "trajectories.csv").rfind('\n'))
        << "the study should have trajectories";

    const fs::path two = fresh("two");
    const auto spread = mpirun_mhbench("run " + study_options + "--threads 1 --out " + two.string());
    ASSERT_EQ(spread.exit_code, 0) << spread.out << spread.err;
    expect_same_records(two, one);
    // Rank 0 alone prints and writes; context.ini says how the runs were spread.
    EXPECT_EQ(occurrences(spread.out, "study finished:"), 1u) << spread.out;
    EXPECT_NE(read_text(two / "context.ini").find("mpi_ranks = 2\n"), std::string::npos)
        << read_text(two / "context.ini");
    EXPECT_EQ(read_text(one / "context.ini").find("mpi_ranks"), std::string::npos);
}

TEST(MpiCli, AStudyInterruptedInOneProcessIsFinishedUnderMpirun) {
    const fs::path one = fresh("whole");
    ASSERT_EQ(run_mhbench("run " + study_options + "--quiet --out " + one.string()).exit_code, 0);

    // SIGINT to a one-process run as soon as it has stored a run (store.bin, or journal.txt in
    // the older format), so that it stops with some runs kept and most to do.
    const fs::path dir = fresh("resumed");
    const std::string stored = "cat '" + (dir / "store.bin").string() + "' '" +
                               (dir / "journal.txt").string() + "' 2>/dev/null | wc -c";
    const std::string command = std::string("'") + MHB_CLI_PATH + "' run " + study_options +
                                "--threads 1 --quiet --out " + dir.string();
    const auto first = run_shell(command + " & pid=$!; i=0; while [ \"$(" + stored +
                                 ")\" -eq 0 ] && [ $i -lt 600 ]; do sleep 0.05; i=$((i+1)); done; "
                                 "kill -INT $pid; wait $pid");
    ASSERT_EQ(first.exit_code, 130) << first.err;
    ASSERT_FALSE(fs::exists(dir / "runs.csv"));

    const auto second = mpirun_mhbench("run " + study_options + "--threads 1 --out " + dir.string());
    ASSERT_EQ(second.exit_code, 0) << second.out << second.err;
    expect_same_records(dir, one);
}

// Runs by precision: rank 0 plans each round from the results, every rank runs it, and the
// stopping points are a one-process run's.
TEST(MpiCli, RunsByPrecisionStopWhereOneProcessStops) {
    const std::string by_precision =
        "--algorithms 'itlbo tlbo pso' --problems 'sphere:dim=5 pmsm' --iterations 60 "
        "--runs auto --precision 0.15 --max-runs 30 --no-report ";
    const fs::path one = fresh("precision_one");
    const auto single = run_mhbench("run " + by_precision + "--threads 1 --quiet --out " + one.string());
    ASSERT_EQ(single.exit_code, 0) << single.err;
    const fs::path two = fresh("precision_two");
    const auto spread = mpirun_mhbench("run " + by_precision + "--threads 1 --out " + two.string());
    ASSERT_EQ(spread.exit_code, 0) << spread.out << spread.err;
    EXPECT_NE(spread.err.find("round 2:"), std::string::npos) << spread.err;
    expect_same_records(two, one);
}

TEST(MpiCli, WhenRankZeroRefusesTheDirectoryEveryRankEnds) {
    // A directory of the user's own files is never taken over: rank 0 refuses it before any run,
    // and the other rank, waiting for runs, must be released rather than hang.
    const fs::path dir = fresh("users_own");
    fs::create_directories(dir);
    std::ofstream(dir / "notes.txt") << "mine\n";
    const auto r = mpirun_mhbench("run " + study_options + "--threads 1 --out " + dir.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.exit_code, 124) << "timed out: a rank hung";
    EXPECT_NE(r.err.find("mhbench run: " + dir.string()), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("study finished"), std::string::npos) << r.out;
    EXPECT_EQ(read_text(dir / "notes.txt"), "mine\n");
    EXPECT_FALSE(fs::exists(dir / "runs.csv"));
}

// Each rank reads its own copy of a data file (on a cluster, each node's): here one path,
// /proc/self/cwd/drive.csv, that is a different file in each rank's working directory.
TEST(MpiCli, RanksThatReadDifferentDataAreRefusedBeforeAnyRun) {
    const fs::path a = fresh("data_a");
    const fs::path b = fresh("data_b");
    fs::create_directories(a);
    fs::create_directories(b);
    ASSERT_EQ(run_mhbench("simulate --out " + (a / "drive.csv").string()).exit_code, 0);
    ASSERT_EQ(run_mhbench("simulate --load 3 --out " + (b / "drive.csv").string()).exit_code, 0);
    const fs::path out = fresh("data_out");
    const std::string run = std::string(" '") + MHB_CLI_PATH +
                            "' run --algorithms pso --problems pmsm:data=/proc/self/cwd/drive.csv "
                            "--iterations 2 --runs 2 --no-report --out " +
                            out.string();
    const auto r = run_shell(std::string("timeout 300 ") + MHB_MPIEXEC +
                             " --allow-run-as-root --oversubscribe -n 1 --wdir " + a.string() + run +
                             " : -n 1 --wdir " + b.string() + run);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("mhbench run: /proc/self/cwd/drive.csv: sha256 "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" in rank 1, sha256 "), std::string::npos) << r.err;
    EXPECT_NE(
        r.err.find(
            "mhbench run: every rank must read the same data files, plug-ins and programs; nothing was run"),
        std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out)); // refused before rank 0 touched the directory
}

// The same for an external program: each rank runs its own copy of the model's script.
TEST(MpiCli, RanksThatRunDifferentExternalProgramsAreRefusedBeforeAnyRun) {
    const fs::path a = fresh("program_a");
    const fs::path b = fresh("program_b");
    fs::create_directories(a);
    fs::create_directories(b);
    const fs::path script = fs::path(MHB_SOURCE_DIR) / "scripts/external/sphere_problem.py";
    fs::copy_file(script, a / "model.py");
    fs::copy_file(script, b / "model.py");
    std::ofstream(b / "model.py", std::ios::app) << "# another version\n";
    const fs::path out = fresh("program_out");
    const std::string run = std::string(" '") + MHB_CLI_PATH +
                            "' run --algorithms pso --problem \"external:cmd='/usr/bin/python3 "
                            "/proc/self/cwd/model.py'\" --evaluations 100 --runs 2 --no-report --out " +
                            out.string();
    const auto r = run_shell(std::string("timeout 300 ") + MHB_MPIEXEC +
                             " --allow-run-as-root --oversubscribe -n 1 --wdir " + a.string() + run +
                             " : -n 1 --wdir " + b.string() + run);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("mhbench run: rank 1: program of external:cmd="), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(rank 0 has another)"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

} // namespace
