// The subcommands of the `mhbench` executable. Each lives in its own file as
// `int run_<name>_command(const std::vector<std::string>& args)` and is listed once in main.cpp.
// Only the CLI parses command lines (Boost.Program_options) and only the CLI exits: library code
// throws, and main turns an exception into one line on stderr and a non-zero exit.
#pragma once

#include <string>
#include <vector>

namespace mhb::cli {

using CommandFunction = int (*)(const std::vector<std::string>& args);

struct Command {
    const char* name;
    const char* summary;
    CommandFunction run;
};

// Exit codes shared by every command.
inline constexpr int exit_ok = 0;
inline constexpr int exit_failure = 1; // the work failed (bad data, a failed run, I/O)
inline constexpr int exit_usage = 2;   // the command line was wrong
inline constexpr int exit_interrupted = 130;

} // namespace mhb::cli
