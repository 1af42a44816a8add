// One external program (README, "External programs (any language)") as a child process spoken to
// line by line over its stdin and stdout. It runs in a process group of its own, so that killing
// it also kills what it started (a shell's children, a simulator's helpers), and with
// PR_SET_PDEATHSIG, so that a mhbench killed by any signal (SIGKILL included) never leaves it
// behind. A watcher process (forked without exec) kills the group when mhbench dies, so that what
// the child started does not outlive it either. Its stderr is kept (the last lines) for the error a fault
// turns into. Every read has a deadline: a hung child is a fault, never a hang of mhbench.
#pragma once

#include <chrono>
#include <deque>
#include <stdexcept>
#include <string>
#include <sys/types.h>
#include <vector>

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

// The file exec would run for `program`: itself when it holds a '/', else the first executable
// regular file of that name in PATH; empty when there is none.
std::string resolve_program(const std::string& program);

class ChildLink {
public:
    // Starts `argv` (argv[0] searched in PATH when it has no '/'), no shell. Throws ChildFault
    // when it cannot be executed.
    explicit ChildLink(const std::vector<std::string>& argv);
    ~ChildLink(); // kills the process group and reaps the child
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
    // SIGKILL to its process group and a reap; idempotent.
    void kill();

    [[nodiscard]] pid_t pid() const { return pid_; }
    // Its last stderr lines, joined by " | " (empty if it wrote none).
    [[nodiscard]] std::string stderr_tail();
    // What messages call it: the script, not its interpreter (command.hpp, program_name).
    [[nodiscard]] const std::string& program() const { return program_; }

private:
    void drain_stderr(bool wait_for_end);
    void add_stderr(const char* data, std::size_t size);
    // "exited with status 3", "was killed by signal 9 (Killed)", or `if_running` if it has not
    // exited (within a short wait).
    [[nodiscard]] std::string exit_description(const char* if_running);
    [[nodiscard]] bool exited();

    std::string program_;
    pid_t pid_ = -1;
    int in_ = -1;  // its stdin, our end
    int out_ = -1; // its stdout, our end
    int err_ = -1; // its stderr, our end
    bool reaped_ = false;
    bool exited_ = false; // seen to exit (not reaped yet: see kill())
    int exit_code_ = 0;   // CLD_EXITED, CLD_KILLED, ...
    int exit_status_ = 0; // its exit status or signal
    pid_t watcher_ = -1;  // the process that kills the group if mhbench dies
    int lifeline_ = -1;   // the watcher waits for this pipe's end
    std::string out_buffer_;
    std::string err_partial_;
    std::deque<std::string> err_lines_;
};

} // namespace mhb::external
