// Progress of a long study, on a stream (stderr in the CLI), in one of two forms:
//  - on a terminal, a bar redrawn in place (carriage return) a few times a second:
//      [##########..........]  12/40 runs  3.1 runs/s  2.4e+06 evals/s  elapsed 0:03  eta 0:07
//  - in a batch log (stderr not a terminal), a plain line every `line_interval` seconds:
//      progress: 12/40 runs (30%), 3.1 runs/s, 2.4e+06 evals/s, elapsed 0:03, eta 0:07
// Either appears only once a study has run for `delay_seconds`, so short studies print nothing.
// Rates and the ETA count this session's runs only (a resumed study's earlier runs took no time
// here). The CLI decides the form, and --quiet silences both.
#pragma once

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <mutex>
#include <string>

namespace mhb {

// True when stderr is an interactive terminal (a progress bar in a log file is noise).
bool stderr_is_terminal();

struct ProgressOptions {
    bool terminal = true;        // the bar; false: plain lines
    double delay_seconds = 1.0;  // nothing before this much time has passed
    double line_interval = 10.0; // seconds between plain lines
};

class ProgressBar {
public:
    // `already`: runs finished before this session (a resumed study).
    ProgressBar(std::ostream& out, std::int64_t total, std::int64_t already, ProgressOptions options);

    // Thread-safe. `done` counts every finished run of the study, resumed ones included;
    // `evaluations` is what the run that just finished spent.
    void update(std::int64_t done, std::int64_t evaluations = 0);
    // Draws the final state (if anything was shown) and ends the bar's line.
    void finish();

private:
    void draw(double elapsed);

    std::ostream& out_;
    std::int64_t total_;
    std::int64_t already_;
    ProgressOptions options_;
    std::chrono::steady_clock::time_point start_;
    double last_draw_ = -1.0;
    std::int64_t done_ = 0;
    double evaluations_ = 0; // this session's
    bool shown_ = false;
    std::mutex mutex_;
};

// "m:ss" or "h:mm:ss".
std::string format_duration(double seconds);

} // namespace mhb
