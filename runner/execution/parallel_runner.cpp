#include "runner/execution/parallel_runner.hpp"

#include <chrono>
#include <mutex>
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <stdexcept>
#include <vector>

#include "results/store/study_writer.hpp"
#include "runner/run/execute_run.hpp"

namespace mhb {

int resolve_thread_count(int threads) {
    if (threads < 0)
        throw std::invalid_argument("threads = " + std::to_string(threads) + " is outside [0, inf)");
    return threads == 0 ? tbb::info::default_concurrency() : threads;
}

std::vector<std::int64_t> pending_runs(const PreparedStudy& study, const StudyWriter& writer,
                                       const RunnerOptions& options, RunnerOutcome& outcome) {
    std::vector<std::int64_t> wanted = options.run_ids.value_or(std::vector<std::int64_t>{});
    if (!options.run_ids) {
        wanted.resize(static_cast<std::size_t>(study.run_count()));
        for (std::size_t i = 0; i < wanted.size(); ++i)
            wanted[i] = static_cast<std::int64_t>(i);
    }
    outcome.total = static_cast<std::int64_t>(wanted.size());
    // The store may hold more (runs of a larger study kept for later); only the wanted ones count.
    std::vector<std::int64_t> pending;
    for (const std::int64_t id : wanted) {
        if (id < 0 || id >= study.run_count())
            throw std::logic_error("run_study: run " + std::to_string(id) + " is not a run of this study");
        if (writer.completed().count(id) != 0)
            ++outcome.resumed;
        else
            pending.push_back(id);
    }
    return pending;
}

RunnerOutcome run_study(const PreparedStudy& study, StudyWriter& writer, const RunnerOptions& options) {
    RunnerOutcome outcome;
    const std::vector<std::int64_t> pending = pending_runs(study, writer, options, outcome);

    const auto stopping = [&] { return options.stop != nullptr && options.stop->load(); };
    std::mutex progress_mutex;
    std::int64_t kept = outcome.resumed;
    {
        const tbb::global_control cap(tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(resolve_thread_count(options.threads)));
        // Grain 1 with the simple partitioner: one task per run, so a slow run never holds
        // back a chunk of others, and a stop request is seen before each run starts.
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, pending.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range) {
                for (std::size_t i = range.begin(); i != range.end(); ++i) {
                    if (stopping())
                        return;
                    const auto started = std::chrono::steady_clock::now();
                    const RunRecord record = execute_run(study.request(pending[i]));
                    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - started;
                    writer.append(record, wall.count());
                    const std::lock_guard<std::mutex> lock(progress_mutex);
                    ++kept;
                    if (options.on_run_finished)
                        options.on_run_finished(kept, outcome.total, record);
                }
            },
            tbb::simple_partitioner());
        outcome.kept = kept;
        outcome.interrupted = kept < outcome.total;
        if (!outcome.interrupted && options.finish_writer)
            writer.finish(); // renders in parallel too: under the same cap
    }
    return outcome;
}

} // namespace mhb
