#include "runner/distribution/mpi/local_runs.hpp"

#include <utility>

#include "runner/run/execute_run.hpp"

namespace mhb {

LocalRuns::LocalRuns(const PreparedStudy& study, int threads)
    : study_(study), threads_(threads),
      cap_(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads) + 1),
      // No slot reserved for the calling thread: it only hands runs in.
      arena_(threads, 0) {}

LocalRuns::~LocalRuns() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return running_ == 0; });
}

void LocalRuns::start(std::int64_t run_id) {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        ++running_;
    }
    // enqueue, not execute: execute would make the calling thread wait for a free slot.
    arena_.enqueue([this, run_id] {
        FinishedRun finished;
        try {
            const auto started = std::chrono::steady_clock::now();
            finished.record = execute_run(study_.request(run_id));
            finished.wall_seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        } catch (...) { // an enqueued task must not throw (std::terminate): hand it over instead
            finished.record.run_id = run_id;
            finished.error = std::current_exception();
        }
        const std::lock_guard<std::mutex> lock(mutex_);
        finished_.push_back(std::move(finished));
        --running_;
        // Under the lock: once running_ is 0 the destructor may proceed, and this task must not
        // touch the object after that.
        changed_.notify_all();
    });
}

int LocalRuns::running() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return running_;
}

bool LocalRuns::idle() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return running_ == 0 && finished_.empty();
}

std::vector<FinishedRun> LocalRuns::take_finished() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(finished_, {});
}

void LocalRuns::wait(std::chrono::microseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, timeout, [this] { return !finished_.empty(); });
}

} // namespace mhb
