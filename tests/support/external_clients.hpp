// Specs of the external protocol's test and reference clients (tests/data/external/,
// scripts/external/), run with Debian's /usr/bin/python3, and a check that no child of this
// process is left, live or zombie: the external tests share them.
#pragma once

#include <filesystem>
#include <string>
#include <sys/types.h>
#include <unistd.h>
#include <vector>

#include "support/files.hpp"

namespace mhb::test_support {

inline std::string python_command(const std::string& script, const std::string& arguments = "") {
    return "/usr/bin/python3 '" + script + "'" + (arguments.empty() ? "" : " " + arguments);
}

inline std::string test_client(const std::string& name, const std::string& arguments = "") {
    return python_command(std::string(MHB_TEST_DATA_DIR) + "/external/" + name, arguments);
}

inline std::string reference_client(const std::string& name, const std::string& arguments = "") {
    return python_command(std::string(MHB_SOURCE_DIR) + "/scripts/external/" + name, arguments);
}

// The pids of this process's children, zombies included (an unreaped child is a leak too).
inline std::vector<pid_t> children_of_this_process() {
    std::vector<pid_t> found;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos)
            continue;
        const std::string stat = read_text(entry.path() / "stat");
        const auto paren = stat.rfind(')');
        if (paren == std::string::npos || paren + 4 >= stat.size())
            continue;
        // "pid (comm) S ppid ...": the state, then the parent.
        const long parent = std::strtol(stat.c_str() + paren + 4, nullptr, 10);
        if (parent == ::getpid())
            found.push_back(static_cast<pid_t>(std::stol(name)));
    }
    return found;
}

} // namespace mhb::test_support
