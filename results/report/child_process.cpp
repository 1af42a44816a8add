#include "results/report/child_process.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <mutex>
#include <optional>
#include <pthread.h>
#include <sys/wait.h>

#include "problems/core/process/child_process.hpp"

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

// Replaces the handler of `signal` by on_stop_while_child_runs unless the signal is ignored (a
// process started in the background or under nohup keeps ignoring it). Returns whether it did.
bool handle_stop_signal(int signal, struct sigaction& previous) {
    if (::sigaction(signal, nullptr, &previous) != 0 || previous.sa_handler == SIG_IGN)
        return false;
    struct sigaction action {};
    action.sa_handler = on_stop_while_child_runs;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0; // no SA_RESTART: the wait returns EINTR and goes on
    return ::sigaction(signal, &action, nullptr) == 0;
}

// SIGINT and SIGTERM passed on to the child while it runs (on_stop_while_child_runs). They stay
// blocked in this thread from before the handlers are installed until the child's pid is known, so
// that the handler never runs without a child to pass the stop to here (the child, which inherits
// the mask, resets it once its own dispositions are set).
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
    ~StopForwarding() { restore(); }
    StopForwarding(const StopForwarding&) = delete;
    StopForwarding& operator=(const StopForwarding&) = delete;

    // From now on a stop goes to `pid`.
    void child_started(pid_t pid) {
        running_child.store(pid);
        ::pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
        if (stops_received.load() > 0) // a stop that another thread handled before the pid was known
            ::kill(pid, SIGTERM);
    }
    // No child to pass a stop to any more; the handlers and the mask as they were. Idempotent.
    void restore() {
        running_child.store(-1);
        if (handles_int_)
            ::sigaction(SIGINT, &previous_int_, nullptr);
        if (handles_term_)
            ::sigaction(SIGTERM, &previous_term_, nullptr);
        handles_int_ = handles_term_ = false;
        ::pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
    }

    [[nodiscard]] bool stop_requested() const { return stops_received.load() > 0; }

private:
    sigset_t previous_mask_{};
    struct sigaction previous_int_ {};
    struct sigaction previous_term_ {};
    bool handles_int_ = false;
    bool handles_term_ = false;
};

} // namespace

ChildOutcome run_child_process(const std::string& program, const std::vector<std::string>& arguments,
                               bool capture_output) {
    static std::mutex one_at_a_time; // the signal handling above serves one child
    const std::lock_guard<std::mutex> lock(one_at_a_time);
    ChildOutcome outcome;
    std::vector<std::string> argv = {program};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    const process::Stream output = capture_output ? process::Stream::memory : process::Stream::null;
    StopForwarding stops;
    try {
        process::ChildProcess child(argv, {.output = output, .errors = output, .ignore_interrupt = true});
        stops.child_started(child.pid());
        child.wait_for_exit();
        stops.restore();
        outcome.status = child.end();
        outcome.started = true;
        outcome.out = child.captured_output();
        outcome.err = child.captured_errors();
    } catch (const std::runtime_error& e) { // process::SpawnError, or a wait that failed
        outcome.error = e.what();
    }
    outcome.stop_requested = stops.stop_requested();
    return outcome;
}

} // namespace mhb
