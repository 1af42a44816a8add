// Runs a prepared study on oneTBB: one task per run (parallel_for, grain 1), the thread count
// capped by tbb::global_control. Each finished run is stored by the StudyWriter at once, so
// an interruption loses nothing; runs already in the store are skipped (resume, extension). Results do
// not depend on the thread count: seeds come from derive_seed (via execute_run) and the store
// sorts by run id.
//
// Cancellation: once `*stop` becomes true, no new run starts; runs under way finish and are
// stored. The CLI sets it from SIGINT/SIGTERM; tests set it from on_run_finished.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "results/store/run_record.hpp"
#include "runner/study/study.hpp"

namespace mhb {

class StudyWriter; // results/store/study_writer.hpp

struct RunnerOptions {
    int threads = 0;                         // 0: every hardware thread
    const std::atomic<bool>* stop = nullptr; // may be set from a signal handler
    // The runs to do (a shard of the study, possibly none); unset: every run of the study.
    std::optional<std::vector<std::int64_t>> run_ids;
    // Called after each run is stored, with the runs now kept, the study's total and the run's
    // record (its run id, the evaluations it spent). Calls are serialised (never two at once), but
    // may come from any worker thread.
    std::function<void(std::int64_t kept, std::int64_t total, const RunRecord& record)> on_run_finished;
    // Whether the writer renders the study's files once every run is done (runs by precision render
    // after their last round, not after each).
    bool finish_writer = true;
};

struct RunnerOutcome {
    std::int64_t total = 0;   // runs to do: the study's, or the shard's
    std::int64_t resumed = 0; // found already finished in the store
    std::int64_t kept = 0;    // finished and stored, resumed ones included
    bool interrupted = false; // stopped before all runs were done (the study is not finished)
};

// Runs every run of `study` not yet in `writer`'s store. When all are done, finishes the
// writer (sorted files, runs.csv last); when stopped early, leaves the store for a resume.
// A run that throws becomes a failed record; an I/O error of the writer propagates.
RunnerOutcome run_study(const PreparedStudy& study, StudyWriter& writer, const RunnerOptions& options = {});

// The runs `options` asks for (its run_ids, or every run of `study`) that `writer`'s store does
// not hold, in that order; sets outcome.total and outcome.resumed. Throws std::logic_error for
// an id outside the study. run_study and the MPI runner share it.
std::vector<std::int64_t> pending_runs(const PreparedStudy& study, const StudyWriter& writer,
                                       const RunnerOptions& options, RunnerOutcome& outcome);

// The thread count `threads` = 0 stands for (oneTBB's default concurrency).
int resolve_thread_count(int threads);

} // namespace mhb
