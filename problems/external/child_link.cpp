#include "problems/external/child_link.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "problems/core/process/executable_path.hpp"
#include "problems/external/command.hpp"

namespace mhb::external {
namespace {

constexpr std::size_t max_line = 64 << 20;   // a reply longer than this is garbage, not data
constexpr std::size_t kept_stderr_lines = 8; // what a failed record carries of the child's stderr

void close_fd(int& fd) {
    if (fd >= 0)
        ::close(fd);
    fd = -1;
}

// In the forked child: tells the parent why it could not exec (errno) and ends.
[[noreturn]] void report_failure(int report) {
    const int error = errno;
    (void)!::write(report, &error, sizeof error);
    ::_exit(127);
}

// In the forked child, until exec: async-signal-safe calls only (mhbench has threads).
[[noreturn]] void exec_child(const char* path, char* const* argv, pid_t parent, int in, int out, int err,
                             int report) {
    const auto fail = [report] { report_failure(report); };
    // A group of its own: killing -pid reaches everything it starts, and a Ctrl-C at the terminal
    // reaches mhbench only, which then ends its children itself.
    if (::setpgid(0, 0) != 0)
        fail();
    // Killed with the thread that forked it, however that dies. If the parent died before the
    // prctl, the signal will never come: give up now.
    if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0)
        fail();
    if (::getppid() != parent)
        ::_exit(127);
    if (::dup2(in, STDIN_FILENO) < 0 || ::dup2(out, STDOUT_FILENO) < 0 || ::dup2(err, STDERR_FILENO) < 0)
        fail();
    struct sigaction by_default {};
    by_default.sa_handler = SIG_DFL;
    sigemptyset(&by_default.sa_mask);
    for (const int signal : {SIGINT, SIGTERM, SIGPIPE})
        ::sigaction(signal, &by_default, nullptr);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    (void)::close_range(STDERR_FILENO + 1, ~0U, CLOSE_RANGE_CLOEXEC);
    ::execv(path, argv);
    report_failure(report);
}

// The watcher's life (see ChildLink): it waits for the end of the lifeline, whose only write end
// mhbench holds, and then kills the child's process group. The end comes when mhbench closes it
// (the child is being ended anyway) or when mhbench dies, however it dies: SIGKILL included, which
// PR_SET_PDEATHSIG covers for the child itself but not for what the child started. Forked without
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
// pq_reset_sigpipe): the write fails with EPIPE, which send() turns into a ChildFault, whatever the
// process does with SIGPIPE. mhbench ignores it (runner/cli/main.cpp), but a test or another host
// of this library may not, and its default ends the whole process without a word.
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

} // namespace

// Resolved before fork: getenv is not async-signal-safe.
std::string resolve_program(const std::string& program) {
    return process::find_executable(program).value_or(std::string());
}

ChildLink::ChildLink(const std::vector<std::string>& argv) {
    if (argv.empty())
        throw ChildFault("the command is empty", {});
    program_ = program_name(argv);
    const std::string path = resolve_program(argv.front());
    if (path.empty())
        throw ChildFault(argv.front() + ": not found in PATH", {});
    std::vector<std::string> words = argv;
    std::vector<char*> pointers;
    for (auto& w : words)
        pointers.push_back(w.data());
    pointers.push_back(nullptr);

    int to_child[2];
    int from_child[2];
    int errors[2];
    int report[2];
    if (::pipe2(to_child, O_CLOEXEC) != 0)
        throw ChildFault(std::string("cannot create a pipe (") + std::strerror(errno) + ")", {});
    if (::pipe2(from_child, O_CLOEXEC) != 0 || ::pipe2(errors, O_CLOEXEC) != 0 ||
        ::pipe2(report, O_CLOEXEC) != 0) {
        // Rare enough (descriptors exhausted) that leaking a pipe pair until exit is not worth
        // the bookkeeping; the error is what matters.
        throw ChildFault(std::string("cannot create a pipe (") + std::strerror(errno) + ")", {});
    }
    const pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ == 0)
        exec_child(path.c_str(), pointers.data(), parent, to_child[0], from_child[1], errors[1], report[1]);
    const int fork_error = errno;
    ::close(to_child[0]);
    ::close(from_child[1]);
    ::close(errors[1]);
    ::close(report[1]);
    in_ = to_child[1];
    out_ = from_child[0];
    err_ = errors[0];
    if (pid_ < 0) {
        ::close(report[0]);
        close_fd(in_);
        close_fd(out_);
        close_fd(err_);
        reaped_ = true;
        throw ChildFault(std::string("cannot start a process (") + std::strerror(fork_error) + ")", {});
    }
    // Also here (not only in the child), so that a kill(-pid) right after fork finds the group.
    (void)::setpgid(pid_, pid_);
    int exec_error = 0;
    ssize_t got = 0;
    do
        got = ::read(report[0], &exec_error, sizeof exec_error);
    while (got < 0 && errno == EINTR);
    ::close(report[0]);
    if (got == static_cast<ssize_t>(sizeof exec_error)) {
        kill();
        throw ChildFault(path + " cannot be run (" + std::strerror(exec_error) + ")", {});
    }
    int life[2];
    if (::pipe2(life, O_CLOEXEC) == 0) {
        watcher_ = ::fork();
        if (watcher_ == 0)
            watch(life[0], pid_);
        ::close(life[0]);
        if (watcher_ > 0)
            lifeline_ = life[1];
        else
            ::close(life[1]);
    }
    // So that a child that does not read is waited for in poll, with its stderr drained, not in a
    // write. (It does not keep a write to a child that has exited from raising SIGPIPE: see
    // SigpipeBlock for that.)
    ::fcntl(in_, F_SETFL, ::fcntl(in_, F_GETFL) | O_NONBLOCK);
}

ChildLink::~ChildLink() {
    kill();
}

void ChildLink::kill() {
    if (!reaped_ && pid_ > 0) {
        // Until the child is reaped its pid cannot be reused, so -pid_ is still its group.
        ::kill(-pid_, SIGKILL);
        ::kill(pid_, SIGKILL);
        close_fd(lifeline_);
        if (watcher_ > 0)
            while (::waitpid(watcher_, nullptr, 0) < 0 && errno == EINTR) {
            }
        watcher_ = -1;
        int status = 0;
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
        reaped_ = true;
    }
    close_fd(in_);
    close_fd(out_);
    if (err_ >= 0) {
        drain_stderr(false);
        close_fd(err_);
    }
}

bool ChildLink::exited() {
    if (exited_ || pid_ <= 0)
        return exited_;
    // WNOWAIT: seen, not reaped, so that its group stays its own until kill() (see there).
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
        info.si_pid == pid_) {
        exited_ = true;
        exit_code_ = info.si_code;
        exit_status_ = info.si_status;
    }
    return exited_;
}

void ChildLink::finish(std::chrono::duration<double> grace) {
    close_fd(in_);
    const auto deadline = std::chrono::steady_clock::now() + grace;
    while (!reaped_ && !exited() && std::chrono::steady_clock::now() < deadline)
        ::usleep(1000);
    kill();
}

void ChildLink::send(const std::string& line) {
    std::string text = line;
    text += '\n';
    const SigpipeBlock block;
    std::size_t done = 0;
    while (done < text.size()) {
        if (in_ < 0)
            throw ChildFault(program_ + " " + exit_description("closed its output"), stderr_tail());
        const ssize_t wrote = ::write(in_, text.data() + done, text.size() - done);
        if (wrote > 0) {
            done += static_cast<std::size_t>(wrote);
            continue;
        }
        if (wrote < 0 && errno == EINTR)
            continue;
        if (wrote < 0 && errno == EAGAIN) {
            // Its stdin is full: it is not reading. Wait for room while keeping its stderr
            // drained (a child blocked writing stderr would never read).
            pollfd fds[2] = {{in_, POLLOUT, 0}, {err_, POLLIN, 0}};
            if (::poll(fds, err_ >= 0 ? 2 : 1, 1000) > 0 && (fds[1].revents & (POLLIN | POLLHUP)) != 0)
                drain_stderr(false);
            continue;
        }
        if (wrote < 0 && errno == EPIPE) {
            // No reader left: it exited (or closed its stdin) before reading all it was sent.
            block.take_back();
            throw ChildFault(program_ + " " + exit_description("closed its stdin") +
                                 " before reading all it was sent",
                             stderr_tail());
        }
        throw ChildFault(program_ + ": cannot write to its stdin (" + std::strerror(errno) + ")",
                         stderr_tail());
    }
}

std::string ChildLink::receive(std::chrono::duration<double> timeout) {
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(timeout);
    for (;;) {
        if (const auto newline = out_buffer_.find('\n'); newline != std::string::npos) {
            std::string line = out_buffer_.substr(0, newline);
            out_buffer_.erase(0, newline + 1);
            if (!line.empty() && line.back() == '\r')
                line.pop_back();
            return line;
        }
        if (out_buffer_.size() > max_line)
            throw ChildFault(program_ + " wrote a line longer than 64 MiB", stderr_tail());
        if (out_ < 0)
            throw ChildFault(program_ + " " + exit_description("closed its output"), stderr_tail());
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0)
            throw ChildFault(program_ + " did not answer within " +
                                 std::to_string(std::chrono::duration<double>(timeout).count()) + " s",
                             stderr_tail());
        pollfd fds[2] = {{out_, POLLIN, 0}, {err_, POLLIN, 0}};
        const int ready =
            ::poll(fds, err_ >= 0 ? 2 : 1, static_cast<int>(std::min<long long>(left.count() + 1, 1000)));
        if (ready < 0 && errno != EINTR)
            throw ChildFault(std::string("poll failed (") + std::strerror(errno) + ")", stderr_tail());
        if (ready <= 0)
            continue;
        if (err_ >= 0 && (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) != 0)
            drain_stderr(false);
        if ((fds[0].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
            char buffer[65536];
            const ssize_t got = ::read(out_, buffer, sizeof buffer);
            if (got > 0)
                out_buffer_.append(buffer, static_cast<std::size_t>(got));
            else if (got == 0 || (errno != EINTR && errno != EAGAIN)) {
                // End of its stdout: it exited (or closed it, which is as good as exiting).
                close_fd(out_);
                if (!out_buffer_.empty() && out_buffer_.find('\n') == std::string::npos)
                    out_buffer_ += '\n'; // a last line without its newline is still read as one
            }
        }
    }
}

void ChildLink::add_stderr(const char* data, std::size_t size) {
    err_partial_.append(data, size);
    for (auto newline = err_partial_.find('\n'); newline != std::string::npos;
         newline = err_partial_.find('\n')) {
        std::string line = err_partial_.substr(0, newline);
        err_partial_.erase(0, newline + 1);
        if (line.size() > 300)
            line = line.substr(0, 300) + "...";
        if (!line.empty())
            err_lines_.push_back(std::move(line));
        if (err_lines_.size() > kept_stderr_lines)
            err_lines_.pop_front();
    }
    if (err_partial_.size() > 4096)
        err_partial_.erase(0, err_partial_.size() - 4096);
}

void ChildLink::drain_stderr(bool wait_for_end) {
    if (err_ < 0)
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
        add_stderr(buffer, static_cast<std::size_t>(got));
    }
}

std::string ChildLink::stderr_tail() {
    drain_stderr(false);
    std::string tail;
    for (const auto& line : err_lines_)
        tail += (tail.empty() ? "" : " | ") + line;
    if (!err_partial_.empty())
        tail += (tail.empty() ? "" : " | ") + err_partial_;
    return tail;
}

std::string ChildLink::exit_description(const char* if_running) {
    // It closed its pipes: give it a moment to exit so that the status can be told.
    for (int i = 0; i < 100 && !exited(); ++i)
        ::usleep(1000);
    if (!exited_)
        return if_running;
    drain_stderr(true);
    if (exit_code_ == CLD_EXITED)
        return "exited with status " + std::to_string(exit_status_);
    if (exit_code_ == CLD_KILLED || exit_code_ == CLD_DUMPED)
        return std::string("was killed by signal ") + std::to_string(exit_status_) + " (" +
               ::strsignal(exit_status_) + ")";
    return "ended";
}

} // namespace mhb::external
