// The child process of an external program: a write to one that has exited is a ChildFault that
// says so, in any host of the library (this test process keeps SIGPIPE at its default, which
// would end it), and leaves no SIGPIPE pending behind; and a program gets SIGPIPE at its default
// even from a process that ignores it, as mhbench does.
#include <csignal>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "problems/external/child_link.hpp"

namespace mhb {
namespace {

TEST(ExternalChildLink, WritingToAProgramThatHasExitedIsAFaultNotASigpipe) {
    struct sigaction now {};
    ASSERT_EQ(::sigaction(SIGPIPE, nullptr, &now), 0);
    ASSERT_EQ(now.sa_handler, SIG_DFL);
    external::ChildLink link({"/bin/sh", "-c", "echo gone >&2; exit 5"});
    try {
        // Far more than a pipe holds: whenever the program exits, the rest has no reader.
        link.send(std::string(std::size_t{1} << 22, ' '));
        ADD_FAILURE() << "no fault";
    } catch (const external::ChildFault& fault) {
        EXPECT_EQ(std::string(fault.what()), "/bin/sh exited with status 5 before reading all it was sent");
        EXPECT_EQ(fault.stderr_tail(), "gone");
    }
    sigset_t pending;
    sigemptyset(&pending);
    ASSERT_EQ(::sigpending(&pending), 0);
    EXPECT_EQ(sigismember(&pending, SIGPIPE), 0);
}

TEST(ExternalChildLink, AProgramGetsSigpipeAtItsDefaultFromAProcessThatIgnoresIt) {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    struct sigaction previous {};
    ASSERT_EQ(::sigaction(SIGPIPE, &ignore, &previous), 0);
    std::string ignored;
    {
        // The mask of ignored signals, in hexadecimal, of the program itself (exec keeps it).
        external::ChildLink link(
            {"/bin/sh", "-c", "exec sed -n 's/^SigIgn:[[:space:]]*//p' /proc/self/status"});
        ignored = link.receive(std::chrono::seconds(10));
    }
    ::sigaction(SIGPIPE, &previous, nullptr);
    ASSERT_FALSE(ignored.empty());
    const unsigned long long mask = std::stoull(ignored, nullptr, 16);
    EXPECT_EQ(mask & (1ULL << (SIGPIPE - 1)), 0U) << ignored;
}

} // namespace
} // namespace mhb
