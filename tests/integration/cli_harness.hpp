// Runs the real `mhbench` binary (MHB_CLI_PATH) for the integration tests and collects its exit
// code, stdout and stderr. Output goes through files named after the process and the test, so
// tests that CTest runs in parallel never share them.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "support/files.hpp"

namespace mhb::testing_cli {

struct CliResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

using mhb::test_support::read_text;

inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

// A scratch directory for this test binary.
inline std::filesystem::path scratch_directory() {
    const auto dir = std::filesystem::temp_directory_path() / ("mhb_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

// `name` in the scratch directory, removed if it was there.
inline std::filesystem::path fresh(const std::string& name) {
    const auto dir = scratch_directory() / name;
    std::filesystem::remove_all(dir);
    return dir;
}

// A path in single quotes for the shell (paths with a quote in them are not supported).
inline std::string shell_quoted(const std::filesystem::path& path) {
    std::string out = "'"; // appended, not `"'" + ...`: GCC 12 warns (-Wrestrict) on that falsely
    out += path.string();
    return out += '\'';
}

// Runs a shell command line and collects what it printed.
inline CliResult run_shell(const std::string& command) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name =
        info != nullptr ? std::string(info->test_suite_name()) + "." + info->name() : "none";
    const auto out = scratch_directory() / (name + ".stdout");
    const auto err = scratch_directory() / (name + ".stderr");
    const std::string line = "(" + command + ") >'" + out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(line.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_text(out);
    r.err = read_text(err);
    return r;
}

// Runs `mhbench ARGS` (ARGS as typed in a shell).
inline CliResult run_mhbench(const std::string& args) {
    // Appended piece by piece: GCC 12 takes `std::string("'") + MHB_CLI_PATH + ...`, inlined, for a
    // copy past the first temporary's small buffer (a false -Warray-bounds).
    std::string command = "'";
    command += MHB_CLI_PATH;
    command += "' ";
    command += args;
    return run_shell(command);
}

} // namespace mhb::testing_cli
