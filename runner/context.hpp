// context.ini: where and how a study was run (mhbench version, git commit, compiler, build
// type, threads, hardware threads, date and time UTC, host name, command line). Unlike study.ini
// it differs from machine to machine and is rewritten by every session of a resumed study; it
// never influences results.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "problems/problem.hpp"

namespace mhb {

// `command_line` is argv as given (quoted here when an argument holds spaces).
std::string context_ini(int threads, const std::vector<std::string>& command_line);

// "data_file = SHA256 PATH" for each data file of the study's problems (each file once): which
// exact content a study read, for the record.
std::string context_data_files(const std::vector<std::unique_ptr<Problem>>& problems);

} // namespace mhb
