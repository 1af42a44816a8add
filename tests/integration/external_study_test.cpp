// External programs in a real `mhbench run` study: a Python optimiser beside a built-in one on a
// Python problem, byte-identical with 1 and 2 threads; a problem whose program crashes fails its
// own runs with one line each while the study's other runs finish; a changed script is refused
// on extension like a changed data file; a program that exits before reading all it was sent is
// a failed run or the end of a complete one, never a SIGPIPE that ends mhbench without a word.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <thread>

#include "cli_harness.hpp"
#include "support/external_clients.hpp"
#include "support/processes.hpp"

namespace {

namespace fs = std::filesystem;
using mhb::testing_cli::fresh;
using mhb::testing_cli::lines_of;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::scratch_directory;

// A spec with blanks in cmd, quoted for the shell (the quotes inside keep it one spec).
std::string spec(const std::string& kind, const std::string& command, const std::string& options = "") {
    return "\"" + kind + ":cmd='" + command + "'" + (options.empty() ? "" : "," + options) + "\"";
}

std::string python(const std::string& script, const std::string& arguments = "") {
    return "/usr/bin/python3 " + script + (arguments.empty() ? "" : " " + arguments);
}

const std::string es = std::string(MHB_SOURCE_DIR) + "/scripts/external/one_plus_one_es.py";
const std::string sphere = std::string(MHB_SOURCE_DIR) + "/scripts/external/sphere_problem.py";
const std::string faulty = std::string(MHB_TEST_DATA_DIR) + "/external/faulty_problem.py";
const std::string pmsm = std::string(MHB_SOURCE_DIR) + "/scripts/external/pmsm_steady_problem.py";
const std::string early_problem = std::string(MHB_TEST_DATA_DIR) + "/external/early_exit_problem.py";
const std::string early_optimizer = std::string(MHB_TEST_DATA_DIR) + "/external/early_exit_optimizer.py";

TEST(ExternalStudy, PythonOptimiserAndProblemGiveTheSameRecordsOnOneAndTwoThreads) {
    // The reference clients ignore further arguments: a marker that only this test's processes carry.
    const std::string study =
        "--algorithm " + spec("external", python(es, "study-es-marker"), "params=lambda=5") +
        " --algorithms random-search --problem " +
        spec("external", python(sphere, "study-sphere-marker"), "params=dim=4,workers=2") +
        " --runs 3 --evaluations 300 --seed 5 --no-report";
    const fs::path one = fresh("external1");
    const fs::path two = fresh("external2");
    const auto a = run_mhbench("run " + study + " --threads 1 --out " + one.string());
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const auto b = run_mhbench("run " + study + " --threads 2 --out " + two.string());
    ASSERT_EQ(b.exit_code, 0) << b.err;
    for (const char* name : {"runs.csv", "curves.csv", "checkpoints.csv", "study.ini"})
        EXPECT_EQ(read_text(one / name), read_text(two / name)) << name;
    const auto rows = lines_of(read_text(one / "runs.csv"));
    EXPECT_EQ(rows.size(), 7U); // 2 algorithms x 3 runs and the header
    EXPECT_EQ(read_text(one / "runs.csv").find(",false,"), std::string::npos) << read_text(one / "runs.csv");
    // Extending the study from its own study.ini computes nothing new.
    const auto c = run_mhbench("run --study-file " + (one / "study.ini").string() +
                               " --threads 2 --no-report --out " + one.string());
    EXPECT_EQ(c.exit_code, 0) << c.err;
    EXPECT_TRUE(mhb::test_support::processes_with("study-sphere-marker").empty());
    EXPECT_TRUE(mhb::test_support::processes_with("study-es-marker").empty());
}

TEST(ExternalStudy, ACrashingProblemFailsItsOwnRunsAndTheOthersFinish) {
    const fs::path dir = fresh("external_crash");
    const auto r =
        run_mhbench("run --algorithms random-search --problems sphere:dim=2 --problem " +
                    spec("external", python(faulty, "crash 3 study-crash-marker")) +
                    " --runs 2 --evaluations 300 --seed 5 --no-report --threads 2 --out " + dir.string());
    const std::string runs = read_text(dir / "runs.csv");
    const auto rows = lines_of(runs);
    ASSERT_EQ(rows.size(), 5U) << r.err;
    int failed = 0;
    for (const auto& row : rows)
        if (row.find("exited with status 3; its stderr: faulty: segmentation fault in the model") !=
            std::string::npos)
            ++failed;
    EXPECT_EQ(failed, 2) << runs;
    EXPECT_TRUE(mhb::test_support::processes_with("study-crash-marker").empty());
}

// pso's first population at dimension 100 is one eval message of about 400 KiB, far more than the
// pipe holds; the program exits without reading it, so mhbench's write of the rest has no reader.
TEST(ExternalStudy, AProblemThatExitsBeforeReadingABatchFailsItsRunsAndMhbenchSaysSo) {
    const fs::path dir = fresh("external_early_problem");
    const auto r =
        run_mhbench("run --algorithms pso:np=200 --problem " +
                    spec("external", python(early_problem, "100 early-problem-marker")) +
                    " --runs 2 --evaluations 2000 --seed 5 --no-report --threads 2 --out " + dir.string());
    EXPECT_EQ(r.exit_code, 1) << r.err; // failed runs, not a signal (141)
    EXPECT_NE(r.out.find("study finished: 2 runs (2 failed)"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("2 of 2 runs failed"), std::string::npos) << r.err;
    const auto rows = lines_of(read_text(dir / "runs.csv"));
    ASSERT_EQ(rows.size(), 3U);
    for (std::size_t i = 1; i < rows.size(); ++i) {
        // Named by its script, not by the interpreter that runs it.
        EXPECT_NE(rows[i].find("early_exit_problem.py exited with status 3 before reading all it was sent; "
                               "its stderr: early: the model gave up"),
                  std::string::npos)
            << rows[i];
        EXPECT_NE(rows[i].find(",failed,"), std::string::npos) << rows[i];
    }
    EXPECT_TRUE(mhb::test_support::processes_with("early-problem-marker").empty());
}

// An optimiser may exit once its budget is spent without waiting for "stop": after its whole last
// answer (mhbench's "stop" then races with its exit: under load it lost, and SIGPIPE ended
// mhbench), or after the start of it (the rest has no reader, every time). Either run is complete.
TEST(ExternalStudy, AnOptimiserThatExitsOnceItsBudgetIsSpentCompletesItsRuns) {
    const fs::path dir = fresh("external_early_optimizer");
    const auto r = run_mhbench(
        "run --algorithm " +
        spec("external", python(early_optimizer, "answer 100 early-opt-marker"), "label=answer") +
        " --algorithm " +
        spec("external", python(early_optimizer, "partial 100 early-opt-marker"), "label=partial") +
        " --problems sphere:dim=100 --runs 15 --evaluations 300 --seed 5 --no-report --threads 2 "
        "--out " +
        dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("study finished: 30 runs (0 failed), 9000 evaluations"), std::string::npos) << r.out;
    EXPECT_TRUE(mhb::test_support::wait_until(
        [] { return mhb::test_support::processes_with("early-opt-marker").empty(); }, 5.0));
}

TEST(ExternalStudy, PluginCheckOfAnOptimiserThatExitsEarlyPrintsItsLines) {
    const auto r =
        run_mhbench("plugin-check --problem sphere:dim=100 --runs 2 --evaluations 300 --algorithm " +
                    spec("external", python(early_optimizer, "partial 100 early-check-marker")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("pass  budget"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("verdict: pass"), std::string::npos) << r.out;
}

// The cells of a CSV line, quoted fields ("..." with "" for a quote) unquoted.
std::vector<std::string> cells_of(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
            cells.back() += line[++i];
        else if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            cells.emplace_back();
        else
            cells.back() += c;
    }
    return cells;
}

// The Python PMSM model reads the motor's parameters from the dataset's metadata and declares them
// ("truth"): runs.csv gets the true values and the estimates' errors, as for the built-in model.
TEST(ExternalStudy, AProblemThatDeclaresItsTruthFillsTheTrueAndErrorColumns) {
    const fs::path dir = fresh("external_truth");
    const std::string data = std::string(MHB_TEST_DATA_DIR) + "/pmsm/pmsm_public_2200rpm_2.5Nm_clean_ss.csv";
    const auto r = run_mhbench("run --algorithms tlbo --problem " +
                               spec("external", python(pmsm), "params=data=" + data) +
                               " --runs 1 --evaluations 2000 --seed 5 --no-report --out " + dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = lines_of(read_text(dir / "runs.csv"));
    ASSERT_EQ(rows.size(), 2U);
    const auto header = cells_of(rows[0]);
    const auto row = cells_of(rows[1]);
    const auto at = [&](const std::string& column) {
        const auto found = std::find(header.begin(), header.end(), column);
        return found == header.end() || static_cast<std::size_t>(found - header.begin()) >= row.size()
                   ? std::string("(no column)")
                   : row[static_cast<std::size_t>(found - header.begin())];
    };
    const std::pair<const char*, const char*> truths[] = {
        {"Rs", "0.33"}, {"Ld", "0.00324"}, {"Lq", "0.00324"}, {"psi", "0.0776"}};
    for (const auto& [name, truth] : truths) {
        EXPECT_EQ(at(std::string(name) + "_true"), truth) << rows[0] << "\n" << rows[1];
        const std::string error = at(std::string(name) + "_err_pct");
        EXPECT_FALSE(error.empty() || error == "(no column)") << name << ": " << rows[1];
    }
}

TEST(ExternalStudy, AChangedScriptIsRefusedOnExtension) {
    const fs::path dir = fresh("external_changed");
    const fs::path script = scratch_directory() / "changing_sphere.py";
    fs::copy_file(sphere, script, fs::copy_options::overwrite_existing);
    const std::string study = "--algorithms random-search --problem " +
                              spec("external", python(script.string())) +
                              " --runs 1 --evaluations 100 --seed 5 --no-report --out " + dir.string();
    const auto a = run_mhbench("run " + study);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    { std::ofstream(script, std::ios::app) << "# changed\n"; }
    const auto b = run_mhbench("run " + study);
    EXPECT_NE(b.exit_code, 0);
    EXPECT_NE(b.err.find("the external program changed"), std::string::npos) << b.err;
}

// The README's worked example, smaller: a Python optimiser beside built-ins on CEC 2017 F1-F5,
// with the report's tables naming it beside them.
TEST(ExternalStudy, APythonOptimiserIsComparedWithTheBuiltInsOnCec2017) {
    const fs::path dir = fresh("external_cec");
    const auto r =
        run_mhbench("run --algorithm " + spec("external", python(es, "cec-es-marker"), "label=python-es") +
                    " --algorithms 'itlbo pso' --problems cec2017:f=1-5,dim=10 --runs 2 "
                    "--evaluations 1000 --no-figures --quiet --out " +
                    dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(lines_of(read_text(dir / "runs.csv")).size(), 31U); // 3 algorithms x 5 functions x 2 runs
    const std::string report = read_text(dir / "report" / "report.md");
    for (const char* label : {"python-es", "itlbo", "pso"})
        EXPECT_NE(report.find(label), std::string::npos) << label;
    EXPECT_TRUE(mhb::test_support::processes_with("cec-es-marker").empty());
}

// SIGKILL of mhbench while external programs compute (a Python optimiser and a Python problem
// served by two workers), then the same command: the records of a study run at once, byte for
// byte, and no program of the killed session left.
TEST(ExternalStudy, SigkillDuringExternalRunsLeavesADirectoryTheSameCommandCompletes) {
    const fs::path dir = fresh("external_killed");
    const fs::path reference = fresh("external_killed_reference");
    const std::string study =
        "run --quiet --no-report --algorithm " +
        spec("external", python(es, "killed-es-marker"), "params=lambda=4") +
        " --algorithms random-search --problem " +
        spec("external", python(sphere, "killed-sphere-marker"), "params=dim=3,workers=2") +
        " --runs 8 --evaluations 3000 --seed 9 --threads 2 --out ";
    ASSERT_EQ(run_mhbench(study + reference.string()).exit_code, 0);
    const std::string command = std::string("'") + MHB_CLI_PATH + "' " + study + "'" + dir.string() + "'";
    const auto killed = mhb::testing_cli::run_shell(
        command + " & pid=$!; i=0; while ! [ -s '" + (dir / "store.bin").string() +
        "' ] && [ $i -lt 2000 ]; do sleep 0.01; i=$((i+1)); done; kill -KILL $pid; "
        "wait $pid; exit $?");
    EXPECT_EQ(killed.exit_code, 137) << killed.err;
    EXPECT_TRUE(mhb::test_support::wait_until(
        [&] { return mhb::test_support::processes_with("killed-sphere-marker").empty(); }, 10.0));
    const auto again = mhb::testing_cli::run_shell(command);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    for (const char* file : {"runs.csv", "curves.csv", "checkpoints.csv", "improvements.csv"})
        EXPECT_EQ(read_text(dir / file), read_text(reference / file)) << file;
    EXPECT_TRUE(mhb::test_support::processes_with("killed-es-marker").empty());
}

// mhbench killed (SIGKILL: no handler runs) or stopped (SIGTERM twice) while an external problem
// hangs with a grandchild of its own: neither the program nor what it started outlives mhbench.
TEST(ExternalStudy, NoProgramOutlivesMhbenchKilledOrStopped) {
    for (const char* signal : {"KILL", "TERM"}) {
        const std::string marker = std::string("outlive-marker-") + signal;
        const fs::path dir = fresh(std::string("external_kill_") + signal);
        const fs::path pid_file = scratch_directory() / (marker + ".pid");
        std::string command = "'";
        command += MHB_CLI_PATH;
        command += "' run --algorithms random-search --problem ";
        command += spec("external", python(faulty, "hang 1 " + marker), "timeout=100");
        command += " --runs 1 --evaluations 100 --no-report --out " + dir.string();
        command += " >/dev/null 2>&1 & echo $! > '" + pid_file.string() + "'";
        ASSERT_EQ(std::system(command.c_str()), 0);
        // The program, its grandchild, the watcher and mhbench itself carry the marker.
        ASSERT_TRUE(mhb::test_support::wait_until(
            [&] {
                return mhb::test_support::processes_with({"time.sleep(1000)", marker}).size() == 1;
            },
            20.0));
        const std::string pid = mhb::testing_cli::read_text(pid_file);
        // A first SIGTERM lets the runs under way finish (bounded by timeout=); the second ends
        // mhbench at once (its handler is reset), like a second Ctrl-C.
        ASSERT_EQ(std::system(("kill -" + std::string(signal) + " " + pid).c_str()), 0);
        if (std::string(signal) == "TERM") {
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            ASSERT_EQ(std::system(("kill -TERM " + pid).c_str()), 0);
        }
        EXPECT_TRUE(mhb::test_support::wait_until(
            [&] { return mhb::test_support::processes_with(marker).empty(); }, 10.0))
            << signal << ": " << mhb::test_support::processes_with(marker).size() << " left";
    }
}

} // namespace
