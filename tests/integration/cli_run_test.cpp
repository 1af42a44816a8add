// `mhbench run` and `mhbench list` end to end, through the real binary (MHB_CLI_PATH): results
// byte-identical for 1 and 2 threads and when re-run from study.ini; every bad input gives one
// line per error, a non-zero exit and no runs.csv; Ctrl-C keeps finished runs and resumes.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "algorithms/algorithm_registry.hpp"
#include "cli_harness.hpp"
#include "problems/problem_registry.hpp"
#include "runner/execution/context.hpp"
#include "runner/study/study_presets.hpp"

namespace {

// The registries' own lists, so the expectations follow as components are added.
template <class Registry> std::string known_names(const Registry& registry) {
    std::string names;
    for (const auto& e : registry.entries())
        names += (names.empty() ? "" : ", ") + e.name;
    return names;
}
std::string known_algorithm_names() {
    return known_names(mhb::builtin_algorithms());
}
std::string known_problem_names() {
    return known_names(mhb::builtin_problems());
}
std::string known_study_names() {
    std::string names;
    for (const auto& p : mhb::study_presets())
        names += (names.empty() ? "" : ", ") + p.name;
    return names;
}
namespace fs = std::filesystem;

const fs::path cli_run_work = mhb::testing_cli::scratch_directory();

using mhb::testing_cli::fresh;
using mhb::testing_cli::lines_of;
using mhb::testing_cli::read_text;
using mhb::testing_cli::scratch_directory;
using CliRunResult = mhb::testing_cli::CliResult;
using mhb::testing_cli::run_shell;

CliRunResult mhbench(const std::string& args) {
    return mhb::testing_cli::run_mhbench(args);
}

const std::string small_study_options =
    "--algorithms \"random-search random-search:batch=20\" --problems sphere:dim=3 "
    "--problem sphere:dim=5,bound=2 --runs 4 --iterations 30 --evaluations 500 --seed 9";

const char* const deterministic_files[] = {"runs.csv",         "curves.csv",       "checkpoints.csv",
                                           "trajectories.csv", "improvements.csv", "study.ini"};

TEST(CliRun, OneAndTwoThreadsGiveByteIdenticalResults) {
    const fs::path one = fresh("threads1");
    const fs::path two = fresh("threads2");
    const CliRunResult a =
        mhbench("run " + small_study_options + " --no-report --threads 1 --out " + one.string());
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const CliRunResult b =
        mhbench("run " + small_study_options + " --no-report --threads 2 --out " + two.string());
    ASSERT_EQ(b.exit_code, 0) << b.err;
    for (const char* name : deterministic_files)
        EXPECT_EQ(read_text(one / name), read_text(two / name)) << name;
    // 2 problems x 2 algorithms x 4 runs, numbered from 0, plus the header.
    EXPECT_EQ(lines_of(read_text(one / "runs.csv")).size(), 17u);
    EXPECT_NE(read_text(one / "context.ini").find("threads = 1\n"), std::string::npos);
    EXPECT_NE(read_text(two / "context.ini").find("threads = 2\n"), std::string::npos);
    // The summary: runs, failures, evaluations, wall time and the directory. The budget is exact:
    // batch 50 stops at 500 evaluations (before 30 iterations), batch 20 at 20 + 30 * 20 = 620 > 500
    // also at 500, so 16 runs x 500.
    EXPECT_NE(a.out.find("study finished: 16 runs (0 failed), 8000 evaluations"), std::string::npos) << a.out;
    EXPECT_NE(a.out.find("results in " + one.string()), std::string::npos) << a.out;
    EXPECT_EQ(a.err, ""); // no progress bar when stderr is not a terminal
}

TEST(CliRun, StudyFileRunsTheSameStudyAgain) {
    const fs::path first = fresh("original");
    const fs::path again = fresh("from_file");
    ASSERT_EQ(
        mhbench("run " + small_study_options + " --no-report --threads 2 --quiet --out " + first.string())
            .exit_code,
        0);
    const CliRunResult r = mhbench("run --no-report --study-file " + (first / "study.ini").string() +
                                   " --threads 1 --quiet --out " + again.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, ""); // --quiet
    for (const char* name : deterministic_files)
        EXPECT_EQ(read_text(first / name), read_text(again / name)) << name;
    // Options override the file: another seed gives another study with other results.
    const fs::path other = fresh("other_seed");
    ASSERT_EQ(mhbench("run --no-report --study-file " + (first / "study.ini").string() +
                      " --seed 10 --quiet --out " + other.string())
                  .exit_code,
              0);
    EXPECT_NE(read_text(first / "runs.csv"), read_text(other / "runs.csv"));
}

TEST(CliRun, PresetsRunAndOptionsOverrideThem) {
    const fs::path dir = fresh("smoke");
    const CliRunResult r =
        mhbench("run --study smoke --runs 3 --evaluations 200 --no-report --quiet --out " + dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string ini = read_text(dir / "study.ini");
    EXPECT_NE(ini.find("algorithms = random-search\nproblems = sphere:dim=5\nruns = 3\n"), std::string::npos)
        << ini;
    // --evaluations replaces the preset's whole budget (its 100 iterations are dropped).
    EXPECT_NE(ini.find("budget = evaluations=200\n"), std::string::npos);
    EXPECT_EQ(ini.find("iterations"), std::string::npos);
}

TEST(CliRun, DryRunPrintsTheExpandedStudyAndItsCostAndRunsNothing) {
    const fs::path dir = fresh("dry");
    const CliRunResult r =
        mhbench("run --algorithms 'itlbo:tutorial={on,off},obl={on,off}' tlbo --problems "
                "'sphere:dim={2,3}' --budget evaluations=300 --budget iterations=4 --runs 5 "
                "--dry-run --threads 2 --out " +
                dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(dir));
    const auto has = [&](const std::string& text) { return r.out.find(text) != std::string::npos; };
    EXPECT_TRUE(has("study: 5 algorithms x 2 problems x 2 budgets x 5 runs = 100 runs; seed 1, seeds common"))
        << r.out;
    EXPECT_TRUE(has("  itlbo[T+O+]  itlbo\n")) << r.out;
    EXPECT_TRUE(has("  itlbo[T-O-]  itlbo:obl=off,tutorial=off\n")) << r.out;
    EXPECT_TRUE(has("  TLBO         tlbo\n")) << r.out; // its registered display name
    EXPECT_TRUE(has("  sphere:dim=3\n"));
    EXPECT_TRUE(has("  evaluations=300: 15000 evaluations\n")) << r.out; // 5 x 2 x 5 x 300, exactly
    EXPECT_TRUE(has("  iterations=4: about ")) << r.out;
    EXPECT_TRUE(has("on 2 threads (runs ")) << r.out;
    EXPECT_TRUE(has("(runs calibrated on ")) << r.out;
    EXPECT_TRUE(has("\nreport: tables about ")) << r.out; // the report and its figures are estimated too
    EXPECT_TRUE(has(" figures (convergence ")) << r.out;
}

TEST(CliRun, StudyFileAndCommandLineErrorsAreReportedTogetherWithFileAndLine) {
    const fs::path file = scratch_directory() / "bad-study.ini";
    std::ofstream(file) << "# a study with mistakes\n"
                           "algorithms = pso:w=2 \\\n"
                           "             itlbo:obl={on,off,on}\n"
                           "problems = sphere:dim=3\n"
                           "runs = many\n"
                           "threads = 4\n"
                           "budget = iterations=10\n";
    const CliRunResult r = mhbench("run --study-file " + file.string() + " --seeds sometimes --dry-run");
    EXPECT_EQ(r.exit_code, 2);
    const std::string f = file.string();
    EXPECT_EQ(lines_of(r.err),
              (std::vector<std::string>{
                  "mhbench run: " + f + ":5: runs = many is not an integer",
                  "mhbench run: " + f +
                      ":6: unknown key 'threads' (it is not part of a study: give --threads on "
                      "the command line)",
                  "mhbench run: seeds = sometimes is not one of {common, per-algorithm}",
                  "mhbench run: " + f + ":2: pso: parameter 'w' = 2 is outside [0, 1]",
                  "mhbench run: " + f +
                      ":2: algorithm 'itlbo:obl={on,off,on}': parameter 'obl': value 'on' is "
                      "listed twice in the set",
              }));
    EXPECT_EQ(mhbench("run --study-file " + scratch_directory().string() + " --dry-run").err,
              "mhbench run: " + scratch_directory().string() + ": is a directory, not a study file (try " +
                  (scratch_directory() / "study.ini").string() + ")\n");
}

// Each case: the arguments, and the error lines expected on stderr (exactly, in order).
struct BadRunArguments {
    std::string args;
    std::vector<std::string> errors;
};

TEST(CliRun, BadInputGivesOneLinePerErrorNonZeroExitAndNoRunsCsv) {
    fs::create_directories(cli_run_work);
    std::ofstream(cli_run_work / "a_file") << "not a directory\n";
    const std::vector<BadRunArguments> cases = {
        {"--algorithms nope --problems sphere --iterations 5",
         {"mhbench run: unknown algorithm 'nope'; known: " + known_algorithm_names()}},
        {"--algorithms random-search --problems nope --iterations 5",
         {"mhbench run: unknown problem 'nope'; known: " + known_problem_names()}},
        {"--algorithms random-search:batch=0 --problems sphere --iterations 5",
         {"mhbench run: random-search: parameter 'batch' = 0 is outside [1, 1000000000]"}},
        {"--algorithms random-search --problems sphere:dim=0 --runs 0 --iterations 5 --threads 0",
         {"mhbench run: threads = 0 is outside [1, inf)",
          "mhbench run: sphere: parameter 'dim' = 0 is outside [1, 10000]",
          "mhbench run: study: runs = 0 is outside [1, 1000000]"}},
        {"--algorithms random-search --problems sphere",
         {"mhbench run: budget: give a number of iterations or of evaluations (or both)"}},
        {"--algorithms random-search --problems sphere --evaluations lots --runs 2.5",
         {"mhbench run: runs = 2.5 is not an integer", "mhbench run: evaluations = lots is not an integer"}},
        {"--study nope", {"mhbench run: unknown study 'nope'; known: " + known_study_names()}},
        {"--algorithms random-search --problems sphere --iterations 5 --out " +
             (cli_run_work / "a_file" / "sub").string(),
         {"mhbench run: " + (cli_run_work / "a_file" / "sub").string() +
          ": cannot create the output directory (Not a directory)"}},
        {"--algorithms random-search --problems sphere --iterations 5 --bogus",
         {"mhbench run: unrecognised option '--bogus' (see mhbench run --help)"}},
    };
    for (const auto& c : cases) {
        const fs::path dir = fresh("bad");
        const bool has_out = c.args.find("--out") != std::string::npos;
        const CliRunResult r = mhbench("run " + c.args + (has_out ? "" : " --out " + dir.string()));
        EXPECT_NE(r.exit_code, 0) << c.args;
        EXPECT_EQ(lines_of(r.err), c.errors) << c.args;
        EXPECT_FALSE(fs::exists(dir / "runs.csv")) << c.args;
        EXPECT_FALSE(fs::exists(dir)) << c.args; // validation comes before anything is written
    }
}

TEST(CliRun, AFinishedStudyRefusesAChangedSeedUnlessOverwriteIsGiven) {
    const fs::path dir = fresh("finished");
    const std::string args =
        "run --algorithms random-search --problems sphere:dim=2 --runs 2 --iterations 3 --no-report --out " +
        dir.string();
    ASSERT_EQ(mhbench(args).exit_code, 0);
    const std::string runs = read_text(dir / "runs.csv");
    const CliRunResult again = mhbench(args + " --seed 5");
    EXPECT_NE(again.exit_code, 0);
    EXPECT_EQ(lines_of(again.err),
              (std::vector<std::string>{
                  "mhbench run: " + dir.string() + ": 2 stored runs would change:",
                  "  seed = 5, but the stored runs were made with seed = 1",
                  "pass --recompute-changed to compute these runs again (keeping every other stored run), "
                  "--overwrite to discard the stored runs and start again, or choose another --out"}));
    EXPECT_EQ(read_text(dir / "runs.csv"), runs); // untouched
    ASSERT_EQ(mhbench(args + " --seed 5 --overwrite").exit_code, 0);
    EXPECT_NE(read_text(dir / "runs.csv"), runs);
    EXPECT_NE(read_text(dir / "study.ini").find("seed = 5\n"), std::string::npos);
}

// context.ini keeps every session that wrote into the directory; the report shows the first and
// the latest.
TEST(CliRun, AnExtendedStudyKeepsTheHistoryOfItsSessions) {
    const fs::path dir = fresh("history");
    const std::string args = "run --algorithms random-search --problems sphere:dim=2 --iterations 3 --out " +
                             dir.string() + " --no-figures --quiet --runs ";
    ASSERT_EQ(mhbench(args + "2").exit_code, 0);
    const CliRunResult extended = mhbench(args + "3");
    ASSERT_EQ(extended.exit_code, 0) << extended.err;
    const std::string context = read_text(dir / "context.ini");
    std::vector<std::string> sessions;
    for (const auto& line : lines_of(context))
        if (line.rfind("session = ", 0) == 0)
            sessions.push_back(line);
    ASSERT_EQ(sessions.size(), 2u) << context;
    EXPECT_TRUE(sessions[0].ends_with("--runs 2")) << sessions[0];
    EXPECT_TRUE(sessions[1].ends_with("--runs 3")) << sessions[1];
    EXPECT_NE(context.find("command = mhbench " + args + "3\n"), std::string::npos) << context;
    const std::string html = read_text(dir / "report" / "index.html");
    EXPECT_NE(html.find("<dt>First session</dt>"), std::string::npos);
    EXPECT_NE(html.find("<dt>Latest session (of 2)</dt>"), std::string::npos);
    const std::string tex = read_text(dir / "report" / "report.tex");
    EXPECT_NE(tex.find("first session &"), std::string::npos);
    EXPECT_NE(tex.find("latest session (of 2) &"), std::string::npos);
    // --overwrite discards the runs, and with them the sessions that made them.
    ASSERT_EQ(mhbench(args + "2 --overwrite --no-report").exit_code, 0);
    EXPECT_EQ(lines_of(mhb::context_sessions(read_text(dir / "context.ini"))).size(), 1u);
}

TEST(CliRun, InterruptKeepsFinishedRunsAndTheSameCommandResumes) {
    const fs::path dir = fresh("interrupted");
    // Far more work than the test waits for (1000 runs of about 20 ms).
    const std::string command =
        std::string("'") + MHB_CLI_PATH +
        "' run --no-report --algorithms random-search:batch=1000 --problems sphere:dim=5 --runs 1000 "
        "--evaluations 200000 --threads 1 --out " +
        dir.string();
    // SIGINT as soon as the store grows, i.e. once this session has stored a run.
    const std::string journal = (dir / "store.bin").string();
    const std::string interrupt = "s0=$(cat " + journal + " 2>/dev/null | wc -c); " + command +
                                  " & pid=$!; i=0; while [ \"$(cat " + journal +
                                  " 2>/dev/null | wc -c)\" -le \"$s0\" ] && [ $i -lt 600 ]; do sleep 0.05; "
                                  "i=$((i+1)); done; kill -INT $pid; wait $pid";
    const auto kept_of = [](const std::string& err) {
        // "interrupted: K of 1000 runs kept in DIR; run the same command again to resume"
        return std::stoll(err.substr(err.find(':') + 2));
    };
    const CliRunResult first = run_shell(interrupt);
    EXPECT_EQ(first.exit_code, 130) << first.err;
    EXPECT_EQ(lines_of(first.err),
              std::vector<std::string>{"interrupted: " + std::to_string(kept_of(first.err)) +
                                       " of 1000 runs kept in " + dir.string() +
                                       "; run the same command again to resume"});
    EXPECT_GE(kept_of(first.err), 1);
    EXPECT_FALSE(fs::exists(dir / "runs.csv"));
    EXPECT_TRUE(fs::exists(dir / "store.bin"));

    // The same command again picks up where it stopped: the count only grows.
    const CliRunResult second = run_shell(interrupt);
    EXPECT_EQ(second.exit_code, 130) << second.err;
    EXPECT_GE(kept_of(second.err), kept_of(first.err) + 1);
    EXPECT_FALSE(fs::exists(dir / "runs.csv"));
    fs::remove_all(dir); // 1000-run stores are not worth keeping in /tmp
}

TEST(CliList, ListsTheOutputFormatsFromTheReporterRegistry) {
    const CliRunResult r = mhbench("list formats");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* line : {"  md (table format, default)", "  csv (table format, default)",
                             "  ioh (every report)", "  html (every report)"})
        EXPECT_NE(r.out.find(std::string("\n") + line + "\n"), std::string::npos) << line << '\n' << r.out;
    EXPECT_EQ(r.out.find("Algorithms"), std::string::npos); // only what was asked for
}

TEST(CliList, ListsRandomSearchWithItsParameter) {
    const CliRunResult r = mhbench("list algorithms");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("random-search"), std::string::npos);
    EXPECT_NE(r.out.find("Brooks (1958)"), std::string::npos);
    // The parameter row: name, default, allowed range, meaning.
    bool found = false;
    for (const auto& line : lines_of(r.out))
        if (line.find("batch") != std::string::npos && line.find("50") != std::string::npos &&
            line.find("[1, 1000000000]") != std::string::npos &&
            line.find("evaluations per iteration") != std::string::npos)
            found = true;
    EXPECT_TRUE(found) << r.out;
    EXPECT_EQ(r.out.find("Problems"), std::string::npos); // only what was asked for
    // Each entry's implementation version, which joins its runs' identities.
    EXPECT_NE(r.out.find("\n  random-search (version " +
                         std::to_string(mhb::builtin_algorithms().find("random-search").version) + ")\n"),
              std::string::npos)
        << r.out;

    const CliRunResult all = mhbench("list");
    ASSERT_EQ(all.exit_code, 0);
    for (const char* word : {"Algorithms", "Problems", "sphere", "Study presets", "paper", "smoke"})
        EXPECT_NE(all.out.find(word), std::string::npos) << word;

    const CliRunResult bad = mhbench("list nothing");
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_EQ(lines_of(bad.err),
              std::vector<std::string>{
                  "mhbench list: unknown list 'nothing'; known: algorithms, problems, studies, formats"});
}

TEST(CliList, ANameShowsThatEntryAloneAndAMisspeltOneTheNearName) {
    const CliRunResult pmsm = mhbench("list problems pmsm");
    ASSERT_EQ(pmsm.exit_code, 0) << pmsm.err;
    EXPECT_EQ(pmsm.out.rfind("  pmsm (version ", 0), 0U) << pmsm.out; // the entry first, no heading
    EXPECT_NE(pmsm.out.find("      parameter "), std::string::npos) << pmsm.out;
    EXPECT_EQ(pmsm.out.find("sphere"), std::string::npos); // nothing else
    EXPECT_NE(pmsm.out.find("Write it as name:key=value,... e.g. pmsm:"), std::string::npos) << pmsm.out;

    const CliRunResult study = mhbench("list studies paper");
    ASSERT_EQ(study.exit_code, 0) << study.err;
    EXPECT_EQ(study.out.rfind("  paper\n", 0), 0U) << study.out;
    EXPECT_EQ(study.out.find("  smoke\n"), std::string::npos);

    const CliRunResult typo = mhbench("list algorithms itlob");
    EXPECT_EQ(typo.exit_code, 2);
    EXPECT_EQ(lines_of(typo.err),
              std::vector<std::string>{"mhbench list: unknown algorithm 'itlob'; did you mean 'itlbo'?"});
    const CliRunResult kind = mhbench("list algoritms");
    EXPECT_EQ(kind.exit_code, 2);
    EXPECT_EQ(lines_of(kind.err),
              std::vector<std::string>{"mhbench list: unknown list 'algoritms'; did you mean 'algorithms'?"});
}

TEST(CliHelp, EveryCommandExplainsItself) {
    const CliRunResult top = mhbench("--help");
    EXPECT_EQ(top.exit_code, 0);
    EXPECT_NE(top.out.find("run "), std::string::npos);
    EXPECT_NE(top.out.find("list "), std::string::npos);

    const CliRunResult run = mhbench("run --help");
    EXPECT_EQ(run.exit_code, 0);
    for (const char* option : {"--algorithms", "--problems", "--runs", "--seed", "--threads", "--iterations",
                               "--evaluations", "--target", "--out", "--overwrite", "--study", "--study-file",
                               "--progress", "--quiet", "default 20", "Examples:", "paper"})
        EXPECT_NE(run.out.find(option), std::string::npos) << option;

    const CliRunResult list = mhbench("list --help");
    EXPECT_EQ(list.exit_code, 0);
    EXPECT_NE(list.out.find("mhbench list [algorithms|problems|studies [NAME]]"), std::string::npos);
}

} // namespace

namespace {

TEST(CliRun, AStudyWhoseRunsAllFailExitsNonZeroAndSaysWhyEvenWhenQuiet) {
    const fs::path dir = fresh("all_failed");
    // A model that crashes at its first evaluation.
    const std::string crashing = "--problem \"external:cmd='/usr/bin/python3 " +
                                 std::string(MHB_TEST_DATA_DIR) +
                                 "/external/faulty_problem.py crash 1 cli-all-failed'\"";
    const CliRunResult r = mhbench("run --algorithms tlbo " + crashing +
                                   " --evaluations 100 --runs 2 --quiet --out " + dir.string());
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("2 of 2 runs failed (all of them)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("segmentation fault in the model"), std::string::npos) << r.err;
    // Some failed: the study and its report go on, and stderr still says so.
    const CliRunResult some =
        mhbench("run --algorithms tlbo --problems sphere:dim=2 " + crashing +
                " --evaluations 100 --runs 2 --no-report --out " + fresh("some_failed").string());
    EXPECT_EQ(some.exit_code, 0) << some.err;
    EXPECT_NE(some.err.find("2 of 4 runs failed; each carries its message in"), std::string::npos)
        << some.err;
}

TEST(CliRun, OutIntoADirectoryOfSomeoneElsesFilesIsRefusedAndTouchesNothing) {
    const fs::path dir = fresh("users_own");
    fs::create_directories(dir);
    std::ofstream(dir / "curves.csv") << "my own curves\n";
    std::ofstream(dir / "study.ini") << "my own notes\n";
    for (const char* extra : {"", " --overwrite"}) {
        const CliRunResult r = mhbench("run --study smoke --out " + dir.string() + extra);
        EXPECT_EQ(r.exit_code, 1) << extra;
        EXPECT_EQ(r.err,
                  "mhbench run: " + dir.string() +
                      ": is not empty and is not a mhbench study (it has no .mhbench-study); its files are "
                      "left alone: choose a new or empty --out\n");
    }
    EXPECT_EQ(read_text(dir / "curves.csv"), "my own curves\n");
    EXPECT_EQ(read_text(dir / "study.ini"), "my own notes\n");
    EXPECT_FALSE(fs::exists(dir / "runs.csv"));
    // A study directory carries the marker; running again into it is the usual resume/refusal.
    const fs::path study = fresh("marked");
    ASSERT_EQ(mhbench("run --study smoke --quiet --no-report --out " + study.string()).exit_code, 0);
    EXPECT_TRUE(fs::exists(study / ".mhbench-study"));
}

TEST(CliMain, VersionTakesNoOtherArgument) {
    EXPECT_EQ(mhbench("--version").exit_code, 0);
    const CliRunResult r = mhbench("--version --bogus");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "mhbench: --version takes no other argument (got '--bogus')\n");
}

} // namespace
