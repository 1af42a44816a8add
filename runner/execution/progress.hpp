// Progress of a long study, on a stream (stderr in the CLI), in one of two forms:
//  - on a terminal, a bar redrawn in place (carriage return) a few times a second:
//      [#######.............] 12/40 runs 34%  3.1 runs/s  2.4e+06 evals/s  elapsed 0:03  eta 0:09 ...
//  - in a batch log (stderr not a terminal), a plain line every `line_interval` seconds:
//      progress: 12/40 runs (34% of the work), 3.1 runs/s, 2.4e+06 evals/s, elapsed 0:03, eta ...
//    where the ETA reads "0:09 (runs 0:07, report 0:02)" when a report follows the runs.
// Either appears only once a study has run for `delay_seconds`, so short studies print nothing.
// The percentage and the ETA weigh each run by its expected cost (ProgressWork), not by its
// count: a study whose long runs come last is not promised an early end. The ETA adds what
// follows the runs (the report and its figures, as the dry run estimates it). Rates and the ETA
// count this session's runs only (a resumed study's earlier runs took no time here). The CLI
// decides the form, and --quiet silences both. Display only: nothing here touches a record.
#pragma once

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace mhb {

// True when stderr is an interactive terminal (a progress bar in a log file is noise).
bool stderr_is_terminal();

struct ProgressOptions {
    bool terminal = true;        // the bar; false: plain lines
    double delay_seconds = 1.0;  // nothing before this much time has passed
    double line_interval = 10.0; // seconds between plain lines
};

// The work a study's progress counts: each run weighted by its expected cost, in any unit (the
// CLI passes the estimate the shards are balanced by, runner/distribution/shards.hpp), so that a
// run ten times longer moves the percentage, and the pace the ETA extrapolates, ten times as far.
class ProgressWork {
public:
    // `costs`: of every run of the study, by run id; `runs`: the ids counted (the study's, or a
    // shard's); `stored`: the runs already finished before this session (others are ignored).
    ProgressWork(std::vector<double> costs, const std::vector<std::int64_t>& runs,
                 const std::set<std::int64_t>& stored);
    // `runs` runs (ids 0 to runs - 1) of one unit each, the first `stored` of them finished.
    static ProgressWork uniform(std::int64_t runs, std::int64_t stored);

    void finished(std::int64_t run_id); // this session; an id outside the study counts one unit
    [[nodiscard]] std::int64_t runs() const { return runs_; }
    [[nodiscard]] std::int64_t runs_done() const { return runs_done_; }
    [[nodiscard]] std::int64_t runs_done_here() const { return runs_done_here_; }
    [[nodiscard]] double fraction_done() const;                   // of the work, stored runs included
    [[nodiscard]] double done_here() const { return done_here_; } // this session's work
    [[nodiscard]] double remaining() const { return total_ - done_; }

private:
    std::vector<double> costs_;
    std::int64_t runs_ = 0, runs_done_ = 0, runs_done_here_ = 0;
    double total_ = 0, done_ = 0, done_here_ = 0;
};

class ProgressBar {
public:
    // `after_runs_seconds`: the estimated time of what follows the runs (the report), added to the
    // ETA; 0 when nothing follows.
    ProgressBar(std::ostream& out, ProgressWork work, ProgressOptions options, double after_runs_seconds = 0);

    // Thread-safe. Run `run_id` finished, having spent `evaluations`.
    void update(std::int64_t run_id, std::int64_t evaluations = 0);
    // Draws the final state (if anything was shown) and ends the bar's line.
    void finish();

private:
    void draw(double elapsed);
    [[nodiscard]] std::string eta_text(double elapsed) const;

    std::ostream& out_;
    ProgressWork work_;
    ProgressOptions options_;
    double after_runs_seconds_;
    std::chrono::steady_clock::time_point start_;
    double last_draw_ = -1.0;
    double evaluations_ = 0; // this session's
    bool shown_ = false;
    std::mutex mutex_;
};

// "m:ss" or "h:mm:ss".
std::string format_duration(double seconds);

} // namespace mhb
