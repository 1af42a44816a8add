#include "runner/context.hpp"

#include <ctime>
#include <thread>
#include <unistd.h>

#include "mhb_version.hpp"

namespace mhb {
namespace {

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return buf;
}

std::string host_name() {
    char buf[256] = {};
    if (gethostname(buf, sizeof buf - 1) != 0)
        return "unknown";
    return buf;
}

// Quotes an argument for a POSIX shell when it needs it, so the line can be pasted back.
std::string shell_quote(const std::string& arg) {
    if (!arg.empty() && arg.find_first_of(" \t\n'\"\\$`*?[]{}()<>|&;#~") == std::string::npos)
        return arg;
    std::string out(1, '\'');
    for (const char c : arg) {
        if (c == '\'')
            out.append("'\\''"); // close the quote, an escaped quote, reopen
        else
            out.push_back(c);
    }
    out.push_back('\'');
    return out;
}

} // namespace

std::string context_ini(int threads, const std::vector<std::string>& command_line) {
    std::string command;
    for (const auto& arg : command_line) {
        if (!command.empty())
            command += ' ';
        command += shell_quote(arg);
    }
    std::string text = "# Where and how this study was run; it does not influence results.\n";
    text += "version = " + std::string(build::version) + '\n';
    text += "git_commit = " + std::string(build::git_commit) + '\n';
    text += "compiler = " + std::string(build::compiler) + '\n';
    text += "build_type = " + std::string(build::build_type) + '\n';
    text += "threads = " + std::to_string(threads) + '\n';
    text += "hardware_threads = " + std::to_string(std::thread::hardware_concurrency()) + '\n';
    text += "date_utc = " + utc_now() + '\n';
    text += "hostname = " + host_name() + '\n';
    text += "command = " + command + '\n';
    return text;
}

} // namespace mhb
