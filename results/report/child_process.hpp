// A helper program (the figure scripts' Python) run to completion as a child process, on top of
// problems/core/process/ (no shell, the arguments passed as they are, its own process group, and
// its life tied to ours: neither it nor what it starts outlives a mhbench killed by any signal,
// SIGKILL included). SIGINT or SIGTERM that reach mhbench while it waits are passed on to the
// child as SIGTERM (SIGKILL at the second), and the outcome says that a stop was asked for, so the
// caller can finish cleanly instead of dying.
#pragma once

#include <string>
#include <vector>

namespace mhb {

struct ChildOutcome {
    bool started = false; // false: the program could not be executed; `error` says why
    std::string error;
    int status = 0;              // the waitpid status (WIFEXITED, WEXITSTATUS, WIFSIGNALED, ...)
    bool stop_requested = false; // SIGINT or SIGTERM reached this process while the child ran
    std::string out;             // what the child wrote on stdout and stderr, when captured
    std::string err;

    [[nodiscard]] bool exited_with(int code) const;
};

// Runs `program` (searched in PATH when it has no '/') with `arguments` as argv[1..] and waits for
// it. Its stdin is /dev/null; stdout and stderr are captured when `capture_output`, else
// discarded; it inherits no other file descriptor. It starts with SIGINT ignored: a Ctrl-C reaches
// it as SIGTERM from here, or through its own handler if it installs one (plot_study.py does),
// never as a KeyboardInterrupt in the middle of the interpreter's start-up. While it runs, this
// process handles SIGINT and SIGTERM (unless they were ignored) and restores the previous handlers
// afterwards. Once it has exited, whatever it started and left running is killed with its group.
// One child at a time: concurrent calls wait for each other.
ChildOutcome run_child_process(const std::string& program, const std::vector<std::string>& arguments,
                               bool capture_output);

} // namespace mhb
