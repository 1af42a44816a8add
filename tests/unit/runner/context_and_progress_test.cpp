// context.ini carries the build's identity and the command line; the progress bar draws the
// documented line, stays silent before its delay, and formats durations.
#include <algorithm>
#include <gtest/gtest.h>
#include <sstream>

#include "mhb_version.hpp"
#include "runner/execution/context.hpp"
#include "runner/execution/progress.hpp"

namespace mhb {
namespace {

TEST(Context, HoldsVersionCommitCompilerThreadsAndQuotedCommandLine) {
    const std::string text = context_ini(3, {"mhbench", "run", "--algorithms", "a b", "--out", "it's"});
    EXPECT_NE(text.find("version = " + std::string(build::version) + "\n"), std::string::npos);
    EXPECT_NE(text.find("git_commit = " + std::string(build::git_commit) + "\n"), std::string::npos);
    EXPECT_NE(text.find("compiler = " + std::string(build::compiler) + "\n"), std::string::npos);
    EXPECT_NE(text.find("build_type = "), std::string::npos);
    EXPECT_NE(text.find("threads = 3\n"), std::string::npos);
    EXPECT_NE(text.find("hardware_threads = "), std::string::npos);
    EXPECT_NE(text.find("date_utc = 20"), std::string::npos);
    EXPECT_NE(text.find("hostname = "), std::string::npos);
    // Quoted so that it can be pasted back into a POSIX shell.
    EXPECT_NE(text.find("command = mhbench run --algorithms 'a b' --out 'it'\\''s'\n"), std::string::npos);
}

TEST(Context, KeepsEverySessionOfAResumedStudyFirstFirst) {
    // A context.ini written before histories were kept: its one session comes from its fields.
    const std::string old =
        "# comment\nversion = 0.0.9\ngit_commit = abc\ngit_dirty_at_build = yes\n"
        "date_utc = 2025-01-02T03:04:05Z\nhostname = node7\ncommand = mhbench run --runs 2\n";
    const std::string old_session = "session = 2025-01-02T03:04:05Z on node7, mhbench 0.0.9 commit abc "
                                    "(dirty: yes): mhbench run --runs 2\n";
    EXPECT_EQ(context_sessions(old), old_session);
    EXPECT_EQ(context_sessions(""), "");

    const std::string second =
        context_with_history(context_ini(1, {"mhbench", "run", "--runs", "3"}), context_sessions(old));
    const std::string third =
        context_with_history(context_ini(1, {"mhbench", "run", "--runs", "4"}), context_sessions(second));
    // The latest session's fields head the file, as readers of context.ini expect.
    EXPECT_EQ(third.rfind("# Where and how", 0), 0U);
    EXPECT_NE(third.find("command = mhbench run --runs 4\n"), std::string::npos);
    EXPECT_EQ(third.find("command = mhbench run --runs 3\n"), std::string::npos);
    // Then every session, the first first, each naming its commit and command.
    const std::string history = context_sessions(third);
    EXPECT_EQ(history.rfind(old_session, 0), 0U) << history;
    EXPECT_EQ(std::count(history.begin(), history.end(), '\n'), 3);
    EXPECT_NE(history.find("): mhbench run --runs 3\nsession = "), std::string::npos) << history;
    EXPECT_TRUE(history.ends_with(", mhbench " + std::string(build::version) + " commit " +
                                  build::git_commit + " (dirty: " + build::git_dirty +
                                  "): mhbench run --runs 4\n"))
        << history;
}

TEST(Progress, FormatsDurations) {
    EXPECT_EQ(format_duration(0.0), "0:00");
    EXPECT_EQ(format_duration(59.4), "0:59");
    EXPECT_EQ(format_duration(61.0), "1:01");
    EXPECT_EQ(format_duration(3725.0), "1:02:05");
    EXPECT_EQ(format_duration(-3.0), "0:00");
}

TEST(Progress, DrawsRunsRatesAndEtaWhenShownAndNothingBeforeTheDelay) {
    std::ostringstream shown;
    ProgressBar bar(shown, ProgressWork::uniform(4, 1), ProgressOptions{true, 0.0, 10.0});
    bar.update(1, 1000);
    bar.update(2, 1000);
    bar.update(3, 1000); // the last run always draws
    bar.finish();
    const std::string text = shown.str();
    EXPECT_NE(text.find("\r[####################] 4/4 runs 100%  "), std::string::npos) << text;
    EXPECT_NE(text.find(" runs/s  "), std::string::npos) << text;
    EXPECT_NE(text.find(" evals/s  elapsed 0:00  eta 0:00"), std::string::npos) << text;
    EXPECT_EQ(text.back(), '\n');

    std::ostringstream quiet;
    ProgressBar late(quiet, ProgressWork::uniform(4, 0), ProgressOptions{true, 3600.0, 10.0});
    for (std::int64_t id = 0; id < 4; ++id)
        late.update(id);
    late.finish();
    EXPECT_EQ(quiet.str(), "");
}

TEST(Progress, ABatchLogGetsAPlainLinePerIntervalAndNoCarriageReturn) {
    std::ostringstream log;
    ProgressBar lines(log, ProgressWork::uniform(3, 0), ProgressOptions{false, 0.0, 1e-9});
    lines.update(0, 50);
    lines.update(1, 50);
    lines.finish();
    const std::string text = log.str();
    EXPECT_EQ(text.find('\r'), std::string::npos);
    EXPECT_EQ(text.rfind("progress: 1/3 runs (33% of the work), ", 0), 0u) << text;
    EXPECT_NE(text.find("\nprogress: 2/3 runs (67% of the work), "), std::string::npos) << text;
    EXPECT_NE(text.find(" evals/s, elapsed 0:00, eta "), std::string::npos) << text;
    // Within the interval nothing more is written.
    std::ostringstream sparse;
    ProgressBar rare(sparse, ProgressWork::uniform(3, 0), ProgressOptions{false, 0.0, 3600.0});
    rare.update(0, 5);
    rare.update(2, 5);
    rare.finish();
    EXPECT_EQ(sparse.str(), "");
}

// Two runs of very different cost: finishing the cheap one moves the work by its share (1%), not
// by half; the expensive one then completes it. A stored run counts as done from the start.
TEST(Progress, RunsWeighByTheirCostNotTheirCount) {
    ProgressWork work({1.0, 99.0}, {0, 1}, {});
    EXPECT_EQ(work.fraction_done(), 0.0);
    work.finished(0);
    EXPECT_DOUBLE_EQ(work.fraction_done(), 0.01);
    EXPECT_EQ(work.runs_done(), 1);
    EXPECT_DOUBLE_EQ(work.remaining(), 99.0);
    work.finished(1);
    EXPECT_DOUBLE_EQ(work.fraction_done(), 1.0);

    const ProgressWork resumed({1.0, 99.0, 5.0}, {1, 2}, {1, 7}); // run 0 is another shard's; 7 not counted
    EXPECT_EQ(resumed.runs(), 2);
    EXPECT_EQ(resumed.runs_done(), 1);
    EXPECT_DOUBLE_EQ(resumed.fraction_done(), 99.0 / 104.0);
    EXPECT_EQ(resumed.done_here(), 0.0); // a resumed run took no time in this session

    std::ostringstream log;
    ProgressBar lines(log, ProgressWork({1.0, 99.0}, {0, 1}, {}), ProgressOptions{false, 0.0, 1e-9});
    lines.update(0, 10);
    EXPECT_EQ(log.str().rfind("progress: 1/2 runs (1% of the work), ", 0), 0u) << log.str();
}

// The ETA adds what follows the runs: "eta T (runs R, report S)" with T = R + S.
TEST(Progress, TheEtaIncludesTheReportAfterTheRuns) {
    std::ostringstream log;
    ProgressBar lines(log, ProgressWork::uniform(2, 0), ProgressOptions{false, 0.0, 1e-9}, 125.0);
    lines.update(0);
    const std::string text = log.str();
    const auto at = text.find(", eta ");
    ASSERT_NE(at, std::string::npos) << text;
    EXPECT_NE(text.find(" (runs ", at), std::string::npos) << text;
    EXPECT_TRUE(text.ends_with(", report 2:05)\n")) << text;
}

} // namespace
} // namespace mhb
