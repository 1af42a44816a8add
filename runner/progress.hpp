// A one-line progress bar for long studies, drawn on a stream (stderr in the CLI):
//   [##########..........]  12/40 runs  elapsed 0:03  eta 0:07
// It redraws in place (carriage return) at most a few times a second, and only appears once a
// study has run for `delay_seconds`, so short studies print nothing. The CLI decides whether to
// enable it: when stderr is a terminal, unless --progress forces it or --quiet silences it.
#pragma once

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <mutex>
#include <string>

namespace mhb {

// True when stderr is an interactive terminal (a progress bar in a log file is noise).
bool stderr_is_terminal();

class ProgressBar {
public:
    // `already`: runs finished before this session (a resumed study); they do not count in the ETA.
    ProgressBar(std::ostream& out, std::int64_t total, std::int64_t already, double delay_seconds);

    // Thread-safe. `done` counts every finished run of the study, resumed ones included.
    void update(std::int64_t done);
    // Draws the final state (if the bar was shown) and ends its line.
    void finish();

private:
    void draw(std::int64_t done, double elapsed);

    std::ostream& out_;
    std::int64_t total_;
    std::int64_t already_;
    double delay_seconds_;
    std::chrono::steady_clock::time_point start_;
    double last_draw_ = -1.0;
    std::int64_t done_ = 0;
    bool shown_ = false;
    std::mutex mutex_;
};

// "m:ss" or "h:mm:ss".
std::string format_duration(double seconds);

} // namespace mhb
