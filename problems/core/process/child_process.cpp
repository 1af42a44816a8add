#include "problems/core/process/child_process.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "problems/core/process/executable_path.hpp"

namespace mhb::process {
namespace {

constexpr std::size_t kept_error_lines = 8; // what a failed record carries of a child's stderr
constexpr std::size_t kept_line_length = 300;
constexpr std::size_t kept_partial_line = 4096;

std::string os_reason(const std::string& what, int error) {
    return what + " (" + std::strerror(error) + ")";
}

void close_fd(int& fd) {
    if (fd >= 0)
        ::close(fd);
    fd = -1;
}

// The descriptors of the child's three streams and the parent's ends, closed unless released.
struct Wiring {
    int child[3] = {-1, -1, -1}; // what becomes its 0, 1 and 2
    int ours[3] = {-1, -1, -1};  // our ends: its stdin's write end, its stdout's and stderr's read ends
    ~Wiring() {
        for (int& fd : child)
            close_fd(fd);
        for (int& fd : ours)
            close_fd(fd);
    }
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

// One stream of the child (0, 1 or 2) wired as asked; SpawnError when the OS refuses.
void wire(Wiring& w, int stream, Stream how) {
    const bool input = stream == STDIN_FILENO;
    if (how == Stream::pipe || how == Stream::tail) {
        int ends[2];
        if (::pipe2(ends, O_CLOEXEC) != 0)
            throw SpawnError(os_reason("cannot create a pipe", errno));
        w.child[stream] = above_standard(input ? ends[0] : ends[1]);
        w.ours[stream] = above_standard(input ? ends[1] : ends[0]);
    } else if (how == Stream::memory) {
        // The child writes it, we read it back from the start once it has exited: the same file.
        w.ours[stream] = above_standard(::memfd_create(
            stream == STDOUT_FILENO ? "mhbench-child-stdout" : "mhbench-child-stderr", MFD_CLOEXEC));
        w.child[stream] =
            w.ours[stream] < 0 ? -1 : above_standard(::fcntl(w.ours[stream], F_DUPFD_CLOEXEC, 0));
    } else {
        w.child[stream] = above_standard(::open("/dev/null", (input ? O_RDONLY : O_WRONLY) | O_CLOEXEC));
    }
    if (w.child[stream] < 0 || (how != Stream::null && w.ours[stream] < 0))
        throw SpawnError(os_reason("cannot open its standard streams", errno));
}

// In the forked child: tells the parent why it could not exec (errno) and ends.
[[noreturn]] void report_failure(int report) {
    const int error = errno;
    (void)!::write(report, &error, sizeof error);
    ::_exit(127);
}

// In the forked child, until exec: async-signal-safe calls only (mhbench has threads).
[[noreturn]] void exec_child(const char* path, char* const* argv, pid_t parent, const Wiring& w, int report,
                             bool ignore_interrupt) {
    // A group of its own (see the header).
    if (::setpgid(0, 0) != 0)
        report_failure(report);
    // Killed with the thread that forked it, however that dies. If the parent died before the
    // prctl, the signal will never come: give up now (the parent is then a reaper, not `parent`).
    if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0)
        report_failure(report);
    if (::getppid() != parent)
        ::_exit(127);
    for (int stream = 0; stream < 3; ++stream)
        if (::dup2(w.child[stream], stream) < 0)
            report_failure(report);
    struct sigaction by_default {};
    by_default.sa_handler = SIG_DFL;
    sigemptyset(&by_default.sa_mask);
    for (const int signal : {SIGINT, SIGTERM, SIGPIPE})
        ::sigaction(signal, &by_default, nullptr);
    if (ignore_interrupt) {
        struct sigaction ignore {};
        ignore.sa_handler = SIG_IGN;
        sigemptyset(&ignore.sa_mask);
        ::sigaction(SIGINT, &ignore, nullptr);
    }
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    // Nothing of the parent's (study files, sockets, other children's pipes) leaks into the child;
    // the pipe that reports an exec failure is close-on-exec already.
    (void)::close_range(STDERR_FILENO + 1, ~0U, CLOSE_RANGE_CLOEXEC);
    ::execv(path, argv);
    report_failure(report);
}

// The watcher's life (see the header): it waits for the end of the lifeline, whose only write end
// mhbench holds, and then kills the child's process group. The end comes when mhbench closes it
// (end(): the child is being ended anyway) or when mhbench dies, however it dies. Forked without
// exec from a process with threads: async-signal-safe calls only.
[[noreturn]] void watch(int lifeline, pid_t group) {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE})
        ::sigaction(signal, &ignore, nullptr); // a Ctrl-C at mhbench's terminal must not end it
    // Nothing else of mhbench's stays open here: above all not the lifelines of other children.
    if (lifeline > 0)
        (void)::close_range(0, static_cast<unsigned>(lifeline) - 1, 0);
    (void)::close_range(static_cast<unsigned>(lifeline) + 1, ~0U, 0);
    char byte = 0;
    while (::read(lifeline, &byte, 1) < 0 && errno == EINTR) {
    }
    ::kill(-group, SIGKILL);
    ::_exit(0);
}

// SIGPIPE blocked in this thread while it writes to a child, and the one that a write to a child
// that has exited raises taken back before the mask is restored (libpq's pq_block_sigpipe and
// pq_reset_sigpipe): the write fails with EPIPE, whatever the process does with SIGPIPE. mhbench
// ignores it (runner/cli/main.cpp), but a test or another host of this library may not, and its
// default ends the whole process without a word.
class SigpipeBlock {
public:
    SigpipeBlock() {
        sigemptyset(&pipe_);
        sigaddset(&pipe_, SIGPIPE);
        ::pthread_sigmask(SIG_BLOCK, &pipe_, &previous_);
        sigset_t pending;
        sigemptyset(&pending);
        // One pending already is not ours to take.
        was_pending_ = ::sigpending(&pending) == 0 && sigismember(&pending, SIGPIPE) == 1;
    }
    ~SigpipeBlock() { ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
    SigpipeBlock(const SigpipeBlock&) = delete;
    SigpipeBlock& operator=(const SigpipeBlock&) = delete;

    // After a write failed with EPIPE: the SIGPIPE it raised (pending while blocked, even when
    // ignored on Linux) is consumed, not delivered when the mask is restored.
    void take_back() const {
        if (was_pending_)
            return;
        const timespec now{0, 0};
        while (::sigtimedwait(&pipe_, nullptr, &now) < 0 && errno == EINTR) {
        }
    }

private:
    sigset_t pipe_{};
    sigset_t previous_{};
    bool was_pending_ = false;
};

// A memory file's content from its start.
std::string read_all(int fd) {
    std::string text;
    if (fd < 0 || ::lseek(fd, 0, SEEK_SET) != 0)
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

// The errno of an exec that failed, as the child reported it, or 0 once the pipe closed without a
// report (exec succeeded, and closed its close-on-exec end).
int exec_failure(int report) {
    int error = 0;
    ssize_t got = 0;
    do
        got = ::read(report, &error, sizeof error);
    while (got < 0 && errno == EINTR);
    return got == static_cast<ssize_t>(sizeof error) ? error : 0;
}

// Milliseconds from now to `deadline` for poll, at least 0 and at most a second (so that a caller's
// loop looks at the clock again).
int poll_timeout(Deadline deadline) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    return static_cast<int>(std::clamp<long long>(left.count() + 1, 0, 1000));
}

} // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const ChildOptions& options)
    : output_(options.output), errors_(options.errors) {
    if (argv.empty())
        throw SpawnError("the command is empty");
    // Before fork: getenv is not async-signal-safe.
    path_ = find_executable(argv.front()).value_or(std::string());
    if (path_.empty())
        throw SpawnError(argv.front() + ": not found in PATH");
    std::vector<std::string> words = argv;
    std::vector<char*> pointers;
    for (auto& w : words)
        pointers.push_back(w.data());
    pointers.push_back(nullptr);

    Wiring w;
    wire(w, STDIN_FILENO, options.input == Stream::pipe ? Stream::pipe : Stream::null);
    wire(w, STDOUT_FILENO, options.output);
    wire(w, STDERR_FILENO, options.errors);
    int report[2];
    if (::pipe2(report, O_CLOEXEC) != 0)
        throw SpawnError(os_reason("cannot create a pipe", errno));
    report[0] = above_standard(report[0]);
    report[1] = above_standard(report[1]);

    const pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ == 0)
        exec_child(path_.c_str(), pointers.data(), parent, w, report[1], options.ignore_interrupt);
    const int fork_error = errno;
    ::close(report[1]);
    for (int& fd : w.child) // the child's now; its pipes see their end when the child's copies close
        close_fd(fd);
    if (pid_ < 0) {
        ::close(report[0]);
        reaped_ = true;
        throw SpawnError(os_reason("cannot start a process", fork_error));
    }
    // Also here (not only in the child), so that a kill(-pid) right after fork finds the group.
    (void)::setpgid(pid_, pid_);
    std::swap(in_, w.ours[STDIN_FILENO]);
    std::swap(out_, w.ours[STDOUT_FILENO]);
    std::swap(err_, w.ours[STDERR_FILENO]);
    const int exec_error = exec_failure(report[0]);
    ::close(report[0]);
    if (exec_error != 0) {
        end();
        close_fd(out_);
        close_fd(err_);
        throw SpawnError(os_reason(path_ + " cannot be run", exec_error));
    }
    start_watcher();
    // So that a child that does not read is waited for in poll, with its stderr drained, not in a
    // write. (It does not keep a write to a child that has exited from raising SIGPIPE: see
    // SigpipeBlock for that.)
    if (in_ >= 0)
        ::fcntl(in_, F_SETFL, ::fcntl(in_, F_GETFL) | O_NONBLOCK);
}

void ChildProcess::start_watcher() {
    int life[2];
    if (::pipe2(life, O_CLOEXEC) != 0)
        return;
    watcher_ = ::fork();
    if (watcher_ == 0)
        watch(life[0], pid_);
    ::close(life[0]);
    if (watcher_ > 0)
        lifeline_ = life[1];
    else
        ::close(life[1]);
}

ChildProcess::~ChildProcess() {
    end();
    close_fd(out_); // memory files, kept by end() for captured_output()
    close_fd(err_);
}

int ChildProcess::end() {
    if (!reaped_ && pid_ > 0) {
        // Until the child is reaped its pid cannot be reused, so -pid_ is still its group.
        ::kill(-pid_, SIGKILL);
        ::kill(pid_, SIGKILL);
        close_fd(lifeline_);
        if (watcher_ > 0)
            while (::waitpid(watcher_, nullptr, 0) < 0 && errno == EINTR) {
            }
        watcher_ = -1;
        while (::waitpid(pid_, &wait_status_, 0) < 0 && errno == EINTR) {
        }
        reaped_ = true;
        if (!exited_) { // what waitid would have said
            exited_ = true;
            exit_code_ = WIFEXITED(wait_status_) ? CLD_EXITED : CLD_KILLED;
            exit_status_ = WIFEXITED(wait_status_) ? WEXITSTATUS(wait_status_) : WTERMSIG(wait_status_);
        }
    }
    close_fd(in_);
    if (output_ == Stream::pipe)
        close_fd(out_);
    if (errors_ == Stream::tail && err_ >= 0) {
        drain_errors(false);
        close_fd(err_);
    }
    return wait_status_;
}

bool ChildProcess::exited() {
    if (exited_ || pid_ <= 0)
        return exited_;
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
        info.si_pid == pid_) {
        exited_ = true;
        exit_code_ = info.si_code;
        exit_status_ = info.si_status;
    }
    return exited_;
}

bool ChildProcess::wait_for_exit(Deadline deadline) {
    while (!reaped_ && !exited() && std::chrono::steady_clock::now() < deadline)
        ::usleep(1000);
    return exited_;
}

void ChildProcess::wait_for_exit() {
    while (!reaped_ && !exited_) {
        siginfo_t info{};
        if (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOWAIT) == 0) {
            exited_ = true;
            exit_code_ = info.si_code;
            exit_status_ = info.si_status;
        } else if (errno != EINTR) {
            throw std::runtime_error(os_reason("cannot wait for " + path_, errno));
        }
    }
}

std::string ChildProcess::exit_description(const char* if_running) {
    // It closed its pipes: give it a moment to exit so that the status can be told.
    for (int i = 0; i < 100 && !exited(); ++i)
        ::usleep(1000);
    if (!exited_)
        return if_running;
    drain_errors(true);
    if (exit_code_ == CLD_EXITED)
        return "exited with status " + std::to_string(exit_status_);
    if (exit_code_ == CLD_KILLED || exit_code_ == CLD_DUMPED)
        return std::string("was killed by signal ") + std::to_string(exit_status_) + " (" +
               ::strsignal(exit_status_) + ")";
    return "ended";
}

void ChildProcess::close_input() {
    close_fd(in_);
}

bool ChildProcess::write_input(std::string_view text) {
    const SigpipeBlock block;
    std::size_t done = 0;
    while (done < text.size()) {
        if (in_ < 0)
            return false;
        const ssize_t wrote = ::write(in_, text.data() + done, text.size() - done);
        if (wrote > 0) {
            done += static_cast<std::size_t>(wrote);
            continue;
        }
        if (wrote < 0 && errno == EINTR)
            continue;
        if (wrote < 0 && errno == EAGAIN) {
            // Its stdin is full: it is not reading. Wait for room while keeping its stderr drained.
            const bool tail = errors_ == Stream::tail && err_ >= 0;
            pollfd fds[2] = {{in_, POLLOUT, 0}, {tail ? err_ : -1, POLLIN, 0}};
            if (::poll(fds, tail ? 2 : 1, 1000) > 0 && (fds[1].revents & (POLLIN | POLLHUP)) != 0)
                drain_errors(false);
            continue;
        }
        if (wrote < 0 && errno == EPIPE) {
            // No reader left: it exited (or closed its stdin) before reading all it was sent.
            block.take_back();
            return false;
        }
        throw std::runtime_error(os_reason("cannot write to its stdin", errno));
    }
    return true;
}

ChildProcess::Read ChildProcess::read_output(std::string& into, Deadline deadline) {
    for (;;) {
        if (out_ < 0)
            return Read::end;
        if (std::chrono::steady_clock::now() >= deadline)
            return Read::timeout;
        const bool tail = errors_ == Stream::tail && err_ >= 0;
        pollfd fds[2] = {{out_, POLLIN, 0}, {tail ? err_ : -1, POLLIN, 0}};
        const int ready = ::poll(fds, tail ? 2 : 1, poll_timeout(deadline));
        if (ready < 0 && errno != EINTR)
            throw std::runtime_error(os_reason("poll failed", errno));
        if (ready <= 0)
            continue;
        if (tail && (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) != 0)
            drain_errors(false);
        if ((fds[0].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
            char buffer[65536];
            const ssize_t got = ::read(out_, buffer, sizeof buffer);
            if (got > 0) {
                into.append(buffer, static_cast<std::size_t>(got));
                return Read::data;
            }
            if (got == 0 || (errno != EINTR && errno != EAGAIN)) {
                close_fd(out_); // the end of its stdout: it exited, or closed it, as good as exiting
                return Read::end;
            }
        }
    }
}

void ChildProcess::drain_errors(bool wait_for_end) {
    if (errors_ != Stream::tail || err_ < 0)
        return;
    for (;;) {
        pollfd fd{err_, POLLIN, 0};
        if (::poll(&fd, 1, wait_for_end ? 100 : 0) <= 0)
            return;
        char buffer[8192];
        const ssize_t got = ::read(err_, buffer, sizeof buffer);
        if (got <= 0) {
            if (got < 0 && errno == EINTR)
                continue;
            close_fd(err_);
            return;
        }
        err_partial_.append(buffer, static_cast<std::size_t>(got));
        for (auto newline = err_partial_.find('\n'); newline != std::string::npos;
             newline = err_partial_.find('\n')) {
            std::string line = err_partial_.substr(0, newline);
            err_partial_.erase(0, newline + 1);
            if (line.size() > kept_line_length)
                line = line.substr(0, kept_line_length) + "...";
            if (!line.empty())
                err_lines_.push_back(std::move(line));
            if (err_lines_.size() > kept_error_lines)
                err_lines_.pop_front();
        }
        if (err_partial_.size() > kept_partial_line)
            err_partial_.erase(0, err_partial_.size() - kept_partial_line);
    }
}

std::string ChildProcess::error_tail() {
    drain_errors(false);
    std::string tail;
    for (const auto& line : err_lines_)
        tail += (tail.empty() ? "" : " | ") + line;
    if (!err_partial_.empty())
        tail += (tail.empty() ? "" : " | ") + err_partial_;
    return tail;
}

std::string ChildProcess::captured_output() const {
    return output_ == Stream::memory ? read_all(out_) : std::string();
}

std::string ChildProcess::captured_errors() const {
    return errors_ == Stream::memory ? read_all(err_) : std::string();
}

} // namespace mhb::process
