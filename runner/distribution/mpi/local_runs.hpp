// The runs one MPI rank executes: each on a oneTBB arena of `threads` threads, started by the
// rank's communication thread (which calls MPI, so it must never be one of the arena's workers
// and never block on a run), and collected back by it. No MPI here.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/task_arena.h>
#include <vector>

#include "results/store/run_record.hpp"
#include "runner/study/study.hpp"

namespace mhb {

struct FinishedRun {
    RunRecord record;
    double wall_seconds = 0.0;
    std::exception_ptr error; // what escaped execute_run (it turns a run's own failure into a record)
};

class LocalRuns {
public:
    LocalRuns(const PreparedStudy& study, int threads);
    // Waits for the runs under way: they refer to this object.
    ~LocalRuns();
    LocalRuns(const LocalRuns&) = delete;
    LocalRuns& operator=(const LocalRuns&) = delete;

    [[nodiscard]] int threads() const { return threads_; }
    void start(std::int64_t run_id);
    [[nodiscard]] int running() const;
    // No run under way and none finished but not taken.
    [[nodiscard]] bool idle() const;
    // The runs finished since the last call, in the order they finished.
    [[nodiscard]] std::vector<FinishedRun> take_finished();
    // Returns when a run has finished (at once if one is waiting to be taken) or after `timeout`.
    void wait(std::chrono::microseconds timeout);

private:
    const PreparedStudy& study_;
    int threads_;
    // One more than the arena's threads: oneTBB counts the calling thread, which never works here.
    tbb::global_control cap_;
    tbb::task_arena arena_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    int running_ = 0;
    std::vector<FinishedRun> finished_;
};

} // namespace mhb
