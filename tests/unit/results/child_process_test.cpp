// run_child_process (results/report/child_process.hpp): arguments reach the program exactly as given, with
// no shell between; the child inherits no descriptor but 0, 1 and 2; a stop signal that reaches
// this process while it waits is passed on and reported; and the child dies with its parent, even
// when the parent is killed with SIGKILL.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "results/report/child_process.hpp"
#include "support/processes.hpp"

namespace mhb {
namespace {
namespace fs = std::filesystem;

using mhb::test_support::processes_with;
using mhb::test_support::wait_until;

std::string unique_marker(const std::string& what) {
    return "mhb-child-test-" + what + "-" + std::to_string(::getpid());
}

TEST(ChildProcess, ArgumentsArriveAsGivenWithoutAShell) {
    const std::vector<std::string> arguments = {"it's a \"dir\"", "$(echo no) `echo no` ; | *", "", "a\\b"};
    std::vector<std::string> printf_arguments = {"[%s]"};
    printf_arguments.insert(printf_arguments.end(), arguments.begin(), arguments.end());
    const ChildOutcome o = run_child_process("printf", printf_arguments, true); // found in PATH
    ASSERT_TRUE(o.started) << o.error;
    EXPECT_TRUE(o.exited_with(0));
    EXPECT_EQ(o.out, "[it's a \"dir\"][$(echo no) `echo no` ; | *][][a\\b]");
    EXPECT_EQ(o.err, "");
    EXPECT_FALSE(o.stop_requested);
}

TEST(ChildProcess, ExitStatusAndBothStreamsAreCollected) {
    const ChildOutcome o = run_child_process("/bin/sh", {"-c", "echo out; echo err >&2; exit 3"}, true);
    ASSERT_TRUE(o.started) << o.error;
    EXPECT_TRUE(o.exited_with(3));
    EXPECT_EQ(o.out, "out\n");
    EXPECT_EQ(o.err, "err\n");
    const ChildOutcome quiet = run_child_process("/bin/sh", {"-c", "echo out; exit 0"}, false);
    EXPECT_TRUE(quiet.exited_with(0));
    EXPECT_EQ(quiet.out, ""); // discarded
}

TEST(ChildProcess, AProgramThatCannotRunIsSaidNotStarted) {
    const ChildOutcome missing = run_child_process("/nonexistent/python3", {"-c", "pass"}, true);
    EXPECT_FALSE(missing.started);
    EXPECT_NE(missing.error.find("/nonexistent/python3 cannot be run (No such file or directory)"),
              std::string::npos)
        << missing.error;
    const ChildOutcome unknown = run_child_process("mhb-no-such-program-anywhere", {}, true);
    EXPECT_FALSE(unknown.started);
    EXPECT_EQ(unknown.error, "mhb-no-such-program-anywhere: not found in PATH");
}

TEST(ChildProcess, InheritsOnlyTheStandardDescriptorsAndNoInput) {
    // A descriptor opened without close-on-exec (as std::ofstream does) must not leak into the child.
    const fs::path file = fs::temp_directory_path() / (unique_marker("fd") + ".txt");
    std::ofstream open_here(file);
    const ChildOutcome o = run_child_process("/bin/sh", {"-c", "ls /proc/$$/fd; cat"}, true);
    open_here.close();
    fs::remove(file);
    ASSERT_TRUE(o.exited_with(0)) << o.err;
    EXPECT_EQ(o.out, "0\n1\n2\n"); // and cat read nothing: stdin is /dev/null
}

TEST(ChildProcess, AStopSignalIsPassedOnAndReported) {
    const std::string marker = unique_marker("stop");
    std::thread stopper([&] {
        // The handler is in place before the child exists: signal once it runs.
        if (wait_until([&] { return !processes_with(marker).empty(); }, 20.0))
            ::kill(::getpid(), SIGTERM);
    });
    const auto started = std::chrono::steady_clock::now();
    // The marker is an argument, so the child can be found in /proc.
    const ChildOutcome o =
        run_child_process("/usr/bin/python3", {"-c", "import time; time.sleep(30)", marker}, true);
    stopper.join();
    ASSERT_TRUE(o.started) << o.error;
    EXPECT_TRUE(o.stop_requested);
    EXPECT_TRUE(WIFSIGNALED(o.status) && WTERMSIG(o.status) == SIGTERM) << o.status;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 20.0);
    struct sigaction now {}; // the previous disposition is back
    ::sigaction(SIGTERM, nullptr, &now);
    EXPECT_EQ(now.sa_handler, SIG_DFL);
}

TEST(ChildProcess, TheChildDiesWithItsParentEvenBySigkill) {
    const std::string marker = unique_marker("orphan");
    const pid_t parent = ::fork();
    ASSERT_GE(parent, 0);
    if (parent == 0) { // the stand-in for mhbench: waits for a child that would sleep a minute
        (void)run_child_process("/usr/bin/python3", {"-c", "import time; time.sleep(60)", marker}, true);
        ::_exit(0);
    }
    ASSERT_TRUE(wait_until([&] { return !processes_with(marker).empty(); }, 20.0));
    const pid_t child = processes_with(marker).front();
    ::kill(parent, SIGKILL);
    int status = 0;
    ::waitpid(parent, &status, 0);
    EXPECT_TRUE(wait_until([&] { return ::kill(child, 0) != 0 || processes_with(marker).empty(); }, 5.0));
    EXPECT_TRUE(wait_until(
        [&] {
            std::ifstream stat_file("/proc/" + std::to_string(child) + "/stat");
            std::string stat((std::istreambuf_iterator<char>(stat_file)), std::istreambuf_iterator<char>());
            const auto paren = stat.rfind(')');
            return stat.empty() || (paren != std::string::npos && stat[paren + 2] == 'Z');
        },
        5.0))
        << "process " << child << " outlived its parent";
}

} // namespace
} // namespace mhb
