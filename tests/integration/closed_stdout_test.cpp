// mhbench's own stdout read by nobody any more (`mhbench list | head -1` once head has gone): the
// write fails, and mhbench ends quietly with status 1 instead of dying of SIGPIPE (141).
#include <gtest/gtest.h>
#include <string>

#include "cli_harness.hpp"

namespace {

using mhb::testing_cli::run_shell;

// `mhbench ARGS` with a stdout pipe whose reader is closed before mhbench starts (so the first
// write has no reader, every time), started like a shell would (SIGPIPE at its default). Prints
// mhbench's exit status, or 128 + the signal that ended it, as a shell does.
std::string with_closed_stdout(const std::string& args) {
    return std::string("/usr/bin/python3 -c \"import os, subprocess, sys\n"
                       "r, w = os.pipe()\nos.close(r)\n"
                       "code = subprocess.call(sys.argv[1:], stdout=w)\n"
                       "print(code if code >= 0 else 128 - code)\" '") +
           MHB_CLI_PATH + "' " + args;
}

TEST(ClosedStdout, ListEndsQuietlyWithAStatus) {
    const auto r = run_shell(with_closed_stdout("list"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "1\n") << r.err;
    EXPECT_EQ(r.err, "");
}

TEST(ClosedStdout, AFullDiskIsSaidOnStderr) {
    const auto r = mhb::testing_cli::run_mhbench("--version >/dev/full");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("mhbench: cannot write to stdout"), std::string::npos) << r.err;
}

} // namespace
