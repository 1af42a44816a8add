// One external program (README, "External programs (any language)") as a child process spoken to
// line by line over its stdin and stdout: the line protocol on top of problems/core/process/
// (ChildProcess: its own process group, PR_SET_PDEATHSIG and the watcher, so that neither it nor
// what it started outlives mhbench, however mhbench dies). Its stderr is kept (the last lines) for
// the error a fault turns into. Every read has a deadline: a hung child is a fault, never a hang
// of mhbench.
#pragma once

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <sys/types.h>
#include <vector>

#include "problems/core/process/child_process.hpp"

namespace mhb::external {

// A child that exited, hung past its deadline or wrote something the protocol does not allow.
// The message is one line; stderr_tail() holds the child's last stderr lines.
class ChildFault : public std::runtime_error {
public:
    ChildFault(const std::string& what, std::string stderr_tail)
        : std::runtime_error(what), stderr_tail_(std::move(stderr_tail)) {}
    [[nodiscard]] const std::string& stderr_tail() const { return stderr_tail_; }

private:
    std::string stderr_tail_;
};

class ChildLink {
public:
    // Starts `argv` (argv[0] searched in PATH when it has no '/'), no shell. Throws ChildFault
    // when it cannot be executed.
    explicit ChildLink(const std::vector<std::string>& argv);
    ChildLink(const ChildLink&) = delete;
    ChildLink& operator=(const ChildLink&) = delete;

    // Writes `line` and a newline. ChildFault if the child has closed its stdin (exited), never a
    // SIGPIPE, whatever the process's disposition of it.
    void send(const std::string& line);
    // The next line of its stdout, waiting at most `timeout`. ChildFault when the child exits
    // (with its status), the deadline passes, or the line is longer than a limit.
    std::string receive(std::chrono::duration<double> timeout);

    // Closes its stdin (a polite end), waits up to `grace` for it to exit, then kills the group.
    void finish(std::chrono::duration<double> grace);
    // SIGKILL to its process group and a reap; idempotent. (Destroying the link does it too.)
    void kill();

    [[nodiscard]] pid_t pid() const { return child_->pid(); }
    // Its last stderr lines, joined by " | " (empty if it wrote none).
    [[nodiscard]] std::string stderr_tail() { return child_->error_tail(); }
    // What messages call it: the script, not its interpreter (command.hpp, program_name).
    [[nodiscard]] const std::string& program() const { return program_; }

private:
    std::string program_;
    std::optional<process::ChildProcess> child_;
    std::string out_buffer_;
};

} // namespace mhb::external
