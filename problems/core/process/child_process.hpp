// A child process that mhbench starts and owns: every program mhbench runs (an external problem or
// optimiser, the figure scripts' Python) is started here, once. No shell: argv is passed as it is
// (argv[0] searched in PATH when it has no '/', executable_path.hpp). The child
//   - runs in a process group of its own, so that ending it also ends what it started (a shell's
//     children, a script's helpers), and a Ctrl-C at mhbench's terminal reaches mhbench only, which
//     then ends its children itself;
//   - gets SIGKILL when the thread that started it dies, however it dies (PR_SET_PDEATHSIG: the
//     *thread*, so a child that outlives the call that started it must be started from a thread
//     that stays; problems/external/spawner.hpp);
//   - has a watcher, a process forked without exec that kills the child's group when mhbench dies
//     by any signal, SIGKILL included, which PR_SET_PDEATHSIG covers for the child but not for what
//     the child started;
//   - inherits no descriptor but 0, 1 and 2, starts with an empty signal mask and with SIGINT,
//     SIGTERM and SIGPIPE at their defaults (mhbench ignores SIGPIPE, and an ignored signal stays
//     ignored across exec), or SIGINT ignored when asked.
// Its stdin, stdout and stderr each go to /dev/null, to a pipe, or (outputs) to a memory file read
// once it has exited; a stderr pipe can keep its last lines (the tail), drained as its other pipes
// are waited on. Writes never raise SIGPIPE; reads and waits take deadlines. Destroying it kills
// its group and reaps it. Linux only (prctl, memfd, close_range), like the rest of mhbench.
#pragma once

#include <chrono>
#include <deque>
#include <stdexcept>
#include <string>
#include <string_view>
#include <sys/types.h>
#include <vector>

namespace mhb::process {

// Where one of the child's standard streams goes.
enum class Stream {
    null,   // /dev/null
    pipe,   // a pipe whose other end this object holds (stdin: write_input; stdout: read_output)
    memory, // stdout or stderr only: a memory file, read by captured() once the child has exited
    tail,   // stderr only: a pipe of which the last lines are kept (error_tail)
};

struct ChildOptions {
    Stream input = Stream::null;
    Stream output = Stream::null;
    Stream errors = Stream::null;
    // The child starts with SIGINT ignored: a stop reaches it as SIGTERM from its parent, which
    // handles SIGINT, or through its own handler if it installs one.
    bool ignore_interrupt = false;
};

// A program that could not be started: "NAME: not found in PATH", "PATH cannot be run (reason)",
// "cannot create a pipe (reason)", ...; one line.
class SpawnError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using Deadline = std::chrono::steady_clock::time_point;

class ChildProcess {
public:
    // Starts `argv`; SpawnError when it cannot be executed.
    ChildProcess(const std::vector<std::string>& argv, const ChildOptions& options);
    ~ChildProcess(); // end()
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    [[nodiscard]] pid_t pid() const { return pid_; }
    // The file that was executed (argv[0] as found in PATH).
    [[nodiscard]] const std::string& path() const { return path_; }

    // Writes all of `text` to its stdin (Stream::pipe), waiting for room as long as it takes while
    // its stderr tail is drained (a child blocked writing stderr would never read). False when it
    // no longer reads (it exited or closed its stdin): the SIGPIPE the write raised is taken back,
    // whatever the process's disposition of it. std::runtime_error for another failure.
    [[nodiscard]] bool write_input(std::string_view text);
    void close_input();
    [[nodiscard]] bool input_open() const { return in_ >= 0; }

    enum class Read { data, end, timeout };
    // Appends what its stdout (Stream::pipe) has to `into`, waiting until `deadline` for something
    // while its stderr tail is drained: data, the end of its stdout (then closed), or the deadline.
    // std::runtime_error if poll fails.
    Read read_output(std::string& into, Deadline deadline);

    // Its last stderr lines (Stream::tail), each cut to 300 characters, joined by " | "; empty if
    // it wrote none.
    [[nodiscard]] std::string error_tail();

    // What it wrote on stdout or stderr (Stream::memory), once it has exited.
    [[nodiscard]] std::string captured_output() const;
    [[nodiscard]] std::string captured_errors() const;

    // Whether it has exited; seen, not reaped, so that its group stays its own until end().
    [[nodiscard]] bool exited();
    // Waits until it exits or `deadline` passes; whether it exited.
    bool wait_for_exit(Deadline deadline);
    // Waits until it exits, however long; a signal handler that runs meanwhile (one that passes a
    // stop on to the child, say) does not end the wait. std::runtime_error if the wait fails.
    void wait_for_exit();
    // "exited with status 3", "was killed by signal 9 (Killed)", or `if_running` if it has not
    // exited within a short wait (a child that closed its pipes is usually exiting).
    [[nodiscard]] std::string exit_description(const char* if_running);

    // SIGKILL to its process group (the child and all it started), the watcher ended, and the child
    // reaped; idempotent. Returns its wait status (waitpid's: WIFEXITED, WEXITSTATUS, ...), which is
    // its own exit when it had exited before.
    int end();

private:
    void start_watcher();
    void drain_errors(bool wait_for_end);

    std::string path_;
    pid_t pid_ = -1;
    int in_ = -1;  // its stdin, our end
    int out_ = -1; // its stdout, our end (pipe or memory file)
    int err_ = -1; // its stderr, our end (pipe or memory file)
    Stream output_ = Stream::null;
    Stream errors_ = Stream::null;
    bool reaped_ = false;
    int wait_status_ = 0;
    bool exited_ = false; // seen to exit (not reaped yet: see end())
    int exit_code_ = 0;   // CLD_EXITED, CLD_KILLED, ...
    int exit_status_ = 0; // its exit status or signal
    pid_t watcher_ = -1;  // the process that kills the group if mhbench dies
    int lifeline_ = -1;   // the watcher waits for the end of this pipe
    std::string err_partial_;
    std::deque<std::string> err_lines_;
};

} // namespace mhb::process
