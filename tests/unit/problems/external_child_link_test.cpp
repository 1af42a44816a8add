// The child process of an external program: a write to one that has exited is a ChildFault that
// says so, in any host of the library (this test process keeps SIGPIPE at its default, which
// would end it), and leaves no SIGPIPE pending behind.
#include <csignal>
#include <gtest/gtest.h>
#include <string>

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

} // namespace
} // namespace mhb
