// context.ini carries the build's identity and the command line; the progress bar draws the
// documented line, stays silent before its delay, and formats durations.
#include <gtest/gtest.h>
#include <sstream>

#include "mhb_version.hpp"
#include "runner/context.hpp"
#include "runner/progress.hpp"

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

TEST(Progress, FormatsDurations) {
    EXPECT_EQ(format_duration(0.0), "0:00");
    EXPECT_EQ(format_duration(59.4), "0:59");
    EXPECT_EQ(format_duration(61.0), "1:01");
    EXPECT_EQ(format_duration(3725.0), "1:02:05");
    EXPECT_EQ(format_duration(-3.0), "0:00");
}

TEST(Progress, DrawsRunsDoneOfTotalWhenShownAndNothingBeforeTheDelay) {
    std::ostringstream shown;
    ProgressBar bar(shown, 4, 1, 0.0);
    bar.update(4); // the last run always draws
    bar.finish();
    const std::string text = shown.str();
    EXPECT_NE(text.find("\r[##############################] 4/4 runs  elapsed 0:00  eta 0:00"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.back(), '\n');

    std::ostringstream quiet;
    ProgressBar late(quiet, 4, 0, 3600.0);
    late.update(1);
    late.update(4);
    late.finish();
    EXPECT_EQ(quiet.str(), "");
}

} // namespace
} // namespace mhb
