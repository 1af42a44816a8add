// Finding processes by their command line, and waiting for a condition: the tests that check no
// child outlives its parent (a plotting script after SIGKILL, say) share them.
#pragma once

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "support/files.hpp"

namespace mhb::test_support {

// The pids of live (not zombie) processes other than this one whose command line (arguments
// joined by spaces) holds every one of `markers`.
inline std::vector<pid_t> processes_with(const std::vector<std::string>& markers) {
    std::vector<pid_t> found;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos || std::stol(name) == ::getpid())
            continue;
        std::string command = read_text(entry.path() / "cmdline");
        std::replace(command.begin(), command.end(), '\0', ' ');
        if (!std::all_of(markers.begin(), markers.end(),
                         [&](const std::string& m) { return command.find(m) != std::string::npos; }))
            continue;
        const std::string stat = read_text(entry.path() / "stat");
        const auto paren = stat.rfind(')');
        if (paren != std::string::npos && paren + 2 < stat.size() && stat[paren + 2] == 'Z')
            continue;
        found.push_back(static_cast<pid_t>(std::stol(name)));
    }
    return found;
}

inline std::vector<pid_t> processes_with(const std::string& marker) {
    return processes_with(std::vector<std::string>{marker});
}

// Whether process `pid` has ended: gone, or a zombie that nobody has reaped yet (an orphan whose
// reaper is slow, or none in a container).
inline bool process_ended(pid_t pid) {
    const std::string stat = read_text("/proc/" + std::to_string(pid) + "/stat");
    const auto paren = stat.rfind(')');
    return stat.empty() || (paren != std::string::npos && paren + 2 < stat.size() && stat[paren + 2] == 'Z');
}

// Polls `condition` every 10 ms for up to `seconds`; its last value.
template <class Condition> bool wait_until(Condition condition, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (condition())
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return condition();
}

} // namespace mhb::test_support
