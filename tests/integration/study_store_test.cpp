// A study directory is a store of finished runs keyed by their identity: the same command
// resumes or re-renders, a larger study (more runs, another optimiser, problem or budget)
// computes only the runs the store lacks and equals the study run at once, byte for byte; a
// changed data file, labelled parameter or seed under stored runs is refused, naming the change;
// SIGKILL during the runs or the report leaves a directory the same command completes.
#include <cstring>
#include <filesystem>
#include <fstream>

#include "cli_harness.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::lines_of;
using mhb::testing_cli::read_text;
using mhb::testing_cli::run_mhbench;
using mhb::testing_cli::run_shell;

fs::path fresh_store_dir(const std::string& name) {
    const fs::path dir = mhb::testing_cli::scratch_directory() / ("store_" + name);
    fs::remove_all(dir);
    return dir;
}

const char* const record_files[] = {"runs.csv",         "curves.csv",       "checkpoints.csv",
                                    "trajectories.csv", "improvements.csv", "algorithms.csv",
                                    "study.ini"};

void expect_same_records(const fs::path& a, const fs::path& b) {
    for (const char* file : record_files)
        EXPECT_EQ(read_text(a / file), read_text(b / file)) << file;
}

// The runs a session computed, from its summary: "... (N run now, M found in the store)", or all
// of them when nothing was found.
long long runs_computed(const std::string& out) {
    const auto now = out.find(" run now, ");
    if (now == std::string::npos) {
        const auto total = out.find("study finished: ");
        return total == std::string::npos ? -1 : std::stoll(out.substr(total + 16));
    }
    const auto open = out.rfind('(', now);
    return std::stoll(out.substr(open + 1, now - open - 1));
}

std::string run_args(const std::string& algorithms, const std::string& problems, const std::string& budgets,
                     int runs, const fs::path& out) {
    return "run --no-report --threads 2 --algorithms '" + algorithms + "' --problems '" + problems + "' " +
           budgets + " --runs " + std::to_string(runs) + " --out " + out.string();
}

TEST(StudyStore, ExtendingByRunsOptimiserProblemAndBudgetComputesOnlyTheNewRuns) {
    const fs::path grown = fresh_store_dir("grown");
    const std::string one_budget = "--budget iterations=8";
    const std::string two_budgets = "--budget iterations=8 --budget evaluations=300";

    auto r = run_mhbench(run_args("tlbo pso", "sphere:dim=3", one_budget, 2, grown));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 4);
    // The same command again: nothing to compute, the same files.
    const std::string before = read_text(grown / "runs.csv");
    r = run_mhbench(run_args("tlbo pso", "sphere:dim=3", one_budget, 2, grown));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 0) << r.out;
    EXPECT_EQ(read_text(grown / "runs.csv"), before);
    // More runs: 2 pairs x 3 new runs.
    r = run_mhbench(run_args("tlbo pso", "sphere:dim=3", one_budget, 5, grown));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 6) << r.out;
    // Another optimiser, listed first so that every run_id moves: 5 new runs.
    r = run_mhbench(run_args("jaya tlbo pso", "sphere:dim=3", one_budget, 5, grown));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 5) << r.out;
    // Another problem: 3 optimisers x 5 runs.
    r = run_mhbench(run_args("jaya tlbo pso", "sphere:dim=3 pmsm", one_budget, 5, grown));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 15) << r.out;
    // Another budget: all 30 again under it.
    r = run_mhbench(run_args("jaya tlbo pso", "sphere:dim=3 pmsm", two_budgets, 5, grown));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 30) << r.out;

    const fs::path at_once = fresh_store_dir("at_once");
    r = run_mhbench(run_args("jaya tlbo pso", "sphere:dim=3 pmsm", two_budgets, 5, at_once));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 60);
    expect_same_records(grown, at_once);

    // A smaller study in the grown directory takes its runs from the store and equals that study
    // run at once; the store keeps the rest for later.
    r = run_mhbench(run_args("pso", "pmsm", one_budget, 3, grown));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 0) << r.out;
    const fs::path small = fresh_store_dir("small");
    ASSERT_EQ(run_mhbench(run_args("pso", "pmsm", one_budget, 3, small)).exit_code, 0);
    expect_same_records(grown, small);
    r = run_mhbench(run_args("jaya tlbo pso", "sphere:dim=3 pmsm", two_budgets, 5, grown));
    EXPECT_EQ(runs_computed(r.out), 0) << r.out;
    expect_same_records(grown, at_once);
}

TEST(StudyStore, ChangesUnderStoredRunsAreRefusedNamingTheChange) {
    const fs::path dir = fresh_store_dir("changes");
    const fs::path data = fresh_store_dir("drive.csv");
    const fs::path other = fresh_store_dir("other.csv");
    ASSERT_EQ(run_mhbench("simulate --out " + data.string()).exit_code, 0);
    ASSERT_EQ(run_mhbench("simulate --load 3 --out " + other.string()).exit_code, 0);
    const std::string problem = "pmsm:data=" + data.string();
    const std::string args = run_args("pso:w=0.6,label=mine tlbo", problem, "--iterations 4", 2, dir);
    ASSERT_EQ(run_mhbench(args).exit_code, 0);
    const std::string runs = read_text(dir / "runs.csv");
    const std::string refusal_end =
        "pass --recompute-changed to compute these runs again (keeping every other stored run), "
        "--overwrite to discard the stored runs and start again, or choose another --out";

    // The data file replaced behind the same path.
    const fs::path saved = fresh_store_dir("drive.csv.saved");
    fs::copy_file(data, saved);
    fs::copy_file(other, data, fs::copy_options::overwrite_existing);
    auto r = run_mhbench(args);
    EXPECT_EQ(r.exit_code, 1);
    const auto err = lines_of(r.err);
    ASSERT_EQ(err.size(), 3u) << r.err;
    EXPECT_EQ(err[0], "mhbench run: " + dir.string() + ": 4 stored runs would change:");
    const std::string changed = ": the file changed since the study started (sha256 ";
    EXPECT_EQ(err[1].rfind("  " + problem + changed, 0), 0u) << err[1];
    EXPECT_EQ(err[1].size(), 2 + problem.size() + changed.size() + 8 + 6 + 8 + 3)
        << err[1]; // "xxxxxxxx.. -> yyyyyyyy..)"
    EXPECT_EQ(err[2], refusal_end);
    EXPECT_EQ(read_text(dir / "runs.csv"), runs); // untouched
    fs::copy_file(saved, data, fs::copy_options::overwrite_existing);

    // A labelled algorithm's parameter.
    r = run_mhbench(run_args("pso:w=0.7,label=mine tlbo", problem, "--iterations 4", 2, dir));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(lines_of(r.err),
              (std::vector<std::string>{"mhbench run: " + dir.string() + ": 2 stored runs would change:",
                                        "  algorithm 'mine': pso:w=0.6 -> pso:w=0.7", refusal_end}));
    // The seed and the seed mode.
    r = run_mhbench(args + " --seed 9");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(lines_of(r.err).at(1), "  seed = 9, but the stored runs were made with seed = 1");
    r = run_mhbench(args + " --seeds per-algorithm");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(lines_of(r.err).at(1),
              "  seeds = per-algorithm, but the stored runs were made with seeds = common");
    EXPECT_EQ(read_text(dir / "runs.csv"), runs);

    // The same content under another path is the same problem: nothing to compute, and runs.csv
    // names the path given now.
    const fs::path moved = fresh_store_dir("moved.csv");
    fs::copy_file(data, moved);
    r = run_mhbench(
        run_args("pso:w=0.6,label=mine tlbo", "pmsm:data=" + moved.string(), "--iterations 4", 2, dir));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 0) << r.out;
    EXPECT_NE(read_text(dir / "runs.csv").find(moved.string()), std::string::npos);

    // --overwrite discards the store and does every run again.
    r = run_mhbench(args + " --seed 9 --overwrite");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(runs_computed(r.out), 4) << r.out;
    // context.ini records the content of every data file.
    EXPECT_NE(read_text(dir / "context.ini").find("data_file = "), std::string::npos);
}

TEST(StudyStore, StudyIniStoresAbsoluteDataPathsSoStudyFilesWorkFromAnyDirectory) {
    const fs::path dir = fresh_store_dir("absolute");
    const fs::path work = fresh_store_dir("workdir");
    fs::create_directories(work);
    ASSERT_EQ(run_mhbench("simulate --out " + (work / "drive.csv").string()).exit_code, 0);
    const auto r =
        run_shell("cd '" + work.string() + "' && '" + MHB_CLI_PATH +
                  "' run --no-report --algorithms tlbo --problems pmsm:data=drive.csv --iterations 3 "
                  "--runs 2 --out '" +
                  dir.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(read_text(dir / "study.ini").find("pmsm:data=" + (work / "drive.csv").string()),
              std::string::npos);
    // From another directory, the stored study file finds the data and the runs.
    const auto again =
        run_shell("cd / && '" + std::string(MHB_CLI_PATH) + "' run --no-report --study-file '" +
                  (dir / "study.ini").string() + "' --out '" + dir.string() + "'");
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(runs_computed(again.out), 0) << again.out;
}

// The bytes of a double as store.bin holds it (little-endian).
std::string stored_bytes(double value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    std::string bytes;
    for (int i = 0; i < 8; ++i)
        bytes.push_back(static_cast<char>((bits >> (8 * i)) & 0xffU));
    return bytes;
}

TEST(StudyStore, AFlippedByteInAStoredValueIsComputedAgainWithOneWarning) {
    const fs::path reference = fresh_store_dir("flipped_reference");
    const fs::path dir = fresh_store_dir("flipped");
    const auto args = [](const fs::path& out) {
        return run_args("pso", "sphere:dim=2", "--evaluations 400", 4, out);
    };
    ASSERT_EQ(run_mhbench(args(reference)).exit_code, 0);
    ASSERT_EQ(run_mhbench(args(dir)).exit_code, 0);
    // Run 1's best f, as runs.csv prints it (exactly: the shortest text that reads back the same).
    const std::string row = lines_of(read_text(dir / "runs.csv")).at(2);
    ASSERT_EQ(row.substr(0, 2), "1,");
    std::vector<std::string> fields;
    for (std::size_t start = 0, comma = 0; comma != std::string::npos; start = comma + 1)
        fields.push_back(row.substr(start, (comma = row.find(',', start)) - start));
    std::string store = read_text(dir / "store.bin");
    const auto at = store.find(stored_bytes(std::stod(fields.at(9))));
    ASSERT_NE(at, std::string::npos);
    // Its first place is the record's best_f field (the curve, checkpoints and improvements that
    // end at the same value come after it): the warning below names the run whose record it is.
    store[at + 3] = static_cast<char>(store[at + 3] ^ 0x10);
    std::ofstream(dir / "store.bin", std::ios::binary | std::ios::trunc) << store;

    const auto again = run_mhbench(args(dir));
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(runs_computed(again.out), 1) << again.out;
    std::vector<std::string> warnings;
    for (const auto& line : lines_of(again.err))
        if (line.find("damaged") != std::string::npos)
            warnings.push_back(line);
    ASSERT_EQ(warnings.size(), 1u) << again.err;
    EXPECT_EQ(warnings[0], "mhbench run: warning: " + (dir / "store.bin").string() +
                               ": the record of run 1 (PSO, sphere:dim=2, evaluations=400, run 1) is "
                               "damaged; it will be computed again");
    expect_same_records(dir, reference);
}

// Issue 34: a study copied by `cp DIR/* NEW/` (which skips .mhbench-study) is reported with one
// warning when its files are what store.bin renders, refused in one line naming the file and
// line when one was edited, and restored (marker and files) by the study's command; a study of
// format 2 (no store.bin) is still read as it is.
TEST(StudyStore, AStudyWithoutItsMarkerIsCheckedAgainstStoreBinAndItsCommandRestoresIt) {
    const fs::path original = fresh_store_dir("marked");
    const fs::path copy = fresh_store_dir("unmarked");
    const std::string args = run_args("pso random-search", "sphere:dim=2", "--evaluations 400", 3, copy);
    ASSERT_EQ(run_mhbench(args.substr(0, args.rfind(" --out ")) + " --out " + original.string()).exit_code,
              0);
    ASSERT_EQ(run_shell("mkdir '" + copy.string() + "' && cp '" + original.string() + "'/* '" +
                        copy.string() + "'/")
                  .exit_code,
              0);
    ASSERT_FALSE(fs::exists(copy / ".mhbench-study"));

    const auto intact = run_mhbench("report " + copy.string() + " --no-figures > /dev/null");
    EXPECT_EQ(intact.exit_code, 0) << intact.err;
    EXPECT_EQ(intact.err, "mhbench report: warning: " + copy.string() +
                              ": has no .mhbench-study; its files were checked against store.bin instead "
                              "(they match, but their number of runs is not checked against study.ini); run "
                              "the study's command again to restore it\n");

    // Run 4's best f, one digit changed: still a number, no longer the stored one.
    std::string runs = read_text(copy / "runs.csv");
    std::size_t at = runs.find(",ok,", runs.find("\n4,")) + 4; // evaluations, iterations, best_f
    for (int field = 0; field < 2; ++field)
        at = runs.find(',', at) + 1;
    runs[at] = runs[at] == '7' ? '8' : '7';
    std::ofstream(copy / "runs.csv", std::ios::binary | std::ios::trunc) << runs;
    const auto edited = run_mhbench("report " + copy.string() + " --no-figures > /dev/null");
    EXPECT_EQ(edited.exit_code, 1);
    EXPECT_EQ(edited.err, "mhbench report: " + (copy / "runs.csv").string() +
                              ", line 6: differs from store.bin's record of run 4 (" + copy.string() +
                              " has no .mhbench-study to vouch for it, so it was checked against store.bin); "
                              "run the study's command again to render it from store.bin\n");

    const auto again = run_mhbench(args);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(runs_computed(again.out), 0) << again.out;
    EXPECT_EQ(read_text(copy / ".mhbench-study"), read_text(original / ".mhbench-study"));
    expect_same_records(copy, original);
    const auto restored = run_mhbench("report " + copy.string() + " --no-figures > /dev/null");
    EXPECT_EQ(restored.exit_code, 0) << restored.err;
    EXPECT_EQ(restored.err, "");

    // Format 2: study.ini and runs.csv, no store.bin, no marker.
    fs::remove(copy / "store.bin");
    fs::remove(copy / ".mhbench-study");
    const auto earlier = run_mhbench("report " + copy.string() + " --no-figures > /dev/null");
    EXPECT_EQ(earlier.exit_code, 0) << earlier.err;
    EXPECT_EQ(earlier.err, "");
}

// SIGKILL at the first sign of the phase named by `ready` (a shell test), then the same command.
void kill_then_complete(const std::string& name, const std::string& extra, const std::string& ready) {
    const fs::path dir = fresh_store_dir(name);
    const fs::path reference = fresh_store_dir(name + "_reference");
    const std::string study = "--algorithms 'random-search:batch=50 tlbo' --problems 'sphere:dim=4 pmsm' "
                              "--evaluations 100000 --runs 20 --threads 2 ";
    ASSERT_EQ(run_mhbench("run --quiet --no-report " + study + "--out " + reference.string()).exit_code, 0);
    const std::string command =
        std::string("'") + MHB_CLI_PATH + "' run --quiet " + study + extra + " --out '" + dir.string() + "'";
    const auto killed = run_shell(command + " & pid=$!; i=0; while ! (" + ready +
                                  ") && [ $i -lt 1200 ]; do sleep 0.01; i=$((i+1)); done; kill -KILL $pid; "
                                  "wait $pid; status=$?; echo $i; exit $status");
    // Killed: 137 from the shell (a run of this size takes far longer than the wait).
    EXPECT_EQ(killed.exit_code, 137) << killed.err;
    const auto again = run_shell(command);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    for (const char* file :
         {"runs.csv", "curves.csv", "checkpoints.csv", "trajectories.csv", "improvements.csv"})
        EXPECT_EQ(read_text(dir / file), read_text(reference / file)) << file;
    // No process of the killed session remains. The pattern's brackets keep grep from finding
    // its own command line.
    const auto left = run_shell("grep -l -s -a 'store_" + name.substr(0, 1) + "[" + name.substr(1, 1) + "]" +
                                name.substr(2) + "' /proc/[0-9]*/cmdline || true");
    EXPECT_EQ(left.out, "");
}

TEST(StudyStore, SigkillDuringTheRunsLeavesADirectoryTheSameCommandCompletes) {
    const fs::path dir = fresh_store_dir("killed_runs");
    kill_then_complete("killed_runs", "--no-report", "[ -s '" + (dir / "store.bin").string() + "' ]");
}

TEST(StudyStore, SigkillDuringTheReportLeavesADirectoryTheSameCommandCompletes) {
    const fs::path dir = fresh_store_dir("killed_report");
    // With figures, so that the plotting child is under way too.
    kill_then_complete("killed_report", "", "[ -e '" + (dir / "runs.csv").string() + "' ]");
}

} // namespace
