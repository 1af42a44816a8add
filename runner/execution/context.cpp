#include "runner/execution/context.hpp"

#include <Eigen/Core>
#include <boost/version.hpp>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <nlopt.h>
#include <oneapi/tbb/version.h>
#include <set>
#include <sstream>
#include <sys/utsname.h>
#include <thread>
#include <unistd.h>

#include "mhb_version.hpp"

namespace mhb {
namespace {

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

// The first "model name" of /proc/cpuinfo (Linux), else "unknown".
std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
            std::string value = line.substr(line.find(':') + 1);
            value.erase(0, value.find_first_not_of(' '));
            return value;
        }
    return "unknown";
}

// PRETTY_NAME of /etc/os-release and the kernel (uname), e.g. "Debian GNU/Linux 12 (bookworm), Linux 6.1".
std::string operating_system() {
    std::string name = "unknown";
    std::ifstream in("/etc/os-release");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("PRETTY_NAME=", 0) == 0) {
            name = line.substr(12);
            if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
                name = name.substr(1, name.size() - 2);
        }
    utsname u{};
    if (uname(&u) == 0)
        name += std::string(", ") + u.sysname + " " + u.release;
    return name;
}

std::string library_versions() {
    int major = 0;
    int minor = 0;
    int bugfix = 0;
    nlopt_version(&major, &minor, &bugfix);
    const std::string nlopt =
        std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(bugfix);
    const std::string eigen = std::to_string(EIGEN_WORLD_VERSION) + "." +
                              std::to_string(EIGEN_MAJOR_VERSION) + "." + std::to_string(EIGEN_MINOR_VERSION);
    std::string boost = BOOST_LIB_VERSION;
    for (char& c : boost)
        c = c == '_' ? '.' : c;
    return "oneTBB " + std::string(TBB_runtime_version()) + ", Eigen " + eigen + ", NLopt " + nlopt +
           ", Boost " + boost;
}

} // namespace

std::string host_name() {
    char buf[256] = {};
    if (gethostname(buf, sizeof buf - 1) != 0)
        return "unknown";
    return buf;
}

std::string utc_now(const char* format) {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char buf[64];
    std::strftime(buf, sizeof buf, format, &utc);
    return buf;
}

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
    text += "git_dirty_at_build = " + std::string(build::git_dirty) + '\n';
    text += "compiler = " + std::string(build::compiler) + '\n';
    text += "build_type = " + std::string(build::build_type) + '\n';
    text += "threads = " + std::to_string(threads) + '\n';
    text += "hardware_threads = " + std::to_string(std::thread::hardware_concurrency()) + '\n';
    text += "cpu = " + cpu_model() + '\n';
    text += "os = " + operating_system() + '\n';
    text += "libraries = " + library_versions() + '\n';
    text += "date_utc = " + utc_now("%Y-%m-%dT%H:%M:%SZ") + '\n';
    text += "hostname = " + host_name() + '\n';
    text += "command = " + command + '\n';
    return text;
}

std::optional<std::string> first_field(const std::string& text, const std::string& key) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key + " = ", 0) == 0)
            return line.substr(key.size() + 3);
    return std::nullopt;
}

std::string context_field(const std::string& context_text, const std::string& key) {
    return first_field(context_text, key).value_or("unknown");
}

std::string context_sessions(const std::string& context_text) {
    std::string sessions;
    std::istringstream in(context_text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(session_key + std::string(" = "), 0) == 0)
            sessions += line + '\n';
    if (!sessions.empty() || context_text.find(" = ") == std::string::npos)
        return sessions;
    // A context.ini from before histories were kept: its one session, from its fields.
    const auto value = [&](const char* key) { return context_field(context_text, key); };
    return std::string(session_key) + " = " + value("date_utc") + " on " + value("hostname") + ", mhbench " +
           value("version") + " commit " + value("git_commit") + " (dirty: " + value("git_dirty_at_build") +
           "): " + value("command") + '\n';
}

std::string context_with_history(const std::string& current, const std::string& earlier_sessions) {
    return current +
           "# Every session that wrote into this directory, the first first (the lines above are the "
           "latest's):\n" +
           earlier_sessions + context_sessions(current);
}

std::string context_data_files(const std::vector<PreparedProblem>& problems) {
    std::string text;
    std::set<std::string> seen;
    for (const PreparedProblem& problem : problems)
        for (const auto& file : problem.problem->data_files())
            // Absolute, so that shards and ranks started from other directories compare by file.
            if (const std::string path = std::filesystem::absolute(file.path).lexically_normal().string();
                seen.insert(file.sha256 + " " + path).second)
                text += "data_file = " + file.sha256 + " " + path + '\n';
    return text;
}

} // namespace mhb
