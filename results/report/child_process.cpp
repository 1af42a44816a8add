#include "results/report/child_process.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <optional>
#include <pthread.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "problems/core/process/executable_path.hpp"

namespace mhb {

bool ChildOutcome::exited_with(int code) const {
    return started && WIFEXITED(status) && WEXITSTATUS(status) == code;
}

namespace {

// The child being waited for (-1: none) and the stop signals received meanwhile. Lock-free
// atomics are safe to use from a signal handler, which may run on any thread of the process.
std::atomic<pid_t> running_child{-1};
std::atomic<int> stops_received{0};
static_assert(std::atomic<pid_t>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

// The first stop asks the child to finish (SIGTERM: plot_study.py then exits quietly); a second
// one ends it at once. kill() is async-signal-safe.
extern "C" void on_stop_while_child_runs(int) {
    const int saved_errno = errno;
    const int count = stops_received.fetch_add(1) + 1;
    const pid_t child = running_child.load();
    if (child > 0)
        ::kill(child, count == 1 ? SIGTERM : SIGKILL);
    errno = saved_errno;
}

class Descriptor {
public:
    explicit Descriptor(int fd = -1) : fd_(fd) {}
    ~Descriptor() { reset(); }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    [[nodiscard]] int get() const { return fd_; }
    void reset(int fd = -1) {
        if (fd_ >= 0)
            ::close(fd_);
        fd_ = fd;
    }

private:
    int fd_;
};

// `fd` moved above the standard descriptors (close-on-exec kept), so that the child's dup2 onto
// 0, 1 and 2 never overwrites one source with another; -1 stays -1.
int above_standard(int fd) {
    if (fd < 0 || fd > STDERR_FILENO)
        return fd;
    const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, STDERR_FILENO + 1);
    ::close(fd);
    return moved;
}

std::string read_all(int fd) {
    std::string text;
    if (::lseek(fd, 0, SEEK_SET) != 0)
        return text;
    char buffer[8192];
    for (;;) {
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return text;
        text.append(buffer, static_cast<std::size_t>(got));
    }
}

std::string os_reason(const std::string& what, int error) {
    return what + " (" + std::strerror(error) + ")";
}

// Replaces the handler of `signal` by on_stop_while_child_runs unless the signal is ignored (a
// process started in the background or under nohup keeps ignoring it). Returns whether it did.
bool handle_stop_signal(int signal, struct sigaction& previous) {
    if (::sigaction(signal, nullptr, &previous) != 0 || previous.sa_handler == SIG_IGN)
        return false;
    struct sigaction action {};
    action.sa_handler = on_stop_while_child_runs;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0; // no SA_RESTART: waitpid returns EINTR and the loop goes on
    return ::sigaction(signal, &action, nullptr) == 0;
}

// In the forked child: tells the parent why it could not exec (errno) and ends.
[[noreturn]] void report_failure(int report_fd) {
    const int error = errno;
    (void)!::write(report_fd, &error, sizeof error);
    ::_exit(127);
}

// In the forked child, until exec: async-signal-safe calls only (the parent may have threads).
[[noreturn]] void exec_child(const char* path, char* const* argv, pid_t parent, int in, int out, int err,
                             int report_fd, const sigset_t& mask) {
    // Killed with the thread that forked it. If the parent died before the prctl, the signal will
    // never come: give up now (the parent is then a reaper's pid, not `parent`).
    if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0)
        report_failure(report_fd);
    if (::getppid() != parent)
        ::_exit(127);
    if (::dup2(in, STDIN_FILENO) < 0 || ::dup2(out, STDOUT_FILENO) < 0 || ::dup2(err, STDERR_FILENO) < 0)
        report_failure(report_fd);
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    struct sigaction by_default {};
    by_default.sa_handler = SIG_DFL;
    sigemptyset(&by_default.sa_mask);
    ::sigaction(SIGINT, &ignore, nullptr); // a stop comes as SIGTERM from the parent (see the header)
    ::sigaction(SIGTERM, &by_default, nullptr);
    ::sigaction(SIGPIPE, &by_default, nullptr);
    ::sigprocmask(SIG_SETMASK, &mask, nullptr);
    // Nothing of the parent's (study files, sockets) leaks into the child; the pipe that reports an
    // exec failure is close-on-exec already.
    (void)::close_range(STDERR_FILENO + 1, ~0U, CLOSE_RANGE_CLOEXEC);
    ::execv(path, argv);
    report_failure(report_fd);
}

// SIGINT and SIGTERM passed on to the child while it runs (on_stop_while_child_runs). They stay
// blocked in this thread from before the handlers are installed until the child's pid is known, so
// that the handler never runs without a child to pass the stop to here, and the child never runs
// it at all.
class StopForwarding {
public:
    StopForwarding() {
        sigset_t stops;
        sigemptyset(&stops);
        sigaddset(&stops, SIGINT);
        sigaddset(&stops, SIGTERM);
        ::pthread_sigmask(SIG_BLOCK, &stops, &previous_mask_);
        stops_received.store(0);
        running_child.store(-1);
        handles_int_ = handle_stop_signal(SIGINT, previous_int_);
        handles_term_ = handle_stop_signal(SIGTERM, previous_term_);
    }
    StopForwarding(const StopForwarding&) = delete;
    StopForwarding& operator=(const StopForwarding&) = delete;

    // The thread's signal mask from before, which the child gets too.
    [[nodiscard]] const sigset_t& previous_mask() const { return previous_mask_; }

    // From now on a stop goes to `pid`.
    void child_started(pid_t pid) {
        running_child.store(pid);
        ::pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
        if (stops_received.load() > 0) // a stop that another thread handled before the pid was known
            ::kill(pid, SIGTERM);
    }

    // No child to pass a stop to any more; the handlers and the mask as they were.
    void restore() {
        running_child.store(-1);
        if (handles_int_)
            ::sigaction(SIGINT, &previous_int_, nullptr);
        if (handles_term_)
            ::sigaction(SIGTERM, &previous_term_, nullptr);
        ::pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
    }

private:
    sigset_t previous_mask_{};
    struct sigaction previous_int_ {};
    struct sigaction previous_term_ {};
    bool handles_int_ = false;
    bool handles_term_ = false;
};

// execv's argument vector: pointers into `text` (the program, then its arguments), then null.
std::vector<char*> exec_arguments(std::vector<std::string>& text) {
    std::vector<char*> argv;
    for (auto& a : text)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    return argv;
}

// Where the child's stdout or stderr goes: a memory file to read back, or /dev/null.
int child_output(bool capture_output, const char* name) {
    return capture_output ? ::memfd_create(name, MFD_CLOEXEC) : ::open("/dev/null", O_WRONLY | O_CLOEXEC);
}

// How a started child ended: the errno of an exec that failed, which it reported, or its wait status.
struct ChildEnd {
    bool exec_failed = false;
    int exec_error = 0;
    int status = 0;
    int wait_error = 0; // waitpid's errno when it failed
};

// Reads the child's report of an exec failure (the pipe closes without one when exec succeeds),
// then waits for it to end.
ChildEnd wait_for_child(pid_t pid, int report_read) {
    ChildEnd end;
    ssize_t got = 0;
    do
        got = ::read(report_read, &end.exec_error, sizeof end.exec_error);
    while (got < 0 && errno == EINTR);
    end.exec_failed = got == static_cast<ssize_t>(sizeof end.exec_error);
    while (::waitpid(pid, &end.status, 0) < 0) {
        if (errno != EINTR) {
            end.wait_error = errno;
            break;
        }
    }
    return end;
}

} // namespace

ChildOutcome run_child_process(const std::string& program, const std::vector<std::string>& arguments,
                               bool capture_output) {
    static std::mutex one_at_a_time; // the signal handling above serves one child
    const std::lock_guard<std::mutex> lock(one_at_a_time);
    ChildOutcome outcome;
    const std::optional<std::string> path = process::find_executable(program);
    if (!path) {
        outcome.error = program + ": not found in PATH";
        return outcome;
    }
    std::vector<std::string> argv_text = {program};
    argv_text.insert(argv_text.end(), arguments.begin(), arguments.end());
    const std::vector<char*> argv = exec_arguments(argv_text);

    const Descriptor in(above_standard(::open("/dev/null", O_RDONLY | O_CLOEXEC)));
    const Descriptor out(above_standard(child_output(capture_output, "mhbench-child-stdout")));
    const Descriptor err(above_standard(child_output(capture_output, "mhbench-child-stderr")));
    if (in.get() < 0 || out.get() < 0 || err.get() < 0) {
        outcome.error = os_reason("cannot open its output files", errno);
        return outcome;
    }
    int pipe_ends[2];
    if (::pipe2(pipe_ends, O_CLOEXEC) != 0) {
        outcome.error = os_reason("cannot create a pipe", errno);
        return outcome;
    }
    const Descriptor report_read(above_standard(pipe_ends[0]));
    Descriptor report_write(above_standard(pipe_ends[1]));

    StopForwarding stops;
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid == 0)
        exec_child(path->c_str(), argv.data(), parent, in.get(), out.get(), err.get(), report_write.get(),
                   stops.previous_mask());
    if (pid < 0) {
        outcome.error = os_reason("cannot start a process", errno);
        stops.restore();
        return outcome;
    }
    stops.child_started(pid);
    report_write.reset();
    const ChildEnd end = wait_for_child(pid, report_read.get());
    stops.restore();
    outcome.stop_requested = stops_received.load() > 0;
    if (end.exec_failed) {
        outcome.error = os_reason(*path + " cannot be run", end.exec_error);
        return outcome;
    }
    if (end.wait_error != 0) {
        outcome.error = os_reason("cannot wait for " + *path, end.wait_error);
        return outcome;
    }
    outcome.started = true;
    outcome.status = end.status;
    if (capture_output) {
        outcome.out = read_all(out.get());
        outcome.err = read_all(err.get());
    }
    return outcome;
}

} // namespace mhb
