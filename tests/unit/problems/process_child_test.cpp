// problems/core/process/child_process.hpp: ending a child ends what it started (its process
// group); its exit is told in words; reads keep their deadline; its stderr's last lines are kept;
// a program that cannot be started says why in one line. (SIGPIPE-safe writes: the ChildLink tests;
// the watcher after a SIGKILL of mhbench: FigureOrphans and ExternalStudy.)
#include <chrono>
#include <csignal>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

#include "problems/core/process/child_process.hpp"
#include "support/processes.hpp"

namespace mhb {
namespace {

using process::ChildProcess;
using process::Stream;
using test_support::process_ended;

std::chrono::steady_clock::time_point in_seconds(double seconds) {
    return std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                  std::chrono::duration<double>(seconds));
}

TEST(ChildProcessModule, EndingAChildEndsWhatItStarted) {
    ChildProcess child({"/bin/sh", "-c", "sleep 300 & echo $!; wait"}, {.output = Stream::pipe});
    std::string said;
    while (said.find('\n') == std::string::npos)
        ASSERT_EQ(child.read_output(said, in_seconds(10)), ChildProcess::Read::data);
    const pid_t grandchild = std::stoi(said);
    EXPECT_FALSE(process_ended(grandchild));
    EXPECT_FALSE(child.exited());
    const int status = child.end();
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
    EXPECT_TRUE(test_support::wait_until([&] { return process_ended(grandchild); }, 5.0));
}

TEST(ChildProcessModule, ItsExitIsToldInWordsAndItsOutputKept) {
    ChildProcess exits({"/bin/sh", "-c", "echo out; echo err >&2; exit 3"},
                       {.output = Stream::memory, .errors = Stream::memory});
    exits.wait_for_exit();
    EXPECT_EQ(exits.exit_description("running"), "exited with status 3");
    EXPECT_EQ(exits.captured_output(), "out\n");
    EXPECT_EQ(exits.captured_errors(), "err\n");
    const int status = exits.end();
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 3) << status;

    ChildProcess killed({"/bin/sh", "-c", "kill -9 $$"}, {});
    EXPECT_TRUE(killed.wait_for_exit(in_seconds(10)));
    EXPECT_EQ(killed.exit_description("running"), "was killed by signal 9 (Killed)");

    ChildProcess running({"sleep", "300"}, {}); // found in PATH
    EXPECT_EQ(running.exit_description("still running"), "still running");
}

TEST(ChildProcessModule, AReadKeepsItsDeadlineAndStderrKeepsItsLastLines) {
    ChildProcess quiet(
        {"/bin/sh", "-c", "for i in 1 2 3 4 5 6 7 8 9 10; do echo line $i >&2; done; exec sleep 300"},
        {.input = Stream::pipe, .output = Stream::pipe, .errors = Stream::tail});
    const auto started = std::chrono::steady_clock::now();
    std::string said;
    EXPECT_EQ(quiet.read_output(said, in_seconds(0.3)), ChildProcess::Read::timeout);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 5.0);
    EXPECT_EQ(said, "");
    const auto deadline = in_seconds(10);
    std::string tail = quiet.error_tail();
    while (!tail.ends_with("line 10") && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        tail = quiet.error_tail();
    }
    EXPECT_EQ(tail, "line 3 | line 4 | line 5 | line 6 | line 7 | line 8 | line 9 | line 10"); // the last 8
    EXPECT_TRUE(quiet.write_input("more than it reads\n"));
}

TEST(ChildProcessModule, AProgramThatCannotStartSaysWhyInOneLine) {
    const auto error_of = [](const std::vector<std::string>& argv) {
        try {
            ChildProcess child(argv, {});
        } catch (const process::SpawnError& e) {
            return std::string(e.what());
        }
        return std::string("started");
    };
    EXPECT_EQ(error_of({}), "the command is empty");
    EXPECT_EQ(error_of({"mhb-no-such-program-anywhere"}), "mhb-no-such-program-anywhere: not found in PATH");
    EXPECT_EQ(error_of({"/nonexistent/program"}),
              "/nonexistent/program cannot be run (No such file or directory)");
}

} // namespace
} // namespace mhb
