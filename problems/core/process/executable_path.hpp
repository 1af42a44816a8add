// The file exec would run for a program name: the name itself when it holds a '/', else the first
// executable regular file of that name in PATH (an empty entry of PATH is the current folder, as
// for execvp; without PATH, /usr/local/bin:/usr/bin:/bin). Call it before fork: getenv is not
// async-signal-safe.
#pragma once

#include <optional>
#include <string>

namespace mhb::process {

std::optional<std::string> find_executable(const std::string& program);

} // namespace mhb::process
